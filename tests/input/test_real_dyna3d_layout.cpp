// The DYNA3D fixed format as LLNL's own tools write it (issue 23): decks of our own in both
// vintages (DYNA3D 88 as INGRID writes it, the later layout as TrueGrid 2.2 writes it) with
// every kind of card these decks hold: comment banners, a commented-out option line, free-format
// blocks, rgb lines, material type 71, section-property cards, integral-real node codes, five
// time-history blocks a card, nodal velocity cards with a gap, one-card pressure loads, mass
// damping, TrueGrid's prescribed-motion card, interface options.  Read, run (closed forms),
// converted both ways; malformed cards of the new layouts refused with their columns; the
// README's card tables equal the generated ones.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "impact3d/input/fixed_cards.h"
#include "impact3d/input/keyword_reader.h"
#include "impact3d/solve/engine.h"
#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

std::string pad(std::string s, std::size_t n) {
  s.resize(std::max(s.size(), n), ' ');
  return s;
}
std::string title(const std::string& t) { return pad(t, 72) + "88 large\n"; }
std::string ints(std::initializer_list<long long> v, int w = 5) {
  std::string s;
  for (long long x : v) s += I(x, w);
  return s;
}
std::string reals(std::initializer_list<double> v) {
  std::string s;
  for (double x : v) s += E(x, 10, 3);
  return s;
}
// material card 1: number, type, density, element type (cols 66-70)
std::string mat_card1(int number, int type, double rho, int et, int ef = 0) {
  std::string s = I(number, 5) + I(type, 5) + E(rho, 10, 4) + I(0, 5) + I(0, 5) + E(0, 10, 4) + I(0, 5) +
                  E(0, 10, 4) + E(0, 10, 4) + I(et, 5) + I(0, 5) + I(ef, 5);
  return s + "\n";
}
// a node card as INGRID writes it: codes as integral reals ("7.")
std::string node88(int id, int code, double x, double y, double z) {
  return I(id, 8) + pad("   " + std::to_string(code) + ".", 5) + E(x, 20, 13) + E(y, 20, 13) + E(z, 20, 13) + "   0.\n";
}
const double kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

// A DYNA3D 88 deck (INGRID's layout): one steel cube (mm) flying at 10 m/s along x; material
// type 71; nodal velocity cards for nodes 1 and 8 only (2-7 interpolated).
std::string deck88(const std::string& card4 = "    0    0    0    0    0    0e20.9") {
  std::string s = title("cube in flight, DYNA3D 88 layout (mm kg ms... SI here)");
  s += "*\n*----------------- ANALYSIS INPUT DATA FOR DYNA3D 88 ------------------*\n";
  s += "*basename commented_out\n";
  s += "*-------------------------- CONTROL CARD #2 ---------------------------*\n";
  s += I(1, 5) + I(8, 10) + I(1, 10) + I(0, 10) + I(0, 10) + I(0, 10) + "\n";
  s += ints({6, 1, 0, 0, 0, 0}) + "\n";  // six node blocks (two cards), one solid block
  s += card4 + "\n";
  s += ints({0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  // (TSSF 0.5: a body one element thick needs TSSF <= 0.67, README "Known limitations")
  s += reals({2e-4, 1e-5, 5e-5}) + ints({0, 0}) + reals({0, 0}) + ints({0, 0}) + reals({0.5}) + "\n";
  s += ints({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += ints({0, 0}) + reals({0}) + ints({0, 0, 0, 0, 250}) + reals({1e-4, 0.995, 0}) + ints({0}) + "\n";
  s += ints({1, 0, 0}) + "\n";
  s += "*\n* free format input\n*\n";
  s += "basename cube88\n";
  s += "exact_output_time  print_time_history_data   endfree\n";
  s += "options\n";
  s += "element_set 1  rgb .69 .35 .93 name es_1\n";
  s += "endfree\n";
  s += "*--------------------------- MATERIAL CARDS ---------------------------*\n";
  s += mat_card1(1, 71, 7.83e3, 0);
  s += "rgb .2 .4 .6\n";
  s += "material type # 71\n";
  s += reals({2e11, 0.3, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({4e8, 1e9, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({1, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({1, 0, 0, 0, 100, 0, 1e-4, 0}) + "\n";
  s += "*-------------------------- NODE DEFINITIONS --------------------------*\n";
  for (int k = 0; k < 8; ++k) s += node88(k + 1, 0, kCube[k][0] * 1e-3, kCube[k][1] * 1e-3, kCube[k][2] * 1e-3);
  s += "*------------------ ELEMENT CARDS FOR SOLID ELEMENTS ------------------*\n";
  s += I(1, 8) + I(1, 5) + ints({1, 2, 3, 4, 5, 6, 7, 8}, 8) + "\n";
  s += "* Nodal Blocks\n*234567812345678\n";
  s += ints({1, 1, 2, 2, 3, 3, 4, 4, 5, 5}, 8) + "\n" + ints({6, 8}, 8) + "\n";
  s += "* Element Blocks\n" + ints({1, 1}, 8) + "\n";
  s += "*-------------------------- INITIAL CONDITIONS ---------------------------*\n";
  s += I(1, 8) + reals({10, 0, 0}) + "\n";
  s += I(8, 8) + reals({10, 0, 0}) + "\n";
  return s;
}

// A deck in the later layout (TrueGrid 2.2): one free Belytschko-Tsay shell (10 mm square, 1 mm
// thick steel, "BLT Shell Section Properties"), a pressure card with multipliers, mass damping
// by control card 7 field 11 (xi = 0.5, omega = 1000 / s: D = 1000 / s), all nodes at 2 m/s
// along z (IMPACT-3D's node-0 card).
std::string deck_later(double end = 1e-3, const std::string& damping = reals({0.5, 1000, 0, 0})) {
  std::string s = title("free shell with mass damping, later DYNA3D layout (SI)");
  s += "*------------------- ANALYSIS INPUT DATA FOR DYNA3D -------------------*\n";
  s += I(1, 5) + I(4, 10) + I(0, 10) + I(0, 10) + I(1, 10) + I(0, 10) + I(0, 10) + reals({0}) + "  0.0\n";
  s += ints({1, 0, 0, 0, 0, 0, 0, 0, 1}) + "\n";
  s += I(0, 10) + ints({0, 0, 0, 0}) + "e20.0" + I(0, 5) + reals({0}) + "\n";
  s += ints({1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({end, end / 100, end / 10}) + ints({0, 0}) + reals({0, 0}) + ints({0, 0}) + reals({0}) + "\n";
  s += ints({0, 0, 0, 0, 0, 0, 0, 0, 0}) + "     " + I(1, 5) + ints({0, 0, 0, 0}) + "\n";  // field 11: one damping set
  s += ints({0, 0}) + reals({0}) + ints({0, 0, 0, 0, 250}) + reals({1e-3, 0.995, 0}) + ints({0}) + "\n";
  s += ints({0, 0, 0, 0}) + reals({0}) + ints({0, 0, 0}) + "\n";
  s += "basename shell_later\nmdamp 1\nprint_time_history_data   endfree\n";
  s += mat_card1(1, 3, 7.8e3, 2, 2);
  s += "material type # 3 (Kinematic/Isotropic elastic-plastic)\n";
  for (double v : {2e11, 0.3, 4e8, 0.0, 1.0}) s += reals({v, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += " BLT Shell Section Properties\n";
  s += reals({0.8333, 3, 0, 0}) + "\n";
  s += reals({1e-3, 1e-3, 1e-3, 1e-3, 0}) + "\n";
  const double q[4][2] = {{0, 0}, {10e-3, 0}, {10e-3, 10e-3}, {0, 10e-3}};
  for (int k = 0; k < 4; ++k) s += I(k + 1, 8) + I(0, 5) + E(q[k][0], 20, 13) + E(q[k][1], 20, 13) + E(0, 20, 13) + I(0, 5) + "\n";
  s += I(1, 8) + I(1, 5) + ints({1, 2, 3, 4}, 8) + "\n";
  s += reals({0, 0, 0, 0}) + "\n";
  s += "* Node Print Blocks\n" + ints({1, 4}, 8) + "\n";
  s += ints({1, 2, 0}) + "\n" + reals({0, 0}) + "\n" + reals({1, 0}) + "\n";
  s += I(1, 5) + ints({1, 2, 3, 4}, 8) + reals({0.5, 0.5, 0.5, 0.5}) + "\n";
  s += I(0, 8) + reals({0, 0, 2}) + "\n";
  s += "* Mass Damping\n" + damping + "\n";
  return s;
}

State run_to_end(const Model& m) {
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = e.step();
  EXPECT_EQ(st, StepStatus::finished);
  return e.state();
}

}  // namespace

TEST(RealDyna3dLayout, Dyna3d88DeckReadsEveryCardKind) {
  if (const char* dump = std::getenv("DUMP_TEST_DECKS")) {
    std::ofstream(std::string(dump) + "/d88.dyn") << deck88();
    std::ofstream(std::string(dump) + "/dlater.dyn") << deck_later();
  }
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(deck88(), m, d)) << all_messages(d);
  EXPECT_EQ(m.fixed_vintage, int(FixedVintage::dyna3d_88));
  EXPECT_EQ(m.basename, "cube88");
  EXPECT_TRUE(m.exact_output_times);
  // type 71: type 3 with E, nu / sigma_y, E_tan / beta packed by pairs
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].type, 3);
  EXPECT_DOUBLE_EQ(m.materials[0].E, 2e11);
  EXPECT_DOUBLE_EQ(m.materials[0].nu, 0.3);
  EXPECT_DOUBLE_EQ(m.materials[0].sigma_y, 4e8);
  EXPECT_DOUBLE_EQ(m.materials[0].E_tan, 1e9);
  EXPECT_DOUBLE_EQ(m.materials[0].beta, 1.0);
  EXPECT_EQ(d.count(2006), 3) << all_messages(d);  // card 8's three nonzero fields
  // six node blocks on two cards, one solid block
  ASSERT_EQ(m.node_th_blocks.size(), 6u);
  EXPECT_EQ(m.node_th_blocks[5][0], 6);
  EXPECT_EQ(m.node_th_blocks[5][1], 8);
  EXPECT_EQ(m.solid_th_blocks.size(), 1u);
  // the options without effect: one warning listing them with their lines
  ASSERT_EQ(d.count(2040), 1);
  const std::string msg = all_messages(d);
  EXPECT_NE(msg.find("print_time_history_data"), std::string::npos) << msg;
  EXPECT_NE(msg.find("element_set 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("rgb .2 .4 .6"), std::string::npos) << msg;
}

TEST(RealDyna3dLayout, CommentedOptionDoesNotMakeAKeywordDeck) {
  DeckFile deck;
  deck.load_from_string("t.dyn", deck88());
  EXPECT_FALSE(is_keyword_deck(deck));
  // without the format flag on the title, a lower-case "*basename" still is a comment
  std::string small = deck88();
  small.replace(72, 8, "        ");
  DeckFile d2;
  d2.load_from_string("s.dyn", small);
  EXPECT_FALSE(is_keyword_deck(d2));
  DeckFile k;
  k.load_from_string("k.k", "$ comment\n*KEYWORD\n*NODE\n");
  EXPECT_TRUE(is_keyword_deck(k));
}

// Nodes 2-7 have no card: their velocity is interpolated between nodes 1 and 8 (both 10 m/s),
// so the cube translates rigidly: every node moves 10 m/s x t, no strain.
TEST(RealDyna3dLayout, Dyna3d88CubeTranslatesRigidlyFromInterpolatedVelocities) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(deck88(), m, d)) << all_messages(d);
  ASSERT_TRUE(check_model(m, d)) << all_messages(d);
  const State s = run_to_end(m);
  EXPECT_NEAR(s.time, 2e-4, 1e-15);
  for (int n = 0; n < 8; ++n) {
    EXPECT_NEAR(s.x[std::size_t(n)] - m.x[std::size_t(n)], 10 * 2e-4, 1e-12) << n;
    EXPECT_NEAR(s.y[std::size_t(n)] - m.y[std::size_t(n)], 0, 1e-15) << n;
  }
  EXPECT_NEAR(s.internal, 0, 1e-12 * s.kinetic);
}

TEST(RealDyna3dLayout, LaterDeckReadsSectionsPressureAndDamping) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(deck_later(), m, d)) << all_messages(d);
  EXPECT_EQ(m.fixed_vintage, int(FixedVintage::dyna3d_later));
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_TRUE(m.materials[0].shell);
  EXPECT_EQ(m.materials[0].shell_section.nip, 3);
  EXPECT_DOUBLE_EQ(m.materials[0].shell_section.shrf, 0.8333);
  ASSERT_EQ(m.shell_thickness.size(), 1u);
  EXPECT_DOUBLE_EQ(m.shell_thickness[0][2], 1e-3);  // the element card's are blank: the section's
  ASSERT_EQ(m.pressure_loads.size(), 1u);
  EXPECT_DOUBLE_EQ(m.pressure_loads[0].factor[3], 0.5);
  EXPECT_TRUE(m.damping.active);
  EXPECT_DOUBLE_EQ(m.damping.d, 2 * 0.5 * 1000);
  EXPECT_EQ(m.node_th_blocks.size(), 1u);
}

// Mass damping D = 2 xi omega on a free body: v(t) = v0 exp(-D t) (closed form), here at
// t = 1 ms with D = 1000 / s: v = 2 e^-1 m/s, within 0.5 % (the central-difference step).
TEST(RealDyna3dLayout, MassDampingCardDecaysAFreeShellsVelocityExponentially) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(deck_later(), m, d)) << all_messages(d);
  ASSERT_TRUE(check_model(m, d)) << all_messages(d);
  const State s = run_to_end(m);
  for (int n = 0; n < 4; ++n) EXPECT_NEAR(s.vz[std::size_t(n)], 2 * std::exp(-1.0), 0.005 * 2 * std::exp(-1.0)) << n;
}

TEST(RealDyna3dLayout, TrueGridMotionCardReadsAndTheOldLayoutIsRefusedWithTheColumns) {
  // later deck + one velocity boundary card: node 2, curve 1, DOF 4 along (0, 3, 4), scale 2
  std::string s = deck_later();
  const std::string c5 = ints({1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  s.replace(s.find(c5), c5.size(), ints({1, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  const std::string iv = I(0, 8) + reals({0, 0, 2}) + "\n";
  const std::string motion = I(2, 8) + I(1, 5) + I(4, 5) + reals({2, 0, 3, 4}) + I(0, 5) + "\n";
  std::string ok = s;
  ok.replace(ok.find(iv), 0, motion);
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(ok, m, d)) << all_messages(d);
  ASSERT_EQ(m.prescribed_motions.size(), 1u);
  EXPECT_EQ(m.prescribed_motions[0].node, 1);
  EXPECT_DOUBLE_EQ(m.prescribed_motions[0].scale, 2);
  EXPECT_DOUBLE_EQ(m.prescribed_motions[0].dir[1], 0.6);
  EXPECT_DOUBLE_EQ(m.prescribed_motions[0].dir[2], 0.8);
  // IMPACT-3D's old layout: node, direction, curve, scale, type, birth, death
  std::string old = s;
  old.replace(old.find(iv), 0, I(2, 8) + I(3, 5) + I(1, 5) + reals({2}) + I(0, 5) + reals({0, 0}) + "\n");
  Model mo;
  Diagnostics dold;
  EXPECT_FALSE(read_string(old, mo, dold));
  ASSERT_EQ(dold.count(1006), 1) << all_messages(dold);
  EXPECT_NE(all_messages(dold).find("swap columns 9-13 and 14-18"), std::string::npos) << all_messages(dold);
}

// Each malformed card of the new layouts: the message, the card and its columns.
TEST(RealDyna3dLayout, MalformedCardsOfTheRealLayoutsNameTheirColumns) {
  struct Case {
    std::string deck;
    int id;
    const char* where;
  };
  auto edit = [](std::string s, const std::string& from, const std::string& to) {
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
  };
  const std::string d88 = deck88(), dl = deck_later();
  const std::vector<Case> cases = {
      // control card 4 (88): the DYNA3D-JOY interface
      {deck88("    5    0    0    0    0    0e20.9"), 1102, "control card 4, field \"DYNA3D-JOY interface nodes\" (cols 1-5)"},
      // a time-history block whose last is below its first
      {edit(d88, ints({1, 1, 2, 2, 3, 3, 4, 4, 5, 5}, 8), ints({1, 1, 2, 2, 3, 3, 4, 4, 5, 2}, 8)), 1003, "field \"last 5\" (cols 73-80)"},
      // a pressure card's node out of range
      {edit(dl, I(1, 5) + ints({1, 2, 3, 4}, 8) + reals({0.5}), I(1, 5) + ints({1, 9, 3, 4}, 8) + reals({0.5})), 1202,
       "pressure card 1, field \"node n2\" (cols 14-21)"},
      // a mass damping card that ends before the end time
      {deck_later(1e-3, reals({0.5, 1000, 0, 1e-4})), 1102, "mass damping card 1, field \"end time\" (cols 31-40)"},
      // a free-format mdamp without a count
      {edit(dl, "mdamp 1", "mdamp x"), 1001, "free format mdamp"},
      // a shell section with a user integration rule
      {edit(dl, reals({0.8333, 3, 0, 0}), reals({0.8333, 3, -1, 0})), 1102, "field \"quadrature rule QR\" (cols 21-30)"},
      // NIP far beyond an int (a fuzz finding: it was converted before it was checked)
      {edit(dl, reals({0.8333, 3, 0, 0}), reals({0.8333, 5.8193e9, 0, 0})), 1003, "field \"NIP\" (cols 11-20)"},
      // a real-valued node code that is not integral
      {edit(d88, node88(3, 0, 1e-3, 1e-3, 0).substr(8, 5), "  7.5"), 1001, "field \"boundary code\" (cols 9-13)"},
  };
  for (const Case& c : cases) {
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_string(c.deck, m, d));
    EXPECT_GE(d.count(c.id), 1) << c.where << "\n" << all_messages(d);
    EXPECT_NE(all_messages(d).find(c.where), std::string::npos) << all_messages(d);
  }
}

// fixed (88 or later) -> keyword -> fixed: the same model each way.
TEST(RealDyna3dLayout, ConverterRoundTripsBothVintages) {
  for (const std::string& text : {deck88(), deck_later()}) {
    Model a;
    Diagnostics d;
    ASSERT_TRUE(read_string(text, a, d)) << all_messages(d);
    std::ostringstream kw;
    write_keyword_deck(kw, a);
    Model b;
    Diagnostics db;
    ASSERT_TRUE(read_any(kw.str(), b, db, "b.k")) << all_messages(db) << kw.str();
    std::ostringstream fx;
    write_fixed_deck(fx, b);
    Model c;
    Diagnostics dc;
    ASSERT_TRUE(read_string(fx.str(), c, dc)) << all_messages(dc) << fx.str();
    EXPECT_EQ(dc.count(2041), 0) << "the converter writes the real layout\n" << all_messages(dc);
    const auto diff = model_differences(a, c, 20);
    EXPECT_TRUE(diff.empty()) << diff.front();
  }
}

// docs/card-tables.md is the generated text (impact3d --card-tables): the manual cannot drift
// from the reader.
TEST(FixedCards, ReadmeTablesAreTheGeneratedOnes) {
  const std::string readme = read_text(source_path("docs/card-tables.md"));
  const std::string begin = "<!-- BEGIN card tables (impact3d --card-tables) -->\n", end = "<!-- END card tables -->";
  const std::size_t a = readme.find(begin), b = readme.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(readme.substr(a + begin.size(), b - a - begin.size()), fixed_card_tables_markdown())
      << "regenerate: impact3d --card-tables, between the markers in docs/card-tables.md";
}

// Every layout's fields lie within 80 columns, in order, without overlap.
TEST(FixedCards, EveryLayoutIsOrderedAndWithinEightyColumns) {
  for (const FixedCardLayout& l : all_fixed_card_layouts()) {
    int last = 0;
    for (const FixedField& f : l.fields) {
      EXPECT_GT(f.c1, last) << l.id << " " << f.name;
      EXPECT_LE(f.c1, f.c2) << l.id << " " << f.name;
      EXPECT_LE(f.c2, 80) << l.id << " " << f.name;
      last = f.c2;
    }
  }
}

namespace {

// A steel cantilever (1 m, ten Hughes-Liu beams, 50 x 50 mm, clamped at node 1) in the later
// layout: a beam material (element type 1) with its "Hughes-Liu Beam Section Properties" cards
// (QR `qr`, CST `cst`), optionally user rule 1 (2 x 2 Gauss written as a user rule, weights 1),
// a tip load P = 100 N along z (nodal load card), critical mass damping of the first mode.
std::string cantilever(int qr = 2, int cst = 0, bool user_rule = false) {
  const int nb = 10;
  std::string s = title("steel cantilever, Hughes-Liu beams, later DYNA3D layout (SI)");
  s += I(1, 5) + I(nb + 1, 10) + I(0, 10) + I(nb, 10) + I(0, 10) + I(0, 10) + I(0, 10) + reals({0}) + "  0.0\n";
  s += ints({0, 0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += I(0, 10) + ints({0, 0, 0, 0}) + "e20.0" + I(0, 5) + reals({0}) + "\n";
  s += ints({1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}) + "\n";
  s += reals({0.06, 0.006, 0.006}) + ints({0, 0}) + reals({0, 0}) + ints({0, 0}) + reals({0}) + "\n";
  s += ints({0, 0, 0, 0, 0, 0, 0, 0, 0}) + "     " + I(1, 5) + ints({0, 0, 0, 0}) + "\n";
  s += ints({0, 0}) + reals({0}) + ints({user_rule ? 1 : 0, user_rule ? 4 : 0, 0, 0, 250}) + reals({1e-3, 0.995, 0}) + ints({0}) + "\n";
  s += ints({0, 0, 0, 0}) + reals({0}) + ints({0, 0, 0}) + "\n";
  s += mat_card1(1, 1, 7.8e3, 1, 1);
  s += "material type # 1 (elastic)\n";
  s += reals({2e11}) + "\n" + reals({0.3}) + "\n\n\n\n\n";
  s += " Hughes-Liu Beam Section Properties\n";
  s += reals({0.8333, double(user_rule ? -1 : qr), double(cst)}) + "\n";
  s += reals({0.05, 0.05, 0.05, 0.05, 0, 0}) + "\n";
  if (user_rule) {
    s += I(4, 5) + reals({1}) + "\n";
    const double g = 1 / std::sqrt(3.0);
    for (double a : {-g, g})
      for (double b : {-g, g}) s += reals({a, b, 1.0}) + "\n";
  }
  for (int k = 0; k <= nb; ++k) s += I(k + 1, 8) + I(k == 0 ? 7 : 0, 5) + E(0.1 * k, 20, 13) + E(0, 20, 13) + E(0, 20, 13) + I(k == 0 ? 7 : 0, 5) + "\n";
  for (int k = 0; k < nb; ++k) s += I(k + 1, 8) + I(1, 5) + ints({k + 1, k + 2, 0}, 8) + "\n";
  s += ints({1, 2, 0}) + "\n" + reals({0, 1}) + "\n" + reals({1, 1}) + "\n";
  s += I(nb + 1, 8) + I(3, 5) + I(1, 5) + reals({100}) + "\n";
  // critical damping of the first bending mode: omega1 = 1.875^2 sqrt(EI / (rho A L^4))
  const double EI = 2e11 * std::pow(0.05, 4) / 12, rhoA = 7.8e3 * 0.05 * 0.05;
  const double omega1 = 1.875104 * 1.875104 * std::sqrt(EI / rhoA);
  s += reals({1.0, omega1, 0, 0}) + "\n";
  return s;
}

}  // namespace

// Beams from the fixed format: a cantilever under a tip load settles (critical mass damping) on
// the closed form P L^3 / 3EI + P L / (k G A) (Timoshenko's shear term, k = 0.8333), within 1 %.
TEST(RealDyna3dLayout, FixedFormatCantileverSettlesOnTheClosedForm) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(cantilever(), m, d)) << all_messages(d);
  ASSERT_TRUE(check_model(m, d)) << all_messages(d);
  ASSERT_EQ(m.num_beams(), 10);
  EXPECT_TRUE(m.materials[0].beam);
  EXPECT_EQ(m.materials[0].beam_section.qr, 2);
  EXPECT_DOUBLE_EQ(m.materials[0].beam_section.ts1, 0.05);
  const State s = run_to_end(m);
  const double E = 2e11, G = E / 2.6, h = 0.05, I = h * h * h * h / 12, P = 100, L = 1;
  const double expected = P * L * L * L / (3 * E * I) + P * L / (0.8333 * G * h * h);
  EXPECT_NEAR(s.z[10] - m.z[10], expected, 0.01 * expected);
}

// A beam quadrature rule far beyond an int is refused naming its field (a fuzz finding: the
// rule was converted to an int before it was checked).
TEST(RealDyna3dLayout, BeamQuadratureRuleBeyondAnIntIsRefused) {
  std::string s = cantilever();
  const std::string card = reals({0.8333, 2, 0});
  s.replace(s.find(card), card.size(), reals({0.8333, 5.8193e9, 0}));
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_string(s, m, d));
  EXPECT_EQ(d.count(1006), 1) << all_messages(d);
  EXPECT_NE(all_messages(d).find("field \"quadrature rule\""), std::string::npos) << all_messages(d);
}

// A user integration rule (QR -1, cross-section type 2) holding 2 x 2 Gauss (points written to
// four digits, +-5.774e-1) gives the built-in rule 2's deflections within 5e-4 (the rounded
// points' second moment, (0.5774 sqrt 3)^2 - 1 = 2e-4); the fixed -> fixed round trip keeps it.
TEST(RealDyna3dLayout, UserBeamRuleEqualsTheBuiltInRuleAndRoundTrips) {
  Model a, b;
  Diagnostics da, db;
  ASSERT_TRUE(read_string(cantilever(), a, da)) << all_messages(da);
  ASSERT_TRUE(read_string(cantilever(2, 2, true), b, db)) << all_messages(db);
  ASSERT_EQ(b.materials[0].beam_section.user_rule.size(), 4u);
  ASSERT_TRUE(check_model(a, da) && check_model(b, db));
  const State sa = run_to_end(a), sb = run_to_end(b);
  for (int n = 1; n < 11; ++n) EXPECT_NEAR(sb.z[std::size_t(n)] / sa.z[std::size_t(n)], 1.0, 5e-4) << n;
  std::ostringstream fx;
  write_fixed_deck(fx, b);
  Model c;
  Diagnostics dc;
  ASSERT_TRUE(read_string(fx.str(), c, dc)) << all_messages(dc) << fx.str();
  const auto diff = model_differences(b, c, 20);
  EXPECT_TRUE(diff.empty()) << diff.front();
  EXPECT_EQ(c.materials[0].beam_section.user_rule, b.materials[0].beam_section.user_rule);
}

// A prescribed rotational velocity (DOF 6, about y) at the tip of the cantilever: 1 rad/s for
// 9 ms, down to 0 at 11 ms (10 mrad in all), then held; with critical damping it settles on a pure end moment's shape, tip rotation
// theta = 0.01 and tip deflection -theta L / 2 (within 1 %); the rotation is the prescribed one.
namespace {

// The cantilever with its tip load replaced by a prescribed rotational velocity about y at the
// tip (DOF 6, type 0): 1 rad/s for 9 ms, down to 0 at 11 ms (10 mrad in all), then held.
std::string cantilever_with_tip_rotation() {
  std::string s = cantilever();
  const std::string c5 = ints({1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  s.replace(s.find(c5), c5.size(), ints({1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  const std::string curve = ints({1, 2, 0}) + "\n" + reals({0, 1}) + "\n" + reals({1, 1}) + "\n";
  s.replace(s.find(curve), curve.size(), ints({1, 4, 0}) + "\n" + reals({0, 1}) + "\n" + reals({0.009, 1}) + "\n" + reals({0.011, 0}) + "\n" +
                                             reals({1, 0}) + "\n");
  const std::string load = I(11, 8) + I(3, 5) + I(1, 5) + reals({100}) + "\n";
  s.replace(s.find(load), load.size(), I(11, 8) + I(1, 5) + I(6, 5) + reals({1, 0, 0, 0}) + I(0, 5) + "\n");
  return s;
}

}  // namespace

TEST(RealDyna3dLayout, PrescribedTipRotationBendsTheCantileverAsAnEndMoment) {
  std::string s = cantilever_with_tip_rotation();
  const std::string c5 = ints({1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  const std::string load = I(11, 8) + I(3, 5) + I(1, 5) + reals({100}) + "\n";
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(s, m, d)) << all_messages(d);
  ASSERT_TRUE(check_model(m, d)) << all_messages(d);
  ASSERT_EQ(m.prescribed_motions.size(), 1u);
  EXPECT_TRUE(m.prescribed_motions[0].rotation);
  const State st = run_to_end(m);
  const double theta = 0.01, L = 1;
  EXPECT_NEAR(st.z[10] - m.z[10], -theta * L / 2, 0.01 * theta * L / 2);
  EXPECT_NEAR(st.energy_ratio(), 1.0, 1e-3);
  // a rotational displacement (type 2) is refused naming the type field
  std::string bad = cantilever();
  bad.replace(bad.find(c5), c5.size(), ints({1, 1, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  bad.replace(bad.find(load) + load.size(), 0, I(11, 8) + I(1, 5) + I(6, 5) + reals({1, 0, 0, 0}) + I(2, 5) + "\n");
  Model mb;
  Diagnostics db;
  EXPECT_FALSE(read_string(bad, mb, db));
  EXPECT_NE(all_messages(db).find("field \"type\" (cols 59-63)"), std::string::npos) << all_messages(db);
}

// The same tip rotation from a keyword deck (issue 25: DOF 5-8 of shell and beam nodes): the
// converter writes the fixed deck's rotational velocity as *BOUNDARY_PRESCRIBED_MOTION_NODE DOF
// 6 and reads it back the same; then the tip's angle is given by its angle (VAD 2: 0 to 10 mrad
// over 10 ms, then held) and by its angular acceleration about *DEFINE_VECTOR y with the other
// rotations held (DOF -8, VAD 1: +-400 rad/s^2 for 5 ms each, 10 mrad at rest; the curve's steps
// over 20 us).  Each settles on
// the pure end moment's shape, tip deflection -theta L / 2 (within 1 %); the tip's rotations about
// x and z stay 0 exactly with DOF -8; the energy books balance (1e-3).
TEST(RealDyna3dLayout, KeywordTipRotationByAngleOrAccelerationBendsTheCantilever) {
  Model f;
  Diagnostics df;
  ASSERT_TRUE(read_string(cantilever_with_tip_rotation(), f, df)) << all_messages(df);
  std::ostringstream k;
  write_keyword_deck(k, f);
  std::string text = k.str();
  ASSERT_NE(text.find("*BOUNDARY_PRESCRIBED_MOTION_NODE"), std::string::npos) << text;
  Model back;
  Diagnostics db;
  ASSERT_TRUE(read_any(text, back, db, "cantilever.k")) << all_messages(db);
  const auto diff = model_differences(f, back, 10);
  EXPECT_TRUE(diff.empty()) << diff.front();
  // the motion block replaced by the variants
  const std::size_t a = text.find("*BOUNDARY_PRESCRIBED_MOTION_NODE"), b = text.find("\n*", a + 1);
  auto card = [](std::initializer_list<std::string> fields, std::size_t w = 10) {
    std::string c;
    for (const std::string& x : fields) c += std::string(x.size() < w ? w - x.size() : 0, ' ') + x;
    return c + "\n";
  };
  auto point = [&](const char* t, const char* v) { return card({t, v}, 20); };
  const std::string angle = "*DEFINE_CURVE\n" + card({"91"}) + point("0.0", "0.0") + point("0.01", "0.01") + point("1.0", "0.01");
  const std::string accel = "*DEFINE_CURVE\n" + card({"92"}) + point("0.0", "400.0") + point("0.00499", "400.0") + point("0.00501", "-400.0") +
                            point("0.00999", "-400.0") + point("0.01001", "0.0") + point("1.0", "0.0") +
                            "*DEFINE_VECTOR\n" + card({"93", "0.0", "0.0", "0.0", "0.0", "2.0", "0.0"});
  const std::string by_angle = "*BOUNDARY_PRESCRIBED_MOTION_NODE\n" + card({"11", "6", "2", "91", "1.0"}) + angle;
  const std::string by_accel = "*BOUNDARY_PRESCRIBED_MOTION_NODE\n" + card({"11", "-8", "1", "92", "1.0", "93"}) + accel;
  for (const std::string& motion : {by_angle, by_accel}) {
    std::string t = text;
    t.replace(a, b + 1 - a, motion);
    Model m;
    Diagnostics d;
    ASSERT_TRUE(read_any(t, m, d, "cantilever.k")) << all_messages(d) << t;
    ASSERT_EQ(m.prescribed_motions.size(), 1u);
    EXPECT_TRUE(m.prescribed_motions[0].rotation);
    const State st = run_to_end(m);
    const double theta = 0.01, L = 1;
    EXPECT_NEAR(st.z[10] - m.z[10], -theta * L / 2, 0.01 * theta * L / 2) << motion;
    EXPECT_NEAR(st.energy_ratio(), 1.0, 1e-3) << motion;
    if (m.prescribed_motions[0].hold_normal) {
      const int r = st.shells.node_rot[10];
      ASSERT_GE(r, 0);
      EXPECT_EQ(st.shells.wx[std::size_t(r)], 0.0);
      EXPECT_EQ(st.shells.wz[std::size_t(r)], 0.0);
    }
  }
}
