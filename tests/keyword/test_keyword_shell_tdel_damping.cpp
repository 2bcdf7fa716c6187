// *MAT_024 TDEL on shells and *CONTROL_DAMPING, against values:
//  - one square Belytschko-Tsay shell (side a, steel) crushed in its plane at a constant speed v
//    (uniaxial strain): its step is the width over the plate wave speed, (a - v t) / c, and the
//    shell is deleted in the first element pass whose step is below TDEL, i.e. the first one
//    past t* = (a - c TDEL) / v;
//  - *CONTROL_DAMPING (LS-DYNA's older name of the dynamic relaxation controls) is read and
//    ignored (warning 2008; the run the same bits), IDRFLG not 0 refused by field (1102).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
using test_support::read_deck_text;
using test_support::ReadDeck;
using test_support::F;
using test_support::I;

namespace {

constexpr double kA = 0.01, kE = 210e9, kRho = 7850, kNu = 0.3, kV = 100;

// A column of n square shells (side a) at y = j a: nodes 2j+1 (0, ja) and 2j+2 (a, ja); y, z and
// the rotations held; the nodes at x = 0 held in x, those at x = a moved at -v in x (eight or
// more shells go through the block kernel, fewer through the scalar one).
std::string crushed_shell(double tdel, const std::string& extra = "", int n = 1) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nshells crushed in their plane\n*CONTROL_TERMINATION\n" << F(6e-5) << "\n" << extra
    << "*PART\nplate\n" << I(1) << I(1) << I(1) << "\n"
    << "*SECTION_SHELL\n" << I(1) << I(2) << F(0.833333) << I(3) << "\n" << F(0.001) << "\n"
    << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n" << I(1) << F(kRho) << F(kE) << F(kNu) << F(250e6) << F(0.0) << F(0.0) << F(tdel)
    << "\n\n\n\n"
    << "*NODE\n";
  for (int j = 0; j <= n; ++j)
    d << I(2 * j + 1, 8) << F(0.0, 16) << F(kA * j, 16) << F(0.0, 16) << "\n"
      << I(2 * j + 2, 8) << F(kA, 16) << F(kA * j, 16) << F(0.0, 16) << "\n";
  d << "*ELEMENT_SHELL\n";
  for (int j = 0; j < n; ++j) d << I(j + 1, 8) << I(1, 8) << I(2 * j + 1, 8) << I(2 * j + 2, 8) << I(2 * j + 4, 8) << I(2 * j + 3, 8) << "\n";
  d << "*BOUNDARY_SPC_NODE\n";
  for (int k = 1; k <= 2 * n + 2; ++k) d << I(k) << I(0) << I(k % 2) << I(1) << I(1) << I(1) << I(1) << I(1) << "\n";
  d << "*DEFINE_CURVE\n" << I(1) << "\n" << F(0.0, 20) << F(1.0, 20) << "\n" << F(1.0, 20) << F(1.0, 20) << "\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int j = 0; j <= n; ++j) d << I(2 * j + 2) << I(1) << I(0) << I(1) << F(-kV) << "\n";
  d << "*END\n";
  return d.str();
}

}  // namespace

TEST(ShellTdel, ShellIsDeletedInThePassItsStepFallsBelowTdel) {
  const double c = std::sqrt(kE / (kRho * (1 - kNu * kNu)));
  const double tdel = 1.2e-6;
  const double t_star = (kA - c * tdel) / kV;
  for (int n : {1, 8}) {  // the scalar kernel, the block kernel
    ReadDeck r = read_deck_text(crushed_shell(tdel, "", n), "tdel.k");
    ASSERT_TRUE(r.ok) << r.messages();
    Engine e(r.m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    double t_before = 0, t_deleted = -1, worst_step = 0;
    int passes = 0, deleted = 0;
    while (!e.finished()) {
      const StepStatus st = e.step();
      ASSERT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << int(st);
      deleted = 0;
      for (int k = 0; k < n; ++k) deleted += s.shells.failed[std::size_t(k)] != 0;
      if (deleted > 0) {
        t_deleted = s.time;
        break;
      }
      // the step of the pass at t: the width over the plate wave speed
      for (int k = 0; k < n; ++k)
        worst_step = std::max(worst_step, std::fabs(s.shells.dt_e[std::size_t(k)] / ((kA - kV * s.time) / c) - 1));
      t_before = s.time;
      ++passes;
    }
    std::printf("%d shell(s): plate wave speed %.2f m/s, t* = %.6e s; last pass kept at %.6e s, %d deleted at %.6e s "
                "(%d passes); step vs (a - v t)/c within %.2e\n", n, c, t_star, t_before, deleted, t_deleted, passes, worst_step);
    ASSERT_GT(t_deleted, 0) << "the shell was not deleted";
    EXPECT_EQ(deleted, n);  // all in the same pass
    EXPECT_LE(t_before, t_star);
    EXPECT_GT(t_deleted, t_star);
    EXPECT_GT(passes, 10);
    EXPECT_LT(worst_step, 1e-9);
    // without TDEL they stay
    ReadDeck k = read_deck_text(crushed_shell(0, "", n), "tdel.k");
    ASSERT_TRUE(k.ok) << k.messages();
    Engine e0(k.m);
    ASSERT_EQ(e0.initialize(), StepStatus::ok);
    while (!e0.finished() && e0.state().time < t_deleted) ASSERT_EQ(e0.step(), StepStatus::ok);
    for (int q = 0; q < n; ++q) EXPECT_EQ(e0.state().shells.failed[std::size_t(q)], 0);
  }
}

TEST(ControlDamping, ReadAndIgnoredUnlessItAsksForDynamicRelaxation) {
  const std::string damping = "*CONTROL_DAMPING\n" + I(250) + F(0.001) + F(0.995) + F(1e20) + F(0.0) + I(0) + F(0.04) + I(0) + "\n";
  ReadDeck a = read_deck_text(crushed_shell(0), "damping.k");
  ReadDeck b = read_deck_text(crushed_shell(0, damping), "damping.k");
  ASSERT_TRUE(a.ok) << a.messages();
  ASSERT_TRUE(b.ok) << b.messages();
  ASSERT_EQ(b.count(2008), 1) << b.messages();
  EXPECT_NE(b.messages().find("*CONTROL_DAMPING"), std::string::npos) << b.messages();
  Engine ea(a.m), eb(b.m);
  ASSERT_EQ(ea.initialize(), StepStatus::ok);
  ASSERT_EQ(eb.initialize(), StepStatus::ok);
  for (int k = 0; k < 20; ++k) {
    ASSERT_EQ(ea.step(), StepStatus::ok);
    ASSERT_EQ(eb.step(), StepStatus::ok);
  }
  EXPECT_EQ(ea.state().x, eb.state().x);
  EXPECT_EQ(ea.state().shells.sig, eb.state().shells.sig);
  const std::string asks = "*CONTROL_DAMPING\n" + I(250) + F(0.001) + F(0.995) + F(1e20) + F(0.0) + I(0) + F(0.04) + I(1) + "\n";
  ReadDeck c = read_deck_text(crushed_shell(0, asks), "damping.k");
  EXPECT_FALSE(c.ok);
  const Diagnostic* x = c.first(1102);
  ASSERT_NE(x, nullptr) << c.messages();
  EXPECT_EQ(x->where.field, "IDRFLG");
  EXPECT_EQ(x->where.col_first, 71);
  EXPECT_EQ(x->where.col_last, 80);
}
