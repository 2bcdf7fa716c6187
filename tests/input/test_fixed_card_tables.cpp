// The fixed-format cards read by their tables (impact3d/input/fixed_cards.cpp): title card,
// material card 1, node, solid, shell and shell thickness cards, beam integration rule cards,
// load curve header and point cards, nodal loads, stonewall, moving stonewall and node list
// cards, IMPACT-3D's initial velocity range card, segment cards, base accelerations, and the
// small format's tables.  A deck of our own in each vintage and format holds every card kind; it
// reads, converts fixed -> keyword -> fixed to the same model and runs to the same bits; each
// malformed card is refused naming file, line, card, field and the columns of its table; the
// printed echo names its columns with the tables' field names.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "impact3d/input/deck_writer.h"
#include "impact3d/input/fixed_cards.h"
#include "impact3d/output/printed_output.h"
#include "impact3d/solve/engine.h"
#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

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
// The layout of a deck: vintage, and the small format (ids I5) or the large (I8).
struct Format {
  bool v88 = false;
  bool small = false;
  int w() const { return small ? 5 : 8; }
};
std::string node(int id, int code, double x, double y, double z, int w = 8) {
  return I(id, w) + I(code, 5) + E(x, 20, 13) + E(y, 20, 13) + E(z, 20, 13) + I(0, 5);
}

// A deck as keyed lines (no comment lines: line k of the deck is entry k - 1), so that a case
// can replace one card and know its line.
struct KeyedDeck {
  std::vector<std::pair<std::string, std::string>> lines;
  void add(const std::string& key, const std::string& text) { lines.push_back({key, text}); }
  int line_of(const std::string& key) const {
    for (std::size_t k = 0; k < lines.size(); ++k)
      if (lines[k].first == key) return int(k) + 1;
    ADD_FAILURE() << "no card " << key;
    return 0;
  }
  KeyedDeck with(const std::string& key, const std::string& text) const {
    KeyedDeck d = *this;
    d.lines[std::size_t(line_of(key) - 1)].second = text;
    return d;
  }
  std::string text() const {
    std::string s;
    for (const auto& l : lines) s += l.second + "\n";
    return s;
  }
};

void control_cards(KeyedDeck& d, Format f) {
  const bool v88 = f.v88;
  // 3 materials, 14 nodes, 1 solid, 1 beam, 1 shell
  if (f.small) d.add("card 2", ints({3, 14, 1, 1, 1, 0, 0}) + reals({0}));
  else if (v88) d.add("card 2", I(3, 5) + I(14, 10) + I(1, 10) + I(1, 10) + I(1, 10) + I(0, 10));
  else d.add("card 2", I(3, 5) + I(14, 10) + I(1, 10) + I(1, 10) + I(1, 10) + I(0, 10) + I(0, 10) + reals({0}) + "  0.0");
  d.add("card 3", v88 ? ints({1, 1, 0, 1, 0, 0}) : ints({1, 1, 0, 1, 0, 0, 0, 0, 0}));  // node, solid, shell blocks
  d.add("card 4", v88 ? "    0    0    0    0    0    0e20.9" : I(0, 10) + ints({0, 0, 0, 0}) + "e20.0" + I(0, 5) + reals({0}));
  // 1 curve, 1 nodal load, 1 pressure, 1 motion, 1 stonewall, range velocity card, 1 interface, base z
  d.add("card 5", ints({1, 1, 1, 1, 1, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0, 0}));
  d.add("card 6", reals({1e-4, 1e-5, 2e-5}) + ints({0, 0}) + reals({0, 0}) + ints({0, 0}) + reals({0.5}));
  d.add("card 7", v88 ? ints({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}) : ints({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0}));
  d.add("card 8", ints({0, 0}) + reals({0}) + ints({1, 4, 0, 0, 0}) + reals({0, 0, 0}) + ints({0}));  // one user beam rule of 4 points
  d.add("card 9", ints({0, 0, 0, 0}) + reals({0}) + ints({0, 0, 0}));
  if (v88) d.add("free format", "mdamp 1");
}

void materials(KeyedDeck& d) {
  const std::string tail = I(0, 5) + I(0, 5) + E(0, 10, 4) + I(0, 5) + E(0, 10, 4) + E(0, 10, 4);
  d.add("material 1 card 1", I(1, 5) + I(1, 5) + E(7.8e3, 10, 4) + tail + I(0, 5) + I(0, 5) + I(0, 5));
  d.add("material 1 title", "steel block");
  d.add("material 1 card 3", reals({2e11}));
  d.add("material 1 card 4", reals({0.3}));
  for (int c = 5; c <= 8; ++c) d.add("material 1 card " + std::to_string(c), "");
  d.add("material 2 card 1", I(2, 5) + I(1, 5) + E(2.7e3, 10, 4) + tail + I(2, 5) + I(0, 5) + I(2, 5));
  d.add("material 2 title", "aluminium plate");
  d.add("material 2 card 3", reals({7e10}));
  d.add("material 2 card 4", reals({0.33}));
  for (int c = 5; c <= 8; ++c) d.add("material 2 card " + std::to_string(c), "");
  d.add("section title", " shell section properties");
  d.add("shell section 1", reals({0.8333, 2, 0, 0}));
  d.add("shell section 2", reals({1e-3, 1e-3, 1e-3, 1e-3}));
  d.add("material 3 card 1", I(3, 5) + I(1, 5) + E(7.8e3, 10, 4) + tail + I(1, 5) + I(0, 5) + I(1, 5));
  d.add("material 3 title", "steel beam");
  d.add("material 3 card 3", reals({2e11}));
  d.add("material 3 card 4", reals({0.3}));
  for (int c = 5; c <= 8; ++c) d.add("material 3 card " + std::to_string(c), "");
  d.add("beam section title", " Hughes-Liu Beam Section Properties");
  // built-in rule 2 (a keyword deck cannot hold a user rule: *INTEGRATION_BEAM is refused), so
  // user rule 1 below is read and checked but used by no section
  d.add("beam section 1", reals({0.8333, 2, 0}));
  d.add("beam section 2", reals({0.01, 0.01, 0.01, 0.01, 0, 0}));
  // user rule 1: 2 x 2 Gauss points written as a rule
  d.add("rule 1 header", I(4, 5) + reals({1}));
  const double g = 0.5773502692;
  d.add("rule 1 point 1", reals({-g, -g, 1}));
  d.add("rule 1 point 2", reals({g, -g, 1}));
  d.add("rule 1 point 3", reals({g, g, 1}));
  d.add("rule 1 point 4", reals({-g, g, 1}));
}

void mesh(KeyedDeck& d, Format f) {
  const int w = f.w();
  const double h = 0.01;
  const double cube[8][3] = {{0, 0, 0}, {h, 0, 0}, {h, h, 0}, {0, h, 0}, {0, 0, h}, {h, 0, h}, {h, h, h}, {0, h, h}};
  for (int k = 0; k < 8; ++k) d.add("node " + std::to_string(k + 1), node(k + 1, k < 4 ? 3 : 0, cube[k][0], cube[k][1], cube[k][2], w));
  const double plate[4][2] = {{0, 0}, {h, 0}, {h, h}, {0, h}};
  for (int k = 0; k < 4; ++k) d.add("node " + std::to_string(k + 9), node(k + 9, 0, plate[k][0], plate[k][1], 1.5 * h, w));
  d.add("node 13", node(13, 0, 5 * h, 0, 0, w));
  d.add("node 14", node(14, 0, 6 * h, 0, 0, w));
  d.add("solid 1", I(1, w) + I(1, 5) + ints({1, 2, 3, 4, 5, 6, 7, 8}, w));
  d.add("beam 1", I(1, 8) + I(3, 5) + ints({13, 14, 0}, 8));  // (the beam card is I8 in both formats)
  d.add("shell 1", I(1, w) + I(2, 5) + ints({9, 10, 11, 12}, w));
  d.add("shell 1 thickness", reals({0, 0, 0, 0}));
  d.add("node blocks", ints({5, 12}, 8));
  d.add("solid blocks", ints({1, 1}, 8));
  d.add("shell blocks", ints({1, 1}, 8));
}

void loads(KeyedDeck& d, Format f) {
  const int w = f.w();
  d.add("curve 1 header", ints({1, 2}));
  d.add("curve 1 point 1", reals({0, 1}));
  d.add("curve 1 point 2", reals({1, 1}));
  d.add("nodal load", I(12, w) + I(3, 5) + I(1, 5) + reals({-10}));
  d.add("pressure", I(1, 5) + ints({9, 10, 11, 12}, w) + reals({1e3, 1e3, 1e3, 1e3}));
  d.add("motion", I(9, 8) + I(1, 5) + I(1, 5) + reals({0}) + reals({0, 0, 0}) + I(0, 5));
  d.add("stonewall", ints({4, 1}) + reals({0, 0, -1e-3, 0, 0, 1, 0}));
  d.add("moving stonewall", reals({100, 0}));
  d.add("stonewall nodes", ints({1, 2, 3, 4}, w));
  d.add("velocity", I(5, 8) + reals({0, 0, -1}) + I(12, 8) + I(1, 5));
  d.add("interface", I(1, 8) + I(1, 8) + I(3, 5) + reals({0, 0, 0}));
  d.add("slave segment", I(1, w) + ints({9, 10, 11, 12}, w));
  d.add("master segment", I(1, w) + ints({5, 6, 7, 8}, w));
  d.add("base z", I(1, 5) + reals({9.81}));
  d.add("mass damping", reals({0.01, 1000, 0, 0}));
}

// Every card kind of the fixed format in one deck: a steel cube under a shell plate in contact
// with it, a free Hughes-Liu beam and a user beam integration rule, a moving stonewall, a nodal load, a pressure, a prescribed motion, base
// acceleration, mass damping, time-history blocks, IMPACT-3D's range velocity card.
KeyedDeck every_card_deck(bool v88, bool small = false) {
  const Format f{v88, small};
  KeyedDeck d;
  d.add("title", std::string(v88 ? "every card kind, DYNA3D 88 layout" : "every card kind, later layout").append(72, ' ').substr(0, 72) +
                     (small ? "" : "88 large"));
  control_cards(d, f);
  materials(d);
  mesh(d, f);
  loads(d, f);
  return d;
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

TEST(FixedCardTables, EveryCardKindReadsInBothVintagesAndFormats) {
  if (const char* dump = std::getenv("DUMP_TEST_DECKS")) {  // the fuzz seeds every_card_{88,later}.dyn
    std::ofstream(std::string(dump) + "/every_card_88.dyn") << every_card_deck(true).text();
    std::ofstream(std::string(dump) + "/every_card_later.dyn") << every_card_deck(false).text();
    std::ofstream(std::string(dump) + "/every_card_small.dyn") << every_card_deck(false, true).text();
  }
  for (int k = 0; k < 4; ++k) {
    const bool v88 = k % 2 == 0, small = k >= 2;
    Model m;
    Diagnostics d;
    ASSERT_TRUE(read_string(every_card_deck(v88, small).text(), m, d)) << all_messages(d);
    EXPECT_EQ(m.large_format, !small);
    EXPECT_EQ(m.fixed_vintage, int(v88 ? FixedVintage::dyna3d_88 : FixedVintage::dyna3d_later));
    EXPECT_EQ(m.num_nodes(), 14);
    EXPECT_EQ(m.num_beams(), 1);
    ASSERT_EQ(m.materials.size(), 3u);
    EXPECT_EQ(m.materials[2].beam_section.qr, 2);
    EXPECT_EQ(m.bc[0], 3);
    EXPECT_DOUBLE_EQ(m.z[8], 0.015);
    EXPECT_EQ(m.num_hexes(), 1);
    EXPECT_EQ(m.num_shells(), 1);
    EXPECT_DOUBLE_EQ(m.shell_thickness[0][2], 1e-3);  // blank thickness card: the section's
    ASSERT_EQ(m.load_curves.size(), 1u);
    ASSERT_EQ(m.nodal_loads.size(), 1u);
    EXPECT_DOUBLE_EQ(m.nodal_loads[0].scale, -10);
    ASSERT_EQ(m.walls.size(), 1u);
    EXPECT_DOUBLE_EQ(m.walls[0].mass, 100);
    EXPECT_EQ(m.walls[0].nodes.size(), 4u);
    ASSERT_EQ(m.init_velocities.size(), 1u);
    EXPECT_EQ(m.init_velocities[0].first, 5);
    EXPECT_EQ(m.init_velocities[0].last, 12);
    ASSERT_EQ(m.interfaces.size(), 1u);
    EXPECT_EQ(m.interfaces[0].slave.size(), 1u);
    ASSERT_EQ(m.body_loads.size(), 1u);
    EXPECT_DOUBLE_EQ(m.body_loads[0].scale, 9.81);
    EXPECT_EQ(m.pressure_loads.size(), 1u);
    EXPECT_EQ(m.prescribed_motions.size(), 1u);
    EXPECT_TRUE(m.damping.active);
    EXPECT_EQ(m.shell_th_blocks.size(), 1u);
  }
}

// fixed (88 or later, large or small format) -> keyword -> fixed (later, large): the same model,
// and the same run to the last bit.
TEST(FixedCardTables, EveryCardKindRoundTripsThroughTheConverterToTheSameRun) {
  for (int k = 0; k < 4; ++k) {
    const bool v88 = k % 2 == 0, small = k >= 2;
    Model a;
    Diagnostics da;
    ASSERT_TRUE(read_string(every_card_deck(v88, small).text(), a, da)) << all_messages(da);
    std::ostringstream kw;
    write_keyword_deck(kw, a);
    Model b;
    Diagnostics db;
    ASSERT_TRUE(read_any(kw.str(), b, db, "b.k")) << all_messages(db) << kw.str();
    std::ostringstream fx;
    std::vector<std::string> notes;
    write_fixed_deck(fx, b, &notes);
    Model c;
    Diagnostics dc;
    ASSERT_TRUE(read_string(fx.str(), c, dc)) << all_messages(dc) << fx.str();
    EXPECT_EQ(dc.count(2041), 0) << all_messages(dc);
    const auto diff = model_differences(a, c, 20);
    EXPECT_TRUE(diff.empty()) << diff.front();
    const State sa = run_to_end(a), sc = run_to_end(c);
    ASSERT_EQ(sa.x.size(), sc.x.size());
    EXPECT_GT(sa.cycle, 10);
    for (std::size_t n = 0; n < sa.x.size(); ++n) {
      EXPECT_EQ(sa.x[n], sc.x[n]) << n;
      EXPECT_EQ(sa.z[n], sc.z[n]) << n;
      EXPECT_EQ(sa.vz[n], sc.vz[n]) << n;
    }
  }
}

namespace {

// A malformed card: the deck's card `key` replaced by `text` gives message `id` on that card's
// line, naming `card` and `field` with the columns of `table_field` (or `field`) in `table`.
struct Case {
  const char* key;
  std::string text;
  int id;
  std::string card;
  const char* field;
  const char* table;  // the table whose field gives the columns
  const char* table_field;  // a message over several fields: the first (the span ends at ZH or t)
};

void expect_refused(const KeyedDeck& good, const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    const KeyedDeck bad = good.with(c.key, c.text);
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_string(bad.text(), m, d, "tables.dyn")) << c.key;
    const FixedCardLayout& l = fixed_card_layout(c.table, FixedVintage::dyna3d_later);
    const FixedField& f = l.field(c.table_field ? c.table_field : c.field);
    const int c1 = c.id == 1101 ? 73 : f.c1, c2 = c.table_field ? l.field(std::string(c.field) == "XT-ZH" ? "ZH" : "t").c2 : f.c2;
    bool found = false;
    for (const Diagnostic& x : d.all())
      found = found || (x.id == c.id && x.where.file == "tables.dyn" && x.where.line == bad.line_of(c.key) && x.where.card == c.card &&
                        x.where.field == c.field && x.where.col_first == c1 && x.where.col_last == c2);
    EXPECT_TRUE(found) << c.key << ": expected " << c.id << " at line " << bad.line_of(c.key) << ", " << c.card << ", field \"" << c.field
                       << "\" (cols " << c1 << "-" << c2 << ")\n" << all_messages(d);
  }
}

}  // namespace

// Each malformed card of the tabled kinds: its message names the file, the card's line, the
// card, the field and the field's columns in the table.
TEST(FixedCardTables, MalformedCardsNameFileLineCardFieldAndColumns) {
  const KeyedDeck good = every_card_deck(false);
  const std::string tail = I(0, 5) + I(0, 5) + E(0, 10, 4) + I(0, 5) + E(0, 10, 4) + E(0, 10, 4);
  const std::vector<Case> cases = {
      {"title", std::string(72, 'x') + "10 large", 1101, "title card", "format flag", "title card", nullptr},
      {"material 1 card 1", I(1, 5) + I(99, 5) + E(7.8e3, 10, 4) + tail, 1103, "material set 1 card 1", "material type", "material card 1", nullptr},
      {"material 1 card 1", I(1, 5) + I(1, 5) + E(0, 10, 4) + tail, 1207, "material set 1 card 1", "density", "material card 1", nullptr},
      {"material 1 card 1", I(1, 5) + I(1, 5) + E(7.8e3, 10, 4) + tail + I(5, 5), 1006, "material set 1 card 1", "element type", "material card 1", nullptr},
      {"material 1 card 1", I(1, 5) + I(1, 5) + E(7.8e3, 10, 4) + "  1.0" + tail.substr(5), 1001, "material set 1 card 1", "EOS type", "material card 1", nullptr},
      {"node 3", node(3, 9, 0.01, 0.01, 0), 1216, "node card for node 3", "boundary code", "node card", nullptr},
      {"node 3", I(3, 8) + I(0, 5) + "   1.0.0e-2         ", 1002, "node card for node 3", "x", "node card", nullptr},
      {"node 3", node(3, 0, 0.01, 0.01, 0).substr(0, 73) + I(8, 5), 1216, "node card for node 3", "rotational code", "node card", nullptr},
      {"solid 1", I(1, 8) + I(7, 5) + ints({1, 2, 3, 4, 5, 6, 7, 8}, 8), 1203, "solid element card for element 1", "material number", "solid element card", nullptr},
      {"solid 1", I(1, 8) + I(1, 5) + ints({1, 2, 3, 4, 99, 6, 7, 8}, 8), 1202, "solid element card for element 1", "node n5", "solid element card", nullptr},
      {"solid 1", I(1, 8) + I(1, 5) + ints({1, 2, 3, 4, 5}, 8) + "     6.0" + ints({7, 8}, 8), 1001, "solid element card for element 1", "node n6", "solid element card", nullptr},
      {"shell 1", I(1, 8) + I(1, 5) + ints({9, 10, 11, 12}, 8), 1203, "shell element card for element 1", "material number", "shell element card", nullptr},
      {"shell 1", I(1, 8) + I(2, 5) + ints({9, 99, 11, 12}, 8), 1202, "shell element card for element 1", "node n2", "shell element card", nullptr},
      {"shell 1 thickness", reals({1e-3, 1e-3, -1e-3, 1e-3}), 1241, "shell element 1 thickness card", "thickness t3", "shell thickness card", nullptr},
      {"curve 1 header", ints({5, 2}), 1201, "load curve 1 header card", "curve number", "load curve header card", nullptr},
      {"curve 1 point 2", reals({0, 1}), 1217, "load curve 1 point 2", "time", "load curve point card", nullptr},
      {"nodal load", I(12, 8) + I(5, 5) + I(1, 5) + reals({-10}), 1102, "nodal load card 1", "direction", "nodal load card", nullptr},
      {"nodal load", I(12, 8) + I(3, 5) + I(3, 5) + reals({-10}), 1201, "nodal load card 1", "load curve", "nodal load card", nullptr},
      {"nodal load", I(15, 8) + I(3, 5) + I(1, 5) + reals({-10}), 1202, "nodal load card 1", "node", "nodal load card", nullptr},
      {"stonewall", ints({4, 1}) + reals({0, 0, -1e-3, 0, 0, 1, 2}), 1219, "stonewall 1 card 1", "FRIC", "stonewall card", nullptr},
      {"stonewall", ints({4, 1}) + reals({0, 0, 0, 0, 0, 0, 0}), 1213, "stonewall 1 card 1", "XT-ZH", "stonewall card", "XT"},
      {"stonewall", ints({15, 1}) + reals({0, 0, -1e-3, 0, 0, 1, 0}), 1003, "stonewall 1 card 1", "NSN", "stonewall card", nullptr},
      {"moving stonewall", reals({0, 0}), 1003, "stonewall 1 card 2 (moving wall)", "MASS", "moving stonewall card", nullptr},
      {"stonewall nodes", ints({1, 2, 99, 4}, 8), 1202, "stonewall 1 node card 1", "node 3", "node list card", nullptr},
      {"velocity", I(5, 8) + reals({0, 0, -1}) + I(99, 8) + I(1, 5), 1202, "initial-velocity card 1", "last node", "initial velocity range card", nullptr},
      {"velocity", I(5, 8) + reals({0, 0, -1}) + I(12, 8) + I(-1, 5), 1003, "initial-velocity card 1", "increment", "initial velocity range card", nullptr},
      {"slave segment", I(1, 8) + ints({9, 10, 99, 12}, 8), 1202, "sliding interface 1 slave segment card 1 of 1", "node n3", "segment card", nullptr},
      {"base z", I(4, 5) + reals({9.81}), 1201, "base acceleration card (z)", "load curve", "base acceleration card", nullptr},
      {"base z", I(1, 5) + "  9.81.0  ", 1002, "base acceleration card (z)", "scale factor", "base acceleration card", nullptr},
      {"rule 1 header", I(5, 5) + reals({1}), 1003, "beam integration rule 1 header card", "number of points", "beam integration rule header card", nullptr},
      {"rule 1 point 2", reals({0.5, -0.5, -1}), 1003, "beam integration rule 1 point 2", "weight", "beam integration point card", nullptr},
      {"rule 1 point 3", reals({0.5, 1.5, 1}), 1003, "beam integration rule 1 point 3", "s, t", "beam integration point card", "s"},
  };
  expect_refused(good, cases);
}

// The small format's tables (ids I5): each malformed card names the small table's columns.
TEST(FixedCardTables, MalformedSmallFormatCardsNameTheSmallTablesColumns) {
  const KeyedDeck good = every_card_deck(false, true);
  const std::vector<Case> cases = {
      {"card 2", ints({3, 14, 1, 1, 1, 1, 0}) + reals({0}), 1102, "control card 2", "NUMELT", "control card 2 (small format)", nullptr},
      {"card 2", ints({3, 14, 1, 1, 1, 0, 0}) + reals({-1}), 1221, "control card 2", "interface output interval", "control card 2 (small format)", nullptr},
      {"node 3", node(3, 9, 0.01, 0.01, 0, 5), 1216, "node card for node 3", "boundary code", "node card (small format)", nullptr},
      {"node 3", node(3, 0, 0.01, 0.01, 0, 5).substr(0, 70) + I(9, 5), 1216, "node card for node 3", "rotational code", "node card (small format)", nullptr},
      {"solid 1", I(1, 5) + I(1, 5) + ints({1, 2, 3, 4, 99, 6, 7, 8}, 5), 1202, "solid element card for element 1", "node n5", "solid element card (small format)", nullptr},
      {"shell 1", I(1, 5) + I(2, 5) + ints({9, 99, 11, 12}, 5), 1202, "shell element card for element 1", "node n2", "shell element card (small format)", nullptr},
      {"nodal load", I(12, 5) + I(5, 5) + I(1, 5) + reals({-10}), 1102, "nodal load card 1", "direction", "nodal load card (small format)", nullptr},
      {"pressure", I(1, 5) + ints({9, 10, 99, 12}, 5) + reals({1e3, 1e3, 1e3, 1e3}), 1202, "pressure card 1", "node n3", "pressure card (small format)", nullptr},
      {"pressure", I(1, 5) + ints({9, 10, 11, 12}, 5) + reals({1e3, 1e3, 1e3, 1e3}) + "     " + " 1.0.0e-3 ", 1002, "pressure card 1", "arrival time", "pressure card (small format)", nullptr},
      {"stonewall nodes", ints({1, 2, 99, 4}, 5), 1202, "stonewall 1 node card 1", "node 3", "node list card (small format)", nullptr},
      {"slave segment", I(1, 5) + ints({9, 10, 99, 12}, 5), 1202, "sliding interface 1 slave segment card 1 of 1", "node n3", "segment card (small format)", nullptr},
  };
  expect_refused(good, cases);
}

// The printed echo heads the node, solid and shell cards with their tables' field names.
TEST(FixedCardTables, PrintedEchoNamesTheTablesFields) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(every_card_deck(false).text(), m, d)) << all_messages(d);
  std::ostringstream os;
  write_model_summary(os, m);
  const std::string p = os.str();
  for (const char* id : {"node card", "solid element card", "shell element card", "shell thickness card"})
    for (const char* name : {"node number", "boundary code", "element number", "material number", "node n4", "thickness t3"}) {
      const FixedCardLayout& l = fixed_card_layout(id, FixedVintage::dyna3d_later);
      bool has = false;
      for (const FixedField& f : l.fields) has = has || std::string(f.name) == name;
      if (has) {
        EXPECT_NE(p.find(name), std::string::npos) << id << " " << name << "\n" << p;
      }
    }
  EXPECT_NE(p.find("n o d e   c a r d s   (the first 10 of 14)"), std::string::npos) << p;
  // node 9: its card's values under the heads (z = 1.5 cm)
  EXPECT_NE(p.find("1.5000e-02"), std::string::npos) << p;
}
