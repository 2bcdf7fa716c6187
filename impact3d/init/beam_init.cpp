#include "impact3d/init/beam_init.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "impact3d/material/material_types.h"
#include "impact3d/init/corner_map.h"

namespace impact3d {

namespace {

// The one table of material types that beams take (a rigid type's beams join its rigid body).
struct BeamMaterial {
  int type;
  bool rigid;
  BeamMaterialKind kind;
};
constexpr BeamMaterial kBeamMaterials[] = {
    {1, false, BeamMaterialKind::elastic},
    {3, false, BeamMaterialKind::plastic_kinematic},
    {20, true, BeamMaterialKind::elastic},
    {24, false, BeamMaterialKind::piecewise_linear},
    {100, false, BeamMaterialKind::plastic_kinematic},  // *MAT_SPOTWELD: isotropic (beta 1), its failure rule
};

const BeamMaterial* find_beam_material(int type) {
  for (const BeamMaterial& b : kBeamMaterials)
    if (b.type == type) return &b;
  return nullptr;
}

double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

bool has_beam_kernel(int type) { return find_beam_material(type) != nullptr; }

// The material types of the family's table, in its order.
static std::vector<int> beam_material_types() {
  std::vector<int> types;
  for (const BeamMaterial& m : kBeamMaterials) types.push_back(m.type);
  return types;
}

std::string beam_material_keywords() { return keywords_of_types(beam_material_types()); }

std::string beam_material_numbers() { return numbers_of_types(beam_material_types()); }

BeamSectionSize beam_section_size(const Model& m, int b) {
  const BeamSectionData& sec = m.materials[std::size_t(m.beam_material[std::size_t(b)])].beam_section;
  std::array<double, 4> t = {sec.ts1, sec.ts2, sec.tt1, sec.tt2};
  if (std::size_t(b) < m.beam_thickness.size()) {
    const auto& e = m.beam_thickness[std::size_t(b)];
    if (e[0] != 0 || e[1] != 0 || e[2] != 0 || e[3] != 0) t = e;
  }
  BeamSectionSize sz;
  sz.cst = sec.cst;
  sz.ts = 0.5 * (t[0] + t[1]);
  sz.tt = 0.5 * (t[2] + t[3]);
  return sz;
}

double beam_area(const Model& m, int b) {
  const BeamSectionData& sec = m.materials[std::size_t(m.beam_material[std::size_t(b)])].beam_section;
  if (sec.elform != 1) return sec.area;
  return beam_section_properties(beam_section_size(m, b)).area;
}

const double* beam_orientation_vector(const Model& m, int b) {
  if (m.beam_orientation.empty()) return nullptr;
  const auto& v = m.beam_orientation[std::size_t(b)];
  return v[0] != 0 || v[1] != 0 || v[2] != 0 ? v.data() : nullptr;
}

bool beam_initial_s_axis(const Model& m, int b, double s[3]) {
  const auto& c = m.beam_nodes[std::size_t(b)];
  const std::size_t n1 = std::size_t(c[0]), n2 = std::size_t(c[1]);
  double r[3] = {m.x[n2] - m.x[n1], m.y[n2] - m.y[n1], m.z[n2] - m.z[n1]};
  const double L = std::sqrt(dot3(r, r));
  if (!(L > 0)) return false;
  for (double& v : r) v /= L;
  double g[3] = {0, 0, 0};
  if (c[2] >= 0) {
    const std::size_t n3 = std::size_t(c[2]);
    g[0] = m.x[n3] - m.x[n1];
    g[1] = m.y[n3] - m.y[n1];
    g[2] = m.z[n3] - m.z[n1];
  } else if (const double* v = beam_orientation_vector(m, b)) {
    for (int k = 0; k < 3; ++k) g[k] = v[k];
  } else {
    int a = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(r[k]) < std::fabs(r[a])) a = k;
    g[a] = 1;
  }
  return beam_s_axis(r, g, s);
}

double beam_rotary_inertia(double beam_mass, double length0, const BeamSectionProperties& p) {
  const double rg2 = p.area > 0 ? (p.i_s + p.i_t) / p.area : 0.0;
  return 0.5 * beam_mass * (0.25 * length0 * length0 + rg2);
}

double resultant_beam_step_scale(const MaterialConstants& mc, const BeamResultantSection& sec, double length0,
                                 double beam_mass, double node_inertia) {
  const double L = length0, m = beam_mass, J = node_inertia;
  const double axial = 4 * mc.E * sec.area / (L * m);
  const double imax = std::max(sec.iss, sec.itt);
  const double bending = 12 * mc.E * imax / L * (4 / (L * L * m) + 1 / (2 * J));
  const double bending2 = 2 * mc.E * imax / (L * J);
  const double torsion = 2 * mc.G * sec.jt / (L * J);
  const double w2 = std::max({axial, bending, bending2, torsion});
  return axial > 0 ? std::max(1.0, std::sqrt(w2 / axial)) : 1.0;
}

namespace {

// The node -> corner map with the beams' ends after the solids' and shells' corners at each node.
void add_beam_corners(State& s) {
  const BeamState& bm = s.beams;
  append_corners(s.corner_start, s.corner_list, s.nn, bm.nb, 2, bm.corner_base,
                 [&](int b, int j) { return bm.conn[std::size_t(b)][std::size_t(j)]; });
}

// Whether beam b acts on the rotations of its nodes: a deformable Hughes-Liu beam.
bool beam_turns_nodes(const Model& m, const BeamState& bm, int b) {
  return !bm.rigid_elem[std::size_t(b)] && m.materials[std::size_t(bm.mat[std::size_t(b)])].beam_section.elform != 3;
}

// The rotational degrees of freedom of the shells' nodes and of the nodes of deformable
// Hughes-Liu beams, renumbered in node order; each keeps the shells' corners (in their order)
// and then the beams' ends.  beam_inertia: per node, the beams' rotary inertia.
void merge_beam_rotations(const Model& m, State& s, const std::vector<double>& beam_inertia,
                          const std::vector<char>& beam_uses) {
  ShellState& sh = s.shells;
  const BeamState& bm = s.beams;
  const std::size_t nn = std::size_t(s.nn);
  std::vector<double> inertia(nn, 0.0);
  std::vector<int> old_of_node(nn, -1);
  for (int r = 0; r < sh.nr; ++r) {
    old_of_node[std::size_t(sh.rot_node[std::size_t(r)])] = r;
    inertia[std::size_t(sh.rot_node[std::size_t(r)])] = sh.inertia[std::size_t(r)];
  }
  const std::vector<int> old_start = sh.rot_corner_start, old_list = sh.rot_corner_list;
  sh.node_rot.assign(nn, -1);
  sh.rot_node.clear();
  for (std::size_t i = 0; i < nn; ++i)
    if (old_of_node[i] >= 0 || beam_uses[i]) {
      sh.node_rot[i] = int(sh.rot_node.size());
      sh.rot_node.push_back(int(i));
    }
  sh.nr = int(sh.rot_node.size());
  for (auto* v : {&sh.wx, &sh.wy, &sh.wz, &sh.inertia}) v->assign(std::size_t(sh.nr), 0.0);
  sh.rot_fix.assign(std::size_t(sh.nr), 0);
  std::vector<int> beam_count(std::size_t(sh.nr), 0);
  for (int b = 0; b < bm.nb; ++b)
    if (beam_turns_nodes(m, bm, b))
      for (int j = 0; j < 2; ++j) ++beam_count[std::size_t(sh.node_rot[std::size_t(bm.conn[std::size_t(b)][std::size_t(j)])])];
  sh.rot_corner_start.assign(std::size_t(sh.nr) + 1, 0);
  for (int r = 0; r < sh.nr; ++r) {
    const std::size_t n = std::size_t(sh.rot_node[std::size_t(r)]);
    sh.inertia[std::size_t(r)] = inertia[n] + beam_inertia[n];
    if (!m.rot_bc.empty()) sh.rot_fix[std::size_t(r)] = m.rot_bc[n];
    const int o = old_of_node[n];
    const int old_count = o >= 0 ? old_start[std::size_t(o) + 1] - old_start[std::size_t(o)] : 0;
    sh.rot_corner_start[std::size_t(r) + 1] = sh.rot_corner_start[std::size_t(r)] + old_count + beam_count[std::size_t(r)];
  }
  sh.rot_corner_list.assign(std::size_t(sh.rot_corner_start[std::size_t(sh.nr)]), 0);
  std::vector<int> fill(std::size_t(sh.nr));
  for (int r = 0; r < sh.nr; ++r) {
    int f = sh.rot_corner_start[std::size_t(r)];
    const int o = old_of_node[std::size_t(sh.rot_node[std::size_t(r)])];
    if (o >= 0)
      for (int c = old_start[std::size_t(o)]; c < old_start[std::size_t(o) + 1]; ++c)
        sh.rot_corner_list[std::size_t(f++)] = old_list[std::size_t(c)];
    fill[std::size_t(r)] = f;
  }
  for (int b = 0; b < bm.nb; ++b)
    if (beam_turns_nodes(m, bm, b))
      for (int j = 0; j < 2; ++j) {
        const int r = sh.node_rot[std::size_t(bm.conn[std::size_t(b)][std::size_t(j)])];
        sh.rot_corner_list[std::size_t(fill[std::size_t(r)]++)] = int(bm.moment_base + 2 * std::size_t(b) + std::size_t(j));
      }
}

// What the beam groups need stored per point or per beam.
struct BeamStorageNeeds {
  bool plastic = false, kinematic = false, resultant = false;
};

// The group of one material's beams: its kernel (rigid, truss, resultant or Hughes-Liu) and
// section rule.
BeamGroup make_beam_group(const Model& m, const State& s, std::size_t k) {
  const MaterialData& md = m.materials[k];
  const BeamMaterial* bmat = find_beam_material(s.mats[k].type);
  BeamGroup g;
  g.material = int(k);
  g.shrf = md.beam_section.shrf > 0 ? md.beam_section.shrf : 1.0;
  g.material_kind = bmat ? bmat->kind : BeamMaterialKind::elastic;
  g.spot_weld = s.mats[k].type == 100;
  if (!bmat || bmat->rigid) {
    g.kernel = BeamKernel::rigid;
  } else if (md.beam_section.elform == 3) {
    g.kernel = BeamKernel::truss;
    g.rule.push_back({0, 0, 4});
  } else if (md.beam_section.elform == 2) {
    g.kernel = BeamKernel::resultant;  // no section points: 6 resultants per beam (BeamState::bs)
  } else {
    g.kernel = BeamKernel::hughes_liu;
    beam_integration_rule(md.beam_section, g.rule);
  }
  return g;
}

// Groups: one per material with beams, in material order; the beams in group order (bm.order)
// and their integration points (bm.ip_start).
BeamStorageNeeds group_beams(const Model& m, const State& s, BeamState& bm) {
  const int nb = bm.nb;
  std::vector<int> count(s.mats.size(), 0);
  for (int b = 0; b < nb; ++b) ++count[std::size_t(bm.mat[std::size_t(b)])];
  std::vector<int> first(s.mats.size(), 0), points_of_material(s.mats.size(), 0);
  int placed = 0;
  BeamStorageNeeds need;
  for (std::size_t k = 0; k < s.mats.size(); ++k) {
    if (count[k] == 0) continue;
    BeamGroup g = make_beam_group(m, s, k);
    g.first = placed;
    g.count = count[k];
    first[k] = placed;
    placed += count[k];
    points_of_material[k] = int(g.rule.size());
    need.resultant = need.resultant || g.kernel == BeamKernel::resultant;
    need.plastic = need.plastic || (g.kernel != BeamKernel::rigid && g.material_kind != BeamMaterialKind::elastic);
    need.kinematic = need.kinematic || (g.kernel != BeamKernel::rigid && g.material_kind == BeamMaterialKind::plastic_kinematic);
    bm.groups.push_back(std::move(g));
  }
  bm.order.assign(std::size_t(nb), 0);
  for (int b = 0; b < nb; ++b) bm.order[std::size_t(first[std::size_t(bm.mat[std::size_t(b)])]++)] = b;
  bm.ip_start.assign(std::size_t(nb) + 1, 0);
  for (int b = 0; b < nb; ++b)
    bm.ip_start[std::size_t(b) + 1] = bm.ip_start[std::size_t(b)] + points_of_material[std::size_t(bm.mat[std::size_t(b)])];
  return need;
}

// *MAT_SPOTWELD NF: room for each such beam's last NF resultant vectors.
void allocate_weld_filters(const State& s, BeamState& bm) {
  const int nb = bm.nb;
  bool filtered = false;
  for (const BeamGroup& g : bm.groups) filtered = filtered || (g.spot_weld && s.mats[std::size_t(g.material)].k[kSpotWeldNF] > 0);
  bm.weld_res_start.assign(filtered ? std::size_t(nb) + 1 : 0, 0);
  bm.weld_res_count.assign(filtered ? std::size_t(nb) : 0, 0);
  if (filtered)
    for (int b = 0; b < nb; ++b) {
      const MaterialConstants& mc = s.mats[std::size_t(bm.mat[std::size_t(b)])];
      const int nf = mc.type == 100 ? int(mc.k[kSpotWeldNF]) : 0;
      bm.weld_res_start[std::size_t(b) + 1] = bm.weld_res_start[std::size_t(b)] + 6 * nf;
    }
  bm.weld_res.assign(filtered ? std::size_t(bm.weld_res_start[std::size_t(nb)]) : 0, 0.0);
}

// The per-point and per-beam arrays, allocated once.
void allocate_beam_state(const State& s, const BeamStorageNeeds& need, BeamState& bm) {
  const std::size_t nb = std::size_t(bm.nb);
  const std::size_t npt = std::size_t(bm.ip_start[nb]);
  bm.sig.assign(3 * npt, 0.0);
  bm.eps_rr.assign(npt, 0.0);
  bm.back.assign(need.kinematic ? 6 * npt : 0, 0.0);
  bm.eps_p.assign(need.plastic ? npt : 0, 0.0);
  bm.yielded.assign(need.plastic ? npt : 0, 0);
  bm.res.assign(6 * nb, 0.0);
  bm.bs.assign(need.resultant ? 6 * nb : 0, 0.0);
  bm.rsec.assign(need.resultant ? nb : 0, BeamResultantSection{});
  bm.step_scale.assign(nb, 1.0);
  for (auto* v : {&bm.dt_e, &bm.de_ie, &bm.energy, &bm.area, &bm.length0}) v->assign(nb, 0.0);
  bm.e2.assign(3 * nb, 0.0);
  bm.bad.assign(nb, 0);
  bm.failed.assign(nb, 0);
  bm.newly_failed.clear();
  bm.newly_failed.reserve(nb);
  allocate_weld_filters(s, bm);
  bm.rigid_elem.assign(nb, 0);
  bm.size.assign(nb, BeamSectionSize{});
}

// Beam b's section, length and s axis; half its mass to each node; for a deformable beam (not a
// truss) its rotary inertia J to each node's (beam_inertia, beam_uses) and, ELFORM 2, its step scale.
void init_beam_geometry(const Model& m, State& s, int b, std::vector<double>& beam_inertia, std::vector<char>& beam_uses) {
  BeamState& bm = s.beams;
  const std::size_t B = std::size_t(b);
  const int mat = bm.mat[B];
  const BeamSectionData& sec = m.materials[std::size_t(mat)].beam_section;
  const MaterialConstants& mc = s.mats[std::size_t(mat)];
  const BeamMaterial* bmat = find_beam_material(mc.type);
  const bool rigid = !bmat || bmat->rigid;
  const bool truss = sec.elform == 3;
  bm.rigid_elem[B] = rigid;
  bm.size[B] = beam_section_size(m, b);
  bm.area[B] = beam_area(m, b);
  const auto& c = bm.conn[B];
  const std::size_t n1 = std::size_t(c[0]), n2 = std::size_t(c[1]);
  const double dx = s.x[n2] - s.x[n1], dy = s.y[n2] - s.y[n1], dz = s.z[n2] - s.z[n1];
  bm.length0[B] = std::sqrt(dx * dx + dy * dy + dz * dz);
  double e2[3] = {0, 0, 0};
  beam_initial_s_axis(m, b, e2);  // the input checks refuse a beam without one
  for (int a = 0; a < 3; ++a) bm.e2[3 * B + std::size_t(a)] = e2[a];
  const double me = mc.rho * bm.area[B] * bm.length0[B];
  s.mass[n1] += 0.5 * me;
  s.mass[n2] += 0.5 * me;
  bm.dt_e[B] = std::numeric_limits<double>::infinity();
  if (rigid || truss) return;
  BeamSectionProperties props = beam_section_properties(bm.size[B]);
  if (sec.elform == 2) {
    props = BeamSectionProperties{sec.area, sec.iss, sec.itt};
    if (!bm.rsec.empty()) bm.rsec[B] = BeamResultantSection{sec.area, sec.iss, sec.itt, sec.jt > 0 ? sec.jt : sec.iss + sec.itt};
  }
  const double J = beam_rotary_inertia(me, bm.length0[B], props);
  for (std::size_t n : {n1, n2}) {
    beam_inertia[n] += J;
    beam_uses[n] = 1;
  }
  if (sec.elform == 2) bm.step_scale[B] = resultant_beam_step_scale(mc, bm.rsec[B], bm.length0[B], me, J);
}

}  // namespace

void init_beams(const Model& m, State& s) {
  BeamState& bm = s.beams;
  bm = BeamState{};
  const int nb = m.num_beams();
  bm.nb = nb;
  if (nb == 0) return;
  bm.conn = m.beam_nodes;
  bm.mat = m.beam_material;
  const BeamStorageNeeds need = group_beams(m, s, bm);
  allocate_beam_state(s, need, bm);
  // geometry, masses, rotary inertias
  std::vector<double> beam_inertia(std::size_t(s.nn), 0.0);
  std::vector<char> beam_uses(std::size_t(s.nn), 0);
  for (int b = 0; b < nb; ++b) init_beam_geometry(m, s, b, beam_inertia, beam_uses);
  bm.length = bm.length0;
  // end forces and moments
  bm.corner_base = s.cfx.size();
  for (auto* v : {&s.cfx, &s.cfy, &s.cfz}) v->resize(bm.corner_base + 2 * std::size_t(nb), 0.0);
  ShellState& sh = s.shells;
  bm.moment_base = sh.cmx.size();
  for (auto* v : {&sh.cmx, &sh.cmy, &sh.cmz}) v->resize(bm.moment_base + 2 * std::size_t(nb), 0.0);
  add_beam_corners(s);
  merge_beam_rotations(m, s, beam_inertia, beam_uses);
}

}  // namespace impact3d
