// Keyword decks, the nodes' and elements' resolve steps: *NODE, *ELEMENT_SOLID, *ELEMENT_SHELL
// and *ELEMENT_BEAM records into the Model, renumbered 1..N in increasing id order (a repeated
// id error 1200), their nodes and parts looked up (1202, 1308), each part's elements listed for
// the part steps (keyword_parts_resolve.cpp).  The records are read by
// keyword_nodes_elements.cpp; KeywordReader::resolve (keyword_reader.cpp) runs the steps first
// (ResolveContext, keyword_resolve.h).

#include "impact3d/input/keyword_resolve.h"

#include <algorithm>
#include <array>
#include <cstdint>

#include "impact3d/input/element_shapes.h"

namespace impact3d::kw {

void resolve_nodes(ResolveContext& rc) {
  std::vector<std::uint32_t> order;
  const std::size_t nn = order_by_id(rc.me.nodes, order, [&](const RNode& n, const RNode& first) {
    rc.err(1200, n.ref(), "*NODE node " + std::to_string(n.id), "NID", "node " + std::to_string(n.id) + " also defined at " + at(first.ref()));
  });
  const auto kept = [&](std::size_t k) { return &rc.me.nodes[order[k]]; };
  assign_huge(rc.m.x, nn, 0.0);
  assign_huge(rc.m.y, nn, 0.0);
  assign_huge(rc.m.z, nn, 0.0);
  assign_huge(rc.m.bc, nn, 0);
  rc.node_ids.resize(nn);
  bool identity = true;
  for (std::size_t k = 0; k < nn; ++k) {
    const RNode& n = *kept(k);
    rc.node_ids[k] = n.id;
    rc.m.x[k] = n.x;
    rc.m.y[k] = n.y;
    rc.m.z[k] = n.z;
    rc.m.bc[k] = n.tc;
    identity = identity && n.id == int(k) + 1;
  }
  rc.m.node_user_id.clear();
  if (!identity) rc.m.node_user_id = rc.node_ids;
  rc.node_ids_identity = identity;
  release(order);
  release(rc.me.nodes);  // the raw nodes are not needed any more
  if (nn == 0) {
    Location loc;
    loc.file = rc.main_file;
    rc.diag.add(1311, loc, "*NODE: the deck defines no nodes");
  }
}

void resolve_parts_and_elements(ResolveContext& rc) {
  for (std::size_t k = 0; k < rc.ps.parts.size(); ++k) {
    auto [it, fresh] = rc.part_index.emplace(rc.ps.parts[k].pid, int(k));
    if (!fresh) rc.err(1200, rc.ps.parts[k].ref, "*PART " + std::to_string(rc.ps.parts[k].pid), "PID", "also defined at " + at(rc.ps.parts[it->second].ref));
  }
  rc.part_elems.assign(rc.ps.parts.size(), {});
  std::vector<std::uint32_t> order;
  const std::size_t ne = order_by_id(rc.me.elems, order, [&](const RElem& e, const RElem& first) {
    rc.err(1200, e.ref(), "*ELEMENT_SOLID element " + std::to_string(e.id), "EID", "element " + std::to_string(e.id) + " also defined at " + at(first.ref()));
  });
  std::array<int, 8> undefined;
  undefined.fill(-1);
  assign_huge(rc.m.hex_nodes, ne, undefined);
  assign_huge(rc.m.hex_material, ne, -1);
  assign_huge(rc.m.hex_line, ne, 0);
  assign_huge(rc.m.hex_file, ne, -1);
  rc.elem_ids.resize(ne);
  bool identity = true;
  const DeckFile* last_file = nullptr;
  int last_file_index = -1;
  int last_pid = 0;
  auto last_part = rc.part_index.end();
  for (std::size_t k = 0; k < ne; ++k) {
    const RElem& e = rc.me.elems[order[k]];
    rc.elem_ids[k] = e.id;
    identity = identity && e.id == int(k) + 1;
    rc.m.hex_line[k] = e.card.line ? e.card.line->number : 0;
    if (e.card.file != last_file || !last_file) {
      last_file = e.card.file;
      last_file_index = rc.file_index(e.card.file);
    }
    rc.m.hex_file[k] = last_file_index;
    const auto card = [&] { return "*ELEMENT_SOLID element " + std::to_string(e.id); };
    bool ok = true;
    std::array<int, 8> n{};
    for (int j = 0; j < 8; ++j) {
      int idx = rc.node_index(e.n[std::size_t(j)]);
      if (idx < 0) {
        std::string f = "N" + std::to_string(j + 1);
        rc.err(1202, e.node_ref(j), card(), f.c_str(), "node " + std::to_string(e.n[std::size_t(j)]) + " is not defined by *NODE");
        ok = false;
      }
      n[std::size_t(j)] = idx;
    }
    if (last_part == rc.part_index.end() || e.pid != last_pid) {
      last_part = rc.part_index.find(e.pid);
      last_pid = e.pid;
    }
    auto pit = last_part;
    if (pit == rc.part_index.end()) {
      rc.err(1308, e.pid_ref(), card(), "PID", "part " + std::to_string(e.pid) + " is not defined by *PART" + rc.refused_note('p', e.pid));
      ok = false;
    } else {
      rc.part_elems[std::size_t(pit->second)].push_back(int(k));
    }
    if (ok && !is_valid_solid_node_pattern(n)) {
      Ref r = e.node_ref(0);
      r.c2 = e.node_ref(7).c2;
      rc.err(1222, r, card(), "N1-N8");
      ok = false;
    }
    if (ok) {
      make_canonical_solid_node_pattern(n);
      rc.m.hex_nodes[k] = n;
      rc.m.hex_material[k] = -2 - pit->second;  // part index, replaced by the material index
    }
  }
  release(order);
  release(rc.me.elems);  // the raw elements are not needed any more
  rc.m.hex_user_id.clear();
  if (!identity) rc.m.hex_user_id = rc.elem_ids;
  if (ne == 0 && rc.me.shells.empty() && rc.me.beams.empty()) {
    Location loc;
    loc.file = rc.main_file;
    rc.diag.add(1311, loc, "*ELEMENT_SOLID, *ELEMENT_SHELL, *ELEMENT_BEAM: the deck defines no elements");
  }
}

// The Model's arrays of one element kind (shells or beams), N nodes an element.
template <std::size_t N>
struct ElementArrays {
  std::vector<std::array<int, N>>& nodes;
  std::vector<int>& material;
  std::vector<std::array<double, 4>>& thickness;
  std::vector<int>& line;
  std::vector<int>& file;
  std::vector<int>& user_id;
};

// Shell or beam cards -> the kind's arrays in increasing id order (material: -2 - part index
// until the part steps; an element whose nodes or part are refused gets -1 and nodes -1) and
// the parts' lists of them.  A beam's N3 (orientation) may be 0: none.  valid: the kind's own
// check of the node indices, reporting; kept(e): the kind's further data of each element kept.
template <class Card, std::size_t N, class Valid, class Kept>
void resolve_element_cards(ResolveContext& rc, std::vector<Card>& cards, const char* keyword, ElementArrays<N> a,
                           std::vector<std::vector<int>>& part_list, Valid valid, Kept kept) {
  part_list.assign(rc.ps.parts.size(), {});
  std::stable_sort(cards.begin(), cards.end(), [](const Card& x, const Card& y) { return x.id < y.id; });
  std::vector<int> ids;
  bool identity = true;
  for (std::size_t q = 0; q < cards.size(); ++q) {
    const Card& e = cards[q];
    const std::string card = std::string(keyword) + " element " + std::to_string(e.id);
    if (q > 0 && cards[q - 1].id == e.id) {
      rc.err(1200, e.ref, card, "EID", "element " + std::to_string(e.id) + " also defined at " + at(cards[q - 1].ref));
      continue;
    }
    std::array<int, N> n;
    n.fill(-1);
    bool ok = true;
    for (std::size_t j = 0; j < N; ++j) {
      if (N == 3 && j == 2 && e.n[2] == 0) break;  // a beam without orientation node
      n[j] = rc.node_index(e.n[j]);
      if (n[j] < 0) {
        const std::string f = "N" + std::to_string(j + 1);
        rc.err(1202, e.node_refs[j], card, f.c_str(), "node " + std::to_string(e.n[j]) + " is not defined by *NODE");
        ok = false;
      }
    }
    ok = ok && valid(e, n, card);
    auto pit = rc.part_index.find(e.pid);
    if (pit == rc.part_index.end()) {
      rc.err(1308, e.pid_ref, card, "PID", "part " + std::to_string(e.pid) + " is not defined by *PART" + rc.refused_note('p', e.pid));
      ok = false;
    }
    const int k = int(a.nodes.size());
    if (!ok) n.fill(-1);
    a.nodes.push_back(n);
    a.material.push_back(ok ? -2 - pit->second : -1);
    a.thickness.push_back(e.t);
    kept(e);
    a.line.push_back(e.line);
    a.file.push_back(rc.file_index(e.file));
    ids.push_back(e.id);
    identity = identity && e.id == k + 1;
    if (ok) part_list[std::size_t(pit->second)].push_back(k);
  }
  a.user_id.clear();
  if (!identity) a.user_id = ids;
  release(cards);
}

// *ELEMENT_SHELL cards -> Model::shell_* (a quadrilateral, or a triangle with N3 = N4).
void resolve_shells(ResolveContext& rc) {
  Model& m = rc.m;
  resolve_element_cards(rc, rc.me.shells, "*ELEMENT_SHELL",
                        ElementArrays<4>{m.shell_nodes, m.shell_material, m.shell_thickness, m.shell_line, m.shell_file, m.shell_user_id},
                        rc.part_shells, [&](const RShell& e, const std::array<int, 4>& n, const std::string& card) {
                          if (!(n[0] == n[1] || n[0] == n[2] || n[1] == n[2] || n[0] == n[3] || n[1] == n[3])) return true;
                          Ref r = e.node_refs[0];
                          r.c2 = e.node_refs[3].c2;
                          rc.err(1222, r, card, "N1-N4", "a shell is a quadrilateral or a triangle with N3 = N4");
                          return false;
                        },
                        [](const RShell&) {});
  m.shell_rotary_scale = rc.ctl.rotascl;
}

// *ELEMENT_BEAM cards -> Model::beam_* (N1 and N2 different; beam_orientation only when some
// beam gives an _ORIENTATION vector).
void resolve_beams(ResolveContext& rc) {
  Model& m = rc.m;
  bool oriented = false;
  for (const RBeam& e : rc.me.beams) oriented = oriented || e.v[0] != 0 || e.v[1] != 0 || e.v[2] != 0;
  m.beam_orientation.clear();
  resolve_element_cards(rc, rc.me.beams, "*ELEMENT_BEAM",
                        ElementArrays<3>{m.beam_nodes, m.beam_material, m.beam_thickness, m.beam_line, m.beam_file, m.beam_user_id},
                        rc.part_beams, [&](const RBeam& e, const std::array<int, 3>& n, const std::string& card) {
                          if (n[0] != n[1]) return true;
                          Ref r = e.node_refs[0];
                          r.c2 = e.node_refs[1].c2;
                          rc.err(1250, r, card, "N1-N2", "N1 = N2");
                          return false;
                        },
                        [&](const RBeam& e) {
                          if (oriented) m.beam_orientation.push_back(e.v);
                        });
}

}  // namespace impact3d::kw
