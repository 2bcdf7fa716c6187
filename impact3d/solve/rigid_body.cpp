#include "impact3d/solve/rigid_body.h"

#include <Eigen/Dense>
#include <cmath>

namespace impact3d {

namespace {
using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

Mat3 to_mat(const std::array<double, 9>& a) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = a[std::size_t(3 * i + j)];
  return m;
}
void from_mat(const Mat3& m, std::array<double, 9>& a) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[std::size_t(3 * i + j)] = m(i, j);
}

// Angular velocity from angular momentum with the current inertia R I0 R^T (pseudo-inverse,
// so a body whose nodes are collinear still works).
Vec3 calc_omega(const RigidBody& rb) {
  Mat3 R = to_mat(rb.rot);
  Mat3 I = R * to_mat(rb.inertia0) * R.transpose();
  Vec3 L(rb.ang_mom[0], rb.ang_mom[1], rb.ang_mom[2]);
  Eigen::SelfAdjointEigenSolver<Mat3> es(I);
  Vec3 lam = es.eigenvalues();
  double tol = 1e-12 * std::max(lam.maxCoeff(), 0.0);
  Vec3 inv;
  for (int k = 0; k < 3; ++k) inv(k) = lam(k) > tol ? 1.0 / lam(k) : 0.0;
  return es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose() * L;
}

// With constrained rotations (bits of rb.fix_rotation): those components of omega are zero and
// the free ones carry the free components of L, I_ff omega_f = L_f; the constraint's moment
// takes the rest, so L becomes I omega (stored back in rb.ang_mom).
Vec3 constrained_omega(RigidBody& rb) {
  const Mat3 R = to_mat(rb.rot);
  const Mat3 I = R * to_mat(rb.inertia0) * R.transpose();
  // the free block: constrained rows and columns zeroed (their eigenvalues are then 0 and the
  // pseudo-inverse, as in calc_omega, leaves those components out)
  Mat3 Iff = I;
  Vec3 Lf(rb.ang_mom[0], rb.ang_mom[1], rb.ang_mom[2]);
  for (int a = 0; a < 3; ++a)
    if (rb.fix_rotation & (1u << a)) {
      Iff.row(a).setZero();
      Iff.col(a).setZero();
      Lf(a) = 0;
    }
  Eigen::SelfAdjointEigenSolver<Mat3> es(Iff);
  const Vec3 lam = es.eigenvalues();
  const double tol = 1e-12 * std::max(lam.maxCoeff(), 0.0);
  Vec3 inv;
  for (int k = 0; k < 3; ++k) inv(k) = lam(k) > tol ? 1.0 / lam(k) : 0.0;
  Vec3 w = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose() * Lf;
  for (int a = 0; a < 3; ++a)
    if (rb.fix_rotation & (1u << a)) w(a) = 0;
  const Vec3 L = I * w;
  for (int a = 0; a < 3; ++a) rb.ang_mom[std::size_t(a)] = L(a);
  return w;
}

Mat3 rotation_of(const Vec3& phi) {
  double a = phi.norm();
  if (a == 0) return Mat3::Identity();
  return Eigen::AngleAxisd(a, phi / a).toRotationMatrix();
}
}  // namespace

void update_rigid_body_velocities(State& s, double dt_n, double dt_next) {
  (void)dt_next;
  for (RigidBody& rb : s.rigid) {
    if (rb.released) continue;  // a failed spot weld
    Vec3 F = Vec3::Zero(), M = Vec3::Zero();
    Vec3 c(rb.com[0], rb.com[1], rb.com[2]);
    unsigned fixed = 0;
    for (int n : rb.nodes) {
      const std::size_t k = std::size_t(n);
      Vec3 f(s.fx[k], s.fy[k], s.fz[k]);
      Vec3 r = Vec3(s.x[k], s.y[k], s.z[k]) - c;
      F += f;
      M += r.cross(f);
      fixed |= s.fix[k];
      // a node with a rotational degree of freedom (deformable shells or beams on it): their
      // end and corner moments act on the body too (internal: subtracted)
      const int q = s.shells.node_rot.empty() ? -1 : s.shells.node_rot[k];
      if (q >= 0)
        for (int c = s.shells.rot_corner_start[std::size_t(q)]; c < s.shells.rot_corner_start[std::size_t(q) + 1]; ++c) {
          const std::size_t cc = std::size_t(s.shells.rot_corner_list[std::size_t(c)]);
          M -= Vec3(s.shells.cmx[cc], s.shells.cmy[cc], s.shells.cmz[cc]);
        }
    }
    fixed |= rb.fix_translation;  // the material's constraints (CMO/CON1/CON2)
    for (int a = 0; a < 3; ++a) {
      rb.vcom[std::size_t(a)] += dt_n * F(a) / rb.mass;
      if (fixed & (1u << a)) rb.vcom[std::size_t(a)] = 0;  // a fixed node fixes that translation
      rb.ang_mom[std::size_t(a)] += dt_n * M(a);
    }
    Vec3 w = rb.fix_rotation ? constrained_omega(rb) : calc_omega(rb);
    for (int a = 0; a < 3; ++a) rb.omega[std::size_t(a)] = w(a);
    set_rigid_body_node_velocities(s, rb);
  }
}

void set_rigid_body_node_velocities(State& s, const RigidBody& rb) {
  const Vec3 c(rb.com[0], rb.com[1], rb.com[2]);
  const Vec3 w(rb.omega[0], rb.omega[1], rb.omega[2]);
  const Vec3 vc(rb.vcom[0], rb.vcom[1], rb.vcom[2]);
  for (int n : rb.nodes) {
    const std::size_t k = std::size_t(n);
    Vec3 r = Vec3(s.x[k], s.y[k], s.z[k]) - c;
    Vec3 v = vc + w.cross(r);
    s.vx[k] = v(0);
    s.vy[k] = v(1);
    s.vz[k] = v(2);
  }
}

std::array<double, 3> rigid_body_old_velocity(const State& s, const RigidBody& rb) {
  double p[3] = {0, 0, 0};
  for (int n : rb.nodes) {
    const std::size_t k = std::size_t(n);
    p[0] += s.mass[k] * s.vx_old[k];
    p[1] += s.mass[k] * s.vy_old[k];
    p[2] += s.mass[k] * s.vz_old[k];
  }
  return {p[0] / rb.mass, p[1] / rb.mass, p[2] / rb.mass};
}

std::array<double, 3> rigid_body_inertia_times(const RigidBody& rb, const std::array<double, 3>& w) {
  const Mat3 R = to_mat(rb.rot);
  const Vec3 L = R * (to_mat(rb.inertia0) * (R.transpose() * Vec3(w[0], w[1], w[2])));
  return {L(0), L(1), L(2)};
}

void set_rigid_body_angular_velocity(State& s, RigidBody& rb, const std::array<double, 3>& w) {
  rb.omega = w;
  rb.ang_mom = rigid_body_inertia_times(rb, w);
  set_rigid_body_node_velocities(s, rb);
}

void update_rigid_body_positions(State& s, double dt_next) {
  for (RigidBody& rb : s.rigid) {
    if (rb.released) continue;  // a failed spot weld: its nodes moved with their velocities
    Vec3 w(rb.omega[0], rb.omega[1], rb.omega[2]);
    Mat3 R = rotation_of(w * dt_next) * to_mat(rb.rot);
    from_mat(R, rb.rot);
    for (int a = 0; a < 3; ++a) rb.com[std::size_t(a)] += dt_next * rb.vcom[std::size_t(a)];
    Vec3 c(rb.com[0], rb.com[1], rb.com[2]);
    for (std::size_t j = 0; j < rb.nodes.size(); ++j) {
      const std::size_t k = std::size_t(rb.nodes[j]);
      Vec3 x = c + R * Vec3(rb.r0[3 * j], rb.r0[3 * j + 1], rb.r0[3 * j + 2]);
      s.x[k] = x(0);
      s.y[k] = x(1);
      s.z[k] = x(2);
    }
  }
}

}  // namespace impact3d
