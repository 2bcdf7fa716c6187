// Rigid bodies (material type 20): free flight with translation and spin keeps the shape and
// conserves linear and angular momentum and kinetic energy; the motion is the closed-form
// rigid motion x(t) = c + V t + R(omega t) (x0 - c).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "impact3d/solve/engine.h"
#include "test_models.h"

using namespace impact3d;
using namespace solve_test;

TEST(RigidBody, FreeFlightWithSpinIsTheClosedFormRigidMotion) {
  ScopedThreads threads(1);
  MaterialData rigid;
  rigid.number = 1;
  rigid.type = 20;
  rigid.rho = 8930;
  rigid.E = 117e9;
  rigid.nu = 0.35;
  Box b;
  b.nx = b.ny = b.nz = 2;
  b.lx = b.ly = b.lz = 2e-3;
  b.x0 = b.y0 = b.z0 = -1e-3;  // centred on the origin
  const double T = 1e-4;
  Model m = make_box_model(b, rigid, T);
  const Eigen::Vector3d V(3.0, -1.0, 2.0), w(2000.0, 500.0, -1000.0);  // m/s, rad/s
  set_velocity_field(m, [&](double x, double y, double z) {
    const Eigen::Vector3d v = V + w.cross(Eigen::Vector3d(x, y, z));
    return std::array<double, 3>{v(0), v(1), v(2)};
  });
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  EXPECT_NEAR(s.time, T, 1e-15);

  // closed form: a cube's inertia is isotropic, so omega is constant and the rotation is
  // exp(omega t); tolerance 1e-9 of the size (the update is exact rotation per step)
  const double a = w.norm() * T;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(a, w.normalized()).toRotationMatrix();
  double worst = 0;
  for (int i = 0; i < s.nn; ++i) {
    const Eigen::Vector3d x0(m.x[std::size_t(i)], m.y[std::size_t(i)], m.z[std::size_t(i)]);
    const Eigen::Vector3d expect = V * T + R * x0;
    const Eigen::Vector3d got(s.x[std::size_t(i)], s.y[std::size_t(i)], s.z[std::size_t(i)]);
    worst = std::max(worst, (got - expect).norm());
  }
  EXPECT_LT(worst, 1e-9 * 2e-3) << "rotation angle " << a << " rad";

  // momentum and kinetic energy: 1e-12 relative (no forces act)
  const auto p = momentum(s);
  const double M = total_mass(s);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[std::size_t(k)] / M, V(k), 1e-12 * V.norm());
  const double ke0 = eng.state().initial_total;
  EXPECT_NEAR(s.kinetic, ke0, 1e-12 * ke0);
  // no element of a rigid body carries stress or energy
  EXPECT_EQ(max_abs_stress(s), 0.0);
  EXPECT_EQ(s.internal, 0.0);
  EXPECT_EQ(s.hourglass, 0.0);
}
