// The fully integrated selective-reduced hexahedron (*SECTION_SOLID ELFORM 2,
// element/hex_sri.h): patch test on a distorted mesh, rigid rotation, the bar wave speed, a
// cantilever's static deflection against beam theory (and the one-point element's), a
// uniaxial plastic test against the closed form, energy conservation of a free vibration, the
// same bits for 1 and 2 threads, and a restart dump that continues bit for bit.

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "impact3d/element/hex_sri.h"
#include "impact3d/init/initialize.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/element_processing.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

MaterialData sri(MaterialData md) {
  md.solid_elform = 2;
  md.hourglass_coef = 0;
  return md;
}

// A 2 x 2 x 2 box of unit cubes with every node but the corners moved (a distorted mesh whose
// interior node (1, 1, 1) has all eight solids around it).
Model distorted_box(const MaterialData& md) {
  Box b;
  b.nx = b.ny = b.nz = 2;
  b.lx = b.ly = b.lz = 2;
  Model m = make_box_model(b, md, 1.0);
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) {
        const int inner = (i == 1) + (j == 1) + (k == 1);
        if (inner == 0) continue;
        const std::size_t n = std::size_t(b.node(i, j, k));
        const double s = 0.11 * inner;
        m.x[n] += s * std::sin(1.3 * n + 0.2);
        m.y[n] += s * std::cos(2.1 * n + 0.5);
        m.z[n] += s * std::sin(0.7 * n + 1.1);
      }
  return m;
}

// One element pass with x^n = X + dt/2 A X and v^{n+1/2} = A X: the midpoint configuration is
// the mesh X and the velocity gradient there exactly A.
void pass_with_gradient(const Model& m, State& s, const double A[3][3], double dt) {
  for (int n = 0; n < s.nn; ++n) {
    const std::size_t k = std::size_t(n);
    const double X[3] = {m.x[k], m.y[k], m.z[k]};
    double v[3];
    for (int i = 0; i < 3; ++i) v[i] = A[i][0] * X[0] + A[i][1] * X[1] + A[i][2] * X[2];
    s.x[k] = X[0] + 0.5 * dt * v[0], s.y[k] = X[1] + 0.5 * dt * v[1], s.z[k] = X[2] + 0.5 * dt * v[2];
    s.vx[k] = v[0], s.vy[k] = v[1], s.vz[k] = v[2];
  }
  s.dt_half = dt;
  calc_forces_for_elems(m, s);
}

// The net internal force on node n (its corners summed) and the largest corner force.
std::array<double, 4> node_force(const State& s, int n) {
  std::array<double, 4> f{};
  for (int c = s.corner_start[std::size_t(n)]; c < s.corner_start[std::size_t(n) + 1]; ++c) {
    const std::size_t ci = std::size_t(s.corner_list[std::size_t(c)]);
    f[0] += s.cfx[ci], f[1] += s.cfy[ci], f[2] += s.cfz[ci];
  }
  for (std::size_t c = 0; c < s.cfx.size(); ++c)
    f[3] = std::max({f[3], std::fabs(s.cfx[c]), std::fabs(s.cfy[c]), std::fabs(s.cfz[c])});
  return f;
}

}  // namespace

// Patch test: a linear velocity (displacement increment) field on the distorted mesh gives
// every Gauss point of every solid the stress dt (lambda tr D I + 2 G D), D = sym(A), to 1e-10,
// and the interior node's corner forces cancel to 1e-10 of the largest corner force.
TEST(HexSri, PatchTestConstantStressOnDistortedMesh) {
  ScopedThreads one(1);
  const MaterialData md = sri(copper_elastic());
  const Model m = distorted_box(md);
  State s;
  initialize_state(m, s);
  ASSERT_EQ(s.pt_sig.size(), std::size_t(6 * 8 * 8));
  const double A[3][3] = {{0.3, 0.1, -0.2}, {0.05, -0.1, 0.15}, {0.12, -0.07, 0.2}};
  const double dt = 1e-3;
  pass_with_gradient(m, s, A, dt);
  const Elastic el = elastic_of(md);
  const double lambda = el.K - 2 * el.G / 3, tr = A[0][0] + A[1][1] + A[2][2];
  const double D[6] = {A[0][0], A[1][1], A[2][2], 0.5 * (A[0][1] + A[1][0]), 0.5 * (A[1][2] + A[2][1]),
                       0.5 * (A[2][0] + A[0][2])};
  double expect[6], big = 0;
  for (int c = 0; c < 6; ++c) {
    expect[c] = dt * ((c < 3 ? lambda * tr : 0.0) + 2 * el.G * D[c]);
    big = std::max(big, std::fabs(expect[c]));
  }
  double worst = 0;
  for (std::size_t p = 0; p < s.pt_eps_p.size(); ++p)
    for (int c = 0; c < 6; ++c) worst = std::max(worst, std::fabs(s.pt_sig[6 * p + std::size_t(c)] - expect[c]));
  std::printf("patch test: largest point stress error %.3g of %.3g\n", worst, big);
  EXPECT_LT(worst, 1e-10 * big);
  const std::array<double, 4> f = node_force(s, 13);  // node (1, 1, 1)
  std::printf("patch test: interior node force %.3g %.3g %.3g (largest corner force %.3g)\n", f[0], f[1], f[2], f[3]);
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::fabs(f[i]), 1e-10 * f[3]);
}

// Rigid rotation: a skew velocity gradient leaves every point unstrained (stress below 1e-12 of
// what the same gradient's symmetric magnitude would give); and a one-element cube pre-stressed
// sigma_xx = S turned 90 degrees about z in 20000 steps carries sigma_yy = S within 1%.
TEST(HexSri, RigidRotationWithoutStrain) {
  ScopedThreads one(1);
  const MaterialData md = sri(copper_elastic());
  {
    const Model m = distorted_box(md);
    State s;
    initialize_state(m, s);
    const double w = 0.4, A[3][3] = {{0, -w, 0.2}, {w, 0, -0.3}, {-0.2, 0.3, 0}};
    const double dt = 1e-3;
    pass_with_gradient(m, s, A, dt);
    double worst = 0;
    for (double v : s.pt_sig) worst = std::max(worst, std::fabs(v));
    std::printf("rigid rotation: largest point stress %.3g (E w dt = %.3g)\n", worst, md.E * w * dt);
    EXPECT_LT(worst, 1e-12 * md.E * w * dt);
  }
  Box b;
  Model m = make_box_model(b, md, 1.0);
  State s;
  initialize_state(m, s);
  const double S = 1e9;
  for (std::size_t p = 0; p < 8; ++p) s.pt_sig[6 * p] = S;
  const int N = 20000;
  const double dth = 0.5 * M_PI / N, dt = 1e-6;
  auto place = [&](double th, int n, double out[3]) {
    const double X = m.x[std::size_t(n)] - 0.5, Y = m.y[std::size_t(n)] - 0.5;
    out[0] = std::cos(th) * X - std::sin(th) * Y, out[1] = std::sin(th) * X + std::cos(th) * Y, out[2] = m.z[std::size_t(n)];
  };
  for (int step = 0; step < N; ++step) {
    for (int n = 0; n < s.nn; ++n) {
      double a[3], c[3];
      place(step * dth, n, a);
      place((step + 1) * dth, n, c);
      const std::size_t k = std::size_t(n);
      s.x[k] = c[0], s.y[k] = c[1], s.z[k] = c[2];
      s.vx[k] = (c[0] - a[0]) / dt, s.vy[k] = (c[1] - a[1]) / dt, s.vz[k] = (c[2] - a[2]) / dt;
    }
    s.dt_half = dt;
    calc_forces_for_elems(m, s);
  }
  std::printf("rotated 90 degrees: sigma xx %.4g yy %.4g xy %.4g (S = %.3g)\n", s.sig[0], s.sig[1], s.sig[3], S);
  EXPECT_NEAR(s.sig[1], S, 0.01 * S);
  EXPECT_NEAR(s.sig[0], 0.0, 0.01 * S);
  EXPECT_NEAR(s.sig[3], 0.0, 0.01 * S);
}

// Bar velocity c0 = sqrt(E / rho) in a copper bar of 1 x 1 mm section, one element across,
// 200 layers, 1 m/s onto a rigid wall (the one-point element's test, tests/solve/test_waves.cpp):
// the time the half-amplitude front takes from layer 50 to layer 150.  3%, as there.
TEST(HexSri, BarWaveSpeed) {
  ScopedThreads one(1);
  const MaterialData mat = sri(copper_elastic());
  const double L = 0.1, a = 1e-3, v = 1.0;
  const int nz = 200;
  const double c0 = std::sqrt(mat.E / mat.rho);
  Model m = make_box_model({1, 1, nz, a, a, L, -a / 2, -a / 2, 0}, mat, 0.95 * L / c0);
  set_uniform_velocity(m, 0, 0, -v);
  add_floor_wall(m);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const int e1 = 50, e2 = 150;
  const double half = -0.5 * mat.rho * c0 * v;
  double t1 = -1, t2 = -1, p1 = 0, p2 = 0, tp = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double s1 = s.sig[6 * e1 + 2], s2 = s.sig[6 * e2 + 2];
    if (t1 < 0 && s1 <= half) t1 = tp + (s.time - tp) * (half - p1) / (s1 - p1);
    if (t2 < 0 && s2 <= half) t2 = tp + (s.time - tp) * (half - p2) / (s2 - p2);
    p1 = s1, p2 = s2, tp = s.time;
  }
  ASSERT_EQ(st, StepStatus::finished);
  ASSERT_GT(t2, t1);
  ASSERT_GT(t1, 0);
  const double c = (e2 - e1) * (L / nz) / (t2 - t1);
  std::printf("ELFORM 2 bar velocity: measured %.1f m/s, c0 %.1f m/s (%.2f%%)\n", c, c0, 100 * (c / c0 - 1));
  EXPECT_NEAR(c / c0, 1.0, 0.03);
}

namespace {

// A steel cantilever L x h x h (x along the axis, clamped at x = 0), nx x nh x nh solids, a tip
// load P in z suddenly applied, spread over the tip face's nodes by their area shares; returns
// the tip's z displacement averaged over `periods` periods of the first bending mode (an
// undamped system oscillates about its static deflection: the mean is the static one).
double cantilever_mean_tip_deflection(const MaterialData& md, int nx, int nh, double P, double periods,
                                      double& beam_theory) {
  const double L = 10, h = 1;
  Box b;
  b.nx = nx, b.ny = nh, b.nz = nh;
  b.lx = L, b.ly = h, b.lz = h;
  b.y0 = -h / 2, b.z0 = -h / 2;
  Model m = make_box_model(b, md, 1.0);
  for (int k = 0; k <= nh; ++k)
    for (int j = 0; j <= nh; ++j) m.bc[std::size_t(b.node(0, j, k))] = 7;
  LoadCurve lc;
  lc.number = 1;
  lc.t = {0, 1e9};
  lc.f = {1, 1};
  m.load_curves = {lc};
  for (int k = 0; k <= nh; ++k)
    for (int j = 0; j <= nh; ++j) {
      NodalLoad nl;
      nl.node = b.node(nx, j, k);
      nl.dir = {0, 0, 1};
      nl.curve = 0;
      nl.scale = P / (nh * nh) * ((j == 0 || j == nh) ? 0.5 : 1.0) * ((k == 0 || k == nh) ? 0.5 : 1.0);
      m.nodal_loads.push_back(nl);
    }
  const double I = h * h * h * h / 12, A = h * h, G = md.E / (2 * (1 + md.nu));
  beam_theory = P * L * L * L / (3 * md.E * I) + P * L / (5.0 / 6.0 * G * A);  // Timoshenko
  const double T1 = 2 * M_PI / (1.8751 * 1.8751 * std::sqrt(md.E * I / (md.rho * A * L * L * L * L)));
  m.control.end_time = periods * T1;
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  std::vector<int> tip;
  for (int k = 0; k <= nh; ++k)
    for (int j = 0; j <= nh; ++j) tip.push_back(b.node(nx, j, k));
  double integral = 0, tprev = 0, wprev = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    double w = 0;
    for (int n : tip) w += s.z[std::size_t(n)] - m.z[std::size_t(n)];
    w /= double(tip.size());
    integral += 0.5 * (w + wprev) * (s.time - tprev);
    wprev = w, tprev = s.time;
  }
  EXPECT_EQ(st, StepStatus::finished);
  return integral / tprev;
}

MaterialData steel() {
  MaterialData m;
  m.number = 1;
  m.type = 1;
  m.rho = 7800;
  m.E = 2e11;
  m.nu = 0.3;
  m.title = "steel";
  return m;
}

}  // namespace

// Cantilever L/h = 10 under a tip load: the time-mean tip deflection over 6 periods of the
// first mode against Timoshenko beam theory.  ELFORM 2, 20 x 2 x 2 cubic solids: within 5%.
// ELFORM 1 with viscous hourglass control (type 1, 0.1), the same mesh: bending is its
// hourglass mode, held only by viscosity: far off (more than 10 times ELFORM 2's error).
TEST(HexSri, CantileverStaticDeflection) {
  ScopedThreads one(1);
  const double P = 1e5;  // tip deflection ~ 2 mm on 10 m: small deformation
  double theory = 0;
  const double w2 = cantilever_mean_tip_deflection(sri(steel()), 20, 2, P, 6, theory);
  MaterialData p1 = steel();
  p1.hourglass_type = 1;
  p1.hourglass_coef = 0.1;
  const double w1 = cantilever_mean_tip_deflection(p1, 20, 2, P, 6, theory);
  std::printf("cantilever 20x2x2: beam theory %.5g, ELFORM 2 %.5g (%.2f%%), ELFORM 1 IHQ 1 %.5g (%.2f%%)\n", theory, w2,
              100 * (w2 / theory - 1), w1, 100 * (w1 / theory - 1));
  EXPECT_NEAR(w2 / theory, 1.0, 0.05);
  EXPECT_GT(std::fabs(w1 / theory - 1), 10 * std::fabs(w2 / theory - 1));
}

// Uniaxial plastic test: a cube (1 mm) on symmetry planes pulled in x at 10 /s after a ramp,
// type 3 isotropic hardening (sigma_y 0.4 GPa, E_tan 2 GPa).  Closed form in log strain
// eps = ln(l / l0) (the hypoelastic rate form integrates D to it): sigma = E eps below
// sigma_y / E, sigma_y + E_tan (eps - sigma_y / E) above.  Within 0.5% of sigma_y at every
// 0.1% of strain to 2%; the points' plastic strain (their mean is the element's) within 1%.
TEST(HexSri, UniaxialPlasticClosedForm) {
  ScopedThreads one(1);
  MaterialData md = sri(copper_plastic());
  md.E_tan = 2e9;
  const double L = 1e-3, rate = 10, t_end = 0.0205 / rate;
  Box b;
  b.lx = b.ly = b.lz = L;
  Model m = make_box_model(b, md, t_end);
  // x = 0: x fixed; y = 0: y; z = 0: z (codes 1, 2, 3 and their combinations)
  for (int n = 0; n < m.num_nodes(); ++n) {
    const std::size_t k = std::size_t(n);
    const bool fx = m.x[k] == 0, fy = m.y[k] == 0, fz = m.z[k] == 0;
    m.bc[k] = fx && fy && fz ? 7 : fx && fy ? 4 : fy && fz ? 5 : fz && fx ? 6 : fx ? 1 : fy ? 2 : fz ? 3 : 0;
  }
  LoadCurve lc;
  lc.number = 1;
  const double ramp = 2e-5;
  lc.t = {0, ramp, 1};
  lc.f = {0, 1, 1};
  m.load_curves = {lc};
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.x[std::size_t(n)] == L) {
      PrescribedMotion pm;
      pm.node = n;
      pm.dir = {1, 0, 0};
      pm.scale = rate * L;
      m.prescribed_motions.push_back(pm);
    }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const double E = md.E, sy = md.sigma_y, Et = md.E_tan, Ep = E * Et / (E - Et);
  double next = 0.001, worst = 0, worst_ep = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double eps = std::log(s.x[1] / L);  // node (1, 0, 0)
    if (eps < next) continue;
    next += 0.001;
    const double expect = eps < sy / E ? E * eps : sy + Et * (eps - sy / E);
    worst = std::max(worst, std::fabs(s.sig[0] - expect));
    const double ep = std::max(0.0, (expect - sy) / Ep);
    for (double p : s.pt_eps_p) worst_ep = std::max(worst_ep, std::fabs(p - ep));
    if (eps > 0.019) std::printf("eps %.4f: sigma %.5g, closed form %.5g; eps_p %.5g (%.5g)\n", eps, s.sig[0], expect, s.eps_p[0], ep);
  }
  ASSERT_EQ(st, StepStatus::finished);
  std::printf("uniaxial plastic: largest stress error %.3g (sigma_y %.3g), plastic strain %.3g\n", worst, sy, worst_ep);
  EXPECT_LT(worst, 0.005 * sy);
  EXPECT_LT(worst_ep, 0.01 * 0.0166);
  EXPECT_GT(eng.state().eps_p[0], 0.015);
}

namespace {

// A free steel block 10 x 2 x 2 m of 20 x 4 x 4 ELFORM 2 solids, set vibrating in bending and
// twisting by an initial velocity field with zero net momentum.
Model vibrating_block(int nx, int ny, int nz, double t_end) {
  Box b;
  b.nx = nx, b.ny = ny, b.nz = nz;
  b.lx = 10, b.ly = 2, b.lz = 2;
  b.x0 = -5, b.y0 = -1, b.z0 = -1;
  Model m = make_box_model(b, sri(steel()), t_end);
  set_velocity_field(m, [](double x, double y, double z) {
    return std::array<double, 3>{0.5 * y * z, 2.0 * (x * x / 25 - 1.0 / 3) - 0.3 * x * z, 0.3 * x * y};
  });
  return m;
}

}  // namespace

// Energy conservation: a cantilever 10 x 1 x 1 m of 20 x 2 x 2 solids released with the
// velocity 0.1 (x / L)^2 m/s in z vibrates freely for 0.5 s (about 3 periods of its first mode,
// 6900 cycles).  The energy ratio (kinetic, internal, bulk viscosity over the initial) swings
// with the kinetic energy taken at the half step (the one-point element's ratio swings as much
// on the same model: 0.998-1.003); its drift, the mean over the second half of the run against
// the mean over the first, stays within 1e-3, and the swing within 5e-3.
TEST(HexSri, FreeVibrationConservesEnergy) {
  ScopedThreads one(1);
  Box b;
  b.nx = 20, b.ny = 2, b.nz = 2, b.lx = 10, b.ly = 1, b.lz = 1, b.y0 = -0.5, b.z0 = -0.5;
  Model m = make_box_model(b, sri(steel()), 0.5);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.x[std::size_t(n)] == 0) m.bc[std::size_t(n)] = 7;
  set_velocity_field(m, [](double x, double, double) { return std::array<double, 3>{0, 0, 0.1 * x * x / 100}; });
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  double lowest = 1, highest = 1, peak_internal = 0, sum[2] = {0, 0};
  int count[2] = {0, 0};
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const double r = eng.state().energy_ratio();
    lowest = std::min(lowest, r);
    highest = std::max(highest, r);
    const int half = eng.state().time > 0.25;
    sum[half] += r, ++count[half];
    peak_internal = std::max(peak_internal, eng.state().internal);
  }
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  const double drift = sum[1] / count[1] - sum[0] / count[0];
  std::printf("free vibration: %d cycles, energy ratio in [%.7f, %.7f], drift %.3g, peak internal / initial %.3f\n",
              s.cycle, lowest, highest, drift, peak_internal / s.initial_total);
  EXPECT_GT(peak_internal, 0.5 * s.initial_total);  // the energy did move into the solids
  EXPECT_LT(std::fabs(drift), 1e-3);
  EXPECT_NEAR(lowest, 1.0, 5e-3);
  EXPECT_NEAR(highest, 1.0, 5e-3);
}

namespace {
State run_cycles(const Model& m, int threads, int cycles) {
  omp_set_num_threads(threads);
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  for (int c = 0; c < cycles; ++c) EXPECT_EQ(eng.step(), StepStatus::ok);
  omp_set_num_threads(1);
  return eng.state();
}
}  // namespace

// 64 x 12 x 11 = 8448 ELFORM 2 solids (past the element pass's threshold for threads), 15
// cycles of the vibrating field on type 3 (yielding): the same bits on 1 and 2 threads.
TEST(HexSri, SameBitsForOneAndTwoThreads) {
  Model m = vibrating_block(64, 12, 11, 1.0);
  m.materials[0] = sri(copper_plastic());
  m.materials[0].sigma_y = 1e6;  // yields at once
  set_velocity_field(m, [](double x, double y, double z) {
    return std::array<double, 3>{5 * y * z, 20.0 * (x * x / 25 - 1.0 / 3) - 3 * x * z, 3 * x * y};
  });
  ASSERT_GT(m.num_hexes(), 8192);
  const State a = run_cycles(m, 1, 15), c = run_cycles(m, 2, 15);
  EXPECT_EQ(a.x, c.x);
  EXPECT_EQ(a.pt_sig, c.pt_sig);
  EXPECT_EQ(a.pt_eps_p, c.pt_eps_p);
  EXPECT_EQ(a.sig, c.sig);
  EXPECT_EQ(a.internal, c.internal);
  EXPECT_GT(*std::max_element(a.pt_eps_p.begin(), a.pt_eps_p.end()), 0.0);
}

// A restart dump after 200 cycles (the points' stresses, plastic strains and back stresses in
// it) restores a State that goes on to the same bits as the uninterrupted run.
TEST(HexSri, RestartDumpContinuesBitForBit) {
  ScopedThreads one(1);
  Model m = vibrating_block(10, 2, 2, 1.0);
  m.materials[0] = sri(copper_plastic());
  m.materials[0].sigma_y = 1e6;
  m.materials[0].beta = 0.5;  // kinematic part: back stresses per point
  Engine a(m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  for (int c = 0; c < 200; ++c) ASSERT_EQ(a.step(), StepStatus::ok);
  ASSERT_FALSE(a.state().pt_back.empty());
  DumpHeader h;
  h.deck_name = "sri.k";
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/hex_sri_restart_dump";
  write_restart_dump(path, h, a.state(), a.contact().restart_data());
  Engine b(m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  for (int c = 0; c < 200; ++c) {
    ASSERT_EQ(a.step(), StepStatus::ok);
    ASSERT_EQ(b.step(), StepStatus::ok);
  }
  EXPECT_EQ(a.state().x, b.state().x);
  EXPECT_EQ(a.state().pt_sig, b.state().pt_sig);
  EXPECT_EQ(a.state().pt_back, b.state().pt_back);
  EXPECT_EQ(a.state().pt_eps_p, b.state().pt_eps_p);
  EXPECT_EQ(a.state().internal, b.state().internal);
  EXPECT_GT(*std::max_element(a.state().pt_eps_p.begin(), a.state().pt_eps_p.end()), 0.0);
}
