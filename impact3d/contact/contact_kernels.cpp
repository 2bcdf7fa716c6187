#include "impact3d/contact/contact_kernels.h"

#include <algorithm>
#include <cmath>

namespace impact3d::contact {

namespace {
constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};

inline double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
inline double norm(const double a[3]) { return std::sqrt(dot(a, a)); }

// The diagonals' normal (not normalised): (X2 - X0) x (X3 - X1), twice the area vector.
void diagonal_normal(const SegX& X, double n[3]) {
  const double d1[3] = {X[2][0] - X[0][0], X[2][1] - X[0][1], X[2][2] - X[0][2]};
  const double d2[3] = {X[3][0] - X[1][0], X[3][1] - X[1][1], X[3][2] - X[1][2]};
  cross(d1, d2, n);
}

// Point of edge e at parameter t in [0, 1] -> (xi, eta).
void edge_param(int e, double t, double& xi, double& eta) {
  switch (e) {
    case 0: xi = -1 + 2 * t; eta = -1; break;
    case 1: xi = 1; eta = -1 + 2 * t; break;
    case 2: xi = 1 - 2 * t; eta = 1; break;
    default: xi = -1; eta = 1 - 2 * t; break;
  }
}
}  // namespace

void shape4(double xi, double eta, double N[4]) {
  for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1 + kXi[a] * xi) * (1 + kEta[a] * eta);
}

void segment_point(const SegX& X, double xi, double eta, double x[3], double x_xi[3],
                   double x_eta[3]) {
  double N[4];
  shape4(xi, eta, N);
  for (int i = 0; i < 3; ++i) {
    x[i] = x_xi[i] = x_eta[i] = 0;
    for (int a = 0; a < 4; ++a) {
      x[i] += N[a] * X[a][i];
      x_xi[i] += 0.25 * kXi[a] * (1 + kEta[a] * eta) * X[a][i];
      x_eta[i] += 0.25 * kEta[a] * (1 + kXi[a] * xi) * X[a][i];
    }
  }
}

void segment_normal(const SegX& X, double xi, double eta, double n[3]) {
  double x[3], a[3], b[3];
  segment_point(X, xi, eta, x, a, b);
  cross(a, b, n);
  double len = norm(n);
  double ref[3];
  diagonal_normal(X, ref);
  const double ref_len = norm(ref);
  // tangents (nearly) parallel: the collapsed corner of a triangle
  if (!(len > 1e-8 * 0.25 * ref_len)) {
    for (int i = 0; i < 3; ++i) n[i] = ref[i];
    len = ref_len;
  }
  if (len > 0)
    for (int i = 0; i < 3; ++i) n[i] /= len;
}

double segment_area(const SegX& X) {
  double n[3];
  diagonal_normal(X, n);
  return 0.5 * norm(n);
}

int project_to_patch(const SegX& X, const double p[3], double& xi, double& eta) {
  xi = 0;
  eta = 0;
  // x_{xi eta}: constant on a bilinear patch
  double c[3];
  for (int i = 0; i < 3; ++i) c[i] = 0.25 * (X[0][i] - X[1][i] + X[2][i] - X[3][i]);
  int it = 0;
  for (; it < 30; ++it) {
    double x[3], a[3], b[3];
    segment_point(X, xi, eta, x, a, b);
    const double r[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    const double g0 = dot(r, a), g1 = dot(r, b);
    const double h00 = dot(a, a), h11 = dot(b, b);
    double h01 = dot(a, b) + dot(r, c);
    double det = h00 * h11 - h01 * h01;
    if (!(det > 1e-10 * h00 * h11)) {  // not positive: Gauss-Newton
      h01 = dot(a, b);
      det = h00 * h11 - h01 * h01;
      if (!(det > 1e-14 * h00 * h11)) break;  // degenerate patch
    }
    const double dxi = -(h11 * g0 - h01 * g1) / det;
    const double deta = -(h00 * g1 - h01 * g0) / det;
    const double xi_new = std::clamp(xi + dxi, -2.0, 2.0);
    const double eta_new = std::clamp(eta + deta, -2.0, 2.0);
    const double step = std::abs(xi_new - xi) + std::abs(eta_new - eta);
    xi = xi_new;
    eta = eta_new;
    if (step < 1e-13) {
      ++it;
      break;
    }
  }
  return it;
}

namespace {

// The straight edge e (from corner e to corner e+1) nearest to p and the parameter t in [0, 1]
// of its nearest point; the first edge at equal distance.
void nearest_edge_point(const SegX& X, const double p[3], int& best_e, double& best_t) {
  double best_d2 = 0;
  for (int e = 0; e < 4; ++e) {
    const double* A = X[e];
    const double* B = X[(e + 1) % 4];
    const double ab[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const double ap[3] = {p[0] - A[0], p[1] - A[1], p[2] - A[2]};
    const double l2 = dot(ab, ab);
    const double t = l2 > 0 ? std::clamp(dot(ap, ab) / l2, 0.0, 1.0) : 0.0;
    const double d[3] = {ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
    const double d2 = dot(d, d);
    if (e == 0 || d2 < best_d2) {
      best_e = e;
      best_t = t;
      best_d2 = d2;
    }
  }
}

}  // namespace

SegmentHit closest_point_on_segment(const SegX& X, const double p[3], std::uint8_t boundary_edges,
                                    double tol) {
  SegmentHit h;
  double xi, eta;
  project_to_patch(X, p, xi, eta);
  if (std::abs(xi) <= 1 + tol && std::abs(eta) <= 1 + tol) {
    // interior (seed fig. 2): the normal through x_p passes through the node
    double x[3], a[3], b[3];
    segment_point(X, xi, eta, x, a, b);
    h.valid = true;
    h.xi = std::clamp(xi, -1.0, 1.0);
    h.eta = std::clamp(eta, -1.0, 1.0);
    segment_normal(X, h.xi, h.eta, h.n);
    for (int i = 0; i < 3; ++i) h.xp[i] = x[i];
    const double e[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
    h.gap = dot(e, h.n);
    h.dist = norm(e);
    return h;
  }
  // beyond the square: nearest point on the straight edges
  int best_e = 0;
  double best_t = 0;
  nearest_edge_point(X, p, best_e, best_t);
  const bool bnd = (boundary_edges >> best_e) & 1;
  const bool bnd_prev = (boundary_edges >> ((best_e + 3) % 4)) & 1;
  const bool bnd_next = (boundary_edges >> ((best_e + 1) % 4)) & 1;
  if (bnd || (best_t == 0 && bnd_prev) || (best_t == 1 && bnd_next)) {
    // beyond the rim of the surface (a free edge or a symmetry plane, where the mirrored
    // neighbour is not modelled): the face extended, i.e. the normal of the clamped point,
    // accepted only for a node that is deeper below the face than it is beyond the rim
    h.xi = std::clamp(xi, -1.0, 1.0);
    h.eta = std::clamp(eta, -1.0, 1.0);
    double a[3], b[3];
    segment_point(X, h.xi, h.eta, h.xp, a, b);
    segment_normal(X, h.xi, h.eta, h.n);
    const double e[3] = {p[0] - h.xp[0], p[1] - h.xp[1], p[2] - h.xp[2]};
    h.gap = dot(e, h.n);
    h.dist = norm(e);
    const double lat[3] = {e[0] - h.gap * h.n[0], e[1] - h.gap * h.n[1], e[2] - h.gap * h.n[2]};
    h.on_edge = true;
    h.valid = h.gap < 0 && norm(lat) <= -h.gap;
    return h;
  }
  h.valid = true;
  h.on_edge = true;
  edge_param(best_e, best_t, h.xi, h.eta);
  const double* A = X[best_e];
  const double* B = X[(best_e + 1) % 4];
  for (int i = 0; i < 3; ++i) h.xp[i] = A[i] + best_t * (B[i] - A[i]);
  double ns[3];
  segment_normal(X, h.xi, h.eta, ns);
  const double e[3] = {p[0] - h.xp[0], p[1] - h.xp[1], p[2] - h.xp[2]};
  h.dist = norm(e);
  const double side = dot(e, ns);
  const double scale = std::sqrt(segment_area(X));
  if (h.dist <= 1e-12 * scale) {  // on the edge itself: no offset direction
    for (int i = 0; i < 3; ++i) h.n[i] = ns[i];
    h.gap = side;
    return h;
  }
  const double sgn = side < 0 ? -1.0 : 1.0;
  for (int i = 0; i < 3; ++i) h.n[i] = sgn * e[i] / h.dist;
  h.gap = sgn * h.dist;
  return h;
}

SegmentHit closest_point_on_shell_segment(const SegX& X, const double p[3], double tol) {
  SegmentHit h;
  h.valid = true;
  double xi, eta;
  project_to_patch(X, p, xi, eta);
  if (std::abs(xi) <= 1 + tol && std::abs(eta) <= 1 + tol) {
    double x[3], a[3], b[3];
    segment_point(X, xi, eta, x, a, b);
    h.xi = std::clamp(xi, -1.0, 1.0);
    h.eta = std::clamp(eta, -1.0, 1.0);
    double ns[3];
    segment_normal(X, h.xi, h.eta, ns);
    for (int i = 0; i < 3; ++i) h.xp[i] = x[i];
    const double e[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
    const double d = dot(e, ns);
    const double sgn = d < 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) h.n[i] = sgn * ns[i];
    h.gap = h.dist = std::abs(d);
    return h;
  }
  int best_e = 0;
  double best_t = 0;
  nearest_edge_point(X, p, best_e, best_t);
  h.on_edge = true;
  edge_param(best_e, best_t, h.xi, h.eta);
  const double* A = X[best_e];
  const double* B = X[(best_e + 1) % 4];
  for (int i = 0; i < 3; ++i) h.xp[i] = A[i] + best_t * (B[i] - A[i]);
  const double e[3] = {p[0] - h.xp[0], p[1] - h.xp[1], p[2] - h.xp[2]};
  h.dist = norm(e);
  h.gap = h.dist;
  if (h.dist <= 1e-12 * std::sqrt(segment_area(X))) {
    segment_normal(X, h.xi, h.eta, h.n);
    return h;
  }
  for (int i = 0; i < 3; ++i) h.n[i] = e[i] / h.dist;
  return h;
}

double shell_stiffness(double mu, double bulk_modulus, double area, double max_diagonal) {
  return max_diagonal > 0 ? mu * bulk_modulus * area / max_diagonal : 0.0;
}

double dyna3d_stiffness(double mu, double bulk_modulus, double area, double volume) {
  return volume > 0 ? mu * bulk_modulus * area * area / volume : 0.0;
}

double penopt_stiffness(int penopt, double k_segment, double k_node) {
  if (!(k_node > 0) || penopt == 2) return k_segment;
  if (penopt == 3) return k_node;
  return std::min(k_segment, k_node);
}

double soft_constraint_stiffness(double k0, double sofscl, double m_star, double dt_c) {
  if (!(m_star > 0) || !(dt_c > 0)) return k0;
  return std::max(k0, sofscl * 0.5 * m_star / (dt_c * dt_c));
}

double segment_pair_stiffness(double mu, double m1, double m2, double dt_c) {
  if (!(m1 > 0) || !(m2 > 0) || !(dt_c > 0)) return 0.0;
  return 0.5 * mu * (m1 * m2 / (m1 + m2)) / (dt_c * dt_c);
}

void segment_point_coordinates(int i, double& xi, double& eta) {
  constexpr double g = 0.57735026918962576451;  // 1/sqrt(3)
  xi = (i == 1 || i == 2) ? g : -g;
  eta = i >= 2 ? g : -g;
}

double max_stable_alpha(double tssf) { return std::max(1.0 - tssf * tssf, 0.01); }

double max_stable_stiffness(double tssf, double dt, double m1, double m2, bool symmetric) {
  if (!(m1 > 0) || !(m2 > 0) || !(dt > 0)) return 0.0;
  const double c = symmetric ? 2.0 : 4.0;
  return c * max_stable_alpha(tssf) / (dt * dt * (1.0 / m1 + 1.0 / m2));
}

void distribute_force(const double f[3], const double N[4], double fa[4][3]) {
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) fa[a][i] = -f[i] * N[a];
}

void pyramid_stiffness(double k, const double N[4], double K[5][5]) {
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) K[a][b] = k * N[a] * N[b];
    K[a][4] = K[4][a] = -k * N[a];
  }
  K[4][4] = k;
}

double pyramid_eigenvalue(double k, const double N[4], double m_seg, double m_node) {
  double s = 0;
  for (int a = 0; a < 4; ++a) s += N[a] * N[a];
  return k * (1.0 / m_node + s / m_seg);
}

double friction_coefficient(double fs, double fd, double decay, double vt) {
  return fd + (fs - fd) * std::exp(-decay * std::abs(vt));
}

void friction_force(double mu, double fn, const double n[3], const double vrel[3],
                    double inv_meff, double dt, double ft[3]) {
  ft[0] = ft[1] = ft[2] = 0;
  if (!(mu > 0) || !(fn > 0) || !(inv_meff > 0) || !(dt > 0)) return;
  const double vn = dot(vrel, n);
  const double vt[3] = {vrel[0] - vn * n[0], vrel[1] - vn * n[1], vrel[2] - vn * n[2]};
  const double vt_mag = norm(vt);
  if (!(vt_mag > 0)) return;
  const double cap = 0.5 * vt_mag / (dt * inv_meff);
  const double f = std::min(mu * fn, cap);
  for (int i = 0; i < 3; ++i) ft[i] = -f * vt[i] / vt_mag;
}

}  // namespace impact3d::contact
