// Physics verification: stress waves.  Wave speeds in a bar (uniaxial stress) and a confined
// column (uniaxial strain), an elastic bar bouncing off a rigid wall (1-D bar-wave theory), and
// the elastic-plastic two-wave structure of a confined column hitting a wall.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

// Column along z of n_lat x n_lat x nz hexahedra, section a x a, length L, impact end z = 0
// on a z = 0 stonewall, all nodes at vz = -v.
Model impact_column(const MaterialData& mat, int n_lat, double a, int nz, double L, double v,
                    double t_end, int bc_code) {
  Model m = make_box_model({n_lat, n_lat, nz, a, a, L, -a / 2, -a / 2, 0}, mat, t_end, bc_code);
  set_uniform_velocity(m, 0, 0, -v);
  add_floor_wall(m);
  return m;
}

// Wave speed from the times at which sigma_zz in the elements of layers k1 < k2 first reaches
// half of `plateau` (linear interpolation between cycles): (z2 - z1) / (t2 - t1).  The half-
// amplitude point of a front travels at the wave speed however the front is smeared (bulk
// viscosity, mesh dispersion), and the difference of two stations removes the start-up delay.
double measured_wave_speed(const Model& m, int n_lat, double dz, int k1, int k2, double plateau) {
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  const int e1 = k1 * n_lat * n_lat, e2 = k2 * n_lat * n_lat;  // first element of each layer
  double t1 = -1, t2 = -1;
  double prev1 = 0, prev2 = 0, tprev = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double s1 = s.sig[6 * std::size_t(e1) + 2], s2 = s.sig[6 * std::size_t(e2) + 2];
    const double half = 0.5 * plateau;
    if (t1 < 0 && s1 <= half) t1 = tprev + (s.time - tprev) * (half - prev1) / (s1 - prev1);
    if (t2 < 0 && s2 <= half) t2 = tprev + (s.time - tprev) * (half - prev2) / (s2 - prev2);
    prev1 = s1;
    prev2 = s2;
    tprev = s.time;
  }
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_GT(t1, 0);
  EXPECT_GT(t2, t1);
  return (k2 - k1) * dz / (t2 - t1);
}

}  // namespace

// Bar velocity c0 = sqrt(E / rho): a 100 mm copper bar of 1 x 1 mm section (one element
// across, lateral faces free: uniaxial stress), 200 layers, 1 m/s onto a rigid wall.  Stations
// at 25 mm and 75 mm; end before the reflection from the free end comes back to 75 mm.
TEST(WaveSpeed, BarVelocityInUniaxialStress) {
  ScopedThreads one(1);
  const MaterialData mat = copper_elastic();
  const double L = 0.1, a = 1e-3, v = 1.0;
  const int nz = 200;
  const double c0 = std::sqrt(mat.E / mat.rho);  // 3619.7 m/s
  Model m = impact_column(mat, 1, a, nz, L, v, 0.95 * L / c0, 0);
  const double c = measured_wave_speed(m, 1, L / nz, 50, 150, -mat.rho * c0 * v);
  std::printf("bar velocity: measured %.1f m/s, c0 = sqrt(E/rho) = %.1f m/s (%.2f%%)\n", c, c0,
              100 * (c / c0 - 1));
  // 3%: a section one element wide carries uniaxial stress only approximately (lateral inertia
  // of the Poisson expansion: Rayleigh-Love dispersion, small for a 1 mm section and a sharp
  // front seen at half amplitude).
  EXPECT_NEAR(c / c0, 1.0, 0.03);
}

// Dilatational velocity sqrt((K + 4G/3) / rho): the same column with every node on x/y rollers
// (BC code 4): uniaxial strain.
TEST(WaveSpeed, DilatationalVelocityInUniaxialStrain) {
  ScopedThreads one(1);
  const MaterialData mat = copper_elastic();
  const double L = 0.1, a = 0.5e-3, v = 1.0;
  const int nz = 200;
  const double cd = std::sqrt(elastic_of(mat).M / mat.rho);  // 4585.6 m/s
  Model m = impact_column(mat, 1, a, nz, L, v, 0.95 * L / cd, 4);
  const double c = measured_wave_speed(m, 1, L / nz, 50, 150, -mat.rho * cd * v);
  std::printf("dilatational velocity: measured %.1f m/s, sqrt((K+4G/3)/rho) = %.1f m/s (%.2f%%)\n",
              c, cd, 100 * (c / cd - 1));
  // 3% (the brief's tolerance); with rollers the problem is exactly one-dimensional and only
  // the mesh dispersion of the smeared front remains.
  EXPECT_NEAR(c / cd, 1.0, 0.03);
}

// Elastic bar on a rigid wall below yield: copper, L = 20 mm, 5 m/s onto a frictionless z = 0
// stonewall, lateral faces free.  1-D bar-wave theory: contact for 2L/c0 = 11.05 us, then the
// bar leaves at 5 m/s with all its energy.
//  Section: 0.5 x 0.5 mm (L/d = 40), 2 x 2 x 100 elements of 0.25 x 0.25 x 0.2 mm.  The deck's
//  2 x 2 mm section (L/d = 10, decks/bar_wall_elastic.dyn) rebounds 5% slow whatever the
//  viscosities (measured: -4.6% with no bulk viscosity and no hourglass control at all, with
//  (KE + IE) / KE0 = 0.997): lateral inertia (Pochhammer-Chree dispersion) leaves ~5% of the
//  energy in vibration when the bar leaves, which 1-D theory ignores; it shrinks with the
//  slenderness (-3.2% at 1 mm, -2.1% at 0.5 mm).  Near-cubic elements: the bulk viscosity uses
//  l = V^(1/3) while the time step uses V / A_max, so flat elements (the deck's 1 x 1 x 0.5 mm)
//  get a bulk viscosity several times stronger than their step assumes.
//  100 layers: the impact-end node layer hits the wall perfectly plastically (its normal
//  velocity is removed in one step), losing its kinetic energy to the wall: 1/(2 nz) = 0.5%.
//  Hourglass type 3 (Flanagan-Belytschko), default coefficient and bulk viscosity.
TEST(BarOnWall, ElasticBounceContactTimeAndRebound) {
  ScopedThreads one(1);
  MaterialData mat = copper_elastic();
  mat.hourglass_type = 3;
  const double L = 20e-3, a = 0.5e-3, v = 5.0;
  const int nz = 100;
  const double c0 = std::sqrt(mat.E / mat.rho);
  const double t_contact = 2 * L / c0;  // 11.05 us
  Model m = impact_column(mat, 2, a, nz, L, v, 2.5 * t_contact, 0);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const double ke0 = eng.state().kinetic;
  const double mtot = total_mass(eng.state());
  double t_last_force = 0, fmax = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double t_before = eng.state().time;
    st = eng.step();
    const double f = eng.state().wall_force[0][2];
    fmax = std::max(fmax, -f);
    // the wall force of a cycle is the impulse over [t^n, t^{n+1}]: contact lasts until the end
    // of the last cycle with a force (t_before + dt) -- take the midpoint of that cycle
    if (f != 0) t_last_force = 0.5 * (t_before + eng.state().time);
  }
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  const double vcom = momentum(s)[2] / mtot;
  std::printf("bar on wall: contact %.3f us (2L/c0 %.3f us, %.2f%%), rebound %.4f m/s (%.2f%%), "
              "energy ratio %.5f, bar KE/KE0 %.4f, (KE+IE)/KE0 %.4f, wall work/KE0 %.4f, "
              "hg/KE0 %.2e, bv/KE0 %.2e, peak wall force %.1f N (rho c0 v A = %.1f N)\n",
              t_last_force * 1e6, t_contact * 1e6, 100 * (t_last_force / t_contact - 1), vcom,
              100 * (vcom / v - 1), s.energy_ratio(), s.kinetic / ke0,
              (s.kinetic + s.internal) / ke0, s.wall_work / ke0, s.hourglass / ke0,
              s.bulk_viscous / ke0, fmax, mat.rho * c0 * v * a * a);
  // Contact time 2L/c0 within 3% (the brief's tolerance: dispersion of the 3-D bar, L/d = 10,
  // delays the tail of the reflected unloading wave slightly).
  EXPECT_NEAR(t_last_force / t_contact, 1.0, 0.03);
  // Rebound: centre-of-mass velocity +v within 3% (first-layer loss 0.5% in energy, 0.25% in
  // velocity; the rest is energy left in bar vibrations and taken by the viscosities).
  EXPECT_NEAR(vcom / v, 1.0, 0.03);
  // Energy books (wall work included): ratio within 2% of 1.
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.02);
  EXPECT_LT(s.kinetic + s.internal, ke0 * 1.0000001);  // nothing is created
}

// Uniaxial strain, elastic-plastic copper (sigma_y 0.4 GPa, E_tan 0.1 GPa, isotropic),
// column on x/y rollers (BC 4 on every node) hitting a rigid wall at v = 50 m/s: the two-wave
// structure of 1-D plasticity.
//  Elastic precursor: the Hugoniot elastic limit HEL = sigma_y (1 - nu) / (1 - 2 nu)
//    = 0.8667 GPa, travelling at c_el = sqrt((K + 4G/3) / rho) = 4585.6 m/s, particle velocity
//    jump u_HEL = HEL / (rho c_el) = 21.17 m/s.
//  Plastic wave: in uniaxial strain after yield, d sigma_zz / d eps = K + (4/3) G E_p / (3G + E_p)
//    (tests/material: the radial return gives deps_p = 2G deps / (3G + E_p)), E_p = E E_tan /
//    (E - E_tan) = 0.10009 GPa: K_p = 130.044 GPa, c_p = sqrt(K_p / rho) = 3816.1 m/s.
//    Behind it the material is at rest on the wall, so the plateau is
//    sigma = HEL + rho c_p (v - u_HEL) = 0.8667 + 0.9825 = 1.849 GPa (compression).
TEST(ColumnOnWall, UniaxialStrainElasticPlasticTwoWaves) {
  ScopedThreads one(1);
  const MaterialData mat = copper_plastic();
  const Elastic el = elastic_of(mat);
  const double v = 50, L = 40e-3;
  const int nz = 400;
  const double dz = L / nz;
  const double E_p = mat.E * mat.E_tan / (mat.E - mat.E_tan);
  const double c_el = std::sqrt(el.M / mat.rho);
  const double hel = mat.sigma_y * (1 - mat.nu) / (1 - 2 * mat.nu);
  const double u_hel = hel / (mat.rho * c_el);
  const double K_p = el.K + 4.0 / 3.0 * el.G * E_p / (3 * el.G + E_p);
  const double c_p = std::sqrt(K_p / mat.rho);
  const double plateau = hel + mat.rho * c_p * (v - u_hel);
  ASSERT_NEAR(plateau, 1.85e9, 0.01e9);  // the "about 1.85 GPa"
  const double t_end = 0.75 * L / c_el;  // elastic front at 3/4 of the column
  Model m = impact_column(mat, 1, dz, nz, L, v, t_end, 4);
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double zp = c_p * s.time, ze = c_el * s.time;  // plastic and elastic fronts
  // Averages of sigma_zz (element stress, tension positive) over windows well clear of the
  // smeared fronts: behind the plastic wave z in [0.15, 0.75] zp (the impact-end elements see
  // the start-up transient); in the precursor the middle 40% between the fronts.
  auto mean_szz = [&](double za, double zb) {
    double sum = 0;
    int n = 0;
    for (int k = 0; k < nz; ++k) {
      const double zc = (k + 0.5) * dz;
      if (zc < za || zc > zb) continue;
      sum += s.sig[6 * std::size_t(k) + 2];
      ++n;
    }
    EXPECT_GT(n, 10);
    return sum / n;
  };
  const double s_plastic = mean_szz(0.15 * zp, 0.75 * zp);
  const double gap = ze - zp;
  const double s_elastic = mean_szz(zp + 0.3 * gap, ze - 0.3 * gap);
  std::printf("column: plastic plateau %.4f GPa (closed form %.4f, %.2f%%), precursor %.4f GPa "
              "(HEL %.4f, %.2f%%), fronts at %.1f / %.1f mm, max eps_p %.4f\n",
              -s_plastic / 1e9, plateau / 1e9, 100 * (-s_plastic / plateau - 1), -s_elastic / 1e9,
              hel / 1e9, 100 * (-s_elastic / hel - 1), zp * 1e3, ze * 1e3,
              *std::max_element(s.eps_p.begin(), s.eps_p.end()));
  // 5% (the brief's tolerance): the closed forms are small-strain (the rate form integrates
  // log strain, ~1% strains here) and the windows see some ringing behind the fronts.
  EXPECT_NEAR(-s_plastic / plateau, 1.0, 0.05);
  EXPECT_NEAR(-s_elastic / hel, 1.0, 0.05);
}

// Energy books with bulk viscosity: an elastic copper column on rollers (uniaxial strain, 1-D)
// bouncing off a rigid wall at 5 m/s, default viscosities (Q1 1.5, Q2 0.06), one 2 x 2 mm
// element across and 100 layers of 0.2 mm (flat elements: l = V^(1/3) = 0.93 mm makes the bulk
// viscosity strong, and the front rings from step to step).  Final energy ratio 1 within 1%
// (measured 1.0001).  During the compression it peaks at 1.047 (cycles 15-20): the kinetic
// energy is taken with v^{n+1/2}, and for a front ringing near the Nyquist frequency (omega dt
// ~ 2) the half-step kinetic energy differs from the conserved discrete energy by O((omega dt)^2
// / 8) of the ringing energy; bound 1.06 on every cycle.  Regression: the bulk viscous work was booked
// as q^{n+1} trD^{n+1/2}, the work of a q that had not acted yet; with the strain rate
// alternating in sign behind the front this booked 1.28 KE0 as dissipated while the column
// really lost 0.14 KE0, an energy ratio of 2.14.  Also the contact time 2L/c_d (c_d the
// dilatational speed) within 3%.
TEST(ColumnOnWall, ElasticEnergyBooksWithBulkViscosity) {
  ScopedThreads one(1);
  const MaterialData mat = copper_elastic();
  const double L = 20e-3, a = 2e-3, v = 5.0;
  const int nz = 100;
  const double cd = std::sqrt(elastic_of(mat).M / mat.rho);
  const double t_contact = 2 * L / cd;  // 8.72 us
  Model m = impact_column(mat, 1, a, nz, L, v, 2.5 * t_contact, 4);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const double ke0 = eng.state().kinetic;
  double ratio_min = 1, ratio_max = 1, t_last_force = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double t_before = eng.state().time;
    st = eng.step();
    ratio_min = std::min(ratio_min, eng.state().energy_ratio());
    ratio_max = std::max(ratio_max, eng.state().energy_ratio());
    if (eng.state().wall_force[0][2] != 0) t_last_force = 0.5 * (t_before + eng.state().time);
  }
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  std::printf("1-D column energy books: final ratio %.5f (%.5f..%.5f), bv/KE0 %.4f, "
              "(KE+IE)/KE0 %.4f, contact %.3f us (2L/c_d %.3f us)\n",
              s.energy_ratio(), ratio_min, ratio_max, s.bulk_viscous / ke0, (s.kinetic + s.internal) / ke0,
              t_last_force * 1e6, t_contact * 1e6);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.01);
  EXPECT_GT(ratio_min, 0.99);
  EXPECT_LT(ratio_max, 1.06);
  EXPECT_NEAR(t_last_force / t_contact, 1.0, 0.03);
}
