#include "impact3d/contact/tied_nodes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impact3d/contact/contact_kernels.h"

namespace impact3d {

namespace {

void segment_coordinates(const Model& m, const std::array<int, 4>& seg, contact::SegX& X) {
  for (int a = 0; a < 4; ++a) {
    const std::size_t n = std::size_t(seg[std::size_t(a)]);
    X[a][0] = m.x[n];
    X[a][1] = m.y[n];
    X[a][2] = m.z[n];
  }
}

double distance(const double a[3], const double b[3]) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Node p's projection on segment `seg`: true when it lies on the segment (within the extension)
// and within `reach`; then xi, eta (clamped to the square) and the distance.
bool project_on_segment(const Model& m, const std::array<int, 4>& seg, const double p[3], double reach, double& xi,
                        double& eta, double& d) {
  contact::SegX X;
  segment_coordinates(m, seg, X);
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min({X[0][i], X[1][i], X[2][i], X[3][i]}) - reach;
    hi[i] = std::max({X[0][i], X[1][i], X[2][i], X[3][i]}) + reach;
    if (p[i] < lo[i] || p[i] > hi[i]) return false;
  }
  contact::project_to_patch(X, p, xi, eta);
  const double lim = 1 + kTieSegmentExtension;
  if (!(std::fabs(xi) <= lim && std::fabs(eta) <= lim)) return false;
  xi = std::clamp(xi, -1.0, 1.0);
  eta = std::clamp(eta, -1.0, 1.0);
  double x[3], a[3], b[3];
  contact::segment_point(X, xi, eta, x, a, b);
  d = distance(p, x);
  return d <= reach;
}

}  // namespace

double tie_default_reach(const Model& m, const std::array<int, 4>& seg) {
  contact::SegX X;
  segment_coordinates(m, seg, X);
  return 0.05 * std::min(distance(X[0], X[2]), distance(X[1], X[3]));
}

std::vector<int> tie_slave_nodes(Model& m, int c) {
  TiedContact& tc = m.tied_contacts[std::size_t(c)];
  std::vector<int> untied;
  tc.tied = 0;
  for (int n : tc.slave_nodes) {
    const std::size_t k = std::size_t(n);
    const double p[3] = {m.x[k], m.y[k], m.z[k]};
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity(), best_xi = 0, best_eta = 0;
    for (std::size_t s = 0; s < tc.master.size(); ++s) {
      const std::array<int, 4>& seg = tc.master[s];
      if (std::find(seg.begin(), seg.end(), n) != seg.end()) continue;  // its own segment
      const double reach = tc.tolerance > 0 ? tc.tolerance : tie_default_reach(m, seg);
      double xi = 0, eta = 0, d = 0;
      if (project_on_segment(m, seg, p, reach, xi, eta, d) && d < best_d) {
        best = int(s), best_d = d, best_xi = xi, best_eta = eta;
      }
    }
    if (best < 0) {
      untied.push_back(n);
      continue;
    }
    NodeTie t;
    t.node = n;
    t.contact = c;
    t.seg = tc.master[std::size_t(best)];
    double N[4];
    contact::shape4(best_xi, best_eta, N);
    for (int a = 0; a < 4; ++a) t.w[std::size_t(a)] = N[a];
    if (t.seg[3] == t.seg[2]) t.w[2] += t.w[3], t.w[3] = 0;  // a triangle: its third node once
    // the node moves onto the segment
    double x[3] = {0, 0, 0};
    for (int a = 0; a < 4; ++a)
      x[0] += t.w[std::size_t(a)] * m.x[std::size_t(t.seg[std::size_t(a)])],
          x[1] += t.w[std::size_t(a)] * m.y[std::size_t(t.seg[std::size_t(a)])],
          x[2] += t.w[std::size_t(a)] * m.z[std::size_t(t.seg[std::size_t(a)])];
    m.x[k] = x[0], m.y[k] = x[1], m.z[k] = x[2];
    m.node_ties.push_back(t);
    ++tc.tied;
  }
  return untied;
}

}  // namespace impact3d
