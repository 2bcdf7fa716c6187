#include "impact3d/solve/spot_weld.h"

#include <cmath>
#include <utility>

namespace impact3d {

namespace {
// The node's normal now: its initial normal turned with the body.
std::array<double, 3> current_normal(const RigidBody& rb, std::size_t j) {
  const double* n = &rb.n0[3 * j];
  const auto& R = rb.rot;
  return {R[0] * n[0] + R[1] * n[1] + R[2] * n[2], R[3] * n[0] + R[4] * n[1] + R[5] * n[2],
          R[6] * n[0] + R[7] * n[1] + R[8] * n[2]};
}

// Shell k's plastic strain integrated through its thickness (its group's rule).
double shell_plastic_strain(const ShellState& sh, std::size_t k) {
  const ShellGroupConstants* c = nullptr;
  for (const ShellGroup& g : sh.groups)
    if (g.material == sh.mat[k]) c = &g.constants;
  const int nip = sh.nip[k];
  double sum = 0, wsum = 0;
  for (int p = 0; p < nip; ++p) {
    const double w = c && nip == c->nip ? c->weight[p] : 1.0;
    sum += w * sh.eps_p[shell_point_at(sh, int(k), p)];
    wsum += w;
  }
  return wsum > 0 ? sum / wsum : 0.0;
}

// The largest plastic strain over a weld's nodes, and the node (-1: no node's is positive).
std::pair<double, int> weld_plastic_strain(const State& s, const RigidBody& rb) {
  std::pair<double, int> worst{0.0, -1};
  for (int n : rb.nodes) {
    const double e = spot_weld_node_plastic_strain(s, n);
    if (e > worst.first) worst = {e, n};
  }
  return worst;
}
}  // namespace

double spot_weld_node_plastic_strain(const State& s, int n) {
  const ShellState& sh = s.shells;
  const std::size_t solid_corners = 8 * s.slot_elem.size();
  const std::size_t shell_end = sh.corner_base + 4 * std::size_t(sh.ns);
  double sum = 0, wsum = 0;
  for (int i = s.corner_start[std::size_t(n)]; i < s.corner_start[std::size_t(n) + 1]; ++i) {
    const std::size_t c = std::size_t(s.corner_list[std::size_t(i)]);
    if (c < solid_corners) {
      const int e = s.corner_element(c);
      if (e < 0 || s.rigid_elem[std::size_t(e)] || s.failed[std::size_t(e)]) continue;
      const double w = s.vol[std::size_t(e)];
      sum += w * (s.eps_p.empty() ? 0.0 : s.eps_p[std::size_t(e)]);
      wsum += w;
    } else if (c >= sh.corner_base && c < shell_end) {
      const std::size_t k = (c - sh.corner_base) / 4, j = (c - sh.corner_base) % 4;
      if (sh.rigid_elem[k] || sh.failed[k]) continue;
      if (j == 3 && sh.conn[k][3] == sh.conn[k][2]) continue;  // a triangle's node once
      const double w = sh.area[k];
      sum += w * (sh.eps_p.empty() ? 0.0 : shell_plastic_strain(sh, k));
      wsum += w;
    }  // beams: not sheets
  }
  return wsum > 0 ? sum / wsum : 0.0;
}

std::array<double, 3> spot_weld_constraint_force(const State& s, const RigidBody& rb, std::size_t j, double dt_n) {
  const std::size_t k = std::size_t(rb.nodes[j]);
  const double m = s.mass[k];
  return {m * (s.vx[k] - s.vx_old[k]) / dt_n - s.fx[k], m * (s.vy[k] - s.vy_old[k]) / dt_n - s.fy[k],
          m * (s.vz[k] - s.vz_old[k]) / dt_n - s.fz[k]};
}

double spot_weld_failure_measure(const SpotWeld& w, const State& s, const RigidBody& rb, double dt_n) {
  if (!(w.sn > 0) && !(w.ss > 0)) return 0;
  double worst = 0;
  for (std::size_t j = 0; j < rb.nodes.size(); ++j) {
    const std::array<double, 3> f = spot_weld_constraint_force(s, rb, j, dt_n);
    const std::array<double, 3> n = current_normal(rb, j);
    const double fn_signed = f[0] * n[0] + f[1] * n[1] + f[2] * n[2];
    const double sx = f[0] - fn_signed * n[0], sy = f[1] - fn_signed * n[1], sz = f[2] - fn_signed * n[2];
    const double fs = std::sqrt(sx * sx + sy * sy + sz * sz);
    const double fn = rb.axis_normal ? std::fabs(fn_signed) : std::max(fn_signed, 0.0);  // tension only
    double v = 0;
    if (w.sn > 0) v += std::pow(fn / w.sn, w.n);
    if (w.ss > 0) v += std::pow(fs / w.ss, w.m);
    worst = std::max(worst, v);
  }
  return worst;
}

void check_spot_weld_failure(const Model& m, State& s, double dt_n) {
  s.newly_released.clear();
  if (!(dt_n > 0)) return;
  for (std::size_t r = 0; r < s.rigid.size(); ++r) {
    RigidBody& rb = s.rigid[r];
    if (rb.weld < 0 || rb.released) continue;
    const SpotWeld& w = m.spot_welds[std::size_t(rb.weld)];
    if (s.time >= w.tfail || spot_weld_failure_measure(w, s, rb, dt_n) >= 1 ||
        (w.epsf > 0 && weld_plastic_strain(s, rb).first >= w.epsf)) {
      rb.released = true;
      for (int n : rb.nodes) s.rigid_of_node[std::size_t(n)] = -1;
      s.newly_released.push_back(int(r));
    }
  }
}

}  // namespace impact3d
