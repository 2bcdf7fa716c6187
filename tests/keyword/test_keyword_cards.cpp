// The keyword cards read by their tables (impact3d/input/keyword_cards.cpp): the control and
// database cards give the Model's controls from their fields, blank and 0 values as the tables
// say; a bad field is refused naming file, line, card, field and the columns of its position
// (standard, long and comma formats); the checks come in the tables' order; docs/keyword-tables.md is
// the generated page (impact3d --keyword-tables).

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/keyword_cards.h"
#include "impact3d/input/keyword_reader.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

using namespace impact3d;

namespace {

std::string file_text(const std::string& rel) {
  std::ifstream in(std::string(IMPACT3D_SOURCE_DIR) + "/" + rel, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// One hexahedron with these control cards.
std::string deck(const std::string& controls) {
  return "*KEYWORD\n" + controls +
         "*PART\ncube\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
         "*MAT_ELASTIC\n         17.85000E-9  200000.0       0.3\n*NODE\n"
         "       1             0.0             0.0             0.0\n       2             1.0             0.0             0.0\n"
         "       3             1.0             1.0             0.0\n       4             0.0             1.0             0.0\n"
         "       5             0.0             0.0             1.0\n       6             1.0             0.0             1.0\n"
         "       7             1.0             1.0             1.0\n       8             0.0             1.0             1.0\n"
         "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7       8\n*END\n";
}

// A card of fields right-aligned in `width` columns.
std::string card(std::initializer_list<const char*> fields, int width = 10) {
  std::string s;
  for (const char* f : fields) s += std::string(std::size_t(width) - std::string(f).size(), ' ') + f;
  return s + "\n";
}

struct Read {
  Model m;
  Diagnostics d;
  bool ok = false;
  std::vector<std::string> lines() const {
    std::vector<std::string> v;
    for (const Diagnostic& x : d.all()) v.push_back(render(x));
    return v;
  }
};

Read read(const std::string& text) {
  Read r;
  DeckFile f;
  f.load_from_string("deck.k", text);
  r.ok = read_keyword_deck(f, r.m, r.d);
  return r;
}

}  // namespace

TEST(KeywordCards, ControlCardsGiveTheModelsControls) {
  const Read r = read(deck("*CONTROL_TERMINATION\n" + card({"2.0E-05", "40", "0.25", "0", "1.E+8"}) +
                           "*CONTROL_TIMESTEP\n" + card({"1.E-7", "0.0", "", "", "0.0", "", "1", "1"}) +
                           "*CONTROL_CONTACT\n" + card({"0.0", "", "", "2", "3"}) +
                           "*CONTROL_OUTPUT\n" + card({"", "", "", "", "", "", "0"}) +
                           "*DATABASE_BINARY_D3PLOT\n    5.0E-7\n*DATABASE_NODOUT\n    2.0E-7\n"
                           "*DATABASE_BINARY_D3DUMP\n        7.\n*DATABASE_BINARY_INTFOR\n\n"));
  ASSERT_TRUE(r.ok) << r.lines().front();
  const ControlData& k = r.m.control;
  EXPECT_EQ(k.end_time, 2.0e-5);
  EXPECT_EQ(k.end_cycle, 40);
  EXPECT_EQ(k.min_step_factor, 0.25);
  EXPECT_EQ(k.end_mass_percent, 0.0) << "ENDMAS 1e8: LS-DYNA's default, no limit";
  EXPECT_EQ(k.initial_dt, 1e-7);
  EXPECT_EQ(k.tssf, 0.9) << "TSSFAC 0 stands for its blank value";
  EXPECT_TRUE(k.erode_small_steps);
  EXPECT_TRUE(k.mass_scaling_first_only);
  EXPECT_EQ(k.penalty_scale, 0.1) << "SLSFAC 0 stands for 0.1";
  EXPECT_EQ(k.report_interval, 100) << "IKEDIT 0 stands for 100";
  EXPECT_EQ(k.plot_interval, 5e-7);
  EXPECT_EQ(k.th_interval, 2e-7);
  EXPECT_EQ(k.restart_dump_cycles, 7) << "an integral real reads as the count";
  EXPECT_EQ(k.intfor_interval, 0.0) << "*DATABASE_BINARY_INTFOR with a blank card: the plot interval";
}

TEST(KeywordCards, BlankControlsTakeTheTablesBlankValues) {
  const Read r = read(deck("*CONTROL_TERMINATION\n   1.0E-05\n*CONTROL_TIMESTEP\n\n*CONTROL_HOURGLASS\n\n"));
  ASSERT_TRUE(r.ok) << r.lines().front();
  EXPECT_EQ(r.m.control.tssf, 0.9);
  EXPECT_EQ(r.m.control.report_interval, 100);
  EXPECT_EQ(r.m.control.plot_interval, 1e-5 / 20);
  EXPECT_EQ(r.m.control.th_interval, 1e-5 / 1000);
  EXPECT_LT(r.m.control.intfor_interval, 0.0) << "no *DATABASE_BINARY_INTFOR: no interface-force database";
}

// Each message names the field and the columns of its position: 10 columns a field, 20 in
// long format, the text between commas in free format.
TEST(KeywordCards, ErrorsNameTheFieldsColumnsInEveryFormat) {
  const Read fixed = read(deck("*CONTROL_TERMINATION\n   1.0E-05\n*CONTROL_CONTACT\n" + card({"", "", "", "7"})));
  ASSERT_EQ(fixed.lines().size(), 1u);
  EXPECT_EQ(fixed.lines()[0], "deck.k:5: error 1006: *CONTROL_CONTACT card 1, field \"SHLTHK\" (cols 31-40): not a valid choice: "
                              "0 shells at their mid-surface, 1 at +-t/2 except rigid shells, 2 at +-t/2 [found \"7\"]");
  const Read lng = read(deck("*CONTROL_TERMINATION\n   1.0E-05\n*CONTROL_CONTACT +\n" + card({"", "", "", "7"}, 20)));
  ASSERT_EQ(lng.lines().size(), 1u);
  EXPECT_NE(lng.lines()[0].find("field \"SHLTHK\" (cols 61-80)"), std::string::npos) << lng.lines()[0];
  const Read free = read(deck("*CONTROL_TERMINATION\n1.0E-05,-2\n"));
  ASSERT_EQ(free.lines().size(), 1u);
  EXPECT_EQ(free.lines()[0], "deck.k:3: error 1003: *CONTROL_TERMINATION, field \"ENDCYC\" (cols 9-10): value out of range: "
                             "must be 0 (no limit) or a cycle count [found \"-2\"]");
}

// Checks per field (each right after its field) or after the card, as the tables say: the
// order of the messages is the reader's of old.
TEST(KeywordCards, ChecksComeInTheTablesOrder) {
  const Read per_field = read(deck("*CONTROL_TERMINATION\n      -1.0       abc\n"));
  ASSERT_EQ(per_field.lines().size(), 2u);
  EXPECT_NE(per_field.lines()[0].find("error 1214"), std::string::npos);
  EXPECT_NE(per_field.lines()[1].find("error 1001"), std::string::npos);
  const Read after = read(deck("*CONTROL_TERMINATION\n   1.0E-05\n*CONTROL_HOURGLASS\n         7        zz\n"));
  ASSERT_EQ(after.lines().size(), 2u);
  EXPECT_NE(after.lines()[0].find("error 1002"), std::string::npos);
  EXPECT_NE(after.lines()[1].find("error 1102"), std::string::npos);
  EXPECT_NE(after.lines()[1].find("hourglass type 7 (IMPACT-3D has"), std::string::npos) << after.lines()[1];
}

TEST(KeywordCards, EveryCardHoldsItsFieldsOnceInOrder) {
  std::set<std::string> names;
  for (const KeywordSpec& s : all_keyword_specs()) {
    for (const char* n : s.names) {
      EXPECT_TRUE(names.insert(n).second) << n << " has two entries";
      EXPECT_EQ(find_keyword_spec(n), &s) << n;
    }
    for (const KeywordCardLayout& c : s.cards) {
      int last = -1;
      for (const KeywordField& f : c.fields) {
        EXPECT_GT(f.index, last) << s.names.front() << " " << f.name;
        EXPECT_LT(f.index, c.count) << s.names.front() << " " << f.name;
        last = f.index;
        for (const KeywordCheck& ch : f.checks) {
          if (ch.id == 0) continue;  // accepted
          EXPECT_EQ(message_def(ch.id).id, ch.id) << f.name;
        }
      }
    }
  }
  EXPECT_NE(find_keyword_spec("CONTROL_MPP_IO_NODUMP"), nullptr) << "CONTROL_MPP_* is a prefix";
  EXPECT_EQ(find_keyword_spec("CONTROL_ADAPTIVE"), nullptr);
}

// docs/keyword-tables.md's tables are the generated ones (impact3d --keyword-tables): the manual
// cannot drift from the reader.
TEST(KeywordCards, DocsPageIsTheGeneratedOne) {
  const std::string page = file_text("docs/keyword-tables.md");
  const std::string begin = "<!-- BEGIN keyword tables (impact3d --keyword-tables) -->\n", end = "<!-- END keyword tables -->";
  const std::size_t a = page.find(begin), b = page.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(page.substr(a + begin.size(), b - a - begin.size()), keyword_tables_markdown())
      << "regenerate: impact3d --keyword-tables, between the markers in docs/keyword-tables.md";
}

// The section cards: named by their id once it is read; card 2 of *SECTION_BEAM by ELFORM;
// T1 / TS1 / A checked once the card's sizes are read (so a bad T2 comes first); 0 and blank
// as the tables say.
TEST(KeywordCards, SectionCardsByTheirTables) {
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read shell = read(deck(head + "*SECTION_SHELL\n" + card({"7", "", "0", "0"}) + card({"-1.0", "x"})));
  ASSERT_EQ(shell.lines().size(), 2u);
  EXPECT_EQ(shell.lines()[0], "deck.k:6: error 1002: *SECTION_SHELL 7, field \"T2\" (cols 11-20): not a real number [found \"x\"]");
  EXPECT_EQ(shell.lines()[1], "deck.k:6: error 1241: *SECTION_SHELL 7, field \"T1\" (cols 1-10): shell thickness must be positive [found \"-1.0\"]");
  const Read beams = read(deck(head + "*SECTION_BEAM\n" + card({"8", "2"}) + card({"0.0", "1.0", "1.0", "-1.0"}) +
                               "*SECTION_BEAM\n" + card({"9", "3", "", "2.5"}) + card({"2.0"})));
  ASSERT_EQ(beams.lines().size(), 3u);
  EXPECT_NE(beams.lines()[0].find("*SECTION_BEAM 8, field \"A\" (cols 1-10): beam section size must be positive: the area must be positive"), std::string::npos) << beams.lines()[0];
  EXPECT_NE(beams.lines()[1].find("*SECTION_BEAM 8, field \"J\" (cols 31-40)"), std::string::npos) << beams.lines()[1];
  EXPECT_NE(beams.lines()[2].find("*SECTION_BEAM 9, field \"QR/IRID\" (cols 31-40): value out of range: quadrature rule 1-5"), std::string::npos) << beams.lines()[2];
  const Read hg = read(deck(head + "*HOURGLASS\n" + card({"3", "7", "-1"})));
  ASSERT_EQ(hg.lines().size(), 2u);
  EXPECT_NE(hg.lines()[0].find("*HOURGLASS 3, field \"IHQ\" (cols 11-20): feature not supported by IMPACT-3D: hourglass type 7"), std::string::npos) << hg.lines()[0];
  EXPECT_NE(hg.lines()[1].find("*HOURGLASS 3, field \"QM\""), std::string::npos) << hg.lines()[1];
}

// Curves and initial conditions by their tables: SFA / SFO 0 stand for 1; a point card is named
// by its curve and read in 20 columns in either format; the first nonzero VXRE-VZRE of
// *INITIAL_VELOCITY card 3 is the one warning.
TEST(KeywordCards, CurvesAndInitialVelocitiesByTheirTables) {
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read curve = read(deck(head + "*DEFINE_CURVE\n" + card({"4", "", "0.0", "2.0", "1.0"}) + card({"0.0", "1.0"}, 20) +
                               card({"1.0", "3.0"}, 20) + "*LOAD_NODE_POINT\n" + card({"1", "1", "4"})));
  ASSERT_TRUE(curve.ok) << curve.lines().front();
  ASSERT_EQ(curve.m.load_curves.size(), 1u);
  EXPECT_EQ(curve.m.load_curves[0].t, (std::vector<double>{1.0, 2.0})) << "A x SFA (0: 1) + OFFA";
  EXPECT_EQ(curve.m.load_curves[0].f, (std::vector<double>{2.0, 6.0})) << "O x SFO";
  const Read bad = read(deck(head + "*DEFINE_CURVE\n" + card({"4"}) + card({"1.0", "0.0"}, 20) + card({"0.5", "x"}, 20) +
                             "*LOAD_NODE_POINT\n" + card({"1", "1", "4"})));
  ASSERT_EQ(bad.lines().size(), 2u);
  EXPECT_EQ(bad.lines()[0], "deck.k:7: error 1002: *DEFINE_CURVE curve 4 point, field \"O\" (cols 21-40): not a real number [found \"x\"]");
  EXPECT_NE(bad.lines()[1].find("error 1217: *DEFINE_CURVE curve 4 point, field \"A\" (cols 1-20)"), std::string::npos) << bad.lines()[1];
  const Read vel = read(deck(head + "*SET_NODE_LIST\n" + card({"1"}) + card({"1", "2"}) + "*INITIAL_VELOCITY\n" + card({"0", "1"}) +
                             card({"5.0"}) + card({"1.0", "", "", "", "2.0", "3.0"})));
  ASSERT_EQ(vel.lines().size(), 1u);
  EXPECT_NE(vel.lines()[0].find("warning 2006: *INITIAL_VELOCITY card 3, field \"VXRE/VYRE/VZRE\" (cols 41-50)"), std::string::npos)
      << vel.lines()[0];
}

// Nodes and elements by their tables: *NODE's columns 8 16 16 16 8 8 (10 for the ids in I10
// format, 20 in long format) in the reader and in messages; a bad element id is reported once
// the element's node card is read (after the node card's own messages), and the element's
// messages name it; the plain cards the fast path reads give the same model as the same cards
// in comma format (read by the table).
TEST(KeywordCards, NodesAndElementsByTheirTables) {
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const KeywordCardLayout& node = find_keyword_spec("NODE")->card("");
  EXPECT_EQ(node.columns(false, false), (std::vector<int>{8, 16, 16, 16, 8, 8}));
  EXPECT_EQ(node.columns(false, true), (std::vector<int>{10, 16, 16, 16, 10, 10}));
  EXPECT_EQ(node.columns(true, true), std::vector<int>(6, 20));

  // I10: a ten-digit node id, and its TC in columns 59-68
  const Read i10 = read(deck(head + "*NODE %\n1234567890             0.0             0.0             0.0         9\n"));
  ASSERT_EQ(i10.lines().size(), 1u) << i10.lines().front();
  EXPECT_EQ(i10.lines()[0], "deck.k:5: error 1216: *NODE node 1234567890, field \"TC\" (cols 59-68): boundary-condition code must be 0-7 [found \"9\"]");

  // two-line solid with a bad id: the node card's message first, then EID
  const Read solid = read(deck(head + "*ELEMENT_SOLID\n" + card({"-4", "1"}, 8) + card({"1", "x", "3", "4", "5", "6", "7", "8"}, 8)));
  ASSERT_GE(solid.lines().size(), 2u);
  EXPECT_EQ(solid.lines()[0], "deck.k:6: error 1001: *ELEMENT_SOLID element -4 node card, field \"N2\" (cols 9-16): not an integer [found \"x\"]");
  EXPECT_EQ(solid.lines()[1], "deck.k:5: error 1201: *ELEMENT_SOLID element -4, field \"EID\" (cols 1-8): number outside the allowed range: element ids must be positive [found \"-4\"]");

  // shells: N5 refused, THIC2 negative on the thickness card (16 columns)
  const std::string shell_part = "*PART\nshell\n         2         2         1\n*SECTION_SHELL\n         2         2\n       0.1\n";
  const Read shell = read(deck(head + shell_part + "*ELEMENT_SHELL_THICKNESS\n" + card({"5", "2", "1", "2", "3", "4", "9"}, 8) +
                               card({"0.1", "-0.1"}, 16)));
  ASSERT_GE(shell.lines().size(), 2u);
  EXPECT_EQ(shell.lines()[0], "deck.k:11: error 1102: *ELEMENT_SHELL_THICKNESS element 5, field \"N5\" (cols 49-56): feature not supported by IMPACT-3D: 8-node shells [found \"9\"]");
  EXPECT_EQ(shell.lines()[1], "deck.k:12: error 1241: *ELEMENT_SHELL_THICKNESS element 5 thickness card, field \"THIC2\" (cols 17-32): shell thickness must be positive [found \"-0.1\"]");

  // the fast path (plain cards) and the table (comma format) read the same model
  const std::string fixed = head + shell_part + "*ELEMENT_SHELL\n" + card({"7", "2", "2", "3", "7", "6"}, 8) + card({"8", "2", "1", "2", "6"}, 8);
  const std::string comma = head + shell_part + "*ELEMENT_SHELL\n7,2,2,3,7,6\n8,2,1,2,6\n";
  const Read a = read(deck(fixed)), b = read(deck(comma));
  ASSERT_TRUE(a.ok && b.ok) << (a.ok ? b.lines().front() : a.lines().front());
  ASSERT_EQ(a.m.shell_nodes.size(), 2u);
  EXPECT_EQ(a.m.shell_nodes, b.m.shell_nodes);
  EXPECT_EQ(a.m.shell_nodes[1][3], a.m.shell_nodes[1][2]);  // a triangle: N4 is N3
  EXPECT_EQ(a.m.x, b.m.x);
}

// The *MAT_ and *EOS_ tables are made from the material and EOS tables (material_types.h,
// material/eos.h): every type's keywords and every form's keyword have one, card 1 begins with
// the id (and RO), and each parameter is a field at its card and column; a material's
// parameter checks come once its cards are read, in the type's order.
TEST(KeywordCards, MaterialCardsFromTheMaterialTable) {
  for (const MaterialType* t : material_types()) {
    for (const char* k : t->keywords) {
      const KeywordSpec* s = find_keyword_spec(k);
      ASSERT_NE(s, nullptr) << k;
      EXPECT_EQ(s->family, KeywordFamily::materials) << k;
      ASSERT_EQ(s->cards.size(), std::size_t(t->keyword_cards)) << k;
      EXPECT_STREQ(s->cards[0].fields[0].name, "MID");
      EXPECT_STREQ(s->cards[0].fields[1].name, "RO");
      for (const MaterialParam& p : t->params) {
        if (p.kcard < 0) continue;
        bool found = false;
        for (const KeywordField& f : s->cards[std::size_t(p.kcard)].fields) found = found || (f.index == p.kfield && std::string(f.name) == p.key);
        EXPECT_TRUE(found) << k << " " << p.key;
        EXPECT_FALSE(p.kcard == 0 && p.kfield < 2) << k << " " << p.key;
      }
    }
  }
  for (const EosForm* f : eos_forms()) {
    const KeywordSpec* s = find_keyword_spec(f->keyword);
    ASSERT_NE(s, nullptr) << f->keyword;
    ASSERT_EQ(s->cards.size(), f->widths.size());
    for (std::size_t c = 0; c < s->cards.size(); ++c) {  // no two fields on one column (checks run as read)
      std::set<int> idx;
      for (const KeywordField& x : s->cards[c].fields) EXPECT_TRUE(idx.insert(x.index).second) << f->keyword << " " << x.name;
    }
  }
  const KeywordCardLayout& elastic = find_keyword_spec("MAT_ELASTIC")->card("card 1");
  EXPECT_EQ(elastic.field("PR").index, 3);
  EXPECT_EQ(elastic.field("PR").checked_after, kByReader);

  // RO as read, the parameters' checks after the card (E before PR), in their columns
  const Read r = read("*KEYWORD\n*CONTROL_TERMINATION\n   1.0E-05\n*MAT_ELASTIC\n" + card({"4", "-1.0", "-2.0", "0.7"}) + "*END\n");
  ASSERT_GE(r.lines().size(), 3u);
  EXPECT_EQ(r.lines()[0].find("deck.k:5: error 1207: *MAT_ELASTIC material 4, field \"RO\" (cols 11-20)"), 0u) << r.lines()[0];
  EXPECT_EQ(r.lines()[1].find("deck.k:5: error 1208: *MAT_ELASTIC material 4, field \"E\" (cols 21-30)"), 0u) << r.lines()[1];
  EXPECT_EQ(r.lines()[2].find("deck.k:5: error 1209: *MAT_ELASTIC material 4, field \"PR\" (cols 31-40)"), 0u) << r.lines()[2];
}

// Coordinate systems and transformations by their tables: a text field (DIR, OPTION) is read
// as text, the rest as numbers; TRANID is checked once the card is named by it; the option
// card's numbers are all named A in messages (the zero rotation axis "A1-A3").
TEST(KeywordCards, SystemsAndTransformationsByTheirTables) {
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  EXPECT_EQ(find_keyword_spec("DEFINE_COORDINATE_NODES")->card("card 1").field("DIR").kind, FieldKind::text);
  const Read r = read(deck(head + "*DEFINE_COORDINATE_NODES\n" + card({"4", "1", "2", "4", "0", "y"}) +
                           "*DEFINE_TRANSFORMATION\n" + card({"-3"}) + card({"ROTATE", "0", "0", "0", "0", "0", "0", "x"}) +
                           card({"translate"})));
  ASSERT_EQ(r.lines().size(), 5u);
  EXPECT_EQ(r.lines()[0].find("deck.k:5: error 1102: *DEFINE_COORDINATE_NODES 4, field \"DIR\" (cols 51-60)"), 0u) << r.lines()[0];
  EXPECT_EQ(r.lines()[1].find("deck.k:7: error 1201: *DEFINE_TRANSFORMATION -3, field \"TRANID\" (cols 1-10)"), 0u) << r.lines()[1];
  EXPECT_EQ(r.lines()[2].find("deck.k:8: error 1002: *DEFINE_TRANSFORMATION transformation -3, field \"A\" (cols 71-80)"), 0u) << r.lines()[2];
  EXPECT_EQ(r.lines()[3].find("deck.k:8: error 1003: *DEFINE_TRANSFORMATION transformation -3, field \"A1-A3\" (cols 11-20)"), 0u) << r.lines()[3];
  EXPECT_EQ(r.lines()[4].find("deck.k:9: error 1006: *DEFINE_TRANSFORMATION transformation -3, field \"OPTION\" (cols 1-10)"), 0u) << r.lines()[4];
}

// Sets by their tables: every form has its cards (the _LIST spelling too); a _GENERAL card
// whose first field is a number continues the option before it (first in the set: error 1006
// naming OPTION); a bad range names BEND, a negative increment INCR, on the card named by the
// set; *SET_SEGMENT's card 1 keeps its name.
TEST(KeywordCards, SetsByTheirTables) {
  for (const char* n : {"SET_NODE", "SET_NODE_LIST", "SET_SOLID_GENERATE_INCREMENT", "SET_SHELL_LIST_ADD", "SET_PART_GENERATE",
                        "SET_SEGMENT_GENERAL", "SET_NODE_GENERAL"})
    EXPECT_NE(find_keyword_spec(n), nullptr) << n;
  EXPECT_EQ(find_keyword_spec("SET_PART_GENERAL"), nullptr);  // refused (error 1102 by the reader)
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read r = read(deck(head + "*SET_NODE_GENERATE_INCREMENT\n" + card({"5"}) + card({"4", "2", "1", "1", "8", "-2"}) +
                           "*SET_SOLID_GENERAL\n" + card({"6"}) + card({"1", "2"}) + "*SET_SEGMENT\n" + card({"7"}) +
                           "*SET_SEGMENT\n" + card({"7"})));
  ASSERT_EQ(r.lines().size(), 4u);
  EXPECT_EQ(r.lines()[0].find("deck.k:6: error 1003: *SET_NODE_GENERATE_INCREMENT set 5, field \"BEND\" (cols 11-20)"), 0u) << r.lines()[0];
  EXPECT_EQ(r.lines()[1].find("deck.k:6: error 1003: *SET_NODE_GENERATE_INCREMENT set 5, field \"INCR\" (cols 51-60)"), 0u) << r.lines()[1];
  EXPECT_EQ(r.lines()[2].find("deck.k:9: error 1006: *SET_SOLID_GENERAL set 6, field \"OPTION\" (cols 1-10)"), 0u) << r.lines()[2];
  EXPECT_EQ(r.lines()[3].find("deck.k:13: error 1200: *SET_SEGMENT card 1, field \"SID\" (cols 1-10)"), 0u) << r.lines()[3];
}

// The contacts: card 2's friction checks after DC is read (a bad FD first, as the reader has
// always reported them), card 3's SFSB against SFSA before its later fields, the _ERODING_ card
// required (the contact is dropped without it), and the keyword's side types.
TEST(KeywordCards, ContactCardsByTheirTables) {
  for (const char* n : {"CONTACT_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_SINGLE_SURFACE", "CONTACT_ERODING_NODES_TO_SURFACE",
                        "CONTACT_FORCE_TRANSDUCER_PENALTY"})
    EXPECT_NE(find_keyword_spec(n), nullptr) << n;
  EXPECT_EQ(find_keyword_spec("CONTACT_TIED_SHELL_EDGE_TO_SURFACE_BEAM_OFFSET"), nullptr);
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read r = read(deck(head + "*CONTACT_SURFACE_TO_SURFACE\n" + card({"1", "1", "3", "4"}) + card({"-1.0", "x", "-2.0"}) +
                           card({"0.0", "2.0", "y"}) + "*CONTACT_ERODING_SINGLE_SURFACE\n" + card({"1", "", "3"}) + card({""}) +
                           card({""})));
  const std::vector<std::string> l = r.lines();
  ASSERT_GE(l.size(), 7u);
  EXPECT_EQ(l[0].find("deck.k:5: error 1104: *CONTACT_SURFACE_TO_SURFACE card 1, field \"SURFBTYP\" (cols 31-40)"), 0u) << l[0];
  EXPECT_EQ(l[1].find("deck.k:6: error 1002: *CONTACT_SURFACE_TO_SURFACE card 2, field \"FD\" (cols 11-20)"), 0u) << l[1];
  EXPECT_EQ(l[2].find("deck.k:6: error 1219: *CONTACT_SURFACE_TO_SURFACE card 2, field \"FS\" (cols 1-10)"), 0u) << l[2];
  EXPECT_EQ(l[3].find("deck.k:6: error 1003: *CONTACT_SURFACE_TO_SURFACE card 2, field \"DC\" (cols 21-30)"), 0u) << l[3];
  EXPECT_EQ(l[4].find("deck.k:7: warning 2006: *CONTACT_SURFACE_TO_SURFACE card 3, field \"SFSB\" (cols 11-20)"), 0u) << l[4];
  EXPECT_EQ(l[5].find("deck.k:7: error 1002: *CONTACT_SURFACE_TO_SURFACE card 3, field \"SAST/SBST/SFSAT/SFSBT/FSF/VSF\" (cols 21-30)"), 0u) << l[5];
  EXPECT_EQ(l[6].find("deck.k:8: error 1316: *CONTACT_ERODING_SINGLE_SURFACE"), 0u) << l[6];
}

// Planar walls and spot welds: card 2's WVEL (as read) before the normal's length (named
// XT-ZH) and FRIC; a moving wall's MASS once V0 is read; a weld's SN and SS before N and M.
TEST(KeywordCards, WallAndWeldCardsByTheirTables) {
  for (const char* n : {"RIGIDWALL_PLANAR", "CONSTRAINED_SPOTWELD", "CONSTRAINED_GENERALIZED_WELD_SPOT"})
    EXPECT_NE(find_keyword_spec(n), nullptr) << n;
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read r = read(deck(head + "*RIGIDWALL_PLANAR_MOVING\n" + card({"0"}) + card({"1.0", "", "", "1.0", "", "", "2.0", "3.0"}) +
                           card({"-1.0", "x"}) + "*CONSTRAINED_SPOTWELD\n" + card({"1", "2", "5.0", "-1.0", "", "", "y"})));
  const std::vector<std::string> l = r.lines();
  ASSERT_GE(l.size(), 8u);
  EXPECT_EQ(l[0].find("deck.k:6: warning 2006: *RIGIDWALL_PLANAR_MOVING card 2, field \"WVEL\" (cols 71-80)"), 0u) << l[0];
  EXPECT_EQ(l[1].find("deck.k:6: error 1213: *RIGIDWALL_PLANAR_MOVING card 2, field \"XT-ZH\" (cols 1-10)"), 0u) << l[1];
  EXPECT_EQ(l[2].find("deck.k:6: error 1219: *RIGIDWALL_PLANAR_MOVING card 2, field \"FRIC\" (cols 61-70)"), 0u) << l[2];
  EXPECT_EQ(l[3].find("deck.k:7: error 1002: *RIGIDWALL_PLANAR_MOVING card 3, field \"V0\" (cols 11-20)"), 0u) << l[3];
  EXPECT_EQ(l[4].find("deck.k:7: error 1003: *RIGIDWALL_PLANAR_MOVING card 3, field \"MASS\" (cols 1-10)"), 0u) << l[4];
  EXPECT_EQ(l[5].find("deck.k:9: error 1003: *CONSTRAINED_SPOTWELD, field \"SS\" (cols 31-40)"), 0u) << l[5];
  EXPECT_EQ(l[6].find("deck.k:9: error 1003: *CONSTRAINED_SPOTWELD, field \"N\" (cols 41-50)"), 0u) << l[6];
  EXPECT_EQ(l[7].find("deck.k:9: error 1002: *CONSTRAINED_SPOTWELD, field \"TF\" (cols 61-70)"), 0u) << l[7];
}

// Histories, *TITLE and *COMMENT: a history _ID card keeps its columns (10, then the heading)
// in long format; the title is the first card as written (a tab in it is no error); *COMMENT's
// IMPACT-3D lines set what the converter wrote there, any other is error 1312.
TEST(KeywordCards, HistoriesTitleAndCommentByTheirTables) {
  for (const char* n : {"DATABASE_HISTORY_NODE", "DATABASE_HISTORY_SHELL_ID", "DATABASE_HISTORY_SOLID_SET", "TITLE", "COMMENT"})
    EXPECT_NE(find_keyword_spec(n), nullptr) << n;
  EXPECT_TRUE(find_keyword_spec("DATABASE_HISTORY_NODE_ID")->cards.front().fixed);
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read r = read(deck(head + "*TITLE\n  a\ttitle  \n*COMMENT\nimpact-3d viscosity_flag 1\nIMPACT-3D BOGUS 2\n"
                           "*DATABASE_HISTORY_NODE_ID+\n       abc the heading\n"));
  const std::vector<std::string> l = r.lines();
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].find("deck.k:8: error 1312: *COMMENT"), 0u) << l[0];
  EXPECT_EQ(l[1].find("deck.k:10: error 1001: *DATABASE_HISTORY_NODE_ID+, field \"NID\" (cols 1-10)"), 0u) << l[1];
  EXPECT_EQ(r.m.title, "  a\ttitle");
  EXPECT_EQ(r.m.control.viscosity_flag, 1);
}

// The keywords that shape the deck read by their tables too: *INCLUDE_TRANSFORM's cards 2-5
// (each message names its field, IDNOFF rather than the "offset" of old, and a bad field is
// refused once), *PARAMETER's PRMR / VAL pairs and *PARAMETER_EXPRESSION's PRMR by their
// columns (20 in long format); the *KEYWORD options and *CASE's CASEID, words in any columns,
// are named with the word's columns.
TEST(KeywordCards, DeckShapingKeywordsByTheirTables) {
  for (const char* n : {"KEYWORD", "INCLUDE", "INCLUDE_PATH_RELATIVE", "INCLUDE_TRANSFORM", "PARAMETER", "PARAMETER_EXPRESSION", "CASE"})
    EXPECT_EQ(find_keyword_spec(n)->family, KeywordFamily::deck) << n;
  const auto has = [](const std::vector<std::string>& l, const std::string& line) {
    return std::find(l.begin(), l.end(), line) != l.end();
  };
  const std::string head = "*CONTROL_TERMINATION\n   1.0E-05\n";
  const Read x = read(deck(head + "*INCLUDE_TRANSFORM\nnone.k\n" + card({"-5", "abc"}) + card({"0"}) + card({"2.0", "1.0", "-1.0", "0"})));
  const std::vector<std::string> l = x.lines();
  EXPECT_TRUE(has(l, "deck.k:6: error 1001: *INCLUDE_TRANSFORM card 2, field \"IDEOFF\" (cols 11-20): not an integer [found \"abc\"]")) << l[0];
  EXPECT_TRUE(has(l, "deck.k:6: error 1003: *INCLUDE_TRANSFORM card 2, field \"IDNOFF\" (cols 1-10): value out of range: "
                     "id offsets must not be negative [found \"-5\"]")) << l[0];
  EXPECT_TRUE(has(l, "deck.k:8: error 1102: *INCLUDE_TRANSFORM card 4, field \"FCTMAS\" (cols 1-10): feature not supported by IMPACT-3D: "
                     "unit conversion of the included data (mass) [found \"2.0\"]"));
  EXPECT_TRUE(has(l, "deck.k:8: error 1003: *INCLUDE_TRANSFORM card 4, field \"FCTLEN\" (cols 21-30): value out of range: "
                     "must be positive [found \"-1.0\"]"));
  EXPECT_EQ(l.size(), 5u) << "and 1306 for the file: one message a bad field";
  const Read lng = read(deck(head + "*INCLUDE_TRANSFORM +\nnone.k\n" + card({"0", "-1"}, 20)));
  EXPECT_NE(lng.lines()[0].find("card 2, field \"IDEOFF\" (cols 21-40)"), std::string::npos) << lng.lines()[0];

  const Read p = read(deck(head + "*PARAMETER\n" + card({"R A", "1.5", "X B", "2"}) + "*PARAMETER_EXPRESSION +\n" +
                           "C TEXT              1 + 1\n"));
  ASSERT_EQ(p.lines().size(), 2u);
  EXPECT_EQ(p.lines()[0], "deck.k:5: error 1006: *PARAMETER, field \"PRMR\" (cols 21-30): not a valid choice: "
                          "a type letter R, I or C followed by the parameter name [found \"X B\"]");
  EXPECT_EQ(p.lines()[1].find("deck.k:7: error 1006: *PARAMETER_EXPRESSION, field \"PRMR\" (cols 1-20)"), 0u) << p.lines()[1];

  const Read k = read("*KEYWORD 20M NCPU=0 LONG=X\n" + deck(head).substr(9));
  ASSERT_EQ(k.lines().size(), 2u);
  EXPECT_EQ(k.lines()[0], "deck.k:1: error 1312: *KEYWORD, field \"NCPU\" (cols 14-19): keyword option not supported: supported: LONG=Y, "
                          "LONG=S, I10=Y, I10=N, MEMORY=, MEMORY2=, NCPU=n (1 <= |n| <= 1024) and a memory size [found \"NCPU=0\"]");
  EXPECT_NE(k.lines()[1].find("field \"LONG\" (cols 21-26)"), std::string::npos) << k.lines()[1];

  const Read c = read(deck(head + "*CASE\n    1x   job\n"));
  ASSERT_FALSE(c.lines().empty());
  EXPECT_EQ(c.lines()[0], "deck.k:5: error 1001: *CASE, field \"CASEID\" (cols 5-6): not an integer: a positive case id [found \"1x\"]");
}
