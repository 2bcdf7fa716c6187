// The Belytschko-Tsay shell's drilling constraint (impact3d/element/shell_bt.h): the corner
// rotation about the normal tied to the element's in-plane spin by the penalty moments
// dM_i/dt = k_d (w_i.e3 - omega_z), k_d = drill_coef G h A / 4.  Checked on one distorted,
// tilted quadrilateral:
//   * a rigid rotation (v = Omega x x at the midpoint geometry, w = Omega) gives no moment and
//     no force (the constraint is objective);
//   * a corner turning about the normal alone gets k_d w dt on that corner only;
//   * the corner forces and moments of stored drilling moments are their work conjugates: for
//     any velocities, sum f.v + m.w = sum M_i (w_i.e3 - omega_z) to round-off;
//   * without the drilling state (null) the element is the plain Belytschko-Tsay one (no moment
//     about the normal: round-off only).
// The physics it restores (the Scordelis-Lo roof and the pinched cylinder converge to their
// references) is tested in tests/decks.

#include <gtest/gtest.h>

#include <cmath>

#include "impact3d/element/shell_bt.h"

using namespace impact3d;

namespace {

const double kE = 2.1e11, kNu = 0.3, kRho = 7850, kH = 0.01;

ShellGroupConstants constants() {
  ShellGroupConstants g;
  g.nip = 2;
  gauss_legendre_rule(g.nip, g.zeta, g.weight);
  g.shrf = 5.0 / 6.0;
  g.hourglass_type = 4;
  g.hourglass_coef = 0.0;
  g.rho = kRho;
  g.E = kE;
  g.nu = kNu;
  g.G = kE / (2 * (1 + kNu));
  g.c_plate = std::sqrt(kE / (kRho * (1 - kNu * kNu)));
  g.drill_coef = kShellDrillingCoef;
  return g;
}

MaterialConstants material() {
  MaterialConstants mc;
  mc.E = kE;
  mc.nu = kNu;
  mc.G = kE / (2 * (1 + kNu));
  mc.rho = kRho;
  return mc;
}

// A distorted quadrilateral in its plane, turned into a tilted plane through (0.3, -0.2, 0.1).
void geometry(double x[4][3]) {
  const double p[4][2] = {{0, 0}, {0.11, 0.01}, {0.13, 0.09}, {-0.02, 0.1}};
  const double a[3] = {std::cos(0.4), std::sin(0.4) * std::cos(0.7), std::sin(0.4) * std::sin(0.7)};
  // b: a unit vector normal to a
  double b[3] = {-a[1], a[0], 0};
  const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1]);
  for (double& c : b) c /= lb;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) x[i][k] = (k == 0 ? 0.3 : k == 1 ? -0.2 : 0.1) + p[i][0] * a[k] + p[i][1] * b[k];
}

void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

struct Element {
  double sig[5 * 2] = {}, hgq[5] = {}, drill[4] = {};
  ShellPointState st() { return ShellPointState{sig, nullptr, nullptr, nullptr, hgq, drill}; }
};

}  // namespace

TEST(ShellDrilling, RigidRotationGivesNoMomentNorForce) {
  const ShellGroupConstants g = constants();
  const MaterialConstants mc = material();
  const double omega[3] = {3.0, -7.0, 11.0};
  double xm[4][3];
  geometry(xm);
  Element el;
  ShellKernelIO io;
  io.h = kH;
  io.dt = 1e-6;
  for (int i = 0; i < 4; ++i) {
    cross(omega, xm[i], io.v[i]);
    for (int k = 0; k < 3; ++k) {
      io.x[i][k] = xm[i][k] + 0.5 * io.dt * io.v[i][k];  // so that x - dt v / 2 = xm
      io.w[i][k] = omega[k];
    }
  }
  const ShellPointState st = el.st();
  calc_shell_bt_forces(g, mc, ShellMaterialKind::elastic, io, st);
  ASSERT_FALSE(io.bad);
  // the scale: one corner turning at |omega| about the normal for the step
  const double kd = g.drill_coef * g.G * kH * io.area / 4;
  const double scale = kd * std::sqrt(3 * 3 + 7 * 7 + 11 * 11.0) * io.dt;
  for (int i = 0; i < 4; ++i) EXPECT_LT(std::fabs(el.drill[i]), 1e-9 * scale) << "corner " << i;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::fabs(io.m[i][k]), 1e-9 * scale);
}

TEST(ShellDrilling, CornerTurningAboutTheNormalIsResisted) {
  const ShellGroupConstants g = constants();
  const MaterialConstants mc = material();
  Element el;
  ShellKernelIO io;
  io.h = kH;
  io.dt = 1e-6;
  geometry(io.x);
  ShellFrame fr;
  ASSERT_TRUE(calc_shell_frame(io.x, fr));
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) io.v[i][k] = io.w[i][k] = 0;
  const double wn = 5.0;
  for (int k = 0; k < 3; ++k) io.w[2][k] = wn * fr.e[2][k];
  const ShellPointState st = el.st();
  calc_shell_bt_forces(g, mc, ShellMaterialKind::elastic, io, st);
  const double kd = g.drill_coef * g.G * kH * fr.area / 4;
  EXPECT_NEAR(el.drill[2], kd * wn * io.dt, 1e-12 * kd * wn * io.dt);
  EXPECT_EQ(el.drill[0], 0.0);
  EXPECT_EQ(el.drill[1], 0.0);
  EXPECT_EQ(el.drill[3], 0.0);
  // the moment on that corner is along the normal, resisting
  const double mn = io.m[2][0] * fr.e[2][0] + io.m[2][1] * fr.e[2][1] + io.m[2][2] * fr.e[2][2];
  EXPECT_NEAR(mn, kd * wn * io.dt, 1e-9 * kd * wn * io.dt);
  // the energy booked: the trapezoid of the moment times the rotation, (0 + M) / 2 w dt
  EXPECT_NEAR(io.de_ie, 0.5 * kd * wn * io.dt * wn * io.dt, 1e-9 * kd * wn * wn * io.dt * io.dt);
  // the plain element: no drilling state, no moment about the normal
  ShellPointState plain = el.st();
  plain.drill = nullptr;
  ShellKernelIO io2 = io;
  calc_shell_bt_forces(g, mc, ShellMaterialKind::elastic, io2, plain);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::fabs(io2.m[i][k]), 1e-9 * kd * wn * io.dt);  // round-off
}

TEST(ShellDrilling, ForcesAndMomentsAreTheWorkConjugatesOfTheStoredMoments) {
  const ShellGroupConstants g = constants();
  const MaterialConstants mc = material();
  Element el;
  const double M[4] = {1.5, -0.25, 0.75, 2.0};
  for (int i = 0; i < 4; ++i) el.drill[i] = M[i];
  ShellKernelIO io;
  io.h = kH;
  io.dt = 0;  // no update: only the stored moments act (stresses zero, hourglass off)
  geometry(io.x);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) io.v[i][k] = io.w[i][k] = 0;
  const ShellPointState st = el.st();
  calc_shell_bt_forces(g, mc, ShellMaterialKind::elastic, io, st);
  ShellFrame fr;
  ASSERT_TRUE(calc_shell_frame(io.x, fr));
  // arbitrary velocities
  double v[4][3], w[4][3];
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      v[i][k] = std::sin(1.0 + 3 * i + k);
      w[i][k] = std::cos(2.0 + 5 * i + 2 * k);
    }
  double power = 0, ref = 0, spin = 0, scale = 0;
  for (int i = 0; i < 4; ++i) {
    double vl[2] = {0, 0};
    for (int k = 0; k < 3; ++k) {
      power += io.f[i][k] * v[i][k] + io.m[i][k] * w[i][k];
      scale += std::fabs(io.f[i][k] * v[i][k]) + std::fabs(io.m[i][k] * w[i][k]);
      vl[0] += fr.e[0][k] * v[i][k];
      vl[1] += fr.e[1][k] * v[i][k];
    }
    spin += 0.5 * (fr.b1[i] * vl[1] - fr.b2[i] * vl[0]);
  }
  for (int i = 0; i < 4; ++i) {
    const double wn = fr.e[2][0] * w[i][0] + fr.e[2][1] * w[i][1] + fr.e[2][2] * w[i][2];
    ref += M[i] * (wn - spin);
  }
  EXPECT_GT(scale, 1.0);
  EXPECT_NEAR(power, ref, 1e-12 * scale);
  // and no net force or net moment about the origin (equilibrium of the element)
  double F[3] = {0, 0, 0}, Mo[3] = {0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    double r[3];
    cross(io.x[i], io.f[i], r);
    for (int k = 0; k < 3; ++k) {
      F[k] += io.f[i][k];
      Mo[k] += io.m[i][k] + r[k];
    }
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(std::fabs(F[k]), 1e-12 * scale);
    EXPECT_LT(std::fabs(Mo[k]), 1e-12 * scale);
  }
}
