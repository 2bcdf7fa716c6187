// Keyword decks, the loads' and boundary conditions' resolve steps: curves, loads, prescribed
// motions and damping, constraints (*BOUNDARY_SPC, *CONSTRAINED_GLOBAL, *NODE RC; timed ones
// as zero-velocity motions), spot welds, rigid walls, initial velocities and temperatures into
// the Model.  The records are read by keyword_loads_bcs.cpp; KeywordReader::resolve
// (keyword_reader.cpp) runs the steps in its order (ResolveContext, keyword_resolve.h).

#include "impact3d/input/keyword_resolve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace impact3d::kw {

// Fixed translational components (bit 0 x, bit 1 y, bit 2 z) -> boundary code 0-7 (bc_bits).
static int bc_code(int bits) {
  static const int code[8] = {0, 1, 2, 4, 3, 6, 5, 7};  // index = bits: x=1, y=2, z=4
  return code[bits & 7];
}

// the family's own steps
static int global_spc_bits(ResolveContext& rc, const RSpc& s);
static std::vector<int> spc_nodes(ResolveContext& rc, const RSpc& s);
static double shortest_edge(ResolveContext& rc);
static void resolve_constrained_global(ResolveContext& rc);
static bool node_has_rotations(ResolveContext& rc, int n);
static void add_rotational_constraints(ResolveContext& rc, const std::vector<int>& nodes, int bits, const Ref& r);
static void report_unused_curves(ResolveContext& rc);
static int curve_of(ResolveContext& rc, const RLoad& l);
static std::array<double, 3> axis_direction(int dof);
static std::vector<int> load_nodes(ResolveContext& rc, const RLoad& l, bool set, const char* field);
static int rigid_material_of_part(ResolveContext& rc, const RLoad& l);
static bool load_direction(ResolveContext& rc, const RLoad& l, std::array<double, 3>& d);
static void resolve_damping(ResolveContext& rc);
static void add_velocity_nodes(ResolveContext& rc, const std::vector<int>& nodes, const std::array<double, 3>& v);
static void add_generated_velocities(ResolveContext& rc, const std::vector<int>& nodes, const RVelocity& v);
static void add_restricted_velocities(ResolveContext& rc, const RVelocity& v);
static void set_rotational_velocities(ResolveContext& rc, const std::vector<int>& nodes, const RVelocity& v);

void resolve_temperatures(ResolveContext& rc) {
  if (rc.ld.temperatures.empty()) return;
  rc.m.node_temperature.assign(std::size_t(rc.m.num_nodes()), std::nan(""));
  for (const RTemperature& t : rc.ld.temperatures) {
    const char* kw = t.set ? "*INITIAL_TEMPERATURE_SET" : "*INITIAL_TEMPERATURE_NODE";
    std::vector<int> nodes;
    if (!t.set) {
      const int idx = rc.node_index(t.id);
      if (idx < 0) {
        rc.err(1202, t.ref, kw, "NID", "node " + std::to_string(t.id) + " is not defined by *NODE");
        continue;
      }
      nodes = {idx};
    } else if (t.id == 0) {
      for (int i = 0; i < rc.m.num_nodes(); ++i) nodes.push_back(i);
    } else if (const RIdList* s = find_node_set(rc, t.id, t.ref, kw, "NSID")) {
      nodes = set_nodes(rc, *s, "*SET_NODE " + std::to_string(t.id));
    }
    for (int n : nodes) rc.m.node_temperature[std::size_t(n)] = t.temp;
  }
}

// The fixed directions (bits x=1, y=2, z=4) of a *BOUNDARY_SPC in the global system: a local
// system whose axes are global axes maps each fixed local direction onto its global axis;
// one with skew axes is not supported unless all or none of the directions are fixed.
int global_spc_bits(ResolveContext& rc, const RSpc& s) {
  if (s.cid == 0 || s.bits == 0 || s.bits == 7) return s.bits;
  const CoordinateSystem* cs = rc.coords.system(s.cid);
  if (!cs) {
    rc.err(1310, s.cid_ref, s.keyword, "CID", "coordinate system " + std::to_string(s.cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
    return 0;
  }
  std::array<int, 3> axis{}, sign{};
  if (!cs->axis_aligned(axis, sign)) {
    rc.err(1102, s.cid_ref, s.keyword, "CID", "constraints along skew local axes (the axes of system " + std::to_string(s.cid) + " are not the global ones)");
    return 0;
  }
  int bits = 0;
  for (int i = 0; i < 3; ++i)
    if (s.bits & (1 << i)) bits |= 1 << axis[std::size_t(i)];
  return bits;
}

// The nodes of a *BOUNDARY_SPC card (its NID or NSID).
std::vector<int> spc_nodes(ResolveContext& rc, const RSpc& s) {
  std::vector<int> nodes;
  const std::string& card = s.keyword;
  if (s.set) {
    if (const RIdList* set = find_node_set(rc, s.id, s.ref, card, "NSID")) nodes = set_nodes(rc, *set, card);
  } else {
    int idx = rc.node_index(s.id);
    if (idx < 0) rc.err(1202, s.ref, card, "NID", "node " + std::to_string(s.id) + " is not defined by *NODE");
    else nodes.push_back(idx);
  }
  return nodes;
}

// The shortest element edge of the model (solids, shells, beams; 0 when there is none).
double shortest_edge(ResolveContext& rc) {
  double h2 = std::numeric_limits<double>::infinity();
  auto edge = [&](int a, int b) {
    if (a < 0 || b < 0 || a == b) return;
    const std::size_t i = std::size_t(a), j = std::size_t(b);
    const double dx = rc.m.x[i] - rc.m.x[j], dy = rc.m.y[i] - rc.m.y[j], dz = rc.m.z[i] - rc.m.z[j];
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 > 0) h2 = std::min(h2, d2);
  };
  static const int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& n : rc.m.hex_nodes)
    for (const auto& e : hex_edges) edge(n[std::size_t(e[0])], n[std::size_t(e[1])]);
  for (const auto& n : rc.m.shell_nodes)
    for (std::size_t k = 0; k < 4; ++k) edge(n[k], n[(k + 1) % 4]);
  for (const auto& n : rc.m.beam_nodes) edge(n[0], n[1]);
  return std::isfinite(h2) ? std::sqrt(h2) : 0.0;
}

// *CONSTRAINED_GLOBAL: every node within TOL of the plane (TOL 0: 1e-3 of the shortest
// element edge) takes the plane's translational code; nodes with rotations (shells', beams')
// also its rotational one (solid nodes have no rotations: RC means nothing for them).
void resolve_constrained_global(ResolveContext& rc) {
  if (rc.ld.globals.empty()) return;
  const double h = shortest_edge(rc);
  for (const RGlobalConstraint& g : rc.ld.globals) {
    if (g.dir < 1 || g.dir > 3) continue;  // (reported)
    const double tol = g.tol > 0 ? g.tol : 1e-3 * h;
    const std::vector<double>& c = g.dir == 1 ? rc.m.x : g.dir == 2 ? rc.m.y : rc.m.z;
    const int bits = bc_bits(g.tc);
    std::vector<int> rot_nodes;
    for (int n = 0; n < rc.m.num_nodes(); ++n) {
      if (!(std::fabs(c[std::size_t(n)] - g.at) <= tol)) continue;
      rc.m.bc[std::size_t(n)] = bc_code(bc_bits(rc.m.bc[std::size_t(n)]) | bits);
      if (g.rc != 0 && node_has_rotations(rc, n)) rot_nodes.push_back(n);
    }
    if (!rot_nodes.empty()) add_rotational_constraints(rc, rot_nodes, bc_bits(g.rc), g.ref);
  }
}

// *BOUNDARY_SPC_..._BIRTH_DEATH: each fixed direction of each node becomes a prescribed zero
// velocity (a rotational one for rotations of nodes that have them) from BIRTH to DEATH, on a
// zero curve added after the deck's curves (as LS-DYNA's manual writes the same constraint).
void resolve_timed_spc(ResolveContext& rc) {
  int zero = -1, no_rotations = 0;
  Ref no_rotations_ref;
  for (const RSpc& s : rc.ld.spcs) {
    if (!s.birth_death) continue;
    const std::vector<int> nodes = spc_nodes(rc, s);
    const int line = s.ref.line ? s.ref.line->number : 0;
    for (int f = 0; f < 6; ++f) {
      if (!((f < 3 ? s.bits : s.rbits) & (1 << (f % 3)))) continue;
      std::array<double, 3> d{};
      d[std::size_t(f % 3)] = 1;
      if (s.cid != 0 && !rc.coords.to_global_direction(s.cid, d, d)) {
        rc.err(1310, s.cid_ref, s.keyword, "CID", "coordinate system " + std::to_string(s.cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
        return;
      }
      if (zero < 0) {
        LoadCurve lc;
        lc.number = int(rc.m.load_curves.size()) + 1;
        lc.t = {0.0, 1.0};
        lc.f = {0.0, 0.0};
        rc.m.load_curves.push_back(std::move(lc));
        rc.m.control.numlc = int(rc.m.load_curves.size());
        zero = int(rc.m.load_curves.size()) - 1;
      }
      for (int n : nodes) {
        if (f >= 3 && !node_has_rotations(rc, n)) {
          if (no_rotations++ == 0) no_rotations_ref = s.ref;
          continue;
        }
        PrescribedMotion pm;
        pm.node = n;
        pm.dir = d;
        pm.kind = MotionKind::velocity;
        pm.rotation = f >= 3;
        pm.curve = zero;
        pm.scale = 1;
        pm.birth = s.birth;
        pm.death = s.death;
        pm.line = line;
        rc.m.prescribed_motions.push_back(pm);
      }
    }
  }
  if (no_rotations)
    rc.diag.add(2005, loc_of(no_rotations_ref, "", nullptr, false), std::to_string(no_rotations) + " rotational constraint(s) (*BOUNDARY_SPC_..._BIRTH_DEATH DOFR*)");
}

void resolve_spc(ResolveContext& rc) {
  resolve_constrained_global(rc);
  for (const RSpc& s : rc.ld.spcs) {
    if (s.birth_death) continue;  // resolve_timed_spc
    std::vector<int> nodes = spc_nodes(rc, s);
    const int bits = global_spc_bits(rc, s);
    for (int n : nodes) rc.m.bc[std::size_t(n)] = bc_code(bc_bits(rc.m.bc[std::size_t(n)]) | bits);
    if (s.rbits) add_rotational_constraints(rc, nodes, s.rbits, s.ref);
  }
  for (const auto& [id, bits] : rc.me.node_rc) {
    const int idx = rc.node_index(id);
    if (idx >= 0) add_rotational_constraints(rc, {idx}, bits, Ref{});
  }
  if (rc.rotational_spc) {
    Location loc = loc_of(rc.rotational_ref, "", nullptr, false);
    rc.diag.add(2005, loc, std::to_string(rc.rotational_spc) + " rotational constraint(s) (*NODE RC, *BOUNDARY_SPC DOFR*)");
  }
}

// Spot welds: their nodes (N1 N2, or the set's) and the normal axis of CID.
void resolve_spot_welds(ResolveContext& rc) {
  for (const RWeld& r : rc.ld.welds) {
    SpotWeld w;
    const std::string& card = r.keyword;
    if (r.generalized) {
      if (const RIdList* set = find_node_set(rc, r.nsid, r.ref, card, "NSID")) w.nodes = set_nodes(rc, *set, card);
      else continue;
      std::vector<int> sorted = w.nodes;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) remove_repeated_nodes(w.nodes);
      if (w.nodes.size() < 2) {
        rc.err(1314, r.ref, card, "NSID", "a spot weld needs two nodes or more; set " + std::to_string(r.nsid) + " has " + std::to_string(w.nodes.size()));
        continue;
      }
    } else {
      bool ok = true;
      for (int j = 0; j < 2; ++j) {
        const int id = j == 0 ? r.n1 : r.n2;
        const int idx = rc.node_index(id);
        if (idx < 0) {
          rc.err(1202, j == 0 ? r.ref : r.ref2, card, j == 0 ? "N1" : "N2", "node " + std::to_string(id) + " is not defined by *NODE");
          ok = false;
        }
        w.nodes.push_back(idx);
      }
      if (!ok) continue;
      if (w.nodes[0] == w.nodes[1]) {
        Ref rr = r.ref;
        rr.c2 = r.ref2.c2;
        rc.err(1003, rr, card, "N1-N2", "N1 = N2: a weld joins two different nodes");
        continue;
      }
    }
    if (r.cid != 0) {
      std::array<double, 3> z = {0, 0, 1};
      if (!global_direction(rc, r.cid, r.cid_ref, card, "CID", z)) continue;
      w.has_axis = true;
      w.axis = z;
    }
    w.sn = r.sn;
    w.ss = r.ss;
    w.n = r.n;
    w.m = r.m;
    w.tfail = r.tfail > 0 ? r.tfail : 1e20;
    w.epsf = r.epsf;
    w.id = r.wid;
    w.generalized = r.generalized;
    w.line = r.ref.line ? r.ref.line->number : 0;
    w.file = rc.file_index(r.ref.file);
    rc.m.spot_welds.push_back(std::move(w));
  }
}

// Rotational constraints act on the nodes that shells use; on other nodes they are counted
// for warning 2005 (solids have no rotations).
bool node_has_rotations(ResolveContext& rc, int n) {
  add_rotational_constraints(rc, {}, 0, Ref{});  // marks rc.shell_node
  return rc.shell_node[std::size_t(n)] != 0;
}

void add_rotational_constraints(ResolveContext& rc, const std::vector<int>& nodes, int bits, const Ref& r) {
  if (rc.shell_node.empty()) {
    rc.shell_node.assign(std::size_t(rc.m.num_nodes()), 0);
    for (const auto& n : rc.m.shell_nodes)
      if (n[0] >= 0)
        for (int v : n) rc.shell_node[std::size_t(v)] = 1;
    for (const auto& n : rc.m.beam_nodes)  // beam ends have rotations too
      if (n[0] >= 0)
        for (int j = 0; j < 2; ++j) rc.shell_node[std::size_t(n[std::size_t(j)])] = 1;
  }
  if (nodes.empty()) return;
  if (rc.m.rot_bc.empty()) rc.m.rot_bc.assign(std::size_t(rc.m.num_nodes()), 0);
  for (int n : nodes) {
    if (rc.shell_node[std::size_t(n)]) rc.m.rot_bc[std::size_t(n)] |= std::uint8_t(bits);
    else if (rc.rotational_spc++ == 0) rc.rotational_ref = r;
  }
}

void resolve_curves(ResolveContext& rc) {
  // renumbered 1..NUMLC in deck order (the fixed format needs 1..NUMLC)
  rc.curve_used.assign(rc.ld.curves.size(), 0);
  for (std::size_t k = 0; k < rc.ld.curves.size(); ++k) {
    LoadCurve lc = rc.ld.curves[k];
    const std::string card = "*DEFINE_CURVE " + std::to_string(lc.number);
    if (lc.t.size() < 2) rc.err(1003, rc.ld.curve_refs[k], card, "LCID", "a curve needs at least 2 points");
    rc.curve_index.emplace(lc.number, int(k));
    lc.number = int(k) + 1;
    rc.m.load_curves.push_back(std::move(lc));
    // a curve a material uses (a flow stress curve: the *MAT card still holds the deck's id)
    // is used
    bool used = false;
    for (const auto& [mid, r] : rc.mt.mats) used = used || material_uses_curve(r.md, rc.ld.curves[k].number);
    for (const auto& [eid, r] : rc.mt.eos) used = used || eos_curve(r.eos) == rc.ld.curves[k].number;  // an EOS energy deposition
    if (used) rc.curve_used[k] = 1;
  }
  rc.m.control.numlc = int(rc.m.load_curves.size());
}

// curves no load or motion uses: one warning line (Diagnostics folds the repeats)
void report_unused_curves(ResolveContext& rc) {
  for (std::size_t k = 0; k < rc.ld.curves.size(); ++k)
    if (!rc.curve_used[k])
      rc.diag.add(2004, loc_of(rc.ld.curve_refs[k], "*DEFINE_CURVE " + std::to_string(rc.ld.curves[k].number), nullptr, false));
}

// 0-based index of the curve a load refers to, or -1 (error 1310)
int curve_of(ResolveContext& rc, const RLoad& l) {
  auto it = rc.curve_index.find(l.lcid);
  if (it == rc.curve_index.end()) {
    if (l.lcid != 0) rc.err(1310, l.lc_ref, l.keyword, "LCID", "*DEFINE_CURVE " + std::to_string(l.lcid) + " is not defined");
    return -1;
  }
  rc.curve_used[std::size_t(it->second)] = 1;
  return it->second;
}

std::array<double, 3> axis_direction(int dof) {
  std::array<double, 3> d{};
  if (dof >= 1 && dof <= 3) d[std::size_t(dof - 1)] = 1;
  return d;
}

// nodes of a load's NID or NSID
std::vector<int> load_nodes(ResolveContext& rc, const RLoad& l, bool set, const char* field) {
  std::vector<int> nodes;
  if (set) {
    if (const RIdList* st = find_node_set(rc, l.id, l.ref, l.keyword, field)) nodes = set_nodes(rc, *st, l.keyword);
  } else {
    const int idx = rc.node_index(l.id);
    if (idx < 0) rc.err(1202, l.ref, l.keyword, field, "node " + std::to_string(l.id) + " is not defined by *NODE");
    else nodes.push_back(idx);
  }
  return nodes;
}

// the rigid material of a part (PID of *LOAD_RIGID_BODY, *BOUNDARY_PRESCRIBED_MOTION_RIGID), or -1
int rigid_material_of_part(ResolveContext& rc, const RLoad& l) {
  auto p = rc.part_index.find(l.id);
  if (p == rc.part_index.end()) {
    rc.err(1308, l.ref, l.keyword, "PID", "part " + std::to_string(l.id) + " is not defined" + rc.refused_note('p', l.id));
    return -1;
  }
  const int mt = rc.part_material[std::size_t(p->second)];
  if (mt < 0) return -1;
  const MaterialType* t = find_material_type(rc.m.materials[std::size_t(mt)].type);  // (null: its *MAT was refused)
  if (!t || !t->rigid) {
    rc.err(1006, l.ref, l.keyword, "PID", "part " + std::to_string(l.id) + " is not a rigid body (*MAT_RIGID)");
    return -1;
  }
  return mt;
}

// The global unit direction of a load or motion: DOF 1-3 along the axes of its system CID
// (global when 0), DOF 4 along its *DEFINE_VECTOR VID, a body load's direction in its CID; a
// motion's DOF 5-7 about the axes, 8 (and -4, -8) along or about VID.
// False (error reported) when the system or vector is undefined.
bool load_direction(ResolveContext& rc, const RLoad& l, std::array<double, 3>& d) {
  if (l.kind == RLoad::body) {
    d = l.dir;
    return global_direction(rc, l.cid, l.cid_ref, l.keyword, "CID", d);
  }
  const bool motion = l.kind == RLoad::motion_node || l.kind == RLoad::motion_set || l.kind == RLoad::motion_rigid;
  if (motion ? motion_along_vector(l.dof) : l.dof == 4) {
    if (l.vid == 0) return false;  // (VID required: reported when read)
    if (!rc.coords.vector(l.vid, d)) {
      rc.err(1310, l.vid_ref, l.keyword, "VID", "vector " + std::to_string(l.vid) + " is not defined by *DEFINE_VECTOR");
      return false;
    }
    return true;
  }
  // DOF 5-7: about x y z; 9-11: turning about an axis along x y z
  d = axis_direction(motion && motion_is_rotation(l.dof) ? l.dof - 4 : motion && motion_is_orbit(l.dof) ? std::abs(l.dof) - 8 : l.dof);
  return global_direction(rc, l.cid, l.cid_ref, l.keyword, "CID", d);
}

void resolve_damping(ResolveContext& rc) {
  if (!rc.ld.damping_given) return;
  GlobalDamping& g = rc.m.damping;
  g.active = true;
  g.d = rc.ld.damping.sf;
  g.factor = rc.ld.damping.dir;
  g.line = rc.ld.damping.ref.line ? rc.ld.damping.ref.line->number : 0;
  if (rc.ld.damping.lcid != 0) {
    g.curve = curve_of(rc, rc.ld.damping);
    if (g.curve < 0) g.active = false;  // (reported)
  }
  if (rc.ld.damping_rotations && rc.m.num_shells() > 0)
    rc.err(2006, rc.ld.damping.ref, rc.ld.damping.keyword, "SRX", "the rotations of shell nodes are not damped (translations only)");
}

// The node indices of a segment's N1-N4; false (error 1202 for the first undefined node) when
// one is not defined.
static bool segment_node_indices(ResolveContext& rc, const std::array<int, 4>& ids, const std::array<Ref, 4>& refs,
                                 const std::string& card, std::array<int, 4>& f) {
  for (int q = 0; q < 4; ++q) {
    f[std::size_t(q)] = rc.node_index(ids[std::size_t(q)]);
    if (f[std::size_t(q)] < 0) {
      const std::string fn = "N" + std::to_string(q + 1);
      rc.err(1202, refs[std::size_t(q)], card, fn.c_str(), "node " + std::to_string(ids[std::size_t(q)]) + " is not defined by *NODE");
      return false;
    }
  }
  return true;
}

// The faces of a *LOAD_SEGMENT (its card's) or *LOAD_SEGMENT_SET (its set's segments).
static void load_segments(ResolveContext& rc, const RLoad& l, std::vector<std::array<int, 4>>& faces) {
  std::array<int, 4> f{};
  if (l.kind == RLoad::segment) {
    if (segment_node_indices(rc, l.nodes, l.node_refs, l.keyword, f)) faces.push_back(f);
    return;
  }
  auto it = rc.sb.seg_sets.find(l.id);
  if (it == rc.sb.seg_sets.end()) {
    rc.err(1309, l.ref, l.keyword, "SSID", "*SET_SEGMENT " + std::to_string(l.id) + " is not defined" + rc.refused_note('S', l.id));
    return;
  }
  const std::string card = "*SET_SEGMENT " + std::to_string(l.id);
  for (std::size_t j = 0; j < it->second.segs.size(); ++j)
    if (segment_node_indices(rc, it->second.segs[j], it->second.refs[j], card, f)) faces.push_back(f);
}

// A load card's prescribed motion along (or about) dir on its curve (no node or body yet).
static PrescribedMotion motion_of(const RLoad& l, const std::array<double, 3>& dir, int curve, int line) {
  PrescribedMotion pm;
  pm.dir = dir;
  pm.hold_normal = l.dof < 0;  // DOF -4, -8
  pm.kind = l.vad;
  pm.curve = curve;
  pm.scale = l.sf;
  pm.birth = l.birth;
  pm.death = l.death;
  pm.line = line;
  return pm;
}

// Per node: 1 for the nodes of rigid bodies' solids.
static std::vector<char> rigid_body_nodes(ResolveContext& rc) {
  std::vector<char> rigid_node(std::size_t(rc.m.num_nodes()), 0);
  for (int e = 0; e < rc.m.num_hexes(); ++e) {
    const int mt = rc.m.hex_material[std::size_t(e)];
    const MaterialType* t = mt >= 0 ? find_material_type(rc.m.materials[std::size_t(mt)].type) : nullptr;
    if (t && t->rigid)
      for (int n : rc.m.hex_nodes[std::size_t(e)]) if (n >= 0) rigid_node[std::size_t(n)] = 1;
  }
  return rigid_node;
}

// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET: the motion on each of the card's nodes (none when
// its curve or direction was refused, pm.curve < 0); nodes of rigid bodies refused (1226), and
// rotations (DOF 5-8, -8) of nodes with no rotations (1102).
static void add_node_motions(ResolveContext& rc, const RLoad& l, PrescribedMotion pm, const std::vector<char>& rigid_node) {
  set_node_motion_kind(l, pm);
  int refused = 0, first = -1, no_rotations = 0, first_without = -1;
  for (int n : load_nodes(rc, l, l.kind == RLoad::motion_set, l.kind == RLoad::motion_node ? "NID" : "NSID")) {
    if (rigid_node[std::size_t(n)]) {
      if (refused++ == 0) first = n;
      continue;
    }
    if (pm.curve < 0) continue;
    if (pm.rotation && !node_has_rotations(rc, n)) {
      if (no_rotations++ == 0) first_without = n;
      continue;
    }
    pm.node = n;
    rc.m.prescribed_motions.push_back(pm);
  }
  if (refused > 0)
    rc.err(1226, l.ref, l.keyword, l.kind == RLoad::motion_node ? "NID" : "NSID",
        std::to_string(refused) + " node(s) of rigid bodies, the first node " + std::to_string(rc.m.node_id(first)) +
            ": prescribe the body's motion with *BOUNDARY_PRESCRIBED_MOTION_RIGID");
  if (no_rotations > 0)
    rc.err(1102, l.ref, l.keyword, "DOF",
           std::to_string(no_rotations) + " node(s) with no rotations (no shell or beam end uses them), the first node " +
               std::to_string(rc.m.node_id(first_without)) + ": rotations (DOF 5-8) of solid nodes");
}

void resolve_loads(ResolveContext& rc) {
  resolve_damping(rc);
  std::vector<char> rigid_node;  // nodes of rigid bodies (prescribed node motions refused there)
  for (const RLoad& l : rc.ld.loads) {
    int curve = curve_of(rc, l);
    std::array<double, 3> dir{};
    if (!load_direction(rc, l, dir)) curve = -1;  // (reported) nothing of it is kept
    const int line = l.ref.line ? l.ref.line->number : l.lc_ref.line ? l.lc_ref.line->number : 0;
    switch (l.kind) {
      case RLoad::node:
      case RLoad::node_set:
        for (int n : load_nodes(rc, l, l.kind == RLoad::node_set, l.kind == RLoad::node ? "NID" : "NSID")) {
          if (curve < 0) continue;
          rc.m.nodal_loads.push_back({n, dir, curve, l.sf, line});
        }
        break;
      case RLoad::rigid_body: {
        // the force acts at the body's centre of mass: spread over its nodes by mass (the
        // engine's rigid-body update sums it back into one force, with no moment)
        const int mt = rigid_material_of_part(rc, l);
        if (mt < 0 || curve < 0) break;
        rc.m.rigid_body_loads.push_back({mt, dir, curve, l.sf, line});
        break;
      }
      case RLoad::segment:
      case RLoad::segment_set: {
        std::vector<std::array<int, 4>> faces;
        load_segments(rc, l, faces);
        if (curve < 0) break;
        for (const auto& f : faces) {
          PressureLoad p;
          p.nodes = f;
          p.curve = curve;
          p.scale = l.sf;
          p.birth = l.birth;
          p.death = l.death;
          p.line = line;
          rc.m.pressure_loads.push_back(p);
        }
        break;
      }
      case RLoad::body:
        if (curve >= 0) rc.m.body_loads.push_back({dir, curve, l.sf, line});
        break;
      case RLoad::motion_node:
      case RLoad::motion_set:
        if (rigid_node.empty()) rigid_node = rigid_body_nodes(rc);
        add_node_motions(rc, l, motion_of(l, dir, curve, line), rigid_node);
        break;
      case RLoad::motion_rigid: {
        const int mt = rigid_material_of_part(rc, l);
        if (mt < 0 || curve < 0) break;
        PrescribedMotion pm = motion_of(l, dir, curve, line);
        pm.rigid_material = mt;
        pm.rotation = motion_is_rotation(l.dof);  // about the axis dir through the centre of mass
        rc.m.prescribed_motions.push_back(pm);
        break;
      }
    }
  }
  if (rc.ld.body_parts_psid != 0) {
    for (int p : parts_of(rc, true, rc.ld.body_parts_psid, rc.ld.body_parts_ref, "*LOAD_BODY_PARTS", "PSID")) {
      const int mt = rc.part_material[std::size_t(p)];
      if (mt >= 0) rc.m.body_load_materials.push_back(mt);
    }
    std::sort(rc.m.body_load_materials.begin(), rc.m.body_load_materials.end());
    rc.m.body_load_materials.erase(std::unique(rc.m.body_load_materials.begin(), rc.m.body_load_materials.end()), rc.m.body_load_materials.end());
  }
  report_unused_curves(rc);
}

void resolve_walls(ResolveContext& rc) {
  rc.ld.walls.insert(rc.ld.walls.end(), rc.ld.geometric_walls.begin(), rc.ld.geometric_walls.end());  // after the planar walls
  for (RWall& w : rc.ld.walls) {
    if (w.nsidex != 0 || w.boxid != 0) {  // the nodes of NSID (0: all) in the box, less NSIDEX
      std::vector<int> nodes;
      if (w.nsid == 0) {
        for (int k = 0; k < rc.m.num_nodes(); ++k) nodes.push_back(k);
      } else if (const RIdList* s = find_node_set(rc, w.nsid, w.nsid_ref, w.keyword, "NSID")) {
        nodes = set_nodes(rc, *s, "*SET_NODE " + std::to_string(w.nsid));
      }
      std::vector<char> exempt(std::size_t(rc.m.num_nodes()), 0);
      if (w.nsidex != 0)
        if (const RIdList* s = find_node_set(rc, w.nsidex, w.nsidex_ref, w.keyword, "NSIDEX"))
          for (int n : set_nodes(rc, *s, "*SET_NODE " + std::to_string(w.nsidex))) exempt[std::size_t(n)] = 1;
      const Box* box = w.boxid != 0 ? find_box(rc, w.boxid, w.boxid_ref, w.keyword, "BOXID") : nullptr;
      for (int n : nodes)
        if (!exempt[std::size_t(n)] && (!box || box->contains(rc.m.x[std::size_t(n)], rc.m.y[std::size_t(n)], rc.m.z[std::size_t(n)])))
          w.w.nodes.push_back(n);
      remove_repeated_nodes(w.w.nodes);
      if (w.w.nodes.empty()) rc.err(1314, w.boxid != 0 ? w.boxid_ref : w.nsidex_ref, w.keyword, w.boxid != 0 ? "BOXID" : "NSIDEX", "no node is left for the wall");
    } else if (w.nsid != 0) {
      if (const RIdList* s = find_node_set(rc, w.nsid, w.nsid_ref, w.keyword, "NSID")) {
        w.w.nodes = set_nodes(rc, *s, "*SET_NODE_LIST " + std::to_string(w.nsid));
        remove_repeated_nodes(w.w.nodes);
        if (w.w.nodes.empty()) rc.err(1314, w.nsid_ref, w.keyword, "NSID", "the node set has no nodes (0 = all nodes)");
      }
    }
    rc.m.walls.push_back(w.w);
  }
  rc.m.control.num_walls = int(rc.m.walls.size());
}

// Appends the nodes as initial-velocity ranges: arithmetic runs first..last by increment.
void add_velocity_nodes(ResolveContext& rc, const std::vector<int>& nodes, const std::array<double, 3>& v) {
  for (std::size_t j = 0; j < nodes.size();) {
    InitialVelocity iv;
    iv.first = nodes[j] + 1;
    iv.last = iv.first;
    iv.increment = 1;
    iv.v = v;
    std::size_t e = j;
    if (j + 1 < nodes.size() && nodes[j + 1] > nodes[j]) {
      int inc = nodes[j + 1] - nodes[j];
      e = j + 1;
      while (e + 1 < nodes.size() && nodes[e + 1] - nodes[e] == inc) ++e;
      iv.increment = inc;
      iv.last = nodes[e] + 1;
    }
    rc.m.init_velocities.push_back(iv);
    j = e + 1;
  }
}

// translation v.v plus, with OMEGA, the rotation OMEGA n x (x - xc): node by node
void add_generated_velocities(ResolveContext& rc, const std::vector<int>& nodes, const RVelocity& v) {
  if (v.omega == 0) {
    add_velocity_nodes(rc, nodes, v.v);
    return;
  }
  for (int i : nodes) {
    const double r[3] = {rc.m.x[std::size_t(i)] - v.xc[0], rc.m.y[std::size_t(i)] - v.xc[1], rc.m.z[std::size_t(i)] - v.xc[2]};
    const std::array<double, 3> vi = {v.v[0] + v.omega * (v.n[1] * r[2] - v.n[2] * r[1]),
                                      v.v[1] + v.omega * (v.n[2] * r[0] - v.n[0] * r[2]),
                                      v.v[2] + v.omega * (v.n[0] * r[1] - v.n[1] * r[0])};
    add_velocity_nodes(rc, {i}, vi);
  }
}

// *INITIAL_VELOCITY with BOXID or NSIDEX: the nodes of NSID (all nodes for 0) inside the
// box take v, except the nodes of NSIDEX, which take ve.
void add_restricted_velocities(ResolveContext& rc, const RVelocity& v) {
  std::vector<int> nodes;
  if (v.id == 0) {
    for (int k = 0; k < rc.m.num_nodes(); ++k) nodes.push_back(k);
  } else if (const RIdList* s = find_node_set(rc, v.id, v.ref, "*INITIAL_VELOCITY", "NSID")) {
    nodes = set_nodes(rc, *s, "*SET_NODE " + std::to_string(v.id));
  }
  std::vector<char> exempt(std::size_t(rc.m.num_nodes()), 0);
  std::vector<int> exempted;
  if (v.nsidex > 0)
    if (const RIdList* s = find_node_set(rc, v.nsidex, v.nsidex_ref, "*INITIAL_VELOCITY", "NSIDEX"))
      for (int n : set_nodes(rc, *s, "*SET_NODE " + std::to_string(v.nsidex))) {
        if (!exempt[std::size_t(n)]) exempted.push_back(n);
        exempt[std::size_t(n)] = 1;
      }
  const Box* box = v.boxid != 0 ? find_box(rc, v.boxid, v.boxid_ref, "*INITIAL_VELOCITY", "BOXID") : nullptr;
  std::vector<int> moved;
  for (int n : nodes) {
    if (exempt[std::size_t(n)]) continue;
    if (box && !box->contains(rc.m.x[std::size_t(n)], rc.m.y[std::size_t(n)], rc.m.z[std::size_t(n)])) continue;
    moved.push_back(n);
  }
  add_velocity_nodes(rc, moved, v.v);
  std::sort(exempted.begin(), exempted.end());
  add_velocity_nodes(rc, exempted, v.ve);
}

// Rotational initial velocities (VXR VYR VZR, or OMEGA n of *INITIAL_VELOCITY_GENERATION)
// on the nodes (only shell nodes have rotations; on others they have no effect).
void set_rotational_velocities(ResolveContext& rc, const std::vector<int>& nodes, const RVelocity& v) {
  std::array<double, 3> w = v.w;
  bool any = v.has_w;
  if (v.omega != 0) {
    for (int a = 0; a < 3; ++a) w[std::size_t(a)] = v.omega * v.n[std::size_t(a)];
    any = true;
  }
  if (!any) return;
  if (rc.m.init_omega.empty()) rc.m.init_omega.assign(std::size_t(rc.m.num_nodes()), {0, 0, 0});
  for (int n : nodes) rc.m.init_omega[std::size_t(n)] = w;
}

void resolve_velocities(ResolveContext& rc) {
  for (RVelocity v : rc.ld.velocities) {
    // ICID: the velocities (and the rotation axis) are given in a local system
    const std::string& icid_card = v.keyword;
    if (!global_direction(rc, v.icid, v.icid_ref, icid_card, "ICID", v.v)) continue;
    global_direction(rc, v.icid, v.icid_ref, icid_card, "ICID", v.n);
    global_direction(rc, v.icid, v.icid_ref, icid_card, "ICID", v.ve);
    if (v.nsidex != 0 || v.boxid != 0) {
      add_restricted_velocities(rc, v);
      continue;
    }
    switch (v.kind) {
      case RVelocity::all: {
        InitialVelocity iv;
        iv.first = 0;
        iv.last = 0;
        iv.v = v.v;
        rc.m.init_velocities.push_back(iv);
        if (v.has_w) {
          std::vector<int> all(std::size_t(rc.m.num_nodes()));
          for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
          set_rotational_velocities(rc, all, v);
        }
        break;
      }
      case RVelocity::node: {
        int idx = rc.node_index(v.id);
        if (idx < 0) rc.err(1202, v.ref, "*INITIAL_VELOCITY_NODE", "NID", "node " + std::to_string(v.id) + " is not defined by *NODE");
        else {
          add_velocity_nodes(rc, {idx}, v.v);
          set_rotational_velocities(rc, {idx}, v);
        }
        break;
      }
      case RVelocity::node_set:
        if (const RIdList* s = find_node_set(rc, v.id, v.ref, "*INITIAL_VELOCITY", "NSID")) {
          const std::vector<int> nodes = set_nodes(rc, *s, "*SET_NODE_LIST " + std::to_string(v.id));
          add_generated_velocities(rc, nodes, v);
          set_rotational_velocities(rc, nodes, v);
        }
        break;
      case RVelocity::part:
      case RVelocity::part_set: {
        const std::vector<int> nodes = nodes_of_parts(rc, parts_of(rc, v.kind == RVelocity::part_set, v.id, v.ref, "*INITIAL_VELOCITY_GENERATION", "ID"));
        add_generated_velocities(rc, nodes, v);
        set_rotational_velocities(rc, nodes, v);
        break;
      }
    }
  }
  rc.m.control.num_init_velocity_cards = int(rc.m.init_velocities.size());
}

}  // namespace impact3d::kw
