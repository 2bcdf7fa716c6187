// The shells' element pass in blocks of 8 (shell_block.h) gives the bits of the scalar kernel
// shell by shell, and the same bits on one and on two threads: whole runs with the groups in
// blocks against the same runs with every group forced to the scalar kernel (ShellGroup::blocks
// off after initialization), compared field by field:
//   * a 65 x 65 plate (4225 shells: past the shells' threads threshold, 528 blocks and one shell
//     left over for the scalar kernel) stretched, bent and twisted, 40 cycles: elastic NIP 2,
//     elastic NIP 3 with the stiffness hourglass form, plastic-kinematic NIP 5 (beta 0.5),
//     piecewise-linear NIP 5 (a table);
//   * the same plastic-kinematic plate with a failure strain, so that shells are deleted (blocks
//     holding a deleted shell go through the scalar kernel);
//   * the shipped shell decks (decks/keyword/scordelis_lo_roof.k, pinched_cylinder.k), 300 cycles.

#include <gtest/gtest.h>

#include <omp.h>

#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/shell_models.h"

using namespace impact3d;

namespace {

MaterialData plate_material(int type, int nip) {
  MaterialData md = shell_test::steel_shell(type, nip);
  if (type == 24) {
    const MaterialType& t = material_type(24);
    set_param_defaults(md, t);  // (blanks E, nu, rho: set again)
    const MaterialData steel = shell_test::steel_shell(type, nip);
    md.rho = steel.rho;
    md.E = steel.E;
    md.nu = steel.nu;
    const double eps[4] = {0, 0.001, 0.005, 0.02}, es[4] = {2e7, 3e8, 3.8e8, 4.2e8};
    for (int i = 0; i < 4; ++i) {
      param_value(md, *find_param(t, "EPS" + std::to_string(i + 1))) = eps[i];
      param_value(md, *find_param(t, "ES" + std::to_string(i + 1))) = es[i];
    }
  }
  md.sigma_y = 2e7;
  md.beta = 0.5;
  return md;
}

Model make_plate_model(const MaterialData& md) {
  const int n = 65;
  Model m = shell_test::make_plate(n, n, 1.0, 1.0, 0.01, md, 1.0);
  for (int i = 0; i < m.num_nodes(); ++i) {
    const std::size_t I = std::size_t(i);
    const double x = m.x[I], y = m.y[I];
    m.init_velocities.push_back({i + 1, i + 1, 1, {20.0 * (x - 0.5), 10.0 * x * y, 30.0 * x * (1 + y)}});
  }
  m.control.num_init_velocity_cards = int(m.init_velocities.size());
  return m;
}

State run(const Model& m, int threads, bool blocks, int cycles) {
  omp_set_num_threads(threads);
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  bool any_blocks = false;
  for (ShellGroup& g : eng.state().shells.groups) {
    any_blocks = any_blocks || g.blocks;
    if (!blocks) g.blocks = false;
  }
  EXPECT_TRUE(any_blocks);  // the block kernel covers these materials
  for (int c = 0; c < cycles; ++c) {
    const StepStatus st = eng.step();
    EXPECT_EQ(st, StepStatus::ok);
    if (st != StepStatus::ok) break;
  }
  omp_set_num_threads(1);
  return eng.state();
}

void expect_same_state(const State& a, const State& b) {
  EXPECT_EQ(a.cycle, b.cycle);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.vz, b.vz);
  EXPECT_EQ(a.shells.wx, b.shells.wx);
  EXPECT_EQ(a.shells.wy, b.shells.wy);
  EXPECT_EQ(a.shells.sig, b.shells.sig);
  EXPECT_EQ(a.shells.back, b.shells.back);
  EXPECT_EQ(a.shells.eps_p, b.shells.eps_p);
  EXPECT_EQ(a.shells.yielded, b.shells.yielded);
  EXPECT_EQ(a.shells.hgq, b.shells.hgq);
  EXPECT_EQ(a.shells.drill, b.shells.drill);
  EXPECT_EQ(a.shells.dt_e, b.shells.dt_e);
  EXPECT_EQ(a.shells.energy, b.shells.energy);
  EXPECT_EQ(a.shells.failed, b.shells.failed);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_EQ(a.hourglass, b.hourglass);
  EXPECT_EQ(a.time, b.time);
}

void expect_blocks_same_bits(const Model& m, int cycles) {
  const State scalar = run(m, 1, false, cycles);
  const State one = run(m, 1, true, cycles);
  const State two = run(m, 2, true, cycles);
  {
    SCOPED_TRACE("blocks against the scalar kernel");
    expect_same_state(one, scalar);
  }
  {
    SCOPED_TRACE("two threads against one");
    expect_same_state(two, one);
  }
  EXPECT_GT(one.internal, 0.0);
}

}  // namespace

TEST(ShellBlocks, ElasticPlateSameBitsAsScalarAndForAnyThreadCount) {
  expect_blocks_same_bits(make_plate_model(shell_test::steel_shell(1, 2)), 40);
  MaterialData md = shell_test::steel_shell(1, 3);
  md.hourglass_type = 4;
  expect_blocks_same_bits(make_plate_model(md), 40);
}

TEST(ShellBlocks, PlasticKinematicPlateSameBits) {
  const Model m = make_plate_model(plate_material(3, 5));
  const State s = run(m, 1, true, 40);
  int yielded = 0;
  for (auto y : s.shells.yielded) yielded += y;
  EXPECT_GT(yielded, 1000);  // the plastic branch ran
  expect_blocks_same_bits(m, 40);
}

TEST(ShellBlocks, PiecewiseLinearPlateSameBits) {
  const Model m = make_plate_model(plate_material(24, 5));
  const State s = run(m, 1, true, 40);
  int yielded = 0;
  for (auto y : s.shells.yielded) yielded += y;
  EXPECT_GT(yielded, 1000);
  expect_blocks_same_bits(m, 40);
}

TEST(ShellBlocks, DeletedShellsSameBits) {
  MaterialData md = plate_material(3, 5);
  md.fail_strain = 2e-4;
  const Model m = make_plate_model(md);
  const State s = run(m, 1, true, 60);
  int failed = 0;
  for (auto f : s.shells.failed) failed += f != 0;
  EXPECT_GT(failed, 0);                    // some shells deleted ...
  EXPECT_LT(failed, s.shells.ns);          // ... not all
  expect_blocks_same_bits(m, 60);
}

TEST(ShellBlocks, ShippedShellDecksSameBits) {
  for (const char* name : {"scordelis_lo_roof.k", "pinched_cylinder.k"}) {
    SCOPED_TRACE(name);
    Model m;
    Diagnostics d;
    ASSERT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR "/decks/keyword/") + name, m, d));
    expect_blocks_same_bits(m, 300);
  }
}
