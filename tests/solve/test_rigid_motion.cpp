// Physics verification: rigid-body motions of a free block (translation, large rotation) and
// conservation of linear momentum.  Programmatic models (tests/solve/test_models.h).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

// Deterministic pseudo-random numbers in [-1, 1] (no dependence on the library's RNG).
struct Lcg {
  uint64_t s;
  double next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(s >> 11) * (2.0 / 9007199254740992.0) - 1.0;
  }
};

// Perturbs every node of the model by up to frac * h in each direction (a distorted mesh: the
// elements are no longer parallelepipeds, so the DYNA3D base vectors Gamma are not orthogonal
// to linear velocity fields, while the Flanagan-Belytschko gamma vectors are).
void distort(Model& m, double h, double frac, uint64_t seed) {
  Lcg r{seed};
  for (int n = 0; n < m.num_nodes(); ++n) {
    m.x[std::size_t(n)] += frac * h * r.next();
    m.y[std::size_t(n)] += frac * h * r.next();
    m.z[std::size_t(n)] += frac * h * r.next();
  }
}

}  // namespace

// Rigid translation: a 3x3x3 block of 1 mm at v = (1, -2, 3) m/s for 10 us, no walls.
TEST(RigidMotion, TranslationIsStressFreeAndConservesEnergy) {
  ScopedThreads one(1);
  const double L = 1e-3, t_end = 10e-6;
  const double v[3] = {1.0, -2.0, 3.0};
  const double vmag = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  Model m = make_box_model({3, 3, 3, L, L, L}, copper_elastic(), t_end);
  distort(m, L / 3, 0.1, 7);
  set_uniform_velocity(m, v[0], v[1], v[2]);
  Engine eng(m);
  StepStatus st = eng.run_to_end();
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  ASSERT_GT(s.cycle, 100);
  // A uniform velocity field has D = W = 0 exactly in exact arithmetic (sum_I b_I = 0); what
  // remains is round-off, of relative size 1e-16 per step.  The bound 1e-6 * E * (v t / L) is
  // the stress a strain error of one part in a million of the travelled distance would give.
  const double E = m.materials[0].E;
  EXPECT_LT(max_abs_stress(s), 1e-6 * E * (vmag * t_end / L));
  // No hourglass or bulk viscosity work for a rigid motion: relative to the kinetic energy,
  // below 1e-10 (round-off of the hourglass velocities is ~1e-16 v).
  EXPECT_LT(std::fabs(s.hourglass), 1e-10 * s.kinetic);
  EXPECT_LT(std::fabs(s.bulk_viscous), 1e-10 * s.kinetic);
  EXPECT_LT(std::fabs(s.internal), 1e-10 * s.kinetic);
  // Kinetic energy and velocities are unchanged (relative 1e-12: round-off only).
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-12);
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    ASSERT_NEAR(s.vx[k], v[0], 1e-12 * vmag);
    ASSERT_NEAR(s.vy[k], v[1], 1e-12 * vmag);
    ASSERT_NEAR(s.vz[k], v[2], 1e-12 * vmag);
    // displacement v t (relative 1e-9 of the travel: the sum of ~150 rounded increments)
    ASSERT_NEAR(s.x[k] - m.x[k], v[0] * s.time, 1e-9 * vmag * s.time);
    ASSERT_NEAR(s.y[k] - m.y[k], v[1] * s.time, 1e-9 * vmag * s.time);
    ASSERT_NEAR(s.z[k] - m.z[k], v[2] * s.time, 1e-9 * vmag * s.time);
  }
}

// Angular momentum sum m x^n x v^{n+1/2} (= sum m x^{n+1} x v^{n+1/2}).
std::array<double, 3> angular_momentum(const State& s) {
  std::array<double, 3> l{};
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    l[0] += s.mass[k] * (s.y[k] * s.vz[k] - s.z[k] * s.vy[k]);
    l[1] += s.mass[k] * (s.z[k] * s.vx[k] - s.x[k] * s.vz[k]);
    l[2] += s.mass[k] * (s.x[k] * s.vy[k] - s.y[k] * s.vx[k]);
  }
  return l;
}

// Rigid rotation through 90 degrees: a 3x3x3 block of 1 mm spinning at omega = 2000 rad/s
// (v_max ~ 1.7 m/s, ~13000 cycles) about the oblique axis (1,1,1)/sqrt(3) through its centre
// of mass, no walls, Flanagan-Belytschko hourglass control (type 2 and 3).  Parameter: hourglass
// type, and whether the mesh is distorted (10% random node perturbation: the elements are no
// longer parallelepipeds and the FB gamma vectors must still be orthogonal to the rotation).
class RigidRotation : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(RigidRotation, LargeRotationIsStrainFree) {
  ScopedThreads one(1);
  const double L = 1e-3;
  const double omega = 2000;           // rad/s
  const double theta = M_PI / 2;       // 90 degrees
  const double t_end = theta / omega;  // 785 us
  const double ax[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  MaterialData mat = copper_elastic();
  mat.hourglass_type = std::get<0>(GetParam());
  const bool distorted = std::get<1>(GetParam());
  Model m = make_box_model({3, 3, 3, L, L, L, -L / 2, -L / 2, -L / 2}, mat, t_end);
  if (distorted) distort(m, L / 3, 0.1, 11);
  // centre of mass of the engine's lumped masses
  std::array<double, 3> c{};
  {
    Engine e0(m);
    ASSERT_EQ(e0.initialize(), StepStatus::ok);
    const State& s0 = e0.state();
    const double mt = total_mass(s0);
    for (int i = 0; i < s0.nn; ++i) {
      const std::size_t k = std::size_t(i);
      c[0] += s0.mass[k] * s0.x[k] / mt;
      c[1] += s0.mass[k] * s0.y[k] / mt;
      c[2] += s0.mass[k] * s0.z[k] / mt;
    }
  }
  for (int n = 0; n < m.num_nodes(); ++n) {  // put the centre of mass at the origin
    m.x[std::size_t(n)] -= c[0];
    m.y[std::size_t(n)] -= c[1];
    m.z[std::size_t(n)] -= c[2];
  }
  set_velocity_field(m, [&](double x, double y, double z) {
    return std::array<double, 3>{omega * (ax[1] * z - ax[2] * y), omega * (ax[2] * x - ax[0] * z),
                                 omega * (ax[0] * y - ax[1] * x)};
  });
  double rmax = 0;  // largest distance from the axis
  for (int n = 0; n < m.num_nodes(); ++n) {
    const double r[3] = {m.x[std::size_t(n)], m.y[std::size_t(n)], m.z[std::size_t(n)]};
    const double ra = r[0] * ax[0] + r[1] * ax[1] + r[2] * ax[2];
    rmax = std::max(rmax, std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] - ra * ra));
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const auto l0 = angular_momentum(eng.state());
  StepStatus st = StepStatus::ok;
  double hg_quarter = 0;  // hourglass energy after the first quarter of the run
  while (st == StepStatus::ok) {
    st = eng.step();
    if (hg_quarter == 0 && eng.state().time >= t_end / 4) hg_quarter = eng.state().hourglass;
  }
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  const double rho = mat.rho;

  // Stress.  A free spinning body is not stress-free: the centripetal acceleration omega^2 r
  // needs div sigma = -rho omega^2 r, so sigma ~ rho omega^2 R^2 (a spinning disc: (3+nu)/8
  // rho omega^2 R^2 at the centre), up to twice that while the suddenly "applied" centrifugal
  // load rings.  Bound: 2 rho omega^2 R^2 (~48 kPa here; measured ~5-8 kPa).  A non-objective
  // update would be far above it: strain rates taken on the end-of-step configuration instead
  // of the midpoint give D ~ omega^2 dt per step, a strain omega^2 dt t ~ 2e-4 after 90 degrees,
  // i.e. ~20 MPa.  The midpoint (Hughes-Winget) kinematics make the strain increment of an exact
  // rotation step zero; the first-order Jaumann rotation sigma + dt (W sigma - sigma W) is not an
  // exact rotation and scales the existing stress by 1 + O((omega dt)^2) per step: ~2e-4 over
  // the run (omega dt ~ 1.2e-4, 13000 steps), a relative error of the small physical stress.
  // Rotating a stress of order E with this update would leave that 2e-4 E as spurious stress,
  // which is why the test keeps the physical stress small.
  const double sig_bound = 2 * rho * omega * omega * rmax * rmax;
  EXPECT_LT(max_abs_stress(s), sig_bound) << "bound " << sig_bound;

  // Hourglass energy.  The FB gamma vectors are orthogonal to any velocity field linear in the
  // current coordinates, rigid rotation included, on distorted elements too.  The only hourglass
  // work is the damping of the ring-down of the centrifugal deformation in the first cycles
  // (a suddenly applied load rings with the static strain energy U, which the hourglass and bulk
  // viscosities then dissipate): hg + bv <= 2 U, U ~ the final internal energy.  After that, the
  // hourglass energy must not grow while the block turns: growth over the last 3/4 of the run
  // < 1e-10 of the kinetic energy (a non-invariant hourglass would damp the rotation itself).
  //
  // On the distorted mesh the sustained centrifugal load has a component along hourglass
  // patterns, which the viscous (stiffness-free) FB control resists only by damping: a slow
  // creep whose work stays at the scale of the centrifugal strain energy, rho omega^2 R^2 / E
  // (= 2e-7) of the kinetic energy; measured 1.9e-7.  Bound 1e-6 KE.  The DYNA3D type 1 vectors
  // on the same mesh stop the rotation (RigidRotationType1.DistortedMeshDampsRotation).
  if (!distorted) {
    EXPECT_LT(s.hourglass + s.bulk_viscous, 2 * s.internal);
    EXPECT_LT(std::fabs(s.hourglass - hg_quarter), 1e-10 * s.kinetic);
  } else {
    EXPECT_LT(s.hourglass, 1e-6 * s.kinetic);
  }

  // Energy: the kinetic energy I omega^2 / 2 is conserved; relative 1e-8 (the central-
  // difference kinetic energy is taken at the half step; the strain energy is ~3e-8 of it).
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-8);

  // Angular momentum sum m x^n x v^{n+1/2} changes by sum x^n x f^n dt: zero for the stress
  // forces (sigma symmetric) and for the FB hourglass forces (gamma orthogonal to x), so it is
  // conserved to round-off: 1e-12 relative.
  const auto l1 = angular_momentum(s);
  const double lmag = std::sqrt(l0[0] * l0[0] + l0[1] * l0[1] + l0[2] * l0[2]);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(l1[std::size_t(a)], l0[std::size_t(a)], 1e-12 * lmag);

  // The undistorted cube (isotropic inertia: the rotation stays about the fixed axis) has turned
  // by theta as a rigid body: every node within 1e-6 R of R(theta) x0 (phase error of the central
  // difference ~ (omega dt)^2 theta / 24 ~ 1e-9, centrifugal stretch rho omega^2 R^2 / E ~ 1e-7).
  // The distorted block is not isotropic and precesses (torque-free Euler motion): no closed
  // form, the angular momentum check above covers it.
  double max_err = 0;
  if (!distorted) {
    const double ct = std::cos(theta), sn = std::sin(theta);
    for (int i = 0; i < s.nn; ++i) {
      const std::size_t k = std::size_t(i);
      const double r[3] = {m.x[k], m.y[k], m.z[k]};
      const double ar = ax[0] * r[0] + ax[1] * r[1] + ax[2] * r[2];
      const double axr[3] = {ax[1] * r[2] - ax[2] * r[1], ax[2] * r[0] - ax[0] * r[2],
                             ax[0] * r[1] - ax[1] * r[0]};
      double e2 = 0;
      const double cur[3] = {s.x[k], s.y[k], s.z[k]};
      for (int a = 0; a < 3; ++a) {
        const double rr = r[a] * ct + axr[a] * sn + ax[a] * ar * (1 - ct);
        e2 += (cur[a] - rr) * (cur[a] - rr);
      }
      max_err = std::max(max_err, std::sqrt(e2));
    }
    EXPECT_LT(max_err, 1e-6 * rmax);
  }
  std::printf("rotation hg type %d distorted %d: cycles %d, max |sigma| %.3e Pa (bound %.3e), "
              "hg/ke %.3e, late hg growth/ke %.3e, (hg+bv)/ie %.3f, energy ratio - 1 %.3e, "
              "|dL|/L %.2e, position error / R %.3e\n",
              std::get<0>(GetParam()), int(distorted), s.cycle, max_abs_stress(s), sig_bound,
              s.hourglass / s.kinetic, (s.hourglass - hg_quarter) / s.kinetic,
              (s.hourglass + s.bulk_viscous) / s.internal, s.energy_ratio() - 1,
              std::sqrt((l1[0] - l0[0]) * (l1[0] - l0[0]) + (l1[1] - l0[1]) * (l1[1] - l0[1]) +
                        (l1[2] - l0[2]) * (l1[2] - l0[2])) / lmag,
              max_err / rmax);
}

// Contrast: the DYNA3D type 1 base vectors Gamma are not orthogonal to a rotation of a
// distorted element, so the hourglass viscosity damps the rigid rotation itself.  The same
// distorted block as above: more than half the kinetic energy goes to hourglass energy within the
// 90 degrees (measured: the rotation stops).  This shows the distorted case above discriminates.
TEST(RigidRotationType1, DistortedMeshDampsRotation) {
  ScopedThreads one(1);
  const double L = 1e-3, omega = 2000;
  MaterialData mat = copper_elastic();
  mat.hourglass_type = 1;
  Model m = make_box_model({3, 3, 3, L, L, L, -L / 2, -L / 2, -L / 2}, mat, M_PI / 2 / omega);
  distort(m, L / 3, 0.1, 11);
  set_velocity_field(m, [&](double x, double y, double) {
    return std::array<double, 3>{-omega * y, omega * x, 0.0};
  });
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const double ke0 = eng.state().kinetic;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  EXPECT_GT(eng.state().hourglass, 0.5 * ke0);
}

INSTANTIATE_TEST_SUITE_P(FlanaganBelytschko, RigidRotation,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Bool()));

// Linear momentum of a free body: internal forces (stress, bulk viscosity, every hourglass
// type) sum to zero over each element's nodes, so sum m v is conserved to round-off.  A random
// velocity field (+-30 m/s about a mean drift) on an elastic-plastic block: plastic flow, bulk
// viscosity and hourglass forces all act.
class Momentum : public ::testing::TestWithParam<int> {};

TEST_P(Momentum, FreeBodyConservesLinearMomentum) {
  ScopedThreads one(1);
  const double L = 2e-3;
  MaterialData mat = copper_plastic();
  mat.hourglass_type = GetParam();
  Model m = make_box_model({4, 3, 5, L, 0.75 * L, 1.25 * L}, mat, 10e-6);
  distort(m, L / 4, 0.1, 3);
  Lcg r{42};
  set_velocity_field(m, [&](double, double, double) {
    return std::array<double, 3>{10 + 30 * r.next(), -5 + 30 * r.next(), 20 + 30 * r.next()};
  });
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const auto p0 = momentum(eng.state());
  double scale = 0;  // sum m |v|: the size of the terms in the sums
  for (int i = 0; i < eng.state().nn; ++i) {
    const std::size_t k = std::size_t(i);
    const State& s = eng.state();
    scale += s.mass[k] * std::sqrt(s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k] + s.vz[k] * s.vz[k]);
  }
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  ASSERT_GT(s.cycle, 50);
  EXPECT_GT(s.internal + s.hourglass + s.bulk_viscous, 0.01 * s.kinetic);  // forces did act
  const auto p = momentum(s);
  // 1e-12 relative to sum m|v|: the internal forces cancel to round-off in each nodal sum,
  // ~1e-16 per term and cycle, a few hundred cycles.
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p[std::size_t(a)], p0[std::size_t(a)], 1e-12 * scale);
  std::printf("momentum hg type %d: cycles %d, |dp| / sum m|v| = %.2e %.2e %.2e\n", GetParam(),
              s.cycle, (p[0] - p0[0]) / scale, (p[1] - p0[1]) / scale, (p[2] - p0[2]) / scale);
}

INSTANTIATE_TEST_SUITE_P(HourglassTypes, Momentum, ::testing::Values(1, 2, 3, 4, 5));
