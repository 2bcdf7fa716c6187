// DYNA3D fixed-format shell cards (docs/deck-format.md "Shell element cards", "Material sets": element type
// 2 and the shell section card): a keyword shell deck converted to the fixed format and back is
// the same Model and runs to the same bits; a hand-written two-shell deck reads as stated; each
// malformed shell card is a numbered message naming its line, card and columns.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

// A clamped plastic strip of nx x 2 shells (0.5 m x 40 mm, steel), one triangle at the free end
// and a thicker row given by *ELEMENT_SHELL_THICKNESS, x = 0 clamped (translations and
// rotations by an SPC set), every node at vz = 20 m/s.
std::string keyword_strip(int nx) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nshell strip for the fixed format\n*CONTROL_TERMINATION\n 5.000e-04\n"
    << "*DATABASE_BINARY_D3PLOT\n 1.000e-04\n*PART\nstrip\n         1         1         1\n"
    << "*SECTION_SHELL\n         1         2  0.833333         3\n    0.0100\n"
    << "*MAT_PLASTIC_KINEMATIC\n         1    7850.0   2.1e+11       0.3   2.5e+08   2.0e+09       1.0\n*NODE\n";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= nx; ++i) d << I(1 + i + (nx + 1) * j, 8) << E(0.5 * i / nx, 16, 8) << E(0.02 * j, 16, 8) << E(0, 16) << "\n";
  d << "*ELEMENT_SHELL\n";
  for (int i = 0; i < nx; ++i) {
    const int n1 = 1 + i, n2 = 2 + i, n3 = 2 + i + nx + 1, n4 = 1 + i + nx + 1;
    d << I(i + 1, 8) << I(1, 8) << I(n1, 8) << I(n2, 8) << I(n3, 8) << I(i + 1 == nx ? n3 : n4, 8) << "\n";
  }
  d << "*ELEMENT_SHELL_THICKNESS\n";
  for (int i = 0; i < nx; ++i) {
    const int n1 = 1 + i + nx + 1;
    d << I(nx + i + 1, 8) << I(1, 8) << I(n1, 8) << I(n1 + 1, 8) << I(n1 + 1 + nx + 1, 8) << I(n1 + nx + 1, 8) << "\n"
      << E(0.012, 16) << E(0.012, 16) << E(0.011, 16) << E(0.011, 16) << "\n";
  }
  d << "*SET_NODE_LIST\n         1\n" << I(1, 10) << I(nx + 2, 10) << I(2 * nx + 3, 10) << "\n"
    << "*BOUNDARY_SPC_SET\n         1         0         1         1         1         1         1         1\n"
    << "*BOUNDARY_SPC_NODE\n" << I(nx + 1, 10) << "         0         0         1         0         1         0         1\n"
    << "*INITIAL_VELOCITY\n         0\n       0.0       0.0      20.0\n*END\n";
  return d.str();
}

std::string diff_text(const Model& a, const Model& b) {
  std::string all;
  for (const auto& s : model_differences(a, b, 50)) all += s + "\n";
  return all;
}

// A hand-written large-format deck: two quadrilateral shells of material 1 (elastic, element
// type 2), 6 nodes, nodes 1 and 4 clamped with rotational code 7.
struct TwoShellDeck {
  std::vector<std::string> lines;
  TwoShellDeck() {
    auto pad = [](std::string s, std::size_t n) { s.resize(std::max(s.size(), n), ' '); return s; };
    lines.push_back(pad("two shells", 72) + "88 large");
    lines.push_back(I(1, 5) + I(6, 10) + I(0, 10) + I(0, 10) + I(2, 10));            // card 2: NUMELS cols 36-45
    lines.push_back("    0    0    0    0    0  100    0    0    0");
    lines.push_back("         0    0    0    0    0e20.0    0");
    lines.push_back("    0    0    0    0    0    0    1    0");
    lines.push_back("  1.0e-04");
    lines.push_back("");
    lines.push_back("");
    lines.push_back("");
    lines.push_back(pad(I(1, 5) + I(1, 5) + E(7850) + I(0, 5) + I(4, 5) + E(0.1) + I(1, 5) + E(1.5) + E(0.06), 65) + I(2, 5));  // line 10
    lines.push_back("steel plate");
    lines.push_back(E(2.1e11));
    lines.push_back(E(0.3));
    for (int k = 0; k < 4; ++k) lines.push_back("");
    lines.push_back(E(5.0 / 6) + I(3, 10) + I(0, 10) + E(0.004) + E(0.004) + E(0.004) + E(0.004));  // line 18: section
    const double xy[6][2] = {{0, 0}, {0.1, 0}, {0.2, 0}, {0, 0.1}, {0.1, 0.1}, {0.2, 0.1}};
    for (int n = 0; n < 6; ++n)
      lines.push_back(I(n + 1, 8) + I(n % 3 == 0 ? 7 : 0, 5) + E(xy[n][0], 20) + E(xy[n][1], 20) + E(0, 20) + I(n % 3 == 0 ? 7 : 0, 5));
    lines.push_back(I(1, 8) + I(1, 5) + I(1, 8) + I(2, 8) + I(5, 8) + I(4, 8));  // line 25
    lines.push_back("");                                                          // line 26: section thickness
    lines.push_back(I(2, 8) + I(1, 5) + I(2, 8) + I(3, 8) + I(6, 8) + I(5, 8));  // line 27
    lines.push_back(E(0.005) + E(0.005) + E(0.006) + E(0.006));                  // line 28
    lines.push_back(I(0, 8) + E(0) + E(0) + E(1.0));                             // initial velocity
  }
  std::string text() const {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }
};

// Reads `deck` expecting exactly the message `id` on `line` naming `cols` (e.g. "cols 9-13").
void expect_message(const std::string& deck, int id, int line, const std::string& cols, const std::string& what) {
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_string(deck, m, d)) << what;
  EXPECT_GE(d.count(id), 1) << what << "\n" << all_messages(d);
  bool found = false;
  for (const auto& x : d.all())
    if (x.id == id) {
      const std::string r = render(x);
      found = found || (x.where.line == line && r.find(cols) != std::string::npos);
    }
  EXPECT_TRUE(found) << what << ": expected " << id << " on line " << line << " naming " << cols << "\n" << all_messages(d);
}

}  // namespace

TEST(ShellCards, KeywordStripConvertedToFixedFormatAndBackIsTheSameModel) {
  Model k;
  Diagnostics dk;
  ASSERT_TRUE(read_any(keyword_strip(10), k, dk, "strip.k")) << all_messages(dk);
  ASSERT_EQ(k.num_shells(), 20);
  std::ostringstream fixed;
  std::vector<std::string> notes;
  write_fixed_deck(fixed, k, &notes);
  for (const auto& n : notes) EXPECT_EQ(n.find("does not fit"), std::string::npos) << n;
  Model f;
  Diagnostics df;
  ASSERT_TRUE(read_any(fixed.str(), f, df, "strip.dyn")) << all_messages(df) << fixed.str();
  EXPECT_FALSE(f.keyword_deck);
  EXPECT_EQ(diff_text(k, f), "");
  EXPECT_EQ(f.shell_nodes[9][2], f.shell_nodes[9][3]);                 // the triangle
  EXPECT_DOUBLE_EQ(f.shell_thickness[12][2], 0.011);                   // a thickness card
  EXPECT_EQ(f.rot_bc[0], 7);                                           // clamped: all rotations
  EXPECT_EQ(f.rot_bc[10], 5);                                          // rx, rz (code 6 z+x)
  EXPECT_EQ(f.materials[0].shell_section.nip, 3);
  // and back to a keyword deck
  std::ostringstream kw;
  write_keyword_deck(kw, f, &notes);
  Model k2;
  Diagnostics dk2;
  ASSERT_TRUE(read_any(kw.str(), k2, dk2, "strip2.k")) << all_messages(dk2);
  EXPECT_EQ(diff_text(f, k2), "");
}

TEST(ShellCards, KeywordAndFixedFormatStripRunToTheSameBits) {
  Model k;
  Diagnostics dk;
  ASSERT_TRUE(read_any(keyword_strip(10), k, dk, "strip.k")) << all_messages(dk);
  std::ostringstream fixed;
  write_fixed_deck(fixed, k, nullptr);
  Model f;
  Diagnostics df;
  ASSERT_TRUE(read_any(fixed.str(), f, df, "strip.dyn")) << all_messages(df);
  Engine a(k), b(f);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  StepStatus sa = StepStatus::ok, sb = StepStatus::ok;
  while (sa == StepStatus::ok) sa = a.step();
  while (sb == StepStatus::ok) sb = b.step();
  ASSERT_EQ(sa, StepStatus::finished);
  ASSERT_EQ(sb, StepStatus::finished);
  const State &x = a.state(), &y = b.state();
  EXPECT_EQ(x.cycle, y.cycle);
  EXPECT_GT(x.cycle, 100);
  EXPECT_EQ(x.x, y.x);
  EXPECT_EQ(x.z, y.z);
  EXPECT_EQ(x.vz, y.vz);
  EXPECT_EQ(x.shells.sig, y.shells.sig);
  EXPECT_EQ(x.shells.eps_p, y.shells.eps_p);
  EXPECT_EQ(x.shells.wy, y.shells.wy);
  EXPECT_EQ(x.internal, y.internal);
  EXPECT_GT(*std::max_element(x.shells.eps_p.begin(), x.shells.eps_p.end()), 0.0);  // it yielded
  // the clamped rotations stayed zero in both
  EXPECT_EQ(y.shells.wy[std::size_t(y.shells.node_rot[0])], 0.0);
}

TEST(ShellCards, HandWrittenTwoShellDeckReadsAsStated) {
  TwoShellDeck deck;
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(deck.text(), m, d)) << all_messages(d) << deck.text();
  ASSERT_EQ(m.num_shells(), 2);
  EXPECT_EQ(m.num_hexes(), 0);
  EXPECT_TRUE(m.materials[0].shell);
  EXPECT_EQ(m.materials[0].shell_section.nip, 3);
  EXPECT_DOUBLE_EQ(m.materials[0].shell_section.shrf, 0.83333);  // as written (%.4e)
  EXPECT_EQ(m.materials[0].hourglass_type, 4);
  EXPECT_DOUBLE_EQ(m.shell_thickness[0][1], 0.004);  // blank thickness card: the section's
  EXPECT_DOUBLE_EQ(m.shell_thickness[1][2], 0.006);
  EXPECT_EQ((std::array<int, 4>{1, 2, 5, 4}), m.shell_nodes[1]);
  EXPECT_EQ(m.rot_bc[3], 7);
  EXPECT_EQ(m.rot_bc[1], 0);
  EXPECT_EQ(d.count(2005), 0);
}

TEST(ShellCards, MalformedShellCardsNameLineCardAndColumns) {
  auto with = [](int line, const std::string& text) {
    TwoShellDeck d;
    d.lines[std::size_t(line - 1)] = text;
    return d.text();
  };
  TwoShellDeck base;
  // shell card: node n3 beyond NUMNP (cols 30-37), material 2 undefined (cols 9-13)
  expect_message(with(25, I(1, 8) + I(1, 5) + I(1, 8) + I(2, 8) + I(9, 8) + I(4, 8)), 1202, 25, "cols 30-37", "node n3");
  expect_message(with(25, I(1, 8) + I(2, 5) + I(1, 8) + I(2, 8) + I(5, 8) + I(4, 8)), 1203, 25, "cols 9-13", "material");
  expect_message(with(25, I(1, 8) + I(1, 5) + I(1, 8) + I(1, 8) + I(5, 8) + I(4, 8)), 1222, 25, "cols 14-45", "repeated node");
  expect_message(with(25, I(3, 8) + I(1, 5) + I(1, 8) + I(2, 8) + I(5, 8) + I(4, 8)), 1201, 25, "cols 1-8", "shell number");
  expect_message(with(28, E(0.005) + E(-0.005) + E(0.006) + E(0.006)), 1241, 28, "cols 11-20", "negative thickness");
  expect_message(with(28, E(0.005) + "   abc    "), 1002, 28, "cols 11-20", "thickness not a number");
  // section card: NIP 12, SHRF 1.5, QR 1, negative T1
  expect_message(with(18, E(5.0 / 6) + I(12, 10) + I(0, 10) + E(0.004)), 1102, 18, "cols 11-20", "NIP");
  // NIP far beyond an int (a fuzz finding: it was converted before it was checked)
  expect_message(with(18, E(5.0 / 6) + E(5.8193e9) + I(0, 10) + E(0.004)), 1003, 18, "cols 11-20", "NIP 5.8e9");
  expect_message(with(18, E(1.5) + I(3, 10) + I(0, 10) + E(0.004)), 1003, 18, "cols 1-10", "SHRF");
  expect_message(with(18, E(0.8) + I(3, 10) + I(1, 10) + E(0.004)), 1102, 18, "cols 21-30", "QR");
  expect_message(with(18, E(0.8) + I(3, 10) + I(0, 10) + E(-0.004)), 1241, 18, "cols 31-40", "T1");
  // material card 1: a type with no shell form (18 power law), formulation 1 (Hughes-Liu)
  std::string mat = base.lines[9];
  std::string m98 = mat;  // (type 98 has no shell form; type 18 has had one since issue 25)
  m98.replace(5, 5, I(98, 5));
  expect_message(with(10, m98), 1103, 10, "cols 6-10", "type 98 shell");
  std::string ef = mat;
  ef.resize(80, ' ');
  ef.replace(75, 5, I(1, 5));
  expect_message(with(10, ef), 1102, 10, "cols 76-80", "formulation");
  // a solid material (element type 0) named by a shell
  std::string solid = mat;
  solid.replace(65, 5, I(0, 5));
  {
    TwoShellDeck d;
    d.lines[9] = solid;
    d.lines.erase(d.lines.begin() + 17);  // no section card for a solid material
    expect_message(d.text(), 1203, 24, "cols 9-13", "solid material");
  }
  // the deck ends before the last thickness card
  {
    TwoShellDeck d;
    d.lines.resize(27);
    Model m;
    Diagnostics dg;
    EXPECT_FALSE(read_string(d.text(), m, dg));
    EXPECT_EQ(dg.count(1004), 1) << all_messages(dg);
    EXPECT_NE(all_messages(dg).find("shell element 2 thickness card"), std::string::npos) << all_messages(dg);
  }
  // NUMELH 0 and NUMELS 0: no element
  expect_message(with(2, I(1, 5) + I(6, 10) + I(0, 10) + I(0, 10) + I(0, 10)), 1003, 2, "cols 16-25", "no elements");
  // a rotational code on a node no shell uses: warning 2005, the code dropped
  {
    TwoShellDeck d;
    d.lines[1] = I(1, 5) + I(7, 10) + I(0, 10) + I(0, 10) + I(2, 10);
    d.lines.insert(d.lines.begin() + 24, I(7, 8) + I(0, 5) + E(1, 20) + E(1, 20) + E(1, 20) + I(3, 5));
    Model m;
    Diagnostics dg;
    read_string(d.text(), m, dg);
    EXPECT_EQ(dg.count(2005), 1) << all_messages(dg);
    ASSERT_EQ(m.rot_bc.size(), 7u);
    EXPECT_EQ(m.rot_bc[6], 0);
  }
}

// The converter refuses what the fixed shell cards cannot hold (exit 2, no file).
TEST(ShellCards, FixedFormatRefusesInitialRotationalVelocities) {
  std::string deck = keyword_strip(4);
  deck.replace(deck.find("*END"), 4,
               "*INITIAL_VELOCITY_NODE\n       3       0.0       0.0       0.5       0.0       2.5       0.0\n*END");
  Model k;
  Diagnostics dk;
  ASSERT_TRUE(read_any(deck, k, dk, "strip.k")) << all_messages(dk);
  std::ostringstream log;
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/shell_fixed_refused_omega.dyn";
  EXPECT_EQ(write_converted_decks(k, "", path, log), exit_code::input_error);
  EXPECT_NE(log.str().find("initial rotational velocities"), std::string::npos) << log.str();
}
