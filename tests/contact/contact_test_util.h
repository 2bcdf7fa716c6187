#pragma once
// Helpers of the contact tests: shipped decks, programmatic multi-body box models with sliding
// interfaces between box faces, momentum and contact-force reductions.  SI units.

#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace contact_test {

using impact3d::MaterialData;
using impact3d::Model;
using impact3d::State;

inline Model read_deck(const std::string& name) {
  Model m;
  impact3d::Diagnostics diag;
  const std::string path = std::string(IMPACT3D_SOURCE_DIR) + "/decks/" + name;
  const bool ok = impact3d::read_and_check_deck(path, m, diag);
  EXPECT_TRUE(ok) << path;
  return m;
}

struct ScopedThreads {
  int saved;
  explicit ScopedThreads(int n) : saved(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~ScopedThreads() { omp_set_num_threads(saved); }
};

inline MaterialData copper(int number) {
  MaterialData m;
  m.number = number;
  m.type = 1;
  m.rho = 8930;
  m.E = 117e9;
  m.nu = 0.35;
  m.title = "copper, elastic";
  return m;
}

// A box of nx*ny*nz hexahedra appended to the model (material index mat, 0-based).  Node
// (i, j, k) -> first_node + i + (nx+1)(j + (ny+1) k).
struct Box {
  int nx = 1, ny = 1, nz = 1;
  double lx = 1, ly = 1, lz = 1;
  double x0 = 0, y0 = 0, z0 = 0;
  int first_node = 0, first_elem = 0;
  int node(int i, int j, int k) const { return first_node + i + (nx + 1) * (j + (ny + 1) * k); }
  int num_nodes() const { return (nx + 1) * (ny + 1) * (nz + 1); }
  // Faces as segments, counter-clockwise seen from outside: bottom (z = z0) and top.
  std::vector<std::array<int, 4>> bottom() const {
    std::vector<std::array<int, 4>> f;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        f.push_back({node(i, j, 0), node(i, j + 1, 0), node(i + 1, j + 1, 0), node(i + 1, j, 0)});
    return f;
  }
  std::vector<std::array<int, 4>> top() const {
    std::vector<std::array<int, 4>> f;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        f.push_back({node(i, j, nz), node(i + 1, j, nz), node(i + 1, j + 1, nz), node(i, j + 1, nz)});
    return f;
  }
};

inline Box add_box(Model& m, Box b, int mat, int bc = 0) {
  b.first_node = m.num_nodes();
  b.first_elem = m.num_hexes();
  for (int k = 0; k <= b.nz; ++k)
    for (int j = 0; j <= b.ny; ++j)
      for (int i = 0; i <= b.nx; ++i) {
        m.x.push_back(b.x0 + b.lx * i / b.nx);
        m.y.push_back(b.y0 + b.ly * j / b.ny);
        m.z.push_back(b.z0 + b.lz * k / b.nz);
        m.bc.push_back(bc);
      }
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j)
      for (int i = 0; i < b.nx; ++i) {
        m.hex_nodes.push_back({b.node(i, j, k), b.node(i + 1, j, k), b.node(i + 1, j + 1, k),
                               b.node(i, j + 1, k), b.node(i, j, k + 1), b.node(i + 1, j, k + 1),
                               b.node(i + 1, j + 1, k + 1), b.node(i, j + 1, k + 1)});
        m.hex_material.push_back(mat);
        m.hex_line.push_back(0);
      }
  m.control.numnp = m.num_nodes();
  m.control.numelh = m.num_hexes();
  return b;
}

inline void set_velocity(Model& m, const Box& b, double vx, double vy, double vz) {
  impact3d::InitialVelocity iv;
  iv.first = b.first_node + 1;
  iv.last = b.first_node + b.num_nodes();
  iv.v = {vx, vy, vz};
  m.init_velocities.push_back(iv);
}

inline Model empty_model(double end_time, std::vector<MaterialData> mats) {
  Model m;
  m.title = "contact test";
  m.materials = std::move(mats);
  m.control.nmmat = int(m.materials.size());
  m.control.end_time = end_time;
  return m;
}

// Momentum of the nodes [first, last).
inline std::array<double, 3> momentum(const State& s, int first, int last) {
  std::array<double, 3> p{0, 0, 0};
  for (int i = first; i < last; ++i) {
    const std::size_t k = std::size_t(i);
    p[0] += s.mass[k] * s.vx[k];
    p[1] += s.mass[k] * s.vy[k];
    p[2] += s.mass[k] * s.vz[k];
  }
  return p;
}
inline double mass_of(const State& s, int first, int last) {
  double m = 0;
  for (int i = first; i < last; ++i) m += s.mass[std::size_t(i)];
  return m;
}
// Sum of the external (contact) forces on the nodes [first, last) this cycle.
inline std::array<double, 3> contact_force(const State& s, int first, int last) {
  std::array<double, 3> f{0, 0, 0};
  for (int i = first; i < last; ++i) {
    f[0] += s.fext_x[std::size_t(i)];
    f[1] += s.fext_y[std::size_t(i)];
    f[2] += s.fext_z[std::size_t(i)];
  }
  return f;
}

}  // namespace contact_test
