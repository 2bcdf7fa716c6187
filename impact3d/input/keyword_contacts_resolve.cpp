// Keyword decks, the contacts' resolve step: each *CONTACT_... side (segment set, part, part
// set, node set, all parts; SABOXID / SBBOXID) becomes segments and beam nodes, and the
// contact a sliding interface, a force transducer or a tied contact.  The records are read by
// keyword_contacts.cpp; KeywordReader::resolve (keyword_reader.cpp) runs the step once the
// sets and parts are resolved (ResolveContext, keyword_resolve.h).

#include "impact3d/input/keyword_resolve.h"

#include <algorithm>
#include <cmath>

#include "impact3d/contact/tied_nodes.h"

namespace impact3d::kw {

// Faces of the hexahedron (0-based local nodes), counter-clockwise seen from outside.
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// the family's own steps
static void exterior_faces_of_elements(ResolveContext& rc, const std::vector<int>& elems, std::vector<std::array<int, 4>>& out, std::vector<int>& lines,
                                std::vector<int>& files);
static void shell_segments(ResolveContext& rc, const std::vector<int>& parts, const std::vector<char>* node_filter,
                    std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files);
static void exterior_faces(ResolveContext& rc, const std::vector<int>& parts, const std::vector<char>* node_filter,
                    std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files);
static void segment_set_segments(ResolveContext& rc, const RSegSet& s, int sid, std::vector<std::array<int, 4>>& out, std::vector<int>& lines,
                          std::vector<int>& files);
static void resolve_side(ResolveContext& rc, const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                  std::vector<int>& lines, std::vector<int>& files, std::vector<int>& beam_nodes,
                  bool can_be_nodes);
static void keep_segments_in_box(ResolveContext& rc, const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                          std::vector<int>& lines, std::vector<int>& files);
static void resolve_tied_contact(ResolveContext& rc, const RContact& c);
static void drop_symmetry_plane_faces(ResolveContext& rc, std::size_t first, std::vector<std::array<int, 4>>& out,
                                      std::vector<int>& lines, std::vector<int>& files);

// Exterior faces of a list of elements (faces not shared by two of them).
void exterior_faces_of_elements(ResolveContext& rc, const std::vector<int>& elems, std::vector<std::array<int, 4>>& out, std::vector<int>& lines,
                                std::vector<int>& files) {
  rc.element_filter = &elems;
  exterior_faces(rc, {}, nullptr, out, lines, files);
  rc.element_filter = nullptr;
}

// The shells of the parts (or, with a node filter, every shell whose nodes are all in it) as
// contact segments, in shell order: n1 n2 n3 n4 (both sides of a shell are used).
void shell_segments(ResolveContext& rc, const std::vector<int>& parts, const std::vector<char>* node_filter,
                    std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files) {
  std::vector<int> shells;
  if (node_filter) {
    for (int k = 0; k < rc.m.num_shells(); ++k) shells.push_back(k);
  } else {
    for (int p : parts) shells.insert(shells.end(), rc.part_shells[std::size_t(p)].begin(), rc.part_shells[std::size_t(p)].end());
    std::sort(shells.begin(), shells.end());
    shells.erase(std::unique(shells.begin(), shells.end()), shells.end());
  }
  for (int k : shells) {
    const auto& n = rc.m.shell_nodes[std::size_t(k)];
    if (n[0] < 0) continue;
    if (node_filter && !std::all_of(n.begin(), n.end(), [&](int v) { return (*node_filter)[std::size_t(v)] != 0; })) continue;
    out.push_back(n);
    lines.push_back(rc.m.shell_line[std::size_t(k)]);
    files.push_back(rc.m.shell_file.empty() ? -1 : rc.m.shell_file[std::size_t(k)]);
  }
}

// Exterior faces of the elements of the parts (faces not shared by two of those elements),
// in element and face order, outward counter-clockwise; triangles as n1 n2 n3 n3.
void exterior_faces(ResolveContext& rc, const std::vector<int>& parts, const std::vector<char>* node_filter,
                    std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files) {
  std::vector<int> elems;
  for (int p : parts) elems.insert(elems.end(), rc.part_elems[std::size_t(p)].begin(), rc.part_elems[std::size_t(p)].end());
  if (node_filter) {
    elems.clear();
    for (int e = 0; e < rc.m.num_hexes(); ++e) elems.push_back(e);
  }
  if (rc.element_filter) elems = *rc.element_filter;
  std::sort(elems.begin(), elems.end());
  elems.erase(std::unique(elems.begin(), elems.end()), elems.end());
  std::map<std::array<int, 4>, int> count;
  auto key = [](std::array<int, 4> f) {
    std::sort(f.begin(), f.end());
    auto end = std::unique(f.begin(), f.end());
    for (auto it = end; it != f.end(); ++it) *it = -1;
    return f;
  };
  auto face = [&](int e, int f) {
    const auto& n = rc.m.hex_nodes[std::size_t(e)];
    return std::array<int, 4>{n[std::size_t(kHexFaces[f][0])], n[std::size_t(kHexFaces[f][1])],
                              n[std::size_t(kHexFaces[f][2])], n[std::size_t(kHexFaces[f][3])]};
  };
  for (int e : elems) {
    if (rc.m.hex_nodes[std::size_t(e)][0] < 0) continue;
    for (int f = 0; f < 6; ++f) ++count[key(face(e, f))];
  }
  for (int e : elems) {
    if (rc.m.hex_nodes[std::size_t(e)][0] < 0) continue;
    for (int f = 0; f < 6; ++f) {
      std::array<int, 4> s = face(e, f);
      std::array<int, 4> k = key(s);
      if (k[2] < 0) continue;  // collapsed face (edge or point)
      if (count[k] != 1 && !rc.all_faces) continue;
      if (k[3] < 0) {
        // triangle: rotate the cycle so that the repeated node is n3 = n4
        for (int r = 0; r < 4 && s[2] != s[3]; ++r) s = {s[1], s[2], s[3], s[0]};
        if (s[2] != s[3]) continue;
      }
      if (node_filter) {
        bool all = true;
        for (int v : s) all = all && (*node_filter)[std::size_t(v)];
        if (!all) continue;
      }
      out.push_back(s);
      lines.push_back(rc.m.hex_line[std::size_t(e)]);
      files.push_back(rc.m.hex_file.empty() ? -1 : rc.m.hex_file[std::size_t(e)]);
    }
  }
}

void segment_set_segments(ResolveContext& rc, const RSegSet& s, int sid, std::vector<std::array<int, 4>>& out, std::vector<int>& lines,
                          std::vector<int>& files) {
  const std::string card = "*SET_SEGMENT " + std::to_string(sid);
  for (std::size_t j = 0; j < s.segs.size(); ++j) {
    std::array<int, 4> seg{};
    bool ok = true;
    for (int q = 0; q < 4; ++q) {
      int idx = rc.node_index(s.segs[j][std::size_t(q)]);
      if (idx < 0) {
        std::string f = "N" + std::to_string(q + 1);
        rc.err(1202, s.refs[j][std::size_t(q)], card, f.c_str(), "node " + std::to_string(s.segs[j][std::size_t(q)]) + " is not defined by *NODE");
        ok = false;
      }
      seg[std::size_t(q)] = idx;
    }
    if (ok) {
      out.push_back(seg);
      lines.push_back(s.refs[j][0].line ? s.refs[j][0].line->number : 0);
      files.push_back(rc.file_index(s.refs[j][0].file));
    }
  }
  if (s.terms.empty()) return;
  if (!rc.resolving_segments.insert(&s).second) {
    rc.err(1309, s.ref, card, "SID", "the set contains itself (through *SET_SEGMENT_ADD)");
    return;
  }
  for (const RSetTerm& t : s.terms) {
    if (t.remove || (t.option != "SET" && t.option != "PART" && t.option != "SET_SOLID")) {
      rc.err(t.option == "SET_SHELL" || t.option == "BOX" || t.remove ? 1102 : 1006, t.ref, card, "OPTION",
          t.option == "SET_SHELL" || t.option == "BOX" || t.remove ? (t.remove ? "D" : "") + t.option + " in *SET_SEGMENT_GENERAL (IMPACT-3D has PART, SET_SOLID)"
                                                                   : std::string("segment set options: PART, SET_SOLID"));
      continue;
    }
    for (std::size_t j = 0; j < t.ids.size(); ++j) {
      if (t.option == "SET") {
        auto it = rc.sb.seg_sets.find(t.ids[j]);
        if (it == rc.sb.seg_sets.end()) rc.err(1309, t.refs[j], card, "SSID", "*SET_SEGMENT " + std::to_string(t.ids[j]) + " is not defined" + rc.refused_note('S', t.ids[j]));
        else segment_set_segments(rc, it->second, t.ids[j], out, lines, files);
      } else if (t.option == "PART") {
        exterior_faces(rc, parts_of(rc, false, t.ids[j], t.refs[j], card, "E"), nullptr, out, lines, files);
      } else if (const RIdList* ss = find_solid_set(rc, t.ids[j], t.refs[j], card, "E")) {
        exterior_faces_of_elements(rc, set_solids(rc, *ss, "*SET_SOLID " + std::to_string(t.ids[j])), out, lines, files);
      }
    }
  }
  rc.resolving_segments.erase(&s);
}

// ISYM 1 (LS-DYNA: "do not include faces with normal boundary constraints"): the solid faces
// out[first...] whose unit normal lies within 1e-3 rad of a global axis (the two other
// components' length at most 1e-3) and whose every node is constrained along that axis
// (*NODE TC, *BOUNDARY_SPC, *CONSTRAINED_GLOBAL: the nodes' boundary codes) leave the side.
void drop_symmetry_plane_faces(ResolveContext& rc, std::size_t first, std::vector<std::array<int, 4>>& out,
                               std::vector<int>& lines, std::vector<int>& files) {
  const Model& m = rc.m;
  auto fixes = [&](int axis, int n) {
    const int code = m.bc[std::size_t(n)];
    return axis == 0 ? bc_fixes_x(code) : axis == 1 ? bc_fixes_y(code) : bc_fixes_z(code);
  };
  auto d = [&](int a, int b) {
    return std::array<double, 3>{m.x[std::size_t(b)] - m.x[std::size_t(a)], m.y[std::size_t(b)] - m.y[std::size_t(a)],
                                 m.z[std::size_t(b)] - m.z[std::size_t(a)]};
  };
  std::size_t kept = first;
  for (std::size_t k = first; k < out.size(); ++k) {
    const auto& s = out[k];
    // quadrilateral: the diagonals' cross product; triangle (n3 = n4): the edges'
    const auto u = s[2] == s[3] ? d(s[0], s[1]) : d(s[0], s[2]);
    const auto v = s[2] == s[3] ? d(s[0], s[2]) : d(s[1], s[3]);
    const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    int axis = 0;
    for (int q = 1; q < 3; ++q)
      if (std::abs(n[std::size_t(q)]) > std::abs(n[std::size_t(axis)])) axis = q;
    const double off = std::hypot(n[std::size_t((axis + 1) % 3)], n[std::size_t((axis + 2) % 3)]);
    bool on_plane = len > 0 && off <= 1e-3 * len;
    for (int q = 0; q < 4 && on_plane; ++q) on_plane = fixes(axis, s[std::size_t(q)]);
    if (on_plane) continue;
    out[kept] = out[k], lines[kept] = lines[k], files[kept] = files[k];
    ++kept;
  }
  out.resize(kept), lines.resize(kept), files.resize(kept);
}

// A side's segments (out, with their cards' lines and files) and its beam nodes (the end
// nodes of its parts' beams, or the node set's beam end nodes; in SABOXID / SBBOXID's box;
// sorted, none a node of the side's segments): beams are contact nodes, never segments.
// can_be_nodes: a side of beam nodes alone is a contact's slave side (else error 1255).
void resolve_side(ResolveContext& rc, const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                  std::vector<int>& lines, std::vector<int>& files, std::vector<int>& beam_nodes,
                  bool can_be_nodes) {
  const int errors_before = rc.diag.error_count();
  const char* field = slave ? "SURFA" : "SURFB";
  std::vector<char> beam_end(std::size_t(rc.m.num_nodes()), 0);
  auto mark_beam_ends = [&](int e) {
    const auto& bn = rc.m.beam_nodes[std::size_t(e)];
    if (bn[0] >= 0 && bn[1] >= 0) beam_end[std::size_t(bn[0])] = beam_end[std::size_t(bn[1])] = 1;
  };
  auto in_set = [&](const std::vector<char>& mark, int e) {
    const auto& bn = rc.m.beam_nodes[std::size_t(e)];
    return bn[0] >= 0 && bn[1] >= 0 && (mark[std::size_t(bn[0])] || mark[std::size_t(bn[1])]);
  };
  if (side.type == 0) {
    auto it = rc.sb.seg_sets.find(side.id);
    if (it == rc.sb.seg_sets.end()) {
      rc.err(1309, side.id_ref, card, field, "*SET_SEGMENT " + std::to_string(side.id) + " is not defined" + rc.refused_note('S', side.id));
      return;
    }
    segment_set_segments(rc, it->second, side.id, out, lines, files);
  } else if (side.type == 2 || side.type == 3 || side.type == 5) {
    // a part's segments: the exterior faces of its solids, then its shells (both sides)
    std::vector<int> parts;
    if (side.type == 5)
      for (std::size_t p = 0; p < rc.ps.parts.size(); ++p) parts.push_back(int(p));
    else
      parts = parts_of(rc, side.type == 2, side.id, side.id_ref, card, field);
    const std::size_t first_face = out.size();
    exterior_faces(rc, parts, nullptr, out, lines, files);
    if (rc.isym) drop_symmetry_plane_faces(rc, first_face, out, lines, files);
    shell_segments(rc, parts, nullptr, out, lines, files);
    for (int p : parts)
      for (int e : rc.part_beams[std::size_t(p)]) mark_beam_ends(e);
  } else if (side.type == 4) {
    if (const RIdList* s = find_node_set(rc, side.id, side.id_ref, card, field)) {
      std::vector<char> mark(std::size_t(rc.m.num_nodes()), 0);
      for (int n : set_nodes(rc, *s, "*SET_NODE_LIST " + std::to_string(side.id))) mark[std::size_t(n)] = 1;
      exterior_faces(rc, {}, &mark, out, lines, files);
      shell_segments(rc, {}, &mark, out, lines, files);
      for (int e = 0; e < rc.m.num_beams(); ++e)
        if (in_set(mark, e)) mark_beam_ends(e);
      for (std::size_t n = 0; n < mark.size(); ++n) beam_end[n] = char(beam_end[n] && mark[n]);
    }
  }
  if (side.boxid != 0) keep_segments_in_box(rc, side, slave, card, out, lines, files);
  const auto bit = side.boxid != 0 ? rc.sb.boxes.find(side.boxid) : rc.sb.boxes.end();  // (an undefined box: 1310 above)
  const Box* box = bit != rc.sb.boxes.end() ? &bit->second.box : nullptr;
  for (const auto& sg : out)
    for (int v : sg) beam_end[std::size_t(v)] = 0;
  beam_nodes.clear();
  for (std::size_t n = 0; n < beam_end.size(); ++n)
    if (beam_end[n] && (!box || box->contains(rc.m.x[n], rc.m.y[n], rc.m.z[n]))) beam_nodes.push_back(int(n));
  if (out.empty() && !beam_nodes.empty() && !can_be_nodes && rc.diag.error_count() == errors_before) {
    rc.err(1255, side.id_ref, card, field,
        std::string(slave ? "the single surface" : "the master side (SURFB)") + " holds beams (" +
            std::to_string(beam_nodes.size()) + " beam nodes) and no solid faces or shells to strike");
    return;
  }
  if (out.empty() && beam_nodes.empty() && rc.diag.error_count() == errors_before &&
      (side.type == 0 || side.type == 2 || side.type == 3 || side.type == 4 || side.type == 5))
    rc.err(1314, side.boxid != 0 ? side.box_ref : side.id_ref, card, side.boxid != 0 ? (slave ? "SABOXID" : "SBBOXID") : field,
        side.boxid != 0 ? "no segment has its centroid in the box" : "no segments");
}

// SABOXID / SBBOXID: the side keeps the segments whose centroid (mean of the corner nodes)
// is in the box.
void keep_segments_in_box(ResolveContext& rc, const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                          std::vector<int>& lines, std::vector<int>& files) {
  const Box* box = find_box(rc, side.boxid, side.box_ref, card, slave ? "SABOXID" : "SBBOXID");
  if (!box) return;
  std::size_t kept = 0;
  for (std::size_t j = 0; j < out.size(); ++j) {
    double c[3] = {0, 0, 0};
    for (int v : out[j]) {
      c[0] += rc.m.x[std::size_t(v)] / 4;
      c[1] += rc.m.y[std::size_t(v)] / 4;
      c[2] += rc.m.z[std::size_t(v)] / 4;
    }
    if (!box->contains(c[0], c[1], c[2])) continue;
    out[kept] = out[j];
    lines[kept] = lines[j];
    files[kept] = files[j];
    ++kept;
  }
  out.resize(kept);
  lines.resize(kept);
  files.resize(kept);
}

// A tied contact (*CONTACT_SPOTWELD..., *CONTACT_TIED_..._TO_SURFACE): its slave nodes (a node
// set's nodes; a segment set's or parts' segment and beam nodes) and master segments, then
// the ties (contact/tied_nodes.h); slave nodes out of every segment's reach warning 2015.
void resolve_tied_contact(ResolveContext& rc, const RContact& c) {
  TiedContact tc;
  tc.spotweld = c.tied >= 2;
  tc.torsion = c.tied == 3;
  tc.keyword = c.name;
  // translations only for TIED_NODES/SURFACE_TO_SURFACE; rotations too for spot welds and shell edges
  tc.rotations = tc.spotweld || c.name == "CONTACT_TIED_SHELL_EDGE_TO_SURFACE";
  tc.offset = c.offset;
  tc.id = c.cid;
  tc.line = c.ref.line ? c.ref.line->number : 0;
  tc.tolerance = c.sast < 0 ? -c.sast : 0.0;
  std::vector<int> lines, files, beam_nodes;
  if (c.a.type == 4 && c.a.boxid == 0) {
    if (const RIdList* s = find_node_set(rc, c.a.id, c.a.id_ref, c.keyword, "SURFA"))
      tc.slave_nodes = set_nodes(rc, *s, "*SET_NODE_LIST " + std::to_string(c.a.id));
  } else {
    std::vector<std::array<int, 4>> segs;
    resolve_side(rc, c.a, true, c.keyword, segs, lines, files, beam_nodes, true);
    for (const auto& sg : segs) tc.slave_nodes.insert(tc.slave_nodes.end(), sg.begin(), sg.end());
    tc.slave_nodes.insert(tc.slave_nodes.end(), beam_nodes.begin(), beam_nodes.end());
  }
  std::sort(tc.slave_nodes.begin(), tc.slave_nodes.end());
  tc.slave_nodes.erase(std::unique(tc.slave_nodes.begin(), tc.slave_nodes.end()), tc.slave_nodes.end());
  lines.clear(), files.clear();
  resolve_side(rc, c.b, false, c.keyword, tc.master, lines, files, beam_nodes, false);
  if (tc.slave_nodes.empty() || tc.master.empty()) return;  // (1309 / 1314 / 1255 above)
  rc.m.tied_contacts.push_back(std::move(tc));
  const std::vector<int> untied = tie_slave_nodes(rc.m, int(rc.m.tied_contacts.size()) - 1);
  if (untied.empty()) return;
  std::string ids;
  for (std::size_t k = 0; k < untied.size() && k < 10; ++k) ids += (k ? ", " : "") + std::to_string(rc.m.node_id(untied[k]));
  if (untied.size() > 10) ids += ", ...";
  rc.diag.add(2015, loc_of(c.ref, c.keyword, "SURFA"),
            std::to_string(untied.size()) + " slave node(s) lie within reach of no master segment (inside its normal "
            "projection, at most 5 % of its shorter diagonal from it, or |SAST| of a negative SAST) and are not tied: " + ids);
}

void resolve_contacts(ResolveContext& rc) {
  for (const RContact& c : rc.contacts) {
    rc.isym = c.isym;  // (every side of this contact made of parts)
    if (c.tied) {
      resolve_tied_contact(rc, c);
      continue;
    }
    if (c.transducer) {
      // side A (and B): the nodes of the segments, or of the node set
      ForceTransducer ft;
      ft.id = c.cid;
      ft.line = c.ref.line ? c.ref.line->number : 0;
      for (int sd = 0; sd < 2; ++sd) {
        const RSide& side = sd == 0 ? c.a : c.b;
        if (sd == 1 && side.id == 0) break;  // no side B: every contact force on A
        std::vector<int>& nodes = sd == 0 ? ft.a_nodes : ft.b_nodes;
        if (side.type == 4 && side.boxid == 0) {
          if (const RIdList* s = find_node_set(rc, side.id, side.id_ref, c.keyword, sd == 0 ? "SURFA" : "SURFB"))
            nodes = set_nodes(rc, *s, "*SET_NODE_LIST " + std::to_string(side.id));
        } else {
          std::vector<std::array<int, 4>> segs;
          std::vector<int> lines, files, beam_nodes;
          resolve_side(rc, side, sd == 0, c.keyword, segs, lines, files, beam_nodes, true);
          for (const auto& sg : segs) nodes.insert(nodes.end(), sg.begin(), sg.end());
          nodes.insert(nodes.end(), beam_nodes.begin(), beam_nodes.end());
        }
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        if (sd == 1) ft.has_b = true;
      }
      rc.m.force_transducers.push_back(std::move(ft));
      continue;
    }
    SlidingInterface si;
    si.type = c.single ? 4 : 3;
    si.eroding = c.eroding;
    si.keyword = c.name;
    rc.all_faces = c.eroding;  // an eroding side holds every face of its solids
    si.fs = c.fs;
    si.fd = c.fd;
    si.decay = c.dc;
    si.penalty_scale = c.sfsa == 1 ? 0 : c.sfsa * rc.ctl.slsfac;
    // SOFT 0 DYNA3D, 1 LS-DYNA's soft constraint, 2 LS-DYNA's segment-based, -1 IMPACT-3D maximum stable
    si.stiffness_method = c.soft == 1 ? 2 : c.soft == 2 ? 3 : c.soft == -1 ? 1 : 0;
    si.sofscl = c.sofscl;
    si.penopt = rc.ctl.penopt;
    si.symmetric = c.symmetric;
    si.shell_thickness = c.automatic ? 2 : c.thkopt == 1 ? c.shlthk : c.thkopt == 2 ? 0 : rc.ctl.shlthk;
    si.intfor_slave = c.sapr;
    si.intfor_master = c.sbpr;
    si.line = c.ref.line ? c.ref.line->number : 0;
    resolve_side(rc, c.a, true, c.keyword, si.slave, si.slave_line, si.slave_file, si.slave_nodes, !c.single);
    if (!c.single) resolve_side(rc, c.b, false, c.keyword, si.master, si.master_line, si.master_file, si.master_nodes, false);
    if (!c.symmetric) si.master_nodes.clear();  // one pass: the master side's nodes search nothing
    if (si.stiffness_method == 3) {
      // segment-based contact: segments only (LS-DYNA's does not work with beams)
      si.slave_nodes.clear();
      si.master_nodes.clear();
    }
    rc.all_faces = false;
    rc.m.interfaces.push_back(std::move(si));
  }
  rc.isym = false;
  rc.m.control.num_interfaces = int(rc.m.interfaces.size());
}

}  // namespace impact3d::kw
