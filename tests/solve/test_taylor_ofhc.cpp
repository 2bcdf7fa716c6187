// Validation: the OFHC-copper Taylor bar with Johnson-Cook (type 15) against the measured
// result.  Test: OFHC copper, L0 = 25.4 mm, D0 = 7.62 mm, 190 m/s onto a rigid anvil; measured
// final length Lf = 0.638 L0 = 16.21 mm and footprint (largest) diameter Dm = 1.78 D0 =
// 13.56 mm (Johnson & Cook 1983, also quoted by Johnson & Holmquist 1988 and Zerilli &
// Armstrong 1987, J. Appl. Phys. 61, 1816; the numbers as tabulated in
// github.com/bbanerjee/HighRateExptData, TaylorData/MATLAB/plotOFHCCu.m, zerilliData).
// Constants: Johnson & Cook 1983 for OFHC copper, A 90 MPa, B 292 MPa, n 0.31, C 0.025, m 1.09,
// TM 1356 K, CP 383 J/kg K, rho 8960, E 124 GPa, nu 0.34, EPSO 1/s, TR 294 K.
//
// The model: the seed's Taylor-bar mesh (decks/taylor_bar.dyn, quarter model, 972 solids)
// scaled to the test's radius and length, all nodes at -190 m/s, frictionless stonewall (the
// same model, refined and with friction: bench/bench_taylor_ofhc.cpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

constexpr double kL0 = 25.4e-3, kD0 = 7.62e-3, kV = 190.0;
constexpr double kLfMeasured = 0.638 * kL0, kDmMeasured = 1.78 * kD0;

Model ofhc_taylor_bar() {
  Model m;
  Diagnostics diag;
  EXPECT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/taylor_bar.dyn", m, diag));
  const double r0 = *std::max_element(m.x.begin(), m.x.end());
  const double l0 = *std::max_element(m.z.begin(), m.z.end());
  for (std::size_t n = 0; n < m.x.size(); ++n) {
    m.x[n] *= 0.5 * kD0 / r0;
    m.y[n] *= 0.5 * kD0 / r0;
    m.z[n] *= kL0 / l0;
  }
  for (InitialVelocity& v : m.init_velocities) v.v = {0.0, 0.0, -kV};
  MaterialData& md = m.materials[0];
  const MaterialType& t = material_type(15);
  md.type = 15;
  set_param_defaults(md, t);
  md.rho = 8960;
  md.E = 124e9;
  md.nu = 0.34;
  auto set = [&](const char* k, double v) { param_value(md, *find_param(t, k)) = v; };
  set("G", md.E / (2 * (1 + md.nu)));
  set("A", 90e6), set("B", 292e6), set("N", 0.31), set("C", 0.025), set("M", 1.09);
  set("TM", 1356), set("TR", 294), set("EPSO", 1.0), set("CP", 383);
  m.control.end_time = 100e-6;
  return m;
}

}  // namespace

// Final length and footprint diameter against the measured ones.  Measured here: Lf 17.30 mm
// (+6.7 %), Dm 14.51 mm (+7.0 %): NOT agreement at the few-percent level.  Separated (issue 13,
// bench/bench_taylor_ofhc.cpp, docs/validation.md "OFHC copper with Johnson-Cook"): the length is converged
// (refined 2x, 3x and 4x in each direction it moves by 0.2 %) and does not depend on VP or the wall
// friction beyond 1 %; a wall friction of 0.1 brings the footprint within 2 % of the measurement;
// the same solver reproduces a published Johnson-Cook Taylor bar of DynELA and Abaqus to 0.3 %.
// The +7 % length is the Johnson-Cook OFHC constants' (their rate term: C = 0 gives Lf -0.5 %).
// The test is a guard on this state (10 % bands around the measurement: a change that moves
// either away from it by ~3 % more fails it), not a passed validation.  The bar has stopped
// deforming: its length changes by less than 0.2 % over the last 10 us.
TEST(TaylorOfhc, JohnsonCookCopperAgainstTheMeasuredShape) {
  Model m = ofhc_taylor_bar();
  ScopedThreads one(1);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  StepStatus st = StepStatus::ok;
  double length_90us = 0;
  while ((st = eng.step()) == StepStatus::ok) {
    if (length_90us == 0 && s.time >= 90e-6) {
      const auto [zmin, zmax] = std::minmax_element(s.z.begin(), s.z.end());
      length_90us = *zmax - *zmin;
    }
  }
  ASSERT_EQ(st, StepStatus::finished);
  const auto [zmin, zmax] = std::minmax_element(s.z.begin(), s.z.end());
  const double length = *zmax - *zmin;
  double rmax = 0;
  for (std::size_t n = 0; n < s.x.size(); ++n) rmax = std::max(rmax, std::hypot(s.x[n], s.y[n]));
  const double dm = 2 * rmax;
  const double eps_max = *std::max_element(s.eps_p.begin(), s.eps_p.end());
  std::printf("OFHC Taylor bar (Johnson-Cook, 190 m/s): Lf %.3f mm (measured %.3f, %+.2f%%), Dm %.3f mm "
              "(measured %.3f, %+.2f%%), max eps_p %.3f, length change over the last 10 us %.2e mm, cycle %d\n",
              length * 1e3, kLfMeasured * 1e3, 100 * (length / kLfMeasured - 1), dm * 1e3, kDmMeasured * 1e3,
              100 * (dm / kDmMeasured - 1), eps_max, (length_90us - length) * 1e3, s.cycle);
  EXPECT_NEAR(length, kLfMeasured, 0.10 * kLfMeasured);
  EXPECT_NEAR(dm, kDmMeasured, 0.10 * kDmMeasured);
  EXPECT_LT(std::fabs(length_90us - length), 0.002 * length);  // the shape is final
}
