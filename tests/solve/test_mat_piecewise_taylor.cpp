// Materials that coincide in full runs: type 24 with a two-point table, and Johnson-Cook (15, 98)
// with n = 1, C = 0 and no heating, with type 3's bilinear hardening give type 3's Taylor bar;
// type 24 deletes at FAIL and below TDEL.

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

Model taylor_bar() {
  Model m;
  Diagnostics diag;
  EXPECT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/taylor_bar.dyn", m, diag));
  return m;
}

// The deck's type-3 copper (sigma_y 0.4 GPa, E_tan 0.1 GPa, beta 1) as type 24 with the
// two-point table (0, sigma_y), (1, sigma_y + E_p), E_p = E E_tan / (E - E_tan).
void to_piecewise_linear(MaterialData& md) {
  const MaterialType& t = material_type(24);
  const double Ep = md.E * md.E_tan / (md.E - md.E_tan);
  const MaterialData keep = md;
  md.type = 24;
  set_param_defaults(md, t);  // (every parameter of type 24 to its default: E, nu, ... too)
  md.E = keep.E, md.nu = keep.nu, md.sigma_y = keep.sigma_y, md.E_tan = keep.E_tan;
  param_value(md, *find_param(t, "EPS1")) = 0;
  param_value(md, *find_param(t, "ES1")) = md.sigma_y;
  param_value(md, *find_param(t, "EPS2")) = 1;
  param_value(md, *find_param(t, "ES2")) = md.sigma_y + Ep;
}

struct Shape {
  double length, eps_max;
};

Shape run(const Model& m, State* out = nullptr) {
  ScopedThreads one(1);
  Engine eng(m);
  EXPECT_EQ(eng.run_to_end(), StepStatus::finished);
  const State& s = eng.state();
  const auto [zmin, zmax] = std::minmax_element(s.z.begin(), s.z.end());
  if (out) *out = s;
  return {*zmax - *zmin, *std::max_element(s.eps_p.begin(), s.eps_p.end())};
}

}  // namespace

// Same hardening line, same return in exact arithmetic (type 3: d eps = f / (3G + E_p); type
// 24: the segment's (q - h(eps0)) / (3G + H)): the runs differ by rounding only (the table's
// slope is (sigma_y + E_p - sigma_y) / 1, not E_p bit for bit), which 80 us of plastic flow
// amplifies; 1e-6 of the length (21 nm of 21 mm) and 1e-5 of the largest plastic strain are
// far below the mesh's own error and far above rounding.
TEST(MatPiecewiseLinearRun, TwoPointTableTaylorBarIsTypeThree) {
  Model m3 = taylor_bar();
  Model m24 = m3;
  to_piecewise_linear(m24.materials[0]);
  const Shape a = run(m3), b = run(m24);
  std::printf("Taylor bar: type 3 L %.9f mm, eps_max %.7f; type 24 L %.9f mm, eps_max %.7f (relative %.2e, %.2e)\n",
              a.length * 1e3, a.eps_max, b.length * 1e3, b.eps_max, std::fabs(b.length / a.length - 1),
              std::fabs(b.eps_max / a.eps_max - 1));
  EXPECT_NEAR(b.length, a.length, 1e-6 * a.length);
  EXPECT_NEAR(b.eps_max, a.eps_max, 1e-5 * a.eps_max);
}

// FAIL 1.5 (the bar's face reaches about 3) to 30 us: exactly the solids whose plastic strain
// reached FAIL are deleted, and they carry no stress.
TEST(MatPiecewiseLinearRun, DeletesAtFailurePlasticStrain) {
  Model m = taylor_bar();
  to_piecewise_linear(m.materials[0]);
  m.materials[0].fail_strain = 1.5;
  m.control.end_time = 30e-6;
  State s;
  run(m, &s);
  int failed = 0;
  for (int e = 0; e < s.ne; ++e) {
    const std::size_t k = std::size_t(e);
    if (s.failed[k]) {
      ++failed;
      EXPECT_GE(s.eps_p[k], 1.5) << e;
      for (int c = 0; c < 6; ++c) EXPECT_EQ(s.sig[6 * k + std::size_t(c)], 0.0);
    } else {
      EXPECT_LT(s.eps_p[k], 1.5) << e;
    }
  }
  std::printf("FAIL 1.5: %d of %d solids deleted by 30 us\n", failed, s.ne);
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, s.ne / 4);
}

// TDEL above every solid's step: every solid is deleted in the first cycle that computes
// stresses; with TDEL below every step none is.
TEST(MatPiecewiseLinearRun, DeletesBelowTdel) {
  for (double tdel : {1.0, 1e-12}) {
    Model m = taylor_bar();
    to_piecewise_linear(m.materials[0]);
    param_value(m.materials[0], *find_param(material_type(24), "TDEL")) = tdel;
    m.control.end_time = 1e-6;
    State s;
    run(m, &s);
    const long failed = std::count_if(s.failed.begin(), s.failed.end(), [](unsigned char f) { return f != 0; });
    EXPECT_EQ(failed, tdel > 1e-3 ? long(s.ne) : 0L) << "TDEL " << tdel;
  }
}

// Johnson-Cook with A = sigma_y, B = E_p, n = 1, C = 0, no thermal terms: type 3's hardening
// line; the Newton return converges to 1e-15 (type 15 also rebuilds E and nu from K and G:
// rounding), so the same tolerances as the two-point table apply.
TEST(MatPiecewiseLinearRun, LinearJohnsonCookTaylorBarIsTypeThree) {
  Model m3 = taylor_bar();
  const Shape a = run(m3);
  for (int type : {15, 98}) {
    Model m = m3;
    MaterialData& md = m.materials[0];
    const double Ep = md.E * md.E_tan / (md.E - md.E_tan), sy = md.sigma_y, E = md.E, nu = md.nu;
    const MaterialType& t = material_type(type);
    md.type = type;
    set_param_defaults(md, t);
    md.E = E, md.nu = nu;
    auto set = [&](const char* k, double v) { param_value(md, *find_param(t, k)) = v; };
    set("A", sy), set("B", Ep), set("N", 1.0), set("EPSO", 1.0);
    if (type == 15) set("G", E / (2 * (1 + nu)));
    const Shape b = run(m);
    std::printf("Taylor bar: type %d L %.9f mm, eps_max %.7f (relative to type 3 %.2e, %.2e)\n", type, b.length * 1e3,
                b.eps_max, std::fabs(b.length / a.length - 1), std::fabs(b.eps_max / a.eps_max - 1));
    EXPECT_NEAR(b.length, a.length, 1e-6 * a.length) << type;
    EXPECT_NEAR(b.eps_max, a.eps_max, 1e-5 * a.eps_max) << type;
  }
}
