#include "impact3d/contact/sliding_interface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

#include "impact3d/contact/contact_kernels.h"
#include "impact3d/element/hexahedron.h"

// Type-3 sliding interfaces (shared/spec/physics.md section 5, seed part II).
//
// Each interface has two surfaces (0 slave, 1 master) and one or two passes: pass 0 puts the
// slave nodes against the master segments, pass 1 (symmetric treatment, seed fig. 4) the master
// nodes against the slave segments.  A pass, every cycle:
//   1. bucket grid of its segments, boxes grown by the largest penetration a segment accepts
//      (rebuilt every cycle: O(segments));
//   2. per node (OpenMP, each node writes only its own slot): the candidate segments are those
//      of the node's cell whose grown box holds the node, taken in segment order; the closest
//      point over them (contact_kernels); penetration p = -gap when 0 < p <= p_max; penalty
//      F = k p n plus Coulomb friction;
//   3. serial scatter in node order: F on the node, -F N_A on the segment's nodes.
// The candidate set does not depend on the grid (the box test decides), so the forces depend
// only on the positions, velocities and dt: same bits for any thread count and any rebuild
// schedule.  Nothing is allocated in apply().

namespace impact3d {

namespace {

constexpr double kInteriorTol = 0.01;  // xi/eta tolerance beyond the square (rim round-off)
constexpr double kDepthFactor = 0.5;   // p_max = 0.5 * min(thickness V/A, sqrt(A)) of the segment
// an increment of the geometric penetration beyond the node's approach by more than this
// fraction of its relative motion in the step (plus kExplainedTol p_max of round-off) is a jump
// of the geometry, not explained by the motion (the curvature's second-order term is far less)
constexpr double kJumpFraction = 0.1;
constexpr double kExplainedTol = 1e-6;

// One surface: its segments and per-segment constants.
struct Surface {
  std::vector<std::array<int, 4>> seg;
  std::vector<std::uint8_t> boundary;  // bit e: edge e is on the surface's rim
  std::vector<double> k0;              // DYNA3D stiffness mu K A^2 / V (initial geometry)
  std::vector<double> node_k;          // per node: the smallest k0 of its segments (PENOPT)
  std::vector<double> pmax;            // largest accepted penetration
  std::vector<int> elem;               // the solid each segment is a face of (-1: none found)
  std::vector<int> shell;              // the shell each segment is (-1: a solid face)
  std::vector<std::uint8_t> two_sided; // 1: a shell with its contact surfaces at +-t/2 (both sides
                                       // usable); 0: a solid face or a mid-surface shell (one side)
  // eroding interfaces: the solid on the face's other side (-1: none).  A face is in the surface
  // while its solid lives and the other one (if any) has failed: interior faces join the
  // surface as failures expose them.  A node is in the surface while one of its faces is.
  std::vector<int> other;
  std::vector<int> node_seg_start, node_seg;  // per node: its segments (eroding only)
  bool eroding = false;
  std::vector<double> offset;          // per segment: half the shell's thickness (0 for a solid face)
  double seg_off_max = 0;              // the largest of them
  // per segment, segment-based contact's segment mass: half its solid's mass, a shell's mass
  // (a segment of neither: the sum of its nodes' masses)
  std::vector<double> seg_mass;
  std::vector<double> node_off;        // per node: half the thickest shell on it (0: no shell)
  double node_off_max = 0;
  // single-surface contact: per node, its ring (the sorted nodes of the segments that have it);
  // a segment with a node of the ring is not a candidate for the node
  std::vector<int> ring_start, ring;
  // sorted, unique: first the segments' nodes (seg_nodes of them), then the side's beam nodes
  // (SlidingInterface::slave_nodes / master_nodes, sorted): contact nodes without segments
  std::vector<int> nodes;
  std::size_t seg_nodes = 0;
  std::vector<std::array<int, 4>> local;  // per segment: its nodes' indices in `nodes`
  std::vector<double> node_force;      // 3 per node: contact force of the last apply() (intfor sides only)
};

// Bucket grid over the segments of one surface.
struct Grid {
  std::vector<double> box;  // 6 per segment: lo xyz, hi xyz (grown)
  std::vector<int> cell_start, cursor, entries;
  int max_cells = 0;
  int dim[3] = {0, 0, 0};
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, h = 1;
};

// Result of one node in one pass.
struct Hit {
  int seg = -1;
  double N[4] = {0, 0, 0, 0};
  double f[3] = {0, 0, 0};   // total force on the node (normal + friction)
  double fn = 0, pen = 0;
  int evaluations = 0;
  double omega_dt = 0;  // the spring's omega dt (stability diagnostic)
  bool refused = false;  // its penetration jumped beyond its approach (the jump went to its offset)
};

// Result of one point of a segment in a segment-based pass (SOFT 2).
struct PointHit {
  int seg = -1;                 // the other side's segment hit (-1: none)
  double Nm[4] = {0, 0, 0, 0};  // its shape functions at the contact point
  double f[3] = {0, 0, 0};      // force on the point (normal + friction)
  double pen = 0, omega_dt = 0;
  int evaluations = 0;
  bool refused = false;
};

struct Pass {
  int node_side = 0, seg_side = 1;
  Grid grid;
  std::vector<Hit> hits;  // one per node of surface node_side
  // segment-based contact: contact::kSegmentPoints per segment of surface node_side (the
  // admitted depths below are then 2 per point)
  std::vector<PointHit> points;
  // 2 per node of surface node_side: last cycle's geometric penetration and the part of it
  // the node's approach did not explain (the spring's offset); both 0: not in contact
  std::vector<double> admitted;
};

struct Interface {
  Surface surf[2];
  Pass pass[2];
  int npass = 2;
  int method = 0;     // SlidingInterface::stiffness_method
  int penopt = 2;
  double sofscl = 0.1;
  double mu = 0.1, fs = 0, fd = 0, decay = 0;
  bool symmetric = true;
  bool single = false;  // single surface (DYNA3D type 4): surface 0 against itself, one pass
  bool segment_based = false;  // LS-DYNA's SOFT 2 (method 3): points of segments against segments
};

void seg_coords(const State& s, const std::array<int, 4>& sg, double X[4][3]) {
  for (int a = 0; a < 4; ++a) {
    const std::size_t k = std::size_t(sg[std::size_t(a)]);
    X[a][0] = s.x[k];
    X[a][1] = s.y[k];
    X[a][2] = s.z[k];
  }
}

// The hexahedron that has all the segment's nodes (-1 if none).
int element_of_segment(const State& s, const std::array<int, 4>& sg) {
  const int n0 = sg[0];
  for (int c = s.corner_start[std::size_t(n0)]; c < s.corner_start[std::size_t(n0) + 1]; ++c) {
    const int e = s.corner_element(std::size_t(s.corner_list[std::size_t(c)]));
    if (e < 0) continue;  // a shell corner
    const auto& hn = s.conn[std::size_t(e)];
    bool all = true;
    for (int a = 1; a < 4 && all; ++a) all = std::find(hn.begin(), hn.end(), sg[std::size_t(a)]) != hn.end();
    if (all) return e;
  }
  return -1;
}

// Sorted node key of a segment (a triangle's repeated node once, -1 padded).
std::array<int, 4> segment_key(std::array<int, 4> f) {
  std::sort(f.begin(), f.end());
  auto end = std::unique(f.begin(), f.end());
  for (auto it = end; it != f.end(); ++it) *it = -1;
  return f;
}

// Shell lookup of the segments (by their nodes) and half the thickest shell on each node.
struct ShellIndex {
  std::map<std::array<int, 4>, int> by_key;
  std::vector<double> node_half;             // per model node: over every shell and beam
  std::vector<double> node_half_deformable;  // the same over the deformable shells and beams only
};

// Half a beam's section size, its contact radius in the contacts that take thicknesses: half
// the larger side of a rectangle, a tube's outer radius, sqrt(A / pi) for a truss or a
// resultant beam (no section shape).
double beam_contact_radius(const BeamState& bm, const BeamGroup& g, int b) {
  const std::size_t B = std::size_t(b);
  if (g.kernel == BeamKernel::truss || g.kernel == BeamKernel::resultant) return std::sqrt(bm.area[B] / M_PI);
  const BeamSectionSize& z = bm.size[B];
  return z.cst == BeamCrossSection::rectangular ? 0.5 * std::max(z.ts, z.tt) : 0.5 * z.ts;
}

// Does shell k keep its +-t/2 contact surfaces under SlidingInterface::shell_thickness `mode`?
bool shell_has_offsets(const State& s, int k, int mode) {
  return mode == 2 || (mode == 1 && !s.shells.rigid_elem[std::size_t(k)]);
}

ShellIndex build_shell_index(const State& s) {
  ShellIndex ix;
  const ShellState& sh = s.shells;
  ix.node_half.assign(std::size_t(s.nn), 0.0);
  ix.node_half_deformable.assign(std::size_t(s.nn), 0.0);
  for (int k = 0; k < sh.ns; ++k) {
    ix.by_key.try_emplace(segment_key(sh.conn[std::size_t(k)]), k);
    const double half = 0.5 * sh.thick[std::size_t(k)];
    for (int n : sh.conn[std::size_t(k)]) {
      ix.node_half[std::size_t(n)] = std::max(ix.node_half[std::size_t(n)], half);
      if (shell_has_offsets(s, k, 1))
        ix.node_half_deformable[std::size_t(n)] = std::max(ix.node_half_deformable[std::size_t(n)], half);
    }
  }
  const BeamState& bm = s.beams;
  for (const BeamGroup& g : bm.groups)
    for (int q = g.first; q < g.first + g.count; ++q) {
      const int b = bm.order[std::size_t(q)];
      const double r = beam_contact_radius(bm, g, b);
      for (int j = 0; j < 2; ++j) {
        const std::size_t n = std::size_t(bm.conn[std::size_t(b)][std::size_t(j)]);
        ix.node_half[n] = std::max(ix.node_half[n], r);
        if (!bm.rigid_elem[std::size_t(b)]) ix.node_half_deformable[n] = std::max(ix.node_half_deformable[n], r);
      }
    }
  return ix;
}

// Eroding surfaces: the solids that have all the segment's nodes; elem the one the segment's
// normal points out of, other the second (-1: none).
void elements_of_eroding_segment(const State& s, const std::array<int, 4>& sg, int& elem, int& other) {
  elem = other = -1;
  double X[4][3];
  seg_coords(s, sg, X);
  const double d1[3] = {X[2][0] - X[0][0], X[2][1] - X[0][1], X[2][2] - X[0][2]};
  const double d2[3] = {X[3][0] - X[1][0], X[3][1] - X[1][1], X[3][2] - X[1][2]};
  const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  double fc[3] = {0, 0, 0};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) fc[i] += 0.25 * X[a][i];
  const int n0 = sg[0];
  for (int c = s.corner_start[std::size_t(n0)]; c < s.corner_start[std::size_t(n0) + 1]; ++c) {
    const int e = s.corner_element(std::size_t(s.corner_list[std::size_t(c)]));
    if (e < 0) continue;
    const auto& hn = s.conn[std::size_t(e)];
    bool all = true;
    for (int a = 1; a < 4 && all; ++a) all = std::find(hn.begin(), hn.end(), sg[std::size_t(a)]) != hn.end();
    if (!all) continue;
    double ec[3] = {0, 0, 0};
    for (int v : hn) {
      ec[0] += 0.125 * s.x[std::size_t(v)];
      ec[1] += 0.125 * s.y[std::size_t(v)];
      ec[2] += 0.125 * s.z[std::size_t(v)];
    }
    const bool out = n[0] * (fc[0] - ec[0]) + n[1] * (fc[1] - ec[1]) + n[2] * (fc[2] - ec[2]) > 0;
    if (out && elem < 0) elem = e;
    else if (other < 0) other = e;
  }
  if (elem < 0) std::swap(elem, other);  // (given inward: the face of that element all the same)
}

// shell_mode: SlidingInterface::shell_thickness
// free_nodes: the side's beam nodes (contact nodes without segments), appended after the
// segments' nodes
// Rim edges: those used by one segment only (a collapsed edge of a triangle is skipped); bit e
// of boundary[j] marks edge e of segment j. (Eroding: the rim of the initial surface, the faces
// without a second solid.)
void mark_rim_edges(const std::vector<std::array<int, 4>>& segs, const std::vector<int>& other,
                    std::vector<std::uint8_t>& boundary) {
  std::map<std::pair<int, int>, int> edge_count;
  for (std::size_t j = 0; j < segs.size(); ++j) {
    if (other[j] >= 0) continue;
    const auto& sg = segs[j];
    for (int e = 0; e < 4; ++e) {
      const int a = sg[std::size_t(e)], b = sg[std::size_t((e + 1) % 4)];
      if (a != b) ++edge_count[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (std::size_t j = 0; j < segs.size(); ++j) {
    const auto& sg = segs[j];
    for (int e = 0; e < 4; ++e) {
      const int a = sg[std::size_t(e)], b = sg[std::size_t((e + 1) % 4)];
      if (a != b && edge_count[{std::min(a, b), std::max(a, b)}] == 1)
        boundary[j] = std::uint8_t(boundary[j] | (1u << e));
    }
  }
}

// Segment j's element (solid, or shell k), penalty stiffness k0, contact offset and depth limit pmax.
void set_segment_stiffness(const State& s, const ShellIndex& shx, double mu, int shell_mode, std::size_t j, Surface& sf) {
  const auto& sg = sf.seg[j];
  double X[4][3];
  seg_coords(s, sg, X);
  const double area = contact::segment_area(X);
  int el = element_of_segment(s, sg);
  if (sf.eroding) {
    int ot;
    elements_of_eroding_segment(s, sg, el, ot);
  }
  sf.elem[j] = el;
  const auto it = el < 0 ? shx.by_key.find(segment_key(sg)) : shx.by_key.end();
  if (it != shx.by_key.end()) {
    // a shell: k = mu K A / (longest diagonal) (LS-DYNA's shell form).  With offsets: its
    // mid-surface with the contact surfaces at +-t/2, both sides usable, a node in contact down
    // to the mid-surface (past it, it is on the other side).  Without (DYNA3D): the
    // mid-surface itself, one-sided along the segment's normal as written, a node in contact
    // down to half the segment's width (as a solid face's depth limit)
    const int k = it->second;
    sf.shell[j] = k;
    const double d1 = std::hypot(X[2][0] - X[0][0], X[2][1] - X[0][1], X[2][2] - X[0][2]);
    const double d2 = std::hypot(X[3][0] - X[1][0], X[3][1] - X[1][1], X[3][2] - X[1][2]);
    const MaterialConstants& mk = s.mats[std::size_t(s.shells.mat[std::size_t(k)])];
    sf.k0[j] = contact::shell_stiffness(mu, mk.K, area, std::max(d1, d2));
    sf.seg_mass[j] = mk.rho * s.shells.area0[std::size_t(k)] * s.shells.thick[std::size_t(k)];
    if (shell_has_offsets(s, k, shell_mode)) {
      const double half = 0.5 * s.shells.thick[std::size_t(k)];
      sf.two_sided[j] = 1;
      sf.offset[j] = half;
      sf.pmax[j] = half;
    } else {
      sf.pmax[j] = kDepthFactor * std::sqrt(area);
    }
    return;
  }
  double vol = 0, K = 0;
  if (el >= 0) {
    vol = s.vol0[std::size_t(el)];
    K = s.mats[std::size_t(s.mat[std::size_t(el)])].K;
  }
  sf.k0[j] = contact::dyna3d_stiffness(mu, K, area, vol);
  if (el >= 0) {
    sf.seg_mass[j] = 0.5 * s.mats[std::size_t(s.mat[std::size_t(el)])].rho * vol;
  } else {
    for (int a = 0; a < 4; ++a)
      if (a == 0 || sg[std::size_t(a)] != sg[std::size_t(a) - 1]) sf.seg_mass[j] += s.mass[std::size_t(sg[std::size_t(a)])];
  }
  // deeper than half the element or half the segment's width: not a contact of this segment
  // (it keeps the grown boxes, and so the search, proportional to the segments)
  const double thick = (el >= 0 && area > 0) ? vol / area : std::sqrt(area);
  sf.pmax[j] = kDepthFactor * std::min(thick, std::sqrt(area));
}

// The surface's nodes: the segments' nodes sorted (seg_nodes of them, local indices per
// segment), then the free nodes not among them.
void index_surface_nodes(const std::vector<int>& free_nodes, Surface& sf) {
  for (const auto& sg : sf.seg)
    for (int n : sg) sf.nodes.push_back(n);
  std::sort(sf.nodes.begin(), sf.nodes.end());
  sf.nodes.erase(std::unique(sf.nodes.begin(), sf.nodes.end()), sf.nodes.end());
  sf.local.resize(sf.seg.size());
  for (std::size_t j = 0; j < sf.seg.size(); ++j)
    for (int a = 0; a < 4; ++a)
      sf.local[j][std::size_t(a)] =
          int(std::lower_bound(sf.nodes.begin(), sf.nodes.end(), sf.seg[j][std::size_t(a)]) - sf.nodes.begin());
  sf.seg_nodes = sf.nodes.size();
  for (int n : free_nodes)
    if (!std::binary_search(sf.nodes.begin(), sf.nodes.begin() + std::ptrdiff_t(sf.seg_nodes), n)) sf.nodes.push_back(n);
}

// Per node its segments (CSR, segment order; a repeated node of a segment once).
void index_node_segments(Surface& sf) {
  auto first_time = [](const std::array<int, 4>& lc, int a) {
    return a == 0 || std::find(lc.begin(), lc.begin() + a, lc[std::size_t(a)]) == lc.begin() + a;
  };
  sf.node_seg_start.assign(sf.nodes.size() + 1, 0);
  for (const auto& lc : sf.local)
    for (int a = 0; a < 4; ++a)
      if (first_time(lc, a)) ++sf.node_seg_start[std::size_t(lc[std::size_t(a)]) + 1];
  for (std::size_t q = 0; q < sf.nodes.size(); ++q) sf.node_seg_start[q + 1] += sf.node_seg_start[q];
  sf.node_seg.assign(std::size_t(sf.node_seg_start.back()), 0);
  std::vector<int> cur(sf.node_seg_start.begin(), sf.node_seg_start.end() - 1);
  for (std::size_t j = 0; j < sf.local.size(); ++j) {
    const auto& lc = sf.local[j];
    for (int a = 0; a < 4; ++a)
      if (first_time(lc, a)) sf.node_seg[std::size_t(cur[std::size_t(lc[std::size_t(a)])]++)] = int(j);
  }
}

// The nodes' own stiffness (PENOPT 1 and 3: the smallest of their segments') and shell offsets
// (a shell node touches at half its shell's thickness; none at the mid-surface).
void set_node_stiffness_and_offsets(const ShellIndex& shx, int shell_mode, Surface& sf) {
  sf.node_k.assign(sf.nodes.size(), 0.0);
  for (std::size_t j = 0; j < sf.seg.size(); ++j)
    for (int a = 0; a < 4; ++a) {
      double& kn = sf.node_k[std::size_t(sf.local[j][std::size_t(a)])];
      if (sf.k0[j] > 0) kn = kn > 0 ? std::min(kn, sf.k0[j]) : sf.k0[j];
    }
  sf.node_off.assign(sf.nodes.size(), 0.0);
  sf.node_off_max = 0;
  if (shell_mode == 0) return;
  const std::vector<double>& half = shell_mode == 2 ? shx.node_half : shx.node_half_deformable;
  for (std::size_t q = 0; q < sf.nodes.size(); ++q) {
    sf.node_off[q] = half[std::size_t(sf.nodes[q])];
    sf.node_off_max = std::max(sf.node_off_max, sf.node_off[q]);
  }
}

void build_surface(const State& s, const ShellIndex& shx, const std::vector<std::array<int, 4>>& segs,
                   const std::vector<int>& free_nodes, double mu, int shell_mode, Surface& sf, bool eroding = false) {
  sf.seg = segs;
  sf.eroding = eroding;
  const std::size_t ns = segs.size();
  sf.other.assign(ns, -1);
  if (eroding)
    for (std::size_t j = 0; j < ns; ++j) {
      int el, ot;
      elements_of_eroding_segment(s, segs[j], el, ot);
      sf.other[j] = ot;
    }
  sf.boundary.assign(ns, 0);
  sf.k0.assign(ns, 0.0);
  sf.pmax.assign(ns, 0.0);
  sf.elem.assign(ns, -1);
  sf.shell.assign(ns, -1);
  sf.two_sided.assign(ns, 0);
  sf.offset.assign(ns, 0.0);
  sf.seg_mass.assign(ns, 0.0);
  mark_rim_edges(segs, sf.other, sf.boundary);
  for (std::size_t j = 0; j < ns; ++j) set_segment_stiffness(s, shx, mu, shell_mode, j, sf);
  sf.seg_off_max = ns ? *std::max_element(sf.offset.begin(), sf.offset.end()) : 0.0;
  index_surface_nodes(free_nodes, sf);
  if (eroding) index_node_segments(sf);
  set_node_stiffness_and_offsets(shx, shell_mode, sf);
}

// The rings of a single surface: for each node the nodes of the segments that have it.
void build_rings(Surface& sf) {
  const std::size_t nn = sf.nodes.size();
  std::vector<std::vector<int>> r(nn);
  for (const auto& lc : sf.local)
    for (int a : lc)
      for (int b : lc) r[std::size_t(a)].push_back(sf.nodes[std::size_t(b)]);
  sf.ring_start.assign(nn + 1, 0);
  sf.ring.clear();
  for (std::size_t q = 0; q < nn; ++q) {
    std::sort(r[q].begin(), r[q].end());
    r[q].erase(std::unique(r[q].begin(), r[q].end()), r[q].end());
    sf.ring.insert(sf.ring.end(), r[q].begin(), r[q].end());
    sf.ring_start[q + 1] = int(sf.ring.size());
  }
}

// A force transducer: node flags (bit 1 side A, bit 2 side B) over the model's nodes.
struct Transducer {
  std::vector<std::uint8_t> flag;
  bool has_b = false;
};

void allocate_grid(std::size_t nseg, Grid& g) {
  g.box.assign(6 * nseg, 0.0);
  g.max_cells = int(4 * nseg + 64);
  g.cell_start.assign(std::size_t(g.max_cells) + 1, 0);
  g.cursor.assign(std::size_t(g.max_cells), 0);
  g.entries.assign(8 * nseg, 0);
}

inline int cell_coord(const Grid& g, int a, double v) {
  return std::clamp(int(std::floor((v - g.lo[a]) / g.h)), 0, g.dim[a] - 1);
}

// Grown boxes of the segments at the current positions, then the grid (counting sort, segments
// in increasing order in every cell).
// extra: the largest offset of the nodes searched (their own shell half-thickness).
void rebuild_grid(const State& s, const Surface& sf, double extra, Grid& g) {
  const std::size_t ns = sf.seg.size();
  double hmax = 0;
  for (int a = 0; a < 3; ++a) {
    g.lo[a] = 1e300;
    g.hi[a] = -1e300;
  }
  for (std::size_t j = 0; j < ns; ++j) {
    double X[4][3];
    seg_coords(s, sf.seg[j], X);
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min({X[0][a], X[1][a], X[2][a], X[3][a]});
      hi[a] = std::max({X[0][a], X[1][a], X[2][a], X[3][a]});
    }
    double ext = 0;
    for (int a = 0; a < 3; ++a) ext = std::max(ext, hi[a] - lo[a]);
    // the interior tolerance extends the patch by tol * (half its size) at most
    const double grow = sf.pmax[j] + extra + kInteriorTol * ext;
    for (int a = 0; a < 3; ++a) {
      double* b = &g.box[6 * j];
      b[a] = lo[a] - grow;
      b[3 + a] = hi[a] + grow;
      g.lo[a] = std::min(g.lo[a], b[a]);
      g.hi[a] = std::max(g.hi[a], b[3 + a]);
      hmax = std::max(hmax, b[3 + a] - b[a]);
    }
  }
  g.h = hmax > 0 ? hmax : 1.0;
  for (;;) {
    long cells = 1;
    for (int a = 0; a < 3; ++a) {
      g.dim[a] = int(std::min((g.hi[a] - g.lo[a]) / g.h, 1e6)) + 1;
      cells *= g.dim[a];
    }
    if (cells <= g.max_cells) break;
    g.h *= 1.25;
  }
  const int ncell = g.dim[0] * g.dim[1] * g.dim[2];
  std::fill(g.cell_start.begin(), g.cell_start.begin() + ncell + 1, 0);
  auto for_cells = [&](std::size_t j, auto&& fn) {
    const double* b = &g.box[6 * j];
    int c0[3], c1[3];
    for (int a = 0; a < 3; ++a) {
      c0[a] = cell_coord(g, a, b[a]);
      c1[a] = cell_coord(g, a, b[3 + a]);
    }
    for (int k = c0[2]; k <= c1[2]; ++k)
      for (int jj = c0[1]; jj <= c1[1]; ++jj)
        for (int i = c0[0]; i <= c1[0]; ++i) fn(i + g.dim[0] * (jj + g.dim[1] * k));
  };
  for (std::size_t j = 0; j < ns; ++j) for_cells(j, [&](int c) { ++g.cell_start[std::size_t(c) + 1]; });
  for (int c = 0; c < ncell; ++c) g.cell_start[std::size_t(c) + 1] += g.cell_start[std::size_t(c)];
  std::copy(g.cell_start.begin(), g.cell_start.begin() + ncell, g.cursor.begin());
  for (std::size_t j = 0; j < ns; ++j)
    for_cells(j, [&](int c) { g.entries[std::size_t(g.cursor[std::size_t(c)]++)] = int(j); });
}

// Whether segment j is in the surface now: the face of a failed (deleted) solid, or a deleted
// shell, no longer exists; an eroding surface's interior face exists once the solid on its
// other side has failed.
inline bool segment_active(const State& s, const Surface& sf, std::size_t j) {
  if (const int el = sf.elem[j]; el >= 0 && s.failed[std::size_t(el)]) return false;
  if (const int ot = sf.other[j]; ot >= 0 && !s.failed[std::size_t(ot)]) return false;
  if (const int sh = sf.shell[j]; sh >= 0 && s.shells.failed[std::size_t(sh)]) return false;
  return true;
}

inline bool in_box(const double* b, const double p[3]) {
  return p[0] >= b[0] && p[0] <= b[3] && p[1] >= b[1] && p[1] <= b[4] && p[2] >= b[2] &&
         p[2] <= b[5];
}

// A solid's elastic step V / A_max / c at the current positions (DBL_MAX: none).
double solid_elastic_step(const State& s, std::size_t E) {
  const double c = s.mats[std::size_t(s.mat[E])].c;
  if (!(c > 0)) return std::numeric_limits<double>::max();
  double x[8], y[8], z[8];
  for (int a = 0; a < 8; ++a) {
    const std::size_t n = std::size_t(s.conn[E][std::size_t(a)]);
    x[a] = s.x[n];
    y[a] = s.y[n];
    z[a] = s.z[n];
  }
  const double amax = calc_hex_max_face_area(x, y, z);
  return amax > 0 ? s.vol[E] / amax / c : std::numeric_limits<double>::max();
}

// The solids' part: the element pass of this cycle computed it for every deformable solid it
// processed (State::elastic_dt_solids, from the same V and A_max), so only the failed solids
// (whose V the pass no longer updates) are computed here; without that pass (a restart's
// first cycle), every solid.
double solids_elastic_step(const State& s) {
  double dtmin = std::numeric_limits<double>::max();
  if (s.elastic_dt_cycle == s.cycle) {
    if (s.elastic_dt_solids < dtmin) dtmin = s.elastic_dt_solids;
    for (int e = 0; e < s.ne; ++e) {
      const std::size_t E = std::size_t(e);
      if (s.failed[E] && !s.rigid_elem[E]) dtmin = std::min(dtmin, solid_elastic_step(s, E));
    }
    return dtmin;
  }
#pragma omp parallel for schedule(static) reduction(min : dtmin) if (s.ne >= 8192)
  for (int e = 0; e < s.ne; ++e) {
    const std::size_t E = std::size_t(e);
    if (!s.rigid_elem[E]) dtmin = std::min(dtmin, solid_elastic_step(s, E));
  }
  return dtmin;
}

// The step of the maximum stable stiffness: TSSF x the smallest element step l / c without the
// bulk-viscosity term (DYNA3D's step drops by ~6% whenever an element compresses, Q = C1 c, and
// a stiffness following those jumps, k ~ 1/dt^2, pumps energy into the springs: loaded at one
// k, unloaded at another).  It is >= the engine's step, so the stiffness stays <= the seed's
// k(dt), and it varies smoothly with the geometry.  Minimum: the same for any thread count.
double elastic_step(const State& s, double tssf) {
  double dtmin = solids_elastic_step(s);
  // shells: their elastic step (they have no bulk viscosity)
  const ShellState& sh = s.shells;
  for (int k = 0; k < sh.ns; ++k) {
    const std::size_t K = std::size_t(k);
    if (sh.rigid_elem[K] || sh.failed[K]) continue;
    if (sh.dt_e[K] > 0 && sh.dt_e[K] < dtmin) dtmin = sh.dt_e[K];
  }
  // beams: their element step
  const BeamState& bm = s.beams;
  for (int b = 0; b < bm.nb; ++b) {
    const std::size_t B = std::size_t(b);
    if (bm.rigid_elem[B] || bm.failed[B]) continue;
    if (bm.dt_e[B] > 0 && bm.dt_e[B] < dtmin) dtmin = bm.dt_e[B];
  }
  return tssf * dtmin;
}

// Whether node q of the pass's node side is in play: inside the grid's box and, on an eroding
// surface, on a face still in the surface (its solids not all failed; a beam node always is).
bool node_in_play(const State& s, const Surface& nodes_sf, const Grid& g, int q, const double* p) {
  if (p[0] < g.lo[0] || p[0] > g.hi[0] || p[1] < g.lo[1] || p[1] > g.hi[1] || p[2] < g.lo[2] || p[2] > g.hi[2])
    return false;
  if (!nodes_sf.eroding || std::size_t(q) >= nodes_sf.seg_nodes) return true;
  for (int c2 = nodes_sf.node_seg_start[std::size_t(q)]; c2 < nodes_sf.node_seg_start[std::size_t(q) + 1]; ++c2)
    if (segment_active(s, nodes_sf, std::size_t(nodes_sf.node_seg[std::size_t(c2)]))) return true;
  return false;
}

// The order of candidate segments for a point: its distance to the contact surface (the
// mid-surface distance less the offsets r); at equal distance a face point before an edge point.
double nearest_surface_key(const contact::SegmentHit& h, double r) {
  return r == 0 ? h.dist * (h.on_edge ? 1 + 1e-9 : 1.0) : h.dist + (h.on_edge ? 1e-9 * h.dist : 0.0) - r;
}

// A lower bound of the distance from p to any point closest_point_on_segment returns for the
// face X: the distance to its corners' box (a bilinear face lies in its corners' hull), the box
// grown by twice what the interior test reaches beyond the square (kInteriorTol of x_xi and
// x_eta, each at most about half the box's diagonal).
double face_distance_lower_bound(const double X[4][3], const double* p) {
  double lo[3], hi[3], ext = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    lo[i] = std::min(std::min(X[0][i], X[1][i]), std::min(X[2][i], X[3][i]));
    hi[i] = std::max(std::max(X[0][i], X[1][i]), std::max(X[2][i], X[3][i]));
    ext += hi[i] - lo[i];
  }
  const double pad = 2 * kInteriorTol * ext;
  double d2 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double over = std::max({lo[i] - pad - p[i], p[i] - hi[i] - pad, 0.0});
    d2 += over * over;
  }
  return std::sqrt(d2);
}

// The nearest segment to point p among its grid cell's candidates, or -1: its hit bh and the sum
// of the offsets r (r_point, the point's own, plus the segment's).  allowed(j) says whether
// segment j may be tried (the pair rules), accepted(h, two_sided) whether its hit counts.
// Nearest contact surface: the least key (the mid-surface distance less the offsets; at equal
// distance a face point before an edge point), at equal keys the lower segment (the candidates
// come in segment order).  A solid face whose corners' box is already farther than the best key
// is not projected: its key could not be lower, so the choice is the one of projecting all.
template <class Allowed, class Accepted>
int nearest_segment_in_cell(const State& s, const Surface& segs, const Grid& g, const double* p, double r_point,
                            int& evaluations, Allowed allowed, Accepted accepted, contact::SegmentHit& bh,
                            double& best_r) {
  const int c = cell_coord(g, 0, p[0]) + g.dim[0] * (cell_coord(g, 1, p[1]) + g.dim[1] * cell_coord(g, 2, p[2]));
  int best = -1;
  double best_key = 0;
  for (int e = g.cell_start[std::size_t(c)]; e < g.cell_start[std::size_t(c) + 1]; ++e) {
    const int j = g.entries[std::size_t(e)];
    if (!in_box(&g.box[6 * std::size_t(j)], p) || !allowed(j)) continue;
    double X[4][3];
    seg_coords(s, segs.seg[std::size_t(j)], X);
    const double r = segs.offset[std::size_t(j)] + r_point;
    const bool two_sided = segs.two_sided[std::size_t(j)];
    if (best >= 0 && !two_sided && face_distance_lower_bound(X, p) - r > best_key) continue;
    ++evaluations;
    contact::SegmentHit h = two_sided ? contact::closest_point_on_shell_segment(X, p, kInteriorTol)
                                      : contact::closest_point_on_segment(X, p, segs.boundary[std::size_t(j)], kInteriorTol);
    if (!h.valid || !accepted(h, two_sided)) continue;
    const double key = nearest_surface_key(h, r);
    if (best < 0 || key < best_key) {
      best = j;
      best_key = key;
      best_r = r;
      bh = h;
    }
  }
  return best;
}

// The nearest segment of node q's grid cell, or -1: not one of the node's own segments (nor, on
// a single surface, one around it: the ring), active.
int find_nearest_segment(const State& s, const Interface& in, const Surface& nodes_sf, const Surface& segs, const Grid& g,
                         int q, const double* p, Hit& hit, contact::SegmentHit& bh, double& best_r) {
  const int node = nodes_sf.nodes[std::size_t(q)];
  // the node's own offset: half its shell's thickness (0 for a solid's node)
  const double r_node = nodes_sf.node_off[std::size_t(q)];
  const int* ring = in.single ? nodes_sf.ring.data() + nodes_sf.ring_start[std::size_t(q)] : nullptr;
  const int* ring_end = in.single ? nodes_sf.ring.data() + nodes_sf.ring_start[std::size_t(q) + 1] : nullptr;
  auto allowed = [&](int j) {
    const auto& sg = segs.seg[std::size_t(j)];
    if (sg[0] == node || sg[1] == node || sg[2] == node || sg[3] == node) return false;
    if (ring && std::any_of(sg.begin(), sg.end(), [&](int v) { return std::binary_search(ring, ring_end, v); }))
      return false;
    return segment_active(s, segs, std::size_t(j));
  };
  auto any_hit = [](const contact::SegmentHit&, bool) { return true; };
  return nearest_segment_in_cell(s, segs, g, p, r_node, hit.evaluations, allowed, any_hit, bh, best_r);
}

// The velocity of node k relative to the contact point of segment sg (shape values N).
void relative_velocity(const State& s, std::size_t k, const std::array<int, 4>& sg, const double* N, double* vrel) {
  vrel[0] = s.vx[k];
  vrel[1] = s.vy[k];
  vrel[2] = s.vz[k];
  for (int a = 0; a < 4; ++a) {
    const std::size_t ka = std::size_t(sg[std::size_t(a)]);
    vrel[0] -= N[a] * s.vx[ka];
    vrel[1] -= N[a] * s.vy[ka];
    vrel[2] -= N[a] * s.vz[ka];
  }
}

// 1/m* of node k against the contact point of segment sg: 1/m_k + sum N_a^2 / m_a (massless nodes left out).
double inverse_contact_mass(const State& s, std::size_t k, const std::array<int, 4>& sg, const double* N) {
  double lam = s.mass[k] > 0 ? 1.0 / s.mass[k] : 0.0;
  for (int a = 0; a < 4; ++a) {
    const double ma = s.mass[std::size_t(sg[std::size_t(a)])];
    if (ma > 0) lam += N[a] * N[a] / ma;
  }
  return lam;
}

// The spring holds the penetration the node's approach explains.  Each cycle the geometric
// penetration changes by its increment; the relative normal approach over the step that
// brought the node here, -(v^{n-1/2} . n) dt^{n-1/2}, explains it up to the surface's
// curvature (second order).  An increment beyond the approach by more than
// kJumpFraction |v_rel| dt (plus round-off) is a jump of the geometry, not a motion: the
// node started inside, a failed solid's face exposed it, it slid under an edge.  That
// unexplained part goes to the node's offset, and the spring holds the penetration less the
// offset: a spring of the whole depth would throw the node out with energy no motion gave
// it.  The offset shrinks with the geometric depth (never above it) and ends with the
// contact.  A node that came in from outside has no offset: the spring is the geometric
// depth, as it was.  Returns the penetration the spring holds (adm: this cycle's depth and offset).
double admitted_penetration(double pen, double pmax, const double* vrel, const double* n, double dt_half,
                            double pen_before, double offset_before, bool& refused, double* adm) {
  const double approach = -(vrel[0] * n[0] + vrel[1] * n[1] + vrel[2] * n[2]);
  const double vrel_mag = std::sqrt(vrel[0] * vrel[0] + vrel[1] * vrel[1] + vrel[2] * vrel[2]);
  const double jump = (pen - pen_before) - approach * dt_half;
  double offset = offset_before;
  if (jump > kExplainedTol * pmax + kJumpFraction * vrel_mag * dt_half) {
    offset += jump;
    refused = true;
  }
  offset = std::min(offset, pen);
  const double pen_used = pen - offset;
  adm[0] = pen;
  adm[1] = offset;
  // (an offset node whose approach is round-off, sliding along the face, is not in contact)
  if (!(pen_used > 0) || (offset > 0 && pen_used <= kExplainedTol * pmax)) return 0.0;
  return pen_used;
}

// The friction force of a contact of normal force fn added to hit.f.
void add_friction_force(const State& s, const Interface& in, std::size_t k, const std::array<int, 4>& sg, const double* N,
                        const double* n, const double* vrel, double fn, double dt, Hit& hit) {
  const double inv_meff = inverse_contact_mass(s, k, sg, N);
  const double vn = vrel[0] * n[0] + vrel[1] * n[1] + vrel[2] * n[2];
  const double vt[3] = {vrel[0] - vn * n[0], vrel[1] - vn * n[1], vrel[2] - vn * n[2]};
  const double mu = contact::friction_coefficient(in.fs, in.fd, in.decay, std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]));
  double ft[3];
  contact::friction_force(mu, fn, n, vrel, inv_meff, dt, ft);
  for (int i = 0; i < 3; ++i) hit.f[i] += ft[i];
}

// ---- segment-based contact (LS-DYNA SOFT = 2)

// Whether segment j of `segs` may meet point-carrying segment jo of `own` (same interface): not
// one that shares a node with it, and on a single surface not one with a node of the rings of
// its nodes (the segments around it and their neighbours touch it by construction).
bool segment_pair_allowed(const Interface& in, const Surface& own, std::size_t jo, const std::array<int, 4>& sg) {
  const auto& so = own.seg[jo];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (so[std::size_t(a)] == sg[std::size_t(b)]) return false;
  if (!in.single) return true;
  for (int a = 0; a < 4; ++a) {
    const std::size_t q = std::size_t(own.local[jo][std::size_t(a)]);
    const int* ring = own.ring.data() + own.ring_start[q];
    const int* ring_end = own.ring.data() + own.ring_start[q + 1];
    if (std::any_of(sg.begin(), sg.end(), [&](int v) { return std::binary_search(ring, ring_end, v); })) return false;
  }
  return true;
}

// The nearest segment of `segs` to point p of segment jo of `own` (its outward normal n_own, its
// offset r_own), or -1: its hit bh and the sum of the offsets r.  Two one-sided faces meet only
// facing each other (n_own . n < 0).
int find_segment_for_point(const State& s, const Interface& in, const Surface& own, std::size_t jo, const Surface& segs,
                           const Grid& g, const double* p, const double* n_own, PointHit& hit, contact::SegmentHit& bh,
                           double& best_r) {
  const bool own_one_sided = !own.two_sided[jo];
  auto allowed = [&](int j) {
    return segment_pair_allowed(in, own, jo, segs.seg[std::size_t(j)]) && segment_active(s, segs, std::size_t(j));
  };
  auto facing = [&](const contact::SegmentHit& h, bool two_sided) {
    return !own_one_sided || two_sided || n_own[0] * h.n[0] + n_own[1] * h.n[1] + n_own[2] * h.n[2] < 0;
  };
  return nearest_segment_in_cell(s, segs, g, p, own.offset[jo], hit.evaluations, allowed, facing, bh, best_r);
}

// sum_a N_a v_a over a segment's nodes (the velocity of its point of shape values N).
void point_velocity(const State& s, const std::array<int, 4>& sg, const double* N, double* v) {
  v[0] = v[1] = v[2] = 0;
  for (int a = 0; a < 4; ++a) {
    const std::size_t ka = std::size_t(sg[std::size_t(a)]);
    v[0] += N[a] * s.vx[ka];
    v[1] += N[a] * s.vy[ka];
    v[2] += N[a] * s.vz[ka];
  }
}

// sum_a N_a^2 / m_a over a segment's nodes (massless nodes left out).
double inverse_point_mass(const State& s, const std::array<int, 4>& sg, const double* N) {
  double lam = 0;
  for (int a = 0; a < 4; ++a) {
    const double ma = s.mass[std::size_t(sg[std::size_t(a)])];
    if (ma > 0) lam += N[a] * N[a] / ma;
  }
  return lam;
}

}  // namespace

struct SlidingInterfaces::Impl {
  std::vector<Interface> ifaces;
  std::vector<Transducer> transducers;
  std::vector<std::array<double, 3>> forces;
  std::vector<int> contact_nodes;    // union of all surface nodes, sorted
  std::vector<double> cur, prev;     // 3 per node: contact force this cycle / last cycle
  bool has_prev = false;
  double tssf = 0.9;
  bool any_max_stable = false;
  double max_pen = 0;
  SearchStats stats;

  double dt_soft = 0;  // the soft constraint's step: the first, then the largest taken
  void node_pass(const Model& m, const State& s, Interface& in, Pass& ps, double dt, double dt_k);
  void segment_pass(const State& s, Interface& in, Pass& ps, double dt);
  void scatter_segment_pass(Interface& in, Pass& ps, std::array<double, 3>& fres);
  double penalty_stiffness(const State& s, const Interface& in, const Surface& nodes_sf, const Surface& segs, int q,
                           int best, const double* N, double dt_k) const;
};

// The penalty stiffness of node q against segment best: DYNA3D's (with PENOPT), LS-DYNA's soft
// constraint, or the seed's largest stable stiffness at the segment's node nearest the contact point.
double SlidingInterfaces::Impl::penalty_stiffness(const State& s, const Interface& in, const Surface& nodes_sf,
                                                  const Surface& segs, int q, int best, const double* N,
                                                  double dt_k) const {
  const std::size_t k = std::size_t(nodes_sf.nodes[std::size_t(q)]);
  if (in.method != 1) {  // DYNA3D (with PENOPT), or LS-DYNA's soft constraint
    double kpen = contact::penopt_stiffness(in.penopt, segs.k0[std::size_t(best)], nodes_sf.node_k[std::size_t(q)]);
    if (in.method == 2) {
      double m_star = s.mass[k];
      for (int a = 0; a < 4; ++a) m_star = std::min(m_star, s.mass[std::size_t(segs.seg[std::size_t(best)][std::size_t(a)])]);
      kpen = contact::soft_constraint_stiffness(kpen, in.sofscl, m_star, dt_soft);
    }
    return kpen;
  }
  int a_near = 0;
  for (int a = 1; a < 4; ++a)
    if (N[a] > N[a_near]) a_near = a;
  const int nm = segs.seg[std::size_t(best)][std::size_t(a_near)];
  return contact::max_stable_stiffness(tssf, dt_k, s.mass[k], s.mass[std::size_t(nm)], in.symmetric);
}

// Step 2 of a pass: every node of the pass against the segments (parallel, per-node slots).
void SlidingInterfaces::Impl::node_pass(const Model&, const State& s, Interface& in, Pass& ps,
                                        double dt, double dt_k) {
  const Surface& nodes_sf = in.surf[ps.node_side];
  const Surface& segs = in.surf[ps.seg_side];
  const Grid& g = ps.grid;
  const int nn = int(nodes_sf.nodes.size());
  // (threads only on large surfaces: waking a sleeping thread costs more than a small search)
#pragma omp parallel for schedule(static) if (nn >= 4096)
  for (int q = 0; q < nn; ++q) {
    Hit& hit = ps.hits[std::size_t(q)];
    hit = Hit{};
    double* adm = &ps.admitted[2 * std::size_t(q)];
    const double pen_before = adm[0], offset_before = adm[1];
    adm[0] = adm[1] = 0.0;
    const std::size_t k = std::size_t(nodes_sf.nodes[std::size_t(q)]);
    const double p[3] = {s.x[k], s.y[k], s.z[k]};
    if (!node_in_play(s, nodes_sf, g, q, p)) continue;
    contact::SegmentHit bh;
    double best_r = 0;
    const int best = find_nearest_segment(s, in, nodes_sf, segs, g, q, p, hit, bh, best_r);
    if (best < 0) continue;
    // penetration of the contact surfaces: the offsets less the gap of the mid-surfaces
    const double pen = best_r - bh.gap;
    const double pmax = segs.pmax[std::size_t(best)] + nodes_sf.node_off[std::size_t(q)];
    if (!(pen > 0) || pen > pmax) continue;
    double N[4];
    contact::shape4(bh.xi, bh.eta, N);
    const double kpen = penalty_stiffness(s, in, nodes_sf, segs, q, best, N, dt_k);
    const auto& sg = segs.seg[std::size_t(best)];
    double vrel[3];
    relative_velocity(s, k, sg, N, vrel);
    const double pen_used = admitted_penetration(pen, pmax, vrel, bh.n, s.dt_half, pen_before, offset_before, hit.refused, adm);
    if (!(pen_used > 0)) continue;
    hit.omega_dt = dt * std::sqrt(kpen * inverse_contact_mass(s, k, sg, N));
    const double fn = kpen * pen_used;
    hit.seg = best;
    for (int a = 0; a < 4; ++a) hit.N[a] = N[a];
    hit.fn = fn;
    hit.pen = pen_used;
    for (int i = 0; i < 3; ++i) hit.f[i] = fn * bh.n[i];
    if (in.fs > 0 || in.fd > 0) add_friction_force(s, in, k, sg, N, bh.n, vrel, fn, dt, hit);
  }
}

// Segment-based contact (SOFT 2), step 2 of a pass: every point of every segment of the pass's
// own side against the other side's segments (parallel, per-point slots).  A point penetrating
// a segment by p gets F = w k p n, k the pair's stiffness 0.5 mu m1 m2 / (m1 + m2) / dt_c^2,
// w = 1/4 (a quarter a point) halved where each pair is met both ways (symmetric passes, single
// surface); the spring holds the penetration the points' approach explains (as for nodes).
void SlidingInterfaces::Impl::segment_pass(const State& s, Interface& in, Pass& ps, double dt) {
  const Surface& own = in.surf[ps.node_side];
  const Surface& segs = in.surf[ps.seg_side];
  const Grid& g = ps.grid;
  const int ns = int(own.seg.size());
  const double w = 1.0 / (contact::kSegmentPoints * (in.symmetric ? 2.0 : 1.0));
#pragma omp parallel for schedule(static) if (ns >= 1024)
  for (int jo = 0; jo < ns; ++jo) {
    const std::size_t J = std::size_t(jo);
    const auto& so = own.seg[J];
    const bool active = segment_active(s, own, J);
    double X[4][3];
    seg_coords(s, so, X);
    for (int i = 0; i < contact::kSegmentPoints; ++i) {
      const std::size_t slot = contact::kSegmentPoints * J + std::size_t(i);
      PointHit& hit = ps.points[slot];
      hit = PointHit{};
      double* adm = &ps.admitted[2 * slot];
      const double pen_before = adm[0], offset_before = adm[1];
      adm[0] = adm[1] = 0.0;
      if (!active) continue;
      double xi, eta, p[3], x_xi[3], x_eta[3], n_own[3], Ns[4];
      contact::segment_point_coordinates(i, xi, eta);
      contact::segment_point(X, xi, eta, p, x_xi, x_eta);
      if (p[0] < g.lo[0] || p[0] > g.hi[0] || p[1] < g.lo[1] || p[1] > g.hi[1] || p[2] < g.lo[2] || p[2] > g.hi[2]) continue;
      contact::segment_normal(X, xi, eta, n_own);
      contact::SegmentHit bh;
      double best_r = 0;
      const int best = find_segment_for_point(s, in, own, J, segs, g, p, n_own, hit, bh, best_r);
      if (best < 0) continue;
      const double pen = best_r - bh.gap;
      const double pmax = segs.pmax[std::size_t(best)] + own.offset[J];
      if (!(pen > 0) || pen > pmax) continue;
      const auto& sm = segs.seg[std::size_t(best)];
      double Nm[4], vp[3], vm[3];
      contact::shape4(xi, eta, Ns);
      contact::shape4(bh.xi, bh.eta, Nm);
      point_velocity(s, so, Ns, vp);
      point_velocity(s, sm, Nm, vm);
      const double vrel[3] = {vp[0] - vm[0], vp[1] - vm[1], vp[2] - vm[2]};
      const double pen_used = admitted_penetration(pen, pmax, vrel, bh.n, s.dt_half, pen_before, offset_before, hit.refused, adm);
      if (!(pen_used > 0)) continue;
      const double m1 = own.seg_mass[J], m2 = segs.seg_mass[std::size_t(best)];
      const double k = contact::segment_pair_stiffness(in.mu, m1, m2, dt_soft);
      hit.omega_dt = (m1 > 0 && m2 > 0) ? dt * std::sqrt(k * (1.0 / m1 + 1.0 / m2)) : 0.0;
      const double fn = w * k * pen_used;
      hit.seg = best;
      for (int a = 0; a < 4; ++a) hit.Nm[a] = Nm[a];
      hit.pen = pen_used;
      for (int c = 0; c < 3; ++c) hit.f[c] = fn * bh.n[c];
      if (in.fs > 0 || in.fd > 0) {
        // the stick cap shared by the points of the pair: 1/m* of the point over w
        const double inv_meff = (inverse_point_mass(s, so, Ns) + inverse_point_mass(s, sm, Nm)) / w;
        const double vn = vrel[0] * bh.n[0] + vrel[1] * bh.n[1] + vrel[2] * bh.n[2];
        const double vt[3] = {vrel[0] - vn * bh.n[0], vrel[1] - vn * bh.n[1], vrel[2] - vn * bh.n[2]};
        const double mu = contact::friction_coefficient(in.fs, in.fd, in.decay, std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]));
        double ft[3];
        contact::friction_force(mu, fn, bh.n, vrel, inv_meff, dt, ft);
        for (int c = 0; c < 3; ++c) hit.f[c] += ft[c];
      }
    }
  }
}

// Step 3 of a segment-based pass, in segment and point order: F on the point's segment nodes by
// its shape functions, -F on the hit segment's nodes by theirs (the sum is zero).
void SlidingInterfaces::Impl::scatter_segment_pass(Interface& in, Pass& ps, std::array<double, 3>& fres) {
  Surface& own = in.surf[ps.node_side];
  Surface& segs = in.surf[ps.seg_side];
  const double sign = ps.node_side == 0 ? 1.0 : -1.0;  // force on the slave side
  const std::size_t nif = ifaces.size();
  for (std::size_t jo = 0; jo < own.seg.size(); ++jo)
    for (int i = 0; i < contact::kSegmentPoints; ++i) {
      const PointHit& h = ps.points[contact::kSegmentPoints * jo + std::size_t(i)];
      ++stats.nodes;
      stats.evaluations += h.evaluations;
      stats.refused += h.refused ? 1 : 0;
      if (h.seg < 0) continue;
      ++stats.contacts;
      stats.max_omega_dt = std::max(stats.max_omega_dt, h.omega_dt);
      max_pen = std::max(max_pen, h.pen);
      double xi, eta, Ns[4];
      contact::segment_point_coordinates(i, xi, eta);
      contact::shape4(xi, eta, Ns);
      const auto& so = own.seg[jo];
      const auto& sm = segs.seg[std::size_t(h.seg)];
      double fo[4][3], fm[4][3];
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c) {
          fo[a][c] = h.f[c] * Ns[a];
          fm[a][c] = -h.f[c] * h.Nm[a];
        }
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c) {
          cur[3 * std::size_t(so[std::size_t(a)]) + std::size_t(c)] += fo[a][c];
          cur[3 * std::size_t(sm[std::size_t(a)]) + std::size_t(c)] += fm[a][c];
        }
      for (int c = 0; c < 3; ++c) fres[std::size_t(c)] += sign * h.f[c];
      // the interface-force database: the force on each node of a recorded side
      for (auto [sf, seg, f] : {std::tuple{&own, jo, &fo}, std::tuple{&segs, std::size_t(h.seg), &fm}})
        if (!sf->node_force.empty())
          for (int a = 0; a < 4; ++a)
            for (int c = 0; c < 3; ++c) sf->node_force[3 * std::size_t(sf->local[seg][std::size_t(a)]) + std::size_t(c)] += (*f)[a][c];
      // force transducers: the forces on their side-A nodes (from side B only, when given: a
      // segment's forces count when the other segment is all in B)
      for (std::size_t t = 0; t < transducers.size(); ++t) {
        const Transducer& tr = transducers[t];
        auto& ft = forces[nif + t];
        auto all_b = [&](const std::array<int, 4>& sg) {
          bool b = true;
          for (int v : sg) b = b && (tr.flag[std::size_t(v)] & 2);
          return b;
        };
        const bool from_m = !tr.has_b || all_b(sm), from_o = !tr.has_b || all_b(so);
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 3; ++c) {
            if (from_m && (tr.flag[std::size_t(so[std::size_t(a)])] & 1)) ft[std::size_t(c)] += fo[a][c];
            if (from_o && (tr.flag[std::size_t(sm[std::size_t(a)])] & 1)) ft[std::size_t(c)] += fm[a][c];
          }
      }
    }
}

SlidingInterfaces::SlidingInterfaces() : impl_(std::make_unique<Impl>()) {}
SlidingInterfaces::~SlidingInterfaces() = default;
SlidingInterfaces::SlidingInterfaces(SlidingInterfaces&&) noexcept = default;
SlidingInterfaces& SlidingInterfaces::operator=(SlidingInterfaces&&) noexcept = default;

void SlidingInterfaces::initialize(const Model& m, const State& s) {
  Impl& im = *impl_;
  im = Impl{};
  im.tssf = m.control.tssf;
  im.ifaces.resize(m.interfaces.size());
  const ShellIndex shx = build_shell_index(s);
  for (std::size_t i = 0; i < m.interfaces.size(); ++i) {
    const SlidingInterface& d = m.interfaces[i];
    Interface& in = im.ifaces[i];
    in.method = d.stiffness_method;
    in.penopt = d.penopt;
    in.sofscl = d.sofscl;
    in.mu = d.penalty_scale > 0 ? d.penalty_scale : m.control.penalty_scale;
    in.fs = d.fs;
    in.fd = d.fd;
    in.decay = d.decay;
    in.symmetric = d.symmetric;
    in.npass = d.symmetric ? 2 : 1;
    im.any_max_stable = im.any_max_stable || in.method == 1;
    in.segment_based = in.method == 3;
    in.single = d.type == 4;
    if (in.single) {
      // one pass, but every pair of the surface is met both ways (a node of each against the
      // other's segment): the maximum stable stiffness takes the symmetric constant
      in.npass = 1;
      in.symmetric = true;
    }
    build_surface(s, shx, d.slave, d.slave_nodes, in.mu, d.shell_thickness, in.surf[0], d.eroding);
    build_surface(s, shx, in.single ? std::vector<std::array<int, 4>>{} : d.master,
                  in.single ? std::vector<int>{} : d.master_nodes, in.mu, d.shell_thickness, in.surf[1], d.eroding);
    if (in.single) build_rings(in.surf[0]);
    for (int p = 0; p < in.npass; ++p) {
      Pass& ps = in.pass[p];
      ps.node_side = p == 0 ? 0 : 1;
      ps.seg_side = in.single ? 0 : 1 - ps.node_side;
      allocate_grid(in.surf[ps.seg_side].seg.size(), ps.grid);
      if (in.segment_based) {
        const std::size_t np = contact::kSegmentPoints * in.surf[ps.node_side].seg.size();
        ps.points.assign(np, PointHit{});
        ps.admitted.assign(2 * np, 0.0);
      } else {
        ps.hits.assign(in.surf[ps.node_side].nodes.size(), Hit{});
        ps.admitted.assign(2 * in.surf[ps.node_side].nodes.size(), 0.0);
      }
    }
    for (int sd = 0; sd < 2; ++sd)
      im.contact_nodes.insert(im.contact_nodes.end(), in.surf[sd].nodes.begin(), in.surf[sd].nodes.end());
  }
  std::sort(im.contact_nodes.begin(), im.contact_nodes.end());
  im.contact_nodes.erase(std::unique(im.contact_nodes.begin(), im.contact_nodes.end()), im.contact_nodes.end());
  // the sides the interface-force database writes record their nodal forces
  if (m.control.intfor_interval >= 0)
    for (std::size_t i = 0; i < m.interfaces.size(); ++i)
      for (int sd = 0; sd < 2; ++sd)
        if (sd == 0 ? m.interfaces[i].intfor_slave : m.interfaces[i].intfor_master)
          im.ifaces[i].surf[sd].node_force.assign(3 * im.ifaces[i].surf[sd].nodes.size(), 0.0);
  im.transducers.resize(m.force_transducers.size());
  for (std::size_t t = 0; t < m.force_transducers.size(); ++t) {
    const ForceTransducer& d = m.force_transducers[t];
    Transducer& tr = im.transducers[t];
    tr.flag.assign(std::size_t(s.nn), 0);
    tr.has_b = d.has_b;
    for (int n : d.a_nodes) tr.flag[std::size_t(n)] |= 1;
    for (int n : d.b_nodes) tr.flag[std::size_t(n)] |= 2;
  }
  im.forces.assign(m.interfaces.size() + m.force_transducers.size(), {0.0, 0.0, 0.0});
  im.cur.assign(3 * std::size_t(s.nn), 0.0);
  im.prev.assign(3 * std::size_t(s.nn), 0.0);
}

void SlidingInterfaces::apply(const Model& m, State& s, double dt) {
  Impl& im = *impl_;
  if (im.ifaces.empty()) return;
  // (the contact energy of these forces is booked by book_energy() once the cycle's velocities
  // are final)
  for (int n : im.contact_nodes)
    for (int a = 0; a < 3; ++a) im.cur[3 * std::size_t(n) + std::size_t(a)] = 0.0;
  im.max_pen = 0;
  im.stats = SearchStats{};
  const double dt_k = im.any_max_stable ? std::max(dt, elastic_step(s, im.tssf)) : dt;
  im.dt_soft = std::max(im.dt_soft, dt);
  const std::size_t nif = im.ifaces.size();
  for (std::size_t t = 0; t < im.transducers.size(); ++t) im.forces[nif + t] = {0.0, 0.0, 0.0};
  // 2. every interface, every pass
  for (std::size_t i = 0; i < im.ifaces.size(); ++i) {
    Interface& in = im.ifaces[i];
    for (Surface& sf : in.surf) std::fill(sf.node_force.begin(), sf.node_force.end(), 0.0);
    std::array<double, 3> fres{0.0, 0.0, 0.0};
    for (int p = 0; p < in.npass; ++p) {
      Pass& ps = in.pass[p];
      const Surface& nodes_sf = in.surf[ps.node_side];
      const Surface& segs = in.surf[ps.seg_side];
      if (segs.seg.empty()) continue;
      if (in.segment_based) {
        rebuild_grid(s, segs, nodes_sf.seg_off_max, ps.grid);
        im.segment_pass(s, in, ps, dt);
        im.scatter_segment_pass(in, ps, fres);
        continue;
      }
      rebuild_grid(s, segs, nodes_sf.node_off_max, ps.grid);
      im.node_pass(m, s, in, ps, dt, dt_k);
      // 3. scatter in node order
      const double sign = ps.node_side == 0 ? 1.0 : -1.0;  // force on the slave side
      for (std::size_t q = 0; q < nodes_sf.nodes.size(); ++q) {
        const Hit& h = ps.hits[q];
        ++im.stats.nodes;
        im.stats.evaluations += h.evaluations;
        im.stats.refused += h.refused ? 1 : 0;
        if (h.seg < 0) continue;
        ++im.stats.contacts;
        im.stats.max_omega_dt = std::max(im.stats.max_omega_dt, h.omega_dt);
        im.max_pen = std::max(im.max_pen, h.pen);
        const std::size_t k = std::size_t(nodes_sf.nodes[q]);
        double fa[4][3];
        contact::distribute_force(h.f, h.N, fa);
        for (int a = 0; a < 3; ++a) im.cur[3 * k + std::size_t(a)] += h.f[a];
        const auto& sg = segs.seg[std::size_t(h.seg)];
        for (int b = 0; b < 4; ++b) {
          const std::size_t kb = std::size_t(sg[std::size_t(b)]);
          for (int a = 0; a < 3; ++a) im.cur[3 * kb + std::size_t(a)] += fa[b][a];
        }
        for (int a = 0; a < 3; ++a) fres[std::size_t(a)] += sign * h.f[a];
        // the interface-force database: the force on each node of a recorded side
        if (double* fn = nodes_sf.node_force.empty() ? nullptr : &in.surf[ps.node_side].node_force[3 * q])
          for (int a = 0; a < 3; ++a) fn[a] += h.f[a];
        if (!segs.node_force.empty()) {
          Surface& ss = in.surf[ps.seg_side];
          for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 3; ++a)
              ss.node_force[3 * std::size_t(ss.local[std::size_t(h.seg)][std::size_t(b)]) + std::size_t(a)] += fa[b][a];
        }
        // force transducers: the forces on their side-A nodes (from side B only, when given:
        // the node's force counts when its segment is all in B, the segment's when the node is)
        for (std::size_t t = 0; t < im.transducers.size(); ++t) {
          const Transducer& tr = im.transducers[t];
          auto& ft = im.forces[nif + t];
          if (tr.flag[k] & 1) {
            bool from_b = true;
            if (tr.has_b)
              for (int b = 0; b < 4; ++b) from_b = from_b && (tr.flag[std::size_t(sg[std::size_t(b)])] & 2);
            if (from_b)
              for (int a = 0; a < 3; ++a) ft[std::size_t(a)] += h.f[a];
          }
          if (!tr.has_b || (tr.flag[k] & 2))
            for (int b = 0; b < 4; ++b)
              if (tr.flag[std::size_t(sg[std::size_t(b)])] & 1)
                for (int a = 0; a < 3; ++a) ft[std::size_t(a)] += fa[b][a];
        }
      }
    }
    im.forces[i] = fres;
  }
  for (int n : im.contact_nodes) {
    const std::size_t k = std::size_t(n);
    s.fext_x[k] += im.cur[3 * k];
    s.fext_y[k] += im.cur[3 * k + 1];
    s.fext_z[k] += im.cur[3 * k + 2];
  }
  im.prev.swap(im.cur);
  im.has_prev = true;
}

// Contact energy: the work of the last apply()'s forces on the mean velocity
// (v^{n-1/2} + v^{n+1/2}) / 2 over dt_n, the form that balances the central-difference kinetic
// energy, taken with the velocities the cycle reached: after the rigid bodies (whose nodes move
// with their body's resultant, not their own force), the walls and the prescribed motions.
void SlidingInterfaces::book_energy(State& s, double dt_n) const {
  const Impl& im = *impl_;
  if (im.ifaces.empty() || !im.has_prev) return;
  double w = 0;
  for (int n : im.contact_nodes) {
    const std::size_t k = std::size_t(n);
    w += im.prev[3 * k] * 0.5 * (s.vx_old[k] + s.vx[k]) + im.prev[3 * k + 1] * 0.5 * (s.vy_old[k] + s.vy[k]) +
         im.prev[3 * k + 2] * 0.5 * (s.vz_old[k] + s.vz[k]);
  }
  s.contact -= dt_n * w;
}

bool SlidingInterfaces::empty() const { return impl_->ifaces.empty(); }
bool SlidingInterfaces::uses_elastic_step() const { return impl_->any_max_stable; }

const std::vector<std::array<double, 3>>& SlidingInterfaces::interface_forces() const {
  return impl_->forces;
}
const std::vector<int>& SlidingInterfaces::surface_nodes(std::size_t i, int side) const {
  return impl_->ifaces[i].surf[side].nodes;
}
const std::vector<double>& SlidingInterfaces::surface_node_forces(std::size_t i, int side) const {
  return impl_->ifaces[i].surf[side].node_force;
}
double SlidingInterfaces::max_penetration() const { return impl_->max_pen; }
SlidingInterfaces::SearchStats SlidingInterfaces::search_stats() const { return impl_->stats; }
SlidingInterfaces::RestartData SlidingInterfaces::restart_data() const {
  RestartData d{impl_->prev, {}, impl_->dt_soft, impl_->has_prev};
  for (const Interface& in : impl_->ifaces)
    for (int p = 0; p < in.npass; ++p) d.admitted.insert(d.admitted.end(), in.pass[p].admitted.begin(), in.pass[p].admitted.end());
  return d;
}
void SlidingInterfaces::restore(const RestartData& d) {
  impl_->prev = d.forces;
  impl_->has_prev = d.has;
  impl_->dt_soft = d.dtn;
  // the admitted depths in interface and pass order (a dump without them: none admitted)
  std::size_t total = 0;
  for (const Interface& in : impl_->ifaces)
    for (int p = 0; p < in.npass; ++p) total += in.pass[p].admitted.size();
  std::size_t at = 0;
  for (Interface& in : impl_->ifaces)
    for (int p = 0; p < in.npass; ++p)
      for (double& a : in.pass[p].admitted) a = d.admitted.size() == total ? d.admitted[at++] : 0.0;
}

}  // namespace impact3d
