#pragma once
// Test support shared by the test folders: box meshes appended to a Model, and a scoped OpenMP
// thread count.

#include <omp.h>

#include <array>
#include <vector>

#include "impact3d/model/model.h"

namespace test_support {

using impact3d::Model;

// Sets the OpenMP thread count for the scope.  The small models of the tests run a few
// microseconds per cycle: on a shared 2-core machine two spinning threads cost far more than
// they save, so most tests run on one thread (the determinism tests compare 1 and 2).
struct ScopedThreads {
  int saved;
  explicit ScopedThreads(int n) : saved(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~ScopedThreads() { omp_set_num_threads(saved); }
  ScopedThreads(const ScopedThreads&) = delete;
  ScopedThreads& operator=(const ScopedThreads&) = delete;
};

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

}  // namespace test_support
