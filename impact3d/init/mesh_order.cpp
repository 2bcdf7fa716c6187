#include "impact3d/init/mesh_order.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <type_traits>
#include <utility>

namespace impact3d {

bool parse_mesh_order_mode(const std::string& text, MeshOrderMode& mode) {
  if (text == "auto") mode = MeshOrderMode::automatic;
  else if (text == "on") mode = MeshOrderMode::on;
  else if (text == "off") mode = MeshOrderMode::off;
  else return false;
  return true;
}

double mesh_locality_cost(const Model& m) {
  double spread = 0, jump = 0;
  std::size_t count = 0;
  int prev_min = -1;
  for (const auto& hn : m.hex_nodes) {
    const auto [lo, hi] = std::minmax_element(hn.begin(), hn.end());
    spread += double(*hi - *lo);
    ++count;
    if (prev_min >= 0) jump += double(std::abs(*lo - prev_min));
    prev_min = *lo;
  }
  for (const auto& sn : m.shell_nodes) {
    int lo = m.num_nodes(), hi = -1;
    for (int n : sn)
      if (n >= 0) lo = std::min(lo, n), hi = std::max(hi, n);
    if (hi < 0) continue;
    spread += double(hi - lo);
    ++count;
  }
  if (count == 0) return 0;
  return spread / double(count) + (m.num_hexes() > 1 ? jump / double(m.num_hexes() - 1) : 0.0);
}

namespace {

// Node -> elements (solids e, then shells num_hexes() + k, then beams num_hexes() + num_shells() + b),
// CSR, in increasing element order.
struct NodeElements {
  std::vector<int> start, list;
};

NodeElements build_node_elements(const Model& m) {
  const int nn = m.num_nodes(), ne = m.num_hexes();
  NodeElements ix;
  ix.start.assign(std::size_t(nn) + 1, 0);
  auto each = [&](auto&& f) {
    for (int e = 0; e < ne; ++e)
      for (int n : m.hex_nodes[std::size_t(e)]) f(n, e);
    for (int k = 0; k < m.num_shells(); ++k) {
      const auto& sn = m.shell_nodes[std::size_t(k)];
      for (int j = 0; j < 4; ++j)
        if (sn[std::size_t(j)] >= 0 && (j < 3 || sn[3] != sn[2])) f(sn[std::size_t(j)], ne + k);
    }
    for (int b = 0; b < m.num_beams(); ++b)  // a beam joins its two ends
      for (int j = 0; j < 2; ++j)
        if (m.beam_nodes[std::size_t(b)][std::size_t(j)] >= 0)
          f(m.beam_nodes[std::size_t(b)][std::size_t(j)], ne + m.num_shells() + b);
  };
  each([&](int n, int) { ++ix.start[std::size_t(n) + 1]; });
  for (int i = 0; i < nn; ++i) ix.start[std::size_t(i) + 1] += ix.start[std::size_t(i)];
  ix.list.assign(std::size_t(ix.start[std::size_t(nn)]), 0);
  std::vector<int> fill(ix.start.begin(), ix.start.end() - 1);
  each([&](int n, int el) { ix.list[std::size_t(fill[std::size_t(n)]++)] = el; });
  return ix;
}

class NodeGraph {
 public:
  explicit NodeGraph(const Model& m) : m_(m), ix_(build_node_elements(m)), mark_(std::size_t(m.num_nodes()), 0) {}

  int degree(int n) const { return ix_.start[std::size_t(n) + 1] - ix_.start[std::size_t(n)]; }

  // Calls f(v) for every node v sharing an element with u (v may repeat; u itself skipped).
  template <class F>
  void for_each_neighbour(int u, F&& f) const {
    const int ne = m_.num_hexes();
    for (int c = ix_.start[std::size_t(u)]; c < ix_.start[std::size_t(u) + 1]; ++c) {
      const int el = ix_.list[std::size_t(c)];
      if (el < ne) {
        for (int v : m_.hex_nodes[std::size_t(el)])
          if (v != u) f(v);
      } else if (el >= ne + m_.num_shells()) {
        const auto& bn = m_.beam_nodes[std::size_t(el - ne - m_.num_shells())];
        for (int j = 0; j < 2; ++j)
          if (bn[std::size_t(j)] >= 0 && bn[std::size_t(j)] != u) f(bn[std::size_t(j)]);
      } else {
        for (int v : m_.shell_nodes[std::size_t(el - ne)])
          if (v >= 0 && v != u) f(v);
      }
    }
  }

  // Breadth-first levels from start over nodes not yet numbered (numbered[v] == 0).  Returns
  // the eccentricity; last holds the nodes of the last level.
  int levels_from(int start, const std::vector<char>& numbered, std::vector<int>& last) {
    const unsigned stamp = ++stamp_;
    std::vector<int>& q = queue_;
    q.clear();
    q.push_back(start);
    mark_[std::size_t(start)] = stamp;
    std::size_t head = 0;
    int depth = 0;
    std::size_t level_begin = 0;
    while (head < q.size()) {
      const std::size_t level_end = q.size();
      level_begin = head;
      for (; head < level_end; ++head)
        for_each_neighbour(q[head], [&](int v) {
          if (numbered[std::size_t(v)] || mark_[std::size_t(v)] == stamp) return;
          mark_[std::size_t(v)] = stamp;
          q.push_back(v);
        });
      if (q.size() > level_end) ++depth;
    }
    last.assign(q.begin() + std::ptrdiff_t(level_begin), q.end());
    return depth;
  }

 private:
  const Model& m_;
  NodeElements ix_;
  std::vector<unsigned> mark_;
  unsigned stamp_ = 0;
  std::vector<int> queue_;
};

}  // namespace

void compute_locality_order(const Model& m, std::vector<int>& node_new_of_old, std::vector<int>& hex_new_of_old) {
  const int nn = m.num_nodes(), ne = m.num_hexes();
  NodeGraph g(m);
  std::vector<char> numbered(std::size_t(nn), 0);
  std::vector<int> cm;  // Cuthill-McKee order (old indices)
  cm.reserve(std::size_t(nn));
  std::vector<int> last, fresh;
  for (int seed = 0; seed < nn; ++seed) {
    if (numbered[std::size_t(seed)]) continue;
    // a peripheral node of seed's component: the lowest-valence node of the last level of a
    // breadth-first search from seed (one step of George and Liu's search: further steps cost
    // a pass over the mesh each and gave the same locality cost on the bars measured)
    g.levels_from(seed, numbered, last);
    int start = last.front();
    for (int v : last)
      if (g.degree(v) < g.degree(start) || (g.degree(v) == g.degree(start) && v < start)) start = v;
    // Cuthill-McKee from it: each node's unnumbered neighbours by increasing degree
    std::size_t head = cm.size();
    cm.push_back(start);
    numbered[std::size_t(start)] = 1;
    for (; head < cm.size(); ++head) {
      fresh.clear();
      g.for_each_neighbour(cm[head], [&](int v) {
        if (numbered[std::size_t(v)]) return;
        numbered[std::size_t(v)] = 1;
        fresh.push_back(v);
      });
      std::sort(fresh.begin(), fresh.end(), [&](int a, int b) {
        return g.degree(a) != g.degree(b) ? g.degree(a) < g.degree(b) : a < b;
      });
      cm.insert(cm.end(), fresh.begin(), fresh.end());
    }
  }
  node_new_of_old.assign(std::size_t(nn), 0);
  for (int p = 0; p < nn; ++p) node_new_of_old[std::size_t(cm[std::size_t(p)])] = nn - 1 - p;  // reversed
  // solids by their lowest new node, then by deck order
  std::vector<int> low(static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    int lo = nn;
    for (int n : m.hex_nodes[std::size_t(e)]) lo = std::min(lo, node_new_of_old[std::size_t(n)]);
    low[std::size_t(e)] = lo;
  }
  std::vector<int> by(static_cast<std::size_t>(ne));
  std::iota(by.begin(), by.end(), 0);
  std::stable_sort(by.begin(), by.end(), [&](int a, int b) { return low[std::size_t(a)] < low[std::size_t(b)]; });
  hex_new_of_old.assign(std::size_t(ne), 0);
  for (int p = 0; p < ne; ++p) hex_new_of_old[std::size_t(by[std::size_t(p)])] = p;
}

namespace {

// Each array (empty: not given) moved to the new order: v[new_of_old[i]] = old v[i].
template <class... V>
void permute_arrays(const std::vector<int>& new_of_old, V&... arrays) {
  auto permute = [&](auto& v) {
    if (v.empty()) return;
    std::remove_reference_t<decltype(v)> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[std::size_t(new_of_old[i])] = std::move(v[i]);
    v.swap(out);
  };
  (permute(arrays), ...);
}

// order[k] (deck k -> index) composed with index -> new index
void compose_order(std::vector<int>& order, const std::vector<int>& new_of_old) {
  if (order.empty()) {
    order = new_of_old;
    return;
  }
  for (int& o : order) o = new_of_old[std::size_t(o)];
}

bool is_identity(const std::vector<int>& v, int offset) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] != int(i) + offset) return false;
  return true;
}

}  // namespace

void permute_model(Model& m, const std::vector<int>& node_new_of_old, const std::vector<int>& hex_new_of_old) {
  const int nn = m.num_nodes(), ne = m.num_hexes();
  auto node = [&](int n) { return n < 0 ? n : node_new_of_old[std::size_t(n)]; };
  // the deck's ids travel with the nodes and solids
  if (m.node_user_id.empty()) {
    m.node_user_id.resize(std::size_t(nn));
    std::iota(m.node_user_id.begin(), m.node_user_id.end(), 1);
  }
  if (m.hex_user_id.empty()) {
    m.hex_user_id.resize(std::size_t(ne));
    std::iota(m.hex_user_id.begin(), m.hex_user_id.end(), 1);
  }
  // per node
  permute_arrays(node_new_of_old, m.x, m.y, m.z, m.bc, m.node_user_id, m.rot_bc, m.init_omega, m.node_temperature);
  // per solid, and their nodes
  for (auto& hn : m.hex_nodes)
    for (int& n : hn) n = node(n);
  permute_arrays(hex_new_of_old, m.hex_nodes, m.hex_material, m.hex_line, m.hex_file, m.hex_user_id);
  // node references
  for (auto& sn : m.shell_nodes)
    for (int& n : sn) n = node(n);
  for (auto& bn : m.beam_nodes)
    for (int& n : bn)
      if (n >= 0) n = node(n);
  for (auto& w : m.walls)
    for (int& n : w.nodes) n = node(n);
  for (auto& si : m.interfaces) {
    for (auto& sg : si.slave)
      for (int& n : sg) n = node(n);
    for (auto& sg : si.master)
      for (int& n : sg) n = node(n);
    for (auto* list : {&si.slave_nodes, &si.master_nodes}) {
      for (int& n : *list) n = node(n);
      std::sort(list->begin(), list->end());  // kept sorted (SlidingInterface)
    }
  }
  for (auto& ft : m.force_transducers) {
    for (auto* list : {&ft.a_nodes, &ft.b_nodes}) {
      for (int& n : *list) n = node(n);
      std::sort(list->begin(), list->end());  // kept sorted (ForceTransducer)
    }
  }
  for (auto& l : m.nodal_loads) l.node = node(l.node);
  for (auto& l : m.pressure_loads)
    for (int& n : l.nodes) n = node(n);
  for (auto& pm : m.prescribed_motions) pm.node = node(pm.node);
  for (auto& w : m.spot_welds)
    for (int& n : w.nodes) n = node(n);
  for (auto& tc : m.tied_contacts) {
    for (int& n : tc.slave_nodes) n = node(n);
    std::sort(tc.slave_nodes.begin(), tc.slave_nodes.end());  // kept sorted (TiedContact)
    for (auto& sg : tc.master)
      for (int& n : sg) n = node(n);
  }
  for (auto& t : m.node_ties) {
    t.node = node(t.node);
    for (int& n : t.seg) n = node(n);
  }
  compose_order(m.node_order, node_new_of_old);
  compose_order(m.hex_order, hex_new_of_old);
}

Model model_in_deck_order(const Model& m) {
  Model d = m;
  if (!m.renumbered()) return d;
  std::vector<int> node_back(std::size_t(m.num_nodes())), hex_back(std::size_t(m.num_hexes()));
  for (int k = 0; k < m.num_nodes(); ++k) node_back[std::size_t(m.node_of_deck_number(k + 1))] = k;
  for (int k = 0; k < m.num_hexes(); ++k) hex_back[std::size_t(m.hex_of_deck_number(k + 1))] = k;
  permute_model(d, node_back, hex_back);
  d.node_order.clear();
  d.hex_order.clear();
  if (is_identity(d.node_user_id, 1)) d.node_user_id.clear();
  if (is_identity(d.hex_user_id, 1)) d.hex_user_id.clear();
  return d;
}

MeshOrderReport order_mesh_for_locality(Model& m, MeshOrderMode mode) {
  MeshOrderReport r;
  r.mode = mode;
  if (mode == MeshOrderMode::off || m.num_nodes() == 0) return r;
  r.deck_cost = mesh_locality_cost(m);
  if (mode == MeshOrderMode::automatic && m.num_hexes() + m.num_shells() < kMeshOrderMinElements) return r;
  // a numbering whose cost is within 2 N^(2/3) is as local as a 3-D mesh of N nodes allows
  // (a cube's plane-by-plane numbering costs about N^(2/3)): not worth computing another
  r.local_bound = 2 * std::cbrt(double(m.num_nodes()) * double(m.num_nodes()));
  if (mode == MeshOrderMode::automatic && r.deck_cost <= r.local_bound) return r;
  std::vector<int> node_new, hex_new;
  compute_locality_order(m, node_new, hex_new);
  // the cost of the new numbering, from the maps (without moving the model)
  {
    Model probe;
    probe.x.resize(m.x.size());
    probe.hex_nodes.resize(m.hex_nodes.size());
    for (std::size_t e = 0; e < m.hex_nodes.size(); ++e)
      for (int j = 0; j < 8; ++j)
        probe.hex_nodes[std::size_t(hex_new[e])][std::size_t(j)] = node_new[std::size_t(m.hex_nodes[e][std::size_t(j)])];
    probe.shell_nodes = m.shell_nodes;
    for (auto& sn : probe.shell_nodes)
      for (int& n : sn)
        if (n >= 0) n = node_new[std::size_t(n)];
    r.ordered_cost = mesh_locality_cost(probe);
  }
  if (mode == MeshOrderMode::automatic && !(2 * r.ordered_cost <= r.deck_cost)) return r;
  permute_model(m, node_new, hex_new);
  r.renumbered = true;
  return r;
}

std::string mesh_order_line(const MeshOrderReport& r) {
  const char* how = r.mode == MeshOrderMode::on ? "reorder=on" : r.mode == MeshOrderMode::off ? "reorder=off" : "reorder=auto";
  char buf[300];
  if (r.renumbered)
    std::snprintf(buf, sizeof buf,
                  " mesh order: nodes and solids renumbered for locality (reverse Cuthill-McKee, %s): locality cost %.1f -> %.1f",
                  how, r.deck_cost, r.ordered_cost);
  else if (r.mode == MeshOrderMode::off)
    std::snprintf(buf, sizeof buf, " mesh order: the deck's (%s)", how);
  else if (r.ordered_cost == 0 && r.local_bound == 0)
    std::snprintf(buf, sizeof buf, " mesh order: the deck's (%s: below %d solids and shells)", how, kMeshOrderMinElements);
  else if (r.ordered_cost == 0)
    std::snprintf(buf, sizeof buf, " mesh order: the deck's (%s: locality cost %.1f, within 2 N^(2/3) = %.1f)", how,
                  r.deck_cost, r.local_bound);
  else
    std::snprintf(buf, sizeof buf, " mesh order: the deck's (%s: locality cost %.1f, renumbered %.1f)", how,
                  r.deck_cost, r.ordered_cost);
  return buf;
}

}  // namespace impact3d
