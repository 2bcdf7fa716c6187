// Volume, volume derivatives, face areas, strain rate, stress forces, bulk viscosity and time step
// of the one-point hexahedron, each against a closed form.

#include <gtest/gtest.h>

#include <cmath>

#include "hex_test_util.h"
#include "impact3d/element/hexahedron.h"

using namespace impact3d;
using hex_test::Hex;

namespace {

double volume_of(const Hex& h) { return calc_hex_volume(h.x, h.y, h.z); }

double volume_from_derivatives(const Hex& h, double dx[8], double dy[8], double dz[8]) {
  return calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
}

}  // namespace

TEST(HexVolume, UnitCube) {
  const Hex h = hex_test::box(1, 1, 1);
  // Closed form 1; tolerance 1e-15 (a few ulps of sums of O(1) products).
  EXPECT_NEAR(volume_of(h), 1.0, 1e-15);
  double dx[8], dy[8], dz[8];
  EXPECT_NEAR(volume_from_derivatives(h, dx, dy, dz), 1.0, 1e-15);
  // dV/dx_I of the unit cube is +-1/4 (the outward face normals, area 1, shared by 4 nodes).
  for (int n = 0; n < 8; ++n) {
    EXPECT_NEAR(dx[n], 0.25 * hex_test::kXi[n], 1e-15);
    EXPECT_NEAR(dy[n], 0.25 * hex_test::kEta[n], 1e-15);
    EXPECT_NEAR(dz[n], 0.25 * hex_test::kZeta[n], 1e-15);
  }
}

TEST(HexVolume, TranslatedBox) {
  const Hex h = hex_test::box(2.0, 3.0, 0.5, 10.0, -7.0, 3.0);
  // Closed form a b c = 3; relative tolerance 1e-14 (coordinates up to 10 cancel in differences).
  EXPECT_NEAR(volume_of(h), 3.0, 3.0 * 1e-14);
}

TEST(HexVolume, ShearedParallelepiped) {
  const double F[3][3] = {{1.2, 0.3, -0.2}, {0.1, 0.9, 0.4}, {-0.3, 0.2, 1.1}};
  const double t[3] = {0.5, -1.0, 2.0};
  const Hex h = hex_test::affine(hex_test::box(1, 1, 1), F, t);
  const double detF = F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) -
                      F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
                      F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
  // Closed form det F (an affine image of the unit cube); the 6-tetrahedron decomposition is
  // exact for planar faces.  Relative tolerance 1e-14.
  EXPECT_NEAR(volume_of(h), detF, detF * 1e-14);
  EXPECT_NEAR(hex_test::six_tet_volume(h), detF, detF * 1e-14);
}

TEST(HexVolume, FrustumWithPlanarFaces) {
  // Non-affine but planar faces: square 1x1 at z = 0, square 0.5x0.5 (same centre) at z = 1.
  Hex h = hex_test::box(1, 1, 1);
  for (int n = 4; n < 8; ++n) {
    h.x[n] = 0.5 + 0.5 * (h.x[n] - 0.5);
    h.y[n] = 0.5 + 0.5 * (h.y[n] - 0.5);
  }
  // Frustum of a pyramid: V = h/3 (A1 + A2 + sqrt(A1 A2)) = (1 + 1/4 + 1/2)/3 = 7/12.
  // Tolerance 1e-15 absolute (O(1) numbers).
  EXPECT_NEAR(volume_of(h), 7.0 / 12.0, 1e-15);
  EXPECT_NEAR(hex_test::six_tet_volume(h), 7.0 / 12.0, 1e-15);
}

TEST(HexVolume, DistortedHexMatchesQuadratureAndTetrahedra) {
  const Hex h = hex_test::distorted();
  const double vg = hex_test::gauss_volume(h);  // exact for trilinear maps
  // The exact trilinear volume equals the 2x2x2 Gauss integral of det J and the 24-tetrahedron
  // decomposition through face and body centres (both exact for bilinear faces).
  // Relative tolerance 1e-14.
  EXPECT_NEAR(volume_of(h), vg, vg * 1e-14);
  EXPECT_NEAR(hex_test::twenty_four_tet_volume(h), vg, vg * 1e-14);
  double dx[8], dy[8], dz[8];
  EXPECT_NEAR(volume_from_derivatives(h, dx, dy, dz), vg, vg * 1e-14);
  // A 6-tetrahedron split is NOT exact for warped faces: it differs at the size of the warp.
  EXPECT_GT(std::fabs(hex_test::six_tet_volume(h) - vg), 1e-6);
}

TEST(HexVolume, DegenerateWedge) {
  // Rectangle a x L in z = 0 (nodes 1-4), nodes 5 = 6 and 7 = 8 on the ridge at height b over
  // the edge 1-4: a right triangular prism, cross-section (a b / 2), length L.
  const double a = 1.5, L = 2.0, b = 0.8;
  Hex h;
  const double px[8] = {0, a, a, 0, 0, 0, 0, 0};
  const double py[8] = {0, 0, L, L, 0, 0, L, L};
  const double pz[8] = {0, 0, 0, 0, b, b, b, b};
  for (int n = 0; n < 8; ++n) {
    h.x[n] = px[n];
    h.y[n] = py[n];
    h.z[n] = pz[n];
  }
  // Closed form a b L / 2 = 1.2; relative tolerance 1e-15 * 4.
  EXPECT_NEAR(volume_of(h), 0.5 * a * b * L, 4e-15);
  double dx[8], dy[8], dz[8];
  EXPECT_NEAR(volume_from_derivatives(h, dx, dy, dz), 0.5 * a * b * L, 4e-15);
}

TEST(HexVolume, DegenerateTetrahedron) {
  const double p[4][3] = {{0.1, 0.0, 0.2}, {1.3, 0.1, 0.0}, {0.2, 1.1, 0.1}, {0.3, 0.4, 0.9}};
  const double vt = hex_test::tet_volume(p[0], p[1], p[2], p[3]);
  ASSERT_GT(vt, 0.0);
  // Nodes 1, 2, 3, 3, 4, 4, 4, 4: the face 1-2-3-4 is the flat triangle 1-2-3 and the whole top
  // face is the apex, so the trilinear map fills exactly the tetrahedron.
  Hex h;
  const int map_a[8] = {0, 1, 2, 2, 3, 3, 3, 3};
  for (int n = 0; n < 8; ++n) {
    h.x[n] = p[map_a[n]][0];
    h.y[n] = p[map_a[n]][1];
    h.z[n] = p[map_a[n]][2];
  }
  // Closed form: the tetrahedron's volume; relative tolerance 1e-14.
  EXPECT_NEAR(volume_of(h), vt, vt * 1e-14);
  // The deck convention (deck-format.md, as LS-DYNA) n4 = n5 = ... = n8 (nodes 1, 2, 3, 4, 4, 4,
  // 4, 4) used AS IS by the trilinear hexahedron is NOT the tetrahedron: the face 1-2-3-4 becomes
  // the hyperbolic-paraboloid patch through all four vertices (boundary 1-2-3-4-1), which
  // bisects the tetrahedron, and the faces 1-2-6-5 and 2-3-7-6 are the triangles 1-2-4 and
  // 2-3-4.  The exact trilinear volume is therefore half the tetrahedron's.  (A reader should map
  // such elements to 1, 2, 3, 3, 4, 4, 4, 4.)  Closed forms: Gauss volume and vt / 2, relative
  // tolerance 1e-14.
  const int map_b[8] = {0, 1, 2, 3, 3, 3, 3, 3};
  for (int n = 0; n < 8; ++n) {
    h.x[n] = p[map_b[n]][0];
    h.y[n] = p[map_b[n]][1];
    h.z[n] = p[map_b[n]][2];
  }
  EXPECT_NEAR(volume_of(h), hex_test::gauss_volume(h), vt * 1e-14);
  EXPECT_NEAR(volume_of(h), 0.5 * vt, vt * 1e-14);
}

TEST(HexVolumeDerivatives, SumToZeroAndReproduceLinearFields) {
  const Hex hs[3] = {hex_test::box(1, 1, 1), hex_test::distorted(),
                     hex_test::box(0.3, 2.0, 1.1, 5.0, 1.0, -2.0)};
  for (const Hex& h : hs) {
    double dx[8], dy[8], dz[8];
    const double v = volume_from_derivatives(h, dx, dy, dz);
    double s[3] = {0, 0, 0};
    // G_ij = sum_I x_iI dV/dx_jI must be V delta_ij (b reproduces linear fields exactly).
    double G[3][3] = {};
    for (int n = 0; n < 8; ++n) {
      s[0] += dx[n];
      s[1] += dy[n];
      s[2] += dz[n];
      const double xi[3] = {h.x[n], h.y[n], h.z[n]};
      const double di[3] = {dx[n], dy[n], dz[n]};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) G[i][j] += xi[i] * di[j];
    }
    // Closed forms 0 and V delta_ij; tolerance 1e-14 (coordinates up to 5 times O(1)
    // derivatives, summed over 8 nodes).
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(s[i], 0.0, 1e-14);
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(G[i][j], i == j ? v : 0.0, 1e-13);
    }
  }
}

TEST(HexVolumeDerivatives, MatchCentralFiniteDifferences) {
  Hex h = hex_test::distorted();
  double dx[8], dy[8], dz[8];
  volume_from_derivatives(h, dx, dy, dz);
  // V is linear in each single coordinate (it is homogeneous of degree one in the x's, the y's
  // and the z's separately), so the central difference has no truncation error: only
  // round-off ~ 1e-16 / eps.  With eps = 1e-4 the tolerance is 1e-11.
  const double eps = 1e-4;
  for (int n = 0; n < 8; ++n) {
    double* coords[3] = {h.x, h.y, h.z};
    const double an[3] = {dx[n], dy[n], dz[n]};
    for (int i = 0; i < 3; ++i) {
      const double save = coords[i][n];
      coords[i][n] = save + eps;
      const double vp = volume_of(h);
      coords[i][n] = save - eps;
      const double vm = volume_of(h);
      coords[i][n] = save;
      EXPECT_NEAR((vp - vm) / (2 * eps), an[i], 1e-11) << "node " << n << " dir " << i;
    }
  }
}

TEST(HexFaceArea, BoxAndSheared) {
  // Box 1 x 2 x 3: largest face 2 x 3 = 6; tolerance 1e-15 relative.
  EXPECT_NEAR(calc_hex_max_face_area(hex_test::box(1, 2, 3).x, hex_test::box(1, 2, 3).y,
                                     hex_test::box(1, 2, 3).z),
              6.0, 6e-15);
  // Frustum of FrustumWithPlanarFaces: the base 1 x 1 (the trapezoid sides have area
  // (1 + 0.5)/2 * sqrt(1 + 0.25^2) = 0.773).
  Hex h = hex_test::box(1, 1, 1);
  for (int n = 4; n < 8; ++n) {
    h.x[n] = 0.5 + 0.5 * (h.x[n] - 0.5);
    h.y[n] = 0.5 + 0.5 * (h.y[n] - 0.5);
  }
  EXPECT_NEAR(calc_hex_max_face_area(h.x, h.y, h.z), 1.0, 1e-15);
  // Stretch z by 4: side trapezoids have area 0.75 * sqrt(16 + 0.0625) = 3.0052...
  for (int n = 0; n < 8; ++n) h.z[n] *= 4.0;
  EXPECT_NEAR(calc_hex_max_face_area(h.x, h.y, h.z), 0.75 * std::sqrt(16.0 + 0.0625), 1e-14);
}

namespace {

// b = dV/dx / V and the strain rate of the velocity field v = A x + v0 on hex h.
void strain_rate_of_linear_field(const Hex& h, const double A[3][3], const double v0[3],
                                 double d[6], double w[3]) {
  double dx[8], dy[8], dz[8], bx[8], by[8], bz[8], vx[8], vy[8], vz[8];
  const double v = calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
  for (int n = 0; n < 8; ++n) {
    bx[n] = dx[n] / v;
    by[n] = dy[n] / v;
    bz[n] = dz[n] / v;
    vx[n] = A[0][0] * h.x[n] + A[0][1] * h.y[n] + A[0][2] * h.z[n] + v0[0];
    vy[n] = A[1][0] * h.x[n] + A[1][1] * h.y[n] + A[1][2] * h.z[n] + v0[1];
    vz[n] = A[2][0] * h.x[n] + A[2][1] * h.y[n] + A[2][2] * h.z[n] + v0[2];
  }
  calc_hex_strain_rate(bx, by, bz, vx, vy, vz, d, w);
}

}  // namespace

TEST(HexStrainRate, RigidTranslationAndRotation) {
  const Hex h = hex_test::distorted();
  double d[6], w[3];
  const double zero[3][3] = {};
  const double v0[3] = {3.0, -2.0, 5.0};
  strain_rate_of_linear_field(h, zero, v0, d, w);
  // Closed form D = 0, W = 0; tolerance 1e-14 (|v| ~ 5, |b| ~ 1).
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(d[k], 0.0, 1e-14);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[k], 0.0, 1e-14);
  // Rigid rotation v = omega x x: L = [[0,-oz,oy],[oz,0,-ox],[-oy,ox,0]], so D = 0 and
  // w = (W_xy, W_yz, W_zx) = (-oz, -ox, -oy).  Tolerance 1e-14.
  const double o[3] = {0.7, -1.3, 2.1};
  const double A[3][3] = {{0, -o[2], o[1]}, {o[2], 0, -o[0]}, {-o[1], o[0], 0}};
  strain_rate_of_linear_field(h, A, v0, d, w);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(d[k], 0.0, 1e-14);
  EXPECT_NEAR(w[0], -o[2], 1e-14);
  EXPECT_NEAR(w[1], -o[0], 1e-14);
  EXPECT_NEAR(w[2], -o[1], 1e-14);
}

TEST(HexStrainRate, GeneralLinearFieldOnDistortedHex) {
  const Hex h = hex_test::distorted();
  const double A[3][3] = {{0.3, -1.2, 0.5}, {0.8, -0.4, 0.9}, {-0.6, 0.2, 0.7}};
  const double v0[3] = {1, 2, 3};
  double d[6], w[3];
  strain_rate_of_linear_field(h, A, v0, d, w);
  // D = sym(A), W = skew(A) exactly (uniform gradient reproduces linear fields); tolerance 1e-14.
  EXPECT_NEAR(d[0], A[0][0], 1e-14);
  EXPECT_NEAR(d[1], A[1][1], 1e-14);
  EXPECT_NEAR(d[2], A[2][2], 1e-14);
  EXPECT_NEAR(d[3], 0.5 * (A[0][1] + A[1][0]), 1e-14);
  EXPECT_NEAR(d[4], 0.5 * (A[1][2] + A[2][1]), 1e-14);
  EXPECT_NEAR(d[5], 0.5 * (A[2][0] + A[0][2]), 1e-14);
  EXPECT_NEAR(w[0], 0.5 * (A[0][1] - A[1][0]), 1e-14);
  EXPECT_NEAR(w[1], 0.5 * (A[1][2] - A[2][1]), 1e-14);
  EXPECT_NEAR(w[2], 0.5 * (A[2][0] - A[0][2]), 1e-14);
}

TEST(HexStressForce, ResultantAndVirial) {
  const Hex h = hex_test::distorted();
  double dx[8], dy[8], dz[8], fx[8], fy[8], fz[8];
  const double v = calc_hex_volume_derivatives(h.x, h.y, h.z, dx, dy, dz);
  const double sig[6] = {100.0, -50.0, 30.0, 20.0, -10.0, 5.0};
  calc_hex_stress_force(sig, dx, dy, dz, fx, fy, fz);
  // Closed forms: sum_I f_iI = 0 (self-equilibrated) and the virial sum_I f_iI x_jI = V sigma_ij.
  // Tolerance 1e-12 (stresses ~100 times O(1) geometry, 8-term sums).
  double s[3] = {0, 0, 0}, vir[3][3] = {};
  for (int n = 0; n < 8; ++n) {
    s[0] += fx[n];
    s[1] += fy[n];
    s[2] += fz[n];
    const double f[3] = {fx[n], fy[n], fz[n]};
    const double xx[3] = {h.x[n], h.y[n], h.z[n]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) vir[i][j] += f[i] * xx[j];
  }
  const double S[3][3] = {{sig[0], sig[3], sig[5]}, {sig[3], sig[1], sig[4]},
                          {sig[5], sig[4], sig[2]}};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(s[i], 0.0, 1e-12);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(vir[i][j], v * S[i][j], 1e-12);
  }
  // Unit cube: f_iI = sigma_ij n_jI / 4 with n_I = (xi, eta, zeta)_I.
  const Hex c = hex_test::box(1, 1, 1);
  calc_hex_volume_derivatives(c.x, c.y, c.z, dx, dy, dz);
  calc_hex_stress_force(sig, dx, dy, dz, fx, fy, fz);
  for (int n = 0; n < 8; ++n) {
    const double nn[3] = {hex_test::kXi[n], hex_test::kEta[n], hex_test::kZeta[n]};
    EXPECT_NEAR(fx[n], 0.25 * (S[0][0] * nn[0] + S[0][1] * nn[1] + S[0][2] * nn[2]), 1e-13);
    EXPECT_NEAR(fy[n], 0.25 * (S[1][0] * nn[0] + S[1][1] * nn[1] + S[1][2] * nn[2]), 1e-13);
    EXPECT_NEAR(fz[n], 0.25 * (S[2][0] * nn[0] + S[2][1] * nn[1] + S[2][2] * nn[2]), 1e-13);
  }
}

TEST(HexBulkViscosity, ClosedForm) {
  const double rho = 8930.0, c = 4500.0, l = 2.0, q1 = 1.5, q2 = 0.06;
  // Rigid motion / expansion: trD >= 0 gives q = 0 exactly.
  EXPECT_EQ(calc_bulk_viscosity(rho, c, l, 0.0, q1, q2), 0.0);
  EXPECT_EQ(calc_bulk_viscosity(rho, c, l, 3.0, q1, q2), 0.0);
  // Compression trD = -100: l = 2, q = rho l (q1 l trD^2 - q2 c trD)
  //   = 8930 * 2 * (1.5 * 2 * 1e4 + 0.06 * 4500 * 100) = 8930 * 2 * 57000.  Relative 1e-14.
  const double q = calc_bulk_viscosity(rho, c, l, -100.0, q1, q2);
  EXPECT_NEAR(q, 8930.0 * 2.0 * 57000.0, 8930.0 * 2.0 * 57000.0 * 1e-14);
}

TEST(HexTimeStep, UnitCubeSoundSpeedOne) {
  const Hex h = hex_test::box(1, 1, 1);
  const double a = calc_hex_max_face_area(h.x, h.y, h.z);
  const double v = calc_hex_volume(h.x, h.y, h.z);
  // l = V / A_max = 1, c = 1, no viscosity: dt = l / c = 1.  Tolerance 1e-15.
  EXPECT_NEAR(calc_hex_time_step(v, a, 1.0, 0.0, 1.5, 0.06), 1.0, 1e-15);
  EXPECT_NEAR(calc_hex_time_step(v, a, 1.0, -0.5, 0.0, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(calc_hex_time_step(v, a, 1.0, 2.0, 1.5, 0.06), 1.0, 1e-15);  // tension: Q = 0
  // Compression trD = -0.5 with q1 = 1.5, q2 = 0.06: Q = 0.06 + 0.75 = 0.81,
  // dt = 1 / (0.81 + sqrt(0.81^2 + 1)).  Tolerance 1e-15.
  EXPECT_NEAR(calc_hex_time_step(v, a, 1.0, -0.5, 1.5, 0.06),
              1.0 / (0.81 + std::sqrt(0.81 * 0.81 + 1.0)), 1e-15);
  // Box 2 x 2 x 0.5, c = 4: l = 2 / 4 = 0.5, dt = 0.125.
  const Hex b = hex_test::box(2, 2, 0.5);
  EXPECT_NEAR(calc_hex_time_step(calc_hex_volume(b.x, b.y, b.z),
                                 calc_hex_max_face_area(b.x, b.y, b.z), 4.0, 0.0, 1.5, 0.06),
              0.125, 1e-16);
}
