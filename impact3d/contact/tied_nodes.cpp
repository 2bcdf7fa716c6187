#include "impact3d/contact/tied_nodes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

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

namespace {

// The segment a node ties to among `candidates` (increasing segment indices): the nearest within
// reach, the first on equal distances; -1 when none.
struct TieChoice {
  int seg = -1;
  double xi = 0, eta = 0;
};

TieChoice choose_segment(const Model& m, const TiedContact& tc, const std::vector<double>& reach, int n,
                         const int* candidates, std::size_t count) {
  const std::size_t k = std::size_t(n);
  const double p[3] = {m.x[k], m.y[k], m.z[k]};
  TieChoice best;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t s = std::size_t(candidates[i]);
    const std::array<int, 4>& seg = tc.master[s];
    if (std::find(seg.begin(), seg.end(), n) != seg.end()) continue;  // its own segment
    double xi = 0, eta = 0, d = 0;
    if (project_on_segment(m, seg, p, reach[s], xi, eta, d) && d < best_d) {
      best.seg = int(s), best.xi = xi, best.eta = eta;
      best_d = d;
    }
  }
  return best;
}

// Ties node n to segment `ch.seg` at (xi, eta): the NodeTie appended, the node moved onto it.
void tie_node_to_segment(Model& m, TiedContact& tc, int c, int n, const TieChoice& ch) {
  NodeTie t;
  t.node = n;
  t.contact = c;
  t.seg = tc.master[std::size_t(ch.seg)];
  double N[4];
  contact::shape4(ch.xi, ch.eta, N);
  for (int a = 0; a < 4; ++a) t.w[std::size_t(a)] = N[a];
  if (t.seg[3] == t.seg[2]) t.w[2] += t.w[3], t.w[3] = 0;  // a triangle: its third node once
  double x[3] = {0, 0, 0};
  for (int a = 0; a < 4; ++a) {
    const std::size_t q = std::size_t(t.seg[std::size_t(a)]);
    x[0] += t.w[std::size_t(a)] * m.x[q];
    x[1] += t.w[std::size_t(a)] * m.y[q];
    x[2] += t.w[std::size_t(a)] * m.z[q];
  }
  const std::size_t k = std::size_t(n);
  if (tc.offset == 1) {  // a penalty spring keeps the offset: its part along the segment's normal
    contact::SegX X;
    segment_coordinates(m, t.seg, X);
    double d1[3], d2[3];
    for (int i = 0; i < 3; ++i) d1[i] = X[2][i] - X[0][i], d2[i] = X[3][i] - X[1][i];
    double nn[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
    const double ln = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
    for (double& v : nn) v /= ln;
    const double d[3] = {m.x[k] - x[0], m.y[k] - x[1], m.z[k] - x[2]};
    t.gap = d[0] * nn[0] + d[1] * nn[1] + d[2] * nn[2];
    for (int i = 0; i < 3; ++i) t.rest[std::size_t(i)] = d[i] - t.gap * nn[i];
  } else if (tc.offset == 0) {
    m.x[k] = x[0], m.y[k] = x[1], m.z[k] = x[2];
  }
  m.node_ties.push_back(t);
  ++tc.tied;
}

std::vector<double> segment_reaches(const Model& m, const TiedContact& tc) {
  std::vector<double> reach(tc.master.size());
  for (std::size_t s = 0; s < tc.master.size(); ++s)
    reach[s] = tc.tolerance > 0 ? tc.tolerance : tie_default_reach(m, tc.master[s]);
  return reach;
}

// A uniform grid over the master segments' boxes, each grown by its reach (the box
// project_on_segment tests first).  A segment is listed in every cell its grown box meets, in
// increasing segment order; a node whose cell lists no segment is out of every segment's reach,
// and a node is only within reach of the segments its cell lists.
class SegmentGrid {
 public:
  SegmentGrid(const Model& m, const TiedContact& tc, const std::vector<double>& reach) {
    const std::size_t ns = tc.master.size();
    box_.resize(6 * ns);
    double extent = 0;
    for (int i = 0; i < 3; ++i) lo_[i] = std::numeric_limits<double>::infinity(), hi_[i] = -lo_[i];
    for (std::size_t s = 0; s < ns; ++s) {
      contact::SegX X;
      segment_coordinates(m, tc.master[s], X);
      for (int i = 0; i < 3; ++i) {
        const double a = std::min({X[0][i], X[1][i], X[2][i], X[3][i]}) - reach[s];
        const double b = std::max({X[0][i], X[1][i], X[2][i], X[3][i]}) + reach[s];
        box_[6 * s + std::size_t(i)] = a, box_[6 * s + 3 + std::size_t(i)] = b;
        lo_[i] = std::min(lo_[i], a), hi_[i] = std::max(hi_[i], b);
        extent = std::max(extent, b - a);
      }
    }
    size_cells(extent, ns);
    fill_cells(ns);
  }
  // The segments listed in node p's cell (none outside the grid).
  std::pair<const int*, std::size_t> candidates(const double p[3]) const {
    std::size_t cell = 0;
    for (int i = 2; i >= 0; --i) {
      if (!(p[i] >= lo_[i] && p[i] <= hi_[i])) return {nullptr, 0};
      cell = cell * std::size_t(n_[i]) + std::size_t(index(p[i], i));
    }
    return {items_.data() + start_[cell], std::size_t(start_[cell + 1] - start_[cell])};
  }

 private:
  int index(double v, int i) const { return std::clamp(int((v - lo_[i]) / h_), 0, n_[i] - 1); }
  // Cells at least as large as the largest grown box (a segment meets at most 8), and no more
  // than about 4 cells a segment.
  void size_cells(double extent, std::size_t ns) {
    if (ns == 0) {
      for (int i = 0; i < 3; ++i) lo_[i] = hi_[i] = 0;
      return;
    }
    h_ = extent > 0 ? extent : 1;
    const double most = 4.0 * double(ns) + 8;
    double n[3];
    for (;;) {  // in doubles: spread-out tiny segments would overflow an int
      double cells = 1;
      for (int i = 0; i < 3; ++i) n[i] = std::max(1.0, std::ceil((hi_[i] - lo_[i]) / h_)), cells *= n[i];
      if (cells <= most) break;
      h_ *= 1.5;
    }
    for (int i = 0; i < 3; ++i) n_[i] = int(n[i]);
  }
  template <class F>
  void for_cells_of(std::size_t s, F&& f) const {
    int a[3], b[3];
    for (int i = 0; i < 3; ++i) a[i] = index(box_[6 * s + std::size_t(i)], i), b[i] = index(box_[6 * s + 3 + std::size_t(i)], i);
    for (int z = a[2]; z <= b[2]; ++z)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int x = a[0]; x <= b[0]; ++x) f((std::size_t(z) * std::size_t(n_[1]) + std::size_t(y)) * std::size_t(n_[0]) + std::size_t(x));
  }
  void fill_cells(std::size_t ns) {  // counting sort: each cell's segments in increasing order
    start_.assign(std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]) + 1, 0);
    for (std::size_t s = 0; s < ns; ++s) for_cells_of(s, [&](std::size_t cell) { ++start_[cell + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(std::size_t(start_.back()));
    std::vector<long long> next(start_.begin(), start_.end() - 1);
    for (std::size_t s = 0; s < ns; ++s) for_cells_of(s, [&](std::size_t cell) { items_[std::size_t(next[cell]++)] = int(s); });
  }

  double lo_[3], hi_[3], h_ = 1;
  int n_[3] = {1, 1, 1};
  std::vector<double> box_;       // per segment: grown box lo x y z, hi x y z
  std::vector<long long> start_;  // per cell: its first entry in items_ (and the end)
  std::vector<int> items_;
};

// True when a slave node is also a master node: tying it moves a segment that later nodes
// search, which a grid of the initial boxes would not see.
bool slaves_move_masters(const Model& m, const TiedContact& tc) {
  std::vector<std::uint8_t> master(m.x.size(), 0);
  for (const std::array<int, 4>& seg : tc.master)
    for (int n : seg) master[std::size_t(n)] = 1;
  for (int n : tc.slave_nodes)
    if (master[std::size_t(n)]) return true;
  return false;
}

}  // namespace

std::vector<int> tie_slave_nodes(Model& m, int c, TieSearch search) {
  TiedContact& tc = m.tied_contacts[std::size_t(c)];
  std::vector<int> untied;
  tc.tied = 0;
  const std::vector<double> reach = segment_reaches(m, tc);
  if (search == TieSearch::grid && slaves_move_masters(m, tc)) search = TieSearch::every_segment;
  std::vector<int> all;
  if (search == TieSearch::every_segment)
    for (std::size_t s = 0; s < tc.master.size(); ++s) all.push_back(int(s));
  std::optional<SegmentGrid> grid;
  if (search == TieSearch::grid) grid.emplace(m, tc, reach);
  for (int n : tc.slave_nodes) {
    const std::size_t k = std::size_t(n);
    const double p[3] = {m.x[k], m.y[k], m.z[k]};
    const auto [list, count] = grid ? grid->candidates(p) : std::pair<const int*, std::size_t>{all.data(), all.size()};
    const TieChoice ch = choose_segment(m, tc, reach, n, list, count);
    if (ch.seg < 0) untied.push_back(n);
    else tie_node_to_segment(m, tc, c, n, ch);
  }
  return untied;
}

}  // namespace impact3d
