// Failure of plastic-kinematic shells (type 3 FS): a shell is deleted once every point through
// its thickness has reached FS; from then on it carries no force and no step, its mass stays;
// the plot database marks it deleted.

#include <gtest/gtest.h>

#include "impact3d/solve/engine.h"
#include "tests/solve/shell_models.h"

using namespace impact3d;
using namespace shell_test;

namespace {

// A 0.1 x 0.02 m steel strip of 40 x 4 shells (2 mm, NIP 3) stretched along x from its held
// edge x = 0: vx = 200 x / L, about 2000 /s.
Model stretched_strip(double fs) {
  MaterialData mat = steel_shell(3, 3);
  mat.fail_strain = fs;
  Model m = make_plate(40, 4, 0.1, 0.02, 0.002, mat, 4e-5);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.x[std::size_t(n)] < 1e-12) m.bc[std::size_t(n)] = 1;  // x held
  for (int n = 0; n < m.num_nodes(); ++n) {
    InitialVelocity iv;
    iv.first = iv.last = n + 1;
    iv.v = {200.0 * m.x[std::size_t(n)] / 0.1, 0, 0};
    m.init_velocities.push_back(iv);
  }
  m.control.num_init_velocity_cards = int(m.init_velocities.size());
  return m;
}

double min_point_strain(const State& s, int k) {
  const ShellState& sh = s.shells;
  double lo = 1e300;
  for (int i = 0; i < sh.nip[std::size_t(k)]; ++i)
    lo = std::min(lo, sh.eps_p[shell_point_at(sh, k, i)]);
  return lo;
}

}  // namespace

TEST(ShellFailure, DeletesShellsWhoseEveryPointReachedFs) {
  const double fs = 0.01;
  Model m = stretched_strip(fs);
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  int first_cycle = -1;
  while (st == StepStatus::ok) {
    st = e.step();
    const State& s = e.state();
    for (int k = 0; k < s.shells.ns; ++k) {
      // a live shell never has every point at FS after its pass; a deleted one did when it went
      if (!s.shells.failed[std::size_t(k)]) EXPECT_LT(min_point_strain(s, k), fs) << "shell " << k << " cycle " << s.cycle;
      else if (first_cycle < 0) first_cycle = s.cycle;
    }
  }
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = e.state();
  int nfailed = 0;
  for (int k = 0; k < s.shells.ns; ++k) {
    if (!s.shells.failed[std::size_t(k)]) continue;
    ++nfailed;
    EXPECT_GE(min_point_strain(s, k), fs);
    for (int j = 0; j < 4; ++j) {  // no force, no moment
      const std::size_t c = s.shells.corner_base + 4 * std::size_t(k) + std::size_t(j);
      EXPECT_EQ(s.cfx[c], 0.0);
      EXPECT_EQ(s.cfy[c], 0.0);
      EXPECT_EQ(s.shells.cmz[4 * std::size_t(k) + std::size_t(j)], 0.0);
    }
  }
  EXPECT_GT(nfailed, 0);
  EXPECT_GT(first_cycle, 10);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.02);
  // FS = 0: never
  const Model plain = stretched_strip(0);  // (the engine keeps a reference to its model)
  Engine never(plain);
  ASSERT_EQ(never.initialize(), StepStatus::ok);
  st = StepStatus::ok;
  while (st == StepStatus::ok) st = never.step();
  for (auto f : never.state().shells.failed) EXPECT_EQ(f, 0);
}
