// LS-DYNA's spot-weld beam, *SECTION_BEAM ELFORM 9 (issue 24), read from keyword decks as car
// models write it: CST 1, TS1 the weld's diameter, TT1 blank (a solid round bar), card 2's
// PRINT and ITOFF fields.  It runs as the Hughes-Liu beam (ELFORM 1) with that round section,
// so its stiffness comes from E, G and the section of the diameter: A = pi d^2 / 4,
// I = pi d^4 / 64.  Closed forms (damped runs to the static answer):
// - a single weld beam (d = 6 mm, 1 mm long) pulled along its axis: u = P L / (E A);
// - a cantilever of 20 ELFORM 9 beams (d = 6 mm, 60 mm) under a tip load P: the tip deflection
//   P L^3 / 3EI + P L / (k G A) (k = SHRF) and the clamp beam's bending moment P (L - L_e / 2)
//   (its one integration point at its middle).
// The refusals: ELFORM 9 with a material other than *MAT_SPOTWELD (1103) and ITOFF 1 (1102,
// naming ITOFF and its columns 61-70).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 2.1e11, kNu = 0.3, kRho = 7850, kD = 0.006;

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// n ELFORM 9 beams from (0, 0, 0) to (L, 0, 0), node 1 clamped, oriented by node 900 at
// (0, 1, 0); a constant load P along dof (1 x, 3 z) at the far node.  material: "spotweld" or
// "elastic"; itoff: card 2's ITOFF; shrf: SHRF.
std::string weld_bar_deck(int n, double L, double P, int dof, double end_time, const std::string& material = "spotweld",
                          int itoff = 0, double shrf = 0.9) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nELFORM 9 spot-weld beams\n*CONTROL_TERMINATION\n" << fmt("%10.4g\n", end_time);
  d << "*PART\nweld\n         1         1         1\n";
  d << "$#   secid    elform      shrf   qr/irid       cst\n";
  d << "*SECTION_BEAM\n         1         9" << fmt("%10.4g", shrf) << "         2         1\n";
  d << "$#     ts1       ts2       tt1       tt2     print               itoff\n";
  d << fmt("%10.4g%10.4g", kD, kD) << "                          1.0          " << fmt("%10.0f\n", itoff);
  if (material == "spotweld") {
    d << "*MAT_SPOTWELD\n         1" << fmt("%10.4g%10.4g%10.4g", kRho, kE, kNu) << "   5.0e+08       0.0       0.0       0.0\n";
    d << "       0.0       0.0       0.0       0.0       0.0       0.0       0.0\n";
  } else {
    d << "*MAT_ELASTIC\n         1" << fmt("%10.4g%10.4g%10.4g\n", kRho, kE, kNu);
  }
  d << "*NODE\n";
  for (int i = 0; i <= n; ++i) d << fmt("%8.0f%16.8g             0.0             0.0\n", i + 1, L * i / n);
  d << "     900             0.0             1.0             0.0\n";
  d << "*ELEMENT_BEAM\n";
  for (int i = 0; i < n; ++i) d << fmt("%8.0f       1%8.0f%8.0f", i + 1, i + 1, i + 2) << "     900\n";
  d << "*BOUNDARY_SPC_NODE\n         1         0         1         1         1         1         1         1\n";
  d << "*DEFINE_CURVE\n         1\n                 0.0                 1.0\n                 1.0                 1.0\n";
  d << "*LOAD_NODE_POINT\n" << fmt("%10.0f%10.0f         1%10.4g\n", n + 1, dof, P);
  d << "*END\n";
  return d.str();
}

struct Read {
  Model m;
  Diagnostics d;
  bool ok = false;
  std::string messages() const {
    std::ostringstream os;
    d.print(os);
    return os.str();
  }
  int count(int id) const {
    int k = 0;
    for (const auto& x : d.all()) k += x.id == id;
    return k;
  }
  const Diagnostic* first(int id) const {
    for (const auto& x : d.all())
      if (x.id == id) return &x;
    return nullptr;
  }
};

Read read_text(const std::string& text) {
  Read r;
  DeckFile deck;
  deck.load_from_string("weld9.k", text);
  r.ok = read_deck(deck, r.m, r.d, InputOptions{});
  if (r.ok) r.ok = check_model(r.m, r.d);
  return r;
}

// Runs the engine to the model's end time.
void run_to_end(Engine& e) {
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = e.step();
  ASSERT_EQ(st, StepStatus::finished);
}

}  // namespace

// The card as LS-DYNA writes it reaches the Hughes-Liu kernel with a solid round section.
TEST(SpotWeldBeam9, CardReadAsARoundHughesLiuBeam) {
  Read r = read_text(weld_bar_deck(1, 0.001, 1000, 1, 1e-5));
  ASSERT_TRUE(r.ok) << r.messages();
  const BeamSectionData& sec = r.m.materials[0].beam_section;
  EXPECT_EQ(sec.elform, 1);
  EXPECT_TRUE(sec.spot_weld_beam);
  EXPECT_EQ(sec.cst, BeamCrossSection::tubular);
  EXPECT_DOUBLE_EQ(sec.ts1, kD);
  EXPECT_DOUBLE_EQ(sec.ts2, kD);
  EXPECT_DOUBLE_EQ(sec.tt1, 0.0);
  EXPECT_DOUBLE_EQ(sec.shrf, 0.9);
}

// A single weld beam pulled along its axis: u = P L / (E A), A = pi d^2 / 4 (0.2 %: the damped
// run's residual motion), and its axial force N = P.
TEST(SpotWeldBeam9, AxialStiffnessIsEAOverL) {
  const double L = 0.001, P = 1000;
  // mass-proportional damping 0.2 c / L (about 0.2 / dt: the explicit update stays stable; the
  // free end's axial mode, sqrt(2) c / L, loses e^-0.1 a cycle), run for 1000 L / c
  const double c = std::sqrt(kE / kRho);
  Read r = read_text(weld_bar_deck(1, L, P, 1, 1000 * L / c));
  ASSERT_TRUE(r.ok) << r.messages();
  r.m.damping.active = true;
  r.m.damping.d = 0.2 * c / L;
  Engine e(r.m);
  run_to_end(e);
  const State& s = e.state();
  const double A = kPi * kD * kD / 4;
  const double u = s.x[1] - L, want = P * L / (kE * A);
  std::printf("[ measured ] ELFORM 9 weld (d %.3g mm, L %.3g mm): axial u %.6e m, P L / E A %.6e m (%+.4f%%); N %.6g N (P %.6g N)\n",
              kD * 1e3, L * 1e3, u, want, 100 * (u / want - 1), s.beams.res[0], P);
  EXPECT_NEAR(u / want, 1.0, 0.002);
  EXPECT_NEAR(s.beams.res[0] / P, 1.0, 0.002);
}

// A cantilever of 20 weld beams under a tip load: P L^3 / 3EI + P L / (k G A) (0.5 %, as the
// Hughes-Liu cantilever of tests/solve/test_beams.cpp), and the clamp beam's bending moment
// P (L - L_e / 2) (0.5 %).
TEST(SpotWeldBeam9, CantileverTipDeflectionAndMoment) {
  const int n = 20;
  const double L = 0.06, P = 10, shrf = 0.9;
  const double A = kPi * kD * kD / 4, I = kPi * kD * kD * kD * kD / 64, G = kE / (2 * (1 + kNu));
  const double omega1 = 1.875104068711961 * 1.875104068711961 * std::sqrt(kE * I / (kRho * A * L * L * L * L));
  Read r = read_text(weld_bar_deck(n, L, P, 3, 8 * 2 * kPi / omega1, "spotweld", 0, shrf));
  ASSERT_TRUE(r.ok) << r.messages();
  r.m.damping.active = true;
  r.m.damping.d = 1.6 * omega1;
  Engine e(r.m);
  run_to_end(e);
  const State& s = e.state();
  const double bending = P * L * L * L / (3 * kE * I), shear = P * L / (shrf * G * A);
  const double w = s.z[std::size_t(n)];
  // the clamp beam's bending moment (about s or t: the load bends the bar in the x-z plane)
  const double m1 = std::hypot(s.beams.res[3], s.beams.res[4]), m_want = P * (L - L / n / 2);
  std::printf("[ measured ] ELFORM 9 cantilever (20 beams, d %.3g mm, L %.3g mm): tip %.6e m; P L^3/3EI + P L/kGA %.6e m (%+.3f%%); "
              "clamp beam moment %.6g N m, P (L - Le/2) %.6g N m (%+.3f%%)\n",
              kD * 1e3, L * 1e3, w, bending + shear, 100 * (w / (bending + shear) - 1), m1, m_want, 100 * (m1 / m_want - 1));
  EXPECT_NEAR(w / (bending + shear), 1.0, 0.005);
  EXPECT_NEAR(m1 / m_want, 1.0, 0.005);
}

// ELFORM 9 takes *MAT_SPOTWELD only (1103); ITOFF 1 (a torsion-free weld) is refused (1102
// naming ITOFF, columns 61-70).
TEST(SpotWeldBeam9, Refusals) {
  {
    Read r = read_text(weld_bar_deck(1, 0.001, 1000, 1, 1e-5, "elastic"));
    EXPECT_FALSE(r.ok);
    ASSERT_GE(r.count(1103), 1) << r.messages();
    EXPECT_NE(r.messages().find("ELFORM 9"), std::string::npos) << r.messages();
  }
  {
    Read r = read_text(weld_bar_deck(1, 0.001, 1000, 1, 1e-5, "spotweld", 1));
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.count(1102), 1) << r.messages();
    EXPECT_EQ(r.first(1102)->where.field, "ITOFF");
    EXPECT_EQ(r.first(1102)->where.col_first, 61);
    EXPECT_EQ(r.first(1102)->where.col_last, 70);
  }
}
