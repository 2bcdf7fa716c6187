#pragma once
// Builders for single-solid equation-of-state tests (material/eos.h): a *MAT_NULL material with
// an EOS, one 1 mm cube squeezed and stretched uniaxially along z by a prescribed velocity of
// its top face (bottom fixed, sides on rollers), and a driver that checks every cycle.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

namespace eos_test {

using namespace impact3d;

inline MaterialData null_material(double rho, const EosData& eos) {
  MaterialData md;
  md.number = 1;
  md.type = 9;
  set_param_defaults(md, material_type(9));
  md.rho = rho;
  md.eos = eos;
  md.title = "null + EOS";
  return md;
}

inline double pressure(const State& s, int e) {
  const double* g = &s.sig[6 * std::size_t(e)];
  return -(g[0] + g[1] + g[2]) / 3;
}

// The cube with the top face's z velocity the piecewise-linear curve (t[i], v[i]) (its load
// curve 1 is the last of m.load_curves), run to end_time.
inline Model squeezed_cube_path(const MaterialData& md, const std::vector<double>& t, const std::vector<double>& v,
                                double end_time) {
  solve_test::Box b;
  b.lx = b.ly = b.lz = 1e-3;
  Model m = solve_test::make_box_model(b, md, end_time, 4);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.z[std::size_t(n)] == 0) m.bc[std::size_t(n)] = 7;
  LoadCurve lc;
  lc.number = int(m.load_curves.size()) + 1;
  lc.t = t;
  lc.f = v;
  m.load_curves.push_back(lc);
  m.control.numlc = int(m.load_curves.size());
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (m.z[std::size_t(n)] == 0) continue;
    PrescribedMotion pm;
    pm.node = n;
    pm.dir = {0, 0, 1};
    pm.curve = lc.number - 1;
    m.prescribed_motions.push_back(pm);
  }
  m.control.tssf = 0.5;
  return m;
}

// The top face moving at -V for T then +V for 1.5 T (mu from 0 to 0.111 and back to -0.048 for
// V T = 0.1 mm).
inline Model squeezed_cube(const MaterialData& md, double V, double T) {
  return squeezed_cube_path(md, {0, T, T * 1.0000001, 3 * T}, {-V, -V, V, V}, 2.5 * T);
}

// Runs the cube; calls check(mu, p, E) after every cycle (check_state(s) too, if given);
// returns the largest mu reached in compression and the smallest in tension.  Every cycle the
// element's energy E times its reference volume (the initial volume / V0) is E0 times it plus
// the work the global books hold (stress and bulk viscosity, and an EOS's deposit).
template <class F, class G>
void run_cube(Model& m, F check, double& mu_max, double& mu_min, G check_state) {
  solve_test::ScopedThreads one(1);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  const int h = s.mats[0].eos_hist;
  ASSERT_GE(h, 0);
  mu_max = 0, mu_min = 0;
  StepStatus st = StepStatus::ok;
  int cycles = 0;
  while ((st = eng.step()) == StepStatus::ok || st == StepStatus::finished) {
    const double mu = s.vol0[0] / s.vol[0] - 1;
    const double E = s.hist[std::size_t(h)];
    check(mu, pressure(s, 0), E);
    check_state(s);
    const double e0 = m.materials[0].eos.e0, vref = s.vol0[0] / m.materials[0].eos.v0;
    EXPECT_NEAR(E * vref, e0 * vref + s.internal + s.bulk_viscous, 1e-9 * (std::fabs(e0 * vref) + std::fabs(s.internal) + 1e-12));
    mu_max = std::max(mu_max, mu), mu_min = std::min(mu_min, mu);
    ++cycles;
    if (st == StepStatus::finished) break;
  }
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_GT(cycles, 20);
}

template <class F>
void run_cube(Model& m, F check, double& mu_max, double& mu_min) {
  run_cube(m, check, mu_max, mu_min, [](const State&) {});
}

}  // namespace eos_test
