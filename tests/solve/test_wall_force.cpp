// The force on a stonewall is the impulse it gives over the step the velocity jump belongs to,
// dt_n = (dt^{n-1/2} + dt^{n+1/2}) / 2: right on the first cycle (dt_n = dt/2) and on a last
// step cut short to land on the termination time (was: impulse / dt^{n+1/2}, 3x too large).
#include <gtest/gtest.h>

#include <cmath>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

TEST(StoneWall, ForceOnTheLastShortStepIsTheBarForce) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/bar_wall_elastic.dyn", m, d));
  m.control.end_time = 5.0001e-6;  // the last step is ~0.1% of a normal one
  Engine eng(m);
  ASSERT_EQ(eng.run_to_end(), StepStatus::finished);
  const auto& md = m.materials[0];
  const double c0 = std::sqrt(md.E / md.rho), area = 2e-3 * 2e-3, v = 5.0;
  const double bar_force = md.rho * c0 * v * area;  // 646 N
  const auto& F = eng.state().wall_force[0];
  // The 2x2-element section rings about the 1-D value by up to ~7% (693..610 N in rwforc);
  // tolerance 10%.  The old bookkeeping gave 1889 N here.
  EXPECT_NEAR(-F[2], bar_force, 0.10 * bar_force);
}
