// Moving stonewalls (mass M, initial velocity V0 along the normal) against closed forms, with
// the elastic copper bar of BarOnWall (0.5 x 0.5 mm section, 20 mm, 2 x 2 x 100 hexahedra):
//  * Galilean: a very heavy wall moving at V0 into the bar at rest is the bar at -V0 on a
//    fixed wall seen from the wall: contact 2L/c0, the bar leaves at 2 V0 (within 3%, as the
//    fixed-wall test), the wall loses exactly the bar's momentum (M V0 = M V + m v_bar);
//  * a free wall of the bar's own mass, struck by the bar at v0: while the first wave runs
//    (t < 2L/c0) the wall obeys M dV/dt = rho c0 A (v0 - V), so V(2L/c0) = v0 (1 - e^-2) =
//    0.8647 v0 (Saint-Venant's bar on a rigid mass; within 3%); momentum of bar + wall kept to
//    1e-12 of m v0 at every cycle; energy ratio (the wall's kinetic energy is booked) within 2%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

constexpr double kL = 20e-3, kA = 0.5e-3;

Model bar_and_wall(double v_bar, double wall_mass, double wall_v0, double t_end) {
  MaterialData mat = copper_elastic();
  mat.hourglass_type = 3;
  Model m = make_box_model({2, 2, 100, kA, kA, kL, -kA / 2, -kA / 2, 0}, mat, t_end, 0);
  set_uniform_velocity(m, 0, 0, -v_bar);
  add_floor_wall(m);
  m.walls[0].mass = wall_mass;
  m.walls[0].v0 = wall_v0;
  return m;
}

}  // namespace

TEST(MovingWall, HeavyWallIntoABarAtRestIsTheGalileanFixedWall) {
  ScopedThreads one(1);
  const MaterialData mat = copper_elastic();
  const double c0 = std::sqrt(mat.E / mat.rho), t_contact = 2 * kL / c0, V0 = 5.0;
  const double m_bar = mat.rho * kA * kA * kL;
  Model m = bar_and_wall(0.0, 1e6 * m_bar, V0, 2.5 * t_contact);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  double t_last = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double t_before = eng.state().time;
    st = eng.step();
    if (eng.state().wall_force[0][2] != 0) t_last = 0.5 * (t_before + eng.state().time);
  }
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  const double vbar = momentum(s)[2] / total_mass(s);
  std::printf("heavy moving wall: contact %.3f us (2L/c0 %.3f), bar leaves at %.4f m/s (2 V0 = %.1f), wall %.7f m/s, "
              "wall moved %.4g m (V0 t %.4g), energy ratio %.5f\n",
              t_last * 1e6, t_contact * 1e6, vbar, 2 * V0, s.wall_vel[0], s.wall_disp[0], V0 * s.time, s.energy_ratio());
  EXPECT_NEAR(t_last / t_contact, 1.0, 0.03);
  EXPECT_NEAR(vbar / (2 * V0), 1.0, 0.03);
  // the wall gives up exactly the bar's momentum: M V0 = M V + m v_bar
  EXPECT_NEAR(s.wall_vel[0], V0 - m_bar * vbar / (1e6 * m_bar), 1e-12 * V0);
  EXPECT_NEAR(s.wall_disp[0], V0 * s.time, 1e-5 * V0 * s.time);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.02);
}

TEST(MovingWall, BarStrikingAFreeWallOfItsOwnMass) {
  ScopedThreads one(1);
  const MaterialData mat = copper_elastic();
  const double c0 = std::sqrt(mat.E / mat.rho), t2 = 2 * kL / c0, v0 = 5.0;
  const double m_bar = mat.rho * kA * kA * kL;
  Model m = bar_and_wall(v0, m_bar, 0.0, 3 * t2);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  const double p0 = momentum(s)[2];  // the wall is at rest
  double worst_p = 0, worst_e = 0, V_at_t2 = 0, t_prev = 0, V_prev = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    t_prev = s.time;
    V_prev = s.wall_vel[0];
    st = eng.step();
    // the wall's normal is +z: its momentum along z is M V (V < 0 once struck)
    const double p = momentum(s)[2] + m_bar * s.wall_vel[0];
    worst_p = std::max(worst_p, std::abs(p - p0) / (m_bar * v0));
    worst_e = std::max(worst_e, std::abs(s.energy_ratio() - 1));
    if (t_prev < t2 && s.time >= t2) V_at_t2 = V_prev + (s.wall_vel[0] - V_prev) * (t2 - t_prev) / (s.time - t_prev);
  }
  ASSERT_EQ(st, StepStatus::finished);
  const double expected = v0 * (1 - std::exp(-2.0));
  std::printf("bar on a free wall of its mass: wall speed at 2L/c0 %.4f m/s (v0 (1 - e^-2) = %.4f, %.2f%%), "
              "final wall %.4f m/s, momentum error %.2e, max |ratio - 1| %.2e\n",
              -V_at_t2, expected, 100 * (-V_at_t2 / expected - 1), -s.wall_vel[0], worst_p, worst_e);
  EXPECT_NEAR(-V_at_t2 / expected, 1.0, 0.03);
  EXPECT_LT(worst_p, 1e-12);
  EXPECT_LT(worst_e, 0.02);
}

// A node held along the wall's normal by its boundary code is a support, not mass: a heavy
// wall moving into the bar whose bottom nodes are fixed in z stops at those nodes (it never
// crosses them) and they stay where they are; the bar gets no momentum from it.
TEST(MovingWall, StopsAtNodesHeldAlongItsNormal) {
  ScopedThreads one(1);
  const MaterialData mat = copper_elastic();
  const double c0 = std::sqrt(mat.E / mat.rho);
  Model m = bar_and_wall(0.0, 1.0, 5.0, 0.5 * kL / c0);
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.z[std::size_t(i)] == 0.0) m.bc[std::size_t(i)] = 3;  // z fixed
  m.walls[0].tail[2] = -1e-5;  // the wall starts 10 um below the bar
  m.walls[0].head[2] = 1.0 - 1e-5;
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  double pz = 0, zmin = 1;
  for (int i = 0; i < s.nn; ++i) {
    pz += s.mass[std::size_t(i)] * s.vz[std::size_t(i)];
    zmin = std::min(zmin, s.z[std::size_t(i)]);
  }
  std::printf("wall stopped by held nodes: wall at %.3g m (gap 1e-5), speed %.3g m/s; bar momentum %.3g\n",
              -1e-5 + s.wall_disp[0], s.wall_vel[0], pz);
  EXPECT_EQ(zmin, 0.0);                               // the held nodes did not move
  EXPECT_LE(-1e-5 + s.wall_disp[0], 1e-15);           // the wall did not cross them
  EXPECT_EQ(s.wall_vel[0], 0.0);                      // it stopped on them
  EXPECT_EQ(pz, 0.0);                                 // and pushed nothing
}
