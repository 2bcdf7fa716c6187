// Initial velocities on the nodes of a rigid body that are not a rigid motion (a deck may give
// them node by node): the body keeps the momentum and angular momentum of the given nodal
// velocities (LS-DYNA's rule), its nodes start with that rigid motion before any energy is
// booked, and the input check warns (2014).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"
#include "test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {
Model rigid_box(double T) {
  MaterialData rigid;
  rigid.number = 1;
  rigid.type = 20;
  rigid.rho = 8930;
  rigid.E = 117e9;
  rigid.nu = 0.35;
  Box b;
  b.nx = b.ny = b.nz = 2;
  b.lx = b.ly = b.lz = 2e-3;
  b.x0 = b.y0 = b.z0 = -1e-3;
  return make_box_model(b, rigid, T);
}
}  // namespace

TEST(RigidInitialVelocity, NonRigidNodalVelocitiesBecomeTheRigidMotionWithTheirMomenta) {
  ScopedThreads threads(1);
  Model m = rigid_box(2e-5);
  const Eigen::Vector3d V(3.0, -1.0, 2.0), w(2000.0, 500.0, -1000.0);
  set_velocity_field(m, [&](double x, double y, double z) {
    const Eigen::Vector3d v = V + w.cross(Eigen::Vector3d(x, y, z));
    std::array<double, 3> r{v(0), v(1), v(2)};
    if (x > 0.5e-3 && y > 0.5e-3 && z > 0.5e-3) r[0] += 40.0;  // one corner node off the rigid motion
    return r;
  });

  Diagnostics diag;
  check_model(m, diag);
  EXPECT_EQ(diag.count(2014), 1);

  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  // momentum and angular momentum (about the centre of mass) of the given nodal velocities,
  // with the lumped masses
  Eigen::Vector3d P = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
  double M = 0;
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    const auto& iv = m.init_velocities[k];
    P += s.mass[k] * Eigen::Vector3d(iv.v[0], iv.v[1], iv.v[2]);
    c += s.mass[k] * Eigen::Vector3d(m.x[k], m.y[k], m.z[k]);
    M += s.mass[k];
  }
  c /= M;
  Eigen::Vector3d L = Eigen::Vector3d::Zero(), Ls = Eigen::Vector3d::Zero(), Ps = Eigen::Vector3d::Zero();
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    const auto& iv = m.init_velocities[k];
    const Eigen::Vector3d r = Eigen::Vector3d(m.x[k], m.y[k], m.z[k]) - c;
    L += s.mass[k] * r.cross(Eigen::Vector3d(iv.v[0], iv.v[1], iv.v[2]) - P / M);
    const Eigen::Vector3d vs(s.vx[k], s.vy[k], s.vz[k]);
    Ls += s.mass[k] * r.cross(vs - P / M);
    Ps += s.mass[k] * vs;
  }
  EXPECT_LT((Ps - P).norm(), 1e-12 * P.norm());
  EXPECT_LT((Ls - L).norm(), 1e-10 * L.norm());
  // the nodal velocities are a rigid motion: v = vcom + omega x r
  ASSERT_EQ(s.rigid.size(), 1u);
  const auto& rb = s.rigid[0];
  const Eigen::Vector3d vc(rb.vcom[0], rb.vcom[1], rb.vcom[2]), om(rb.omega[0], rb.omega[1], rb.omega[2]);
  double worst = 0;
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    const Eigen::Vector3d r = Eigen::Vector3d(m.x[k], m.y[k], m.z[k]) - c;
    worst = std::max(worst, (Eigen::Vector3d(s.vx[k], s.vy[k], s.vz[k]) - vc - om.cross(r)).norm());
  }
  EXPECT_LT(worst, 1e-9 * V.norm());

  // the energies booked from the start are the body's: the ratio stays 1 (no forces act)
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  const double ke0 = eng.state().initial_total;
  EXPECT_GT(ke0, 0);
  EXPECT_NEAR(eng.state().kinetic, ke0, 1e-9 * ke0);
}

TEST(RigidInitialVelocity, RigidNodalVelocitiesAreKeptWithoutWarning) {
  Model m = rigid_box(1e-5);
  const Eigen::Vector3d V(3.0, -1.0, 2.0), w(2000.0, 500.0, -1000.0);
  set_velocity_field(m, [&](double x, double y, double z) {
    const Eigen::Vector3d v = V + w.cross(Eigen::Vector3d(x, y, z));
    return std::array<double, 3>{v(0), v(1), v(2)};
  });
  Diagnostics diag;
  check_model(m, diag);
  EXPECT_EQ(diag.count(2014), 0);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  double worst = 0;
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    const auto& iv = m.init_velocities[k];
    worst = std::max({worst, std::fabs(s.vx[k] - iv.v[0]), std::fabs(s.vy[k] - iv.v[1]), std::fabs(s.vz[k] - iv.v[2])});
  }
  EXPECT_LT(worst, 1e-12 * 10.0);
}
