// *MAT_MODIFIED_JOHNSON_COOK (type 107) with *INITIAL_TEMPERATURE_SET / _NODE in keyword decks as
// LS-DYNA users write them, run by the engine against a closed form:
//  - one solid (symmetry planes x = 0, y = 0, z = 0) compressed along x by its face x = L at a
//    constant speed (after a 10 us ramp) to a true strain of -0.4 at about 3000 /s, starting at
//    the 400 K its nodes are given (T0 293 K), heated adiabatically (XSI 0.9): its axial stress
//    and temperature follow the uniaxial-stress model integrated by hand (E d eps_e = d sigma,
//    |sigma| = (A + B p^N) (1 + pdot/E0DOT)^C (1 - T*^M), dT = XSI |sigma| dp / (RO CP), pdot the
//    plastic strain rate over the step), in 20000 steps: stress within 0.5 %, temperature within
//    0.5 K, from p = 0.02;
//  - the same deck with the nodes at T0 (no *INITIAL_TEMPERATURE) runs stronger, as the closed
//    form at 293 K says;
//  - FLAG1 = 1 (Zerilli-Armstrong, AK4-1 aluminium's constants of the split-Hopkinson deck, SI):
//    the same cube at about 3000 /s from 293 K and from 500 K and at about 300 /s from 293 K
//    follows |sigma| = SIGA + B exp(-beta T) + A p^N exp(-alpha T), beta = BETA0 - BETA1 ln pdot*,
//    alpha = ALPHA0 - ALPHA1 ln pdot*, pdot* = max(pdot / E0DOT, 1), integrated by hand the same
//    way: von Mises stress within 0.3 % at every 0.02 of plastic strain from 0.02 to 0.4,
//    temperature within 0.5 K; its temperature rise equals XSI x (the plastic work the run did,
//    sum of sigma_y dp) / (RO CP) within 1e-9 relative;
//  - options the code cannot honour are refused by field (1102) with file, line, card, field and
//    columns; TC erodes the solid when its temperature reaches it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

namespace {

// 2024-T3-like aluminium (SI)
constexpr double kRho = 2770, kE = 73.1e9, kPr = 0.33, kA = 369e6, kB = 684e6, kN = 0.73, kC = 0.0083, kM = 1.7,
                 kTm = 775, kTr = 293, kT0 = 293, kE0 = 1.0, kCp = 875, kXsi = 0.9, kL = 0.01;
// Zerilli-Armstrong (FLAG1 = 1): AK4-1 aluminium as the split-Hopkinson deck gives it (MPa -> Pa)
constexpr double kSiga = 282e6, kZB = 224e6, kBeta0 = 0.0064, kBeta1 = 3.5e-4, kZA = 625e6, kZN = 0.56,
                 kAlpha0 = 0.00226, kAlpha1 = 1.23e-4;

std::string I(long v, int w = 10) {
  char b[32];
  std::snprintf(b, sizeof b, "%*ld", w, v);
  return b;
}
std::string F(double v, int w = 10) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.*g", w, w > 10 ? 9 : 6, v);
  return b;
}

bool read_text(const std::string& text, Model& m, Diagnostics& d, const char* name = "mjc.k") {
  DeckFile deck;
  deck.load_from_string(name, text);
  return read_deck(deck, m, d, InputOptions{}) && check_model(m, d);
}

std::string messages(const Diagnostics& d) {
  std::ostringstream os;
  d.print(os);
  return os.str();
}

struct Options {
  double t_init = 400;   // *INITIAL_TEMPERATURE_SET on all nodes (0: none)
  bool node_cards = false;  // as *INITIAL_TEMPERATURE_NODE cards instead
  double beta = 0, alpha = 0, flag1 = 0, flag2 = 0, q1 = 0, d1 = 0, wc = 0, tc = 0;
  bool za = false;  // FLAG1 = 1 with the Zerilli-Armstrong constants above
  double za_a = kZA;
};

std::string mat_cards(const Options& o) {
  std::ostringstream d;
  d << "*MAT_MODIFIED_JOHNSON_COOK_TITLE\naluminium\n"
    << "$#     mid        ro         e        pr      beta       xsi        cp     alpha\n"
    << I(1) << F(kRho) << F(kE) << F(kPr) << F(o.beta) << F(kXsi) << F(kCp) << F(o.alpha) << "\n"
    << "$#   e0dot        tr        tm        t0     flag1     flag2\n"
    << F(kE0) << F(kTr) << F(kTm) << F(kT0) << F(o.za ? 1.0 : o.flag1) << F(o.flag2) << "\n"
    << "$#  a/siga       b/b   n/beta0   c/beta1      m/na\n";
  if (o.za)
    d << F(kSiga) << F(kZB) << F(kBeta0) << F(kBeta1) << F(0.0) << "\n"
      << "$#    q1/a      c1/n q2/alpha0 c2/alpha1\n" << F(o.za_a) << F(kZN) << F(kAlpha0) << F(kAlpha1) << "\n";
  else
    d << F(kA) << F(kB) << F(kN) << F(kC) << F(kM) << "\n"
      << "$#    q1/a      c1/n q2/alpha0 c2/alpha1\n" << F(o.q1) << F(0.0) << F(0.0) << F(0.0) << "\n";
  d
    << "$#   dc/dc     pd/wc     d1/na     d2/na     d3/na     d4/na     d5/na\n"
    << F(0.0) << F(o.wc) << F(o.d1) << F(0.0) << F(0.0) << F(0.0) << F(0.0) << "\n"
    << "$#      tc      tauc\n" << F(o.tc) << F(0.0) << "\n";
  return d.str();
}

// One cube (side kL), symmetry planes, face x = kL moved at -v after a ramp over t_ramp.
std::string cube_deck(const Options& o, double t_end, double v, double t_ramp) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\naluminium cube in uniaxial compression\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*PART\ncube\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n" << mat_cards(o)
    << "*DEFINE_CURVE\n         2\n" << F(0.0, 20) << F(0.0, 20) << "\n" << F(t_ramp, 20) << F(1.0, 20) << "\n"
    << F(2 * t_end, 20) << F(1.0, 20) << "\n*NODE\n";
  const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int n = 0; n < 8; ++n) d << I(n + 1, 8) << F(kL * c[n][0], 16) << F(kL * c[n][1], 16) << F(kL * c[n][2], 16) << "\n";
  d << "*ELEMENT_SOLID\n" << I(1, 8) << I(1, 8);
  for (int n = 1; n <= 8; ++n) d << I(n, 8);
  d << "\n*BOUNDARY_SPC_NODE\n";
  for (int n = 0; n < 8; ++n) d << I(n + 1) << I(0) << I(c[n][0] == 0) << I(c[n][1] == 0) << I(c[n][2] == 0) << "\n";
  d << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int n = 0; n < 8; ++n)
    if (c[n][0] == 1) d << I(n + 1) << I(1) << I(0) << I(2) << F(-v) << "\n";
  if (o.t_init > 0 && o.node_cards) {
    d << "*INITIAL_TEMPERATURE_NODE\n$#     nid      temp       loc\n";
    for (int n = 1; n <= 8; ++n) d << I(n) << F(o.t_init) << I(0) << "\n";
  } else if (o.t_init > 0) {
    d << "*SET_NODE_LIST\n         5\n";
    for (int n = 1; n <= 8; ++n) d << I(n);
    d << "\n*INITIAL_TEMPERATURE_SET\n$#    nsid      temp       loc\n" << I(5) << F(o.t_init) << I(0) << "\n";
  }
  d << "*END\n";
  return d.str();
}

double flow(double p, double pdot, double T) {
  const double ts = (T - kTr) / (kTm - kTr);
  const double theta = ts <= 0 ? 1.0 : ts >= 1 ? 0.0 : 1 - std::pow(ts, kM);
  return (kA + kB * std::pow(p, kN)) * std::pow(1 + pdot / kE0, kC) * theta;
}

// the Zerilli-Armstrong flow stress (FLAG1 = 1), T absolute
double flow_za(double p, double pdot, double T) {
  const double L = pdot / kE0 > 1 ? std::log(pdot / kE0) : 0.0;
  return kSiga + kZB * std::exp(-(kBeta0 - kBeta1 * L) * T) + kZA * std::pow(p, kZN) * std::exp(-(kAlpha0 - kAlpha1 * L) * T);
}

// The uniaxial-stress model along the run's strain history (the face's travel under the ramped
// speed, true strain, compression positive), integrated by hand: steps of h (the last one shorter,
// to land on t), each solving E (eps - ep - dp) = (A + B (p + dp)^N) (1 + dp/(h E0DOT))^C theta(T)
// for dp by bisection, then T += XSI sigma dp / (RO CP) (the temperature factor of the step's
// start, as the solid).
struct OneD {
  double sigma = 0, p = 0, T = 0, ep = 0, t = 0;
  double v = 0, t_ramp = 0;
  bool za = false;
  double law(double p1, double pdot, double T1) const { return za ? flow_za(p1, pdot, T1) : flow(p1, pdot, T1); }
  double strain(double t1) const {
    const double d = t1 <= t_ramp ? 0.5 * v * t1 * t1 / t_ramp : v * (t1 - 0.5 * t_ramp);
    return -std::log(1 - d / kL);
  }
  void step(double h) {
    const double eps = strain(t + h);
    const double trial = kE * (eps - ep);
    double dp = 0;
    if (trial > law(p, 0, T)) {
      double lo = 0, hi = trial / kE;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (kE * (eps - ep - mid) > law(p + mid, mid / h, T) ? lo : hi) = mid;
      }
      dp = 0.5 * (lo + hi);
    }
    ep += dp;
    sigma = kE * (eps - ep);
    p += dp;
    T += kXsi * sigma * dp / (kRho * kCp);
    t += h;
  }
  // the state at t1 >= t: whole steps of h kept, the last partial one on a copy
  OneD at(double t1, double h) {
    while (t + h <= t1) step(h);
    OneD c = *this;
    if (t1 > c.t) c.step(t1 - c.t);
    return c;
  }
};

}  // namespace

TEST(ModifiedJohnsonCook, CompressedCubeFollowsTheFlowStressWithHeating) {
  const double v = 30, t_ramp = 1e-5, t_end = 1.1e-4;  // true strain about -0.4 at 3000-4500 /s
  double final_q[3] = {0, 0, 0};
  for (int variant = 0; variant < 3; ++variant) {
    Options o;
    o.node_cards = variant == 1;
    if (variant == 2) o.t_init = 0;  // the nodes at T0
    Model m;
    Diagnostics dg;
    ASSERT_TRUE(read_text(cube_deck(o, t_end, v, t_ramp), m, dg)) << messages(dg);
    ASSERT_EQ(m.materials[0].type, 107);
    Engine e(m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    const double T_start = variant == 2 ? kT0 : o.t_init;
    EXPECT_EQ(s.hist[0], T_start);
    double worst_s = 0, worst_q = 0, worst_T = 0, last_p = 0;
    OneD ref_run;
    ref_run.T = T_start, ref_run.v = v, ref_run.t_ramp = t_ramp;
    int checks = 0;
    StepStatus st = StepStatus::ok;
    while (st == StepStatus::ok && !e.finished()) {
      st = e.step();
      if (s.eps_p[0] < 0.02 || s.eps_p[0] < last_p + 0.02) continue;
      last_p = s.eps_p[0];
      ++checks;
      const OneD ref = ref_run.at(s.time, 5e-9);
      const double q = -s.sig[0] + 0.5 * (s.sig[1] + s.sig[2]);  // the von Mises stress (sigma_yy ~ sigma_zz)
      worst_q = std::max(worst_q, std::fabs(q / ref.sigma - 1));
      worst_s = std::max(worst_s, std::fabs(-s.sig[0] / ref.sigma - 1));
      worst_T = std::max(worst_T, std::fabs(s.hist[0] - ref.T));
    }
    ASSERT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << int(st);
    EXPECT_GT(last_p, 0.3);
    EXPECT_GE(checks, 10);
    EXPECT_LT(worst_q, 0.003) << "variant " << variant;
    EXPECT_LT(worst_s, 0.03) << "variant " << variant;
    EXPECT_LT(worst_T, 0.5) << "variant " << variant;
    EXPECT_GT(s.hist[0] - T_start, 30.0);  // it heated
    final_q[variant] = -s.sig[0] + 0.5 * (s.sig[1] + s.sig[2]);
    std::printf("variant %d: worst |q/closed - 1| %.3e, |sigma_xx/closed - 1| %.3e, |T - closed| %.3f K, final p %.3f, T %.1f K\n",
                variant, worst_q, worst_s, worst_T, s.eps_p[0], s.hist[0]);
    RecordProperty("worst_flow_stress_" + std::to_string(variant), std::to_string(worst_q));
  }
  EXPECT_EQ(final_q[0], final_q[1]);        // the set and the node cards: the same temperatures
  EXPECT_GT(final_q[2], 1.05 * final_q[0]);  // from 293 K it stays stronger
}

// FLAG1 = 1: the Zerilli-Armstrong flow stress at two rates and two temperatures, and the
// adiabatic heating against the plastic work the run did.
TEST(ModifiedJohnsonCook, ZerilliArmstrongCubeFollowsTheFlowStressWithHeating) {
  struct Variant {
    double v, t_ramp, t_end, t_init, h;
  };
  const Variant variants[] = {{30, 1e-5, 1.1e-4, 293, 5e-9}, {30, 1e-5, 1.1e-4, 500, 5e-9}, {3, 1e-4, 1.1e-3, 293, 5e-8}};
  double final_q[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const Variant& var = variants[k];
    Options o;
    o.za = true, o.t_init = var.t_init;
    Model m;
    Diagnostics dg;
    ASSERT_TRUE(read_text(cube_deck(o, var.t_end, var.v, var.t_ramp), m, dg)) << messages(dg);
    Engine e(m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    ASSERT_EQ(s.hist[0], var.t_init);
    double worst_q = 0, worst_T = 0, last_p = 0, work = 0, p_before = 0;
    OneD ref_run;
    ref_run.T = var.t_init, ref_run.v = var.v, ref_run.t_ramp = var.t_ramp, ref_run.za = true;
    int checks = 0;
    StepStatus st = StepStatus::ok;
    while (st == StepStatus::ok && !e.finished()) {
      st = e.step();
      const double* g = &s.sig[0];
      const double q = std::sqrt(0.5 * ((g[0] - g[1]) * (g[0] - g[1]) + (g[1] - g[2]) * (g[1] - g[2]) + (g[2] - g[0]) * (g[2] - g[0])) +
                                 3 * (g[3] * g[3] + g[4] * g[4] + g[5] * g[5]));
      work += q * (s.eps_p[0] - p_before);  // sigma_y dp: after the return mapping q is sigma_y
      p_before = s.eps_p[0];
      if (s.eps_p[0] < 0.02 || s.eps_p[0] < last_p + 0.02) continue;
      last_p = s.eps_p[0];
      ++checks;
      const OneD ref = ref_run.at(s.time, var.h);
      worst_q = std::max(worst_q, std::fabs(q / ref.sigma - 1));
      worst_T = std::max(worst_T, std::fabs(s.hist[0] - ref.T));
    }
    ASSERT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << int(st);
    EXPECT_GT(last_p, 0.3);
    EXPECT_GE(checks, 10);
    EXPECT_LT(worst_q, 0.003) << "variant " << k;
    EXPECT_LT(worst_T, 0.5) << "variant " << k;
    const double rise = s.hist[0] - var.t_init, heat = kXsi * work / (kRho * kCp);
    EXPECT_GT(rise, 20.0);
    EXPECT_NEAR(rise, heat, 1e-9 * heat) << "variant " << k;
    final_q[k] = -s.sig[0] + 0.5 * (s.sig[1] + s.sig[2]);
    std::printf("ZA variant %d: worst |q/closed - 1| %.3e, |T - closed| %.3f K, final p %.3f, T %.1f K, dT %.4f vs XSI W/(RO CP) %.4f\n",
                k, worst_q, worst_T, s.eps_p[0], s.hist[0], rise, heat);
  }
  EXPECT_GT(final_q[0], final_q[1]);  // hotter: softer
  EXPECT_GT(final_q[0], final_q[2]);  // slower: softer
}

// The printed echo names the flow stress the run uses and, for FLAG1 = 1, card 4's A, N, ALPHA0,
// ALPHA1 (card 3's fields are echoed under both names).
TEST(ModifiedJohnsonCook, EchoNamesTheFlowStress) {
  for (bool za : {false, true}) {
    Options o;
    o.za = za;
    Model m;
    Diagnostics dg;
    ASSERT_TRUE(read_text(cube_deck(o, 1e-4, 1, 1e-5), m, dg)) << messages(dg);
    std::ostringstream os;
    echo_material_params(os, m.materials[0], *find_material_type(107));
    const std::string e = os.str();
    EXPECT_EQ(e.find("Zerilli-Armstrong") != std::string::npos, za) << e;
    EXPECT_EQ(e.find("6.250000e+08 5.600000e-01 2.260000e-03 1.230000e-04") != std::string::npos, za) << e;
    EXPECT_NE(e.find("FLAG1 1: BETA0"), std::string::npos) << e;
  }
}

TEST(ModifiedJohnsonCook, TemperatureTcErodesTheSolid) {
  Options o;
  o.tc = 440;  // 400 K at the start, about +60 K by the end
  Model m;
  Diagnostics dg;
  ASSERT_TRUE(read_text(cube_deck(o, 1.1e-4, 30, 1e-5), m, dg)) << messages(dg);
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  double T_before = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok && !e.finished() && !s.failed[0]) {
    T_before = s.hist[0];
    st = e.step();
  }
  ASSERT_TRUE(s.failed[0]) << "T " << s.hist[0];
  EXPECT_LT(T_before, 440.0);
  EXPECT_GE(s.hist[0], 440.0);
}

TEST(ModifiedJohnsonCook, UnsupportedOptionsAreRefusedByField) {
  struct Case {
    Options o;
    int id;
    const char* field;
    int col;
  };
  std::vector<Case> cases;
  auto add = [&](auto set, int id, const char* field, int col) {
    Case c{Options{}, id, field, col};
    set(c.o);
    cases.push_back(c);
  };
  add([](Options& o) { o.beta = 1; }, 1102, "BETA", 41);
  add([](Options& o) { o.alpha = 2e-5; }, 1102, "ALPHA", 71);
  add([](Options& o) { o.flag1 = 2; }, 1003, "FLAG1", 41);
  add([](Options& o) { o.flag2 = 3; }, 1003, "FLAG2", 51);
  add([](Options& o) { o.za = true, o.za_a = -1e6; }, 1003, "Q1/A", 1);
  add([](Options& o) { o.q1 = 100e6; }, 1102, "Q1/A", 1);
  add([](Options& o) { o.d1 = 0.1; }, 1102, "D1", 21);
  add([](Options& o) { o.flag2 = 1, o.wc = 5e8; }, 1102, "PD/WC", 11);
  for (const Case& c : cases) {
    Model m;
    Diagnostics dg;
    read_text(cube_deck(c.o, 1e-4, 1, 1e-5), m, dg);
    bool found = false;
    for (const Diagnostic& x : dg.all())
      if (x.id == c.id && x.where.field == c.field) {
        found = true;
        EXPECT_EQ(x.where.col_first, c.col) << c.field;
        EXPECT_EQ(x.where.col_last, c.col + 9) << c.field;
        EXPECT_EQ(x.where.file, "mjc.k");
        EXPECT_GT(x.where.line, 0);
        EXPECT_NE(x.where.card.find("material 1"), std::string::npos) << x.where.card;
      }
    EXPECT_TRUE(found) << c.field << "\n" << messages(dg);
  }
}

TEST(ModifiedJohnsonCook, InitialTemperatureOfAnUndefinedNodeOrSetIsAnError) {
  Options o;
  o.node_cards = true;
  std::string deck = cube_deck(o, 1e-4, 1, 1e-5);
  deck.replace(deck.find("*END"), 4, "*INITIAL_TEMPERATURE_NODE\n        99     300.0\n*INITIAL_TEMPERATURE_SET\n        77     300.0\n*END");
  Model m;
  Diagnostics dg;
  EXPECT_FALSE(read_text(deck, m, dg));
  EXPECT_TRUE(dg.has(1202)) << messages(dg);
  EXPECT_FALSE(messages(dg).find("NSID") == std::string::npos) << messages(dg);
}

// The converter: keyword -> fixed format -> keyword keeps the material; the fixed format has no
// card for nodal temperatures (a note), the keyword format writes them back.
TEST(ModifiedJohnsonCook, ConverterRoundTrips) {
  for (bool za : {false, true}) {
  Options o;
  o.za = za;
  Model k;
  Diagnostics dk;
  ASSERT_TRUE(read_text(cube_deck(o, 1e-4, 1, 1e-5), k, dk)) << messages(dk);
  ASSERT_EQ(k.node_temperature.size(), 8u);
  std::ostringstream kw;
  std::vector<std::string> notes;
  write_keyword_deck(kw, k, &notes);
  Model k2;
  Diagnostics dk2;
  ASSERT_TRUE(read_text(kw.str(), k2, dk2)) << messages(dk2) << kw.str();
  std::string diff;
  for (const auto& s : model_differences(k, k2, 50)) diff += s + "\n";
  EXPECT_EQ(diff, "");
  EXPECT_EQ(k2.node_temperature, k.node_temperature);
  std::ostringstream fixed;
  notes.clear();
  write_fixed_deck(fixed, k, &notes);
  bool noted = false;
  for (const auto& n : notes) noted = noted || n.find("temperature") != std::string::npos;
  EXPECT_TRUE(noted);
  Model f;
  Diagnostics df;
  ASSERT_TRUE(read_text(fixed.str(), f, df, "mjc.dyn")) << messages(df) << fixed.str();
  EXPECT_EQ(f.materials[0].type, 107);
  EXPECT_EQ(f.materials[0].par, k.materials[0].par);
  }
}
