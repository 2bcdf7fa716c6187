#pragma once
// Small helpers shared by the element tests: reference volumes computed independently of the
// kernels (2x2x2 Gauss quadrature of det J, tetrahedra), affine maps, the MacNeal-Harder patch.

#include <array>
#include <cmath>

namespace hex_test {

struct Hex {
  double x[8], y[8], z[8];
};

// Natural coordinates of the nodes in DYNA3D order.
inline constexpr double kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
inline constexpr double kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
inline constexpr double kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};

// Box [x0, x0 + a] x [y0, y0 + b] x [z0, z0 + c].
inline Hex box(double a, double b, double c, double x0 = 0, double y0 = 0, double z0 = 0) {
  Hex h;
  for (int n = 0; n < 8; ++n) {
    h.x[n] = x0 + a * 0.5 * (kXi[n] + 1);
    h.y[n] = y0 + b * 0.5 * (kEta[n] + 1);
    h.z[n] = z0 + c * 0.5 * (kZeta[n] + 1);
  }
  return h;
}

// x -> F x + t applied to every node.
inline Hex affine(const Hex& h, const double F[3][3], const double t[3]) {
  Hex r;
  for (int n = 0; n < 8; ++n) {
    r.x[n] = F[0][0] * h.x[n] + F[0][1] * h.y[n] + F[0][2] * h.z[n] + t[0];
    r.y[n] = F[1][0] * h.x[n] + F[1][1] * h.y[n] + F[1][2] * h.z[n] + t[1];
    r.z[n] = F[2][0] * h.x[n] + F[2][1] * h.y[n] + F[2][2] * h.z[n] + t[2];
  }
  return r;
}

// A general distorted hexahedron (non-planar faces), positive volume.
inline Hex distorted() {
  Hex h = box(1, 1, 1);
  const double dx[8] = {0.05, -0.10, 0.12, -0.03, 0.08, 0.15, -0.07, 0.02};
  const double dy[8] = {-0.04, 0.09, 0.03, 0.11, -0.12, 0.06, 0.10, -0.05};
  const double dz[8] = {0.07, -0.02, 0.13, -0.09, 0.04, -0.11, 0.05, 0.14};
  for (int n = 0; n < 8; ++n) {
    h.x[n] += dx[n];
    h.y[n] += dy[n];
    h.z[n] += dz[n];
  }
  return h;
}

// Volume by 2x2x2 Gauss quadrature of det(dx/dxi): det J of a trilinear map is of degree <= 2
// in each natural coordinate, so the 2-point rule is exact (to round-off).
inline double gauss_volume(const Hex& h) {
  const double g = 1.0 / std::sqrt(3.0);
  double v = 0;
  for (int i = 0; i < 8; ++i) {
    const double xi = g * kXi[i], et = g * kEta[i], ze = g * kZeta[i];
    double J[3][3] = {};
    for (int n = 0; n < 8; ++n) {
      const double dn[3] = {kXi[n] * (1 + kEta[n] * et) * (1 + kZeta[n] * ze) / 8,
                            kEta[n] * (1 + kXi[n] * xi) * (1 + kZeta[n] * ze) / 8,
                            kZeta[n] * (1 + kXi[n] * xi) * (1 + kEta[n] * et) / 8};
      for (int k = 0; k < 3; ++k) {
        J[0][k] += h.x[n] * dn[k];
        J[1][k] += h.y[n] * dn[k];
        J[2][k] += h.z[n] * dn[k];
      }
    }
    v += J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  }
  return v;  // weights are 1
}

inline double tet_volume(const double a[3], const double b[3], const double c[3],
                         const double d[3]) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

inline void node(const Hex& h, int n, double p[3]) {
  p[0] = h.x[n];
  p[1] = h.y[n];
  p[2] = h.z[n];
}

// Six tetrahedra around the main diagonal 1-7 (0-6 zero-based): exact for hexahedra whose
// faces are planar (the region is then a polyhedron and each face splits into two triangles).
inline double six_tet_volume(const Hex& h) {
  // The six tets share edge 0-6; they go around it through the ring 1,2,3,7,4,5.
  static constexpr int ring[6] = {1, 2, 3, 7, 4, 5};
  double p0[3], p6[3];
  node(h, 0, p0);
  node(h, 6, p6);
  double v = 0;
  for (int k = 0; k < 6; ++k) {
    double a[3], b[3];
    node(h, ring[k], a);
    node(h, ring[(k + 1) % 6], b);
    v += tet_volume(p0, a, b, p6);
  }
  return v;
}

// 24 tetrahedra: each face split into four triangles at its node-average centre, each coned to
// the element's node-average centre.
inline double twenty_four_tet_volume(const Hex& h) {
  static constexpr int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  double c[3] = {0, 0, 0};
  for (int n = 0; n < 8; ++n) {
    c[0] += h.x[n] / 8;
    c[1] += h.y[n] / 8;
    c[2] += h.z[n] / 8;
  }
  double v = 0;
  for (const auto& f : faces) {
    double fc[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      fc[0] += h.x[f[k]] / 4;
      fc[1] += h.y[f[k]] / 4;
      fc[2] += h.z[f[k]] / 4;
    }
    for (int k = 0; k < 4; ++k) {
      double a[3], b[3];
      node(h, f[k], a);
      node(h, f[(k + 1) % 4], b);
      // face nodes listed with outward normal (a -> b counter-clockwise seen from outside)
      v += tet_volume(c, a, b, fc);
    }
  }
  return v;
}

// MacNeal-Harder 7-element patch of the unit cube: nodes 0..7 the cube corners (DYNA3D order),
// 8..15 the interior nodes in the same order.
struct Patch {
  double x[16], y[16], z[16];
  int conn[7][8];
};

inline Patch macneal_harder_patch() {
  Patch p;
  const double inner[8][3] = {{0.249, 0.342, 0.192}, {0.826, 0.288, 0.288},
                              {0.850, 0.649, 0.263}, {0.273, 0.750, 0.230},
                              {0.320, 0.186, 0.643}, {0.677, 0.305, 0.683},
                              {0.788, 0.693, 0.644}, {0.165, 0.745, 0.702}};
  for (int n = 0; n < 8; ++n) {
    p.x[n] = 0.5 * (kXi[n] + 1);
    p.y[n] = 0.5 * (kEta[n] + 1);
    p.z[n] = 0.5 * (kZeta[n] + 1);
    p.x[8 + n] = inner[n][0];
    p.y[8 + n] = inner[n][1];
    p.z[8 + n] = inner[n][2];
  }
  const int conn[7][8] = {
      {8, 9, 10, 11, 12, 13, 14, 15},  // inner
      {0, 1, 2, 3, 8, 9, 10, 11},      // z = 0
      {12, 13, 14, 15, 4, 5, 6, 7},    // z = 1
      {0, 4, 5, 1, 8, 12, 13, 9},      // y = 0
      {3, 2, 6, 7, 11, 10, 14, 15},    // y = 1
      {0, 3, 7, 4, 8, 11, 15, 12},     // x = 0
      {1, 5, 6, 2, 9, 13, 14, 10},     // x = 1
  };
  for (int e = 0; e < 7; ++e)
    for (int k = 0; k < 8; ++k) p.conn[e][k] = conn[e][k];
  return p;
}

inline Hex patch_element(const Patch& p, int e) {
  Hex h;
  for (int k = 0; k < 8; ++k) {
    h.x[k] = p.x[p.conn[e][k]];
    h.y[k] = p.y[p.conn[e][k]];
    h.z[k] = p.z[p.conn[e][k]];
  }
  return h;
}

}  // namespace hex_test
