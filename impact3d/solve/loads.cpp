#include "impact3d/solve/loads.h"

#include <algorithm>
#include <cmath>

#include "impact3d/solve/rigid_body.h"
#include "impact3d/solve/shell_processing.h"

namespace impact3d {

double value_of_curve(const LoadCurve& lc, double t) {
  const std::size_t n = lc.t.size();
  if (n == 0) return 0;
  if (n == 1) return lc.f[0];
  // segment [j, j+1] holding t; the first and last segments extend beyond the ends
  std::size_t j = std::size_t(std::upper_bound(lc.t.begin(), lc.t.end(), t) - lc.t.begin());
  j = j == 0 ? 0 : std::min(j - 1, n - 2);
  const double t0 = lc.t[j], t1 = lc.t[j + 1];
  const double w = (t - t0) / (t1 - t0);
  return lc.f[j] + w * (lc.f[j + 1] - lc.f[j]);
}

namespace {

double curve_value(const Model& m, int curve, double t) {
  return value_of_curve(m.load_curves[std::size_t(curve)], t);
}

// Area vector of a face (right-hand rule n1 n2 n3 n4): half the cross product of the diagonals,
// which for a triangle (n3 == n4) is its area vector.
std::array<double, 3> area_vector_of_face(const State& s, const std::array<int, 4>& f) {
  const auto k = [&](int j) { return std::size_t(f[std::size_t(j)]); };
  const double ax = s.x[k(2)] - s.x[k(0)], ay = s.y[k(2)] - s.y[k(0)], az = s.z[k(2)] - s.z[k(0)];
  const double bx = s.x[k(3)] - s.x[k(1)], by = s.y[k(3)] - s.y[k(1)], bz = s.z[k(3)] - s.z[k(1)];
  return {0.5 * (ay * bz - az * by), 0.5 * (az * bx - ax * bz), 0.5 * (ax * by - ay * bx)};
}

void add_force_to_node(State& s, int node, const double* f) {
  const std::size_t k = std::size_t(node);
  s.fext_x[k] += f[0];
  s.fext_y[k] += f[1];
  s.fext_z[k] += f[2];
}

// F . (v^{n-1/2} + v^{n+1/2}) / 2 for one node
double power_on_node(const State& s, int node, const double* f) {
  const std::size_t k = std::size_t(node);
  return 0.5 * (f[0] * (s.vx_old[k] + s.vx[k]) + f[1] * (s.vy_old[k] + s.vy[k]) +
                f[2] * (s.vz_old[k] + s.vz[k]));
}

int rigid_body_of_material(const State& s, int material) {
  for (std::size_t r = 0; r < s.rigid.size(); ++r)
    if (s.rigid[r].material == material) return int(r);
  return -1;
}

bool motion_is_active(const PrescribedMotion& pm, double t) { return t >= pm.birth && t <= pm.death; }

// The velocity along pm.dir that the motion prescribes for v^{n+1/2}, from the current one
// (v^{n-1/2} for the acceleration form) and the current displacement along dir.
double prescribed_velocity(const Model& m, const PrescribedMotion& pm, double t, double dt_n,
                           double dt_next, double v_old_along, double disp_along) {
  switch (pm.kind) {
    case MotionKind::velocity:
      return pm.scale * curve_value(m, pm.curve, t + 0.5 * dt_next);
    case MotionKind::acceleration:
      return v_old_along + dt_n * pm.scale * curve_value(m, pm.curve, t);
    case MotionKind::displacement:
      return (pm.scale * curve_value(m, pm.curve, t + dt_next) - disp_along) / dt_next;
  }
  return 0;
}

// f = -D m (sx vx, sy vy, sz vz) on v^{n-1/2} (explicit, as mass damping is in central
// differences); D of this cycle kept for the work book
void apply_global_damping_to_nodes(const Model& m, State& s, LoadSet& loads, double t) {
  const GlobalDamping& g = m.damping;
  const double d = g.curve >= 0 ? curve_value(m, g.curve, t) : g.d;
  loads.damping_d = d;
  const double cx = d * g.factor[0], cy = d * g.factor[1], cz = d * g.factor[2];
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    const double mk = s.mass[k];
    s.fext_x[k] -= cx * mk * s.vx[k];
    s.fext_y[k] -= cy * mk * s.vy[k];
    s.fext_z[k] -= cz * mk * s.vz[k];
  }
}

}  // namespace

void prepare_loads(const Model& m, State& s, LoadSet& loads) {
  loads.nodal_force.assign(3 * m.nodal_loads.size(), 0.0);
  loads.pressure_force.assign(12 * m.pressure_loads.size(), 0.0);
  loads.rigid_force.assign(3 * m.rigid_body_loads.size(), 0.0);
  loads.rigid_body.clear();
  for (const RigidBodyLoad& l : m.rigid_body_loads) loads.rigid_body.push_back(rigid_body_of_material(s, l.material));
  loads.body_node.clear();
  if (!m.body_loads.empty()) {
    loads.body_node.assign(std::size_t(s.nn), m.body_load_materials.empty() ? 1 : 0);
    if (!m.body_load_materials.empty()) {
      std::vector<uint8_t> loaded(m.materials.size(), 0);
      for (int mt : m.body_load_materials) loaded[std::size_t(mt)] = 1;
      for (int e = 0; e < s.ne; ++e)
        if (loaded[std::size_t(s.mat[std::size_t(e)])])
          for (int n : s.conn[std::size_t(e)]) loads.body_node[std::size_t(n)] = 1;
    }
  }
  loads.free_velocity.assign(m.prescribed_motions.size(), 0.0);
  loads.active.assign(m.prescribed_motions.size(), 0);
  loads.delta.assign(3 * m.prescribed_motions.size(), 0.0);
  loads.motion_body.clear();
  for (const PrescribedMotion& pm : m.prescribed_motions)
    loads.motion_body.push_back(pm.node >= 0 ? -1 : rigid_body_of_material(s, pm.rigid_material));
  loads.rot_old.assign(3 * m.prescribed_motions.size(), 0.0);
  loads.has_rotations = false;
  for (const PrescribedMotion& pm : m.prescribed_motions) loads.has_rotations = loads.has_rotations || pm.rotation;
  loads.terms.assign(load_term_nodes(m).size(), 0.0);
  loads.has_loads = m.has_loads();
  loads.has_motions = !m.prescribed_motions.empty();
  s.motion_angle.assign(m.prescribed_motions.size(), 0.0);  // (a restart dump restores them)
  for (RigidBody& rb : s.rigid) rb.omega_old = rb.omega;
}

void apply_loads_to_nodes(const Model& m, State& s, LoadSet& loads, double t) {
  if (m.damping.active) apply_global_damping_to_nodes(m, s, loads, t);
  for (std::size_t j = 0; j < m.nodal_loads.size(); ++j) {
    const NodalLoad& l = m.nodal_loads[j];
    const double v = l.scale * curve_value(m, l.curve, t);
    double* f = &loads.nodal_force[3 * j];
    for (int a = 0; a < 3; ++a) f[a] = v * l.dir[std::size_t(a)];
    add_force_to_node(s, l.node, f);
  }
  for (std::size_t j = 0; j < m.rigid_body_loads.size(); ++j) {
    // at the centre of mass: spread over the body's nodes by mass (sums to F, no moment)
    const RigidBodyLoad& l = m.rigid_body_loads[j];
    double* F = &loads.rigid_force[3 * j];
    const int r = loads.rigid_body[j];
    if (r < 0) continue;
    const RigidBody& rb = s.rigid[std::size_t(r)];
    const double v = l.scale * curve_value(m, l.curve, t);
    for (int a = 0; a < 3; ++a) F[a] = v * l.dir[std::size_t(a)];
    for (int n : rb.nodes) {
      const double w = s.mass[std::size_t(n)] / rb.mass;
      const double f[3] = {w * F[0], w * F[1], w * F[2]};
      add_force_to_node(s, n, f);
    }
  }
  for (std::size_t j = 0; j < m.pressure_loads.size(); ++j) {
    const PressureLoad& l = m.pressure_loads[j];
    double* f = &loads.pressure_force[12 * j];
    std::fill(f, f + 12, 0.0);
    if (t < l.birth || t > l.death) continue;
    const double p = l.scale * curve_value(m, l.curve, t);
    const std::array<double, 3> A = area_vector_of_face(s, l.nodes);
    const bool triangle = l.nodes[2] == l.nodes[3];
    const int corners = triangle ? 3 : 4;
    for (int c = 0; c < corners; ++c) {
      // a positive pressure pushes against the normal; each corner takes its share of the
      // face, scaled by its multiplier
      const double share = -p * l.factor[std::size_t(c)] / corners;
      for (int a = 0; a < 3; ++a) f[3 * c + a] = share * A[std::size_t(a)];
      add_force_to_node(s, l.nodes[std::size_t(c)], &f[3 * c]);
    }
  }
  if (!m.body_loads.empty()) {
    std::array<double, 3> acc{};
    for (const BodyLoad& b : m.body_loads) {
      const double v = -b.scale * curve_value(m, b.curve, t);
      for (int a = 0; a < 3; ++a) acc[std::size_t(a)] += v * b.dir[std::size_t(a)];
    }
    loads.body_acc = acc;
    for (int i = 0; i < s.nn; ++i) {
      const std::size_t k = std::size_t(i);
      if (!loads.body_node[k]) continue;
      s.fext_x[k] += s.mass[k] * acc[0];
      s.fext_y[k] += s.mass[k] * acc[1];
      s.fext_z[k] += s.mass[k] * acc[2];
    }
  }
}

namespace {

double dot3(const double* a, const std::array<double, 3>& d) { return a[0] * d[0] + a[1] * d[1] + a[2] * d[2]; }
double dot3v(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// DOF -4 / -8: removes the components of v normal to d, the change into delta (3).
void hold_normal_plane(const std::array<double, 3>& d, double* v, double* delta) {
  const double along = dot3(v, d);
  for (std::size_t a = 0; a < 3; ++a) {
    const double normal = v[a] - along * d[a];
    delta[a] = -normal;
    v[a] -= normal;
  }
}

// A node's prescribed component of v^{n+1/2} (and with DOF -4 its normal plane held).
void prescribe_node(const Model& m, State& s, LoadSet& loads, std::size_t j, double t, double dt_n, double dt_next) {
  const PrescribedMotion& pm = m.prescribed_motions[j];
  const auto& d = pm.dir;
  const std::size_t k = std::size_t(pm.node);
  const double v_along = s.vx[k] * d[0] + s.vy[k] * d[1] + s.vz[k] * d[2];
  const double v_old_along = s.vx_old[k] * d[0] + s.vy_old[k] * d[1] + s.vz_old[k] * d[2];
  const double disp = (s.x[k] - m.x[k]) * d[0] + (s.y[k] - m.y[k]) * d[1] + (s.z[k] - m.z[k]) * d[2];
  const double vp = prescribed_velocity(m, pm, t, dt_n, dt_next, v_old_along, disp);
  loads.free_velocity[j] = v_along;
  loads.active[j] = 1;
  s.vx[k] += (vp - v_along) * d[0];
  s.vy[k] += (vp - v_along) * d[1];
  s.vz[k] += (vp - v_along) * d[2];
  if (!pm.hold_normal) return;
  double v[3] = {s.vx[k], s.vy[k], s.vz[k]};
  hold_normal_plane(d, v, &loads.delta[3 * j]);
  s.vx[k] = v[0], s.vy[k] = v[1], s.vz[k] = v[2];
}

// The part of a vector normal to the unit axis d.
void normal_part(const double* v, const std::array<double, 3>& d, double* out) {
  const double along = dot3(v, d);
  for (std::size_t a = 0; a < 3; ++a) out[a] = v[a] - along * d[a];
}

// How a node turning about an axis moved over the last step: the angle it turned (about d) and
// the change of its distance from the axis, both per unit time, from r^n (normal to the axis)
// and x^{n-1} = x^n - dt^{n-1/2} v^{n-1/2}; before the first step from v^{n-1/2} itself.
struct OrbitRates {
  double omega = 0, radial = 0;
};
OrbitRates last_orbit_rates(const State& s, std::size_t k, const std::array<double, 3>& d, const double* r,
                            double rho) {
  const double v_old[3] = {s.vx_old[k], s.vy_old[k], s.vz_old[k]};
  double vn[3];
  normal_part(v_old, d, vn);
  OrbitRates w;
  if (rho <= 0) return w;
  const double dxr[3] = {d[1] * r[2] - d[2] * r[1], d[2] * r[0] - d[0] * r[2], d[0] * r[1] - d[1] * r[0]};
  if (s.dt_half <= 0) {  // the first step: the rates of the initial velocity
    w.omega = dot3v(vn, dxr) / (rho * rho);
    w.radial = dot3v(vn, r) / rho;
    return w;
  }
  const double h = s.dt_half;
  const double p[3] = {r[0] - h * vn[0], r[1] - h * vn[1], r[2] - h * vn[2]};  // r^{n-1}
  const double pxr[3] = {p[1] * r[2] - p[2] * r[1], p[2] * r[0] - p[0] * r[2], p[0] * r[1] - p[1] * r[0]};
  w.omega = std::atan2(dot3(pxr, d), dot3v(p, r)) / h;
  w.radial = (rho - std::sqrt(dot3v(p, p))) / h;
  return w;
}

// A node turning about an axis (LS-DYNA DOF 9-11): its velocity normal to the axis carries it
// from x^n to x^{n+1} on the circle about the axis (the distance from the axis kept), by the
// angle omega dt (kind velocity: omega = the curve at t^{n+1/2}; acceleration: omega^{n-1/2} +
// dt^n alpha(t^n)) or up to the angle the curve gives at t^{n+1} (kind displacement); along the
// axis it moves freely.  DOF -11 to -9 (radial_free): its distance rho from the axis changes as
// a free coordinate, rho-dot^{n+1/2} = rho-dot^{n-1/2} + dt^n (f_r / m + rho omega^2), f_r / m
// the radial part of this cycle's velocity change from the forces.  The change of its velocity
// goes to delta (the reaction's work).
void prescribe_node_orbit(const Model& m, State& s, LoadSet& loads, std::size_t j, double t, double dt_n,
                          double dt_next) {
  const PrescribedMotion& pm = m.prescribed_motions[j];
  const auto& d = pm.dir;
  const std::size_t k = std::size_t(pm.node);
  const double r0[3] = {s.x[k] - pm.center[0], s.y[k] - pm.center[1], s.z[k] - pm.center[2]};
  double r[3];
  normal_part(r0, d, r);  // from the axis
  const bool rates = pm.kind == MotionKind::acceleration || pm.radial_free;
  const double rho = rates ? std::sqrt(dot3v(r, r)) : 0.0;  // its distance from the axis
  const OrbitRates was = rates ? last_orbit_rates(s, k, d, r, rho) : OrbitRates{};
  const double omega = prescribed_velocity(m, pm, t, dt_n, dt_next, was.omega, s.motion_angle[j]);
  const double turn = omega * dt_next;
  const double c = std::cos(turn), sn = std::sin(turn);
  double stretch = 1;  // rho^{n+1} / rho^n
  double* v[3] = {&s.vx[k], &s.vy[k], &s.vz[k]};
  const double v_free[3] = {*v[0], *v[1], *v[2]};
  if (pm.radial_free) {
    if (rho > 0) {
      const double dv[3] = {v_free[0] - s.vx_old[k], v_free[1] - s.vy_old[k], v_free[2] - s.vz_old[k]};
      const double w_n = 0.5 * (was.omega + omega);
      const double rate = was.radial + dot3v(dv, r) / rho + dt_n * rho * w_n * w_n;
      stretch = 1 + dt_next * rate / rho;
    }
  }
  const double dxr[3] = {d[1] * r[2] - d[2] * r[1], d[2] * r[0] - d[0] * r[2], d[0] * r[1] - d[1] * r[0]};
  const double along = dot3(v_free, d);
  loads.free_velocity[j] = along;
  loads.active[j] = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    *v[a] = along * d[a] + ((stretch * c - 1) * r[a] + stretch * sn * dxr[a]) / dt_next;
    loads.delta[3 * j + a] = *v[a] - v_free[a];
  }
  s.motion_angle[j] += turn;
}

// A rigid body's prescribed component of its centre's velocity (DOF 1-4, -4).
void prescribe_rigid_translation(const Model& m, State& s, LoadSet& loads, std::size_t j, RigidBody& rb, double t,
                                 double dt_n, double dt_next) {
  const PrescribedMotion& pm = m.prescribed_motions[j];
  const auto& d = pm.dir;
  const double v_along = rb.vcom[0] * d[0] + rb.vcom[1] * d[1] + rb.vcom[2] * d[2];
  const std::array<double, 3> vc_old = rigid_body_old_velocity(s, rb);
  const double v_old_along = vc_old[0] * d[0] + vc_old[1] * d[1] + vc_old[2] * d[2];
  double disp = 0;
  for (int a = 0; a < 3; ++a) disp += (rb.com[std::size_t(a)] - rb.com0[std::size_t(a)]) * d[std::size_t(a)];
  const double vp = prescribed_velocity(m, pm, t, dt_n, dt_next, v_old_along, disp);
  loads.free_velocity[j] = v_along;
  loads.active[j] = 1;
  for (int a = 0; a < 3; ++a) rb.vcom[std::size_t(a)] += (vp - v_along) * d[std::size_t(a)];
  if (pm.hold_normal) hold_normal_plane(d, rb.vcom.data(), &loads.delta[3 * j]);
  set_rigid_body_node_velocities(s, rb);
}

// A rigid body's prescribed angular velocity about the axis dir through its centre (DOF 5-8,
// -8): omega^{n+1/2} along dir from the curve (velocity), from omega^{n-1/2} (acceleration) or
// from the angle turned so far (displacement); the whole change of omega into delta.
void prescribe_rigid_rotation(const Model& m, State& s, LoadSet& loads, std::size_t j, RigidBody& rb, double t,
                              double dt_n, double dt_next) {
  const PrescribedMotion& pm = m.prescribed_motions[j];
  const auto& d = pm.dir;
  const double w_along = dot3(rb.omega.data(), d);
  const double w_old_along = dot3(rb.omega_old.data(), d);
  const double wp = prescribed_velocity(m, pm, t, dt_n, dt_next, w_old_along, s.motion_angle[j]);
  std::array<double, 3> w = rb.omega;
  for (std::size_t a = 0; a < 3; ++a) w[a] += (wp - w_along) * d[a];
  double held[3];
  if (pm.hold_normal) hold_normal_plane(d, w.data(), held);
  for (std::size_t a = 0; a < 3; ++a) loads.delta[3 * j + a] = w[a] - rb.omega[a];
  loads.free_velocity[j] = w_along;
  loads.active[j] = 1;
  set_rigid_body_angular_velocity(s, rb, w);
}

}  // namespace

void apply_prescribed_motions(const Model& m, State& s, LoadSet& loads, double t, double dt_n,
                              double dt_next, const std::vector<std::uint8_t>* owned) {
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j) {
    const PrescribedMotion& pm = m.prescribed_motions[j];
    loads.active[j] = 0;
    const bool node_rotation = pm.rotation && pm.node >= 0;  // (apply_prescribed_rotations)
    if (node_rotation || !motion_is_active(pm, t)) continue;
    if (pm.node >= 0) {
      if (owned && !(*owned)[std::size_t(pm.node)]) continue;  // another rank's node
      if (pm.orbit) prescribe_node_orbit(m, s, loads, j, t, dt_n, dt_next);
      else prescribe_node(m, s, loads, j, t, dt_n, dt_next);
      continue;
    }
    const int r = loads.motion_body[j];
    if (r < 0) continue;
    RigidBody& rb = s.rigid[std::size_t(r)];
    if (pm.rotation) prescribe_rigid_rotation(m, s, loads, j, rb, t, dt_n, dt_next);
    else prescribe_rigid_translation(m, s, loads, j, rb, t, dt_n, dt_next);
  }
  // the angle each rigid rotation's body turns about its axis this cycle (free or prescribed)
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j) {
    const PrescribedMotion& pm = m.prescribed_motions[j];
    if (pm.rotation && pm.node < 0 && loads.motion_body[j] >= 0)
      s.motion_angle[j] += dt_next * dot3(s.rigid[std::size_t(loads.motion_body[j])].omega.data(), pm.dir);
  }
}

void capture_rotations(const Model& m, const State& s, LoadSet& loads) {
  const ShellState& sh = s.shells;
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j) {
    const PrescribedMotion& pm = m.prescribed_motions[j];
    if (!pm.rotation || pm.node < 0 || sh.node_rot.empty()) continue;
    const int r = sh.node_rot[std::size_t(pm.node)];
    if (r < 0) continue;
    const std::size_t R = std::size_t(r);
    loads.rot_old[3 * j] = sh.wx[R], loads.rot_old[3 * j + 1] = sh.wy[R], loads.rot_old[3 * j + 2] = sh.wz[R];
  }
}

namespace {

// Node rotation j's omega^{n+1/2}: the prescribed component along its axis, with DOF -8 the
// normal ones held; returns the work of the reaction moment over the cycle.
double prescribe_node_rotation(const Model& m, State& s, const LoadSet& loads, std::size_t j, std::size_t R,
                               double t, double dt_n, double dt_next) {
  ShellState& sh = s.shells;
  const PrescribedMotion& pm = m.prescribed_motions[j];
  const auto& d = pm.dir;
  const double* w_old = &loads.rot_old[3 * j];
  const double w_free = sh.wx[R] * d[0] + sh.wy[R] * d[1] + sh.wz[R] * d[2];
  const double w = prescribed_velocity(m, pm, t, dt_n, dt_next, dot3(w_old, d), s.motion_angle[j]);
  sh.wx[R] += (w - w_free) * d[0];
  sh.wy[R] += (w - w_free) * d[1];
  sh.wz[R] += (w - w_free) * d[2];
  double work = sh.inertia[R] * (w - w_free) * 0.5 * (dot3(w_old, d) + w);
  if (pm.hold_normal) {
    double v[3] = {sh.wx[R], sh.wy[R], sh.wz[R]}, held[3];
    hold_normal_plane(d, v, held);
    sh.wx[R] = v[0], sh.wy[R] = v[1], sh.wz[R] = v[2];
    for (std::size_t a = 0; a < 3; ++a) work += sh.inertia[R] * held[a] * 0.5 * (w_old[a] + v[a]);
  }
  s.motion_angle[j] += dt_next * w;
  return work;
}

}  // namespace

void apply_prescribed_rotations(const Model& m, State& s, LoadSet& loads, double t, double dt_n, double dt_next) {
  ShellState& sh = s.shells;
  bool changed = false;
  double work = 0;
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j) {
    const PrescribedMotion& pm = m.prescribed_motions[j];
    if (!pm.rotation || pm.node < 0 || sh.node_rot.empty() || !motion_is_active(pm, t)) continue;
    const int r = sh.node_rot[std::size_t(pm.node)];
    if (r < 0) continue;
    work += prescribe_node_rotation(m, s, loads, j, std::size_t(r), t, dt_n, dt_next);
    changed = true;
  }
  if (!changed) return;
  s.kinetic -= sh.rot_kinetic;
  sh.rot_kinetic = calc_rotational_kinetic_energy(s);
  s.kinetic += sh.rot_kinetic;
  s.external_work += work;
}

namespace {

// The terms of node motion j's reaction power (load_term_nodes: 3 slots): whether it acted, m
// (v_prescribed - v_free) / dt_n along dir on the mean velocity, and its held plane's or
// orbit's change m delta / dt_n on the mean velocity.
void motion_reaction_terms(const Model& m, const State& s, const LoadSet& loads, std::size_t j, double dt_n,
                           double* out) {
  const PrescribedMotion& pm = m.prescribed_motions[j];
  out[0] = out[1] = out[2] = 0;
  if (!loads.active[j] || pm.node < 0) return;
  const auto& d = pm.dir;
  const double* delta = &loads.delta[3 * j];
  const std::size_t k = std::size_t(pm.node);
  const double v_new = s.vx[k] * d[0] + s.vy[k] * d[1] + s.vz[k] * d[2];
  const double v_old = s.vx_old[k] * d[0] + s.vy_old[k] * d[1] + s.vz_old[k] * d[2];
  out[0] = 1;
  out[1] = s.mass[k] * (v_new - loads.free_velocity[j]) / dt_n * 0.5 * (v_old + v_new);
  if (pm.hold_normal || pm.orbit)
    out[2] = s.mass[k] / dt_n * 0.5 * (delta[0] * (s.vx_old[k] + s.vx[k]) + delta[1] * (s.vy_old[k] + s.vy[k]) + delta[2] * (s.vz_old[k] + s.vz[k]));
}

// Adds to w the power of a rigid body's prescribed motion j's reaction: a rotation's reaction
// moment I delta / dt_n on the mean angular velocity; a translation's m (v_prescribed - v_free) /
// dt_n along dir on the mean velocity (a held normal plane: m delta / dt_n on it).
void add_rigid_motion_reaction_power(const Model& m, const State& s, const LoadSet& loads, std::size_t j,
                                     double dt_n, double& w) {
  const PrescribedMotion& pm = m.prescribed_motions[j];
  const int r = loads.motion_body[j];
  if (r < 0) return;
  const auto& d = pm.dir;
  const double* delta = &loads.delta[3 * j];
  const RigidBody& rb = s.rigid[std::size_t(r)];
  if (pm.rotation) {
    const std::array<double, 3> L = rigid_body_inertia_times(rb, {delta[0], delta[1], delta[2]});
    const auto& wo = rb.omega_old;
    for (std::size_t a = 0; a < 3; ++a) w += L[a] / dt_n * 0.5 * (wo[a] + rb.omega[a]);
    return;
  }
  const std::array<double, 3> vc_old = rigid_body_old_velocity(s, rb);
  const double v_new = rb.vcom[0] * d[0] + rb.vcom[1] * d[1] + rb.vcom[2] * d[2];
  const double v_old = vc_old[0] * d[0] + vc_old[1] * d[1] + vc_old[2] * d[2];
  w += rb.mass * (v_new - loads.free_velocity[j]) / dt_n * 0.5 * (v_old + v_new);
  if (pm.hold_normal)
    for (std::size_t a = 0; a < 3; ++a) w += rb.mass * delta[a] / dt_n * 0.5 * (vc_old[a] + rb.vcom[a]);
}

// A node's body-load terms m (v_old + v) and damping terms m v_old (v_old + v), x y z each.
void body_load_terms(const State& s, std::size_t k, double* out) {
  out[0] = s.mass[k] * (s.vx_old[k] + s.vx[k]);
  out[1] = s.mass[k] * (s.vy_old[k] + s.vy[k]);
  out[2] = s.mass[k] * (s.vz_old[k] + s.vz[k]);
}
void damping_terms(const State& s, std::size_t k, double* out) {
  const double mk = s.mass[k];
  out[0] = mk * s.vx_old[k] * (s.vx_old[k] + s.vx[k]);
  out[1] = mk * s.vy_old[k] * (s.vy_old[k] + s.vy[k]);
  out[2] = mk * s.vz_old[k] * (s.vz_old[k] + s.vz[k]);
}

// The node terms: from records (node_stride apart, the body's at offset 0, the damping's after
// them) or, without records, from the State.
struct NodeTerms {
  const double* records = nullptr;
  std::size_t stride = 0, damping_offset = 0;
  const double* body(const State& s, std::size_t k, double* buf) const {
    if (records) return records + stride * k;
    body_load_terms(s, k, buf);
    return buf;
  }
  const double* damping(const State& s, std::size_t k, double* buf) const {
    if (records) return records + stride * k + damping_offset;
    damping_terms(s, k, buf);
    return buf;
  }
};

// The power of the loads and of the motions' reactions this cycle: the terms summed in one
// fixed order (nodal loads, pressures, rigid body loads, body loads, motions, damping).
double external_power(const Model& m, const State& s, const LoadSet& loads, double dt_n, const double* terms,
                      const NodeTerms& nt) {
  double w = 0;
  const double* t = terms;
  for (std::size_t j = 0; j < m.nodal_loads.size(); ++j) w += *t++;
  for (const PressureLoad& l : m.pressure_loads) {
    const int corners = l.nodes[2] == l.nodes[3] ? 3 : 4;
    for (int c = 0; c < corners; ++c) w += t[c];
    t += 4;
  }
  for (std::size_t j = 0; j < m.rigid_body_loads.size(); ++j) {
    const int r = loads.rigid_body[j];
    if (r < 0) continue;
    const RigidBody& rb = s.rigid[std::size_t(r)];
    const std::array<double, 3> vo = rigid_body_old_velocity(s, rb);
    const double* F = &loads.rigid_force[3 * j];
    for (int a = 0; a < 3; ++a) w += F[a] * 0.5 * (vo[std::size_t(a)] + rb.vcom[std::size_t(a)]);
  }
  double buf[3];
  if (!m.body_loads.empty()) {
    // body forces on free components only: a held component does no work (its velocity stays)
    double px = 0, py = 0, pz = 0;
    for (int i = 0; i < s.nn; ++i) {
      const std::size_t k = std::size_t(i);
      if (!loads.body_node[k]) continue;
      const double* p = nt.body(s, k, buf);
      px += p[0];
      py += p[1];
      pz += p[2];
    }
    w += 0.5 * (loads.body_acc[0] * px + loads.body_acc[1] * py + loads.body_acc[2] * pz);
  }
  double wm = 0;  // the motions' reactions, summed apart
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j, t += 3) {
    const PrescribedMotion& pm = m.prescribed_motions[j];
    if (pm.node < 0) {
      if (loads.active[j]) add_rigid_motion_reaction_power(m, s, loads, j, dt_n, wm);
      continue;
    }
    if (t[0] == 0) continue;  // it did not act
    wm += t[1];
    if (pm.hold_normal || pm.orbit) wm += t[2];
  }
  w += wm;
  if (m.damping.active) {  // f . (v^{n-1/2} + v^{n+1/2}) / 2 summed over the nodes
    const GlobalDamping& g = m.damping;
    double px = 0, py = 0, pz = 0;
    for (int i = 0; i < s.nn; ++i) {
      const double* p = nt.damping(s, std::size_t(i), buf);
      px += p[0];
      py += p[1];
      pz += p[2];
    }
    w += -0.5 * loads.damping_d * (g.factor[0] * px + g.factor[1] * py + g.factor[2] * pz);
  }
  return w;
}

void finish_external_work(State& s, double dt_n, double w) {
  s.external_work += dt_n * w;
  for (RigidBody& rb : s.rigid) rb.omega_old = rb.omega;  // omega^{n+1/2}: the next cycle's old one
}

}  // namespace

std::vector<int> load_term_nodes(const Model& m) {
  std::vector<int> out;
  for (const NodalLoad& l : m.nodal_loads) out.push_back(l.node);
  for (const PressureLoad& l : m.pressure_loads) out.insert(out.end(), l.nodes.begin(), l.nodes.end());
  for (const PrescribedMotion& pm : m.prescribed_motions) out.insert(out.end(), 3, pm.node);
  return out;
}

void compute_load_terms(const Model& m, const State& s, const LoadSet& loads, double dt_n,
                        const std::vector<std::uint8_t>* owned, double* terms) {
  const auto mine = [&](int node) { return node >= 0 && (!owned || (*owned)[std::size_t(node)]); };
  double* t = terms;
  for (std::size_t j = 0; j < m.nodal_loads.size(); ++j, ++t)
    if (mine(m.nodal_loads[j].node)) *t = power_on_node(s, m.nodal_loads[j].node, &loads.nodal_force[3 * j]);
  for (std::size_t j = 0; j < m.pressure_loads.size(); ++j, t += 4) {
    const PressureLoad& l = m.pressure_loads[j];
    const int corners = l.nodes[2] == l.nodes[3] ? 3 : 4;
    for (int c = 0; c < corners; ++c)
      if (mine(l.nodes[std::size_t(c)]))
        t[c] = power_on_node(s, l.nodes[std::size_t(c)], &loads.pressure_force[12 * j + 3 * std::size_t(c)]);
  }
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j, t += 3)
    if (mine(m.prescribed_motions[j].node)) motion_reaction_terms(m, s, loads, j, dt_n, t);
}

int node_power_term_count(const Model& m) { return (m.body_loads.empty() ? 0 : 3) + (m.damping.active ? 3 : 0); }

void compute_node_power_terms(const Model& m, const State& s, const LoadSet& loads, std::size_t k, double* out) {
  if (!m.body_loads.empty()) {
    if (loads.body_node[k]) body_load_terms(s, k, out);
    else out[0] = out[1] = out[2] = 0;
    out += 3;
  }
  if (m.damping.active) damping_terms(s, k, out);
}

void book_external_work(const Model& m, State& s, LoadSet& loads, double dt_n) {
  compute_load_terms(m, s, loads, dt_n, nullptr, loads.terms.data());
  finish_external_work(s, dt_n, external_power(m, s, loads, dt_n, loads.terms.data(), NodeTerms{}));
}

void book_external_work_from_terms(const Model& m, State& s, const LoadSet& loads, double dt_n, const double* terms,
                                   const double* node_terms, std::size_t node_stride) {
  const NodeTerms nt{node_terms, node_stride, std::size_t(m.body_loads.empty() ? 0 : 3)};
  finish_external_work(s, dt_n, external_power(m, s, loads, dt_n, terms, nt));
}

}  // namespace impact3d
