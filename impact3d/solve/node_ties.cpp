#include "impact3d/solve/node_ties.h"

#include <algorithm>
#include <cmath>

#include "impact3d/solve/shell_processing.h"

namespace impact3d {

namespace {

// The rotational index of node n (-1: none).
int rot_of(const State& s, int n) {
  return s.shells.node_rot.empty() ? -1 : s.shells.node_rot[std::size_t(n)];
}

// The net moment on rotational dof q: minus the sum of its shell and beam corner moments.
void net_moment(const State& s, int q, double M[3]) {
  const ShellState& sh = s.shells;
  M[0] = M[1] = M[2] = 0;
  for (int c = sh.rot_corner_start[std::size_t(q)]; c < sh.rot_corner_start[std::size_t(q) + 1]; ++c) {
    const std::size_t cc = std::size_t(sh.rot_corner_list[std::size_t(c)]);
    M[0] -= sh.cmx[cc];
    M[1] -= sh.cmy[cc];
    M[2] -= sh.cmz[cc];
  }
}

// The segment of tie t at the current positions: its unit normal (the diagonals' cross product)
// and the spin weights g_a = n x r_a / sum_b |n x r_b|^2, r_a from the centre of its distinct
// nodes: sum_a g_a . v_a is the segment's rate of turning about n (exact for a rigid motion of
// a flat segment), sum_a g_a = 0, and forces T g_a on its nodes are a couple T n.
void tie_geometry(State& s, std::size_t t) {
  TieState& ts = s.ties;
  double X[4][3], c[3] = {0, 0, 0};
  const std::array<int, 4>& idx = ts.tie_master[t];
  const int distinct = idx[3] == idx[2] ? 3 : 4;
  for (int a = 0; a < 4; ++a) {
    const std::size_t k = std::size_t(ts.masters[std::size_t(idx[std::size_t(a)])]);
    X[a][0] = s.x[k], X[a][1] = s.y[k], X[a][2] = s.z[k];
  }
  for (int a = 0; a < distinct; ++a)
    for (int i = 0; i < 3; ++i) c[i] += X[a][i] / distinct;
  const double d1[3] = {X[2][0] - X[0][0], X[2][1] - X[0][1], X[2][2] - X[0][2]};
  const double d2[3] = {X[3][0] - X[1][0], X[3][1] - X[1][1], X[3][2] - X[1][2]};
  double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& v : n) v /= len;
  double g[4][3] = {}, sum = 0;
  for (int a = 0; a < distinct; ++a) {
    const double r[3] = {X[a][0] - c[0], X[a][1] - c[1], X[a][2] - c[2]};
    g[a][0] = n[1] * r[2] - n[2] * r[1], g[a][1] = n[2] * r[0] - n[0] * r[2], g[a][2] = n[0] * r[1] - n[1] * r[0];
    sum += g[a][0] * g[a][0] + g[a][1] * g[a][1] + g[a][2] * g[a][2];
  }
  for (int i = 0; i < 3; ++i) ts.normal[t][std::size_t(i)] = n[i];
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) ts.spin[t][std::size_t(3 * a + i)] = g[a][i] / sum;
}

// The segment's rate of turning about its normal: sum_a g_a . v_a.
double segment_spin(const State& s, std::size_t t) {
  const TieState& ts = s.ties;
  double w = 0;
  for (int a = 0; a < 4; ++a) {
    const std::size_t k = std::size_t(ts.masters[std::size_t(ts.tie_master[t][std::size_t(a)])]);
    const double* g = &ts.spin[t][std::size_t(3 * a)];
    w += g[0] * s.vx[k] + g[1] * s.vy[k] + g[2] * s.vz[k];
  }
  return w;
}

// The slaves' angular velocities from their masters' (the ties that turn): the weights' mix;
// about the segment's normal, for a spot weld, the slave's own (1) or the segment's spin (2).
void tie_slave_rotations(State& s) {
  const TieState& ts = s.ties;
  ShellState& sh = s.shells;
  for (std::size_t t = 0; t < ts.slave.size(); ++t) {
    if (!ts.turns[t]) continue;
    const std::size_t q = std::size_t(rot_of(s, ts.slave[t]));
    double w[3] = {0, 0, 0};
    for (int a = 0; a < 4; ++a) {
      const std::size_t r = std::size_t(rot_of(s, ts.masters[std::size_t(ts.tie_master[t][std::size_t(a)])]));
      const double c = ts.w[t][std::size_t(a)];
      w[0] += c * sh.wx[r], w[1] += c * sh.wy[r], w[2] += c * sh.wz[r];
    }
    if (ts.twist[t]) {
      const double* n = ts.normal[t].data();
      const double about = ts.twist[t] == 1 ? n[0] * sh.wx[q] + n[1] * sh.wy[q] + n[2] * sh.wz[q] : segment_spin(s, t);
      const double mixed = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
      for (int i = 0; i < 3; ++i) w[i] += (about - mixed) * n[i];
    }
    sh.wx[q] = w[0], sh.wy[q] = w[1], sh.wz[q] = w[2];
  }
}

}  // namespace

void init_node_ties(const Model& m, State& s) {
  TieState& ts = s.ties;
  ts = TieState{};
  if (m.node_ties.empty()) return;
  auto penalty = [&](const NodeTie& t) { return m.tied_contacts[std::size_t(t.contact)].offset == 1; };
  for (const NodeTie& t : m.node_ties) {
    if (!penalty(t)) continue;
    ts.pen_slave.push_back(t.node);
    ts.pen_seg.push_back(t.seg);
    ts.pen_w.push_back(t.w);
    ts.pen_gap.push_back(t.gap);
    ts.pen_rest.push_back(t.rest);
  }
  ts.pen_k.assign(ts.pen_slave.size(), 0.0);
  ts.pen_f.assign(ts.pen_slave.size(), {});
  for (const NodeTie& t : m.node_ties)
    if (!penalty(t)) ts.masters.insert(ts.masters.end(), t.seg.begin(), t.seg.end());
  std::sort(ts.masters.begin(), ts.masters.end());
  ts.masters.erase(std::unique(ts.masters.begin(), ts.masters.end()), ts.masters.end());
  for (const NodeTie& t : m.node_ties) {
    if (penalty(t)) continue;
    std::array<int, 4> idx{};
    const TiedContact& tc = m.tied_contacts[std::size_t(t.contact)];
    bool turns = tc.rotations && rot_of(s, t.node) >= 0;
    for (int a = 0; a < 4; ++a) {
      const int n = t.seg[std::size_t(a)];
      idx[std::size_t(a)] = int(std::lower_bound(ts.masters.begin(), ts.masters.end(), n) - ts.masters.begin());
      turns = turns && rot_of(s, n) >= 0;
    }
    ts.slave.push_back(t.node);
    ts.tie_master.push_back(idx);
    ts.w.push_back(t.w);
    ts.turns.push_back(turns ? 1 : 0);
    ts.twist.push_back(!turns || !tc.spotweld ? 0 : tc.torsion ? 2 : 1);
  }
  ts.normal.assign(ts.slave.size(), {});
  ts.spin.assign(ts.slave.size(), {});
  for (std::size_t t = 0; t < ts.slave.size(); ++t)
    if (ts.twist[t]) tie_geometry(s, t);
  const std::size_t nm = ts.masters.size();
  for (auto* v : {&ts.fx, &ts.fy, &ts.fz, &ts.m, &ts.mx, &ts.my, &ts.mz, &ts.j, &ts.wx0, &ts.wy0, &ts.wz0}) v->assign(nm, 0.0);
  tie_slave_velocities(s);
  tie_slave_rotations(s);
}

void tie_translations(State& s, double dt_n) {
  TieState& ts = s.ties;
  if (ts.empty() || !(dt_n > 0)) return;
  for (std::size_t a = 0; a < ts.masters.size(); ++a) {
    const std::size_t k = std::size_t(ts.masters[a]);
    ts.fx[a] = s.fx[k], ts.fy[a] = s.fy[k], ts.fz[a] = s.fz[k], ts.m[a] = s.mass[k];
  }
  // (the ties in order: the same sums for any thread count)
  for (std::size_t t = 0; t < ts.slave.size(); ++t) {
    const std::size_t k = std::size_t(ts.slave[t]);
    for (int a = 0; a < 4; ++a) {
      const std::size_t i = std::size_t(ts.tie_master[t][std::size_t(a)]);
      const double w = ts.w[t][std::size_t(a)];
      ts.fx[i] += w * s.fx[k], ts.fy[i] += w * s.fy[k], ts.fz[i] += w * s.fz[k], ts.m[i] += w * s.mass[k];
    }
    if (!ts.twist[t]) continue;
    tie_geometry(s, t);
    if (ts.twist[t] != 2) continue;
    // the slave's moment about the normal as the couple T g_a on the segment's nodes
    double M[3];
    net_moment(s, rot_of(s, ts.slave[t]), M);
    const double T = M[0] * ts.normal[t][0] + M[1] * ts.normal[t][1] + M[2] * ts.normal[t][2];
    for (int a = 0; a < 4; ++a) {
      const std::size_t i = std::size_t(ts.tie_master[t][std::size_t(a)]);
      const double* g = &ts.spin[t][std::size_t(3 * a)];
      ts.fx[i] += T * g[0], ts.fy[i] += T * g[1], ts.fz[i] += T * g[2];
    }
  }
  for (std::size_t a = 0; a < ts.masters.size(); ++a) {
    const std::size_t k = std::size_t(ts.masters[a]);
    if (!(ts.m[a] > 0)) continue;
    const std::uint8_t f = s.fix[k];
    if (!(f & 1)) s.vx[k] = s.vx_old[k] + dt_n * ts.fx[a] / ts.m[a];
    if (!(f & 2)) s.vy[k] = s.vy_old[k] + dt_n * ts.fy[a] / ts.m[a];
    if (!(f & 4)) s.vz[k] = s.vz_old[k] + dt_n * ts.fz[a] / ts.m[a];
  }
  tie_slave_velocities(s);
}

void tie_slave_velocities(State& s) {
  const TieState& ts = s.ties;
  for (std::size_t t = 0; t < ts.slave.size(); ++t) {
    double v[3] = {0, 0, 0};
    for (int a = 0; a < 4; ++a) {
      const std::size_t i = std::size_t(ts.masters[std::size_t(ts.tie_master[t][std::size_t(a)])]);
      const double w = ts.w[t][std::size_t(a)];
      v[0] += w * s.vx[i], v[1] += w * s.vy[i], v[2] += w * s.vz[i];
    }
    const std::size_t k = std::size_t(ts.slave[t]);
    s.vx[k] = v[0], s.vy[k] = v[1], s.vz[k] = v[2];
  }
}

void save_tied_rotations(State& s) {
  TieState& ts = s.ties;
  const ShellState& sh = s.shells;
  for (std::size_t a = 0; a < ts.masters.size(); ++a) {
    const int q = rot_of(s, ts.masters[a]);
    if (q < 0) continue;
    ts.wx0[a] = sh.wx[std::size_t(q)], ts.wy0[a] = sh.wy[std::size_t(q)], ts.wz0[a] = sh.wz[std::size_t(q)];
  }
}

void tie_rotations(State& s, double dt_n) {
  TieState& ts = s.ties;
  ShellState& sh = s.shells;
  if (ts.empty() || sh.nr == 0 || !(dt_n > 0)) return;
  bool any = false;
  for (std::uint8_t t : ts.turns) any = any || t;
  if (!any) return;
  double M[3];
  for (std::size_t a = 0; a < ts.masters.size(); ++a) {
    const int q = rot_of(s, ts.masters[a]);
    if (q < 0) continue;
    net_moment(s, q, M);
    ts.mx[a] = M[0], ts.my[a] = M[1], ts.mz[a] = M[2], ts.j[a] = sh.inertia[std::size_t(q)];
  }
  for (std::size_t t = 0; t < ts.slave.size(); ++t) {
    if (!ts.turns[t]) continue;
    const int q = rot_of(s, ts.slave[t]);
    net_moment(s, q, M);
    if (ts.twist[t]) {  // a spot weld: the moment about the normal is not the masters' rotations'
      const double* n = ts.normal[t].data();
      const double about = M[0] * n[0] + M[1] * n[1] + M[2] * n[2];
      for (int i = 0; i < 3; ++i) M[i] -= about * n[i];
    }
    for (int a = 0; a < 4; ++a) {
      const std::size_t i = std::size_t(ts.tie_master[t][std::size_t(a)]);
      const double w = ts.w[t][std::size_t(a)];
      ts.mx[i] += w * M[0], ts.my[i] += w * M[1], ts.mz[i] += w * M[2], ts.j[i] += w * sh.inertia[std::size_t(q)];
    }
  }
  for (std::size_t a = 0; a < ts.masters.size(); ++a) {
    const int q = rot_of(s, ts.masters[a]);
    if (q < 0 || !(ts.j[a] > 0)) continue;
    const std::size_t Q = std::size_t(q);
    const std::uint8_t f = sh.rot_fix[Q];
    if (!(f & 1)) sh.wx[Q] = ts.wx0[a] + dt_n * ts.mx[a] / ts.j[a];
    if (!(f & 2)) sh.wy[Q] = ts.wy0[a] + dt_n * ts.my[a] / ts.j[a];
    if (!(f & 4)) sh.wz[Q] = ts.wz0[a] + dt_n * ts.mz[a] / ts.j[a];
  }
  tie_slave_rotations(s);
  s.kinetic -= sh.rot_kinetic;
  sh.rot_kinetic = calc_rotational_kinetic_energy(s);
  s.kinetic += sh.rot_kinetic;
}


// ---------------------------------------------------------------- _OFFSET ties (penalty springs)

void init_offset_tie_stiffness(State& s) {
  TieState& ts = s.ties;
  for (std::size_t t = 0; t < ts.pen_slave.size(); ++t) {
    // the spring between the slave and its point: omega^2 = k (1 / m_s + sum_a w_a^2 / m_a)
    double flex = 1 / s.mass[std::size_t(ts.pen_slave[t])];
    for (int a = 0; a < 4; ++a) {
      const double w = ts.pen_w[t][std::size_t(a)];
      if (w != 0) flex += w * w / s.mass[std::size_t(ts.pen_seg[t][std::size_t(a)])];
    }
    ts.pen_k[t] = kOffsetTieStepShare * kOffsetTieStepShare / (s.dt0 * s.dt0 * flex);
  }
}

namespace {

void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

void apply_offset_ties(State& s) {
  TieState& ts = s.ties;
  // (the ties in order: the same sums for any thread count)
  for (std::size_t t = 0; t < ts.pen_slave.size(); ++t) {
    const std::array<int, 4>& seg = ts.pen_seg[t];
    double X[4][3], p[3] = {0, 0, 0};
    for (int a = 0; a < 4; ++a) {
      const std::size_t q = std::size_t(seg[std::size_t(a)]);
      X[a][0] = s.x[q], X[a][1] = s.y[q], X[a][2] = s.z[q];
      for (int i = 0; i < 3; ++i) p[i] += ts.pen_w[t][std::size_t(a)] * X[a][i];
    }
    double d1[3], d2[3], c[3];
    for (int i = 0; i < 3; ++i) d1[i] = X[2][i] - X[0][i], d2[i] = X[3][i] - X[1][i];
    cross(d1, d2, c);
    const double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    const double n[3] = {c[0] / lc, c[1] / lc, c[2] / lc};
    const std::size_t k = std::size_t(ts.pen_slave[t]);
    const double xs[3] = {s.x[k], s.y[k], s.z[k]};
    const double kk = ts.pen_k[t], gap = ts.pen_gap[t];
    double r[3];
    for (int i = 0; i < 3; ++i) r[i] = xs[i] - p[i] - gap * n[i] - ts.pen_rest[t][std::size_t(i)];
    // U = k |r|^2 / 2: the slave's force -k r, the point's k r by the weights, and the normal's
    // turning: g = k gap (I - n n) r / |c| conjugate to c = d1 x d2
    const double rn = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
    double g[3], h02[3], h13[3];
    for (int i = 0; i < 3; ++i) g[i] = kk * gap * (r[i] - rn * n[i]) / lc;
    cross(d2, g, h02);  // on x2, minus on x0
    cross(g, d1, h13);  // on x3, minus on x1
    std::array<double, 15>& f = ts.pen_f[t];
    for (int i = 0; i < 3; ++i) {
      f[std::size_t(i)] = -kk * r[i];
      for (int a = 0; a < 4; ++a) f[std::size_t(3 + 3 * a + i)] = kk * ts.pen_w[t][std::size_t(a)] * r[i];
      f[std::size_t(3 + 0 + i)] -= h02[i];
      f[std::size_t(3 + 6 + i)] += h02[i];
      f[std::size_t(3 + 3 + i)] -= h13[i];
      f[std::size_t(3 + 9 + i)] += h13[i];
    }
    s.fext_x[k] += f[0], s.fext_y[k] += f[1], s.fext_z[k] += f[2];
    for (int a = 0; a < 4; ++a) {
      const std::size_t q = std::size_t(seg[std::size_t(a)]);
      s.fext_x[q] += f[std::size_t(3 + 3 * a)], s.fext_y[q] += f[std::size_t(4 + 3 * a)], s.fext_z[q] += f[std::size_t(5 + 3 * a)];
    }
  }
}

void book_offset_tie_energy(State& s, double dt_n) {
  // the forces at x^n on the velocities at t^n, (v^{n-1/2} + v^{n+1/2}) / 2 (as the sliding
  // interfaces book theirs): the springs' energy, booked as contact energy
  const TieState& ts = s.ties;
  auto power_on = [&](std::size_t q, const double* f) {
    return 0.5 * (f[0] * (s.vx_old[q] + s.vx[q]) + f[1] * (s.vy_old[q] + s.vy[q]) + f[2] * (s.vz_old[q] + s.vz[q]));
  };
  double power = 0;
  for (std::size_t t = 0; t < ts.pen_slave.size(); ++t) {
    const std::array<double, 15>& f = ts.pen_f[t];
    power += power_on(std::size_t(ts.pen_slave[t]), &f[0]);
    for (int a = 0; a < 4; ++a) power += power_on(std::size_t(ts.pen_seg[t][std::size_t(a)]), &f[std::size_t(3 + 3 * a)]);
  }
  s.contact -= dt_n * power;
}

}  // namespace impact3d
