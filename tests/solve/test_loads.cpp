// Loads and prescribed motions (issue 16) against closed forms: free fall under a body load,
// a step force on the end of a free elastic bar, a bar end driven at constant velocity, a
// pressure on a confined column, prescribed displacement and acceleration histories, loads and
// prescribed motions of rigid bodies, birth and death times; and the energy balance (external
// work booked so that the energy ratio stays 1).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "impact3d/solve/engine.h"
#include "impact3d/solve/loads.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

// curve 1: the constant 1 (two points; the last segment extends beyond t = 1)
void add_unit_curve(Model& m) {
  LoadCurve lc;
  lc.number = int(m.load_curves.size()) + 1;
  lc.t = {0, 1};
  lc.f = {1, 1};
  m.load_curves.push_back(lc);
  m.control.numlc = int(m.load_curves.size());
}
int add_curve(Model& m, std::vector<double> t, std::vector<double> f) {
  LoadCurve lc;
  lc.number = int(m.load_curves.size()) + 1;
  lc.t = std::move(t);
  lc.f = std::move(f);
  m.load_curves.push_back(lc);
  m.control.numlc = int(m.load_curves.size());
  return lc.number - 1;
}

MaterialData steel_nu0() {
  MaterialData m;
  m.number = 1;
  m.type = 1;
  m.rho = 7800;
  m.E = 200e9;
  m.nu = 0.0;  // one element across with nu = 0: the bar wave speed is sqrt(E / rho) exactly
  return m;
}

std::vector<int> nodes_at_z(const Model& m, double z) {
  std::vector<int> out;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (std::fabs(m.z[std::size_t(n)] - z) < 1e-12) out.push_back(n);
  return out;
}

double mean_vz(const State& s, const std::vector<int>& nodes) {
  double v = 0;
  for (int n : nodes) v += s.vz[std::size_t(n)];
  return v / double(nodes.size());
}

}  // namespace

TEST(CurveValue, InterpolatesAndExtendsEndSegments) {
  LoadCurve lc;
  lc.t = {0, 1, 3};
  lc.f = {0, 2, 0};
  EXPECT_DOUBLE_EQ(value_of_curve(lc, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(value_of_curve(lc, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(value_of_curve(lc, 3.0), 0.0);
  EXPECT_DOUBLE_EQ(value_of_curve(lc, 4.0), -1.0);   // last segment extended (LS-DYNA)
  EXPECT_DOUBLE_EQ(value_of_curve(lc, -0.5), -1.0);  // first segment extended
}

// Free fall: a body load g along -z (a positive *LOAD_BODY_Z of 9.81) on an unconstrained
// block.  Central differences integrate a constant acceleration exactly, so every node is at
// z0 - g t^2 / 2 to rounding; the external work equals the kinetic energy (ratio 1).
TEST(Loads, FreeFallUnderBodyLoadIsExact) {
  Model m = make_box_model({2, 2, 2, 0.02, 0.02, 0.02, 0, 0, 0}, copper_elastic(), 2e-3);
  add_unit_curve(m);
  BodyLoad g;
  g.dir = {0, 0, 1};
  g.curve = 0;
  g.scale = 9.81;
  m.body_loads.push_back(g);
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double t = s.time;
  for (int n = 0; n < s.nn; ++n) {
    const std::size_t k = std::size_t(n);
    EXPECT_NEAR(s.z[k] - m.z[k], -0.5 * 9.81 * t * t, 1e-12 * 9.81 * t * t) << "node " << n;
    EXPECT_NEAR(s.x[k], m.x[k], 1e-15);
  }
  EXPECT_NEAR(s.external_work, s.kinetic, 1e-9 * s.kinetic);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
  EXPECT_LT(max_abs_stress(s), 1e-3);  // a rigid translation strains nothing
}

// *LOAD_BODY_PARTS: a body load acts only on the listed materials.
TEST(Loads, BodyLoadActsOnListedMaterialsOnly) {
  // (2 x 2 x 2 blocks: a single free hexahedron is not stable at the solid time step, whose
  // 1-D estimate L / c lies below the highest frequency of one element with 8 free nodes)
  Model m = make_box_model({2, 2, 2, 0.01, 0.01, 0.01, 0, 0, 0}, copper_elastic(), 1e-3);
  MaterialData second = copper_elastic();
  second.number = 2;
  m.materials.push_back(second);
  test_support::add_box(m, {2, 2, 2, 0.01, 0.01, 0.01, 0.1, 0, 0}, 1);
  m.control.nmmat = 2;
  add_unit_curve(m);
  m.body_loads.push_back({{0, 0, 1}, 0, 9.81, 0});
  m.body_load_materials = {1};
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double t = s.time;
  for (int n = 0; n < 27; ++n) EXPECT_EQ(s.z[std::size_t(n)], m.z[std::size_t(n)]);
  for (int n = 27; n < 54; ++n) EXPECT_NEAR(s.z[std::size_t(n)] - m.z[std::size_t(n)], -0.5 * 9.81 * t * t, 1e-12);
}

// *DAMPING_GLOBAL on a free block translating at v0: f = -D m v, so each component decays as
// v0 exp(-D s t) (s its direction factor); the explicit update gives (1 - D s dt) per cycle,
// within D s t * D s dt / 2 of the exponential (here < 2e-4: tolerance 1e-3).  A uniform
// velocity strains nothing, and the damping's work is booked as external work: the energy
// ratio is 1 to round-off (the booked work equals the kinetic energy lost, cycle by cycle).
TEST(Loads, GlobalDampingDecaysAFreeBodyExponentially) {
  Model m = make_box_model({2, 2, 2, 0.02, 0.02, 0.02, 0, 0, 0}, copper_elastic(), 2e-3);
  set_uniform_velocity(m, 10, -5, 2);
  m.damping.active = true;
  m.damping.d = 200;
  m.damping.factor = {1, 1, 0.5};
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double t = s.time - 0.5 * s.dt_half;  // v^{n+1/2}
  const double e = std::exp(-200 * t), ez = std::exp(-100 * t);
  for (int n = 0; n < s.nn; ++n) {
    const std::size_t k = std::size_t(n);
    EXPECT_NEAR(s.vx[k], 10 * e, 1e-3 * 10 * e) << "node " << n;
    EXPECT_NEAR(s.vy[k], -5 * e, 1e-3 * 5 * e);
    EXPECT_NEAR(s.vz[k], 2 * ez, 1e-3 * 2 * ez);
  }
  // displacement: the integral of v0 exp(-D t) = v0 (1 - exp(-D t)) / D, same tolerance
  EXPECT_NEAR(s.x[0] - m.x[0], 10 * (1 - std::exp(-200 * s.time)) / 200, 1e-3 * 0.05);
  EXPECT_LT(max_abs_stress(s), 1e-3);
  EXPECT_LT(s.external_work, 0);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// D from a load curve, a ramp D(t) = D1 t / T: v = v0 exp(-D1 t^2 / (2 T)).
TEST(Loads, GlobalDampingFromACurve) {
  const double T = 2e-3, D1 = 400;
  Model m = make_box_model({2, 2, 2, 0.02, 0.02, 0.02, 0, 0, 0}, copper_elastic(), T);
  set_uniform_velocity(m, 0, 0, 3);
  m.damping.active = true;
  m.damping.curve = add_curve(m, {0, T}, {0, D1});
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double t = s.time - 0.5 * s.dt_half;
  const double v = 3 * std::exp(-D1 * t * t / (2 * T));
  for (int n = 0; n < s.nn; ++n) EXPECT_NEAR(s.vz[std::size_t(n)], v, 1e-3 * v) << "node " << n;
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// A step force F on the end z = L of a free elastic bar (uniaxial stress): the loaded end
// moves at F / (rho c A); the wave reaches the free end z = 0 at L / c, which then moves at
// twice that.  Tolerances: 3% on the velocities (the front is smeared over a few elements
// and rings behind; the plateau is averaged over a window), 2% on the arrival time.
TEST(Loads, StepForceOnFreeBarEnd) {
  const MaterialData mat = steel_nu0();
  const double a = 0.002, L = 0.2;
  const int nz = 200;
  const double c = std::sqrt(mat.E / mat.rho);
  const double t_end = 1.5 * L / c;
  Model m = make_box_model({1, 1, nz, a, a, L, 0, 0, 0}, mat, t_end);
  add_unit_curve(m);
  const double F = 2000.0;  // N: stress 500 MPa / (elastic, no yield)
  const std::vector<int> end = nodes_at_z(m, L), far = nodes_at_z(m, 0);
  for (int n : end) m.nodal_loads.push_back({n, {0, 0, 1}, 0, F / 4, 0});
  const double v1 = F / (mat.rho * c * a * a);

  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  double v_end_sum = 0;
  int v_end_n = 0;
  double t_arrival = -1, vprev = 0, tprev = 0, v_far_sum = 0;
  int v_far_n = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double t = s.time;
    if (t > 0.3 * L / c && t < 0.9 * L / c) v_end_sum += mean_vz(s, end), ++v_end_n;
    const double vf = mean_vz(s, far);
    if (t_arrival < 0 && vf >= v1) t_arrival = tprev + (t - tprev) * (v1 - vprev) / (vf - vprev);
    if (t > 1.2 * L / c) v_far_sum += vf, ++v_far_n;
    vprev = vf;
    tprev = t;
  }
  ASSERT_EQ(st, StepStatus::finished);
  ASSERT_GT(v_end_n, 0);
  ASSERT_GT(v_far_n, 0);
  EXPECT_NEAR(v_end_sum / v_end_n, v1, 0.03 * v1);
  EXPECT_NEAR(v_far_sum / v_far_n, 2 * v1, 0.03 * 2 * v1);
  EXPECT_NEAR(t_arrival, L / c, 0.02 * L / c);
  // momentum = impulse F t exactly (the internal forces cancel)
  // v^{n+1/2}: the impulse up to t^{n+1/2}
  const double t_half = eng.state().time - 0.5 * eng.state().dt_half;
  EXPECT_NEAR(momentum(eng.state())[2], F * t_half, 1e-9 * F * t_half);
  EXPECT_NEAR(eng.state().energy_ratio(), 1.0, 0.01);
}

// The end z = 0 of a bar driven at constant velocity V (prescribed, VAD 0): the far end
// leaves at L / c with 2 V.  The reaction's work balances the energy.
TEST(PrescribedMotion, BarEndDrivenAtConstantVelocity) {
  const MaterialData mat = steel_nu0();
  const double a = 0.002, L = 0.2, V = 1.0;
  const int nz = 200;
  const double c = std::sqrt(mat.E / mat.rho);
  Model m = make_box_model({1, 1, nz, a, a, L, 0, 0, 0}, mat, 1.5 * L / c);
  add_unit_curve(m);
  const std::vector<int> driven = nodes_at_z(m, 0), far = nodes_at_z(m, L);
  for (int n : driven) {
    PrescribedMotion pm;
    pm.node = n;
    pm.dir = {0, 0, 1};
    pm.kind = MotionKind::velocity;
    pm.curve = 0;
    pm.scale = V;
    m.prescribed_motions.push_back(pm);
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  double t_arrival = -1, vprev = 0, tprev = 0, v_far_sum = 0;
  int v_far_n = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    for (int n : driven) ASSERT_DOUBLE_EQ(s.vz[std::size_t(n)], V);
    const double vf = mean_vz(s, far);
    if (t_arrival < 0 && vf >= V) t_arrival = tprev + (s.time - tprev) * (V - vprev) / (vf - vprev);
    if (s.time > 1.2 * L / c) v_far_sum += vf, ++v_far_n;
    vprev = vf;
    tprev = s.time;
  }
  ASSERT_EQ(st, StepStatus::finished);
  ASSERT_GT(v_far_n, 0);
  EXPECT_NEAR(v_far_sum / v_far_n, 2 * V, 0.03 * 2 * V);
  EXPECT_NEAR(t_arrival, L / c, 0.02 * L / c);
  // the driven end moved V t
  for (int n : driven) EXPECT_NEAR(eng.state().z[std::size_t(n)], V * eng.state().time, 1e-12);
  EXPECT_NEAR(eng.state().energy_ratio(), 1.0, 0.01);
}

// A pressure p on the top of a confined column (uniaxial strain, base fixed): the stress behind
// the wave is -p, the top moves at p / (rho c_p); the top displacement is a triangle wave
// between 0 and 2 p L / M whose mean over one period 4 L / c_p is the static p L / M.
TEST(Loads, PressureOnConfinedColumn) {
  const MaterialData mat = copper_elastic();
  const Elastic el = elastic_of(mat);
  const double a = 0.01, L = 0.1, p = 50e6;
  const int nz = 100;
  const double cp = std::sqrt(el.M / mat.rho);
  const double period = 4 * L / cp;
  Model m = make_box_model({1, 1, nz, a, a, L, 0, 0, 0}, mat, period, 4);  // code 4: x, y fixed
  for (int n : nodes_at_z(m, 0)) m.bc[std::size_t(n)] = 7;
  add_unit_curve(m);
  const test_support::Box box{1, 1, nz, a, a, L, 0, 0, 0};
  for (const auto& f : box.top()) {
    PressureLoad pl;
    pl.nodes = f;
    pl.curve = 0;
    pl.scale = p;
    m.pressure_loads.push_back(pl);
  }
  const std::vector<int> top = nodes_at_z(m, L);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  double u_int = 0, t_prev = 0, v_top_sum = 0;
  int v_top_n = 0;
  StepStatus st = StepStatus::ok;
  const int mid = nz / 2;
  double sig_mid = 0;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double u = s.z[std::size_t(top[0])] - L;
    u_int += u * (s.time - t_prev);
    t_prev = s.time;
    if (s.time > 0.2 * L / cp && s.time < 0.8 * L / cp) v_top_sum += mean_vz(s, top), ++v_top_n;
    if (s.time < 0.9 * L / cp) sig_mid = s.sig[6 * std::size_t(mid) + 2];
  }
  ASSERT_EQ(st, StepStatus::finished);
  const double u_static = -p * L / el.M;
  EXPECT_NEAR(u_int / eng.state().time, u_static, 0.03 * std::fabs(u_static));
  EXPECT_NEAR(v_top_sum / v_top_n, -p / (mat.rho * cp), 0.03 * p / (mat.rho * cp));
  EXPECT_NEAR(sig_mid, -p, 0.03 * p);
  EXPECT_NEAR(eng.state().energy_ratio(), 1.0, 0.01);
}

// A prescribed displacement history d(t) (VAD 2) and an acceleration history (VAD 1): the
// node follows them (displacement to rounding; acceleration integrated by central differences,
// exact for a constant acceleration).
TEST(PrescribedMotion, DisplacementAndAccelerationHistories) {
  Model m = make_box_model({2, 2, 2, 0.01, 0.01, 0.01, 0, 0, 0}, copper_elastic(), 1e-4);
  const int ramp = add_curve(m, {0, 1e-4}, {0, 1e-5});   // 10 um over the run
  add_unit_curve(m);
  for (int n : nodes_at_z(m, 0.01)) {
    PrescribedMotion pm;
    pm.node = n;
    pm.dir = {0, 0, 1};
    pm.kind = MotionKind::displacement;
    pm.curve = ramp;
    m.prescribed_motions.push_back(pm);
  }
  for (int n : nodes_at_z(m, 0)) {
    PrescribedMotion pm;
    pm.node = n;
    pm.dir = {1, 0, 0};
    pm.kind = MotionKind::acceleration;
    pm.curve = 1;
    pm.scale = 1000;  // m/s^2 along x
    m.prescribed_motions.push_back(pm);
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    for (int n : nodes_at_z(m, 0.01)) ASSERT_NEAR(s.z[std::size_t(n)] - 0.01, 1e-5 * s.time / 1e-4, 1e-12 * 1e-5);
    for (int n : nodes_at_z(m, 0))
      ASSERT_NEAR(s.x[std::size_t(n)] - m.x[std::size_t(n)], 0.5 * 1000 * s.time * s.time, 1e-15);
  }
  ASSERT_EQ(st, StepStatus::finished);
}

// Birth and death: a velocity prescribed only in [birth, death]; before it the node is free
// (at rest), after it the block keeps the momentum it was given.
TEST(PrescribedMotion, BirthAndDeathTimes) {
  Model m = make_box_model({2, 2, 2, 0.01, 0.01, 0.01, 0, 0, 0}, copper_elastic(), 3e-4);
  add_unit_curve(m);
  for (int n = 0; n < m.num_nodes(); ++n) {
    PrescribedMotion pm;
    pm.node = n;
    pm.dir = {0, 1, 0};
    pm.curve = 0;
    pm.scale = 2.0;
    pm.birth = 1e-4;
    pm.death = 2e-4;
    m.prescribed_motions.push_back(pm);
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double t = eng.state().time;
    st = eng.step();
    const State& s = eng.state();
    if (t < 1e-4) ASSERT_EQ(s.vy[0], 0.0);
    else ASSERT_NEAR(s.vy[0], 2.0, 1e-12) << "t " << t;  // prescribed, then kept (free, no force)
  }
  ASSERT_EQ(st, StepStatus::finished);
  EXPECT_NEAR(eng.state().energy_ratio(), 1.0, 1e-9);
}

namespace {
// A rigid cube (type 20) of side 0.02 m, its mass rho V.
Model rigid_cube(double t_end) {
  MaterialData r = copper_elastic();
  r.type = 20;
  Model m = make_box_model({2, 2, 2, 0.02, 0.02, 0.02, 0, 0, 0}, r, t_end);
  add_unit_curve(m);
  return m;
}
}  // namespace

// *LOAD_RIGID_BODY: a force at the centre of mass accelerates the body without turning it.
TEST(Loads, ForceOnRigidBody) {
  Model m = rigid_cube(1e-3);
  const double F = 100.0, M = 8930 * 8e-6;
  m.rigid_body_loads.push_back({0, {1, 0, 0}, 0, F, 0});
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double t = s.time;
  ASSERT_EQ(s.rigid.size(), 1u);
  EXPECT_NEAR(s.rigid[0].vcom[0], F / M * (t - 0.5 * s.dt_half), 1e-9 * F / M * t);
  EXPECT_NEAR(s.rigid[0].com[0] - 0.01, 0.5 * F / M * t * t, 1e-9 * 0.5 * F / M * t * t);
  for (double w : s.rigid[0].omega) EXPECT_NEAR(w, 0.0, 1e-9);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// *BOUNDARY_PRESCRIBED_MOTION_RIGID: the body's centre moves with the prescribed velocity.
TEST(PrescribedMotion, RigidBodyVelocity) {
  Model m = rigid_cube(1e-3);
  const int ramp = add_curve(m, {0, 1e-3}, {0, 5});  // v = 5000 t
  PrescribedMotion pm;
  pm.rigid_material = 0;
  pm.dir = {0, 0, 1};
  pm.curve = ramp;
  m.prescribed_motions.push_back(pm);
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const double t = s.time;
  // v^{n+1/2} = 5000 t^{n+1/2}: the centre is at 2500 t^2 exactly for a linear velocity
  EXPECT_NEAR(s.rigid[0].com[2] - 0.01, 2500 * t * t, 1e-9 * 2500 * t * t);
  for (int n : s.rigid[0].nodes) EXPECT_DOUBLE_EQ(s.vz[std::size_t(n)], s.rigid[0].vcom[2]);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-6);
}
