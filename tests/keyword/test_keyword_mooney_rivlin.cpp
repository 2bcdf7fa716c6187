// *MAT_MOONEY-RIVLIN_RUBBER (type 27) in keyword decks as LS-DYNA users write them, run by the
// engine against closed forms:
//  - one solid pulled slowly in uniaxial stress (symmetry planes, the far face at a prescribed
//    velocity) to stretch 1.9: the nominal stress follows the incompressible closed form
//    2 (A + B / s) (s - 1 / s^2) within 1 % (PR 0.495; LS-DYNA's compressible W, whose exact
//    uniaxial answer the run follows within 0.2 %);
//  - one Belytschko-Tsay shell pulled the same way (the incompressible plane-stress form): within
//    0.5 % of the same closed form;
//  - a rubber block bouncing off a rigid wall: rebound, energy ratio within 1 % after the
//    contact; a free block sheared about its middle rings with its energy within 1.5 %, as an
//    elastic block of the same small-strain moduli;
//  - the option card's curve fit (A = B = 0 with LCID) and REF refused by field (1102), A = B = 0
//    without a curve 1003, each naming card, field and columns.

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

constexpr double kA = 4e5, kB = 1e5, kRho = 1100, kPr = 0.495, kL = 0.01;

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

bool read_text(const std::string& text, Model& m, Diagnostics& d) {
  DeckFile deck;
  deck.load_from_string("rubber.k", text);
  return read_deck(deck, m, d, InputOptions{}) && check_model(m, d);
}

std::string messages(const Diagnostics& d) {
  std::ostringstream os;
  d.print(os);
  return os.str();
}

std::string mat_card(double A = kA, double B = kB, double ref = 0, double lcid = 0) {
  return "*MAT_MOONEY-RIVLIN_RUBBER\n$#     mid        ro        pr         a         b       ref\n" + I(1) + F(kRho) + F(kPr) +
         F(A) + F(B) + F(ref) + "\n$#     sgl        sw        st      lcid\n       0.0       0.0       0.0" + I(long(lcid)) + "\n";
}

// 0 -> v over the first 5 % of the time, then v
std::string ramp_curve(double t_end) {
  return "*DEFINE_CURVE\n         2\n" + F(0.0, 20) + F(0.0, 20) + "\n" + F(0.05 * t_end, 20) + F(1.0, 20) + "\n" +
         F(2 * t_end, 20) + F(1.0, 20) + "\n";
}

// Nominal stress of incompressible Mooney-Rivlin rubber in uniaxial stress at stretch s.
double nominal_incompressible(double s) { return 2 * (kA + kB / s) * (s - 1 / (s * s)); }

// LS-DYNA's compressible W at principal stretches (s, t, t): Cauchy stresses along and across.
void cauchy_compressible(double s, double t, double& sxx, double& syy) {
  const double C = 0.5 * kA + kB, D = (kA * (5 * kPr - 2) + kB * (11 * kPr - 5)) / (2 * (1 - 2 * kPr));
  const double b1 = s * s, b2 = t * t, I1 = b1 + 2 * b2, I3 = b1 * b2 * b2, J = std::sqrt(I3);
  const double W3 = -2 * C / (I3 * I3 * I3) + 2 * D * (I3 - 1);
  sxx = 2 / J * ((kA + kB * I1) * b1 - kB * b1 * b1 + I3 * W3);
  syy = 2 / J * ((kA + kB * I1) * b2 - kB * b2 * b2 + I3 * W3);
}
// Its uniaxial nominal stress (the lateral stretch t solves sigma_yy = 0).
double nominal_compressible(double s) {
  double lo = 0.3, hi = 1.5;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    double sxx, syy;
    cauchy_compressible(s, mid, sxx, syy);
    (syy > 0 ? hi : lo) = mid;
  }
  const double t = 0.5 * (lo + hi);
  double sxx, syy;
  cauchy_compressible(s, t, sxx, syy);
  return sxx * t * t;
}

// One cube (side kL) with symmetry planes x = 0, y = 0, z = 0 and its face x = kL pulled at v.
std::string solid_bar_deck(double t_end, double v) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nrubber cube in uniaxial tension\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*PART\nrubber\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n" << mat_card()
    << ramp_curve(t_end) << "*NODE\n";
  const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int n = 0; n < 8; ++n) d << I(n + 1, 8) << F(kL * c[n][0], 16) << F(kL * c[n][1], 16) << F(kL * c[n][2], 16) << "\n";
  d << "*ELEMENT_SOLID\n" << I(1, 8) << I(1, 8);
  for (int n = 1; n <= 8; ++n) d << I(n, 8);
  d << "\n*BOUNDARY_SPC_NODE\n";
  for (int n = 0; n < 8; ++n)
    d << I(n + 1) << I(0) << I(c[n][0] == 0) << I(c[n][1] == 0) << I(c[n][2] == 0) << "\n";
  d << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int n = 0; n < 8; ++n)
    if (c[n][0] == 1) d << I(n + 1) << I(1) << I(0) << I(2) << F(v) << "\n";
  d << "*END\n";
  return d.str();
}

// One shell (side kL, 1 mm) in z = 0, edge x = 0 held in x (node 1 also in y), edge x = kL pulled
// at v; z and the rotations held (membrane only).
std::string shell_deck(double t_end, double v) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nrubber shell in uniaxial tension\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*PART\nrubber sheet\n" << I(1) << I(1) << I(1) << "\n*SECTION_SHELL\n" << I(1) << I(2) << F(0.833333) << I(2)
    << "\n" << F(0.001) << F(0.001) << F(0.001) << F(0.001) << "\n" << mat_card() << ramp_curve(t_end) << "*NODE\n";
  const double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int n = 0; n < 4; ++n) d << I(n + 1, 8) << F(kL * c[n][0], 16) << F(kL * c[n][1], 16) << F(0.0, 16) << "\n";
  d << "*ELEMENT_SHELL\n" << I(1, 8) << I(1, 8) << I(1, 8) << I(2, 8) << I(3, 8) << I(4, 8) << "\n*BOUNDARY_SPC_NODE\n";
  for (int n = 0; n < 4; ++n) d << I(n + 1) << I(0) << I(c[n][0] == 0) << I(n == 0) << I(1) << I(1) << I(1) << I(1) << "\n";
  d << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int n = 0; n < 4; ++n)
    if (c[n][0] == 1) d << I(n + 1) << I(1) << I(0) << I(2) << F(v) << "\n";
  d << "*END\n";
  return d.str();
}

}  // namespace

// The stretch reaches 1.9 in 0.1 s (the cube's shear wave crosses it in 0.3 ms: quasi-static).
// Nominal stress = sigma_xx (current cross-section) / kL^2 from the nodes.  Measured worst over
// the path (s 1.1 .. 1.9): see the recorded properties.
TEST(MooneyRivlin, SolidCubeInUniaxialTensionFollowsTheClosedForm) {
  Model m;
  Diagnostics dg;
  const double t_end = 0.1, v = 0.9 * kL / (0.975 * t_end);
  ASSERT_TRUE(read_text(solid_bar_deck(t_end, v), m, dg)) << messages(dg);
  ASSERT_EQ(m.materials[0].type, 27);
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  double worst_inc = 0, worst_cmp = 0, worst_lateral = 0, last_s = 1;
  int checks = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok && !e.finished()) {
    st = e.step();
    const double sx = s.x[1] / kL;  // node 2
    if (sx < 1.1 || sx < last_s + 0.05) continue;
    last_s = sx;
    ++checks;
    const double area = s.y[2] * s.z[4];  // node 3's y, node 5's z
    const double nominal = s.sig[0] * area / (kL * kL);
    worst_inc = std::max(worst_inc, std::fabs(nominal / nominal_incompressible(sx) - 1));
    worst_cmp = std::max(worst_cmp, std::fabs(nominal / nominal_compressible(sx) - 1));
    worst_lateral = std::max(worst_lateral, std::fabs(s.sig[1]) / std::fabs(s.sig[0]));
  }
  ASSERT_NE(st, StepStatus::negative_volume);
  EXPECT_GT(last_s, 1.8);
  EXPECT_GE(checks, 15);
  EXPECT_LT(worst_inc, 0.01);
  EXPECT_LT(worst_cmp, 0.002);
  EXPECT_LT(worst_lateral, 0.002);
  RecordProperty("worst_vs_incompressible", std::to_string(worst_inc));
  RecordProperty("worst_vs_compressible", std::to_string(worst_cmp));
  std::printf("solid: worst |nominal/closed - 1| incompressible %.3e, compressible %.3e, |syy/sxx| %.3e, last stretch %.3f\n",
              worst_inc, worst_cmp, worst_lateral, last_s);
}

// The shell's stress is the Cauchy stress times the thickness stretch (force per initial
// thickness): nominal = sigma_xx (current width) / kL.
TEST(MooneyRivlin, ShellInUniaxialTensionFollowsTheIncompressibleClosedForm) {
  Model m;
  Diagnostics dg;
  const double t_end = 0.1, v = 0.9 * kL / (0.975 * t_end);
  ASSERT_TRUE(read_text(shell_deck(t_end, v), m, dg)) << messages(dg);
  ASSERT_EQ(m.materials[0].type, 27);
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  double worst = 0, last_s = 1;
  int checks = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok && !e.finished()) {
    st = e.step();
    const double sx = s.x[1] / kL;
    if (sx < 1.1 || sx < last_s + 0.05) continue;
    last_s = sx;
    ++checks;
    const double width = s.y[2] - s.y[1];  // nodes 3 and 2
    for (int p = 0; p < 2; ++p) {
      const double nominal = s.shells.sig[shell_sig_at(s.shells, 0, p, 0)] * width / kL;
      worst = std::max(worst, std::fabs(nominal / nominal_incompressible(sx) - 1));
    }
  }
  EXPECT_GT(last_s, 1.8);
  EXPECT_GE(checks, 15);
  EXPECT_LT(worst, 0.005);
  RecordProperty("worst_vs_incompressible", std::to_string(worst));
  std::printf("shell: worst |nominal/closed - 1| %.3e, last stretch %.3f\n", worst, last_s);
}

// A 20 mm rubber cube of 4 x 4 x 4 solids (stiffness hourglass control IHQ 4) at x from 1 mm,
// with velocity v(x) (all nodes, or `breathing`: no wall, the x velocity -a (x - xc) of a free
// block squeezed about its middle).
std::string block_deck(double t_end, bool breathing, double v0, bool elastic = false) {
  const int n = 4;
  const double side = 0.02, h = side / n;
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nrubber block\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*CONTROL_TIMESTEP\n" << F(0.0) << F(0.6) << "\n"
    << "*PART\nrubber\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n" << (elastic ? "*MAT_ELASTIC\n" + I(1) + F(kRho) + F(4 * (kA + kB) * (1 + kPr)) + F(kPr) + "\n" : mat_card())
    << "*CONTROL_HOURGLASS\n" << I(4) << F(0.05) << "\n";
  if (!breathing)
    d << "*RIGIDWALL_PLANAR\n" << I(0) << "\n" << F(0.0) << F(0.0) << F(0.0) << F(1.0) << F(0.0) << F(0.0) << "\n"
      << "*INITIAL_VELOCITY\n" << I(0) << "\n" << F(-v0) << F(0.0) << F(0.0) << "\n";
  auto id = [&](int i, int j, int k) { return 1 + i + (n + 1) * (j + (n + 1) * k); };
  d << "*NODE\n";
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) d << I(id(i, j, k), 8) << F(0.001 + h * i, 16) << F(h * j, 16) << F(h * k, 16) << "\n";
  if (breathing) {
    d << "*INITIAL_VELOCITY_NODE\n";
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) d << I(id(i, j, k)) << F(0.0) << F(-v0 * (2.0 * i / n - 1)) << F(0.0) << "\n";
  }
  d << "*ELEMENT_SOLID\n";
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        d << I(1 + i + n * (j + n * k), 8) << I(1, 8) << I(id(i, j, k), 8) << I(id(i + 1, j, k), 8) << I(id(i + 1, j + 1, k), 8)
          << I(id(i, j + 1, k), 8) << I(id(i, j, k + 1), 8) << I(id(i + 1, j, k + 1), 8) << I(id(i + 1, j + 1, k + 1), 8)
          << I(id(i, j + 1, k + 1), 8) << "\n";
  d << "*END\n";
  return d.str();
}

// The block at 5 m/s onto a rigid wall (*RIGIDWALL_PLANAR): it leaves the wall at more than 0.65
// of its speed (0.69), and once it has (t >= 1.2 ms; the contact ends near 0.8 ms) the energy
// ratio (kinetic + internal + hourglass + bulk viscosity + the wall's work, over the initial) is
// within 1 % (0.41 %; the wall takes the impacting face's normal kinetic energy, 0.21 of the
// initial, bulk viscosity 0.07).  While the face is on the wall the ratio swings by up to 5 %
// (10 % at TSSF 0.9): the stonewall's booking, the same to 0.3 % for an elastic (type 1) block of
// the same small-strain moduli.  The decks use TSSF 0.6: at LS-DYNA's 0.9 these nearly
// incompressible blocks (PR 0.495) diverge, the elastic one too (the step V/A_max / c of a
// one-point hexahedron is not stable for its volumetric mode, whose frequency is up to sqrt(3)
// higher); and with the viscous hourglass control (IHQ 1) the bounce diverges after the rebound,
// the elastic block too (issue 25's defect 4).  Neither is the material's.
TEST(MooneyRivlin, BlockBouncesOffARigidWall) {
  const double v0 = 5;
  Model m;
  Diagnostics dg;
  ASSERT_TRUE(read_text(block_deck(3e-3, false, v0), m, dg)) << messages(dg);
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  const double ke0 = s.kinetic;
  double worst_after = 0, worst = 0, most_internal = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok && !e.finished()) {
    st = e.step();
    worst = std::max(worst, std::fabs(s.energy_ratio() - 1));
    if (s.time >= 1.2e-3) worst_after = std::max(worst_after, std::fabs(s.energy_ratio() - 1));
    most_internal = std::max(most_internal, s.internal);
  }
  ASSERT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << "t " << s.time << " element " << e.error_element();
  double px = 0, mass = 0;
  for (int i = 0; i < s.nn; ++i) px += s.mass[std::size_t(i)] * s.vx[std::size_t(i)], mass += s.mass[std::size_t(i)];
  EXPECT_GT(most_internal, 0.5 * ke0);  // it did squeeze
  EXPECT_LT(worst_after, 0.01);
  EXPECT_LT(worst, 0.12);
  EXPECT_GT(px / mass, 0.65 * v0);
  std::printf("bounce: |E/E0 - 1| after the contact %.3e (during %.3e), peak internal/KE0 %.3f, rebound %.4f of v0, at the end "
              "KE %.4f IE %.4f HG %.4f BV %.4f wall %.4f of KE0\n", worst_after, worst, most_internal / ke0, px / mass / v0,
              s.kinetic / ke0, s.internal / ke0, s.hourglass / ke0, s.bulk_viscous / ke0, s.wall_work / ke0);
  RecordProperty("energy_after_contact", std::to_string(worst_after));
}

// The free block sheared (y velocity -v0 (x - xc)/(side/2), v0 8 m/s: shear strains near 0.3)
// rings for 3 ms: the energy ratio stays within 1.5 % (1.43 %), no worse than that of an elastic
// (type 1) block of the same small-strain moduli run alike (1.49 %: the explicit integration's own
// error, first order in the step: 1.18 % at TSSF 0.5, 0.58 % at 0.25 for both at 2 m/s), while
// 0.45 of the energy goes through the rubber and back.
TEST(MooneyRivlin, FreeBlockRingsConservingEnergyAsAnElasticOne) {
  double worst[2] = {0, 0}, most_internal[2] = {0, 0};
  for (int elastic = 0; elastic < 2; ++elastic) {
    Model m;
    Diagnostics dg;
    ASSERT_TRUE(read_text(block_deck(3e-3, true, 8.0, elastic), m, dg)) << messages(dg);
    Engine e(m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    const double ke0 = s.kinetic;
    StepStatus st = StepStatus::ok;
    while (st == StepStatus::ok && !e.finished()) {
      st = e.step();
      worst[elastic] = std::max(worst[elastic], std::fabs(s.energy_ratio() - 1));
      most_internal[elastic] = std::max(most_internal[elastic], s.internal / ke0);
    }
    ASSERT_TRUE(st == StepStatus::ok || st == StepStatus::finished);
  }
  EXPECT_GT(most_internal[0], 0.4);
  EXPECT_LT(worst[0], 0.015);
  EXPECT_LT(worst[0], 1.1 * worst[1]);
  std::printf("ringing: |E/E0 - 1| Mooney-Rivlin %.3e, elastic %.3e; peak internal/KE0 %.3f and %.3f\n", worst[0], worst[1],
              most_internal[0], most_internal[1]);
  RecordProperty("energy", std::to_string(worst[0]));
}

TEST(MooneyRivlin, CurveFitAndReferenceGeometryAreRefusedByField) {
  auto one = [](double A, double B, double ref, double lcid, int id, const std::string& field, int col) {
    Model m;
    Diagnostics dg;
    read_text(solid_bar_deck(0.1, 0.1).replace(solid_bar_deck(0.1, 0.1).find("*MAT"), mat_card().size(),
                                                mat_card(A, B, ref, lcid)),
              m, dg);
    ASSERT_TRUE(dg.has(id)) << messages(dg);
    bool found = false;
    for (const Diagnostic& x : dg.all())
      if (x.id == id) {
        found = true;
        EXPECT_EQ(x.where.field, field) << messages(dg);
        EXPECT_EQ(x.where.col_first, col) << messages(dg);
        EXPECT_EQ(x.where.col_last, col + 9) << messages(dg);
        EXPECT_EQ(x.where.file, "rubber.k");
        EXPECT_GT(x.where.line, 0);
        EXPECT_NE(x.where.card.find("material 1"), std::string::npos) << x.where.card;
      }
    EXPECT_TRUE(found);
  };
  one(0, 0, 0, 7, 1102, "LCID", 31);
  one(0, 0, 0, 0, 1003, "A", 31);
  one(kA, kB, 1, 0, 1102, "REF", 51);
}

// The converter: the solid cube and the shell decks to the fixed format and back to keywords,
// the same Model each time (PR, A, B and card 2 travel as the type's parameters).
TEST(MooneyRivlin, ConverterRoundTripsBothFormats) {
  for (bool shell : {false, true}) {
    Model k;
    Diagnostics dk;
    ASSERT_TRUE(read_text(shell ? shell_deck(0.1, 0.1) : solid_bar_deck(0.1, 0.1), k, dk)) << messages(dk);
    std::ostringstream fixed;
    std::vector<std::string> notes;
    write_fixed_deck(fixed, k, &notes);
    Model f;
    Diagnostics df;
    DeckFile deck;
    deck.load_from_string("rubber.dyn", fixed.str());
    ASSERT_TRUE(read_deck(deck, f, df, InputOptions{}) && check_model(f, df)) << messages(df) << fixed.str();
    std::string diff;
    for (const auto& s : model_differences(k, f, 50)) diff += s + "\n";
    EXPECT_EQ(diff, "") << "shell " << shell;
    EXPECT_EQ(f.materials[0].type, 27);
    EXPECT_EQ(f.materials[0].shell, shell);
    std::ostringstream kw;
    write_keyword_deck(kw, f, &notes);
    Model k2;
    Diagnostics dk2;
    ASSERT_TRUE(read_text(kw.str(), k2, dk2)) << messages(dk2) << kw.str();
    diff.clear();
    for (const auto& s : model_differences(f, k2, 50)) diff += s + "\n";
    EXPECT_EQ(diff, "") << "shell " << shell;
  }
}
