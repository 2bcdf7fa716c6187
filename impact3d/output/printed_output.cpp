#include "impact3d/output/printed_output.h"

#include "impact3d/input/fixed_cards.h"
#include "impact3d/material/material_types.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace impact3d {

namespace {
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
const char* material_type_name(int t) {
  const MaterialType* mt = find_material_type(t);
  return mt ? mt->name : "unknown";
}
const char* hourglass_name(int t) {
  switch (t) {
    case 1: return "DYNA3D viscous";
    case 2: return "Flanagan-Belytschko viscous";
    case 3: return "Flanagan-Belytschko viscous (exact volume)";
    case 4: return "Flanagan-Belytschko stiffness";
    case 5: return "Flanagan-Belytschko stiffness (exact volume)";
  }
  return "unknown";
}
const char* bc_name(int c) {
  switch (c) {
    case 1: return "x fixed";
    case 2: return "y fixed";
    case 3: return "z fixed";
    case 4: return "x, y fixed";
    case 5: return "y, z fixed";
    case 6: return "z, x fixed";
    case 7: return "x, y, z fixed";
  }
  return "?";
}

// The echo of one card kind: the named fields of its table (fixed_cards.h) as column heads,
// each value under its field's name, so that the echo names fields as the deck format does.
class CardEcho {
 public:
  CardEcho(const char* id, std::vector<const char*> names) : layout_(fixed_card_layout(id, FixedVintage::dyna3d_later)), names_(std::move(names)) {}
  std::string heads() const {
    std::string s;
    for (const char* n : names_) s += pad(n, width(n));
    return s;
  }
  // "name, name, ... (the <id> table)": what the columns of an echo hold.
  std::string legend() const {
    std::string s;
    for (const char* n : names_) s += (s.empty() ? "" : ", ") + std::string(n);
    return s + " (" + layout_.id + ")";
  }
  // One row: integer fields as integers, real fields as %.4e.
  std::string row(const std::vector<double>& values) const {
    std::string s;
    for (std::size_t k = 0; k < names_.size() && k < values.size(); ++k) {
      const bool integer = is_integer(layout_.field(names_[k]).kind);
      s += pad(integer ? std::to_string(static_cast<long long>(values[k])) : fmt("%.4e", values[k]), width(names_[k]));
    }
    return s;
  }

 private:
  int width(const char* name) const {
    const bool integer = is_integer(layout_.field(name).kind);
    return 2 + std::max(int(std::string_view(name).size()), integer ? 8 : 11);
  }
  static std::string pad(const std::string& v, int w) { return std::string(std::size_t(std::max(0, w - int(v.size()))), ' ') + v; }
  const FixedCardLayout& layout_;
  std::vector<const char*> names_;
};

// The deck's number of material slot `mat` (0: none).
int material_label(const Model& m, int mat) { return mat >= 0 && std::size_t(mat) < m.materials.size() ? m.materials[std::size_t(mat)].number : 0; }

// The first cards of the node and solid element kinds, echoed under their tables' field names.
void write_card_echo(std::ostream& os, const Model& m) {
  constexpr int kShown = 10;
  if (m.num_nodes() > 0) {
    const CardEcho e("node card", {"node number", "boundary code", "x", "y", "z"});
    os << " n o d e   c a r d s   (the first " << std::min(kShown, m.num_nodes()) << " of " << m.num_nodes() << ")\n\n " << e.heads() << "\n";
    for (int n = 0; n < m.num_nodes() && n < kShown; ++n) {
      const std::size_t i = std::size_t(n);
      os << " " << e.row({double(m.node_id(n)), double(m.bc[i]), m.x[i], m.y[i], m.z[i]}) << "\n";
    }
    os << "\n";
  }
  if (m.num_hexes() > 0) {
    const CardEcho e("solid element card", {"element number", "material number", "node n1", "node n2", "node n3", "node n4",
                                            "node n5", "node n6", "node n7", "node n8"});
    os << " s o l i d   e l e m e n t   c a r d s   (the first " << std::min(kShown, m.num_hexes()) << " of " << m.num_hexes() << ")\n\n "
       << e.heads() << "\n";
    for (int k = 0; k < m.num_hexes() && k < kShown; ++k) {
      std::vector<double> v{double(m.hex_id(k)), double(material_label(m, m.hex_material[std::size_t(k)]))};
      for (int q : m.hex_nodes[std::size_t(k)]) v.push_back(q < 0 ? 0.0 : double(m.node_id(q)));
      os << " " << e.row(v) << "\n";
    }
    os << "\n";
  }
}

// Loads and prescribed motions: one line each, at most kShown per kind, then the count of the rest.
std::string direction_text(const std::array<double, 3>& d) {
  for (int a = 0; a < 3; ++a)
    if (d[std::size_t(a)] == 1 && d[std::size_t((a + 1) % 3)] == 0 && d[std::size_t((a + 2) % 3)] == 0)
      return std::string(1, "xyz"[a]);
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", d[0], d[1], d[2]);
  return buf;
}

void write_loads(std::ostream& os, const Model& m) {
  if (!m.has_loads() && m.prescribed_motions.empty()) return;
  constexpr std::size_t kShown = 20;
  os << " l o a d s   a n d   p r e s c r i b e d   m o t i o n s\n\n";
  auto curve = [&](int c) { return std::to_string(m.load_curves[std::size_t(c)].number); };
  auto more = [&](std::size_t shown, std::size_t total) {
    if (total > shown) os << "   ... and " << (total - shown) << " more\n";
  };
  if (!m.nodal_loads.empty()) os << "   nodal loads: " << m.nodal_loads.size() << "\n";
  for (std::size_t j = 0; j < std::min(kShown, m.nodal_loads.size()); ++j) {
    const NodalLoad& l = m.nodal_loads[j];
    os << "     node " << m.node_id(l.node) << " along " << direction_text(l.dir) << ": " << fmt("%.6e", l.scale)
       << " x curve " << curve(l.curve) << " (force)\n";
  }
  more(kShown, m.nodal_loads.size());
  if (!m.rigid_body_loads.empty()) os << "   rigid-body loads (at the centre of mass): " << m.rigid_body_loads.size() << "\n";
  for (const RigidBodyLoad& l : m.rigid_body_loads)
    os << "     material " << m.materials[std::size_t(l.material)].number << " along " << direction_text(l.dir) << ": "
       << fmt("%.6e", l.scale) << " x curve " << curve(l.curve) << " (force)\n";
  if (!m.pressure_loads.empty()) os << "   pressure loads: " << m.pressure_loads.size() << " face(s)\n";
  for (std::size_t j = 0; j < std::min(kShown, m.pressure_loads.size()); ++j) {
    const PressureLoad& l = m.pressure_loads[j];
    os << "     face " << m.node_id(l.nodes[0]) << " " << m.node_id(l.nodes[1]) << " " << m.node_id(l.nodes[2]) << " "
       << m.node_id(l.nodes[3]) << ": " << fmt("%.6e", l.scale) << " x curve " << curve(l.curve) << " (stress)";
    if (l.birth > 0) os << " from " << fmt("%.6e", l.birth);
    if (l.death < 1e28) os << " until " << fmt("%.6e", l.death);
    if (l.factor != std::array<double, 4>{1, 1, 1, 1})
      os << ", multipliers " << fmt("%.4g", l.factor[0]) << " " << fmt("%.4g", l.factor[1]) << " " << fmt("%.4g", l.factor[2])
         << " " << fmt("%.4g", l.factor[3]);
    os << "\n";
  }
  more(kShown, m.pressure_loads.size());
  for (const BodyLoad& b : m.body_loads)
    os << "   body load (base acceleration) along " << direction_text(b.dir) << ": -" << fmt("%.6e", b.scale) << " x curve "
       << curve(b.curve) << " (acceleration)" << (m.body_load_materials.empty() ? ", all materials" : ", listed materials") << "\n";
  if (m.damping.active) {
    const GlobalDamping& g = m.damping;
    os << "   global mass damping f = -D m v: D = " << (g.curve >= 0 ? "curve " + curve(g.curve) : fmt("%.6e", g.d))
       << " per unit time, factors x y z " << fmt("%.4g", g.factor[0]) << " " << fmt("%.4g", g.factor[1]) << " "
       << fmt("%.4g", g.factor[2]) << " (its work is external work)\n";
  }
  if (!m.prescribed_motions.empty()) os << "   prescribed motions: " << m.prescribed_motions.size() << "\n";
  for (std::size_t j = 0; j < std::min(kShown, m.prescribed_motions.size()); ++j) {
    const PrescribedMotion& pm = m.prescribed_motions[j];
    static const char* kinds[] = {"velocity", "acceleration", "displacement"};
    os << "     " << (pm.node >= 0 ? "node " + std::to_string(m.node_id(pm.node)) : "rigid body of material " + std::to_string(m.materials[std::size_t(pm.rigid_material)].number))
       << " " << (pm.rotation || pm.orbit ? "angular " : "") << kinds[int(pm.kind)] << (pm.rotation || pm.orbit ? " about " : " along ") << direction_text(pm.dir)
       << (pm.orbit ? " through (" + fmt("%.6e", pm.center[0]) + ", " + fmt("%.6e", pm.center[1]) + ", " + fmt("%.6e", pm.center[2]) + "), turning about it" : "") << (pm.radial_free ? ", its distance from it free" : "")
       << (pm.hold_normal ? (pm.rotation ? " (other rotations held)" : " (normal plane held)") : "") << ": " << fmt("%.6e", pm.scale) << " x curve "
       << curve(pm.curve);
    if (pm.birth > 0) os << " from " << fmt("%.6e", pm.birth);
    if (pm.death < 1e28) os << " until " << fmt("%.6e", pm.death);
    os << "\n";
  }
  more(kShown, m.prescribed_motions.size());
  os << "\n";
}

// Nodal constraints (the node cards' codes and *BOUNDARY_SPC_*), one line per code with the
// node count and the first node numbers.
void write_constraints(std::ostream& os, const Model& m) {
  constexpr std::size_t kFirst = 10;
  std::size_t count[8] = {};
  std::string first[8];
  for (std::size_t i = 0; i < m.bc.size(); ++i) {
    const int c = m.bc[i];
    if (c < 1 || c > 7) continue;
    if (count[c] < kFirst) first[c] += (count[c] ? ", " : "") + std::to_string(m.node_id(int(i)));
    ++count[c];
  }
  bool any = false;
  for (int c = 1; c <= 7; ++c) {
    if (!count[c]) continue;
    if (!any) os << " c o n s t r a i n t s   (node boundary codes, *BOUNDARY_SPC_*)\n\n";
    any = true;
    char buf[64];
    std::snprintf(buf, sizeof buf, "   code %d (%s) ", c, bc_name(c));
    std::string head = buf;
    if (head.size() < 42) head += std::string(42 - head.size(), '.');
    os << head << " " << count[c] << " node(s): " << first[c] << (count[c] > kFirst ? ", ..." : "") << "\n";
  }
  if (any) os << "\n";
}

// The shells: per shell part (material) its count, triangles, thickness and area ranges; the
// first kShown shells (deck id, material, nodes, thicknesses), then the count of the rest; the
// rotational constraints of shell nodes, one line per combination (count, first nodes).
void write_shells(std::ostream& os, const Model& m) {
  if (m.num_shells() == 0) return;
  os << " s h e l l   e l e m e n t s   (Belytschko-Tsay)\n\n";
  const std::size_t nm = m.materials.size();
  std::vector<long long> count(nm, 0), tri(nm, 0);
  std::vector<double> tmin(nm, 1e300), tmax(nm, -1e300), amin(nm, 1e300), amax(nm, -1e300);
  for (int k = 0; k < m.num_shells(); ++k) {
    const int mat = m.shell_material[std::size_t(k)];
    const auto& n = m.shell_nodes[std::size_t(k)];
    if (mat < 0 || std::size_t(mat) >= nm || n[0] < 0) continue;
    const std::size_t q = std::size_t(mat);
    ++count[q];
    const bool triangle = n[2] == n[3];
    tri[q] += triangle ? 1 : 0;
    const auto& t = m.shell_thickness[std::size_t(k)];
    for (int j = 0; j < (triangle ? 3 : 4); ++j) {
      tmin[q] = std::min(tmin[q], t[std::size_t(j)]);
      tmax[q] = std::max(tmax[q], t[std::size_t(j)]);
    }
    // area: half the cross product of the diagonals
    const std::size_t a = std::size_t(n[0]), b = std::size_t(n[1]), c = std::size_t(n[2]), d = std::size_t(n[3]);
    const double d1[3] = {m.x[c] - m.x[a], m.y[c] - m.y[a], m.z[c] - m.z[a]};
    const double d2[3] = {m.x[d] - m.x[b], m.y[d] - m.y[b], m.z[d] - m.z[b]};
    const double cx = d1[1] * d2[2] - d1[2] * d2[1], cy = d1[2] * d2[0] - d1[0] * d2[2], cz = d1[0] * d2[1] - d1[1] * d2[0];
    const double area = 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
    amin[q] = std::min(amin[q], area);
    amax[q] = std::max(amax[q], area);
  }
  for (std::size_t q = 0; q < nm; ++q) {
    if (!count[q]) continue;
    os << "   material " << m.materials[q].number << ": " << count[q] << " shell(s)";
    if (tri[q]) os << " (" << tri[q] << " triangle(s))";
    os << ", thickness " << fmt("%.4e", tmin[q]) << " to " << fmt("%.4e", tmax[q]) << " (length), area "
       << fmt("%.4e", amin[q]) << " to " << fmt("%.4e", amax[q]) << " (length^2)\n";
  }
  constexpr int kShown = 10;
  // the shell element card and its thickness card: the columns named by their tables' fields
  const CardEcho ec("shell element card", {"element number", "material number", "node n1", "node n2", "node n3", "node n4"});
  const CardEcho et("shell thickness card", {"thickness t1", "thickness t2", "thickness t3", "thickness t4"});
  os << "\n   columns: " << ec.legend() << "; " << et.legend() << "\n";
  os << "   shell  material        n1        n2        n3        n4   thicknesses t1-t4\n";
  for (int k = 0; k < m.num_shells() && k < kShown; ++k) {
    const auto& n = m.shell_nodes[std::size_t(k)];
    const auto& t = m.shell_thickness[std::size_t(k)];
    char buf[256];
    std::snprintf(buf, sizeof buf, "%8d %9d %9d %9d %9d %9d   %.4e %.4e %.4e %.4e\n", m.shell_id(k),
                  m.shell_material[std::size_t(k)] + 1, n[0] < 0 ? 0 : m.node_id(n[0]), n[1] < 0 ? 0 : m.node_id(n[1]),
                  n[2] < 0 ? 0 : m.node_id(n[2]), n[3] < 0 ? 0 : m.node_id(n[3]), t[0], t[1], t[2], t[3]);
    os << buf;
  }
  if (m.num_shells() > kShown) os << "   ... and " << (m.num_shells() - kShown) << " more shell(s)\n";
  // rotational constraints, one line per combination
  static const char* const kRot[8] = {"", "rx", "ry", "rx ry", "rz", "rx rz", "ry rz", "rx ry rz"};
  long long rc[8] = {};
  std::string first[8];
  for (std::size_t i = 0; i < m.rot_bc.size(); ++i) {
    const int b = m.rot_bc[i] & 7;
    if (!b) continue;
    if (rc[b]++ < 5) first[b] += (first[b].empty() ? "" : ", ") + std::to_string(m.node_id(int(i)));
  }
  bool any = false;
  for (int b = 1; b < 8; ++b) {
    if (!rc[b]) continue;
    if (!any) os << "\n   rotations fixed on shell nodes:\n";
    any = true;
    os << "     " << kRot[b] << ": " << rc[b] << " node(s): " << first[b] << (rc[b] > 5 ? ", ..." : "") << "\n";
  }
  os << "\n";
}
}  // namespace

void write_counts(std::ostream& os, const Model& m) {
  std::set<int> used;
  for (int mat : m.hex_material) used.insert(mat);
  os << "     number of nodes ...................... " << m.num_nodes() << "\n"
     << "     number of solid elements ............. " << m.num_hexes() << "\n"
     << (m.num_shells() > 0 ? "     number of shell elements ............. " + std::to_string(m.num_shells()) + "\n" : std::string())
     << "     number of materials .................. " << m.materials.size() << "\n"
     << "     number of rigid walls ................ " << m.walls.size() << "\n"
     << "     number of sliding interfaces ......... " << m.interfaces.size() << "\n"
     << "     number of load curves ................ " << m.load_curves.size() << "\n"
     << "     number of initial-velocity cards ..... " << m.init_velocities.size() << "\n"
     << "     node / solid time-history blocks ..... " << m.node_th_blocks.size() << " / "
     << m.solid_th_blocks.size() << "\n"
     << (m.shell_th_blocks.empty() ? std::string()
                                   : "     shell time-history blocks ............ " + std::to_string(m.shell_th_blocks.size()) + "\n")
     << (m.beam_th_blocks.empty() ? std::string()
                                  : "     beam time-history blocks ............. " + std::to_string(m.beam_th_blocks.size()) + "\n");
}

namespace {

// The control cards: counts, times, intervals, step controls.
void write_control_information(std::ostream& os, const Model& m) {
  const ControlData& k = m.control;
  write_counts(os, m);
  os << "     termination time ..................... " << fmt("%.6e", k.end_time) << " (time)\n";
  if (k.end_cycle > 0) os << "     termination cycle .................... " << k.end_cycle << "\n";
  os
     << "     plot-state interval .................. " << fmt("%.6e", k.plot_interval) << " (time)\n"
     << "     time-history interval ................ " << fmt("%.6e", k.th_interval) << " (time)\n"
     << "     restart dump every ................... " << k.restart_dump_cycles << " cycles (0 = none)\n"
     << "     initial time step .................... "
     << (k.initial_dt > 0 ? fmt("%.6e", k.initial_dt) : std::string("computed")) << "\n"
     << "     time-step scale factor ............... " << fmt("%.4f", k.tssf) << "\n";
  if (k.mass_scaling_dt != 0)
    os << "     mass scaling DT2MS ................... " << fmt("%.6e", k.mass_scaling_dt)
       << (k.mass_scaling_dt > 0 ? " (every element's step set to it at the first cycle, then held)"
                                 : " (elements below |DT2MS| get mass)")
       << (k.mass_scaling_first_only ? ", first cycle only (MS1ST)" : "") << "\n";
  if (k.erode_small_steps)
    os << "     erode solids below the minimum step .. yes (ERODE 1: DTMIN x first step)\n";
  if (k.end_mass_percent > 0)
    os << "     added-mass limit ENDMAS .............. " << fmt("%.4g", k.end_mass_percent) << " %\n";
  os << "     sliding-interface penalty scale ...... " << fmt("%.4f", k.penalty_scale) << "\n"
     << "     run-log interval ..................... " << k.report_interval << " cycles\n"
     << "     minimum step factor .................. " << fmt("%.4g", k.min_step_factor) << "\n\n";
}

// One material: its moduli and wave speed as the kernel uses them, its parameters, section,
// hourglass control and bulk viscosity.
void write_material(std::ostream& os, const Model& m, const MaterialData& md) {
  // the moduli and wave speed the kernel uses (its type's derivation: e.g. type 15 takes G
  // from its own card)
  double G = md.E / (2 * (1 + md.nu));
  double K = md.E / (3 * (1 - 2 * md.nu));
  double c = std::sqrt((K + 4 * G / 3) / md.rho);
  if (find_material_type(md.type)) {
    const MaterialConstants mc = derive_constants(md, m);
    G = mc.G, K = mc.K, c = mc.c;
  }
  os << "   material " << md.number << ": " << material_type_name(md.type) << " (type " << md.type << ")"
     << (md.title.empty() ? "" : "  \"" + md.title + "\"") << "\n"
     << "     density .............................. " << fmt("%.6e", md.rho) << " (mass/volume)\n"
     << "     Young's modulus E .................... " << fmt("%.6e", md.E) << " (stress)\n"
     << "     Poisson's ratio ...................... " << fmt("%.4f", md.nu) << "\n"
     << "     bulk modulus K (derived) ............. " << fmt("%.6e", K) << " (stress)\n"
     << "     shear modulus G (derived) ............ " << fmt("%.6e", G) << " (stress)\n"
     << "     dilatational wave speed (derived) .... " << fmt("%.6e", c) << " (length/time)\n";
  if (const MaterialType* mt = find_material_type(md.type)) echo_material_params(os, md, *mt);
  if (md.shell)
    os << "     shell section: Belytschko-Tsay, " << md.shell_section.nip << " Gauss point(s) through the thickness, shear factor "
       << fmt("%.4f", md.shell_section.shrf) << ", T1-T4 " << fmt("%.4e", md.shell_section.t[0]) << " "
       << fmt("%.4e", md.shell_section.t[1]) << " " << fmt("%.4e", md.shell_section.t[2]) << " "
       << fmt("%.4e", md.shell_section.t[3]) << "\n"
       << "     plate wave speed (derived) ........... " << fmt("%.6e", std::sqrt(md.E / (md.rho * (1 - md.nu * md.nu))))
       << " (length/time)\n";
  os << "     hourglass control .................... type " << md.hourglass_type << " ("
     << hourglass_name(md.hourglass_type) << "), coefficient " << fmt("%.4g", md.hourglass_coef) << "\n"
     << "     bulk viscosity Q1 (quadratic) ........ " << fmt("%.4g", md.q1) << "\n"
     << "     bulk viscosity Q2 (linear) ........... " << fmt("%.4g", md.q2) << "\n";
  if (md.packed) os << "     (parameters read packed, 8 per card, from card 3)\n";
  os << "\n";
}

// Each rigid wall: point, normal, friction, nodes, motion.
void write_rigid_walls(std::ostream& os, const Model& m) {
  if (m.walls.empty()) return;
  os << " r i g i d   w a l l s\n\n";
  for (std::size_t w = 0; w < m.walls.size(); ++w) {
    const auto& sw = m.walls[w];
    double n[3] = {sw.head[0] - sw.tail[0], sw.head[1] - sw.tail[1], sw.head[2] - sw.tail[2]};
    double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "   wall %zu: point (%.6g, %.6g, %.6g), normal (%.6f, %.6f, %.6f), ", w + 1,
                  sw.tail[0], sw.tail[1], sw.tail[2], n[0] / l, n[1] / l, n[2] / l);
    os << buf
       << (sw.friction == 0 ? std::string("frictionless")
           : sw.friction == 1 ? std::string("stick")
                              : "Coulomb friction " + fmt("%.4g", sw.friction))
       << ", nodes: " << (sw.nodes.empty() ? std::string("all") : std::to_string(sw.nodes.size()));
    if (sw.mass > 0) os << ", moving: mass " << fmt("%.6e", sw.mass) << ", initial velocity " << fmt("%.6e", sw.v0) << " along the normal";
    if (sw.cylinder())
      os << ", cylinder: radius " << fmt("%.6g", sw.radius) << " about the axis through the point along the normal, length "
         << (sw.length > 0 ? fmt("%.6g", sw.length) : std::string("infinite"));
    os << "\n";
  }
  os << "\n";
}

// Each sliding interface: type, segments, friction, stiffness, treatment, intfor sides.
void write_interfaces(std::ostream& os, const Model& m) {
  if (m.interfaces.empty()) return;
  os << " s l i d i n g   i n t e r f a c e s\n\n";
  for (std::size_t i = 0; i < m.interfaces.size(); ++i) {
    const auto& si = m.interfaces[i];
    const bool single = si.type == 4;
    os << "   interface " << i + 1 << ": type " << si.type
       << (single ? " (single surface)" : " (sliding with impact and separation)") << (si.eroding ? ", eroding" : "") << ", "
       << (single ? std::to_string(si.slave.size()) + " segments"
                  : std::to_string(si.slave.size()) + " slave / " + std::to_string(si.master.size()) + " master segments")
       << (si.slave_nodes.empty() && si.master_nodes.empty()
               ? std::string()
               : single ? ", " + std::to_string(si.slave_nodes.size()) + " beam nodes"
                        : ", " + std::to_string(si.slave_nodes.size()) + " slave / " + std::to_string(si.master_nodes.size()) + " master beam nodes")
       << "\n"
       << "     friction static/dynamic/decay ........ " << fmt("%.4g", si.fs) << " / "
       << fmt("%.4g", si.fd) << " / " << fmt("%.4g", si.decay) << "\n"
       << "     penalty stiffness .................... "
       << (si.stiffness_method == 0 ? "DYNA3D mu K A^2 / V (shells mu K A / diagonal), mu = " +
                                          fmt("%.4g", si.penalty_scale > 0 ? si.penalty_scale : m.control.penalty_scale)
                        : si.stiffness_method == 2 ? "LS-DYNA soft constraint (SOFT 1), SOFSCL = " + fmt("%.4g", si.sofscl)
                        : si.stiffness_method == 3 ? "LS-DYNA segment-based (SOFT 2), 0.5 mu m1 m2 / (m1 + m2) / dt^2, mu = " +
                                                         fmt("%.4g", si.penalty_scale > 0 ? si.penalty_scale : m.control.penalty_scale)
                                                   : std::string("IMPACT-3D maximum stable, alpha = 1 - TSSF^2"))
       << "\n"
       << "     treatment ............................ " << (single ? "one pass over the surface, each node against the segments not around it" : si.symmetric ? "symmetric (two passes)" : "one pass")
       << "\n";
    if (si.intfor_slave || si.intfor_master)
      os << "     interface-force database (intfor) .... "
         << (si.intfor_slave && si.intfor_master ? "both sides" : si.intfor_slave ? "slave side" : "master side") << "\n";
  }
  os << "\n";
}

// Each force transducer, and the interface-force database interval.
void write_force_transducers(std::ostream& os, const Model& m) {
  if (!m.force_transducers.empty()) {
    os << " f o r c e   t r a n s d u c e r s\n\n";
    for (std::size_t t = 0; t < m.force_transducers.size(); ++t) {
      const ForceTransducer& ft = m.force_transducers[t];
      os << "   transducer " << t + 1 << " (rcforc interface " << m.interfaces.size() + t + 1 << ")"
         << (ft.id ? ", id " + std::to_string(ft.id) : std::string()) << ": the contact force on " << ft.a_nodes.size()
         << " side-A nodes" << (ft.has_b ? " from " + std::to_string(ft.b_nodes.size()) + " side-B nodes" : std::string(" from every interface"))
         << "; applies no force\n";
    }
    os << "\n";
  }
  if (m.control.intfor_interval >= 0)
    os << "     interface-force database interval .... " << fmt("%.4e", m.control.intfor_interval > 0 ? m.control.intfor_interval : m.control.plot_interval) << "\n\n";
}

// The initial velocities.  Consecutive definitions of one velocity are one line (an
// *INITIAL_VELOCITY_NODE list of many nodes is many ranges); a rotation sets node by node: at
// most 50 lines, then the count of the rest.
void write_initial_velocities(std::ostream& os, const Model& m) {
  if (m.init_velocities.empty()) return;
  os << " i n i t i a l   v e l o c i t i e s\n\n";
  // Consecutive definitions of one velocity are one line (an *INITIAL_VELOCITY_NODE list of
  // many nodes is many ranges); a rotation sets node by node: at most 50 lines, then the count
  // of the rest.
  constexpr std::size_t kShown = 50, kRanges = 3;
  const auto& ivs = m.init_velocities;
  std::size_t lines = 0;
  for (std::size_t k = 0; k < ivs.size();) {
    std::size_t j = k;
    while (j + 1 < ivs.size() && ivs[j + 1].first != 0 && ivs[k].first != 0 && ivs[j + 1].v == ivs[k].v) ++j;
    if (lines++ == kShown) {
      os << "   ... and " << (ivs.size() - k) << " more definition(s)\n";
      break;
    }
    const auto& iv = ivs[k];
    char buf[200];
    std::snprintf(buf, sizeof buf, ": (%.6g, %.6g, %.6g) (length/time)\n", iv.v[0], iv.v[1], iv.v[2]);
    if (iv.first == 0) {
      os << "   all nodes" << buf;
    } else if (j == k) {
      os << "   nodes " << iv.first << " to " << iv.last << " step " << iv.increment << buf;
    } else {
      long long nodes = 0;
      std::string ranges;
      for (std::size_t q = k; q <= j; ++q) {
        const auto& r = ivs[q];
        nodes += r.increment > 0 && r.last >= r.first ? (r.last - r.first) / r.increment + 1 : 0;
        if (q - k < kRanges)
          ranges += (q > k ? ", " : "") + std::to_string(r.first) + " to " + std::to_string(r.last) + " step " +
                    std::to_string(r.increment);
      }
      if (j - k + 1 > kRanges) ranges += ", ...";
      os << "   " << nodes << " nodes in " << (j - k + 1) << " ranges (" << ranges << ")" << buf;
    }
    k = j + 1;
  }
  os << "\n";
}

// The time-history blocks of nodes, solids, shells and beams.
void write_time_history_blocks(std::ostream& os, const Model& m) {
  if (!m.node_th_blocks.empty() || !m.solid_th_blocks.empty() || !m.shell_th_blocks.empty() || !m.beam_th_blocks.empty()) {
    os << " t i m e   h i s t o r i e s\n\n";
    for (const auto& b : m.node_th_blocks) os << "   nodes " << b[0] << " to " << b[1] << "\n";
    for (const auto& b : m.solid_th_blocks) os << "   solids " << b[0] << " to " << b[1] << "\n";
    for (const auto& b : m.shell_th_blocks)
      os << "   shells " << m.shell_id(b[0] - 1) << " to " << m.shell_id(b[1] - 1) << "\n";
    for (const auto& b : m.beam_th_blocks)
      os << "   beams " << m.beam_id(b[0] - 1) << " to " << m.beam_id(b[1] - 1) << "\n";
    os << "\n";
  }
}

}  // namespace

void write_model_summary(std::ostream& os, const Model& m) {
  os << "\n title: " << m.title << "\n"
     << " deck:  " << m.deck_file
     << (m.keyword_deck ? std::string(" (LS-DYNA keyword format)")
                        : std::string(" (DYNA3D fixed format, ") + (m.large_format ? "large" : "small") + " fields)")
     << "\n"
     << " units: as the deck gives them (consistent set; SI: m, kg, s, Pa)\n\n"
     << " c o n t r o l   i n f o r m a t i o n\n\n";
  write_control_information(os, m);
  os << " m a t e r i a l s\n\n";
  for (const auto& md : m.materials) write_material(os, m, md);
  write_rigid_walls(os, m);
  write_card_echo(os, m);
  write_constraints(os, m);
  write_shells(os, m);
  write_interfaces(os, m);
  write_force_transducers(os, m);
  write_initial_velocities(os, m);
  write_loads(os, m);
  write_time_history_blocks(os, m);
}

void write_diagnostics(std::ostream& os, const Diagnostics& diag) { diag.print(os); }

}  // namespace impact3d
