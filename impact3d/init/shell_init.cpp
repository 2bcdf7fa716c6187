#include "impact3d/init/shell_init.h"

#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "impact3d/element/shell_fi.h"
#include "impact3d/init/corner_map.h"

namespace impact3d {

namespace {

// The one table of material types that shells take: type, kernel, and the type's fields that
// shells refuse when nonzero (message 1102) with the feature's name.
struct ShellMaterial {
  int type;
  ShellKernel kernel;
  const char* refused_field;
  const char* refused_feature;
};
constexpr ShellMaterial kShellMaterials[] = {
    {1, ShellKernel::elastic, nullptr, nullptr},
    {3, ShellKernel::plastic_kinematic, nullptr, nullptr},
    {18, ShellKernel::power_law, nullptr, nullptr},
    {20, ShellKernel::rigid, nullptr, nullptr},
    {24, ShellKernel::piecewise_linear, nullptr, nullptr},
    {27, ShellKernel::mooney_rivlin, nullptr, nullptr},
};

const ShellMaterial* find_shell_material(int type) {
  for (const ShellMaterial& s : kShellMaterials)
    if (s.type == type) return &s;
  return nullptr;
}

}  // namespace

bool has_shell_kernel(int type) { return find_shell_material(type) != nullptr; }

ShellKernel shell_kernel_for_material_type(int type) {
  if (const ShellMaterial* s = find_shell_material(type)) return s->kernel;
  throw std::logic_error("no shell kernel for material type " + std::to_string(type));
}

// The material types of the family's table, in its order.
static std::vector<int> shell_material_types() {
  std::vector<int> types;
  for (const ShellMaterial& m : kShellMaterials) types.push_back(m.type);
  return types;
}

std::string shell_material_keywords() { return keywords_of_types(shell_material_types()); }

std::string shell_material_numbers() { return numbers_of_types(shell_material_types()); }

const MaterialParam* refused_shell_param(const MaterialData& md, const char** feature) {
  const ShellMaterial* s = find_shell_material(md.type);
  if (!s || !s->refused_field) return nullptr;
  const MaterialParam* p = find_param(material_type(md.type), s->refused_field);
  if (!p || param_value(md, *p) == 0) return nullptr;
  *feature = s->refused_feature;
  return p;
}

double shell_rotary_inertia(double corner_mass, double h, double area) {
  return corner_mass * std::max(h * h / 12.0, area / 8.0);
}

double corner_fraction(const std::array<int, 4>& c, int j) {
  if (c[2] != c[3]) return 0.25;
  return j < 2 ? 1.0 / 3.0 : 1.0 / 6.0;
}

namespace {

ShellGroupConstants group_constants(const MaterialData& md, const MaterialConstants& mc) {
  ShellGroupConstants g;
  g.nip = md.shell_section.nip;
  gauss_legendre_rule(g.nip, g.zeta, g.weight);
  g.shrf = md.shell_section.shrf;
  g.hourglass_type = md.hourglass_type;
  g.hourglass_coef = md.hourglass_coef;
  g.rho = mc.rho;
  g.E = mc.E;
  g.nu = mc.nu;
  g.G = mc.G;
  g.c_plate = mc.rho > 0 ? std::sqrt(mc.E / (mc.rho * (1 - mc.nu * mc.nu))) : 0.0;
  g.drill_coef = kShellDrillingCoef;
  g.elform = md.shell_section.elform;
  if (g.elform == 16) g.hourglass_coef = 0;  // no hourglass modes: the part's settings are ignored
  return g;
}

void shell_coordinates(const State& s, int k, double x[4][3]) {
  for (int j = 0; j < 4; ++j) {
    const std::size_t n = std::size_t(s.shells.conn[std::size_t(k)][std::size_t(j)]);
    x[j][0] = s.x[n];
    x[j][1] = s.y[n];
    x[j][2] = s.z[n];
  }
}


// The node -> corner map with the shells' corners after the solids' ones at each node.
void add_shell_corners(State& s) {
  const ShellState& sh = s.shells;
  append_corners(s.corner_start, s.corner_list, s.nn, sh.ns, 4, sh.corner_base,
                 [&](int k, int j) { return sh.conn[std::size_t(k)][std::size_t(j)]; });
}

// The points' layout (the table in model/shell_state.h): run after run in the groups' order,
// a group in blocks one run of width kLanes per whole block, every other shell a run of width 1;
// and the blocks' corner nodes in block order (ShellState::block_nodes).  Returns the number of
// points.
std::size_t lay_out_shell_points(ShellState& sh, const std::vector<int>& points) {
  sh.block_nodes.assign(4 * std::size_t(sh.ns), -1);
  sh.pt_base.assign(std::size_t(sh.ns), 0);
  sh.pt_lane.assign(std::size_t(sh.ns), 0);
  sh.pt_width.assign(std::size_t(sh.ns), 1);
  std::size_t next = 0;
  auto run = [&](const int* ord, int width) {
    for (int l = 0; l < width; ++l) {
      const std::size_t k = std::size_t(ord[l]);
      sh.pt_base[k] = int(next);
      sh.pt_lane[k] = std::uint8_t(l);
      sh.pt_width[k] = std::uint8_t(width);
    }
    next += std::size_t(width) * std::size_t(points[std::size_t(ord[0])]);  // a group's shells: one section
    if (width == kLanes) {
      int* bn = &sh.block_nodes[4 * std::size_t(ord - sh.order.data())];
      for (int j = 0; j < 4; ++j)
        for (int l = 0; l < kLanes; ++l) bn[kLanes * j + l] = sh.conn[std::size_t(ord[l])][std::size_t(j)];
    }
  };
  for (const ShellGroup& g : sh.groups) {
    const int* ord = &sh.order[std::size_t(g.first)];
    const int nb = g.blocks ? g.count / kLanes : 0;
    for (int q = 0; q < nb; ++q) run(ord + q * kLanes, kLanes);
    for (int q = nb * kLanes; q < g.count; ++q) run(ord + q, 1);
  }
  return next;
}

}  // namespace

void init_shells(const Model& m, State& s) {
  ShellState& sh = s.shells;
  sh = ShellState{};
  const int ns = m.num_shells();
  sh.ns = ns;
  if (ns == 0) return;
  sh.conn = m.shell_nodes;
  sh.mat = m.shell_material;
  sh.thick.assign(std::size_t(ns), 0.0);
  sh.area0.assign(std::size_t(ns), 0.0);
  // groups: one per material with shells, in material order
  std::vector<int> count(s.mats.size(), 0);
  for (int k = 0; k < ns; ++k) ++count[std::size_t(sh.mat[std::size_t(k)])];
  std::vector<int> first(s.mats.size(), 0);
  int placed = 0;
  bool plastic = false, kinematic = false, hg_state = false;
  for (std::size_t k = 0; k < s.mats.size(); ++k) {
    if (count[k] == 0) continue;
    ShellGroup g;
    g.kernel = shell_kernel_for_material_type(s.mats[k].type);
    g.material = int(k);
    g.constants = group_constants(m.materials[k], s.mats[k]);
    g.blocks = g.kernel != ShellKernel::rigid && g.constants.elform == 2 &&
               shell_block_covers(shell_material_kind(g.kernel), s.mats[k]);
    g.update_block = material_type(s.mats[k].type).solid.update_block;
    g.first = placed;
    g.count = count[k];
    first[k] = placed;
    placed += count[k];
    plastic = plastic || shell_kernel_is_plastic(g.kernel);
    kinematic = kinematic || shell_kernel_has_back(g.kernel);
    hg_state = hg_state || (g.kernel != ShellKernel::rigid && g.constants.hourglass_coef > 0);
    sh.groups.push_back(g);
  }
  sh.order.assign(std::size_t(ns), 0);
  for (int k = 0; k < ns; ++k) sh.order[std::size_t(first[std::size_t(sh.mat[std::size_t(k)])]++)] = k;
  // integration points
  sh.nip.assign(std::size_t(ns), 0);
  std::vector<int> points(std::size_t(ns), 0);
  for (int k = 0; k < ns; ++k) {
    const ShellSectionData& sec = m.materials[std::size_t(sh.mat[std::size_t(k)])].shell_section;
    sh.nip[std::size_t(k)] = sec.nip;  // through the thickness (ELFORM 16: times 5 sets, shell_fi.h)
    points[std::size_t(k)] = shell_points_per_shell(sec.elform, sec.nip);
  }
  const std::size_t nip_total = lay_out_shell_points(sh, points);
  sh.sig.assign(5 * nip_total, 0.0);
  sh.back.assign(kinematic ? 6 * nip_total : 0, 0.0);
  sh.eps_p.assign(plastic ? nip_total : 0, 0.0);
  sh.yielded.assign(plastic ? nip_total : 0, 0);
  sh.hgq.assign(hg_state ? 5 * std::size_t(ns) : 0, 0.0);
  sh.drill.assign(4 * std::size_t(ns), 0.0);
  for (auto* v : {&sh.dt_e, &sh.de_ie, &sh.de_hg, &sh.energy}) v->assign(std::size_t(ns), 0.0);
  sh.bad.assign(std::size_t(ns), 0);
  sh.rigid_elem.assign(std::size_t(ns), 0);
  sh.failed.assign(std::size_t(ns), 0);
  // geometry, masses; rotational dofs on the nodes of deformable shells
  sh.node_rot.assign(std::size_t(s.nn), -1);
  std::vector<double> inertia_of_node(std::size_t(s.nn), 0.0);
  std::vector<char> uses(std::size_t(s.nn), 0);
  for (int k = 0; k < ns; ++k) {
    const auto& th = m.shell_thickness[std::size_t(k)];
    const auto& c = sh.conn[std::size_t(k)];
    const bool tri = c[2] == c[3];
    const double h = tri ? (th[0] + th[1] + th[2]) / 3.0 : 0.25 * (th[0] + th[1] + th[2] + th[3]);
    sh.thick[std::size_t(k)] = h;
    double x[4][3];
    shell_coordinates(s, k, x);
    ShellFrame fr;
    calc_shell_frame(x, fr);
    sh.area0[std::size_t(k)] = fr.area;
    const MaterialConstants& mc = s.mats[std::size_t(sh.mat[std::size_t(k)])];
    const double me = mc.rho * h * fr.area;
    const bool rigid = shell_kernel_for_material_type(mc.type) == ShellKernel::rigid;
    sh.rigid_elem[std::size_t(k)] = rigid;
    if (rigid) sh.dt_e[std::size_t(k)] = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 4; ++j) {
      const std::size_t n = std::size_t(c[std::size_t(j)]);
      const double mj = me * corner_fraction(c, j);
      s.mass[n] += mj;
      inertia_of_node[n] += shell_rotary_inertia(mj, h, fr.area);
      if (!rigid) uses[n] = 1;
    }
  }
  sh.area = sh.area0;
  for (int i = 0; i < s.nn; ++i)
    if (uses[std::size_t(i)]) {
      sh.node_rot[std::size_t(i)] = int(sh.rot_node.size());
      sh.rot_node.push_back(i);
    }
  sh.nr = int(sh.rot_node.size());
  for (auto* v : {&sh.wx, &sh.wy, &sh.wz, &sh.inertia}) v->assign(std::size_t(sh.nr), 0.0);
  sh.rot_fix.assign(std::size_t(sh.nr), 0);
  for (int r = 0; r < sh.nr; ++r) {
    const std::size_t n = std::size_t(sh.rot_node[std::size_t(r)]);
    sh.inertia[std::size_t(r)] = m.shell_rotary_scale * inertia_of_node[n];
    if (!m.rot_bc.empty()) sh.rot_fix[std::size_t(r)] = m.rot_bc[n];
  }
  // rotational dof -> shell corners, in increasing (shell, corner) order
  sh.rot_corner_start.assign(std::size_t(sh.nr) + 1, 0);
  for (int k = 0; k < ns; ++k)
    if (!sh.rigid_elem[std::size_t(k)])
      for (int n : sh.conn[std::size_t(k)]) ++sh.rot_corner_start[std::size_t(sh.node_rot[std::size_t(n)]) + 1];
  for (int r = 0; r < sh.nr; ++r) sh.rot_corner_start[std::size_t(r) + 1] += sh.rot_corner_start[std::size_t(r)];
  sh.rot_corner_list.assign(std::size_t(sh.rot_corner_start[std::size_t(sh.nr)]), 0);
  std::vector<int> fill(sh.rot_corner_start.begin(), sh.rot_corner_start.end() - 1);
  for (int k = 0; k < ns; ++k)
    if (!sh.rigid_elem[std::size_t(k)])
      for (int j = 0; j < 4; ++j)
        sh.rot_corner_list[std::size_t(fill[std::size_t(sh.node_rot[std::size_t(sh.conn[std::size_t(k)][std::size_t(j)])])]++)] = 4 * k + j;
  // corner forces and moments
  sh.corner_base = s.cfx.size();
  for (auto* v : {&s.cfx, &s.cfy, &s.cfz}) v->resize(sh.corner_base + 4 * std::size_t(ns), 0.0);
  for (auto* v : {&sh.cmx, &sh.cmy, &sh.cmz}) v->assign(4 * std::size_t(ns), 0.0);
  add_shell_corners(s);
}

void init_shell_rotational_velocities(const Model& m, State& s) {
  ShellState& sh = s.shells;
  for (int r = 0; r < sh.nr; ++r) {
    const std::size_t n = std::size_t(sh.rot_node[std::size_t(r)]);
    if (!m.init_omega.empty()) {
      sh.wx[std::size_t(r)] = m.init_omega[n][0];
      sh.wy[std::size_t(r)] = m.init_omega[n][1];
      sh.wz[std::size_t(r)] = m.init_omega[n][2];
    }
    const std::uint8_t f = sh.rot_fix[std::size_t(r)];
    if (f & 1) sh.wx[std::size_t(r)] = 0;
    if (f & 2) sh.wy[std::size_t(r)] = 0;
    if (f & 4) sh.wz[std::size_t(r)] = 0;
  }
}

}  // namespace impact3d
