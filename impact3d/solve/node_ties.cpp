#include "impact3d/solve/node_ties.h"

#include <algorithm>

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

// The slaves' angular velocities from their masters' (the ties that turn).
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
    sh.wx[q] = w[0], sh.wy[q] = w[1], sh.wz[q] = w[2];
  }
}

}  // namespace

void init_node_ties(const Model& m, State& s) {
  TieState& ts = s.ties;
  ts = TieState{};
  if (m.node_ties.empty()) return;
  for (const NodeTie& t : m.node_ties) ts.masters.insert(ts.masters.end(), t.seg.begin(), t.seg.end());
  std::sort(ts.masters.begin(), ts.masters.end());
  ts.masters.erase(std::unique(ts.masters.begin(), ts.masters.end()), ts.masters.end());
  for (const NodeTie& t : m.node_ties) {
    std::array<int, 4> idx{};
    bool turns = rot_of(s, t.node) >= 0;
    for (int a = 0; a < 4; ++a) {
      const int n = t.seg[std::size_t(a)];
      idx[std::size_t(a)] = int(std::lower_bound(ts.masters.begin(), ts.masters.end(), n) - ts.masters.begin());
      turns = turns && rot_of(s, n) >= 0;
    }
    ts.slave.push_back(t.node);
    ts.tie_master.push_back(idx);
    ts.w.push_back(t.w);
    ts.turns.push_back(turns ? 1 : 0);
  }
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

}  // namespace impact3d
