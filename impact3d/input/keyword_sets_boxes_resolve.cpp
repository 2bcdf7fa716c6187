// Keyword decks, the sets', boxes' and coordinate systems' resolve steps: set members as node,
// element and part indices (lists, _GENERATE, _ADD, _GENERAL), boxes, and *DEFINE_COORDINATE_*
// / *DEFINE_VECTOR into the coordinate table; the lookups every later step uses.  The records
// are read by keyword_sets_boxes.cpp; KeywordReader::resolve (keyword_reader.cpp) runs the steps
// (ResolveContext, keyword_resolve.h).

#include "impact3d/input/keyword_resolve.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace impact3d::kw {

// the family's own steps
static void ids_in_range(const std::vector<int>& sorted, const std::array<long long, 3>& r, std::vector<int>& out);
static bool enter_set(ResolveContext& rc, const RIdList& s, const Ref& r, const std::string& card);
static void refuse_set_option(ResolveContext& rc, const RSetTerm& t, const std::string& card, const char* valid);
static std::vector<int> nodes_of_elements(ResolveContext& rc, const std::vector<int>& elems);
static void build_coordinate_system(ResolveContext& rc, const RCoordSystem& r);

// Indices (into sorted ids) of the ids BBEG..BEND by INC.
void ids_in_range(const std::vector<int>& sorted, const std::array<long long, 3>& r, std::vector<int>& out) {
  auto lo = std::lower_bound(sorted.begin(), sorted.end(), r[0]);
  auto hi = std::upper_bound(sorted.begin(), sorted.end(), r[1]);
  for (auto it = lo; it < hi; ++it)
    if ((*it - r[0]) % r[2] == 0) out.push_back(int(it - sorted.begin()));
}

bool enter_set(ResolveContext& rc, const RIdList& s, const Ref& r, const std::string& card) {
  if (!rc.resolving.insert(&s).second) {
    rc.err(1309, r, card, "SID", "the set contains itself (through *SET_..._ADD or _GENERAL)");
    return false;
  }
  return true;
}

// The record of id in `defs`, or null: error `msg` ("<keyword> id is not defined", naming the
// refused keyword that defines it, of kind `kind`, if one does).
template <class Map>
const typename Map::mapped_type* find_defined(ResolveContext& rc, const Map& defs, int id, int msg, const char* keyword, char kind,
                                              const Ref& r, const std::string& card, const char* field) {
  auto it = defs.find(id);
  if (it != defs.end()) return &it->second;
  rc.err(msg, r, card, field, std::string(keyword) + " " + std::to_string(id) + " is not defined" + rc.refused_note(kind, id));
  return nullptr;
}

const Box* find_box(ResolveContext& rc, int id, const Ref& r, const std::string& card, const char* field) {
  const auto* b = find_defined(rc, rc.sb.boxes, id, 1310, "*DEFINE_BOX", 'B', r, card, field);
  return b ? &b->box : nullptr;
}

const RIdList* find_solid_set(ResolveContext& rc, int sid, const Ref& r, const std::string& card, const char* field) {
  return find_defined(rc, rc.sb.solid_sets, sid, 1309, "*SET_SOLID", 'H', r, card, field);
}

// The option of a *SET_..._GENERAL card that IMPACT-3D cannot resolve: error 1102 for the
// element kinds it does not have, 1006 for anything else.
void refuse_set_option(ResolveContext& rc, const RSetTerm& t, const std::string& card, const char* valid) {
  static const std::set<std::string> other_elements = {"SET_SHELL", "SET_BEAM", "SET_TSHELL", "SET_DISCRETE"};
  if (other_elements.count(t.option)) rc.err(1102, t.ref, card, "OPTION", t.option + ": IMPACT-3D has solid elements only");
  else rc.err(1006, t.ref, card, "OPTION", valid);
}

// The _ADD / _GENERAL terms of a set, in order, on mark (per node or element: 1 in the set):
// ALL marks (or, D in front, clears) every one; each id of another term goes to
// member(term, id, ref, value); an option not among `options` is refused (naming `valid`).
template <class Member>
void apply_set_terms(ResolveContext& rc, const RIdList& s, const std::string& card, std::vector<char>& mark,
                     std::initializer_list<const char*> options, const char* valid, Member member) {
  for (const RSetTerm& t : s.terms) {
    const char value = t.remove ? 0 : 1;
    if (t.option == "ALL") {
      std::fill(mark.begin(), mark.end(), value);
      continue;
    }
    if (std::none_of(options.begin(), options.end(), [&](const char* o) { return t.option == o; })) {
      refuse_set_option(rc, t, card, valid);
      continue;
    }
    for (std::size_t j = 0; j < t.ids.size(); ++j) member(t, t.ids[j], t.refs[j], value);
  }
}

// The indices of the marked entries, in increasing order.
static std::vector<int> marked(const std::vector<char>& mark) {
  std::vector<int> out;
  for (std::size_t k = 0; k < mark.size(); ++k)
    if (mark[k]) out.push_back(int(k));
  return out;
}

// Node set members as 0-based node indices (undefined nodes reported).  A list keeps its
// order; a set with _ADD or _GENERAL terms is sorted, each node once.
std::vector<int> set_nodes(ResolveContext& rc, const RIdList& s, const std::string& card) {
  std::vector<int> out;
  for (const auto& r : s.ranges) ids_in_range(rc.node_ids, r, out);  // _GENERATE
  for (std::size_t j = 0; j < s.ids.size(); ++j) {
    int idx = rc.node_index(s.ids[j]);
    if (idx < 0) {
      rc.err(1202, s.refs[j], card, "NID", "node " + std::to_string(s.ids[j]) + " is not defined by *NODE");
      continue;
    }
    out.push_back(idx);
  }
  if (s.terms.empty() || !enter_set(rc, s, s.ref, card)) return out;
  std::vector<char> mark(std::size_t(rc.m.num_nodes()), 0);
  for (int v : out) mark[std::size_t(v)] = 1;
  apply_set_terms(rc, s, card, mark, {"NODE", "PART", "BOX", "SET_SOLID", "SET"},
                  "node set options: ALL, NODE, PART, BOX, SET_SOLID (D in front removes: DNODE, DPART, DBOX, ...)",
                  [&](const RSetTerm& t, int id, const Ref& r, char value) {
                    const auto set_all = [&](const std::vector<int>& nodes) {
                      for (int v : nodes) mark[std::size_t(v)] = value;
                    };
                    if (t.option == "NODE") {
                      const int idx = rc.node_index(id);
                      if (idx < 0) rc.err(1202, r, card, "E", "node " + std::to_string(id) + " is not defined by *NODE");
                      else mark[std::size_t(idx)] = value;
                    } else if (t.option == "PART") {
                      set_all(nodes_of_parts(rc, parts_of(rc, false, id, r, card, "E")));
                    } else if (t.option == "BOX") {
                      if (const Box* bx = find_box(rc, id, r, card, "E"))
                        for (std::size_t k = 0; k < mark.size(); ++k)
                          if (bx->contains(rc.m.x[k], rc.m.y[k], rc.m.z[k])) mark[k] = value;
                    } else if (t.option == "SET_SOLID") {
                      if (const RIdList* ss = find_solid_set(rc, id, r, card, "E"))
                        set_all(nodes_of_elements(rc, set_solids(rc, *ss, "*SET_SOLID " + std::to_string(id))));
                    } else {  // SET: a member of a *SET_NODE_ADD
                      if (const RIdList* ns = find_node_set(rc, id, r, card, "NSID")) set_all(set_nodes(rc, *ns, "*SET_NODE " + std::to_string(id)));
                    }
                  });
  rc.resolving.erase(&s);
  return marked(mark);
}

// Solid set members as element indices, sorted, each once (undefined elements reported).
std::vector<int> set_solids(ResolveContext& rc, const RIdList& s, const std::string& card) {
  std::vector<char> mark(std::size_t(rc.m.num_hexes()), 0);
  std::vector<int> in;
  for (const auto& r : s.ranges) ids_in_range(rc.elem_ids, r, in);
  for (std::size_t j = 0; j < s.ids.size(); ++j) {
    const int idx = rc.elem_index(s.ids[j]);
    if (idx < 0) rc.err(1201, s.refs[j], card, "EID", "element " + std::to_string(s.ids[j]) + " is not defined by *ELEMENT_SOLID");
    else in.push_back(idx);
  }
  for (int e : in) mark[std::size_t(e)] = 1;
  if (s.terms.empty() || !enter_set(rc, s, s.ref, card)) return marked(mark);
  apply_set_terms(rc, s, card, mark, {"ELEM", "PART", "BOX", "SET"},
                  "solid set options: ALL, ELEM, PART, BOX (D in front removes: DELEM, DPART, DBOX)",
                  [&](const RSetTerm& t, int id, const Ref& r, char value) {
                    if (t.option == "ELEM") {
                      const int idx = rc.elem_index(id);
                      if (idx < 0) rc.err(1201, r, card, "E", "element " + std::to_string(id) + " is not defined by *ELEMENT_SOLID");
                      else mark[std::size_t(idx)] = value;
                    } else if (t.option == "PART") {
                      for (int p : parts_of(rc, false, id, r, card, "E"))
                        for (int e : rc.part_elems[std::size_t(p)]) mark[std::size_t(e)] = value;
                    } else if (t.option == "BOX") {  // elements whose centroid is in the box
                      if (const Box* bx = find_box(rc, id, r, card, "E"))
                        for (std::size_t e = 0; e < mark.size(); ++e) {
                          const auto& nd = rc.m.hex_nodes[e];
                          if (nd[0] < 0) continue;
                          double c[3] = {0, 0, 0};
                          for (int v : nd) {
                            c[0] += rc.m.x[std::size_t(v)] / 8;
                            c[1] += rc.m.y[std::size_t(v)] / 8;
                            c[2] += rc.m.z[std::size_t(v)] / 8;
                          }
                          if (bx->contains(c[0], c[1], c[2])) mark[e] = value;
                        }
                    } else if (const RIdList* ss = find_solid_set(rc, id, r, card, "SID")) {  // _ADD member
                      for (int e : set_solids(rc, *ss, "*SET_SOLID " + std::to_string(id))) mark[std::size_t(e)] = value;
                    }
                  });
  rc.resolving.erase(&s);
  return marked(mark);
}

// The nodes of elements (refused elements skipped), sorted, each once.
std::vector<int> nodes_of_elements(ResolveContext& rc, const std::vector<int>& elems) {
  std::vector<char> mark(std::size_t(rc.m.num_nodes()), 0);
  for (int e : elems) {
    const auto& n = rc.m.hex_nodes[std::size_t(e)];
    if (n[0] < 0) continue;
    for (int v : n) mark[std::size_t(v)] = 1;
  }
  return marked(mark);
}

// *DEFINE_COORDINATE_* and *DEFINE_VECTOR into rc.coords, once the nodes are known.  A system
// given in another one (CIDL) or a vector in a system (CID) waits for that system; one that
// never resolves names the missing system.
void resolve_coordinate_systems(ResolveContext& rc) {
  std::vector<char> done(rc.sb.systems.size(), 0);
  for (bool progress = true; progress;) {
    progress = false;
    for (std::size_t k = 0; k < rc.sb.systems.size(); ++k) {
      const RCoordSystem& r = rc.sb.systems[k];
      if (done[k] || !rc.coords.has_system(r.cid)) continue;
      done[k] = 1;
      progress = true;
      build_coordinate_system(rc, r);
    }
  }
  for (std::size_t k = 0; k < rc.sb.systems.size(); ++k)
    if (!done[k]) {
      const RCoordSystem& r = rc.sb.systems[k];
      rc.err(1310, r.cid_ref, r.keyword + " " + std::to_string(r.id), r.kind == RCoordSystem::vector ? "CID" : "CIDL",
          "coordinate system " + std::to_string(r.cid) + " is not defined (or the systems refer to each other)");
    }
}

void build_coordinate_system(ResolveContext& rc, const RCoordSystem& r) {
  const std::string card = r.keyword + " " + std::to_string(r.id);
  const CoordinateSystem* in = rc.coords.system(r.cid);
  auto point = [&](int k) { return in->to_global_point({r.v[std::size_t(3 * k)], r.v[std::size_t(3 * k + 1)], r.v[std::size_t(3 * k + 2)]}); };
  std::array<Vec3, 3> p{};
  const int nodes = r.kind == RCoordSystem::nodes ? 3 : (r.kind == RCoordSystem::vector && r.n[0] != 0) ? 2 : 0;
  for (int j = 0; j < nodes; ++j) {
    const int idx = rc.node_index(r.n[std::size_t(j)]);
    if (idx < 0) {
      rc.err(1202, r.node_refs[std::size_t(j)], card, j == 0 ? "N1" : j == 1 ? "N2" : "N3", "node " + std::to_string(r.n[std::size_t(j)]) + " is not defined by *NODE");
      return;
    }
    p[std::size_t(j)] = {rc.m.x[std::size_t(idx)], rc.m.y[std::size_t(idx)], rc.m.z[std::size_t(idx)]};
  }
  if (r.kind == RCoordSystem::vector) {
    Vec3 t = nodes ? p[0] : point(0), h = nodes ? p[1] : point(1);
    Vec3 d = {h[0] - t[0], h[1] - t[1], h[2] - t[2]};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0)) {
      rc.err(1003, r.ref, card, "VID", "the vector has zero length (tail and head coincide)");
      return;
    }
    for (double& a : d) a /= len;
    rc.coords.add_vector(r.id, d);
    return;
  }
  CoordinateSystem cs;
  bool ok;
  if (r.kind == RCoordSystem::nodes) ok = coordinate_system_from_points(p[0], p[1], p[2], cs);
  else if (r.kind == RCoordSystem::points) ok = coordinate_system_from_points(point(0), point(1), point(2), cs);
  else ok = coordinate_system_from_vectors({r.v[0], r.v[1], r.v[2]}, {r.v[3], r.v[4], r.v[5]}, cs);
  if (!ok) {
    rc.err(1003, r.ref, card, "CID", "the points (or vectors) that define the local x axis and the x-y plane are collinear or coincide");
    return;
  }
  rc.coords.add_system(r.id, cs);
}

// A direction given in system cid (0: global) in global components; false (reported) if cid
// is not defined.
bool global_direction(ResolveContext& rc, int cid, const Ref& r, const std::string& card, const char* field, std::array<double, 3>& v) {
  if (cid == 0) return true;
  if (!rc.coords.to_global_direction(cid, v, v)) {
    rc.err(1310, r, card, field, "coordinate system " + std::to_string(cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
    return false;
  }
  return true;
}

const RIdList* find_node_set(ResolveContext& rc, int sid, const Ref& r, const std::string& card, const char* field) {
  return find_defined(rc, rc.sb.node_sets, sid, 1309, "*SET_NODE_LIST", 'N', r, card, field);
}

// Parts of a part or part set, as part indices.
std::vector<int> parts_of(ResolveContext& rc, bool is_set, int id, const Ref& r, const std::string& card, const char* field) {
  std::vector<int> out;
  if (is_set) {
    auto it = rc.sb.part_sets.find(id);
    if (it == rc.sb.part_sets.end()) {
      rc.err(1309, r, card, field, "*SET_PART_LIST " + std::to_string(id) + " is not defined" + rc.refused_note('P', id));
      return out;
    }
    for (std::size_t j = 0; j < it->second.ids.size(); ++j) {
      auto p = rc.part_index.find(it->second.ids[j]);
      if (p == rc.part_index.end()) rc.err(1308, it->second.refs[j], "*SET_PART_LIST " + std::to_string(id), "PID", "part " + std::to_string(it->second.ids[j]) + " is not defined" + rc.refused_note('p', it->second.ids[j]));
      else out.push_back(p->second);
    }
    // _GENERATE: the parts whose ids lie in the ranges; _ADD: the parts of the member sets
    for (const auto& rg : it->second.ranges)
      for (auto p = rc.part_index.lower_bound(int(rg[0])); p != rc.part_index.end() && p->first <= rg[1]; ++p)
        if ((p->first - rg[0]) % rg[2] == 0) out.push_back(p->second);
    if (!it->second.terms.empty() && enter_set(rc, it->second, it->second.ref, card)) {
      for (const RSetTerm& t : it->second.terms)
        for (std::size_t j = 0; j < t.ids.size(); ++j) {
          std::vector<int> more = parts_of(rc, true, t.ids[j], t.refs[j], it->second.keyword + " " + std::to_string(id), "PSID");
          out.insert(out.end(), more.begin(), more.end());
        }
      rc.resolving.erase(&it->second);
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
    }
  } else {
    auto p = rc.part_index.find(id);
    if (p == rc.part_index.end()) rc.err(1308, r, card, field, "part " + std::to_string(id) + " is not defined" + rc.refused_note('p', id));
    else out.push_back(p->second);
  }
  return out;
}

std::vector<int> nodes_of_parts(ResolveContext& rc, const std::vector<int>& parts) {
  std::vector<char> mark(std::size_t(rc.m.num_nodes()), 0);
  for (int p : parts) {
    for (int e : rc.part_elems[std::size_t(p)]) {
      const auto& n = rc.m.hex_nodes[std::size_t(e)];
      if (n[0] < 0) continue;
      for (int v : n) mark[std::size_t(v)] = 1;
    }
    for (int e : rc.part_shells[std::size_t(p)]) {
      const auto& n = rc.m.shell_nodes[std::size_t(e)];
      if (n[0] < 0) continue;
      for (int v : n) mark[std::size_t(v)] = 1;
    }
  }
  return marked(mark);
}

}  // namespace impact3d::kw
