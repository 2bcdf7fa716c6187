// Physics verification of the fully integrated shell (LS-DYNA ELFORM 16, element/shell_fi.h)
// against closed forms: the membrane patch test, a thin cantilever strip on a coarse mesh against
// P L^3 / 3EI (no shear locking; ELFORM 2 alongside), the hourglass modes that the one-point
// shell leaves free, the energy balance of a free vibrating plate, a rigid rotation without
// strain, and the same bits on one and two threads.

#include <gtest/gtest.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "impact3d/element/shell_fi.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/shell_processing.h"
#include "tests/solve/shell_models.h"
#include "tests/support/threaded_run.h"

using namespace impact3d;
using namespace shell_test;

namespace {

constexpr double kPi = 3.14159265358979323846;

MaterialData fi_shell(int type = 1, int nip = 2) {
  MaterialData m = steel_shell(type, nip);
  m.shell_section.elform = 16;
  return m;
}

int add_constant_curve(Model& m) {
  LoadCurve lc;
  lc.number = int(m.load_curves.size()) + 1;
  lc.t = {0, 1e3};
  lc.f = {1, 1};
  m.load_curves.push_back(lc);
  m.control.numlc = int(m.load_curves.size());
  return lc.number - 1;
}

void add_velocity(Model& m, int node, std::array<double, 3> v) {
  InitialVelocity iv;
  iv.first = iv.last = node + 1;
  iv.v = v;
  m.init_velocities.push_back(iv);
}

StepStatus run_to_end(Engine& eng) {
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  return st;
}

}  // namespace

// Membrane patch test: a 2 x 2 patch of distorted quadrilaterals (inner node off centre) under
// the velocity field of a uniform strain rate gives every Gauss point of every shell the exact
// plane-stress stress (and the mean set the same), and the inner node no net force (to 1e-6 of a
// corner force, as for ELFORM 2: the frames at x^n turn by O(d dt) against the midpoint ones).
TEST(ShellFi, MembranePatchTestOnDistortedMesh) {
  Model m = make_plate(2, 2, 1.0, 1.0, 0.01, fi_shell(), 1.0);
  const std::size_t inner = std::size_t(plate_node(2, 1, 1));
  m.x[inner] = 0.62;
  m.y[inner] = 0.41;
  m.x[std::size_t(plate_node(2, 1, 0))] = 0.45;
  m.y[std::size_t(plate_node(2, 2, 1))] = 0.57;
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  State& s = eng.state();
  const double dxx = 2.0, dyy = -0.7, gxy = 1.3, dt = 1e-7;
  for (std::size_t k = 0; k < std::size_t(s.nn); ++k) {
    s.vx[k] = dxx * s.x[k] + 0.5 * gxy * s.y[k];
    s.vy[k] = 0.5 * gxy * s.x[k] + dyy * s.y[k];
    s.vz[k] = 0;
    s.x[k] += 0.5 * dt * s.vx[k];  // the midpoint geometry is the mesh above
    s.y[k] += 0.5 * dt * s.vy[k];
  }
  s.dt_half = dt;
  std::fill(s.shells.sig.begin(), s.shells.sig.end(), 0.0);
  calc_forces_for_shells(m, s);
  const MaterialConstants& mc = s.mats[0];
  const double c = mc.E / (1 - mc.nu * mc.nu) * dt;
  const double sxx = c * (dxx + mc.nu * dyy), syy = c * (dyy + mc.nu * dxx), sxy = mc.G * gxy * dt;
  double worst = 0;
  for (int k = 0; k < s.shells.ns; ++k) {
    const int nip = s.shells.nip[std::size_t(k)];
    ASSERT_EQ(s.shells.pt_width[std::size_t(k)], 1);  // ELFORM 16: shell by shell, its points together
    for (int p = 0; p < kShellFiPointSets * nip; ++p) {
      double q[5];
      for (int c = 0; c < 5; ++c) q[c] = s.shells.sig[shell_sig_at(s.shells, k, p, c)];
      const double tr = q[0] + q[1], det = q[0] * q[1] - q[2] * q[2];  // frame along edge 1-2
      worst = std::max({worst, std::fabs(tr - sxx - syy) / std::fabs(sxx),
                        std::fabs(det - (sxx * syy - sxy * sxy)) / (sxx * sxx), std::fabs(q[3]) / std::fabs(sxx),
                        std::fabs(q[4]) / std::fabs(sxx)});
    }
  }
  double f[3] = {0, 0, 0}, fmax = 0;
  for (int c2 = s.corner_start[inner]; c2 < s.corner_start[inner + 1]; ++c2) {
    const std::size_t q = std::size_t(s.corner_list[std::size_t(c2)]);
    f[0] += s.cfx[q];
    f[1] += s.cfy[q];
    f[2] += s.cfz[q];
    fmax = std::max({fmax, std::fabs(s.cfx[q]), std::fabs(s.cfy[q])});
  }
  const double fnet = std::fabs(f[0]) + std::fabs(f[1]) + std::fabs(f[2]);
  std::printf("ELFORM 16 patch: largest relative stress error %.2e, inner node net force %.2e of a corner force\n",
              worst, fnet / fmax);
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(fmax, 0);
  EXPECT_LT(fnet, 1e-6 * fmax);
}

namespace {

// A clamped strip L x b x h of nx x 1 shells (nu = 0: beam and plate stiffness agree), end load P
// (z) shared by the two tip nodes, damped near critically for the first mode: the static tip
// deflection.
double cantilever_tip(MaterialData mat, int nx, double L, double b, double h, double P) {
  mat.nu = 0;
  const double EI = mat.E * b * h * h * h / 12.0;
  const double omega1 = 1.875104068711961 * 1.875104068711961 * std::sqrt(EI / (mat.rho * b * h * L * L * L * L));
  Model m = make_plate(nx, 1, L, b, h, mat, 10 * 2 * kPi / omega1);
  m.rot_bc.assign(std::size_t(m.num_nodes()), 0);
  for (int j = 0; j <= 1; ++j) {
    m.bc[std::size_t(plate_node(nx, 0, j))] = 7;
    m.rot_bc[std::size_t(plate_node(nx, 0, j))] = 7;
    m.nodal_loads.push_back({plate_node(nx, nx, j), {0, 0, 1}, add_constant_curve(m), P / 2, 0});
  }
  m.damping.active = true;
  m.damping.d = 1.6 * omega1;
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  EXPECT_EQ(run_to_end(eng), StepStatus::finished);
  const State& s = eng.state();
  return 0.5 * (s.z[std::size_t(plate_node(nx, nx, 0))] + s.z[std::size_t(plate_node(nx, nx, 1))]);
}

}  // namespace

// Cantilever strip L = 1 m, b = 0.1 m, steel with nu = 0, 4 x 1 shells (elements 2.5 : 1), thin
// (L/h = 100) and very thin (L/h = 1000): the tip deflection against P L^3 / 3EI + P L / kGA.  A
// locking shear would make the thin strip orders of magnitude too stiff; the assumed shear keeps
// it at the four linear elements' discretization error (a Timoshenko beam of linear elements
// with a constant shear: 1 - 1/(4 n^2) = 0.9844 at n = 4).  Tolerances: 3 % of the closed form,
// 0.1 % of 1 - 1/(4 n^2).  ELFORM 2 (IHQ 4, QM 0.1) alongside (a one-point shear does not lock
// either: on rectangles the two agree).
TEST(ShellFi, ThinCantileverOnCoarseMeshDoesNotLock) {
  const double L = 1.0, b = 0.1;
  for (double h : {0.01, 0.001}) {
    MaterialData mat = fi_shell(1, 3);
    const double P = 1e-3 * mat.E * b * h * h * h / (L * L);  // tip deflection ~ 1e-3 L / 3 x 12
    const double EI = mat.E * b * h * h * h / 12.0, G = mat.E / 2.0;
    const double exact = P * L * L * L / (3 * EI) + P * L / (5.0 / 6.0 * G * b * h);
    const double w16 = cantilever_tip(mat, 4, L, b, h, P);
    MaterialData bt = steel_shell(1, 3);
    bt.hourglass_type = 4;
    bt.hourglass_coef = 0.1;
    const double w2 = cantilever_tip(bt, 4, L, b, h, P);
    std::printf("cantilever L/h %.0f, 4 x 1 shells: ELFORM 16 %.4f, ELFORM 2 (IHQ 4) %.4f x P L^3/3EI + P L/kGA\n", L / h,
                w16 / exact, w2 / exact);
    EXPECT_NEAR(w16 / exact, 1.0, 0.03);
    EXPECT_NEAR(w16 / exact, 1.0 - 1.0 / 64, 0.001);
  }
}

namespace {

// A free 8 x 8 plate (0.4 m, 10 mm) started in a checkerboard hourglass pattern of the nodes:
// out of plane (vz = +-1 m/s) or in plane (vx = +-1 m/s).  Returns the smallest and the largest
// kinetic energy over 0.2 ms (of the initial one), the hourglass energy at the end (of the
// initial kinetic one) and the step.
std::array<double, 4> hourglass_pattern_run(const MaterialData& mat, bool in_plane) {
  const int n = 8;
  Model m = make_plate(n, n, 0.4, 0.4, 0.01, mat, 2e-4);
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double v = (i % (n + 1) + i / (n + 1)) % 2 ? 1.0 : -1.0;
    add_velocity(m, i, in_plane ? std::array<double, 3>{v, 0, 0} : std::array<double, 3>{0, 0, v});
  }
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  const double ke0 = eng.state().kinetic;
  double ke_min = 1, ke_max = 1, dt = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    ke_min = std::min(ke_min, eng.state().kinetic / ke0);
    ke_max = std::max(ke_max, eng.state().kinetic / ke0);
    dt = std::max(dt, eng.state().dt_half);  // the last step is cut to the end time
  }
  EXPECT_EQ(st, StepStatus::finished);
  return {ke_min, ke_max, eng.state().hourglass / ke0, dt};
}

}  // namespace

// The checkerboard patterns are zero-energy modes of the one-point shell: ELFORM 2 without
// hourglass control (QM 0) keeps their kinetic energy (> 0.99 of it at every step).  ELFORM 16
// has no such modes: the motion turns into strain energy and back (the kinetic energy falls below
// 5 % of the initial one in plane, below 25 % out of plane, where the rotations take their share
// of the kinetic energy); the part's hourglass settings (here IHQ 1, QM 0.1) are ignored: no
// hourglass energy.  The in-plane pattern is an exact mode of the free 2 x 2 integrated mesh
// (every shell in its hourglass mode u = xi eta, lumped masses equal): omega^2 = (4/3)
// (E/(1 - nu^2) + G) / (rho a^2), and central differences carry the half-step kinetic energy up
// to 1/(1 - (omega dt/2)^2) of the initial one (1.574 at the default step, omega dt = 1.21):
// the largest sampled value within 1 % of it.  Out of plane the pattern turns into bending and
// rotations, whose half-step kinetic energy swings too: at most 1.05 of the initial one (1.0176
// over these 0.2 ms with the rotary inertia m max(h^2/12, A/8) per corner, 1.0000 with the
// earlier m (h^2 + A)/12; over 4 ms 1.090 and 1.107: a swing, not a growth).
// (Both modes sit near the element's highest frequencies: the run's energy ratio swings by
// O(omega dt) there, as ELFORM 2's does with IHQ 4; the energy balance is checked on a smooth
// mode below.)
TEST(ShellFi, HourglassModesOfTheOnePointShellAreResisted) {
  MaterialData bt = steel_shell();
  bt.hourglass_coef = 0;
  MaterialData fi = fi_shell();
  fi.hourglass_type = 1;
  fi.hourglass_coef = 0.1;
  for (bool in_plane : {false, true}) {
    const auto free = hourglass_pattern_run(bt, in_plane), full = hourglass_pattern_run(fi, in_plane);
    std::printf("%s checkerboard: smallest KE/KE0 ELFORM 2 (QM 0) %.4f, ELFORM 16 %.4f (largest %.6f)\n",
                in_plane ? "in-plane" : "out-of-plane", free[0], full[0], full[1]);
    EXPECT_GT(free[0], 0.99);
    EXPECT_LT(full[0], in_plane ? 0.05 : 0.25);
    EXPECT_EQ(full[2], 0.0);
    if (!in_plane) {
      EXPECT_LT(full[1], 1.05);
      continue;
    }
    const double a = 0.05, G = fi.E / (2 * (1 + fi.nu));
    const double omega = std::sqrt(4.0 / 3.0 * (fi.E / (1 - fi.nu * fi.nu) + G) / (fi.rho * a * a));
    const double x = 0.5 * omega * full[3], peak = 1 / (1 - x * x);
    std::printf("  in-plane mode: omega dt %.4f, 1/(1 - (omega dt/2)^2) %.4f, largest KE/KE0 %.4f\n", 2 * x, peak, full[1]);
    EXPECT_NEAR(full[1], peak, 0.01 * peak);
  }
}

// The step: ELFORM 16 runs at ELFORM 2's element step (A / longest edge / plate wave speed).  A
// distorted, slightly warped 8 x 8 plate started with random velocities and rotation rates stays
// bounded for 4 ms (over 400 cycles) at 1.2 x that step (kinetic energy below 2 x the initial),
// and blows up at 1.4 x (as ELFORM 2 does: both stable at 1.2, unstable at 1.3), so the default
// TSSF 0.9 keeps the same margin as for ELFORM 2.
TEST(ShellFi, StableAtTheBelytschkoTsayStep) {
  auto run = [](int elform, double tssf) {
    MaterialData mat = steel_shell(1, 3);
    mat.shell_section.elform = elform;
    mat.hourglass_type = 4;
    Model m = make_plate(8, 8, 0.4, 0.4, 0.01, mat, 4e-3);
    m.control.tssf = tssf;
    unsigned long long seed = 12345;
    auto rnd = [&]() {
      seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
      return double(seed >> 11) / 9007199254740992.0 - 0.5;
    };
    for (std::size_t i = 0; i < std::size_t(m.num_nodes()); ++i) {
      m.x[i] += 0.01 * rnd();
      m.y[i] += 0.01 * rnd();
      m.z[i] += 0.002 * rnd();
    }
    m.init_omega.assign(std::size_t(m.num_nodes()), {0, 0, 0});
    for (int i = 0; i < m.num_nodes(); ++i) {
      add_velocity(m, i, {rnd(), rnd(), rnd()});
      m.init_omega[std::size_t(i)] = {10 * rnd(), 10 * rnd(), 10 * rnd()};
    }
    Engine eng(m);
    EXPECT_EQ(eng.initialize(), StepStatus::ok);
    const double ke0 = eng.state().kinetic;
    double ke_max = 0;
    for (StepStatus st = StepStatus::ok; st == StepStatus::ok && ke_max < 100;) {
      st = eng.step();
      ke_max = std::max(ke_max, eng.state().kinetic / ke0);
    }
    return ke_max;
  };
  const double fi12 = run(16, 1.2), fi14 = run(16, 1.4), bt12 = run(2, 1.2);
  std::printf("random start, largest KE/KE0: ELFORM 16 at 1.2 x the step %.3f, at 1.4 x %.3g; ELFORM 2 at 1.2 x %.3f\n",
              fi12, fi14, bt12);
  EXPECT_LT(fi12, 2.0);
  EXPECT_LT(bt12, 2.0);
  EXPECT_GT(fi14, 10.0);
}

// A simply supported square plate (0.1 m, 20 x 20 shells, 5 mm; w = 0 on the edges) started in
// its first mode w = sin(pi x/a) sin(pi y/a) (with the matching rotation rates) exchanges kinetic
// and strain energy over 2 ms (several periods: the kinetic energy falls below 1 % of the initial
// one) with its energy ratio within 1 +- 0.01 (measured 6.3e-3, first order in the step: 3.1e-3 at
// half the step; ELFORM 2 the same to 1e-5).
TEST(ShellFi, FreeVibratingPlateKeepsItsEnergy) {
  const int n = 20;
  const double a = 0.1, v0 = 1.0;
  Model m = make_plate(n, n, a, a, 0.005, fi_shell(1, 3), 2e-3);
  m.init_omega.assign(std::size_t(m.num_nodes()), {0, 0, 0});
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double x = kPi * m.x[std::size_t(i)] / a, y = kPi * m.y[std::size_t(i)] / a;
    const int ix = i % (n + 1), iy = i / (n + 1);
    if (ix == 0 || ix == n || iy == 0 || iy == n) m.bc[std::size_t(i)] = 3;  // z fixed
    add_velocity(m, i, {0, 0, v0 * std::sin(x) * std::sin(y)});
    // theta_x = dw/dy, theta_y = -dw/dx
    m.init_omega[std::size_t(i)] = {v0 * kPi / a * std::sin(x) * std::cos(y), -v0 * kPi / a * std::cos(x) * std::sin(y), 0};
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const double ke0 = eng.state().kinetic;
  double ke_min = 1, worst = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    ke_min = std::min(ke_min, eng.state().kinetic / ke0);
    worst = std::max(worst, std::fabs(eng.state().energy_ratio() - 1));
  }
  ASSERT_EQ(st, StepStatus::finished);
  std::printf("vibrating plate, ELFORM 16: smallest KE/KE0 %.4f, largest |energy ratio - 1| %.2e over %d cycles\n", ke_min,
              worst, eng.state().cycle);
  EXPECT_LT(ke_min, 0.01);
  EXPECT_LT(worst, 0.01);
}

// A 1 m plate (4 x 4, 10 mm) spun by 90 degrees about an in-plane axis at 10 rad/s: no strain
// (the centrifugal stress rho w^2 R^2 ~ 2e5 Pa only), energy kept, the corner where the rotation
// takes it.  Tolerances as ELFORM 2's test: 2e6 Pa, 1e-3, 2 mm.
TEST(ShellFi, RigidRotationByNinetyDegreesLeavesNoStrain) {
  const int n = 4;
  const double L = 1.0, w = 10.0;
  Model m = make_plate(n, n, L, L, 0.01, fi_shell(), 0.5 * kPi / w);
  m.init_omega.assign(std::size_t(m.num_nodes()), {0, w, 0});
  for (int i = 0; i < m.num_nodes(); ++i) add_velocity(m, i, {0, 0, -w * (m.x[std::size_t(i)] - 0.5 * L)});
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  ASSERT_EQ(run_to_end(eng), StepStatus::finished);
  const State& s = eng.state();
  double smax = 0;
  for (double v : s.shells.sig) smax = std::max(smax, std::fabs(v));
  std::printf("ELFORM 16 rigid rotation by 90 degrees: largest stress %.3e Pa, energy ratio %.6f\n", smax,
              s.energy_ratio());
  EXPECT_LT(smax, 2e6);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-3);
  const std::size_t corner = std::size_t(plate_node(n, n, 0));
  EXPECT_NEAR(s.x[corner], 0.5 * L, 2e-3 * L);
  EXPECT_NEAR(s.z[corner], -0.5 * L, 2e-3 * L);
}

// Threads: a 70 x 70 plate of yielding ELFORM 16 shells (past the threshold where the shell pass
// runs on several threads) gives the same bits on one and on two threads.
TEST(ShellFi, SameBitsForAnyThreadCount) {
  const int n = 70;
  MaterialData mat = fi_shell(3, 3);
  mat.sigma_y = 20e6;
  Model m = make_plate(n, n, 1.0, 1.0, 0.002, mat, 1.0);
  for (int j = 0; j <= n; ++j) m.bc[std::size_t(plate_node(n, 0, j))] = 7;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double x = m.x[std::size_t(i)], y = m.y[std::size_t(i)];
    add_velocity(m, i, {5.0 * x, 0, 5.0 * x * (1 + y)});
  }
  const State a = test_support::run_cycles_on_threads(m, 1, 60), b = test_support::run_cycles_on_threads(m, 2, 60);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.shells.sig, b.shells.sig);
  EXPECT_EQ(a.shells.eps_p, b.shells.eps_p);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_GT(*std::max_element(a.shells.eps_p.begin(), a.shells.eps_p.end()), 0.0);
}

namespace {

// The shell materials, each set for a stretch to about 1 % (steel-like except the rubber).
MaterialData material_of_type(int type) {
  MaterialData md = steel_shell(type, 3);
  const MaterialType& t = material_type(type);
  set_param_defaults(md, t);
  md.rho = 7850, md.E = 210e9, md.nu = 0.3;
  if (type == 3 || type == 24) md.sigma_y = 250e6, md.E_tan = 2e9, md.beta = 0.5;
  if (type == 18) {
    param_value(md, *find_param(t, "K")) = 500e6;
    param_value(md, *find_param(t, "N")) = 0.2;
  }
  if (type == 27) {
    md.rho = 1100, md.nu = 0.49;
    param_value(md, *find_param(t, "A")) = 0.5e6;
    param_value(md, *find_param(t, "B")) = 0.1e6;
  }
  return md;
}

// One parallelogram shell whose corners move at v = D X (prescribed velocities, X the initial
// positions: a uniform stretch with shear to about 1 %), 50 us, z held.
State stretched_parallelogram(MaterialData md, int elform) {
  md.shell_section.elform = elform;
  md.hourglass_coef = 0;
  Model m = make_plate(1, 1, 0.01, 0.01, 0.002, md, 5e-5);
  m.x[2] += 0.003, m.x[3] += 0.003;
  const int curve = add_constant_curve(m);
  for (int i = 0; i < 4; ++i) {
    const double x = m.x[std::size_t(i)], y = m.y[std::size_t(i)];
    m.bc[std::size_t(i)] = 3;  // z
    for (int a = 0; a < 2; ++a) {
      PrescribedMotion pm;
      pm.node = i;
      pm.dir = {a == 0 ? 1.0 : 0.0, a == 1 ? 1.0 : 0.0, 0};
      pm.curve = curve;
      pm.scale = a == 0 ? 200 * x + 40 * y : 40 * x - 60 * y;
      m.prescribed_motions.push_back(pm);
    }
  }
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  EXPECT_EQ(run_to_end(eng), StepStatus::finished);
  return eng.state();
}

}  // namespace

// ELFORM 16 takes every material ELFORM 2 takes through the same point update: under a uniform
// stretch (a parallelogram, so that the four Gauss points and the one-point rule see the same
// rates and a constant stress gives both the same corner forces) each of its four Gauss points,
// and their mean, carries ELFORM 2's stress and plastic strain, to 1e-9 of the largest stress:
// elastic (1), plastic-kinematic (3, beta 0.5), power law (18), piecewise-linear (24), Mooney-
// Rivlin (27).
TEST(ShellFi, EveryShellMaterialGivesTheOnePointStressUnderUniformStretch) {
  for (int type : {1, 3, 18, 24, 27}) {
    const MaterialData md = material_of_type(type);
    const State fi = stretched_parallelogram(md, 16), bt = stretched_parallelogram(md, 2);
    const int nip = 3;
    double smax = 0, worst = 0, eps_worst = 0, eps_max = 0;
    for (double v : bt.shells.sig) smax = std::max(smax, std::fabs(v));
    for (int set = 0; set < kShellFiPointSets; ++set)
      for (int p = 0; p < nip; ++p) {
        for (int c = 0; c < 5; ++c)
          worst = std::max(worst, std::fabs(fi.shells.sig[shell_sig_at(fi.shells, 0, nip * set + p, c)] - bt.shells.sig[shell_sig_at(bt.shells, 0, p, c)]));
        if (!bt.shells.eps_p.empty()) {
          const double ep_bt = bt.shells.eps_p[shell_point_at(bt.shells, 0, p)];
          eps_max = std::max(eps_max, ep_bt);
          eps_worst = std::max(eps_worst, std::fabs(fi.shells.eps_p[shell_point_at(fi.shells, 0, nip * set + p)] - ep_bt));
        }
      }
    std::printf("type %d: largest stress %.4e, ELFORM 16 points vs ELFORM 2 %.2e of it; plastic strain %.4e, difference %.2e\n",
                type, smax, worst / smax, eps_max, eps_worst);
    EXPECT_GT(smax, 0.0);
    EXPECT_LT(worst, 1e-9 * smax) << "type " << type;
    EXPECT_LT(eps_worst, 1e-9) << "type " << type;
    if (type == 3 || type == 18 || type == 24) {
      EXPECT_GT(eps_max, 1e-3) << "type " << type;
    }
  }
}
