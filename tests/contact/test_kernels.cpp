// Unit tests of the per-point contact physics (impact3d/contact/contact_kernels.h): the
// closest point on a bilinear segment (Newton, edges, corners), the force distribution and the
// seed's 5-node pyramid spring (eqs. 3, 4, 13), the two stiffness choices, friction.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "impact3d/contact/contact_kernels.h"

using namespace impact3d::contact;

namespace {

// A warped segment (node 2 lifted): not planar, so the normal varies over it.
void warped(SegX& X) {
  const double P[4][3] = {{0, 0, 0}, {2, 0, 0}, {2.2, 1.8, 0.6}, {0, 2, 0}};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) X[a][i] = P[a][i];
}

double dist_at(const SegX& X, double xi, double eta, const double p[3]) {
  double x[3], a[3], b[3];
  segment_point(X, xi, eta, x, a, b);
  return std::sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) +
                   (x[2] - p[2]) * (x[2] - p[2]));
}

}  // namespace

// Newton on the warped patch: the residual x - p is normal to both tangents (tolerance 1e-10
// of the segment size), and no point of a fine (xi, eta) grid is closer (brute force, 1e-12).
TEST(ContactKernels, NewtonProjectionIsTheClosestPoint) {
  SegX X;
  warped(X);
  const double pts[4][3] = {{1.0, 1.0, 0.5}, {1.5, 0.7, -0.3}, {0.3, 1.6, 0.2}, {1.6, 1.4, 0.8}};
  for (const auto& p : pts) {
    double xi, eta;
    const int it = project_to_patch(X, p, xi, eta);
    EXPECT_LT(it, 12);
    ASSERT_LE(std::abs(xi), 1.0);
    ASSERT_LE(std::abs(eta), 1.0);
    double x[3], a[3], b[3];
    segment_point(X, xi, eta, x, a, b);
    const double r[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    EXPECT_NEAR(r[0] * a[0] + r[1] * a[1] + r[2] * a[2], 0.0, 1e-10);
    EXPECT_NEAR(r[0] * b[0] + r[1] * b[1] + r[2] * b[2], 0.0, 1e-10);
    const double d = dist_at(X, xi, eta, p);
    for (int i = 0; i <= 200; ++i)
      for (int j = 0; j <= 200; ++j)
        EXPECT_GE(dist_at(X, -1 + i / 100.0, -1 + j / 100.0, p), d - 1e-12);
    const SegmentHit h = closest_point_on_segment(X, p, 0, 0.01);
    EXPECT_TRUE(h.valid);
    EXPECT_FALSE(h.on_edge);
    EXPECT_NEAR(h.dist, d, 1e-12);
  }
}

// Across edges and corners where the normal jumps.  Unit square z = 0, outward normal +z.
TEST(ContactKernels, EdgesAndCorners) {
  const SegX X = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  // interior, below the face: penetration 0.1 along -z, gap -0.1, normal +z
  {
    const double p[3] = {0.3, 0.6, -0.1};
    const SegmentHit h = closest_point_on_segment(X, p, 0, 0.01);
    ASSERT_TRUE(h.valid);
    EXPECT_NEAR(h.gap, -0.1, 1e-14);
    EXPECT_NEAR(h.n[2], 1.0, 1e-14);
    EXPECT_NEAR(h.xi, -0.4, 1e-14);
    EXPECT_NEAR(h.eta, 0.2, 1e-14);
  }
  // beyond the interior edge x = 1 (shared with a neighbour), below the plane: the node is in a
  // concave corner region seen from this segment: closest point on the edge, normal along the
  // offset, gap = -distance
  {
    const double p[3] = {1.3, 0.5, -0.4};
    const SegmentHit h = closest_point_on_segment(X, p, 0, 0.01);
    ASSERT_TRUE(h.valid);
    EXPECT_TRUE(h.on_edge);
    EXPECT_NEAR(h.xi, 1.0, 1e-14);
    EXPECT_NEAR(h.eta, 0.0, 1e-14);
    EXPECT_NEAR(h.gap, -0.5, 1e-14);
    EXPECT_NEAR(h.n[0], -0.6, 1e-14);  // pushes the node back toward the edge
    EXPECT_NEAR(h.n[2], 0.8, 1e-14);
  }
  // outside a convex edge (above the plane): positive gap, no force
  {
    const double p[3] = {1.3, 0.5, 0.4};
    const SegmentHit h = closest_point_on_segment(X, p, 0, 0.01);
    ASSERT_TRUE(h.valid);
    EXPECT_NEAR(h.gap, 0.5, 1e-14);
  }
  // corner (1, 1)
  {
    const double p[3] = {1.2, 1.2, -0.1};
    const SegmentHit h = closest_point_on_segment(X, p, 0, 0.01);
    ASSERT_TRUE(h.valid);
    EXPECT_NEAR(h.xi, 1.0, 1e-14);
    EXPECT_NEAR(h.eta, 1.0, 1e-14);
    EXPECT_NEAR(h.gap, -0.3, 1e-14);
  }
  // beyond a rim edge of the surface (bit 1: edge 1 at x = 1): off the surface when further
  // beyond the rim than below the face; the face extended (gap along +z) when deeper
  {
    const double p[3] = {1.5, 0.5, -0.4};
    EXPECT_FALSE(closest_point_on_segment(X, p, 0b0010, 0.01).valid);
    const double p2[3] = {1.3, 0.5, -0.4};
    const SegmentHit h2 = closest_point_on_segment(X, p2, 0b0010, 0.01);
    ASSERT_TRUE(h2.valid);
    EXPECT_NEAR(h2.gap, -0.4, 1e-14);
    EXPECT_NEAR(h2.n[2], 1.0, 1e-14);
    EXPECT_EQ(h2.xi, 1.0);
    // within the rim tolerance it is still a face contact
    const double q[3] = {1.004, 0.5, -0.01};
    const SegmentHit h = closest_point_on_segment(X, q, 0b0010, 0.01);
    ASSERT_TRUE(h.valid);
    EXPECT_FALSE(h.on_edge);
    EXPECT_NEAR(h.gap, -0.01, 1e-14);
    EXPECT_EQ(h.xi, 1.0);
  }
}

// Seed eq. 3 / fig. 5: F on the node, -F N_A on the segment: sum zero, moment about the contact
// point zero (the forces act along one line through x_p), to round-off.
TEST(ContactKernels, ForceDistributionConservesMomentum) {
  SegX X;
  warped(X);
  const double p[3] = {1.1, 0.9, 0.1};
  const SegmentHit h = closest_point_on_segment(X, p, 0, 0.01);
  ASSERT_TRUE(h.valid);
  ASSERT_LT(h.gap, 0);
  double N[4];
  shape4(h.xi, h.eta, N);
  const double k = 3.7e9;
  const double f[3] = {-k * h.gap * h.n[0], -k * h.gap * h.n[1], -k * h.gap * h.n[2]};
  double fa[4][3];
  distribute_force(f, N, fa);
  for (int i = 0; i < 3; ++i) {
    double sum = f[i];
    for (int a = 0; a < 4; ++a) sum += fa[a][i];
    EXPECT_NEAR(sum, 0.0, 1e-15 * k);
  }
  // moment about the origin: r x F summed (node at p, segment nodes at X_A)
  double M[3] = {0, 0, 0};
  auto add = [&](const double r[3], const double F[3]) {
    M[0] += r[1] * F[2] - r[2] * F[1];
    M[1] += r[2] * F[0] - r[0] * F[2];
    M[2] += r[0] * F[1] - r[1] * F[0];
  };
  add(h.xp, f);  // the node's force, moved along its line of action to x_p
  for (int a = 0; a < 4; ++a) add(X[a], fa[a]);
  for (double c : M) EXPECT_NEAR(c, 0.0, 1e-14 * k);
}

// Seed eq. 4 and 13: the 5-node pyramid spring k [N N^T, -N; -N^T, 1] reproduces the explicit
// forces (K u = forces of the penetration p = u5 - N.u), and K x = lambda M x with
// M = diag(m1, m1, m1, m1, m5) has eigenvalues 0 (x4) and k (1/m5 + sum N^2 / m1).
// Tolerance: 1e-12 relative to the largest eigenvalue.
TEST(ContactKernels, PyramidSpringEigenvaluesSeedEq13) {
  const double k = 2.5e8, m1 = 3.0e-5, m5 = 1.3e-5;
  const double pts[4][2] = {{0.3, -0.2}, {1.0, 1.0}, {-1.0, 0.5}, {0.0, 0.0}};
  for (const auto& pt : pts) {
    double N[4];
    shape4(pt[0], pt[1], N);
    double K[5][5];
    pyramid_stiffness(k, N, K);
    // forces from K u against the explicit distribution
    const double u[5] = {1e-6, -2e-6, 0.5e-6, 3e-6, -4e-6};
    double un = 0;  // normal displacement of the contact point
    for (int a = 0; a < 4; ++a) un += N[a] * u[a];
    const double pen = u[4] - un;  // seed: p = u5 - u(p)
    const double f5[3] = {0, 0, k * pen};  // eq. 4: F5 = k u5 - k N.u
    double fa[4][3];
    distribute_force(f5, N, fa);
    for (int r = 0; r < 5; ++r) {
      double Ku = 0;
      for (int c = 0; c < 5; ++c) Ku += K[r][c] * u[c];
      const double expect = r < 4 ? fa[r][2] : f5[2];  // F_A = -F5 N_A
      EXPECT_NEAR(Ku, expect, 1e-12 * k * 1e-6);
    }
    // generalized eigenproblem with the lumped masses
    Eigen::Matrix<double, 5, 5> Km, Minv_sqrt = Eigen::Matrix<double, 5, 5>::Zero();
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 5; ++c) Km(r, c) = K[r][c];
    for (int r = 0; r < 4; ++r) Minv_sqrt(r, r) = 1 / std::sqrt(m1);
    Minv_sqrt(4, 4) = 1 / std::sqrt(m5);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 5, 5>> es(Minv_sqrt * Km * Minv_sqrt);
    const auto lam = es.eigenvalues();
    const double l5 = pyramid_eigenvalue(k, N, m1, m5);
    double sn2 = 0;
    for (double n : N) sn2 += n * n;
    EXPECT_NEAR(l5, k * (1 / m5 + sn2 / m1), 1e-15 * l5);
    EXPECT_NEAR(lam(4), l5, 1e-12 * l5);
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(lam(r), 0.0, 1e-12 * l5);
  }
  // the largest lambda_5 is node on node (N_I = 1), the two-node spring of fig. 8
  double Nc[4], Nm[4];
  shape4(1, 1, Nc);
  shape4(0, 0, Nm);
  EXPECT_GT(pyramid_eigenvalue(k, Nc, m1, m5), pyramid_eigenvalue(k, Nm, m1, m5));
  EXPECT_NEAR(pyramid_eigenvalue(k, Nc, m1, m5), k * (1 / m1 + 1 / m5), 1e-15 * k / m5);
}

// Seed eqs. 14-17: with the maximum stable stiffness the node-on-node spring (the worst case of
// eq. 13) with the masses alpha m / 2 of eq. 16 sits exactly on the stability limit 2/dt, and the
// real masses give omega dt = sqrt(2 alpha) < 2.  Tolerance 1e-14.
TEST(ContactKernels, MaxStableStiffnessSeedEq17) {
  const double tssf = 0.9, dt = 1e-7, m1 = 2e-5, m2 = 5e-5;
  const double alpha = max_stable_alpha(tssf);
  EXPECT_NEAR(alpha, 0.19, 1e-15);
  const double k = max_stable_stiffness(tssf, dt, m1, m2, true);
  EXPECT_NEAR(k, 2 * alpha / (dt * dt * (1 / m1 + 1 / m2)), 1e-14 * k);
  const double w2_fict = k * (1 / (0.5 * alpha * m1) + 1 / (0.5 * alpha * m2));
  EXPECT_NEAR(w2_fict * dt * dt, 4.0, 1e-13);
  const double w2 = k * (1 / m1 + 1 / m2);
  EXPECT_NEAR(std::sqrt(w2) * dt, std::sqrt(2 * alpha), 1e-14);
  // one pass: the spring takes the whole alpha m (eq. 14-15)
  EXPECT_NEAR(max_stable_stiffness(tssf, dt, m1, m2, false), 2 * k, 1e-14 * k);
  // DYNA3D choice: mu K A^2 / V
  EXPECT_DOUBLE_EQ(dyna3d_stiffness(0.1, 130e9, 1e-6, 1e-9), 0.1 * 130e9 * 1e-12 / 1e-9);
}

// Coulomb friction: |F_t| = mu F_n against the sliding direction while sliding, capped at half
// the force that stops the relative motion in one step.
TEST(ContactKernels, CoulombFriction) {
  EXPECT_DOUBLE_EQ(friction_coefficient(0.5, 0.3, 0.0, 2.0), 0.5);
  EXPECT_NEAR(friction_coefficient(0.5, 0.3, 1.0, 2.0), 0.3 + 0.2 * std::exp(-2.0), 1e-15);
  EXPECT_DOUBLE_EQ(friction_coefficient(0.5, 0.3, 1.0, 0.0), 0.5);
  const double n[3] = {0, 0, 1};
  const double vrel[3] = {3.0, 4.0, -7.0};  // tangential part (3, 4, 0), |v_t| = 5
  double ft[3];
  friction_force(0.3, 100.0, n, vrel, 1.0 / 1e-3, 1e-6, ft);  // cap 0.5*5*1e-3/1e-6 = 2500
  EXPECT_NEAR(ft[0], -30 * 0.6, 1e-12);
  EXPECT_NEAR(ft[1], -30 * 0.8, 1e-12);
  EXPECT_EQ(ft[2], 0.0);
  friction_force(0.3, 1e6, n, vrel, 1.0 / 1e-3, 1e-6, ft);  // capped
  EXPECT_NEAR(std::hypot(ft[0], ft[1]), 2500.0, 1e-9);
}
