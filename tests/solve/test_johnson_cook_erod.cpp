// *MAT_JOHNSON_COOK EROD on a run: the seed's Taylor bar (972 solids, quarter model, copper at
// 227 m/s onto a frictionless wall) with OFHC Johnson-Cook constants and a damage law that the
// impact end exhausts within 20 us (D1 = 0.3, D2 = D3 = 0: eps_f = 0.3).  EROD = 0 deletes the
// solids whose damage reaches 1; EROD = 1 keeps every solid, and those with D >= 1 carry no
// deviatoric stress (a pure pressure, sig_xx = sig_yy = sig_zz, shears zero, to rounding).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

Model damaged_taylor_bar(double erod) {
  Model m;
  Diagnostics diag;
  EXPECT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/taylor_bar.dyn", m, diag));
  MaterialData& md = m.materials[0];
  const MaterialType& t = material_type(15);
  md.type = 15;
  set_param_defaults(md, t);
  md.rho = 8960, md.E = 124e9, md.nu = 0.34;
  auto set = [&](const char* k, double v) { param_value(md, *find_param(t, k)) = v; };
  set("G", md.E / (2 * (1 + md.nu)));
  set("A", 90e6), set("B", 292e6), set("N", 0.31), set("C", 0.025), set("EPSO", 1.0);
  set("D1", 0.3), set("EROD", erod);
  m.control.end_time = 20e-6;
  return m;
}

}  // namespace

TEST(JohnsonCookErod, NoErosionKeepsTheFailedSolids) {
  ScopedThreads one(1);
  int deleted[2] = {0, 0}, exhausted[2] = {0, 0};
  for (int erod : {0, 1}) {
    const Model m = damaged_taylor_bar(erod);
    Engine eng(m);
    ASSERT_EQ(eng.initialize(), StepStatus::ok);
    StepStatus st;
    while ((st = eng.step()) == StepStatus::ok) {
    }
    ASSERT_EQ(st, StepStatus::finished);
    const State& s = eng.state();
    const std::size_t hs = std::size_t(s.hist_stride);
    for (std::size_t e = 0; e < s.failed.size(); ++e) {
      deleted[erod] += s.failed[e] != 0;
      if (s.hist[hs * e + 1] < 1.0 || s.failed[e]) continue;
      ++exhausted[erod];
      const double* sg = &s.sig[6 * e];
      EXPECT_NEAR(sg[0], sg[1], 1e-9 * std::fabs(sg[0]) + 1e-3) << e;
      EXPECT_NEAR(sg[0], sg[2], 1e-9 * std::fabs(sg[0]) + 1e-3) << e;
      for (int c = 3; c < 6; ++c) EXPECT_EQ(sg[c], 0.0) << e;
    }
  }
  std::printf("EROD 0: %d solids deleted; EROD 1: %d deleted, %d kept with D >= 1\n", deleted[0], deleted[1], exhausted[1]);
  EXPECT_GT(deleted[0], 0);
  EXPECT_EQ(deleted[1], 0);
  EXPECT_GT(exhausted[1], 0);
}
