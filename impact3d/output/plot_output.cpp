#include "impact3d/output/plot_output.h"

#include <algorithm>
#include <cmath>

#include "impact3d/element/beam_hl.h"
#include "impact3d/element/shell_bt.h"
#include "impact3d/init/beam_init.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

PlotGeometry make_plot_geometry(const Model& m) {
  PlotGeometry g;
  g.title = m.title;
  g.num_materials = int(m.materials.size());
  g.num_rigid_walls = int(m.walls.size());
  g.num_interfaces = m.num_interface_outputs();  // interfaces, then force transducers
  g.x0.resize(std::size_t(3) * m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i) {
    g.x0[std::size_t(3 * i)] = m.x[std::size_t(i)];
    g.x0[std::size_t(3 * i + 1)] = m.y[std::size_t(i)];
    g.x0[std::size_t(3 * i + 2)] = m.z[std::size_t(i)];
  }
  g.hex_nodes.resize(std::size_t(8) * m.num_hexes());
  g.hex_material.resize(std::size_t(m.num_hexes()));
  for (int e = 0; e < m.num_hexes(); ++e) {
    for (int j = 0; j < 8; ++j) g.hex_nodes[std::size_t(8 * e + j)] = m.hex_nodes[std::size_t(e)][std::size_t(j)];
    g.hex_material[std::size_t(e)] = m.hex_material[std::size_t(e)] + 1;
  }
  g.shell_nodes.resize(std::size_t(4) * m.num_shells());
  g.shell_material.resize(std::size_t(m.num_shells()));
  for (int k = 0; k < m.num_shells(); ++k) {
    for (int j = 0; j < 4; ++j) g.shell_nodes[std::size_t(4 * k + j)] = m.shell_nodes[std::size_t(k)][std::size_t(j)];
    g.shell_material[std::size_t(k)] = m.shell_material[std::size_t(k)] + 1;
  }
  if (!m.shell_user_id.empty()) g.shell_user_ids = m.shell_user_id;
  // beams: n1 n2, the orientation node, material; the records hold the most points any beam
  // section has (beam_plot_points)
  g.beam_nodes.resize(std::size_t(2) * m.num_beams());
  g.beam_orientation.resize(std::size_t(m.num_beams()));
  g.beam_material.resize(std::size_t(m.num_beams()));
  for (int b = 0; b < m.num_beams(); ++b) {
    for (int j = 0; j < 2; ++j) g.beam_nodes[std::size_t(2 * b + j)] = m.beam_nodes[std::size_t(b)][std::size_t(j)];
    g.beam_orientation[std::size_t(b)] = m.beam_nodes[std::size_t(b)][2];
    g.beam_material[std::size_t(b)] = m.beam_material[std::size_t(b)] + 1;
  }
  if (!m.beam_user_id.empty()) g.beam_user_ids = m.beam_user_id;
  g.beam_points = beam_plot_points(m);
  // the materials' history values (NEIPH): as many as the most any solid's material has, the
  // same count as State::hist_stride
  for (int e = 0; e < m.num_hexes(); ++e)
    g.num_solid_history = std::max(g.num_solid_history, material_history_count(m.materials[std::size_t(m.hex_material[std::size_t(e)])]));
  for (const auto& md : m.materials)
    g.part_titles.push_back(md.title.empty() ? "material " + std::to_string(md.number) : md.title.substr(0, 72));
  // the deck's numbers (NARBS section), so readers show them
  if (!m.node_user_id.empty()) g.node_user_ids = m.node_user_id;
  if (!m.hex_user_id.empty()) g.hex_user_ids = m.hex_user_id;
  return g;
}

namespace {

// A corner's share (mass mc at node i) of material k's kinetic energy and momentum.
void add_corner_motion(const State& s, std::size_t i, double mc, std::size_t k, PlotState& ps) {
  ps.mat_kinetic_energy[k] += 0.5 * mc * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
  ps.mat_velocity[3 * k] += mc * s.vx[i];
  ps.mat_velocity[3 * k + 1] += mc * s.vy[i];
  ps.mat_velocity[3 * k + 2] += mc * s.vz[i];
}

// An element of material k and mass me: its mass booked to the material, mc (its share) at
// each of its n nodes.
void add_element_motion(const State& s, std::size_t k, double me, double mc, const int* nodes, int n, PlotState& ps) {
  ps.mat_mass[k] += me;
  for (int j = 0; j < n; ++j) add_corner_motion(s, std::size_t(nodes[j]), mc, k, ps);
}

// The nodes of the interface sides written to the interface-force database (intfor_slave,
// intfor_master), in increasing order, each once.
std::vector<int> intfor_nodes(const Model& m) {
  std::vector<int> nodes;
  for (const SlidingInterface& si : m.interfaces)
    for (int sd = 0; sd < 2; ++sd)
      if (sd == 0 ? si.intfor_slave : si.intfor_master)
        for (const auto& sg : sd == 0 ? si.slave : si.master) nodes.insert(nodes.end(), sg.begin(), sg.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace

void fill_plot_globals(const Model& m, const State& s, const InterfaceForces& iface, PlotState& ps) {
  const std::size_t ne = std::size_t(s.ne), nm = m.materials.size();
  ps.time = s.time;
  ps.kinetic_energy = s.kinetic;
  ps.internal_energy = s.internal;
  ps.total_energy = s.total_energy();
  // per-material books from element-lumped masses (exact split of nodal mass by material)
  ps.mat_internal_energy.assign(nm, 0.0);
  ps.mat_kinetic_energy.assign(nm, 0.0);
  ps.mat_velocity.assign(3 * nm, 0.0);  // momentum first, divided by the mass below
  ps.mat_mass.assign(nm, 0.0);
  ps.mat_hourglass_energy.assign(nm, 0.0);
  for (std::size_t k = 0; k < nm && k < s.mat_internal.size(); ++k) {
    ps.mat_internal_energy[k] = s.mat_internal[k];
    ps.mat_hourglass_energy[k] = s.mat_hourglass[k];
  }
  for (std::size_t e = 0; e < ne; ++e)
    add_element_motion(s, std::size_t(s.mat[e]), s.mass_e[e], s.mass_e[e] / 8, s.conn[e].data(), 8, ps);
  // beams: rho A L0 each, half per end
  const BeamState& bm = s.beams;
  for (int q = 0; q < bm.nb; ++q) {
    const std::size_t k = std::size_t(bm.mat[std::size_t(q)]);
    const double me = s.mats[k].rho * bm.area[std::size_t(q)] * bm.length0[std::size_t(q)];
    add_element_motion(s, k, me, 0.5 * me, bm.conn[std::size_t(q)].data(), 2, ps);
  }
  // shells: rho h A0 each, a quarter per corner
  const ShellState& sh = s.shells;
  for (int q = 0; q < sh.ns; ++q) {
    const std::size_t k = std::size_t(sh.mat[std::size_t(q)]);
    const double me = s.mats[k].rho * sh.thick[std::size_t(q)] * sh.area0[std::size_t(q)];
    add_element_motion(s, k, me, 0.25 * me, sh.conn[std::size_t(q)].data(), 4, ps);
  }
  // whole-model velocity: total momentum over total mass
  double mtot = 0, p[3] = {0, 0, 0};
  for (std::size_t k = 0; k < nm; ++k) {
    mtot += ps.mat_mass[k];
    for (std::size_t a = 0; a < 3; ++a) p[a] += ps.mat_velocity[3 * k + a];
  }
  // per material: the mean velocity (what the d3plot layout holds; readers show it as the
  // part velocity)
  for (std::size_t k = 0; k < nm; ++k)
    for (std::size_t a = 0; a < 3; ++a)
      ps.mat_velocity[3 * k + a] = ps.mat_mass[k] > 0 ? ps.mat_velocity[3 * k + a] / ps.mat_mass[k] : 0.0;
  for (std::size_t a = 0; a < 3; ++a) ps.velocity[a] = mtot > 0 ? p[a] / mtot : 0;
  // rigid-wall normal force: the push of the body on the wall, positive in compression (as rwforc)
  ps.rigid_wall_forces.resize(m.walls.size());
  for (std::size_t w = 0; w < m.walls.size(); ++w) {
    const auto& sw = m.walls[w];
    const double n[3] = {sw.head[0] - sw.tail[0], sw.head[1] - sw.tail[1], sw.head[2] - sw.tail[2]};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const auto& F = s.wall_force[w];
    // a cylinder: the force's magnitude (its normal turns from node to node)
    ps.rigid_wall_forces[w] = sw.cylinder() ? std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2])
                                            : -(F[0] * n[0] + F[1] * n[1] + F[2] * n[2]) / l + 0.0;
  }
  // sliding interfaces: resultant force on the slave side, x y z (as rcforc); zero before the
  // first contact pass
  // first pass; then the force transducers' measured forces
  const std::size_t nif = std::size_t(m.num_interface_outputs());
  ps.interface_forces.assign(3 * nif, 0.0);
  for (std::size_t i = 0; i < nif && i < iface.size(); ++i)
    for (std::size_t a = 0; a < 3; ++a) ps.interface_forces[3 * i + a] = iface[i][a] + 0.0;
}

namespace {

// Local stress (xx yy xy yz zx, zz = 0) to global axes with the frame rows e1 e2 e3: xx yy zz
// xy yz zx.
void shell_stress_to_global(const double e[3][3], const double l[5], double* g) {
  const double t[3][3] = {{l[0], l[2], l[4]}, {l[2], l[1], l[3]}, {l[4], l[3], 0.0}};
  const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int c = 0; c < 6; ++c) {
    const int i = ij[c][0], j = ij[c][1];
    double v = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) v += e[a][i] * t[a][b] * e[b][j];
    g[c] = v;
  }
}

}  // namespace

// One shell's kShellPlotVars words (plot_database.h): surface stresses from the linear fit of
// the points (N/h + 12 M z / h^3: exact for an elastic section), the plastic strain of the
// lowest, middle and highest point, the resultants, thickness, energy.
void fill_shell_plot_vars(const State& s, int k, double* out) {
  const ShellState& sh = s.shells;
  const std::size_t K = std::size_t(k);
  const int nip = sh.nip[K];
  const double h = sh.thick[K];
  double zeta[kMaxShellIntegrationPoints], w[kMaxShellIntegrationPoints];
  gauss_legendre_rule(nip, zeta, w);
  double N[5] = {0, 0, 0, 0, 0}, M[3] = {0, 0, 0};
  for (int p = 0; p < nip; ++p) {
    double q[5];
    for (int c = 0; c < 5; ++c) q[c] = sh.sig[shell_sig_at(sh, k, p, c)];
    const double wz = 0.5 * h * w[p], z = 0.5 * h * zeta[p];
    for (int c = 0; c < 5; ++c) N[c] += wz * q[c];
    for (int c = 0; c < 3; ++c) M[c] += wz * z * q[c];
  }
  double x[4][3];
  for (int j = 0; j < 4; ++j) {
    const std::size_t n = std::size_t(sh.conn[K][std::size_t(j)]);
    x[j][0] = s.x[n];
    x[j][1] = s.y[n];
    x[j][2] = s.z[n];
  }
  ShellFrame fr;
  if (!calc_shell_frame(x, fr)) {
    for (int c = 0; c < 9; ++c) fr.e[c / 3][c % 3] = c % 4 == 0 ? 1.0 : 0.0;
  }
  const double zs[3] = {0.0, -0.5 * h, 0.5 * h};  // mid-surface, inner, outer
  const bool plastic = !sh.eps_p.empty();
  for (int layer = 0; layer < 3; ++layer) {
    double l[5];
    for (int c = 0; c < 3; ++c) l[c] = N[c] / h + 12.0 * M[c] * zs[layer] / (h * h * h);
    l[3] = N[3] / h;
    l[4] = N[4] / h;
    shell_stress_to_global(fr.e, l, out + 7 * layer);
    double ep = 0;
    if (plastic) {
      const int p = layer == 1 ? 0 : layer == 2 ? nip - 1 : nip / 2;
      ep = sh.eps_p[shell_point_at(sh, k, p)];
      if (layer == 0 && nip % 2 == 0) ep = 0.5 * (ep + sh.eps_p[shell_point_at(sh, k, p - 1)]);
    }
    out[7 * layer + 6] = ep;
  }
  const double res[8] = {M[0], M[1], M[2], N[4], N[3], N[0], N[1], N[2]};  // Mx My Mxy Qx Qy Nx Ny Nxy
  for (int c = 0; c < 8; ++c) out[21 + c] = res[c];
  out[29] = h;
  out[30] = 0;
  out[31] = 0;
  out[32] = sh.energy.empty() ? 0.0 : sh.energy[K];
}

int beam_plot_points(const Model& m) {
  int most = 0;
  std::vector<BeamRulePoint> rule;
  for (const MaterialData& md : m.materials) {
    if (!md.beam) continue;
    if (md.beam_section.elform == 3) most = std::max(most, 1);
    else if (md.beam_section.elform == 2) continue;  // resultants only
    else if (beam_integration_rule(md.beam_section, rule)) most = std::max(most, int(rule.size()));
  }
  return most;
}

void fill_beam_plot_vars(const State& s, int b, int points, double* out) {
  const BeamState& bm = s.beams;
  const std::size_t B = std::size_t(b);
  const double* r = &bm.res[6 * B];  // N Q_s Q_t T M_s M_t
  const double res[6] = {r[0], r[1], r[2], r[4], r[5], r[3]};
  for (int c = 0; c < 6; ++c) out[c] = res[c];
  const std::size_t ip0 = std::size_t(bm.ip_start[B]);
  const int np = bm.ip_start[B + 1] - bm.ip_start[B];
  for (int p = 0; p < points; ++p) {
    double* o = out + 6 + 5 * p;
    if (p >= np) {
      for (int c = 0; c < 5; ++c) o[c] = 0;
      continue;
    }
    const std::size_t q = ip0 + std::size_t(p);
    o[0] = bm.sig[3 * q + 1];
    o[1] = bm.sig[3 * q + 2];
    o[2] = bm.sig[3 * q];
    o[3] = bm.eps_p.empty() ? 0.0 : bm.eps_p[q];
    o[4] = bm.eps_rr.empty() ? 0.0 : bm.eps_rr[q];
  }
}

void fill_plot_state(const Model& m, const State& s, const InterfaceForces& iface, PlotState& ps) {
  const std::size_t nn = std::size_t(s.nn), ne = std::size_t(s.ne);
  fill_plot_globals(m, s, iface, ps);
  ps.coords.resize(3 * nn);
  ps.vel.resize(3 * nn);
  ps.acc.resize(3 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    ps.coords[3 * i] = s.x[i];
    ps.coords[3 * i + 1] = s.y[i];
    ps.coords[3 * i + 2] = s.z[i];
    ps.vel[3 * i] = s.vx[i];
    ps.vel[3 * i + 1] = s.vy[i];
    ps.vel[3 * i + 2] = s.vz[i];
    ps.acc[3 * i] = s.ax[i];
    ps.acc[3 * i + 1] = s.ay[i];
    ps.acc[3 * i + 2] = s.az[i];
  }
  ps.stress.assign(s.sig.begin(), s.sig.end());
  ps.eps.assign(s.eps_p.begin(), s.eps_p.end());
  ps.history.assign(s.hist.begin(), s.hist.end());  // hist_stride (= NEIPH) per solid
  ps.alive.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) ps.alive[e] = s.failed[e] ? 0 : 1;  // deleted solids: 0
  const std::size_t ns = std::size_t(s.shells.ns);
  ps.shell_vars.resize(std::size_t(kShellPlotVars) * ns);
  for (std::size_t k = 0; k < ns; ++k) fill_shell_plot_vars(s, int(k), &ps.shell_vars[std::size_t(kShellPlotVars) * k]);
  const std::size_t nb = std::size_t(s.beams.nb);
  const int points = beam_plot_points(m);
  const std::size_t nv1d = std::size_t(6 + 5 * points);
  ps.beam_vars.resize(nv1d * nb);
  for (std::size_t b = 0; b < nb; ++b) fill_beam_plot_vars(s, int(b), points, &ps.beam_vars[nv1d * b]);
  ps.beam_alive.assign(nb, 1);
  for (std::size_t b = 0; b < nb; ++b) ps.beam_alive[b] = s.beams.failed[b] ? 0 : 1;  // deleted beams: 0
  ps.shell_alive.assign(ns, 1);
  for (std::size_t k = 0; k < ns && k < s.shells.failed.size(); ++k) ps.shell_alive[k] = s.shells.failed[k] ? 0 : 1;
}

void PlotOutput::open(const Model& m, const std::string& root, int word_size,
                      std::int64_t member_words) {
  writer_.open(root, make_plot_geometry(m), word_size, member_words);
}

void PlotOutput::resume(const Model& m, const std::string& root, int word_size,
                        std::int64_t member_words, int keep_states) {
  writer_.resume(root, make_plot_geometry(m), word_size, member_words, keep_states);
}

void PlotOutput::write(const Model& m, const State& s, const InterfaceForces& iface) {
  fill_plot_state(m, s, iface, ps_);
  writer_.write_state(ps_);
  last_time_ = s.time;
}

// ---- the interface-force database (intfor)

bool IntforOutput::wanted(const Model& m) {
  if (m.control.intfor_interval < 0) return false;
  for (const SlidingInterface& si : m.interfaces)
    if (si.intfor_slave || si.intfor_master) return true;
  return false;
}

PlotGeometry IntforOutput::make_geometry(const Model& m) {
  PlotGeometry g;
  g.title = m.title;
  g.num_interfaces = m.num_interface_outputs();
  const std::vector<int> nodes = intfor_nodes(m);
  for (int n : nodes) {
    g.x0.insert(g.x0.end(), {m.x[std::size_t(n)], m.y[std::size_t(n)], m.z[std::size_t(n)]});
    g.node_user_ids.push_back(m.node_id(n));
  }
  auto local = [&](int n) { return int(std::lower_bound(nodes.begin(), nodes.end(), n) - nodes.begin()); };
  for (std::size_t i = 0; i < m.interfaces.size(); ++i)
    for (int sd = 0; sd < 2; ++sd) {
      const SlidingInterface& si = m.interfaces[i];
      if (!(sd == 0 ? si.intfor_slave : si.intfor_master)) continue;
      ++g.num_materials;
      g.part_titles.push_back("interface " + std::to_string(i + 1) + (sd == 0 ? " slave side" : " master side"));
      for (const auto& sg : sd == 0 ? si.slave : si.master) {
        for (int n : sg) g.shell_nodes.push_back(local(n));
        g.shell_material.push_back(g.num_materials);
        g.shell_user_ids.push_back(int(g.shell_user_ids.size()) + 1);
      }
    }
  return g;
}

void IntforOutput::prepare(const Model& m) {
  nodes_ = intfor_nodes(m);
  auto local = [&](int n) { return int(std::lower_bound(nodes_.begin(), nodes_.end(), n) - nodes_.begin()); };
  sides_.clear();
  int shell = 0;
  for (std::size_t i = 0; i < m.interfaces.size(); ++i)
    for (int sd = 0; sd < 2; ++sd) {
      const SlidingInterface& si = m.interfaces[i];
      if (!(sd == 0 ? si.intfor_slave : si.intfor_master)) continue;
      Side S;
      S.iface = i;
      S.side = sd;
      S.first_shell = shell;
      std::vector<int> surf;  // the contact surface's nodes (sorted, as SlidingInterfaces keeps them)
      for (const auto& sg : sd == 0 ? si.slave : si.master) {
        S.seg.push_back({local(sg[0]), local(sg[1]), local(sg[2]), local(sg[3])});
        surf.insert(surf.end(), sg.begin(), sg.end());
      }
      std::sort(surf.begin(), surf.end());
      surf.erase(std::unique(surf.begin(), surf.end()), surf.end());
      for (int n : surf) S.surf_node.push_back(local(n));
      shell += int(S.seg.size());
      sides_.push_back(std::move(S));
    }
  const std::size_t nn = nodes_.size();
  area_.assign(nn, 0.0);
  normal_.assign(3 * nn, 0.0);
  force_.assign(3 * nn, 0.0);
  ps_ = PlotState{};
  ps_.coords.assign(3 * nn, 0.0);
  ps_.vel.assign(3 * nn, 0.0);
  ps_.acc.assign(3 * nn, 0.0);
  ps_.shell_vars.assign(std::size_t(kShellPlotVars) * std::size_t(shell), 0.0);
  ps_.shell_alive.assign(std::size_t(shell), 1);
}

void IntforOutput::open(const Model& m, const std::string& root, int word_size, std::int64_t member_words) {
  prepare(m);
  writer_.open(root, make_geometry(m), word_size, member_words);
}

void IntforOutput::resume(const Model& m, const std::string& root, int word_size, std::int64_t member_words,
                          int keep_states) {
  prepare(m);
  writer_.resume(root, make_geometry(m), word_size, member_words, keep_states);
}

void IntforOutput::write(const Model& m, const State& s, const SlidingInterfaces& contact, const InterfaceForces& iface) {
  const std::size_t nn = nodes_.size();
  ps_.time = s.time;
  const std::size_t nif = std::size_t(m.num_interface_outputs());
  ps_.interface_forces.assign(3 * nif, 0.0);
  for (std::size_t i = 0; i < nif && i < iface.size(); ++i)
    for (std::size_t a = 0; a < 3; ++a) ps_.interface_forces[3 * i + a] = iface[i][a] + 0.0;
  for (std::size_t k = 0; k < nn; ++k) {
    const std::size_t n = std::size_t(nodes_[k]);
    const double x[3] = {s.x[n], s.y[n], s.z[n]}, v[3] = {s.vx[n], s.vy[n], s.vz[n]};
    for (std::size_t a = 0; a < 3; ++a) {
      ps_.coords[3 * k + a] = x[a];
      ps_.vel[3 * k + a] = v[a];
      ps_.acc[3 * k + a] = 0.0;
    }
  }
  for (const Side& S : sides_) {
    // this side's nodal forces, tributary areas and normals at the current positions
    const std::vector<double>& f = contact.surface_node_forces(S.iface, S.side);
    for (int k : S.surf_node) {
      area_[std::size_t(k)] = 0.0;
      for (std::size_t a = 0; a < 3; ++a) normal_[3 * std::size_t(k) + a] = force_[3 * std::size_t(k) + a] = 0.0;
    }
    for (std::size_t q = 0; q < S.surf_node.size() && 3 * q + 2 < f.size(); ++q) {
      const std::size_t k = std::size_t(S.surf_node[q]);
      for (std::size_t a = 0; a < 3; ++a) {
        force_[3 * k + a] = f[3 * q + a];
        ps_.acc[3 * k + a] += f[3 * q + a];
      }
    }
    for (const auto& sg : S.seg) {
      const double* c[4];
      for (int j = 0; j < 4; ++j) c[j] = &ps_.coords[3 * std::size_t(sg[std::size_t(j)])];
      const double d1[3] = {c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]};
      const double d2[3] = {c[3][0] - c[1][0], c[3][1] - c[1][1], c[3][2] - c[1][2]};
      const double an[3] = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                            0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};  // area x outward normal
      for (int j = 0; j < 4; ++j) {
        const std::size_t k = std::size_t(sg[std::size_t(j)]);
        area_[k] += 0.25 * std::sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        for (std::size_t a = 0; a < 3; ++a) normal_[3 * k + a] += 0.25 * an[a];
      }
    }
    // per segment: the mean of its corners' pressure (compression positive) and shear traction
    for (std::size_t e = 0; e < S.seg.size(); ++e) {
      double p = 0, tau = 0;
      for (int j = 0; j < 4; ++j) {
        const std::size_t k = std::size_t(S.seg[e][std::size_t(j)]);
        const double* nv = &normal_[3 * k];
        const double ln = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (!(area_[k] > 0) || !(ln > 0)) continue;
        const double* fk = &force_[3 * k];
        const double fn = (fk[0] * nv[0] + fk[1] * nv[1] + fk[2] * nv[2]) / ln;  // along the outward normal
        const double ft[3] = {fk[0] - fn * nv[0] / ln, fk[1] - fn * nv[1] / ln, fk[2] - fn * nv[2] / ln};
        p += 0.25 * (-fn) / area_[k];
        tau += 0.25 * std::sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]) / area_[k];
      }
      double* out = &ps_.shell_vars[std::size_t(kShellPlotVars) * (std::size_t(S.first_shell) + e)];
      for (int layer = 0; layer < 3; ++layer) {
        out[7 * layer] = out[7 * layer + 1] = out[7 * layer + 2] = -p + 0.0;
        out[7 * layer + 3] = tau;
      }
    }
  }
  writer_.write_state(ps_);
  last_time_ = s.time;
}

}  // namespace impact3d
