#pragma once
// Helpers of the contact tests: shipped decks, programmatic multi-body box models with sliding
// interfaces between box faces, momentum and contact-force reductions.  SI units.

#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/model/model.h"
#include "impact3d/model/state.h"
#include "../support/box_mesh.h"

namespace contact_test {

using impact3d::MaterialData;
using impact3d::Model;
using impact3d::State;

// A keyword field of width w: a real (%g, 6 digits; 9 in fields wider than 10) or an integer.
inline std::string fld(double v, int w) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.*g", w, w > 10 ? 9 : 6, v);
  return b;
}
inline std::string ifld(long v, int w) {
  char b[64];
  std::snprintf(b, sizeof b, "%*ld", w, v);
  return b;
}

inline Model read_deck(const std::string& name) {
  Model m;
  impact3d::Diagnostics diag;
  const std::string path = std::string(IMPACT3D_SOURCE_DIR) + "/decks/" + name;
  const bool ok = impact3d::read_and_check_deck(path, m, diag);
  EXPECT_TRUE(ok) << path;
  return m;
}

using test_support::ScopedThreads;

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

using test_support::add_box;
using test_support::Box;


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
