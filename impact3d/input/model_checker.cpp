// Model checks that need the whole model: element volumes, interface segments on element
// faces, unused materials and nodes, initial-velocity ranges.  Every problem is reported.

#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "impact3d/element/hexahedron.h"
#include "impact3d/element/beam_hl.h"
#include "impact3d/element/shell_bt.h"
#include "impact3d/init/beam_init.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material_types.h"
#include "impact3d/material/eos.h"

namespace impact3d {

namespace {
// Faces of the hexahedron (0-based local nodes), counter-clockwise seen from outside.
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

std::array<int, 4> face_key(std::array<int, 4> f) {
  std::sort(f.begin(), f.end());
  // collapse repeated nodes (triangular faces of wedges/tetrahedra): keep unique, pad with -1
  auto end = std::unique(f.begin(), f.end());
  for (auto it = end; it != f.end(); ++it) *it = -1;
  return f;
}
// The distinct nodes of a face in their cyclic order (a degenerate face repeats nodes).
std::vector<int> face_cycle(const std::array<int, 4>& f) {
  std::vector<int> c;
  for (int k = 0; k < 4; ++k)
    if (f[std::size_t(k)] != f[std::size_t((k + 3) % 4)]) c.push_back(f[std::size_t(k)]);
  if (c.empty()) c.push_back(f[0]);
  return c;
}

struct FaceKeyHash {
  std::size_t operator()(const std::array<int, 4>& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int v : k) h = (h ^ std::uint32_t(v)) * 0x100000001b3ull + (h >> 29);
    return std::size_t(h ^ (h >> 32));
  }
};

// Calls f(key, nodes) for every face of every defined element, in element and face order.
template <class F>
void for_each_element_face(const Model& m, F&& f) {
  for (int e = 0; e < m.num_hexes(); ++e) {
    const auto& n = m.hex_nodes[std::size_t(e)];
    if (n[0] < 0) continue;
    for (const auto& fc : kHexFaces) {
      const std::array<int, 4> nodes = {n[std::size_t(fc[0])], n[std::size_t(fc[1])], n[std::size_t(fc[2])], n[std::size_t(fc[3])]};
      f(face_key(nodes), nodes);
    }
  }
}

bool has_interface_segments(const Model& m) {
  for (const auto& si : m.interfaces)
    if (!si.slave.empty() || !si.master.empty()) return true;
  return false;
}

// a is b rotated (same cyclic order)
bool same_cycle(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  const std::size_t n = a.size();
  for (std::size_t r = 0; r < n; ++r) {
    bool ok = true;
    for (std::size_t k = 0; k < n && ok; ++k) ok = a[k] == b[(k + r) % n];
    if (ok) return true;
  }
  return false;
}
}  // namespace

void orient_interface_segments(Model& m, Diagnostics& diag) {
  // exterior faces: key -> the outward face (counter-clockwise from outside); faces met twice
  // are interior (orientation ambiguous: left as given).  Only the faces that are segments
  // matter: those keys are collected first, then the element faces counted against them (the
  // first face met gives the nodes).
  if (!has_interface_segments(m)) return;
  struct Face { std::array<int, 4> nodes; int count; };
  std::unordered_map<std::array<int, 4>, Face, FaceKeyHash> faces;
  for (const auto& si : m.interfaces)
    for (const auto* segs : {&si.slave, &si.master})
      for (const auto& seg : *segs) faces.try_emplace(face_key(seg), Face{{}, 0});
  for_each_element_face(m, [&](const std::array<int, 4>& key, const std::array<int, 4>& nodes) {
    auto it = faces.find(key);
    if (it == faces.end()) return;
    if (it->second.count++ == 0) it->second.nodes = nodes;
  });
  Location file_loc;
  file_loc.file = m.deck_file;
  for (std::size_t i = 0; i < m.interfaces.size(); ++i) {
    auto& si = m.interfaces[i];
    for (int side = 0; side < 2; ++side) {
      auto& segs = side == 0 ? si.slave : si.master;
      const auto& lines = side == 0 ? si.slave_line : si.master_line;
      for (std::size_t s = 0; s < segs.size(); ++s) {
        auto it = faces.find(face_key(segs[s]));
        if (it == faces.end() || it->second.count != 1) continue;  // not a face, or interior
        const std::vector<int> out = face_cycle(it->second.nodes), given = face_cycle(segs[s]);
        if (same_cycle(given, out)) continue;
        Location loc = file_loc;
        loc.file = m.file_of(side == 0 ? si.slave_file : si.master_file, s);
        if (s < lines.size()) loc.line = lines[s];
        loc.card = "sliding interface " + std::to_string(i + 1) + (side == 0 ? " slave" : " master") +
                   " segment " + std::to_string(s + 1);
        const std::string nodes = "nodes " + std::to_string(m.node_id(segs[s][0])) + " " + std::to_string(m.node_id(segs[s][1])) +
                                  " " + std::to_string(m.node_id(segs[s][2])) + " " + std::to_string(m.node_id(segs[s][3]));
        const std::vector<int> reversed(given.rbegin(), given.rend());
        if (same_cycle(reversed, out)) {
          const auto g = segs[s];
          segs[s] = {g[0], g[3], g[2], g[1]};
          diag.add(2013, loc, nodes);
        } else {
          diag.add(1225, loc, nodes);
        }
      }
    }
  }
}

// Shells: nodes and materials they use, a positive area and thickness each (1240, 1241).
void check_shells(const Model& m, const Location& file_loc, Diagnostics& diag,
                  std::vector<char>& node_used, std::vector<char>& mat_used) {
  for (int k = 0; k < m.num_shells(); ++k) {
    const auto& n = m.shell_nodes[std::size_t(k)];
    if (n[0] < 0) continue;  // already reported
    for (int j = 0; j < 4; ++j) node_used[std::size_t(n[std::size_t(j)])] = 1;
    const int mat = m.shell_material[std::size_t(k)];
    if (mat >= 0 && mat < int(mat_used.size())) mat_used[std::size_t(mat)] = 1;
    Location loc = file_loc;
    loc.file = m.file_of(m.shell_file, std::size_t(k));
    if (std::size_t(k) < m.shell_line.size()) loc.line = m.shell_line[std::size_t(k)];
    loc.card = "shell element " + std::to_string(m.shell_id(k));
    double x[4][3];
    for (int j = 0; j < 4; ++j) {
      const std::size_t i = std::size_t(n[std::size_t(j)]);
      x[j][0] = m.x[i];
      x[j][1] = m.y[i];
      x[j][2] = m.z[i];
    }
    ShellFrame fr;
    if (!calc_shell_frame(x, fr)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "area %.6g", fr.area);
      diag.add(1240, loc, buf);
    }
    const auto& t = m.shell_thickness[std::size_t(k)];
    const int nt = n[2] == n[3] ? 3 : 4;
    for (int j = 0; j < nt; ++j)
      if (!(t[std::size_t(j)] > 0)) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "thickness %.6g at node %d", t[std::size_t(j)], m.node_id(n[std::size_t(j)]));
        diag.add(1241, loc, buf);
        break;
      }
  }
}

// Beams: nodes and materials they use; a beam material with a beam kernel (1103), a known
// formulation and rule (1102), positive section sizes (1251), a length and an s axis (1250).
// Mass scaling does not scale beams (1102).
void check_beams(const Model& m, const Location& file_loc, Diagnostics& diag,
                 std::vector<char>& node_used, std::vector<char>& mat_used) {
  std::vector<char> section_checked(m.materials.size(), 0);
  for (int b = 0; b < m.num_beams(); ++b) {
    const auto& n = m.beam_nodes[std::size_t(b)];
    if (n[0] < 0 || n[1] < 0) continue;  // already reported
    for (int j = 0; j < 3; ++j)
      if (n[std::size_t(j)] >= 0) node_used[std::size_t(n[std::size_t(j)])] = 1;
    const int mat = m.beam_material[std::size_t(b)];
    if (mat < 0 || mat >= int(mat_used.size())) continue;
    mat_used[std::size_t(mat)] = 1;
    Location loc = file_loc;
    loc.file = m.file_of(m.beam_file, std::size_t(b));
    if (std::size_t(b) < m.beam_line.size()) loc.line = m.beam_line[std::size_t(b)];
    loc.card = "beam element " + std::to_string(m.beam_id(b));
    const MaterialData& md = m.materials[std::size_t(mat)];
    const BeamSectionData& sec = md.beam_section;
    if (!section_checked[std::size_t(mat)]) {
      section_checked[std::size_t(mat)] = 1;
      Location ml = file_loc;
      ml.line = sec.line ? sec.line : md.line;
      ml.card = "beam section of material " + std::to_string(md.number);
      if (!has_beam_kernel(md.type))
        diag.add(1103, ml, "material type " + std::to_string(md.type) + " has no beam form; beams take types " + beam_material_numbers());
      if (sec.elform < 1 || sec.elform > 3)
        diag.add(1102, ml, "ELFORM " + std::to_string(sec.elform) + ": beam formulations 1 (Hughes-Liu), 2 (Belytschko-Schwer) and 3 (truss) only");
      if (sec.spot_weld_beam && md.type != 100 && has_beam_kernel(md.type))
        diag.add(1103, ml, "material type " + std::to_string(md.type) + ": the spot-weld beam (ELFORM 9) takes *MAT_SPOTWELD (100)");
      if (sec.elform == 2 && md.type != 1 && has_beam_kernel(md.type) && !material_type(md.type).rigid)
        diag.add(1103, ml, "material type " + std::to_string(md.type) + ": the resultant beam (ELFORM 2) is elastic (type 1) or rigid (20)");
      if (sec.elform == 2 && (!(sec.area > 0) || !(sec.iss > 0) || !(sec.itt > 0) || sec.jt < 0)) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "A %.6g, ISS %.6g, ITT %.6g, J %.6g", sec.area, sec.iss, sec.itt, sec.jt);
        diag.add(1251, ml, buf);
      }
      std::vector<BeamRulePoint> rule;
      if (sec.elform == 1 && !beam_integration_rule(sec, rule))
        diag.add(1102, ml, "QR " + std::to_string(sec.qr) + ": rules 1-5" + std::string(sec.cst == BeamCrossSection::tubular ? " for tubes" : " or a user rule"));
      if (sec.elform == 3 && !(sec.area > 0)) diag.add(1251, ml, "truss area A " + std::to_string(sec.area));
      if (m.control.mass_scaling_dt != 0) diag.add(1102, ml, "mass scaling (DT2MS) of beams");
    }
    if (sec.elform == 1) {
      const BeamSectionSize sz = beam_section_size(m, b);
      const bool tube = sz.cst == BeamCrossSection::tubular;
      if (!(sz.ts > 0) || !(tube ? sz.tt >= 0 && sz.tt < sz.ts : sz.tt > 0)) {
        char buf[96];
        std::snprintf(buf, sizeof buf, tube ? "outer diameter %.6g, inner %.6g" : "TS %.6g, TT %.6g", sz.ts, sz.tt);
        diag.add(1251, loc, buf);
      }
    }
    double s[3];
    if (!beam_initial_s_axis(m, b, s))
      diag.add(1250, loc, "nodes " + std::to_string(m.node_id(n[0])) + " " + std::to_string(m.node_id(n[1])) +
                              (n[2] >= 0 ? " " + std::to_string(m.node_id(n[2])) : std::string()));
  }
}

// Spot welds: each node in one weld at most and on no rigid body (1253), some mass (1254), a
// normal direction at each node (1252: coincident nodes need CID).  node_used: nodes that
// elements use.
// Per node the rigid material whose elements use it (-1: none).
std::vector<int> rigid_material_of_nodes(const Model& m) {
  const std::size_t nn = std::size_t(m.num_nodes());
  std::vector<int> rigid_mat(nn, -1);
  auto is_rigid = [&](int mat) {
    if (mat < 0 || std::size_t(mat) >= m.materials.size()) return false;
    const MaterialType* t = find_material_type(m.materials[std::size_t(mat)].type);
    return t && t->rigid;
  };
  for (int e = 0; e < m.num_hexes(); ++e)
    if (m.hex_nodes[std::size_t(e)][0] >= 0 && is_rigid(m.hex_material[std::size_t(e)]))
      for (int n : m.hex_nodes[std::size_t(e)]) rigid_mat[std::size_t(n)] = m.hex_material[std::size_t(e)];
  for (int k = 0; k < m.num_shells(); ++k)
    if (m.shell_nodes[std::size_t(k)][0] >= 0 && is_rigid(m.shell_material[std::size_t(k)]))
      for (int n : m.shell_nodes[std::size_t(k)]) rigid_mat[std::size_t(n)] = m.shell_material[std::size_t(k)];
  for (int b = 0; b < m.num_beams(); ++b)
    if (m.beam_nodes[std::size_t(b)][0] >= 0 && is_rigid(m.beam_material[std::size_t(b)]))
      for (int j = 0; j < 2; ++j) rigid_mat[std::size_t(m.beam_nodes[std::size_t(b)][std::size_t(j)])] = m.beam_material[std::size_t(b)];
  return rigid_mat;
}

void check_spot_welds(const Model& m, const Location& file_loc, Diagnostics& diag, const std::vector<char>& node_used) {
  if (m.spot_welds.empty()) return;
  const std::size_t nn = std::size_t(m.num_nodes());
  const std::vector<int> rigid_mat = rigid_material_of_nodes(m);  // nodes of rigid bodies
  // the model's size: coincidence is within 1e-9 of it
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < nn; ++i) {
    const double p[3] = {m.x[i], m.y[i], m.z[i]};
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  const double size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  std::vector<int> weld_of(nn, -1);
  for (std::size_t w = 0; w < m.spot_welds.size(); ++w) {
    const SpotWeld& sw = m.spot_welds[w];
    Location loc = file_loc;
    if (sw.file >= 0 && std::size_t(sw.file) < m.source_files.size()) loc.file = m.source_files[std::size_t(sw.file)];
    loc.line = sw.line;
    loc.card = std::string(sw.generalized ? "*CONSTRAINED_GENERALIZED_WELD_SPOT" : "*CONSTRAINED_SPOTWELD") +
               (sw.id ? " WID " + std::to_string(sw.id) : "");
    bool mass = false;
    double c[3] = {0, 0, 0};
    for (int n : sw.nodes) {
      const std::size_t k = std::size_t(n);
      mass = mass || node_used[k];
      if (rigid_mat[k] >= 0)
        diag.add(1253, loc, "node " + std::to_string(m.node_id(n)) + " is on the rigid body of material " +
                                std::to_string(m.materials[std::size_t(rigid_mat[k])].number));
      else if (weld_of[k] >= 0)
        diag.add(1253, loc, "node " + std::to_string(m.node_id(n)) + " is also in the weld at line " +
                                std::to_string(m.spot_welds[std::size_t(weld_of[k])].line));
      else
        weld_of[k] = int(w);
      c[0] += m.x[k] / double(sw.nodes.size());
      c[1] += m.y[k] / double(sw.nodes.size());
      c[2] += m.z[k] / double(sw.nodes.size());
    }
    if (!mass) diag.add(1254, loc, "nodes " + std::to_string(m.node_id(sw.nodes[0])) + " ...");
    if (!sw.has_axis && (sw.sn > 0 || sw.ss > 0))  // the failure rule needs the normal
      for (int n : sw.nodes) {
        const std::size_t k = std::size_t(n);
        const double d = std::sqrt((m.x[k] - c[0]) * (m.x[k] - c[0]) + (m.y[k] - c[1]) * (m.y[k] - c[1]) + (m.z[k] - c[2]) * (m.z[k] - c[2]));
        if (!(d > 1e-9 * size)) {
          diag.add(1252, loc, "node " + std::to_string(m.node_id(n)) + " lies at the centre of the weld's nodes (give CID, whose local z axis is then the normal)");
          break;
        }
      }
  }
  // a prescribed motion on a welded node (the weld moves it as a rigid body)
  for (const PrescribedMotion& pm : m.prescribed_motions)
    if (pm.node >= 0 && weld_of[std::size_t(pm.node)] >= 0) {
      Location loc = file_loc;
      loc.line = pm.line;
      loc.card = "prescribed motion";
      diag.add(1226, loc, "node " + std::to_string(m.node_id(pm.node)) + " is in the spot weld at line " +
                              std::to_string(m.spot_welds[std::size_t(weld_of[std::size_t(pm.node)])].line));
    }
}

// Tied contacts (Model::node_ties): a slave node tied once, not itself a master node of a tie,
// without SPC or prescribed motion; no tied node (slave or master) on a rigid body or in a spot
// weld (error 1256).
void check_node_ties(const Model& m, const Location& file_loc, Diagnostics& diag) {
  if (m.node_ties.empty()) return;
  const std::size_t nn = std::size_t(m.num_nodes());
  const std::vector<int> rigid_mat = rigid_material_of_nodes(m);
  std::vector<char> welded(nn, 0), master(nn, 0), motion(nn, 0);
  std::vector<int> tie_of(nn, -1);
  for (const SpotWeld& w : m.spot_welds)
    for (int n : w.nodes) welded[std::size_t(n)] = 1;
  for (const NodeTie& t : m.node_ties)
    for (int n : t.seg) master[std::size_t(n)] = 1;
  for (const PrescribedMotion& pm : m.prescribed_motions)
    if (pm.node >= 0) motion[std::size_t(pm.node)] = 1;
  for (std::size_t i = 0; i < m.node_ties.size(); ++i) {
    const NodeTie& t = m.node_ties[i];
    const TiedContact& tc = m.tied_contacts[std::size_t(t.contact)];
    Location loc = file_loc;
    loc.line = tc.line;
    loc.card = (tc.keyword.empty() ? std::string(tc.spotweld ? "*CONTACT_SPOTWELD" : "*CONTACT_TIED_NODES_TO_SURFACE") : "*" + tc.keyword) +
               (tc.id ? " " + std::to_string(tc.id) : "");
    const std::size_t k = std::size_t(t.node);
    const std::string node = "slave node " + std::to_string(m.node_id(t.node));
    if (tie_of[k] >= 0)
      diag.add(1256, loc, node + " is tied twice (also by the tied contact at line " +
                              std::to_string(m.tied_contacts[std::size_t(m.node_ties[std::size_t(tie_of[k])].contact)].line) + ")");
    else if (master[k])
      diag.add(1256, loc, node + " is also a node of a master segment of a tie");
    else if (m.bc[k] != 0 || motion[k])
      diag.add(1256, loc, node + " has a " + std::string(motion[k] ? "prescribed motion" : "displacement constraint (SPC)") +
                              ": it moves with its master segment");
    tie_of[k] = int(i);
    for (int n : {t.node, t.seg[0], t.seg[1], t.seg[2], t.seg[3]}) {
      const std::size_t q = std::size_t(n);
      if (rigid_mat[q] < 0 && !welded[q]) continue;
      diag.add(1256, loc, "node " + std::to_string(m.node_id(n)) + (n == t.node ? " (slave)" : " (of the master segment)") +
                              (welded[q] ? " is in a spot weld" : " is on the rigid body of material " +
                                                                    std::to_string(m.materials[std::size_t(rigid_mat[q])].number)));
      break;
    }
  }
}

namespace {
// Warning 2014 for each rigid material whose nodes were given velocities (after the constraints
// have zeroed theirs, as at the start of the run) that no rigid motion v = a + w x r matches.
void check_rigid_velocities(const Model& m, Diagnostics& diag, const Location& file_loc) {
  const std::size_t nn = std::size_t(m.num_nodes());
  std::vector<std::array<double, 3>> v(nn, {0.0, 0.0, 0.0});
  for (const auto& iv : m.init_velocities) {
    if (iv.first == 0) {
      std::fill(v.begin(), v.end(), iv.v);
    } else if (iv.increment > 0) {
      for (int n = iv.first; n <= iv.last; n += iv.increment)
        if (n >= 1 && std::size_t(n) <= nn) v[std::size_t(n - 1)] = iv.v;
    }
  }
  for (std::size_t i = 0; i < nn && i < m.bc.size(); ++i) {
    const int c = m.bc[i];
    if (bc_fixes_x(c)) v[i][0] = 0;
    if (bc_fixes_y(c)) v[i][1] = 0;
    if (bc_fixes_z(c)) v[i][2] = 0;
  }
  for (std::size_t k = 0; k < m.materials.size(); ++k) {
    const MaterialType* t = find_material_type(m.materials[k].type);
    if (!t || !t->rigid) continue;
    std::vector<int> nodes;
    for (int e = 0; e < m.num_hexes(); ++e) {
      const auto& n = m.hex_nodes[std::size_t(e)];
      if (n[0] < 0 || m.hex_material[std::size_t(e)] != int(k)) continue;
      for (int j = 0; j < 8; ++j) nodes.push_back(n[std::size_t(j)]);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (nodes.size() < 2) continue;
    // least-squares rigid motion with equal weights (a rigid field fits exactly whatever the
    // weights): mean velocity, then w from the "inertia" and "angular momentum" about the centroid
    const double cnt = double(nodes.size());
    std::array<double, 3> c{}, vb{};
    double vmax = 0;
    for (int n : nodes) {
      const std::size_t i = std::size_t(n);
      c[0] += m.x[i] / cnt; c[1] += m.y[i] / cnt; c[2] += m.z[i] / cnt;
      for (int a = 0; a < 3; ++a) vb[std::size_t(a)] += v[i][std::size_t(a)] / cnt;
      vmax = std::max(vmax, std::sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]));
    }
    if (!(vmax > 0)) continue;
    double I[3][3] = {}, L[3] = {};
    for (int n : nodes) {
      const std::size_t i = std::size_t(n);
      const double r[3] = {m.x[i] - c[0], m.y[i] - c[1], m.z[i] - c[2]};
      const double u[3] = {v[i][0] - vb[0], v[i][1] - vb[1], v[i][2] - vb[2]};
      const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) I[a][b] += (a == b ? rr : 0) - r[a] * r[b];
      L[0] += r[1] * u[2] - r[2] * u[1];
      L[1] += r[2] * u[0] - r[0] * u[2];
      L[2] += r[0] * u[1] - r[1] * u[0];
    }
    // w = I^-1 L by Cramer's rule; a body on a line (singular I) is fitted by translation alone
    const double det = I[0][0] * (I[1][1] * I[2][2] - I[1][2] * I[2][1]) - I[0][1] * (I[1][0] * I[2][2] - I[1][2] * I[2][0]) +
                       I[0][2] * (I[1][0] * I[2][1] - I[1][1] * I[2][0]);
    const double tr = I[0][0] + I[1][1] + I[2][2];
    double w[3] = {0, 0, 0};
    if (std::abs(det) > 1e-12 * tr * tr * tr) {
      for (int col = 0; col < 3; ++col) {
        double A[3][3];
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) A[a][b] = b == col ? L[a] : I[a][b];
        w[col] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                  A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
      }
    }
    double dmax = 0;
    int worst = nodes[0];
    for (int n : nodes) {
      const std::size_t i = std::size_t(n);
      const double r[3] = {m.x[i] - c[0], m.y[i] - c[1], m.z[i] - c[2]};
      const double d[3] = {v[i][0] - vb[0] - (w[1] * r[2] - w[2] * r[1]), v[i][1] - vb[1] - (w[2] * r[0] - w[0] * r[2]),
                           v[i][2] - vb[2] - (w[0] * r[1] - w[1] * r[0])};
      const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (dn > dmax) { dmax = dn; worst = n; }
    }
    if (dmax > 1e-6 * vmax) {
      Location loc = file_loc;
      loc.line = m.materials[k].line;
      loc.card = "material " + std::to_string(k + 1);
      char buf[160];
      std::snprintf(buf, sizeof buf, "node %d differs from the rigid motion by %.4g (largest given speed %.4g)",
                    m.node_id(worst), dmax, vmax);
      diag.add(2014, loc, buf);
    }
  }
}
}  // namespace

// Curve references of material parameters (ParamCheck::curve): the curve exists, and a flow
// stress curve (plastic strain -> stress) does not soften.
void check_material_curves(const Model& m, Diagnostics& diag, const Location& file_loc) {
  for (const MaterialData& md : m.materials) {
    const MaterialType* t = find_material_type(md.type);
    if (!t) continue;
    if (const int lc = eos_curve(md.eos); lc > 0) {  // an EOS's energy deposition rate (form 6)
      Location loc = file_loc;
      loc.line = md.line;
      loc.card = "material " + std::to_string(md.number) + " EOS";
      loc.field = "LCID";
      const LoadCurve* c = nullptr;
      for (const LoadCurve& l : m.load_curves)
        if (l.number == lc) c = &l;
      if (!c) {
        diag.add(1310, loc, "load curve " + std::to_string(lc) + " is not defined");
      } else {
        for (double f : c->f)
          if (f < 0) {
            diag.add(1003, loc, "the energy deposition rate must not be negative (LS-DYNA: a leak goes through the EOS constants, e.g. C4 < 0)");
            break;
          }
      }
    }
    for (const MaterialParam& p : t->params) {
      if (p.check != ParamCheck::curve) continue;
      const int lc = int(param_value(md, p));
      if (lc == 0) continue;
      Location loc = file_loc;
      loc.line = md.line;
      loc.card = "material " + std::to_string(md.number);
      loc.field = p.fname ? p.fname : p.key;
      if (lc < 0 || std::size_t(lc) > m.load_curves.size()) {
        diag.add(1310, loc, "load curve " + std::to_string(lc) + " is not defined");
        continue;
      }
      const LoadCurve& c = m.load_curves[std::size_t(lc - 1)];
      for (std::size_t i = 0; i < c.t.size(); ++i)
        if (c.t[i] < 0 || c.f[i] < 0 || (i > 0 && c.f[i] < c.f[i - 1])) {
          diag.add(1003, loc, "the flow stress curve must have plastic strains >= 0 and stresses >= 0 that do not decrease (no softening)");
          break;
        }
    }
  }
}

// Fully integrated solids (ELFORM 2, element/hex_sri.h): each Gauss point runs the type's
// scalar point update; an equation of state (a pressure from the element's energy and volume)
// is not served per point.
void check_solid_formulations(const Model& m, const Location& file_loc, Diagnostics& diag,
                              const std::vector<char>& mat_used) {
  for (std::size_t k = 0; k < m.materials.size(); ++k) {
    const MaterialData& md = m.materials[k];
    if (md.solid_elform != 2 || md.shell || md.beam || !mat_used[k]) continue;
    Location loc = file_loc;
    loc.line = md.line;
    loc.card = "material " + std::to_string(md.number);
    const MaterialType* t = find_material_type(md.type);
    if (!t) continue;  // refused when read
    if (md.eos.form != 0 || t->needs_eos)
      diag.add(1102, loc, "an equation of state on fully integrated solids (*SECTION_SOLID ELFORM 2); use ELFORM 1");
    else if (!t->rigid && !t->solid.update_point)
      diag.add(1103, loc, "material type " + std::to_string(md.type) + " on fully integrated solids (*SECTION_SOLID ELFORM 2): it has no point update; use ELFORM 1");
  }
}

namespace {

// Error 1206 for each solid whose initial volume is not positive (solids with an undefined node
// are reported elsewhere).
void check_solid_volumes(const Model& m, const Location& file_loc, Diagnostics& diag) {
  for (int e = 0; e < m.num_hexes(); ++e) {
    const auto& n = m.hex_nodes[std::size_t(e)];
    if (n[0] < 0) continue;  // already reported
    double x[8], y[8], z[8];
    bool defined = true;
    for (int j = 0; j < 8; ++j) {
      x[j] = m.x[std::size_t(n[std::size_t(j)])];
      y[j] = m.y[std::size_t(n[std::size_t(j)])];
      z[j] = m.z[std::size_t(n[std::size_t(j)])];
      defined = defined && std::isfinite(x[j]) && std::isfinite(y[j]) && std::isfinite(z[j]);
    }
    if (!defined) continue;  // uses a node that was never defined (reported as 1204)
    const double v = calc_hex_volume(x, y, z);
    if (v > 0) continue;
    Location loc = file_loc;
    loc.file = m.file_of(m.hex_file, std::size_t(e));
    if (std::size_t(e) < m.hex_line.size()) loc.line = m.hex_line[std::size_t(e)];
    loc.card = "solid element " + std::to_string(m.hex_id(e));
    char buf[64];
    std::snprintf(buf, sizeof buf, "volume %.6g", v);
    diag.add(1206, loc, buf);
  }
}

// The nodes and materials the solids use.
void mark_solids_use(const Model& m, std::vector<char>& node_used, std::vector<char>& mat_used) {
  for (int e = 0; e < m.num_hexes(); ++e) {
    const auto& n = m.hex_nodes[std::size_t(e)];
    if (n[0] < 0) continue;
    for (int j = 0; j < 8; ++j) node_used[std::size_t(n[std::size_t(j)])] = 1;
    const int mat = m.hex_material[std::size_t(e)];
    if (mat >= 0 && mat < int(mat_used.size())) mat_used[std::size_t(mat)] = 1;
  }
}

// *MAT_SPOTWELD on solids: TFAIL is a beam rule here.
void check_spot_weld_solids(const Model& m, const Location& file_loc, Diagnostics& diag, const std::vector<char>& mat_used) {
  for (std::size_t k = 0; k < m.materials.size(); ++k) {
    const MaterialData& md = m.materials[k];
    if (md.type != 100 || md.beam || md.shell || !mat_used[k]) continue;
    const MaterialParam* p = find_param(material_type(100), "TFAIL");
    if (!p || !(param_value(md, *p) > 0)) continue;
    Location loc = file_loc;
    loc.line = md.line;
    loc.card = "material " + std::to_string(md.number);
    diag.add(1102, loc, "TFAIL of *MAT_SPOTWELD solids (the failure time acts on spot-weld beams)");
  }
}

// Warnings 2002 (a material no element uses) and 2003 (nodes no solid, shell or beam uses; the
// first ten named), the latter only for models with solids.
void report_unused(const Model& m, const Location& file_loc, Diagnostics& diag, const std::vector<char>& node_used,
                   const std::vector<char>& mat_used) {
  for (std::size_t k = 0; k < mat_used.size(); ++k) {
    if (!mat_used[k] && m.materials[k].number != 0) {
      Location loc = file_loc;
      loc.line = m.materials[k].line;
      loc.card = "material " + std::to_string(k + 1);
      diag.add(2002, loc);
    }
  }
  int unused_nodes = 0;
  std::string first_unused;
  for (std::size_t k = 0; k < node_used.size(); ++k) {
    if (!node_used[k]) {
      if (unused_nodes < 10) first_unused += (unused_nodes ? ", " : "") + std::to_string(m.node_id(int(k)));
      ++unused_nodes;
    }
  }
  if (unused_nodes && m.num_hexes() > 0)
    diag.add(2003, file_loc, std::to_string(unused_nodes) + " node(s): " + first_unused + (unused_nodes > 10 ? ", ..." : ""));
}

// The interface segments' keys, each true when it is a solid's face or a shell (either side).
std::unordered_map<std::array<int, 4>, bool, FaceKeyHash> find_interface_faces(const Model& m) {
  std::unordered_map<std::array<int, 4>, bool, FaceKeyHash> faces;
  if (!has_interface_segments(m)) return faces;
  for (const auto& si : m.interfaces)
    for (const auto* segs : {&si.slave, &si.master})
      for (const auto& seg : *segs) faces.try_emplace(face_key(seg), false);
  for_each_element_face(m, [&](const std::array<int, 4>& key, const std::array<int, 4>&) {
    auto it = faces.find(key);
    if (it != faces.end()) it->second = true;
  });
  for (const auto& sn : m.shell_nodes) {
    if (sn[0] < 0) continue;
    auto it = faces.find(face_key(sn));
    if (it != faces.end()) it->second = true;
  }
  return faces;
}

// Error 1218 for each interface segment that is no element face.
void check_interface_segments_are_faces(const Model& m, const Location& file_loc, Diagnostics& diag) {
  auto faces = find_interface_faces(m);
  for (std::size_t i = 0; i < m.interfaces.size(); ++i) {
    const auto& si = m.interfaces[i];
    for (int side = 0; side < 2; ++side) {
      const auto& segs = side == 0 ? si.slave : si.master;
      const auto& lines = side == 0 ? si.slave_line : si.master_line;
      for (std::size_t s = 0; s < segs.size(); ++s) {
        if (faces[face_key(segs[s])]) continue;
        Location loc = file_loc;
        loc.file = m.file_of(side == 0 ? si.slave_file : si.master_file, s);
        if (s < lines.size()) loc.line = lines[s];
        loc.card = "sliding interface " + std::to_string(i + 1) + (side == 0 ? " slave" : " master") + " segment " +
                   std::to_string(s + 1);
        diag.add(1218, loc, "nodes " + std::to_string(m.node_id(segs[s][0])) + " " + std::to_string(m.node_id(segs[s][1])) + " " +
                                std::to_string(m.node_id(segs[s][2])) + " " + std::to_string(m.node_id(segs[s][3])));
      }
    }
  }
}

// Stonewalls act on deformable nodes only (the rigid-body update would overwrite the impulse of
// a single node): warning 2012 when the two meet. Initial velocities on the nodes of a rigid
// body: the run gives the body the momentum and angular momentum of the nodal velocities and
// starts its nodes with that rigid motion (initialize.cpp); say so when the nodal velocities
// were not already a rigid motion.
void check_rigid_bodies(const Model& m, const Location& file_loc, Diagnostics& diag) {
  bool has_rigid = false;
  for (const auto& md : m.materials) {
    const MaterialType* t = find_material_type(md.type);
    has_rigid = has_rigid || (t && t->rigid);
  }
  if (!has_rigid) return;
  if (!m.walls.empty()) {
    Location loc = file_loc;
    loc.line = m.walls[0].line;
    loc.card = "stonewall 1";
    diag.add(2012, loc);
  }
  if (!m.init_velocities.empty()) check_rigid_velocities(m, diag, file_loc);
}

}  // namespace

bool check_model(const Model& m, Diagnostics& diag) {
  const int before = diag.error_count();
  Location file_loc;
  file_loc.file = m.deck_file;
  check_solid_volumes(m, file_loc, diag);
  std::vector<char> node_used(std::size_t(m.num_nodes()), 0);
  std::vector<char> mat_used(m.materials.size(), 0);
  mark_solids_use(m, node_used, mat_used);
  check_shells(m, file_loc, diag, node_used, mat_used);
  check_beams(m, file_loc, diag, node_used, mat_used);
  check_spot_welds(m, file_loc, diag, node_used);
  check_node_ties(m, file_loc, diag);
  check_solid_formulations(m, file_loc, diag, mat_used);
  check_spot_weld_solids(m, file_loc, diag, mat_used);
  report_unused(m, file_loc, diag, node_used, mat_used);
  check_material_curves(m, diag, file_loc);
  check_rigid_bodies(m, file_loc, diag);
  check_interface_segments_are_faces(m, file_loc, diag);
  return diag.error_count() == before;
}

bool read_and_check_deck(const std::string& path, Model& model, Diagnostics& diag) {
  return read_and_check_deck(path, model, diag, InputOptions{});
}

bool read_and_check_deck(const std::string& path, Model& model, Diagnostics& diag,
                         const InputOptions& options) {
  DeckFile deck;
  if (!deck.load(path, diag)) return false;
  bool ok = read_deck(deck, model, diag, options);  // fixed format or keyword, by content
  // Cross checks only make sense when the arrays are complete; they still run when only
  // field-level errors occurred, so that all problems are reported in one pass.
  if (model.num_nodes() == model.control.numnp && model.num_hexes() == model.control.numelh &&
      !diag.has(1004) && !diag.has(1013)) {
    orient_interface_segments(model, diag);
    ok = check_model(model, diag) && ok && !diag.has(1225);
  }
  return ok && diag.error_count() == 0;
}

}  // namespace impact3d
