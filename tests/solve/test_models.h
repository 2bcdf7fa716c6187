#pragma once
// Small builders of programmatic Models for the physics verification tests: box meshes of
// hexahedra, copper materials, per-node initial velocities, and a few State reductions.
// Units SI (m, kg, s, Pa) as in the shipped decks.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <omp.h>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"
#include "../support/box_mesh.h"

namespace solve_test {

using impact3d::Model;
using impact3d::MaterialData;
using impact3d::State;

// Copper of the seed examples: E 117 GPa, nu 0.35, rho 8930.
inline MaterialData copper_elastic() {
  MaterialData m;
  m.number = 1;
  m.type = 1;
  m.rho = 8930;
  m.E = 117e9;
  m.nu = 0.35;
  m.title = "copper, elastic";
  return m;
}

// Elastic-plastic copper (type 3, isotropic): sigma_y 0.4 GPa, E_tan 0.1 GPa.
inline MaterialData copper_plastic() {
  MaterialData m = copper_elastic();
  m.type = 3;
  m.sigma_y = 0.4e9;
  m.E_tan = 0.1e9;
  m.beta = 1;
  m.title = "copper, elastic-plastic";
  return m;
}

// Derived elastic constants.
struct Elastic {
  double G, K, M;  // shear, bulk, constrained (K + 4G/3) moduli
};
inline Elastic elastic_of(const MaterialData& m) {
  return {m.E / (2 * (1 + m.nu)), m.E / (3 * (1 - 2 * m.nu)),
          m.E * (1 - m.nu) / ((1 + m.nu) * (1 - 2 * m.nu))};
}

// A box [x0, x0+lx] x [y0, y0+ly] x [z0, z0+lz] of nx*ny*nz hexahedra of one material.
// Node (i, j, k) has index i + (nx+1) (j + (ny+1) k); element (i, j, k) has index
// i + nx (j + ny k).  Faces 1-2-3-4 at z_k, 5-6-7-8 at z_{k+1} (positive volume).
using test_support::Box;

inline Model make_box_model(const Box& b, const MaterialData& mat, double end_time,
                            int bc_code = 0) {
  Model m;
  m.title = "programmatic box";
  m.materials = {mat};
  test_support::add_box(m, b, 0, bc_code);
  m.hex_line.clear();
  m.control.nmmat = 1;
  m.control.end_time = end_time;
  return m;
}

// Same initial velocity on every node.
inline void set_uniform_velocity(Model& m, double vx, double vy, double vz) {
  impact3d::InitialVelocity iv;
  iv.first = 0;
  iv.v = {vx, vy, vz};
  m.init_velocities = {iv};
  m.control.num_init_velocity_cards = 1;
}

// One initial-velocity card per node (0-based node index), v = f(x, y, z).
template <class F>
inline void set_velocity_field(Model& m, F f) {
  m.init_velocities.clear();
  for (int n = 0; n < m.num_nodes(); ++n) {
    impact3d::InitialVelocity iv;
    iv.first = iv.last = n + 1;
    iv.v = f(m.x[std::size_t(n)], m.y[std::size_t(n)], m.z[std::size_t(n)]);
    m.init_velocities.push_back(iv);
  }
  m.control.num_init_velocity_cards = int(m.init_velocities.size());
}

// Stonewall z = 0, normal +z, frictionless, all nodes.
inline void add_floor_wall(Model& m) {
  impact3d::StoneWall w;
  w.tail = {0, 0, 0};
  w.head = {0, 0, 1};
  m.walls.push_back(w);
  m.control.num_walls = int(m.walls.size());
}

using test_support::ScopedThreads;

// Reductions over the State.
inline std::array<double, 3> momentum(const State& s) {
  std::array<double, 3> p{};
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    p[0] += s.mass[k] * s.vx[k];
    p[1] += s.mass[k] * s.vy[k];
    p[2] += s.mass[k] * s.vz[k];
  }
  return p;
}

inline double total_mass(const State& s) {
  double m = 0;
  for (double v : s.mass) m += v;
  return m;
}

inline double max_abs_stress(const State& s) {
  double r = 0;
  for (double v : s.sig) r = std::max(r, std::fabs(v));
  return r;
}

}  // namespace solve_test
