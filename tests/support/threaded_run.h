#pragma once
// Runs of a model on a given OpenMP thread count, for the tests that compare the final
// state of 1 and 2 threads bit for bit.

#include <gtest/gtest.h>

#include "impact3d/model/model.h"
#include "impact3d/solve/engine.h"
#include "tests/support/box_mesh.h"

namespace test_support {

// Runs `m` from initialization to its end (the first step that is not ok) on `threads`
// threads and returns the final state.
inline impact3d::State run_to_end_on_threads(const impact3d::Model& m, int threads) {
  ScopedThreads t(threads);
  impact3d::Engine e(m);
  EXPECT_EQ(e.initialize(), impact3d::StepStatus::ok);
  while (e.step() == impact3d::StepStatus::ok) {
  }
  return e.state();
}

// Runs `cycles` steps of `m` on `threads` threads (each must be ok) and returns the state.
inline impact3d::State run_cycles_on_threads(const impact3d::Model& m, int threads, int cycles) {
  ScopedThreads t(threads);
  impact3d::Engine e(m);
  EXPECT_EQ(e.initialize(), impact3d::StepStatus::ok);
  for (int c = 0; c < cycles; ++c) EXPECT_EQ(e.step(), impact3d::StepStatus::ok);
  return e.state();
}

}  // namespace test_support
