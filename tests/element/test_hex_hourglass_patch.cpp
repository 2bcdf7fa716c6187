// Hourglass control (types 1-5) and the MacNeal-Harder 7-element patch test.

#include <gtest/gtest.h>

#include <cmath>

#include "hex_test_util.h"
#include "impact3d/element/hexahedron.h"

using namespace impact3d;
using hex_test::Hex;

namespace {

// The hourglass base vectors, for closed forms.
constexpr double kG[4][8] = {
    {1, 1, -1, -1, -1, -1, 1, 1},
    {1, -1, -1, 1, -1, 1, 1, -1},
    {1, -1, 1, -1, 1, -1, 1, -1},
    {-1, 1, -1, 1, 1, -1, 1, -1},
};

struct HgResult {
  double fx[8], fy[8], fz[8];
  double hgs[12];
  double power;
  double fmax;  // max |f| component
};

HgResult hourglass(int type, const Hex& h, const double vx[8], const double vy[8],
                   const double vz[8], int calls = 1) {
  double dx[8], dy[8], dz[8];
  const double v = calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
  HourglassInput in{type, 0.1, 7800.0, 5000.0, 8.0e10, v, 1.0e-6};
  HgResult r{};
  for (int k = 0; k < calls; ++k) {
    for (int n = 0; n < 8; ++n) r.fx[n] = r.fy[n] = r.fz[n] = 0.0;
    r.power = calc_hex_hourglass_force(in, h.x, h.y, h.z, dx, dy, dz, vx, vy, vz, r.hgs, r.fx,
                                       r.fy, r.fz);
  }
  r.fmax = 0;
  for (int n = 0; n < 8; ++n) {
    r.fmax = std::fmax(r.fmax, std::fabs(r.fx[n]));
    r.fmax = std::fmax(r.fmax, std::fabs(r.fy[n]));
    r.fmax = std::fmax(r.fmax, std::fabs(r.fz[n]));
  }
  return r;
}

void linear_field(const Hex& h, const double A[3][3], const double v0[3], double vx[8],
                  double vy[8], double vz[8]) {
  for (int n = 0; n < 8; ++n) {
    vx[n] = A[0][0] * h.x[n] + A[0][1] * h.y[n] + A[0][2] * h.z[n] + v0[0];
    vy[n] = A[1][0] * h.x[n] + A[1][1] * h.y[n] + A[1][2] * h.z[n] + v0[1];
    vz[n] = A[2][0] * h.x[n] + A[2][1] * h.y[n] + A[2][2] * h.z[n] + v0[2];
  }
}

// Scales of the forces for the material above (rho c = 3.9e7, G = 8e10): the viscous a_h of a
// unit-size element times a unit velocity, and the stiffness kappa dt.
constexpr double kViscScale = 0.25 * 0.1 * 7800.0 * 5000.0;
constexpr double kStiffScale = 0.25 * 0.1 * 8.0e10 * 1.0e-6;

}  // namespace

TEST(HexHourglass, RigidTranslationGivesNoForceAllTypes) {
  const Hex h = hex_test::distorted();
  const double zero[3][3] = {};
  const double v0[3] = {10.0, -20.0, 30.0};
  double vx[8], vy[8], vz[8];
  linear_field(h, zero, v0, vx, vy, vz);
  for (int type = 1; type <= 5; ++type) {
    const HgResult r = hourglass(type, h, vx, vy, vz, 3);
    // Every Gamma and gamma sums to zero over the nodes, so h = 0.  Tolerance: round-off of
    // sums of |v| = 30 times the force scale, 1e-13 relative.
    const double scale = (type <= 3 ? kViscScale : 3 * kStiffScale) * 30.0;
    EXPECT_LE(r.fmax, 1e-13 * scale) << "type " << type;
    for (int k = 0; k < 12; ++k) EXPECT_LE(std::fabs(r.hgs[k]), 1e-13 * scale);
  }
}

TEST(HexHourglass, RigidRotation) {
  const double o[3] = {0.7, -1.3, 2.1};
  const double A[3][3] = {{0, -o[2], o[1]}, {o[2], 0, -o[0]}, {-o[1], o[0], 0}};
  const double v0[3] = {1, 2, 3};
  double vx[8], vy[8], vz[8];
  // Parallelepiped (affine image of a cube): x is a linear combination of 1, xi, eta, zeta, to
  // which every Gamma is orthogonal, so even type 1 sees no hourglass rate.
  const double F[3][3] = {{1.2, 0.3, -0.2}, {0.1, 0.9, 0.4}, {-0.3, 0.2, 1.1}};
  const double t[3] = {0.5, -1.0, 2.0};
  const Hex p = hex_test::affine(hex_test::box(1, 1, 1), F, t);
  linear_field(p, A, v0, vx, vy, vz);
  for (int type = 1; type <= 5; ++type) {
    const HgResult r = hourglass(type, p, vx, vy, vz, 2);
    // Tolerance 1e-13 relative to the force scale times |v| ~ 10.
    const double scale = (type <= 3 ? kViscScale : 2 * kStiffScale) * 10.0;
    EXPECT_LE(r.fmax, 1e-13 * scale) << "type " << type;
  }
  // Distorted (non-affine) hexahedron: the FB vectors gamma (types 2-5) are orthogonal to all
  // linear fields, so a rigid rotation gives no force; the plain Gamma of type 1 is not (Gamma . x
  // != 0 for a non-parallelepiped), so DYNA3D's type 1 resists a rigid rotation of a distorted
  // element: physically spurious but true of that form.
  const Hex h = hex_test::distorted();
  linear_field(h, A, v0, vx, vy, vz);
  for (int type = 2; type <= 5; ++type) {
    const HgResult r = hourglass(type, h, vx, vy, vz, 2);
    const double scale = (type <= 3 ? kViscScale : 2 * kStiffScale) * 10.0;
    EXPECT_LE(r.fmax, 1e-13 * scale) << "type " << type;
  }
  const HgResult r1 = hourglass(1, h, vx, vy, vz);
  // h_ia = sum_a (A (Gamma_a . x))_i: of order |omega| times the distortion (~0.1): well above
  // round-off.
  EXPECT_GT(r1.fmax, 1e-3 * kViscScale);
  EXPECT_GT(r1.power, 0.0);
}

TEST(HexHourglass, ViscousModeOnUnitCube) {
  // Unit cube (V = 1), velocity v_x = Gamma_1 (the eta-zeta mode), nothing else.
  const Hex h = hex_test::box(1, 1, 1);
  double vx[8], vy[8] = {}, vz[8] = {};
  for (int n = 0; n < 8; ++n) vx[n] = kG[0][n];
  for (int type = 1; type <= 3; ++type) {
    const HgResult r = hourglass(type, h, vx, vy, vz);
    // On a box Gamma . x = 0, so gamma = Gamma.  h_x1 = Gamma_1 . Gamma_1 = 8, others 0:
    // f_xI = a_h 8 Gamma_1I with a_h = qhg rho c V^(2/3) / 4; power = 64 a_h.
    // Relative tolerance 1e-14.
    for (int n = 0; n < 8; ++n) {
      EXPECT_NEAR(r.fx[n], 8.0 * kViscScale * kG[0][n], 8.0 * kViscScale * 1e-14);
      EXPECT_NEAR(r.fy[n], 0.0, 8.0 * kViscScale * 1e-14);
      EXPECT_NEAR(r.fz[n], 0.0, 8.0 * kViscScale * 1e-14);
    }
    EXPECT_NEAR(r.power, 64.0 * kViscScale, 64.0 * kViscScale * 1e-14);
  }
  // a_h scales with V^(2/3): a cube of side 2 (V = 8) under the same nodal velocities gives
  // forces 4 times larger.
  const Hex h2 = hex_test::box(2, 2, 2);
  const HgResult r2 = hourglass(1, h2, vx, vy, vz);
  EXPECT_NEAR(r2.fx[0], 4.0 * 8.0 * kViscScale, 32.0 * kViscScale * 1e-14);
}

TEST(HexHourglass, ViscousPowerIsNonNegative) {
  const Hex h = hex_test::distorted();
  double vx[8], vy[8], vz[8];
  for (int n = 0; n < 8; ++n) {
    vx[n] = std::sin(1.0 + 3.0 * n);
    vy[n] = std::cos(2.0 + 5.0 * n);
    vz[n] = std::sin(0.5 + 7.0 * n);
  }
  for (int type = 1; type <= 3; ++type) {
    const HgResult r = hourglass(type, h, vx, vy, vz);
    // power = a_h sum h^2 > 0 (dissipative): closed-form sign.
    EXPECT_GT(r.power, 0.0) << "type " << type;
  }
}

TEST(HexHourglass, StiffnessAccumulatesResultants) {
  const Hex h = hex_test::box(1, 1, 1);
  double vx[8] = {}, vy[8] = {}, vz[8];
  for (int n = 0; n < 8; ++n) vz[n] = kG[3][n];  // z velocity in the xi-eta-zeta mode
  for (int type = 4; type <= 5; ++type) {
    // After k calls: Q_z4 = k kappa dt 8 with kappa = qhg G V^(1/3) / 4, f_zI = Q_z4 Gamma_4I.
    // Relative tolerance 1e-14.
    for (int k = 1; k <= 3; ++k) {
      const HgResult r = hourglass(type, h, vx, vy, vz, k);
      const double q = k * kStiffScale * 8.0;
      EXPECT_NEAR(r.hgs[3 * 3 + 2], q, q * 1e-14);
      for (int m = 0; m < 12; ++m)
        if (m != 11) {
          EXPECT_EQ(r.hgs[m], 0.0);
        }
      for (int n = 0; n < 8; ++n) {
        EXPECT_NEAR(r.fz[n], q * kG[3][n], q * 1e-14);
        EXPECT_NEAR(r.fx[n], 0.0, q * 1e-14);
      }
      // the energy rate of the mean resultant (Q^{k-1} + Q^k) / 2 . h = 8 (k - 1/2) kappa dt 8:
      // times dt and summed over the k calls, Q^2 / (2 kappa), the spring's stored energy
      const double q_mean = (k - 0.5) * kStiffScale * 8.0;
      EXPECT_NEAR(r.power, 8.0 * q_mean, 8.0 * q_mean * 1e-14);
    }
  }
}

TEST(HexHourglass, ZeroCoefficientLeavesForcesUntouched) {
  const Hex h = hex_test::distorted();
  double dx[8], dy[8], dz[8], vx[8], vy[8], vz[8], hgs[12] = {};
  const double v = calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
  for (int n = 0; n < 8; ++n) vx[n] = vy[n] = vz[n] = kG[2][n];
  double fx[8], fy[8], fz[8];
  for (int n = 0; n < 8; ++n) fx[n] = fy[n] = fz[n] = 1.0;
  HourglassInput in{2, 0.0, 1.0, 1.0, 1.0, v, 1.0};
  // qhg = 0: forces added are exactly zero.
  EXPECT_EQ(calc_hex_hourglass_force(in, h.x, h.y, h.z, dx, dy, dz, vx, vy, vz, hgs, fx, fy, fz),
            0.0);
  for (int n = 0; n < 8; ++n) EXPECT_EQ(fx[n], 1.0);
}

// ---------------------------------------------------------------------------------------------
// MacNeal-Harder patch.

TEST(HexPatch, GeometryFillsTheCube) {
  const hex_test::Patch p = hex_test::macneal_harder_patch();
  double total = 0;
  for (int e = 0; e < 7; ++e) {
    const Hex h = hex_test::patch_element(p, e);
    const double v = calc_hex_volume(h.x, h.y, h.z);
    EXPECT_GT(v, 0.0) << "element " << e;
    // Cross-check each element's volume with the exact quadrature; tolerance 1e-15.
    EXPECT_NEAR(v, hex_test::gauss_volume(h), 1e-15);
    total += v;
  }
  // Conforming bilinear faces: the seven volumes sum to the unit cube.  Tolerance 1e-14.
  EXPECT_NEAR(total, 1.0, 1e-14);
}

TEST(HexPatch, LinearVelocityFieldIsReproduced) {
  const hex_test::Patch p = hex_test::macneal_harder_patch();
  const double A[3][3] = {{0.31, -1.17, 0.52}, {0.83, -0.44, 0.91}, {-0.66, 0.27, 0.73}};
  const double v0[3] = {0.4, -0.9, 1.3};
  double anorm = 0;
  for (auto& row : A)
    for (double a : row) anorm = std::fmax(anorm, std::fabs(a));
  for (int e = 0; e < 7; ++e) {
    const Hex h = hex_test::patch_element(p, e);
    double dx[8], dy[8], dz[8], bx[8], by[8], bz[8], vx[8], vy[8], vz[8];
    const double v = calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
    for (int n = 0; n < 8; ++n) {
      bx[n] = dx[n] / v;
      by[n] = dy[n] / v;
      bz[n] = dz[n] / v;
    }
    linear_field(h, A, v0, vx, vy, vz);
    double d[6], w[3];
    calc_hex_strain_rate(bx, by, bz, vx, vy, vz, d, w);
    // D = sym(A), W = skew(A) to 1e-12 relative to max |A_ij|.
    const double tol = 1e-12 * anorm;
    EXPECT_NEAR(d[0], A[0][0], tol) << "element " << e;
    EXPECT_NEAR(d[1], A[1][1], tol);
    EXPECT_NEAR(d[2], A[2][2], tol);
    EXPECT_NEAR(d[3], 0.5 * (A[0][1] + A[1][0]), tol);
    EXPECT_NEAR(d[4], 0.5 * (A[1][2] + A[2][1]), tol);
    EXPECT_NEAR(d[5], 0.5 * (A[2][0] + A[0][2]), tol);
    EXPECT_NEAR(w[0], 0.5 * (A[0][1] - A[1][0]), tol);
    EXPECT_NEAR(w[1], 0.5 * (A[1][2] - A[2][1]), tol);
    EXPECT_NEAR(w[2], 0.5 * (A[2][0] - A[0][2]), tol);
    // FB hourglass (types 2-5): gamma is orthogonal to linear fields, force zero to round-off:
    // 1e-13 relative to (force scale) x |v| (|v| <= 3 on the unit cube).
    for (int type = 2; type <= 5; ++type) {
      const HgResult r = hourglass(type, h, vx, vy, vz, 2);
      const double scale = (type <= 3 ? kViscScale : 2 * kStiffScale) * 3.0;
      EXPECT_LE(r.fmax, 1e-13 * scale) << "element " << e << " type " << type;
    }
  }
}

TEST(HexPatch, ConstantStressIsInEquilibrium) {
  const hex_test::Patch p = hex_test::macneal_harder_patch();
  const double sig[6] = {120.0, -75.0, 40.0, 33.0, -18.0, 9.0};
  double Fx[16] = {}, Fy[16] = {}, Fz[16] = {};
  for (int e = 0; e < 7; ++e) {
    const Hex h = hex_test::patch_element(p, e);
    double dx[8], dy[8], dz[8], fx[8], fy[8], fz[8];
    calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
    calc_hex_stress_force(sig, dx, dy, dz, fx, fy, fz);
    for (int k = 0; k < 8; ++k) {
      Fx[p.conn[e][k]] += fx[k];
      Fy[p.conn[e][k]] += fy[k];
      Fz[p.conn[e][k]] += fz[k];
    }
  }
  // Interior nodes: the assembled force is sigma_ij dV_total/dx_jI = 0, since moving an interior
  // node does not change the total volume.  Tolerance 1e-12 relative to |sigma| (areas ~ 1).
  const double tol = 1e-12 * 120.0;
  for (int n = 8; n < 16; ++n) {
    EXPECT_NEAR(Fx[n], 0.0, tol) << "node " << n;
    EXPECT_NEAR(Fy[n], 0.0, tol) << "node " << n;
    EXPECT_NEAR(Fz[n], 0.0, tol) << "node " << n;
  }
  // Corners: the unit cube's dV/dx_I = n_I / 4, so F_iI = sigma_ij n_jI / 4 (the traction on
  // the three quarter faces at the corner).
  for (int n = 0; n < 8; ++n) {
    const double nn[3] = {hex_test::kXi[n], hex_test::kEta[n], hex_test::kZeta[n]};
    EXPECT_NEAR(Fx[n], 0.25 * (sig[0] * nn[0] + sig[3] * nn[1] + sig[5] * nn[2]), tol);
    EXPECT_NEAR(Fy[n], 0.25 * (sig[3] * nn[0] + sig[1] * nn[1] + sig[4] * nn[2]), tol);
    EXPECT_NEAR(Fz[n], 0.25 * (sig[5] * nn[0] + sig[4] * nn[1] + sig[2] * nn[2]), tol);
  }
}
