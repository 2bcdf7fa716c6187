// The seed's second example (decks/oblique_rod.dyn): no sliding interface, a frictionless
// stonewall tilted 10 degrees.  Reduced end time 150 us (the deck runs 2600 us; 300 us, 8229 cycles, takes ~70 s of CPU and
// gave the same: momentum drift 3e-15, energy ratio within [1.00000, 1.00022]).  Tolerances:
// normal termination (no negative volume); the momentum along the wall in the symmetry plane,
// t = (cos 10, 0, -sin 10) from the deck's normal, is conserved to 1e-9 of the initial momentum (the wall pushes along
// its normal only, the symmetry plane y = 0 along y); energy ratio within 2% at every cycle.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "impact3d/solve/engine.h"
#include "tests/contact/contact_test_util.h"

using namespace impact3d;
using namespace contact_test;

TEST(ObliqueRod, TiltedFrictionlessWallReduced150us) {
  Model m = read_deck("oblique_rod.dyn");
  ASSERT_EQ(m.walls.size(), 1u);
  ASSERT_EQ(m.walls[0].friction, 0.0);
  m.control.end_time = 150e-6;
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  // in-plane tangent of the wall as the deck gives it (normal (sin 10, 0, cos 10) to 5 digits)
  const auto& w = m.walls[0];
  const double n[3] = {w.head[0] - w.tail[0], w.head[1] - w.tail[1], w.head[2] - w.tail[2]};
  const double nl = std::hypot(n[0], n[2]);
  ASSERT_EQ(n[1], 0.0);
  const double t[3] = {n[2] / nl, 0.0, -n[0] / nl};
  auto pt = [&] {
    const auto p = momentum(s, 0, s.nn);
    return p[0] * t[0] + p[1] * t[1] + p[2] * t[2];
  };
  const auto p0 = momentum(s, 0, s.nn);
  const double pmag = std::sqrt(p0[0] * p0[0] + p0[1] * p0[1] + p0[2] * p0[2]);
  const double pt0 = pt();
  double max_dpt = 0, rmin = 1, rmax = 1;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    max_dpt = std::max(max_dpt, std::abs(pt() - pt0));
    rmin = std::min(rmin, s.energy_ratio());
    rmax = std::max(rmax, s.energy_ratio());
  }
  std::printf("  %d cycles, wall-tangential momentum drift %.2e of |p0|, energy ratio [%.5f, %.5f]\n",
              s.cycle, max_dpt / pmag, rmin, rmax);
  ASSERT_EQ(st, StepStatus::finished);
  EXPECT_LT(max_dpt, 1e-9 * pmag);
  EXPECT_GT(rmin, 0.98);
  EXPECT_LT(rmax, 1.02);
}
