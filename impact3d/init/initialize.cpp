#include "impact3d/init/initialize.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "impact3d/element/hexahedron.h"
#include "impact3d/init/beam_init.h"
#include "impact3d/init/shell_init.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/element_groups.h"
#include "impact3d/solve/node_ties.h"

namespace impact3d {

namespace {

void init_nodes(const Model& m, State& s) {
  const int nn = m.num_nodes();
  s.nn = nn;
  s.x = m.x; s.y = m.y; s.z = m.z;
  for (auto* v : {&s.vx, &s.vy, &s.vz, &s.ax, &s.ay, &s.az, &s.vx_old, &s.vy_old, &s.vz_old, &s.mass})
    v->assign(std::size_t(nn), 0.0);
  // external forces: only sliding interfaces, loads and _OFFSET ties make them (the node pass
  // reads them then)
  bool fext = !m.interfaces.empty() || m.has_loads();
  for (const TiedContact& tc : m.tied_contacts) fext = fext || tc.offset == 1;
  for (auto* v : {&s.fext_x, &s.fext_y, &s.fext_z}) v->assign(fext ? std::size_t(nn) : 0, 0.0);
  s.fix.assign(std::size_t(nn), 0);
  for (int i = 0; i < nn; ++i) {
    int c = m.bc[std::size_t(i)];
    s.fix[std::size_t(i)] = uint8_t((bc_fixes_x(c) ? 1 : 0) | (bc_fixes_y(c) ? 2 : 0) | (bc_fixes_z(c) ? 4 : 0));
  }
  s.rigid_of_node.assign(std::size_t(nn), -1);
}

void init_materials(const Model& m, State& s) {
  s.mats.resize(m.materials.size());
  for (std::size_t k = 0; k < m.materials.size(); ++k) {
    s.mats[k] = derive_constants(m.materials[k], m);  // the type's own (material_types.h)
  }
}

void init_elements(const Model& m, State& s) {
  const int ne = m.num_hexes();
  s.ne = ne;
  s.conn = m.hex_nodes;
  s.mat = m.hex_material;
  s.rigid_elem.assign(std::size_t(ne), 0);
  for (auto* v : {&s.vol0, &s.vol, &s.mass_e, &s.eps_p, &s.q, &s.dt_e})
    v->assign(std::size_t(ne), 0.0);
  s.sig.assign(std::size_t(6) * ne, 0.0);
  build_element_groups(s, m);
  // back stresses and hourglass resultants only when some group carries them
  bool back = false, hgs = false;
  s.hist_stride = 0;
  for (const ElementGroup& g : s.groups) {
    back = back || group_carries_back_stress(*g.solid, s.mats[std::size_t(g.material)]);
    s.hist_stride = std::max(s.hist_stride, g.history);
    hgs = hgs || group_carries_hourglass_state(m.materials[std::size_t(g.material)]);
  }
  s.back.assign(back ? std::size_t(6) * ne : 0, 0.0);
  s.hist.assign(std::size_t(s.hist_stride) * std::size_t(ne), 0.0);
  s.hgs.assign(hgs ? std::size_t(12) * ne : 0, 0.0);
  s.hg_pending.assign(s.groups.size(), 0.0);
  s.dt_vel = 0;
  s.mat_internal.assign(s.mats.size(), 0.0);
  s.mat_hourglass.assign(s.mats.size(), 0.0);
  s.cfx.assign(std::size_t(8) * s.slot_elem.size(), 0.0);
  s.cfy.assign(std::size_t(8) * s.slot_elem.size(), 0.0);
  s.cfz.assign(std::size_t(8) * s.slot_elem.size(), 0.0);
  s.yielded.assign(std::size_t(ne), 0);
  s.failed.assign(std::size_t(ne), 0);
  s.newly_failed.clear();
  s.newly_failed.reserve(std::size_t(ne));
  s.newly_failed_cause.clear();
  s.newly_failed_cause.reserve(std::size_t(ne));
  for (int e = 0; e < ne; ++e) {
    double x[8], y[8], z[8];
    for (int j = 0; j < 8; ++j) {
      int n = s.conn[std::size_t(e)][std::size_t(j)];
      x[j] = s.x[std::size_t(n)];
      y[j] = s.y[std::size_t(n)];
      z[j] = s.z[std::size_t(n)];
    }
    double v = calc_hex_volume(x, y, z);
    s.vol0[std::size_t(e)] = s.vol[std::size_t(e)] = v;
    const MaterialConstants& mc = s.mats[std::size_t(s.mat[std::size_t(e)])];
    s.mass_e[std::size_t(e)] = mc.rho * v;
    s.rigid_elem[std::size_t(e)] = hex_kernel_for_material_type(mc.type) == HexKernel::rigid;
    // rigid solids have no step of their own and never change it
    if (s.rigid_elem[std::size_t(e)]) s.dt_e[std::size_t(e)] = std::numeric_limits<double>::infinity();
    const MaterialData& md = m.materials[std::size_t(s.mat[std::size_t(e)])];
    if (const MaterialType* t = find_material_type(md.type); t && t->temperature_history >= 0) {
      // the solid's initial temperature: the mean of its nodes' (*INITIAL_TEMPERATURE), a node
      // without one at the material's initial temperature
      double sum = 0;
      for (int j = 0; j < 8; ++j) {
        const std::size_t n = std::size_t(s.conn[std::size_t(e)][std::size_t(j)]);
        const double tn = n < m.node_temperature.size() ? m.node_temperature[n] : std::nan("");
        sum += std::isnan(tn) ? t->initial_temperature(md) : tn;
      }
      s.hist[std::size_t(s.hist_stride) * std::size_t(e) + std::size_t(t->temperature_history)] = sum / 8;
    }
    if (mc.eos_form != 0) {  // an equation of state: the initial energy E0 and its pressure
      const double e0 = m.materials[std::size_t(s.mat[std::size_t(e)])].eos.e0;
      s.hist[std::size_t(s.hist_stride) * std::size_t(e) + std::size_t(mc.eos_hist)] = e0;
      const double p0 = calc_eos_initial_pressure(mc, e0);
      for (int c = 0; c < 3; ++c) s.sig[6 * std::size_t(e) + std::size_t(c)] = -p0;
    }
  }
  init_point_state(s);  // the fully integrated solids' points start from their solid's state
  // node -> corner map, in increasing (element, corner) order of the deck's numbering: a node
  // sums its corner forces in the same order whether or not the mesh was renumbered
  // (init/mesh_order.h), so renumbering changes no bit of the nodal forces
  s.corner_start.assign(std::size_t(s.nn) + 1, 0);
  for (int e = 0; e < ne; ++e)
    for (int j = 0; j < 8; ++j) ++s.corner_start[std::size_t(s.conn[std::size_t(e)][std::size_t(j)]) + 1];
  for (int i = 0; i < s.nn; ++i) s.corner_start[std::size_t(i) + 1] += s.corner_start[std::size_t(i)];
  s.corner_list.assign(std::size_t(8) * ne, 0);
  std::vector<int> fill(s.corner_start.begin(), s.corner_start.end() - 1);
  for (int d = 1; d <= ne; ++d) {
    const int e = m.hex_of_deck_number(d);
    for (int j = 0; j < 8; ++j)
      s.corner_list[std::size_t(fill[std::size_t(s.conn[std::size_t(e)][std::size_t(j)])]++)] = int(s.corner_index(e, j));
  }
  // Lumped mass: rho V0 / 8 to each corner (a repeated node of a degenerate element gets its
  // share once per corner), summed in the corner map's order
  for (int i = 0; i < s.nn; ++i) {
    double mass = 0;
    for (int c = s.corner_start[std::size_t(i)]; c < s.corner_start[std::size_t(i) + 1]; ++c)
      mass += s.mass_e[std::size_t(s.corner_element(std::size_t(s.corner_list[std::size_t(c)])))] / 8;
    s.mass[std::size_t(i)] = mass;
  }
}

void init_velocities(const Model& m, State& s) {
  for (const auto& iv : m.init_velocities) {
    if (iv.first == 0) {
      std::fill(s.vx.begin(), s.vx.end(), iv.v[0]);
      std::fill(s.vy.begin(), s.vy.end(), iv.v[1]);
      std::fill(s.vz.begin(), s.vz.end(), iv.v[2]);
    } else {
      for (int n = iv.first; n <= iv.last; n += iv.increment) {  // deck numbers
        const std::size_t k = std::size_t(m.node_of_deck_number(n));
        s.vx[k] = iv.v[0];
        s.vy[k] = iv.v[1];
        s.vz[k] = iv.v[2];
      }
    }
  }
  // constrained components start at rest
  for (int i = 0; i < s.nn; ++i) {
    if (s.fix[std::size_t(i)] & 1) s.vx[std::size_t(i)] = 0;
    if (s.fix[std::size_t(i)] & 2) s.vy[std::size_t(i)] = 0;
    if (s.fix[std::size_t(i)] & 4) s.vz[std::size_t(i)] = 0;
  }
}

// omega = I^-1 L, with a pseudo-inverse where I is singular (nodes on a line: no spin about it).
std::array<double, 3> rigid_omega(const std::array<double, 9>& I, const std::array<double, 3>& L) {
  Eigen::Matrix3d m;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) m(a, b) = I[std::size_t(3 * a + b)];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m);
  Eigen::Vector3d lam = es.eigenvalues(), inv;
  const double tol = 1e-12 * std::max(lam.maxCoeff(), 0.0);
  for (int k = 0; k < 3; ++k) inv(k) = lam(k) > tol ? 1.0 / lam(k) : 0.0;
  Eigen::Vector3d w = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose() * Eigen::Vector3d(L[0], L[1], L[2]);
  return {w(0), w(1), w(2)};
}

// The same with constrained rotations (bits of fix): those components of omega are zero, the
// free ones solve I_ff omega_f = L_f; the angular momentum becomes I omega (ang_mom).
std::array<double, 3> constrained_rigid_omega(const std::array<double, 9>& I, const std::array<double, 3>& L,
                                              unsigned fix, std::array<double, 3>& ang_mom) {
  std::array<double, 9> Iff{};  // the free block, the constrained rows and columns zeroed
  std::array<double, 3> Lf{};
  for (int a = 0; a < 3; ++a) {
    if (fix & (1u << a)) continue;
    Lf[std::size_t(a)] = L[std::size_t(a)];
    for (int b = 0; b < 3; ++b)
      if (!(fix & (1u << b))) Iff[std::size_t(3 * a + b)] = I[std::size_t(3 * a + b)];
  }
  std::array<double, 3> w = rigid_omega(Iff, Lf);
  for (int a = 0; a < 3; ++a)
    if (fix & (1u << a)) w[std::size_t(a)] = 0;
  for (int a = 0; a < 3; ++a) {
    ang_mom[std::size_t(a)] = 0;
    for (int b = 0; b < 3; ++b) ang_mom[std::size_t(a)] += I[std::size_t(3 * a + b)] * w[std::size_t(b)];
  }
  return w;
}

// Node k's share of a rigid body: its inertia about the centre of mass (I, row-major), its
// angular momentum relative to the centre's motion (L), and its initial arm (rb.r0).
void add_node_to_rigid_body(const State& s, std::size_t k, RigidBody& rb, std::array<double, 9>& I,
                            std::array<double, 3>& L) {
  const double mn = s.mass[k];
  const double r[3] = {s.x[k] - rb.com[0], s.y[k] - rb.com[1], s.z[k] - rb.com[2]};
  const double v[3] = {s.vx[k] - rb.vcom[0], s.vy[k] - rb.vcom[1], s.vz[k] - rb.vcom[2]};
  const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) I[std::size_t(3 * a + b)] += mn * ((a == b ? rr : 0) - r[a] * r[b]);
  L[0] += mn * (r[1] * v[2] - r[2] * v[1]);
  L[1] += mn * (r[2] * v[0] - r[0] * v[2]);
  L[2] += mn * (r[0] * v[1] - r[1] * v[0]);
  rb.r0.insert(rb.r0.end(), {r[0], r[1], r[2]});
}

// The body's nodes move with its rigid motion: v = vcom + omega x r.
void set_rigid_node_velocities(State& s, const RigidBody& rb) {
  for (std::size_t j = 0; j < rb.nodes.size(); ++j) {
    const double* r = &rb.r0[3 * j];
    const std::size_t n = std::size_t(rb.nodes[j]);
    s.vx[n] = rb.vcom[0] + rb.omega[1] * r[2] - rb.omega[2] * r[1];
    s.vy[n] = rb.vcom[1] + rb.omega[2] * r[0] - rb.omega[0] * r[2];
    s.vz[n] = rb.vcom[2] + rb.omega[0] * r[1] - rb.omega[1] * r[0];
  }
}

// The body's translations that `fixed` (bits x, y, z) or any of its nodes fixes are zero.
void zero_fixed_translations(const State& s, RigidBody& rb, unsigned fixed) {
  for (int n : rb.nodes) fixed |= s.fix[std::size_t(n)];
  for (int a = 0; a < 3; ++a)
    if (fixed & (1u << a)) rb.vcom[std::size_t(a)] = 0;
}

void init_rigid_bodies(const Model& m, State& s) {
  for (std::size_t k = 0; k < s.mats.size(); ++k) {
    if (!material_type(s.mats[k].type).rigid) continue;
    RigidBody rb;
    rb.material = int(k);
    for (int e = 0; e < s.ne; ++e)
      if (s.mat[std::size_t(e)] == int(k))
        for (int n : s.conn[std::size_t(e)]) rb.nodes.push_back(n);
    for (int q = 0; q < s.shells.ns; ++q)  // rigid shells
      if (s.shells.mat[std::size_t(q)] == rb.material)
        for (int n : s.shells.conn[std::size_t(q)]) rb.nodes.push_back(n);
    for (int q = 0; q < s.beams.nb; ++q)  // rigid beams (their ends; n3 only orients)
      if (s.beams.mat[std::size_t(q)] == rb.material)
        for (int j = 0; j < 2; ++j) rb.nodes.push_back(s.beams.conn[std::size_t(q)][std::size_t(j)]);
    std::sort(rb.nodes.begin(), rb.nodes.end());
    rb.nodes.erase(std::unique(rb.nodes.begin(), rb.nodes.end()), rb.nodes.end());
    if (rb.nodes.empty()) continue;
    // mass properties from the lumped masses of the body's nodes (elements of other materials
    // sharing a node add their share: the node moves with the body)
    double mx = 0, my = 0, mz = 0, px = 0, py = 0, pz = 0;
    for (int n : rb.nodes) {
      double mn = s.mass[std::size_t(n)];
      rb.mass += mn;
      mx += mn * s.x[std::size_t(n)];
      my += mn * s.y[std::size_t(n)];
      mz += mn * s.z[std::size_t(n)];
      px += mn * s.vx[std::size_t(n)];
      py += mn * s.vy[std::size_t(n)];
      pz += mn * s.vz[std::size_t(n)];
    }
    rb.com = {mx / rb.mass, my / rb.mass, mz / rb.mass};
    rb.com0 = rb.com;
    rb.vcom = {px / rb.mass, py / rb.mass, pz / rb.mass};
    std::array<double, 9> I{};
    std::array<double, 3> L{};
    for (int n : rb.nodes) add_node_to_rigid_body(s, std::size_t(n), rb, I, L);
    rb.inertia0 = I;
    rb.ang_mom = L;
    // The nodes start with the rigid motion that has the momentum and angular momentum of the
    // given nodal velocities (LS-DYNA's rule; the input check warns, 2014, when they were not a
    // rigid motion), so that the first energies booked are the body's.
    rb.omega = rigid_omega(I, L);
    rigid_body_constraints(m.materials[k], rb.fix_translation, rb.fix_rotation);
    // as in the run: a fixed node fixes that translation of the body; the material's
    // constraints (CMO/CON1/CON2) its translations and rotations
    zero_fixed_translations(s, rb, rb.fix_translation);
    if (rb.fix_rotation) rb.omega = constrained_rigid_omega(I, L, rb.fix_rotation, rb.ang_mom);
    set_rigid_node_velocities(s, rb);
    int idx = int(s.rigid.size());
    for (int n : rb.nodes) s.rigid_of_node[std::size_t(n)] = idx;
    s.rigid.push_back(std::move(rb));
  }
}

// Spot welds (Model::spot_welds): each a rigid body of its nodes (the input checks have made
// sure that no node is in two bodies and that each has mass), with its nodes' rotary inertias
// (isotropic: they add J to every axis) and their angular momentum, and each node's normal.
void init_spot_welds(const Model& m, State& s) {
  const ShellState& sh = s.shells;
  for (std::size_t w = 0; w < m.spot_welds.size(); ++w) {
    const SpotWeld& sw = m.spot_welds[w];
    RigidBody rb;
    rb.weld = int(w);
    rb.nodes = sw.nodes;
    bool free = true;
    for (int n : rb.nodes) free = free && s.rigid_of_node[std::size_t(n)] < 0;
    if (!free) continue;  // refused by the input checks (1253)
    double mx = 0, my = 0, mz = 0, px = 0, py = 0, pz = 0, jsum = 0, lx = 0, ly = 0, lz = 0;
    double gx = 0, gy = 0, gz = 0;  // the geometric centre (normals)
    for (int n : rb.nodes) {
      const std::size_t k = std::size_t(n);
      const double mn = s.mass[k];
      rb.mass += mn;
      mx += mn * s.x[k], my += mn * s.y[k], mz += mn * s.z[k];
      px += mn * s.vx[k], py += mn * s.vy[k], pz += mn * s.vz[k];
      gx += s.x[k], gy += s.y[k], gz += s.z[k];
      const int q = sh.node_rot.empty() ? -1 : sh.node_rot[k];
      if (q >= 0) {
        const double J = sh.inertia[std::size_t(q)];
        jsum += J;
        lx += J * sh.wx[std::size_t(q)], ly += J * sh.wy[std::size_t(q)], lz += J * sh.wz[std::size_t(q)];
      }
    }
    if (!(rb.mass > 0)) continue;  // refused by the input checks (1254)
    const double nn = double(rb.nodes.size());
    gx /= nn, gy /= nn, gz /= nn;
    rb.com = {mx / rb.mass, my / rb.mass, mz / rb.mass};
    rb.com0 = rb.com;
    rb.vcom = {px / rb.mass, py / rb.mass, pz / rb.mass};
    std::array<double, 9> I{};
    std::array<double, 3> L{lx, ly, lz};
    for (int a = 0; a < 3; ++a) I[std::size_t(4 * a)] = jsum;
    for (int n : rb.nodes) {
      const std::size_t k = std::size_t(n);
      add_node_to_rigid_body(s, k, rb, I, L);
      // the node's normal: towards the geometric centre, or (coincident nodes) CID's z axis
      double d[3] = {gx - s.x[k], gy - s.y[k], gz - s.z[k]};
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (sw.has_axis) {
        rb.axis_normal = true;
        for (int a = 0; a < 3; ++a) d[a] = sw.axis[std::size_t(a)];
      } else {
        for (double& c : d) c = len > 0 ? c / len : 0.0;
      }
      rb.n0.insert(rb.n0.end(), {d[0], d[1], d[2]});
    }
    rb.inertia0 = I;
    rb.ang_mom = L;
    rb.omega = rigid_omega(I, L);
    zero_fixed_translations(s, rb, 0);
    set_rigid_node_velocities(s, rb);
    const int idx = int(s.rigid.size());
    for (int n : rb.nodes) s.rigid_of_node[std::size_t(n)] = idx;
    s.rigid.push_back(std::move(rb));
  }
  s.newly_released.clear();
  s.newly_released.reserve(m.spot_welds.size());
}

}  // namespace

void initialize_state(const Model& m, State& s) {
  init_nodes(m, s);
  init_materials(m, s);
  init_elements(m, s);
  init_shells(m, s);
  init_beams(m, s);
  init_velocities(m, s);
  init_shell_rotational_velocities(m, s);
  init_rigid_bodies(m, s);
  init_spot_welds(m, s);
  init_node_ties(m, s);
  // net nodal forces: kept only for rigid bodies and tied contacts (their updates read them)
  for (auto* v : {&s.fx, &s.fy, &s.fz}) v->assign(s.rigid.empty() && s.ties.empty() ? 0 : std::size_t(s.nn), 0.0);
  s.wall_force.assign(m.walls.size(), {0, 0, 0});
  s.wall_disp.assign(m.walls.size(), 0.0);
  s.wall_vel.assign(m.walls.size(), 0.0);
  for (std::size_t w = 0; w < m.walls.size(); ++w)
    if (m.walls[w].mass > 0) s.wall_vel[w] = m.walls[w].v0;
}

}  // namespace impact3d
