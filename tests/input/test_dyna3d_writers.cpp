// The DYNA3D fixed format as writers of DYNA3D decks settle it (issue 16; FEMGV's DYNA3D
// interface manual and old mesh tools): material card 1 element type (cols 66-70: 0 solid,
// 1 beam, 2 shell, 3 thick shell), sliding interface types 1-9 by name, and columns the reader
// does not read (cols 76-80 of a small-format node card) that hold something.

#include <gtest/gtest.h>

#include <string>

#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

// A small-format deck of one copper hexahedron; material card 1 element type et (cols 66-70);
// node cards with `tail` in cols 76-80.
std::string small_deck(int et, const std::string& tail = "", const std::string& element_tail = "") {
  std::string s;
  s += "small-format deck, 1980s style\n";
  s += "    1    8    1    0    0    0\n";
  s += "    0    0    0    0    0  100    0    0    0\n";
  s += "         0    0    0    0    0e20.0    0\n";
  s += "    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0\n";
  s += "1.0000e-05\n";
  s += "    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0\n";
  s += "\n\n";
  std::string mat1 = "    1    18.9300e+03";
  mat1 += std::string(65 - mat1.size(), ' ') + I(et, 5);
  s += mat1 + "\ncopper\n1.1700e+11\n3.5000e-01\n\n\n\n\n";
  if (et == 1) s += " section properties\n 1.000E+00 2.000E+00 0.000E+00\n 1.000E-03 1.000E-03 1.000E-03 1.000E-03\n";
  const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int k = 0; k < 8; ++k) {
    std::string node = I(k + 1, 5) + I(0, 5) + E(c[k][0] * 1e-3, 20, 10) + E(c[k][1] * 1e-3, 20, 10) + E(c[k][2] * 1e-3, 20, 10) + I(0, 5);
    s += node + tail + "\n";
  }
  s += I(1, 5) + I(1, 5);
  for (int n = 1; n <= 8; ++n) s += I(n, 5);
  return s + element_tail + "\n";
}

}  // namespace

TEST(Dyna3dWriters, MaterialElementTypeIsSolidBeamShellOrThickShell) {
  {
    Model m;
    Diagnostics d;
    EXPECT_TRUE(read_string(small_deck(0), m, d)) << all_messages(d);
  }
  // (element type 2, shells: tests/input/test_shell_cards.cpp)
  // a beam material (element type 1) with its section cards reads: a Hughes-Liu beam section
  {
    Model m;
    Diagnostics d;
    EXPECT_TRUE(read_string(small_deck(1), m, d)) << all_messages(d);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_TRUE(m.materials[0].beam);
    EXPECT_DOUBLE_EQ(m.materials[0].beam_section.ts1, 1e-3);
  }
  // a thick shell is refused by its element type
  {
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_string(small_deck(3), m, d));
    ASSERT_EQ(d.count(1102), 1) << all_messages(d);
    EXPECT_EQ(d.error_count(), 1) << all_messages(d);
    const std::string msg = all_messages(d);
    EXPECT_NE(msg.find("thick shells (element type 3)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("cols 66-70"), std::string::npos) << msg;
  }
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_string(small_deck(4), m, d));
  EXPECT_EQ(d.count(1006), 1) << all_messages(d);
}

TEST(Dyna3dWriters, TextInUnreadColumnsIsOneWarningNamingThem) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(small_deck(0, "    7"), m, d)) << all_messages(d);
  ASSERT_EQ(d.count(2020), 1) << all_messages(d);
  const std::string msg = all_messages(d);
  EXPECT_NE(msg.find("8 node card(s)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("columns 76-80"), std::string::npos) << msg;
  EXPECT_DOUBLE_EQ(m.x[1], 1e-3);  // the cards still read
  Model clean;
  Diagnostics dc;
  ASSERT_TRUE(read_string(small_deck(0, "     "), clean, dc));
  EXPECT_EQ(dc.count(2020), 0);
  // a small-format solid card reads 1-50 (id, material, 8 nodes I5)
  Model e;
  Diagnostics de;
  ASSERT_TRUE(read_string(small_deck(0, "", "    0    1"), e, de)) << all_messages(de);
  ASSERT_EQ(de.count(2020), 1) << all_messages(de);
  EXPECT_NE(all_messages(de).find("columns 51-80, after node n8"), std::string::npos) << all_messages(de);
}

TEST(Dyna3dWriters, SlidingInterfaceTypesAreRefusedByName) {
  const std::string deck = read_text(source_path("decks/two_bars.dyn"));
  const std::string card = "       4       4    30.0000e+00";
  ASSERT_NE(deck.find(card), std::string::npos);
  const char* names[] = {"", "1 sliding only", "2 tied", "", "4 single surface", "5 nodes to surface", "6 nodes tied to surface",
                         "7 shell edge tied to surface", "8 spot weld", "9 tiebreak"};
  for (int type = 1; type <= 9; ++type) {
    if (type == 3 || type == 4) continue;  // (4: single surface, read)
    std::string s = deck;
    s.replace(s.find(card), card.size(), "       4       4" + I(type, 5) + "0.0000e+00");
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_string(s, m, d));
    ASSERT_EQ(d.count(1104), 1) << type << all_messages(d);
    EXPECT_NE(all_messages(d).find(std::string("type ") + names[type]), std::string::npos) << all_messages(d);
  }
  {  // type 4 (single surface) takes its NSS segments only: NMS must be 0
    std::string s = deck;
    s.replace(s.find(card), card.size(), "       4       4    40.0000e+00");
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_string(s, m, d));
    EXPECT_EQ(d.count(1003), 1) << all_messages(d);
    EXPECT_NE(all_messages(d).find("single-surface"), std::string::npos) << all_messages(d);
  }
  {  // type 4 with NSS = the 8 segment cards and NMS = 0: one surface of 8 segments, one pass
    std::string s = deck;
    s.replace(s.find(card), card.size(), "       8       0    40.0000e+00");
    Model m;
    Diagnostics d;
    ASSERT_TRUE(read_string(s, m, d)) << all_messages(d);
    ASSERT_EQ(m.interfaces.size(), 1u);
    EXPECT_EQ(m.interfaces[0].type, 4);
    EXPECT_EQ(m.interfaces[0].slave.size(), 8u);
    EXPECT_TRUE(m.interfaces[0].master.empty());
    EXPECT_FALSE(m.interfaces[0].symmetric);
  }
  std::string s = deck;
  s.replace(s.find(card), card.size(), "       4       4  120.0000e+00");
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_string(s, m, d));
  EXPECT_EQ(d.count(1006), 1) << all_messages(d);
}
