// Equations of state (impact3d/material/eos.h) through the whole cycle:
//  (a) one solid squeezed and stretched uniaxially by prescribed velocities: its pressure is the
//      EOS formula of its own volume and energy at every cycle (linear polynomial, exactly the
//      polynomial when it does not depend on E, the mu^2 terms dropped in tension; Gruneisen
//      with GAMMA0 = 0 exactly the Hugoniot p_H = rho0 C^2 mu (1 + mu) / [1 - (S1 - 1) mu]^2,
//      with GAMMA0 = 2.02 p_H + GAMMA0 (E - E_H) with E_H = p_H mu / (2 (1 + mu))), and its
//      energy E V0 equals the stress and bulk-viscosity work the global books hold;
//  (b) a copper flyer plate (MAT_NULL + Gruneisen) hitting a like target at v: behind the shock
//      the particle velocity is v/2, the pressure rho0 Us up with Us = C + S1 up, and the shock
//      runs at Us (arrival times).
// Units SI.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <vector>

#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/material/eos_test_util.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;
using namespace eos_test;  // null_material, pressure, squeezed_cube, run_cube

namespace {

EosData linear_polynomial(std::array<double, 7> c, double e0) {
  EosData e;
  e.form = 1;
  for (std::size_t j = 0; j < c.size(); ++j) e.c[j] = c[j];
  e.e0 = e0;
  return e;
}

// Copper (Steinberg's us-up fit): C 3940 m/s, S1 1.49, GAMMA0 2.02 (A = 0).
EosData gruneisen_copper(double gamma0) {
  EosData e;
  e.form = 4;
  e.c = {3940, 1.49, 0, 0, gamma0, 0, 0};
  return e;
}

}  // namespace

TEST(EquationOfState, LinearPolynomialIsThePolynomialOfTheSolidsVolumeAndEnergy) {
  // without E terms: the polynomial, C2 mu^2 dropped in tension
  const std::array<double, 7> c = {1e5, 2.2e9, 9e9, 3e10, 0, 0, 0};
  Model m = squeezed_cube(null_material(1000, linear_polynomial(c, 0)), 10, 10e-6);
  double worst = 0, mu_max = 0, mu_min = 0;
  run_cube(m, [&](double mu, double p, double) {
    const double c2 = mu < 0 ? 0 : c[2];
    const double want = c[0] + c[1] * mu + c2 * mu * mu + c[3] * mu * mu * mu;
    worst = std::max(worst, std::fabs(p - want) / std::fabs(c[1] * mu + c[0]));
  }, mu_max, mu_min);
  std::printf("linear polynomial (no E terms): mu %.4f .. %.4f, worst |p - formula| / |p| = %.2e\n", mu_min, mu_max, worst);
  EXPECT_GT(mu_max, 0.1);
  EXPECT_LT(mu_min, -0.04);
  EXPECT_LT(worst, 1e-12);
  // with E terms: p = a(mu) + b(mu) E with the solid's own E
  const std::array<double, 7> ce = {0, 2.2e9, 9e9, 3e10, 0.4, 0.3, 0.2};
  Model me = squeezed_cube(null_material(1000, linear_polynomial(ce, 2e8)), 10, 10e-6);
  worst = 0;
  run_cube(me, [&](double mu, double p, double E) {
    const double k2 = mu < 0 ? 0 : ce[2], k6 = mu < 0 ? 0 : ce[6];
    const double want = ce[1] * mu + k2 * mu * mu + ce[3] * mu * mu * mu + (ce[4] + ce[5] * mu + k6 * mu * mu) * E;
    worst = std::max(worst, std::fabs(p - want) / std::fabs(want));
  }, mu_max, mu_min);
  std::printf("linear polynomial (E terms): worst |p - (a + b E)| / |p| = %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(EquationOfState, GruneisenOnTheHugoniotAndOffIt) {
  auto hugoniot = [](double mu) {
    const double den = 1 - (1.49 - 1) * mu;
    return 8930.0 * 3940 * 3940 * mu * (1 + mu) / (den * den);
  };
  // GAMMA0 = 0: the compressed form is the Hugoniot whatever E; tension rho0 C^2 mu
  Model m = squeezed_cube(null_material(8930, gruneisen_copper(0)), 50, 2e-6);
  double worst = 0, mu_max = 0, mu_min = 0;
  run_cube(m, [&](double mu, double p, double) {
    const double want = mu > 0 ? hugoniot(mu) : 8930.0 * 3940 * 3940 * mu;
    worst = std::max(worst, std::fabs(p - want) / std::fabs(want));
  }, mu_max, mu_min);
  std::printf("Gruneisen GAMMA0 = 0: mu %.4f .. %.4f, worst |p - p_H| / p_H = %.2e\n", mu_min, mu_max, worst);
  EXPECT_GT(mu_max, 0.1);
  EXPECT_LT(worst, 1e-12);
  // GAMMA0 = 2.02, no bulk viscosity (E is the isentrope's -int p dV): p = p_H + GAMMA0 (E - E_H)
  MaterialData md = null_material(8930, gruneisen_copper(2.02));
  md.q1 = md.q2 = 0;
  Model mg = squeezed_cube(md, 50, 2e-6);
  worst = 0;
  double below = 0;
  run_cube(mg, [&](double mu, double p, double E) {
    if (mu <= 0) return;
    const double pH = hugoniot(mu), EH = pH * mu / (2 * (1 + mu));
    const double want = pH + 2.02 * (E - EH);
    worst = std::max(worst, std::fabs(p - want) / want);
    if (mu > 0.1) below = std::max(below, (pH - p) / pH);
  }, mu_max, mu_min);
  std::printf("Gruneisen GAMMA0 = 2.02: worst |p - (p_H + G0 (E - E_H))| / p = %.2e; isentrope below the Hugoniot by %.3f%% at mu > 0.1\n",
              worst, 100 * below);
  EXPECT_LT(worst, 1e-12);
  // the isentrope lies below the Hugoniot by a third-order amount: 0 < (p_H - p_s) / p_H < 2% at mu = 0.11
  EXPECT_GT(below, 0);
  EXPECT_LT(below, 0.02);
}

// *EOS_TABULATED (form 9): 7 points, EV1 = 0 down to -0.2, C convex, T falling, GAMMA 1.6.
EosData tabulated(double v0, double e0) {
  EosData e;
  e.form = 9;
  const double ev[7] = {0, -0.01, -0.03, -0.05, -0.08, -0.12, -0.2};
  const double c[7] = {0, 0.9e9, 2.9e9, 5.2e9, 9.4e9, 16e9, 34e9};
  const double t[7] = {1.0, 0.99, 0.96, 0.93, 0.9, 0.85, 0.8};
  for (int j = 0; j < 7; ++j) e.c[std::size_t(j)] = ev[j], e.c[std::size_t(10 + j)] = c[j], e.c[std::size_t(20 + j)] = t[j];
  e.c[30] = 1.6;
  e.e0 = e0;
  e.v0 = v0;
  return e;
}

// The table's p = C(eps_v) + GAMMA T(eps_v) E, by an independent lookup (end segments extended).
double tabulated_pressure(const EosData& e, double V, double E, int* segment = nullptr) {
  const double ev = std::log(V);
  int n = 1;
  while (n < 10 && e.c[std::size_t(n)] < e.c[std::size_t(n - 1)]) ++n;
  int i = 0;
  for (int j = 0; j + 1 < n; ++j)
    if (ev <= e.c[std::size_t(j)]) i = j;  // the last segment whose upper end is above ev
  if (segment) *segment = ev > e.c[0] ? -1 : ev < e.c[std::size_t(n - 1)] ? n - 1 : i;
  auto lerp = [&](int off) {
    const double x0 = e.c[std::size_t(i)], x1 = e.c[std::size_t(i + 1)];
    const double y0 = e.c[std::size_t(off + i)], y1 = e.c[std::size_t(off + i + 1)];
    return y0 + (y1 - y0) * (ev - x0) / (x1 - x0);
  };
  return lerp(10) + e.c[30] * lerp(20) * E;
}

TEST(EquationOfState, TabulatedLookupAndSlopes) {
  // the coefficients at points, between them and beyond both ends, and a' b' against differences
  const EosData e = tabulated(1, 0);
  MaterialConstants m;
  m.rho = 1000;
  derive_eos_constants(e, m);
  EXPECT_EQ(m.eos_form, 9);
  EXPECT_NEAR(m.K, 0.9e9 / 0.01, 1e-6);  // -dC/d eps_v at V = 1 (p0 = 0)
  double worst = 0, worst_slope = 0;
  for (double V : {1.03, 1.0, 0.995, std::exp(-0.01), 0.97, std::exp(-0.05), 0.93, 0.9, 0.85, std::exp(-0.2), 0.75}) {
    const double mu = 1 / V - 1, E = 3e8;
    double a, b, da, db;
    calc_eos_coefficients(m, mu, a, b, da, db);
    const double want = tabulated_pressure(e, V, E);
    worst = std::max(worst, std::fabs(a + b * E - want) / std::fabs(want));
    // slopes: central differences inside a segment (not at a point)
    const double h = 1e-7 * (1 + mu);
    double a1, b1, a2, b2, x;
    calc_eos_coefficients(m, mu + h, a1, b1, x, x);
    calc_eos_coefficients(m, mu - h, a2, b2, x, x);
    int seg_hi, seg_lo;
    tabulated_pressure(e, 1 / (1 + mu + h), 0, &seg_hi);
    tabulated_pressure(e, 1 / (1 + mu - h), 0, &seg_lo);
    if (seg_hi == seg_lo) {
      worst_slope = std::max(worst_slope, std::fabs((a1 - a2) / (2 * h) - da) / std::fabs(da));
      worst_slope = std::max(worst_slope, std::fabs((b1 - b2) / (2 * h) - db) / std::max(std::fabs(db), 1e-3));
    }
  }
  std::printf("tabulated EOS: worst |p - table| / p %.2e, slopes %.2e\n", worst, worst_slope);
  EXPECT_LT(worst, 1e-13);
  EXPECT_LT(worst_slope, 1e-6);
}

TEST(EquationOfState, TabulatedIsTheTableOfTheSolidsVolumeAndEnergy) {
  // squeezed to mu = 0.111 (eps_v = -0.105: 5 segments) and stretched to eps_v = +0.047 (beyond
  // EV1: the first segment extended); E0 = 1e8 and GAMMA T E
  for (double v0 : {1.0, 0.96}) {
    const EosData e = tabulated(v0, 1e8);
    Model m = squeezed_cube(null_material(1000, e), 10, 10e-6);
    double worst = 0, mu_max = 0, mu_min = 0;
    std::set<int> segments;
    run_cube(m, [&](double mu, double p, double E) {
      const double V = v0 / (1 + mu);  // the EOS's relative volume
      int seg;
      const double want = tabulated_pressure(e, V, E, &seg);
      segments.insert(seg);
      worst = std::max(worst, std::fabs(p - want) / std::max(std::fabs(want), 1e6));
    }, mu_max, mu_min);
    // the initial pressure: the table at V0 with E0
    Engine eng(m);
    ASSERT_EQ(eng.initialize(), StepStatus::ok);
    const double p0 = pressure(eng.state(), 0), p0_want = tabulated_pressure(e, v0, 1e8);
    std::printf("tabulated EOS, V0 = %.2f: eps_v %.4f .. %.4f, %zu segments (-1: beyond EV1), worst |p - table| / p %.2e; "
                "p0 %.6e (table %.6e)\n",
                v0, std::log(v0 / (1 + mu_max)), std::log(v0 / (1 + mu_min)), segments.size(), worst, p0, p0_want);
    EXPECT_LT(worst, 1e-12);
    EXPECT_NEAR(p0, p0_want, 1e-15 * std::fabs(p0_want) + 1e-9);
    EXPECT_GE(segments.size(), 5u);
    EXPECT_TRUE(segments.count(-1));
    if (v0 != 1) {
      EXPECT_GT(p0, 1e9);  // precompressed: eps_v = ln 0.96 = -0.041
    }
  }
}

TEST(EquationOfState, InitialRelativeVolumeShiftsTheLinearPolynomial) {
  // V0 = 0.9: the solid starts at mu = 1/0.9 - 1 = 0.111 (p0 = C1 mu0), its mass stays RO V
  const std::array<double, 7> c = {0, 2.2e9, 0, 0, 0, 0, 0};
  EosData e = linear_polynomial(c, 0);
  e.v0 = 0.9;
  Model m = squeezed_cube(null_material(1000, e), 10, 10e-6);
  double worst = 0, mu_max = 0, mu_min = 0;
  run_cube(m, [&](double mu, double p, double) {
    const double V = 0.9 / (1 + mu), want = c[1] * (1 / V - 1);
    worst = std::max(worst, std::fabs(p - want) / want);
  }, mu_max, mu_min);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  std::printf("linear polynomial, V0 = 0.9: p0 %.6e (C1 (1/V0 - 1) = %.6e), worst |p - C1 (V0^-1 V - 1)| / p %.2e\n",
              pressure(s, 0), c[1] / 9, worst);
  EXPECT_NEAR(pressure(s, 0), c[1] * (1 / 0.9 - 1), 1e-15 * c[1]);
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(s.mass_e[0], 1000 * 1e-9, 1e-21);  // RO times the initial volume
  // the sound speed: sqrt((1 + mu0) C1 / rho0) with the actual density (mass / volume)
  EXPECT_NEAR(s.mats[0].K, c[1] / 0.9, 1e-6 * c[1]);
}

TEST(EquationOfState, JohnsonCookTakesItsPressureFromTheEos) {
  // type 15, perfectly plastic (A = 100 MPa, B = 0), Gruneisen copper: p = p_H (GAMMA0 = 0)
  // and the deviatoric stress on the yield surface, sigma_zz - sigma_xx = -A in compression
  const MaterialType& t = material_type(15);
  MaterialData md;
  md.type = 15;
  set_param_defaults(md, t);
  md.rho = 8930, md.E = 117e9, md.nu = 0.35;
  param_value(md, *find_param(t, "G")) = 46e9;
  param_value(md, *find_param(t, "A")) = 1e8;
  md.eos = gruneisen_copper(0);
  Model m = squeezed_cube(md, 50, 2e-6);
  double worst = 0, worst_dev = 0, mu_max = 0, mu_min = 0;
  run_cube(m, [&](double mu, double p, double) {
    if (mu <= 0.01) return;
    const double den = 1 - 0.49 * mu;
    const double want = 8930.0 * 3940 * 3940 * mu * (1 + mu) / (den * den);
    worst = std::max(worst, std::fabs(p - want) / want);
  }, mu_max, mu_min);
  std::printf("Johnson-Cook + Gruneisen: worst |p - p_H| / p_H = %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
  // the deviatoric part after the run (stretched back into tension: on the yield surface)
  ScopedThreads one(1);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  for (int c = 0; c < 30; ++c) ASSERT_EQ(eng.step(), StepStatus::ok);
  const double* g = &eng.state().sig[0];
  worst_dev = std::fabs(std::fabs(g[0] - g[2]) - 1e8) / 1e8;
  std::printf("Johnson-Cook + Gruneisen: sigma_xx - sigma_zz = %.6e (A = 1e8)\n", g[0] - g[2]);
  EXPECT_LT(worst_dev, 1e-9);
}

// (b) Flyer plate: copper on copper, MAT_NULL + Gruneisen (GAMMA0 2.02), v = 500 m/s.  A column
// of 1 x 1 x 0.1 mm solids (lateral faces on rollers: uniaxial strain): flyer 20 mm (z < 0) at v,
// target 40 mm at rest, the interface nodes at v/2.  Hugoniot: up = v/2 = 250 m/s, Us = C + S1
// up = 4312.5 m/s, p = rho0 Us up = 9.628 GPa.  At t = 6 us the shock is 25.9 mm into the
// target; the release from the flyer's free back (from 4.64 us) has not reached the interface.
TEST(EquationOfState, FlyerPlateGivesTheHugoniotState) {
  ScopedThreads one(1);
  const double v = 500, C = 3940, S1 = 1.49, rho0 = 8930;
  const double up = v / 2, Us = C + S1 * up, pH = rho0 * Us * up;
  const double dz = 1e-4;
  const int nf = 200, nt = 400;
  Box b;
  b.lx = b.ly = 1e-3;
  b.nz = nf + nt;
  b.lz = dz * b.nz;
  b.z0 = -dz * nf;
  Model m = make_box_model(b, null_material(rho0, gruneisen_copper(2.02)), 6e-6, 4);
  set_velocity_field(m, [&](double, double, double z) -> std::array<double, 3> {
    return {0, 0, z < -0.5 * dz ? v : z < 0.5 * dz ? v / 2 : 0.0};
  });
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  // arrival time at each target solid: p crosses pH / 2 (linear in time between cycles)
  std::vector<double> arrival(std::size_t(nt), -1), p_prev(std::size_t(nt), 0);
  double t_prev = 0;
  StepStatus st;
  while ((st = eng.step()) == StepStatus::ok) {
    for (int k = 0; k < nt; ++k) {
      const double p = pressure(s, nf + k);
      if (arrival[std::size_t(k)] < 0 && p >= 0.5 * pH)
        arrival[std::size_t(k)] = t_prev + (s.time - t_prev) * (0.5 * pH - p_prev[std::size_t(k)]) / (p - p_prev[std::size_t(k)]);
      p_prev[std::size_t(k)] = p;
    }
    t_prev = s.time;
  }
  ASSERT_EQ(st, StepStatus::finished);
  // the shocked target between 3 and 20 mm: pressure and particle velocity
  double pm = 0, pmin = 1e300, pmax = 0;
  int np = 0;
  for (int k = 30; k < 200; ++k, ++np) {
    const double p = pressure(s, nf + k);
    pm += p, pmin = std::min(pmin, p), pmax = std::max(pmax, p);
  }
  pm /= np;
  double vm = 0;
  int nv = 0;
  for (int n = 0; n < s.nn; ++n) {
    const double z = m.z[std::size_t(n)];
    if (z > 3e-3 && z < 20e-3) vm += s.vz[std::size_t(n)], ++nv;
  }
  vm /= nv;
  // shock speed: least-squares line through (arrival time, position) of target solids 50-250
  double st_ = 0, sz = 0, stt = 0, stz = 0;
  int ns = 0;
  for (int k = 50; k < 250; ++k, ++ns) {
    const double t = arrival[std::size_t(k)], z = (k + 0.5) * dz;
    ASSERT_GT(t, 0) << k;
    st_ += t, sz += z, stt += t * t, stz += t * z;
  }
  const double us = (ns * stz - st_ * sz) / (ns * stt - st_ * st_);
  std::printf("flyer plate: up %.2f m/s (v/2 = %.1f, %+.3f%%), p %.4f GPa (rho0 Us up = %.4f, %+.3f%%; plateau %.4f..%.4f), "
              "Us from arrivals %.1f m/s (C + S1 up = %.1f, %+.3f%%)\n",
              vm, up, 100 * (vm / up - 1), pm * 1e-9, pH * 1e-9, 100 * (pm / pH - 1), pmin * 1e-9, pmax * 1e-9, us, Us,
              100 * (us / Us - 1));
  EXPECT_NEAR(vm / up, 1.0, 0.001);   // 0.1% (measured 1e-6)
  EXPECT_NEAR(pm / pH, 1.0, 0.001);   // 0.1% (measured 1e-5)
  EXPECT_NEAR(us / Us, 1.0, 0.002);   // 0.2% (measured 3e-5)
}

namespace {

// TNT detonation products (Dobratz & Crawford, LLNL Explosives Handbook, the constants LS-DYNA's
// manual quotes): A 371.2 GPa, B 3.231 GPa, R1 4.15, R2 0.95, OMEG 0.30, E0 7 GJ/m^3, rho 1630.
EosData jwl_tnt() {
  EosData e;
  e.form = 2;
  e.c = {3.712e11, 3.231e9, 4.15, 0.95, 0.30};
  e.e0 = 7e9;
  e.v0 = 1;
  return e;
}
double jwl_pressure(double V, double E) {
  const double A = 3.712e11, B = 3.231e9, R1 = 4.15, R2 = 0.95, w = 0.30;
  return A * (1 - w / (R1 * V)) * std::exp(-R1 * V) + B * (1 - w / (R2 * V)) * std::exp(-R2 * V) + w * E / V;
}
EosData sack_tuesday() {
  EosData e;
  e.form = 3;
  e.c = {2e9, 1.2, 0.5, 0.1, 0.4};
  e.e0 = 1e8;
  e.v0 = 1;
  return e;
}
double sack_pressure(double V, double E) {
  return 2e9 * std::pow(V, -1.2) * std::exp(-0.5 * V) * (1 - 0.1 / V) + 0.4 * E / V;
}

}  // namespace

// JWL (form 2) and Sack Tuesday (form 3): p = a(mu) + b(mu) E at V = 0.5 .. 3 and three
// energies against the formulas written out here (1e-14 relative), the slopes a', b' against
// central differences (1e-7 relative: the difference's truncation); then through the cycle: the
// squeezed cube's pressure is the formula of its own volume and energy (1e-12 relative).
TEST(EquationOfState, JwlAndSackTuesdayAreTheirFormulas) {
  struct Form { EosData e; double (*p)(double, double); const char* name; };
  const Form forms[] = {{jwl_tnt(), jwl_pressure, "JWL"}, {sack_tuesday(), sack_pressure, "Sack Tuesday"}};
  for (const Form& f : forms) {
    MaterialConstants m;
    m.rho = 1630;
    derive_eos_constants(f.e, m);
    EXPECT_EQ(m.eos_form, f.e.form);
    EXPECT_GT(m.K, 0);
    double worst = 0, worst_d = 0;
    for (double V : {0.5, 0.7, 0.9, 1.0, 1.3, 2.0, 3.0}) {
      for (double E : {0.0, 2e9, 7e9}) {
        const double mu = 1 / V - 1;
        double a, b, da, db;
        calc_eos_coefficients(m, mu, a, b, da, db);
        const double want = f.p(V, E);
        worst = std::max(worst, std::fabs(a + b * E - want) / std::fabs(want));
        // the slope in mu of p at fixed E
        const double h = 1e-5 * (1 + mu);
        const double dp = (f.p(1 / (1 + mu + h), E) - f.p(1 / (1 + mu - h), E)) / (2 * h);
        worst_d = std::max(worst_d, std::fabs(da + db * E - dp) / std::fabs(dp));
      }
    }
    std::printf("%s: worst |a + b E - p(V, E)| / p = %.2e, worst slope error %.2e\n", f.name, worst, worst_d);
    EXPECT_LT(worst, 1e-14) << f.name;
    EXPECT_LT(worst_d, 1e-7) << f.name;
  }
  std::printf("JWL TNT p(V = 1, E0 = 7 GJ/m^3) = %.6e Pa\n", jwl_pressure(1, 7e9));
  for (const Form& f : forms) {
    Model m = squeezed_cube(null_material(1630, f.e), 10, 10e-6);
    double worst = 0, mu_max = 0, mu_min = 0;
    run_cube(m, [&](double mu, double p, double E) {
      const double want = f.p(1 / (1 + mu), E);
      worst = std::max(worst, std::fabs(p - want) / std::fabs(want));
    }, mu_max, mu_min);
    std::printf("%s through the cycle: mu %.4f .. %.4f, worst |p - p(V, E)| / p = %.2e\n", f.name, mu_min, mu_max, worst);
    EXPECT_GT(mu_max, 0.1);
    EXPECT_LT(mu_min, -0.04);
    EXPECT_LT(worst, 1e-12) << f.name;
  }
}

// Type 15 with an equation of state and SPALL 3 (PC = -100 MPa): the cube stretched uniaxially.
// Before the spall the pressure is the linear polynomial's C1 mu, bounded below by PC; in the
// cycle the kernel's trial pressure reaches PC the point spalls, and from then on it is a rubble:
// the EOS pressure floored at 0 (no tension, not PC; round-off 1e-12 |PC|), no deviatoric stress; squeezed again, it
// takes compression as the polynomial says.
TEST(EquationOfState, SpalledJohnsonCookPointCarriesNoTension) {
  const MaterialType& t = material_type(15);
  MaterialData md;
  md.number = 1;
  md.type = 15;
  set_param_defaults(md, t);
  md.rho = 7800, md.E = 200e9, md.nu = 0.3, md.title = "Johnson-Cook + EOS";
  const double K = 200e9 / (3 * (1 - 0.6)), pc = -100e6;
  const std::map<std::string, double> values = {{"G", 200e9 / 2.6}, {"A", 400e6}, {"B", 0}, {"N", 1},
                                                {"PC", pc}, {"SPALL", 3}};
  for (const auto& [k, v] : values) param_value(md, *find_param(t, k)) = v;
  md.eos = linear_polynomial({0, K, 0, 0, 0, 0, 0}, 0);
  // stretch at 1 m/s for 2 us (mu to about -2e-3: K mu = -0.33 GPa, past PC), then squeeze
  const double T = 2e-6;
  Model m = squeezed_cube_path(md, {0, T, T * 1.0000001, 4 * T}, {1, 1, -1, -1}, 3.5 * T);
  solve_test::ScopedThreads one(1);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  const int spalled = 2;  // type 15's history values: temperature rise, damage, spalled
  int before = 0, rubble_tension = 0, rubble_compression = 0, spall_cycle = -1, cycles = 0;
  double worst_before = 0, worst_dev = 0, worst_comp = 0;
  StepStatus st;
  while ((st = eng.step()) == StepStatus::ok || st == StepStatus::finished) {
    ++cycles;
    const double mu = s.vol0[0] / s.vol[0] - 1, p = pressure(s, 0);
    const double* g = &s.sig[0];
    if (s.hist[std::size_t(spalled)] == 0) {
      ++before;
      EXPECT_GE(p, pc);
      worst_before = std::max(worst_before, std::fabs(p - std::max(K * mu, pc)) / std::fabs(pc));
    } else {
      if (spall_cycle < 0) spall_cycle = cycles;
      const double pm = -p;
      worst_dev = std::max({worst_dev, std::fabs(g[0] - pm), std::fabs(g[1] - pm), std::fabs(g[2] - pm),
                            std::fabs(g[3]), std::fabs(g[4]), std::fabs(g[5])});
      if (mu < 0) {
        ++rubble_tension;
        EXPECT_LE(std::fabs(p), 1e-12 * std::fabs(pc)) << "cycle " << cycles << " mu " << mu;  // 0 to round-off
      } else {
        ++rubble_compression;
        worst_comp = std::max(worst_comp, std::fabs(p - K * mu) / (K * 1e-4));
      }
    }
    if (st == StepStatus::finished) break;
  }
  std::printf("spalled JC + EOS: %d cycles before the spall (worst |p - max(K mu, PC)| / |PC| %.2e), "
              "spall in cycle %d, %d rubble cycles in tension (p = 0), %d in compression (worst %.2e), "
              "deviator %.2e Pa\n",
              before, worst_before, spall_cycle, rubble_tension, rubble_compression, worst_comp, worst_dev);
  EXPECT_GT(before, 5);
  EXPECT_LT(worst_before, 1e-9);
  EXPECT_GT(spall_cycle, 0);
  EXPECT_GT(rubble_tension, 5);
  EXPECT_GT(rubble_compression, 5);
  EXPECT_LT(worst_comp, 1e-6);
  EXPECT_LT(worst_dev, 1e-12 * std::fabs(pc));  // no deviator (round-off of s - mean)
}
