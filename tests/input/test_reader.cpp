// The DYNA3D fixed-format reader and the model checks on valid decks: every shipped deck, the
// small format, packed material cards, degenerate elements, material values.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "impact3d/element/hexahedron.h"
#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

struct DeckCounts {
  const char* file;
  int nodes, hexes, materials, walls, interfaces, slave, master, init_velocity_cards;
};

const DeckCounts kShipped[] = {
    {"taylor_bar.dyn", 1369, 972, 1, 1, 0, 0, 0, 1},
    {"oblique_rod.dyn", 4818, 3480, 1, 1, 0, 0, 0, 1},
    {"crossed_cylinders.dyn", 722, 432, 2, 0, 1, 72, 72, 2},
    {"one_hex.dyn", 8, 1, 1, 0, 0, 0, 0, 1},
    {"bar_wall_elastic.dyn", 369, 160, 1, 1, 0, 0, 0, 1},
    {"two_bars.dyn", 738, 320, 2, 0, 1, 4, 4, 2},
    {"column_uniaxial_strain.dyn", 164, 40, 1, 1, 0, 0, 0, 1},
};

double tet_volume(const double x[4], const double y[4], const double z[4]) {
  double ax = x[1] - x[0], ay = y[1] - y[0], az = z[1] - z[0];
  double bx = x[2] - x[0], by = y[2] - y[0], bz = z[2] - z[0];
  double cx = x[3] - x[0], cy = y[3] - y[0], cz = z[3] - z[0];
  return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
}

double element_volume(const Model& m, int e) {
  double x[8], y[8], z[8];
  for (int j = 0; j < 8; ++j) {
    int n = m.hex_nodes[std::size_t(e)][std::size_t(j)];
    x[j] = m.x[std::size_t(n)];
    y[j] = m.y[std::size_t(n)];
    z[j] = m.z[std::size_t(n)];
  }
  return calc_hex_volume(x, y, z);
}

// A large-format deck with one elastic material, the given nodes and solids, no walls.
std::string deck_with(const std::vector<std::array<double, 3>>& nodes,
                      const std::vector<std::array<int, 8>>& solids) {
  std::string s;
  s += std::string("generated test deck").append(53, ' ') + "88 large\n";
  s += I(1, 5) + I(long(nodes.size()), 10) + I(long(solids.size()), 10) + I(0, 10) + I(0, 10) + I(0, 10) + "\n";
  s += "    0    0    0    0    0  100    0    0    0\n";
  s += "         0    0    0    0    0e20.0    0\n";
  s += "    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0\n";
  s += "1.0000e-05\n";
  s += "    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0\n";
  s += "\n\n";
  s += I(1, 5) + I(1, 5) + E(2700.0) + "\n" + "aluminium\n" + E(70e9) + "\n" + E(0.33) + "\n\n\n\n\n";
  for (std::size_t k = 0; k < nodes.size(); ++k)
    s += I(long(k + 1), 8) + I(0, 5) + E(nodes[k][0], 20, 12) + E(nodes[k][1], 20, 12) + E(nodes[k][2], 20, 12) + "\n";
  for (std::size_t k = 0; k < solids.size(); ++k) {
    s += I(long(k + 1), 8) + I(1, 5);
    for (int n : solids[k]) s += I(n, 8);
    s += "\n";
  }
  return s;
}

}  // namespace

TEST(ShippedDecks, ReadAndCheckWithNoErrorsAndTheExpectedCounts) {
  for (const auto& d : kShipped) {
    SCOPED_TRACE(d.file);
    Model m;
    Diagnostics diag;
    bool ok = read_and_check_deck(source_path(std::string("decks/") + d.file), m, diag);
    EXPECT_TRUE(ok) << all_messages(diag);
    EXPECT_EQ(diag.error_count(), 0) << all_messages(diag);
    EXPECT_EQ(diag.warning_count(), 0) << all_messages(diag);
    EXPECT_TRUE(m.large_format);
    EXPECT_EQ(m.num_nodes(), d.nodes);
    EXPECT_EQ(m.control.numnp, d.nodes);
    EXPECT_EQ(m.num_hexes(), d.hexes);
    EXPECT_EQ(int(m.materials.size()), d.materials);
    EXPECT_EQ(int(m.walls.size()), d.walls);
    EXPECT_EQ(int(m.init_velocities.size()), d.init_velocity_cards);
    ASSERT_EQ(int(m.interfaces.size()), d.interfaces);
    for (const auto& si : m.interfaces) {
      EXPECT_EQ(int(si.slave.size()), d.slave);
      EXPECT_EQ(int(si.master.size()), d.master);
      EXPECT_EQ(si.type, 3);
      EXPECT_EQ(si.slave_line.size(), si.slave.size());
    }
    EXPECT_GT(m.control.end_time, 0);
    EXPECT_EQ(m.hex_line.size(), std::size_t(d.hexes));
    for (int e = 0; e < m.num_hexes(); ++e) {
      EXPECT_GE(m.hex_material[std::size_t(e)], 0);
      EXPECT_GT(m.hex_line[std::size_t(e)], 0);
      for (int n : m.hex_nodes[std::size_t(e)]) ASSERT_TRUE(n >= 0 && n < m.num_nodes());
      EXPECT_GT(element_volume(m, e), 0);
    }
    for (const auto& md : m.materials) {
      EXPECT_GT(md.number, 0);
      EXPECT_GT(md.rho, 0);
      EXPECT_GT(md.E, 0);
    }
    for (int k = 0; k < m.num_nodes(); ++k) ASSERT_TRUE(std::isfinite(m.x[std::size_t(k)]));
  }
}

TEST(ShippedDecks, TaylorBarValues) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_and_check_deck(source_path("decks/taylor_bar.dyn"), m, diag)) << all_messages(diag);
  ASSERT_EQ(m.walls.size(), 1u);
  EXPECT_DOUBLE_EQ(m.walls[0].head[2] - m.walls[0].tail[2] > 0 ? 1.0 : 0.0, 1.0);
  EXPECT_TRUE(m.walls[0].nodes.empty());
  EXPECT_EQ(m.materials[0].type, 3);
  ASSERT_EQ(m.init_velocities.size(), 1u);
  EXPECT_NEAR(std::fabs(m.init_velocities[0].v[2]), 227.0, 1e-9);
}

TEST(TinyDeck, ReadsAndMaterialValuesRoundTrip) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(tiny_deck(), m, diag)) << all_messages(diag);
  EXPECT_EQ(diag.warning_count(), 0) << all_messages(diag);
  EXPECT_EQ(m.title, "tiny: two steel hexes on a wall, SI units");
  EXPECT_EQ(m.num_nodes(), 12);
  EXPECT_EQ(m.num_hexes(), 2);
  ASSERT_EQ(m.materials.size(), 1u);
  const MaterialData& md = m.materials[0];
  EXPECT_EQ(md.number, 1);
  EXPECT_EQ(md.type, 3);
  EXPECT_EQ(md.title, "steel, elastic-plastic");
  EXPECT_DOUBLE_EQ(md.rho, 7850.0);
  EXPECT_DOUBLE_EQ(md.E, 2.1e11);
  EXPECT_DOUBLE_EQ(md.nu, 0.3);
  EXPECT_DOUBLE_EQ(md.sigma_y, 4.0e8);
  EXPECT_DOUBLE_EQ(md.E_tan, 1.0e9);
  EXPECT_DOUBLE_EQ(md.beta, 1.0);
  EXPECT_FALSE(md.packed);
  EXPECT_FALSE(md.initially_elastic);
  // defaults for blank fields
  EXPECT_EQ(md.hourglass_type, 1);
  EXPECT_DOUBLE_EQ(md.hourglass_coef, 0.10);
  EXPECT_EQ(md.bulk_type, 1);
  EXPECT_DOUBLE_EQ(md.q1, 1.5);
  EXPECT_DOUBLE_EQ(md.q2, 0.06);
  EXPECT_EQ(md.line, 13);
  // control defaults
  EXPECT_DOUBLE_EQ(m.control.end_time, 1e-5);
  EXPECT_DOUBLE_EQ(m.control.tssf, 0.9);
  EXPECT_DOUBLE_EQ(m.control.penalty_scale, 0.10);
  EXPECT_EQ(m.control.report_interval, 100);
  // nodes, solids, wall, velocity
  EXPECT_DOUBLE_EQ(m.x[11], 2e-3);
  EXPECT_DOUBLE_EQ(m.y[11], 1e-3);
  EXPECT_DOUBLE_EQ(m.z[11], 1e-3);
  EXPECT_EQ(m.hex_nodes[1], (std::array<int, 8>{1, 2, 5, 4, 7, 8, 11, 10}));
  EXPECT_EQ(m.hex_line[0], 35);
  EXPECT_EQ(m.hex_line[1], 36);
  ASSERT_EQ(m.walls.size(), 1u);
  EXPECT_DOUBLE_EQ(m.walls[0].tail[2], -1e-4);
  EXPECT_DOUBLE_EQ(m.walls[0].head[2], 1.0);
  EXPECT_EQ(m.walls[0].line, 38);
  ASSERT_EQ(m.init_velocities.size(), 1u);
  EXPECT_EQ(m.init_velocities[0].first, 0);
  EXPECT_DOUBLE_EQ(m.init_velocities[0].v[2], -100.0);
  EXPECT_NEAR(element_volume(m, 0), 1e-9, 1e-21);
}

TEST(TinyDeck, CrLfAndTheSameDeck) {
  std::string text = tiny_deck(), crlf;
  for (char c : text) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(crlf, m, diag)) << all_messages(diag);
  EXPECT_EQ(m.num_hexes(), 2);
  EXPECT_DOUBLE_EQ(m.materials[0].E, 2.1e11);
}

TEST(SmallFormat, TitleWithoutLargeReadsI5Ids) {
  std::string s;
  s += "small-format deck, 1980s style\n";
  // card 2 in small format: NMMAT, NUMNP, NUMELH, beams, shells, thick shells as I5
  s += "    1    8    1    0    0    0\n";
  s += "    0    0    0    0    0  100    0    0    0\n";
  s += "         0    0    0    0    0e20.0    0\n";
  s += "    0    0    0    0    1    0    1    0    0    0    0    0    0    0    0    0\n";
  s += "1.0000e-05                                                                    \n";
  s += "    0    0    0    0    0    0    0    0    0    0    0    0    0    0    0\n";
  s += "\n\n";
  s += "    1    18.9300e+03\ncopper\n1.1700e+11\n3.5000e-01\n\n\n\n\n";
  const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int k = 0; k < 8; ++k) {
    int bc = k < 4 ? 3 : 0;
    s += I(k + 1, 5) + I(bc, 5) + E(c[k][0] * 1e-3, 20, 10) + E(c[k][1] * 1e-3, 20, 10) + E(c[k][2] * 1e-3, 20, 10) + "\n";
  }
  s += I(1, 5) + I(1, 5);
  for (int n = 1; n <= 8; ++n) s += I(n, 5);
  s += "\n";
  // stonewall (I5 node list in small format: 16 per card) and the initial velocity
  s += I(2, 5) + I(0, 5) + E(0) + E(0) + E(-1e-4, 10, 3) + E(0) + E(0) + E(1) + E(0) + "\n";
  s += I(1, 5) + I(2, 5) + "\n";
  s += I(0, 8) + E(0) + E(0) + E(-10.0) + "\n";
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(s, m, diag)) << s << all_messages(diag);
  EXPECT_FALSE(m.large_format);
  EXPECT_EQ(m.num_nodes(), 8);
  EXPECT_EQ(m.num_hexes(), 1);
  EXPECT_EQ(m.bc[0], 3);
  EXPECT_DOUBLE_EQ(m.x[6], 1e-3);
  EXPECT_DOUBLE_EQ(m.z[6], 1e-3);
  EXPECT_EQ(m.hex_nodes[0], (std::array<int, 8>{0, 1, 2, 3, 4, 5, 6, 7}));
  ASSERT_EQ(m.walls.size(), 1u);
  EXPECT_EQ(m.walls[0].nodes, (std::vector<int>{0, 1}));
  EXPECT_NEAR(element_volume(m, 0), 1e-9, 1e-21);
}

TEST(Materials, PackedCardsGiveWarning2001AndTheRightValues) {
  std::string text = tiny_deck();
  // material cards 3-8 (lines 15-20): everything on card 3, cards 4-8 blank
  std::vector<std::string> lines;
  for (std::size_t p = 0, q; p < text.size(); p = q + 1) {
    q = text.find('\n', p);
    lines.push_back(text.substr(p, q - p));
  }
  lines[14] = E(2.0e11) + E(0.29) + E(3.5e8) + E(2.0e9) + E(0.5);
  for (int k = 15; k < 20; ++k) lines[std::size_t(k)] = "";
  std::string packed;
  for (const auto& l : lines) packed += l + "\n";
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(packed, m, diag)) << all_messages(diag);
  ASSERT_TRUE(diag.has(2001)) << all_messages(diag);
  EXPECT_EQ(diag.warning_count(), 1);
  EXPECT_EQ(diag.all()[0].where.line, 15);
  const MaterialData& md = m.materials[0];
  EXPECT_TRUE(md.packed);
  EXPECT_DOUBLE_EQ(md.E, 2.0e11);
  EXPECT_DOUBLE_EQ(md.nu, 0.29);
  EXPECT_DOUBLE_EQ(md.sigma_y, 3.5e8);
  EXPECT_DOUBLE_EQ(md.E_tan, 2.0e9);
  EXPECT_DOUBLE_EQ(md.beta, 0.5);

  // a bad nu in the packed card points at columns 11-20 of card 3
  lines[14] = E(2.0e11) + E(0.6) + E(3.5e8) + E(2.0e9) + E(0.5);
  packed.clear();
  for (const auto& l : lines) packed += l + "\n";
  Model m2;
  Diagnostics d2;
  EXPECT_FALSE(read_string(packed, m2, d2));
  ASSERT_TRUE(d2.has(1209));
  for (const auto& d : d2.all())
    if (d.id == 1209) {
      EXPECT_EQ(d.where.line, 15);
      EXPECT_EQ(d.where.col_first, 11);
      EXPECT_EQ(d.where.col_last, 20);
    }
}

TEST(Materials, CrossedCylindersValues) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_and_check_deck(source_path("decks/crossed_cylinders.dyn"), m, diag));
  for (const auto& md : m.materials) {
    EXPECT_EQ(md.type, 3);
    EXPECT_DOUBLE_EQ(md.rho, 8930.0);
    EXPECT_DOUBLE_EQ(md.hourglass_coef, 0.02);
    EXPECT_DOUBLE_EQ(md.q1, 1.2);
    EXPECT_DOUBLE_EQ(md.q2, 0.06);
    EXPECT_DOUBLE_EQ(md.E, 1.17e11);
    EXPECT_DOUBLE_EQ(md.nu, 0.35);
    EXPECT_DOUBLE_EQ(md.sigma_y, 4.0e8);
    EXPECT_DOUBLE_EQ(md.E_tan, 1.0e8);
    EXPECT_DOUBLE_EQ(md.beta, 1.0);
    EXPECT_TRUE(md.initially_elastic);
  }
}

namespace {
const std::vector<std::array<double, 3>> kTetNodes = {
    {0.0, 0.0, 0.0}, {2.0e-3, 0.1e-3, 0.0}, {0.3e-3, 1.5e-3, 0.2e-3}, {0.4e-3, 0.5e-3, 1.7e-3}};
double exact_tet() {
  double x[4], y[4], z[4];
  for (int k = 0; k < 4; ++k) {
    x[k] = kTetNodes[std::size_t(k)][0];
    y[k] = kTetNodes[std::size_t(k)][1];
    z[k] = kTetNodes[std::size_t(k)][2];
  }
  return tet_volume(x, y, z);
}
}  // namespace

TEST(DegenerateElements, TetrahedronDyna3dForm) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(deck_with(kTetNodes, {{1, 2, 3, 3, 4, 4, 4, 4}}), m, diag)) << all_messages(diag);
  EXPECT_EQ(m.hex_nodes[0], (std::array<int, 8>{0, 1, 2, 2, 3, 3, 3, 3}));
  EXPECT_GT(exact_tet(), 0);
  EXPECT_NEAR(element_volume(m, 0), exact_tet(), 1e-12 * exact_tet());
}

TEST(DegenerateElements, TetrahedronNike3dFormIsRemapped) {
  // n1,n2,n3,n4,n4,n4,n4,n4: as a trilinear hexahedron this spans half the tetrahedron, so the
  // reader stores it as n1,n2,n3,n3,n4,n4,n4,n4.
  {
    double x[8], y[8], z[8];
    const int raw[8] = {0, 1, 2, 3, 3, 3, 3, 3};
    for (int j = 0; j < 8; ++j) {
      x[j] = kTetNodes[std::size_t(raw[j])][0];
      y[j] = kTetNodes[std::size_t(raw[j])][1];
      z[j] = kTetNodes[std::size_t(raw[j])][2];
    }
    EXPECT_NEAR(calc_hex_volume(x, y, z), 0.5 * exact_tet(), 1e-12 * exact_tet())
        << "the reason for the remap";
  }
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(deck_with(kTetNodes, {{1, 2, 3, 4, 4, 4, 4, 4}}), m, diag)) << all_messages(diag);
  EXPECT_EQ(m.hex_nodes[0], (std::array<int, 8>{0, 1, 2, 2, 3, 3, 3, 3}));
  EXPECT_NEAR(element_volume(m, 0), exact_tet(), 1e-12 * exact_tet());
}

TEST(DegenerateElements, InvertedTetrahedronIsReported) {
  Model m;
  Diagnostics diag;
  EXPECT_FALSE(read_string(deck_with(kTetNodes, {{2, 1, 3, 4, 4, 4, 4, 4}}), m, diag));
  ASSERT_TRUE(diag.has(1206)) << all_messages(diag);
  EXPECT_EQ(diag.all().back().where.card, "solid element 1");
}

TEST(DegenerateElements, Wedges) {
  const std::vector<std::array<double, 3>> nodes = {
      {0, 0, 0}, {1e-3, 0, 0}, {1e-3, 1e-3, 0}, {0, 1e-3, 0}, {0, 0, 1e-3}, {0, 1e-3, 1e-3}};
  // n5 = n6, n7 = n8: the top face collapses to the edge 5-6 over the edge 1-4
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_string(deck_with(nodes, {{1, 2, 3, 4, 5, 5, 6, 6}}), m, diag)) << all_messages(diag);
  EXPECT_EQ(m.hex_nodes[0], (std::array<int, 8>{0, 1, 2, 3, 4, 4, 5, 5}));
  EXPECT_NEAR(element_volume(m, 0), 0.5e-9, 1e-21);
  // n3 = n4, n7 = n8: a wedge with triangular faces 1-2-3 and 5-6-7
  const std::vector<std::array<double, 3>> n2 = {
      {0, 0, 0}, {1e-3, 0, 0}, {0, 1e-3, 0}, {0, 0, 1e-3}, {1e-3, 0, 1e-3}, {0, 1e-3, 1e-3}};
  Model m2;
  Diagnostics d2;
  ASSERT_TRUE(read_string(deck_with(n2, {{1, 2, 3, 3, 4, 5, 6, 6}}), m2, d2)) << all_messages(d2);
  EXPECT_NEAR(element_volume(m2, 0), 0.5e-9, 1e-21);
}

TEST(DegenerateElements, OtherRepeatsAreRejected) {
  Model m;
  Diagnostics diag;
  EXPECT_FALSE(read_string(deck_with(kTetNodes, {{1, 1, 2, 3, 4, 4, 4, 4}}), m, diag));
  EXPECT_TRUE(diag.has(1222)) << all_messages(diag);
}

TEST(Reader, DuplicateElementDoesNotGiveASpuriousVolumeError) {
  // the element never defined must not be checked as a degenerate element at node 1
  std::string text = tiny_deck();
  std::size_t p = text.find("       2    1       2");
  ASSERT_NE(p, std::string::npos);
  text[p + 7] = '1';
  Model m;
  Diagnostics diag;
  EXPECT_FALSE(read_string(text, m, diag));
  EXPECT_TRUE(diag.has(1200));
  EXPECT_TRUE(diag.has(1204));
  EXPECT_FALSE(diag.has(1206)) << all_messages(diag);
}
