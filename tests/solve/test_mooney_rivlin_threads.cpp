// Type 27 (Mooney-Rivlin rubber) gives the same bits on one and on two threads: a block of
// 22 x 22 x 17 solids (8228, past the threshold where the element pass hands blocks to several
// threads) and a 65 x 65 plate of shells (4225, past the shells' threshold), each given a
// velocity field that stretches, shears and bends it, 40 cycles.

#include <gtest/gtest.h>

#include <omp.h>

#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/shell_models.h"
#include "tests/solve/test_models.h"

using namespace impact3d;

namespace {

MaterialData rubber(bool shell) {
  MaterialData md;
  md.number = 1;
  md.type = 27;
  set_param_defaults(md, material_type(27));
  md.rho = 1100;
  md.nu = 0.45;  // (0.495 needs TSSF <= 0.6: tests/keyword/test_keyword_mooney_rivlin.cpp)
  param_value(md, *find_param(material_type(27), "A")) = 4e5;
  param_value(md, *find_param(material_type(27), "B")) = 1e5;
  md.title = "rubber";
  if (shell) {
    md.shell = true;
    md.shell_section.nip = 3;
    md.shell_section.shrf = 5.0 / 6.0;
  }
  return md;
}

void set_velocities(Model& m) {
  m.init_velocities.clear();
  for (int i = 0; i < m.num_nodes(); ++i) {
    InitialVelocity iv;
    iv.first = iv.last = i + 1;
    const double x = m.x[std::size_t(i)], y = m.y[std::size_t(i)];
    iv.v = {20.0 * x, 10.0 * x * y, 30.0 * x * (1 + y)};
    m.init_velocities.push_back(iv);
  }
  m.control.num_init_velocity_cards = int(m.init_velocities.size());
}

State run(const Model& m, int threads) {
  omp_set_num_threads(threads);
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  for (int c = 0; c < 40; ++c) EXPECT_EQ(eng.step(), StepStatus::ok);
  omp_set_num_threads(1);
  return eng.state();
}

}  // namespace

TEST(MooneyRivlinThreads, SolidsSameBitsForAnyThreadCount) {
  test_support::Box b;
  b.nx = 22, b.ny = 22, b.nz = 17;
  b.lx = 0.22, b.ly = 0.22, b.lz = 0.17;
  Model m = solve_test::make_box_model(b, rubber(false), 1.0);
  set_velocities(m);
  ASSERT_GT(m.num_hexes(), 8192);
  const State a = run(m, 1), c = run(m, 2);
  EXPECT_EQ(a.x, c.x);
  EXPECT_EQ(a.sig, c.sig);
  EXPECT_EQ(a.hist, c.hist);
  EXPECT_EQ(a.internal, c.internal);
  EXPECT_GT(a.internal, 0.0);
}

TEST(MooneyRivlinThreads, ShellsSameBitsForAnyThreadCount) {
  const int n = 65;
  Model m = shell_test::make_plate(n, n, 1.0, 1.0, 0.005, rubber(true), 1.0);
  set_velocities(m);
  const State a = run(m, 1), c = run(m, 2);
  EXPECT_EQ(a.z, c.z);
  EXPECT_EQ(a.shells.sig, c.shells.sig);
  EXPECT_EQ(a.shells.back, c.shells.back);
  EXPECT_EQ(a.internal, c.internal);
  EXPECT_GT(a.internal, 0.0);
}
