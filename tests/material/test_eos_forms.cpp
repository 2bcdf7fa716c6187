// Equation-of-state forms 5 (*EOS_RATIO_OF_POLYNOMIALS), 6 (*EOS_LINEAR_POLYNOMIAL_WITH_ENERGY_LEAK)
// and 8 (*EOS_TABULATED_COMPACTION) (impact3d/material/eos.h) on one solid through the cycle:
//  - form 5: the pressure is the ratio of polynomials of the solid's own mu and E every cycle
//    (compression and tension, where BETA mu^2 joins F1), to round-off (the energy update's
//    Newton iterations reach the fixed point); p and its slopes against the formula written out;
//  - form 6: a solid held still gains exactly the integral of the deposition curve, booked as
//    internal energy and external work (energy ratio 1); squeezed, p = a(mu) + b(mu) E with E
//    its own energy;
//  - form 8: loading follows the virgin curve C, unloading the line of slope K from the most
//    compacted point (to the pressure cutoff), reloading goes back up that line to the virgin
//    curve; the history value is the smallest ln V reached; the energy balance of the closed
//    test (prescribed motion work in, kinetic + internal + bulk viscosity out).
// Units SI.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "impact3d/output/restart_dump.h"
#include "tests/material/eos_test_util.h"

using namespace impact3d;
using namespace eos_test;

namespace {

// Form 5: F1 = 2e9 mu + 5e9 mu^2 + 1e10 mu^3 + 2e10 mu^4, F2 = 0.5 + 0.3 mu + 0.02 mu^4,
// F3 = 1e-9, F4 = 0, F5 = 1 + 0.1 mu, F6 = 1e-10, F7 = 0; ALPHA 0.1, BETA 1e9; E0 2e8.
EosData ratio_eos() {
  EosData e;
  e.form = 5;
  e.c[1] = 2e9, e.c[2] = 5e9, e.c[3] = 1e10, e.c[4] = 2e10;  // A11-A14
  e.c[5] = 0.5, e.c[6] = 0.3, e.c[9] = 0.02;                 // A20, A21, A24
  e.c[kEosRpF3] = 1e-9;                                      // A30
  e.c[kEosRpF3 + 8] = 1, e.c[kEosRpF3 + 9] = 0.1;            // A50, A51
  e.c[kEosRpF3 + 12] = 1e-10;                                // A60
  e.c[kEosRpAlpha] = 0.1, e.c[kEosRpBeta] = 1e9;
  e.e0 = 2e8;
  return e;
}
double ratio_pressure(double mu, double E) {
  double f1 = 2e9 * mu + 5e9 * mu * mu + 1e10 * mu * mu * mu + 2e10 * mu * mu * mu * mu;
  if (mu < 0) f1 += 1e9 * mu * mu;
  const double f2 = 0.5 + 0.3 * mu + 0.02 * mu * mu * mu * mu, f3 = 1e-9, f5 = 1 + 0.1 * mu, f6 = 1e-10;
  return (f1 + f2 * E + f3 * E * E) / (f5 + f6 * E) * (1 + 0.1 * mu);
}

}  // namespace

TEST(EosForms, RatioOfPolynomialsIsItsFormulaEveryCycle) {
  MaterialConstants m;
  m.rho = 2000;
  derive_eos_constants(ratio_eos(), m);
  double worst = 0, worst_mu = 0, worst_e = 0;
  for (double mu : {-0.08, -0.03, 0.0, 0.02, 0.07, 0.12})
    for (double E : {0.0, 1e8, 5e8}) {
      double p, dpdmu, dpde;
      calc_eos_ratio_of_polynomials(m.eos.data(), mu, E, p, dpdmu, dpde);
      worst = std::max(worst, std::fabs(p - ratio_pressure(mu, E)) / std::max(std::fabs(p), 1e6));
      const double h = 1e-6, he = 1e2;
      const double dm = (ratio_pressure(mu + h, E) - ratio_pressure(mu - h, E)) / (2 * h);
      const double de = (ratio_pressure(mu, E + he) - ratio_pressure(mu, E - he)) / (2 * he);
      if (mu != 0) worst_mu = std::max(worst_mu, std::fabs(dpdmu - dm) / std::fabs(dm));  // (BETA's kink at 0)
      worst_e = std::max(worst_e, std::fabs(dpde - de) / std::fabs(de));
    }
  std::printf("ratio of polynomials: worst |p - formula| / p %.2e, slopes in mu %.2e, in E %.2e\n", worst, worst_mu, worst_e);
  EXPECT_LT(worst, 1e-14);
  EXPECT_LT(worst_mu, 1e-7);
  EXPECT_LT(worst_e, 1e-7);
  // through the cycle (E changes every step: the update's fixed point is p(mu, E^{n+1}))
  Model cube = squeezed_cube(null_material(2000, ratio_eos()), 10, 10e-6);
  double worst_run = 0, mu_max = 0, mu_min = 0;
  run_cube(cube, [&](double mu, double p, double E) {
    worst_run = std::max(worst_run, std::fabs(p - ratio_pressure(mu, E)) / std::fabs(ratio_pressure(mu, E)));
  }, mu_max, mu_min);
  std::printf("ratio of polynomials through the cycle: mu %.4f .. %.4f, worst |p - p(mu, E)| / p = %.2e\n", mu_min, mu_max, worst_run);
  EXPECT_GT(mu_max, 0.1);
  EXPECT_LT(mu_min, -0.04);
  EXPECT_LT(worst_run, 1e-12);
}

namespace {

// Form 6: p = 2.2e9 mu + 0.4 E (C1, C4), E0 1e8, the deposition rate 1e13 -> 2e13 Pa/s over
// 0..10 us (extended beyond: 3e13 at 20 us).
EosData leak_eos() {
  EosData e;
  e.form = 6;
  e.c[1] = 2.2e9, e.c[4] = 0.4;
  e.c[kEosLeakCurve] = 2;
  e.e0 = 1e8;
  return e;
}
LoadCurve leak_curve() {
  LoadCurve lc;
  lc.number = 2;
  lc.t = {0, 10e-6};
  lc.f = {1e13, 2e13};
  return lc;
}
// The curve's integral from 0 to t (1e13 t + 5e17 t^2).
double deposited(double t) { return 1e13 * t + 0.5e18 * t * t; }

}  // namespace

TEST(EosForms, EnergyLeakDepositsTheCurvesIntegral) {
  // a solid held still: E(t) = E0 + the integral, p = 0.4 E, books: internal = external work
  solve_test::Box b;
  b.lx = b.ly = b.lz = 1e-3;
  Model m = solve_test::make_box_model(b, null_material(1000, leak_eos()), 20e-6, 7);
  m.load_curves = {leak_curve()};
  m.load_curves[0].number = 2;
  m.control.numlc = 1;
  {
    solve_test::ScopedThreads one(1);
    Engine eng(m);
    ASSERT_EQ(eng.initialize(), StepStatus::ok);
    const State& s = eng.state();
    const int h = s.mats[0].eos_hist;
    double worst = 0, worst_p = 0, worst_books = 0;
    StepStatus st;
    int cycles = 0;
    while ((st = eng.step()) == StepStatus::ok || st == StepStatus::finished) {
      const double E = s.hist[std::size_t(h)], want = 1e8 + deposited(s.time);
      worst = std::max(worst, std::fabs(E - want) / want);
      worst_p = std::max(worst_p, std::fabs(pressure(s, 0) - 0.4 * E) / (0.4 * E));
      const double vref = s.vol0[0];
      worst_books = std::max(worst_books, std::fabs(s.internal - deposited(s.time) * vref) / (deposited(s.time) * vref));
      worst_books = std::max(worst_books, std::fabs(s.external_work - s.internal) / s.internal);
      ++cycles;
      if (st == StepStatus::finished) break;
    }
    EXPECT_EQ(st, StepStatus::finished);
    std::printf("energy leak, held still: %d cycles to %.3e s, E = E0 + integral to %.2e, p = 0.4 E to %.2e, books %.2e, energy ratio %.15f\n",
                cycles, s.time, worst, worst_p, worst_books, s.energy_ratio());
    EXPECT_GT(cycles, 20);
    EXPECT_LT(worst, 1e-13);
    EXPECT_LT(worst_p, 1e-13);
    EXPECT_LT(worst_books, 1e-12);
    EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-12);
  }
  // squeezed: p = 2.2e9 mu + 0.4 E with the solid's own E (which holds the deposit and the
  // work: run_cube checks E V0 = E0 V0 + internal + bulk viscosity every cycle)
  Model cube = squeezed_cube(null_material(1000, leak_eos()), 10, 10e-6);
  cube.load_curves.push_back(leak_curve());
  cube.control.numlc = 2;
  double worst_run = 0, mu_max = 0, mu_min = 0, ratio = 0;
  run_cube(cube, [&](double mu, double p, double E) {
    const double want = 2.2e9 * mu + 0.4 * E;
    worst_run = std::max(worst_run, std::fabs(p - want) / std::fabs(want));
  }, mu_max, mu_min, [&](const State& s) { ratio = s.energy_ratio(); });
  std::printf("energy leak, squeezed: mu %.4f .. %.4f, worst |p - (a + b E)| / p = %.2e, energy ratio %.9f\n", mu_min, mu_max, worst_run, ratio);
  EXPECT_LT(worst_run, 1e-12);
  EXPECT_NEAR(ratio, 1.0, 1e-3);
}

namespace {

// Form 8: 5 points EV 0 .. -0.3, C convex, T falling, GAMMA 0.5, K 2e9 .. 12e9.
const double kEv[5] = {0, -0.05, -0.1, -0.2, -0.3}, kC[5] = {0, 5e7, 1.5e8, 5e8, 1.2e9}, kT[5] = {1, 1, 0.9, 0.8, 0.8},
             kK[5] = {2e9, 3e9, 5e9, 8e9, 12e9};
EosData compaction_eos() {
  EosData e;
  e.form = 8;
  for (int j = 0; j < 5; ++j) {
    e.c[std::size_t(j)] = kEv[j];
    e.c[std::size_t(kEosTabC + j)] = kC[j];
    e.c[std::size_t(kEosTabT + j)] = kT[j];
    e.c[std::size_t(kEosTabK + j)] = kK[j];
  }
  e.c[kEosTabGamma] = 0.5;
  return e;
}
// Piecewise-linear interpolation of column y in ev (end segments extended; hold: held at the
// ends instead), by its own search.
double column(const double* y, double ev, bool hold = false) {
  int i = 0;
  for (int j = 0; j < 4; ++j)
    if (ev <= kEv[j]) i = j;
  double w = (ev - kEv[i]) / (kEv[i + 1] - kEv[i]);
  if (hold) w = std::min(1.0, std::max(0.0, w));
  return y[i] + w * (y[i + 1] - y[i]);
}
double compaction_pressure(double ev, double ev_min, double E) {
  return column(kC, ev_min) + column(kK, ev_min, true) * (ev_min - ev) + 0.5 * column(kT, ev) * E;
}

}  // namespace

TEST(EosForms, TabulatedCompactionLoadsOnCUnloadsOnKAndReloadsToTheVirginCurve) {
  // top face (1 mm cube): in at 10 m/s for 14 us (ln V to -0.151), out for 6 us (to -0.088),
  // in for 14 us (to -0.27, past the first maximum); PC -2e7 (the unloading reaches it)
  const double V = 10, T = 14e-6;
  MaterialData md = null_material(1800, compaction_eos());
  param_value(md, *find_param(material_type(9), "PC")) = -2e7;
  Model cube = squeezed_cube_path(md, {0, T, T * 1.0000001, T + 6e-6, T + 6e-6 * 1.0000001, 10 * T}, {-V, -V, V, V, -V, -V},
                                  T + 6e-6 + 14e-6);
  double ev_min = 0, first_max = 0, worst = 0;
  int loading = 0, on_line = 0, at_cutoff = 0, back_on_virgin = 0, hist_bad = 0;
  double mu_max = 0, mu_min = 0;
  run_cube(cube, [&](double mu, double p, double E) {
    const double ev = -std::log(1 + mu);  // the kernel's own operations
    const bool virgin = ev <= ev_min;
    if (ev < ev_min) ev_min = ev;
    const double want = std::max(compaction_pressure(ev, ev_min, E), -2e7);
    worst = std::max(worst, std::fabs(p - want) / 1e8);
    if (want == -2e7) ++at_cutoff;
    if (!virgin && first_max == 0) first_max = ev_min;  // the first unloading
    if (!virgin) ++on_line;
    else if (first_max == 0) ++loading;
    else ++back_on_virgin;
  }, mu_max, mu_min, [&](const State& s) {
    if (s.hist[std::size_t(s.mats[0].eos_hist + 1)] != ev_min) ++hist_bad;  // the smallest ln V so far
  });
  std::printf("tabulated compaction: ln V to %.4f (first unloading from %.4f), cycles loading %d, unloading and reloading on K %d "
              "(at the cutoff %d), back on the virgin curve %d; worst |p - formula| / 1e8 Pa = %.2e\n",
              ev_min, first_max, loading, on_line, at_cutoff, back_on_virgin, worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(hist_bad, 0);
  EXPECT_NEAR(first_max, -0.151, 0.01);
  EXPECT_LT(ev_min, -0.25);
  EXPECT_GT(loading, 10);
  EXPECT_GT(on_line, 10);
  EXPECT_GT(at_cutoff, 0);
  EXPECT_GT(back_on_virgin, 10);
}

// The closed test: the cube's top face thrown down at 150 m/s (bottom fixed, sides on rollers:
// no external work) compacts the solid on its virgin curve and springs back along K to the
// cutoff and on, twice; kinetic + internal energy stays the initial kinetic energy (the books'
// own half-step offset, KE at v^{n+1/2} and IE at t^n, is dt P / 2 while power P flows: the
// ratio is compared where the face comes to rest), the solid's E times its volume is the
// internal book (run_cube), and the compaction's hysteresis stays in it.
TEST(EosForms, TabulatedCompactionClosedEnergyBalance) {
  MaterialData md = null_material(1800, compaction_eos());
  param_value(md, *find_param(material_type(9), "PC")) = -2e7;
  md.q1 = md.q2 = 0;  // the compaction alone dissipates
  solve_test::Box b;
  b.lx = b.ly = b.lz = 1e-3;
  Model m = solve_test::make_box_model(b, md, 30e-6, 4);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.z[std::size_t(n)] == 0) m.bc[std::size_t(n)] = 7;
  solve_test::set_velocity_field(m, [](double, double, double z) { return std::array<double, 3>{0, 0, z > 0 ? -150.0 : 0.0}; });
  m.control.tssf = 0.02;  // a single solid on its top face's mass: some 100 steps a compaction
  double worst_ratio = 0, worst_at_rest = 0, ev_min = 0, ke0 = -1, ie_end = 0, ev_end = 0, mu_max = 0, mu_min = 0;
  int at_rest = 0;
  run_cube(m, [&](double mu, double, double) {
    ev_min = std::min(ev_min, -std::log(1 + mu));
    ev_end = -std::log(1 + mu);
  }, mu_max, mu_min, [&](const State& s) {
    if (ke0 < 0) ke0 = s.initial_total;
    worst_ratio = std::max(worst_ratio, std::fabs(s.energy_ratio() - 1));
    if (s.kinetic < 1e-3 * ke0) worst_at_rest = std::max(worst_at_rest, std::fabs(s.energy_ratio() - 1)), ++at_rest;
    ie_end = s.internal + s.bulk_viscous;
  });
  std::printf("tabulated compaction, closed: KE0 %.4e J, most compacted ln V %.4f, at the end ln V %.4f with %.4e J internal "
              "(%.1f%% of KE0); |energy ratio - 1| at rest (%d cycles) %.2e, anywhere %.2e\n", ke0, ev_min, ev_end, ie_end, 100 * ie_end / ke0,
              at_rest, worst_at_rest, worst_ratio);
  EXPECT_LT(ev_min, -0.1);
  EXPECT_GT(ev_end, ev_min + 0.01);  // sprung back
  EXPECT_GT(ie_end, 0.3 * ke0);      // the hysteresis stays
  EXPECT_GT(at_rest, 5);
  EXPECT_LT(worst_at_rest, 1e-3);  // measured 5.6e-4 (the kinks of the path: loading/unloading, the cutoff)
  EXPECT_LT(worst_ratio, 2e-2);
}

// A restart dump taken while the compacted solid unloads keeps its history (E and the most
// compacted ln V, restored with the rest of State::hist): the continued run, unloading and
// reloading to the virgin curve, is the same bits.
TEST(EosForms, TabulatedCompactionRestartDumpContinuesBitForBit) {
  const double V = 10, T = 14e-6;
  MaterialData md = null_material(1800, compaction_eos());
  param_value(md, *find_param(material_type(9), "PC")) = -2e7;
  Model m = squeezed_cube_path(md, {0, T, T * 1.0000001, T + 6e-6, T + 6e-6 * 1.0000001, 10 * T}, {-V, -V, V, V, -V, -V},
                               T + 6e-6 + 14e-6);
  solve_test::ScopedThreads one(1);
  Engine a(m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  for (int c = 0; c < 55; ++c) ASSERT_EQ(a.step(), StepStatus::ok);
  const int h = a.state().mats[0].eos_hist;
  ASSERT_GT(-std::log(a.state().vol0[0] / a.state().vol[0]), a.state().hist[std::size_t(h + 1)]);  // unloading
  DumpHeader dh;
  dh.deck_name = "compaction.k";
  dh.deck_text = "*KEYWORD\n*END\n";
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/eos_compaction_restart_dump";
  write_restart_dump(path, dh, a.state(), a.contact().restart_data());
  Engine b(m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  StepStatus sa = StepStatus::ok, sb = StepStatus::ok;
  int cycles = 0;
  while (sa == StepStatus::ok && sb == StepStatus::ok) sa = a.step(), sb = b.step(), ++cycles;
  EXPECT_EQ(sa, StepStatus::finished);
  EXPECT_EQ(sb, StepStatus::finished);
  EXPECT_GT(cycles, 50);
  EXPECT_EQ(a.state().hist, b.state().hist);
  EXPECT_EQ(a.state().sig, b.state().sig);
  EXPECT_EQ(a.state().z, b.state().z);
  EXPECT_EQ(a.state().internal, b.state().internal);
  EXPECT_LT(a.state().hist[std::size_t(h + 1)], -0.25);  // reloaded past the first maximum
}
