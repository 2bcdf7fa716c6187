// Keyword decks, the rest of a real deck (issue 16): *SET_NODE_GENERAL, *SET_NODE_ADD,
// *SET_PART_ADD, *SET_SOLID (_GENERATE, _GENERAL, _ADD), *SET_SHELL read, *DEFINE_BOX, local
// coordinate systems and vectors (*DEFINE_COORDINATE_SYSTEM, _NODES, _VECTOR, *DEFINE_VECTOR)
// in CID / ICID fields, *DATABASE_HISTORY_NODE_SET / _SOLID_SET, *INITIAL_VELOCITY exclusions
// (NSIDEX, BOXID), *KEYWORD options, *KEYWORD_ID, *INCLUDE_PATH, several ID + data card pairs
// under one _ID keyword, 10-node *ELEMENT_SOLID cards.  The decks are written the way
// LS-PrePost and ANSA write them ($# column lines, padded zeros, abutting fields).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/coordinate_systems.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/keyword_reader.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
namespace fs = std::filesystem;

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& text, const std::string& name = "deck.k") { return test_support::read_deck_text(text, name); }

// A 3 x 1 x 1 row of unit hexahedra (x 0..3), nodes 101 + ix + 4 iy + 8 iz, elements 11, 12 of
// part 7 and 13 of part 8; the deck ends with "*END".
int nid(int ix, int iy, int iz) { return 101 + ix + 4 * iy + 8 * iz; }

std::string base_deck() {
  std::string s =
      "*KEYWORD\n*TITLE\nsets and systems\n"
      "*CONTROL_TERMINATION\n$#  endtim    endcyc     dtmin    endeng    endmas     nosol\n"
      "   1.0E-05         0       0.0       0.01.000000E8         0\n"
      "*PART\n$# title\nleft\n$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid\n"
      "         7         1         1         0         0         0         0         0\n"
      "*PART\n$# title\nright\n         8         1         1\n"
      "*SECTION_SOLID\n         1         1\n"
      "*MAT_ELASTIC\n         1    7.8E-9   2.1E+05       0.3\n"
      "*NODE\n$#   nid               x               y               z      tc      rc\n";
  char buf[160];
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 4; ++ix) {
        std::snprintf(buf, sizeof buf, "%8d%16.1f%16.1f%16.1f%8d%8d\n", nid(ix, iy, iz), double(ix), double(iy), double(iz), 0, 0);
        s += buf;
      }
  s += "*ELEMENT_SOLID\n$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n";
  for (int ix = 0; ix < 3; ++ix) {
    std::snprintf(buf, sizeof buf, "%8d%8d\n%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", 11 + ix, ix < 2 ? 7 : 8, nid(ix, 0, 0),
                  nid(ix + 1, 0, 0), nid(ix + 1, 1, 0), nid(ix, 1, 0), nid(ix, 0, 1), nid(ix + 1, 0, 1), nid(ix + 1, 1, 1),
                  nid(ix, 1, 1), 0, 0);
    s += buf;
  }
  return s + "*END\n";
}

std::string with(const std::string& extra) {
  std::string d = base_deck();
  d.replace(d.find("*END\n"), 5, extra + "*END\n");
  return d;
}

// The deck ids of the nodes whose boundary code fixes x (y, z): how the tests see a node set
// (a *BOUNDARY_SPC_SET of it with DOFX 1).
std::set<int> fixed(const Model& m, int axis = 0) {
  std::set<int> out;
  for (int k = 0; k < m.num_nodes(); ++k) {
    const int c = m.bc[std::size_t(k)];
    const bool f = axis == 0 ? bc_fixes_x(c) : axis == 1 ? bc_fixes_y(c) : bc_fixes_z(c);
    if (f) out.insert(m.node_user_id.empty() ? k + 1 : m.node_user_id[std::size_t(k)]);
  }
  return out;
}
const char* kSpcX20 = "*BOUNDARY_SPC_SET\n$#    nsid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz\n"
                      "        20         0         1         0         0         0         0         0\n";

std::set<int> nodes_at_x(std::initializer_list<int> xs) {
  std::set<int> out;
  for (int ix : xs)
    for (int iy = 0; iy < 2; ++iy)
      for (int iz = 0; iz < 2; ++iz) out.insert(nid(ix, iy, iz));
  return out;
}

// Node velocities after the initial-velocity ranges apply in order (first = 0: all nodes).
std::vector<std::array<double, 3>> node_velocities(const Model& m) {
  std::vector<std::array<double, 3>> v(std::size_t(m.num_nodes()), {0, 0, 0});
  for (const InitialVelocity& iv : m.init_velocities) {
    if (iv.first == 0) {
      for (auto& x : v) x = iv.v;
      continue;
    }
    for (int n = iv.first; n <= iv.last; n += iv.increment) v[std::size_t(n - 1)] = iv.v;
  }
  return v;
}
// The 1-based line of the first line of deck that starts with text.
int line_of(const std::string& deck, const std::string& text) {
  const std::size_t p = deck.find("\n" + text);
  return p == std::string::npos ? -1 : int(std::count(deck.begin(), deck.begin() + std::ptrdiff_t(p) + 1, '\n')) + 1;
}
std::string replaced_once(std::string s, const std::string& from, const std::string& to) {
  const std::size_t p = s.find(from);
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}
int node_of(const Model& m, int id) {
  for (std::size_t k = 0; k < m.node_user_id.size(); ++k)
    if (m.node_user_id[k] == id) return int(k);
  return id - 1;
}

}  // namespace

// ---------------------------------------------------------------------------- sets

TEST(KeywordSets, BaseDeckReads) {
  Read r = read_text(base_deck());
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.m.num_hexes(), 3);
  EXPECT_EQ(r.m.num_nodes(), 16);
}

// *SET_NODE_GENERAL as LS-PrePost writes it (_TITLE, SOLVER field, options left-aligned,
// padded zeros): options apply in order, a D in front removes.
TEST(KeywordSets, NodeGeneralPartBoxNodeAndRemovals) {
  const std::string boxes =
      "*DEFINE_BOX\n$#   boxid       xmn       xmx       ymn       ymx       zmn       zmx\n"
      "         1      -0.1       0.5      -1.0       2.0      -1.0       2.0\n"
      "*DEFINE_BOX_TITLE\nright end\n         2       2.5       3.5      -1.0       2.0      -1.0       2.0\n";
  // part 7 (x 0..2) without the box x <= 0.5: the nodes at x = 1, 2
  Read a = read_text(with(boxes + "*SET_NODE_GENERAL_TITLE\nclamp\n$#     sid       da1       da2       da3       da4    solver\n"
                                  "        20       0.0       0.0       0.0       0.0MECH\n"
                                  "$#  option        e1        e2        e3        e4        e5        e6        e7\n"
                                  "PART               7         0         0         0         0         0         0\n"
                                  "DBOX               1\n" +
                          kSpcX20));
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(fixed(a.m), nodes_at_x({1, 2}));
  // nodes and a box; then one node removed
  Read b = read_text(with(boxes + "*SET_NODE_GENERAL\n        20\nNODE             101       102\nBOX                2\nDNODE            115\n" +
                          kSpcX20));
  ASSERT_TRUE(b.ok) << b.messages();
  std::set<int> expect = nodes_at_x({3});
  expect.erase(115);
  expect.insert({101, 102});
  EXPECT_EQ(fixed(b.m), expect);
  // ALL then DPART 7: the nodes of part 8 only, less those shared with part 7 -> x = 3
  Read c = read_text(with("*SET_NODE_GENERAL\n        20\nALL\nDPART              7\n" + std::string(kSpcX20)));
  ASSERT_TRUE(c.ok) << c.messages();
  EXPECT_EQ(fixed(c.m), nodes_at_x({3}));
}

TEST(KeywordSets, NodeAddAndSolidSetsInAllForms) {
  // *SET_NODE_ADD of a list and a generated set
  Read a = read_text(with("*SET_NODE_LIST\n        21\n       101       105\n"
                          "*SET_NODE_LIST_GENERATE\n        22\n       104       104       112       112\n"
                          "*SET_NODE_ADD\n$#     sid\n        20\n        21        22\n" +
                          std::string(kSpcX20)));
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(fixed(a.m), (std::set<int>{101, 104, 105, 112}));
  // nodes of solid sets: a list, a _GENERATE range, a _GENERAL with PART and DELEM, an _ADD
  for (const std::string solids :
       {"*SET_SOLID\n        30\n        13\n", "*SET_SOLID_GENERATE\n        30\n        13        99\n",
        "*SET_SOLID_GENERAL\n        30\nPART               7         8\nDELEM             11        12\n",
        "*SET_SOLID_LIST_TITLE\nright\n        31\n        13\n*SET_SOLID_ADD\n        30\n        31\n"}) {
    Read r = read_text(with(solids + "*SET_NODE_GENERAL\n        20\nSET_SOLID         30\n" + kSpcX20));
    ASSERT_TRUE(r.ok) << solids << r.messages();
    EXPECT_EQ(fixed(r.m), nodes_at_x({2, 3})) << solids;
  }
  // a solid set by box (element centroids): element 13 (centroid x 2.5)
  Read b = read_text(with("*DEFINE_BOX\n         5       2.2       2.8         0         1         0         1\n"
                          "*SET_SOLID_GENERAL\n        30\nBOX                5\n"
                          "*SET_NODE_GENERAL\n        20\nSET_SOLID         30\n" +
                          std::string(kSpcX20)));
  ASSERT_TRUE(b.ok) << b.messages();
  EXPECT_EQ(fixed(b.m), nodes_at_x({2, 3}));
  // shell sets are read (for the shell elements to come) and used by nothing
  Read s = read_text(with("*SET_SHELL_LIST\n         1\n         1         2\n*SET_SHELL_LIST_GENERATE\n         2\n         1        10\n"));
  EXPECT_TRUE(s.ok) << s.messages();
}

TEST(KeywordSets, PartAddDrivesInitialVelocityGeneration) {
  Read r = read_text(with("*SET_PART_LIST\n         1\n         7\n*SET_PART_LIST_GENERATE\n         2\n         8        20\n"
                          "*SET_PART_ADD\n         3\n         1         2\n"
                          "*INITIAL_VELOCITY_GENERATION\n         3         1       0.0      -5.0       0.0       0.0         0         0\n"
                          "       0.0       0.0       0.0       0.0       0.0       0.0         0         0\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  for (const auto& v : node_velocities(r.m)) EXPECT_EQ(v[0], -5.0);
}

TEST(KeywordSets, BadSetsAreReportedByFieldAndName) {
  const std::string deck = with(
      "*SET_NODE_GENERAL\n        20\nFOO                1\nSET_SHELL          1\nBOX                9\nNODE             999\n"
      "*SET_NODE_ADD\n        21\n        21\n" +
      std::string(kSpcX20) +
      "*BOUNDARY_SPC_SET\n        21         0         1\n");
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.count(1006), 1) << r.messages();  // FOO
  EXPECT_EQ(r.count(1102), 1) << r.messages();  // SET_SHELL: no shells
  EXPECT_EQ(r.count(1310), 1) << r.messages();  // box 9
  EXPECT_EQ(r.count(1202), 1) << r.messages();  // node 999
  EXPECT_EQ(r.count(1309), 1) << r.messages();  // set 21 contains itself
  EXPECT_EQ(r.first(1006)->where.field, "OPTION");
  EXPECT_NE(r.first(1310)->detail.find("*DEFINE_BOX 9 is not defined"), std::string::npos);
}

// ---------------------------------------------------------------------------- histories

TEST(KeywordSets, HistoryNodeAndSolidSets) {
  Read r = read_text(with("*SET_NODE_LIST_GENERATE\n        20\n       101       104\n*SET_SOLID\n        30\n        12        13\n"
                          "*DATABASE_HISTORY_NODE_SET\n$#     id1       id2\n        20\n"
                          "*DATABASE_HISTORY_SOLID_SET\n        30\n"
                          "*DATABASE_HISTORY_NODE_ID\n       116node at the far corner\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.node_th_blocks.size(), 2u);
  EXPECT_EQ(r.m.node_th_blocks[0], (std::array<int, 2>{1, 4}));
  EXPECT_EQ(r.m.node_th_blocks[1], (std::array<int, 2>{16, 16}));
  ASSERT_EQ(r.m.solid_th_blocks.size(), 1u);
  EXPECT_EQ(r.m.solid_th_blocks[0], (std::array<int, 2>{2, 3}));
  Read bad = read_text(with("*DATABASE_HISTORY_SOLID_SET\n        31\n"));
  EXPECT_EQ(bad.count(1309), 1) << bad.messages();
}

// ---------------------------------------------------------------------------- velocities

// *INITIAL_VELOCITY NSID 0 with BOXID: only the nodes in the box move; NSIDEX: its nodes take
// card 3's velocity.
TEST(KeywordSets, InitialVelocityBoxAndExemptedNodes) {
  Read r = read_text(with("*DEFINE_BOX\n         1       0.5       3.5      -1.0       2.0      -1.0       2.0\n"
                          "*SET_NODE_LIST\n        40\n       104       108\n"
                          "*INITIAL_VELOCITY\n$#    nsid    nsidex     boxid    irigid      icid\n"
                          "         0        40         1         0         0\n"
                          "$#      vx        vy        vz       vxr       vyr       vzr\n"
                          "      10.0       0.0       0.0       0.0       0.0       0.0\n"
                          "$#     vxe       vye       vze      vxre      vyre      vzre\n"
                          "       0.0      -3.0       0.0       0.0       0.0       0.0\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  const auto v = node_velocities(r.m);
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 4; ++ix) {
        const int id = nid(ix, iy, iz);
        const auto& vi = v[std::size_t(node_of(r.m, id))];
        if (id == 104 || id == 108) {
          EXPECT_EQ(vi, (std::array<double, 3>{0, -3, 0})) << id;
        } else {
          EXPECT_EQ(vi[0], ix == 0 ? 0.0 : 10.0) << id;
          EXPECT_EQ(vi[1], 0.0) << id;
        }
      }
}

// ---------------------------------------------------------------------------- coordinate systems

TEST(CoordinateSystems, GeometryOfTheDefinitions) {
  CoordinateSystem cs;
  // origin (1, 2, 3), local x along global y, the x-y plane through -x: local y = -global x
  ASSERT_TRUE(coordinate_system_from_points({1, 2, 3}, {1, 5, 3}, {-4, 2, 3}, cs));
  const Vec3 g = cs.to_global_direction({1, 2, 3});
  EXPECT_NEAR(g[0], -2, 1e-15);
  EXPECT_NEAR(g[1], 1, 1e-15);
  EXPECT_NEAR(g[2], 3, 1e-15);
  const Vec3 p = cs.to_global_point({1, 0, 0});
  EXPECT_NEAR(p[1], 3, 1e-15);
  std::array<int, 3> axis{}, sign{};
  ASSERT_TRUE(cs.axis_aligned(axis, sign));
  EXPECT_EQ(axis, (std::array<int, 3>{1, 0, 2}));
  EXPECT_EQ(sign, (std::array<int, 3>{1, -1, 1}));
  EXPECT_FALSE(coordinate_system_from_points({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, cs));  // collinear
  // 30 degrees about z: skew
  CoordinateSystem s;
  ASSERT_TRUE(coordinate_system_from_vectors({std::sqrt(3.0), 1, 0}, {-1, 5, 0}, s));
  EXPECT_FALSE(s.axis_aligned(axis, sign));
  EXPECT_NEAR(s.axis[1][0], -0.5, 1e-15);
  EXPECT_NEAR(s.axis[1][1], std::sqrt(3.0) / 2, 1e-15);
  // rotation 90 degrees about z through (1, 0, 0): (2, 0, 0) -> (1, 1, 0); then scaled by 2
  const AffineMap m = AffineMap::rotation({0, 0, 5}, {1, 0, 0}, 90).then(AffineMap::scaling({2, 2, 2}));
  const Vec3 q = m.apply({2, 0, 0});
  EXPECT_NEAR(q[0], 2, 1e-15);
  EXPECT_NEAR(q[1], 2, 1e-15);
  EXPECT_NEAR(q[2], 0, 1e-15);
}

// CID of *BOUNDARY_SPC: a system whose axes are the global ones up to order and sign maps its
// local DOFs onto the global ones; a skew one is not supported (1102) unless it fixes all or
// none; ICID of *INITIAL_VELOCITY_NODE and _GENERATION turns the velocity into global axes.
TEST(KeywordSystems, SpcAndVelocityInLocalSystems) {
  const std::string systems =
      "*DEFINE_COORDINATE_SYSTEM\n$#     cid        xo        yo        zo        xl        yl        zl      cidl\n"
      "         5       0.0       0.0       0.0       0.0       1.0       0.0         0\n"
      "$#      xp        yp        zp\n      -1.0       0.0       0.0\n"
      "*DEFINE_COORDINATE_VECTOR_TITLE\nskew\n         6       1.0       1.0       0.0      -1.0       1.0       0.0         0\n"
      "*DEFINE_COORDINATE_NODES\n         7       101       102       105         0         X\n";
  // local x of system 5 is global y
  Read a = read_text(with(systems + "*SET_NODE_LIST\n        20\n       101\n"
                                    "*BOUNDARY_SPC_SET\n        20         5         1         0         0\n"
                                    "*BOUNDARY_SPC_NODE\n       116         7         0         0         1\n"
                                    "*INITIAL_VELOCITY_NODE\n       102       2.0       0.0       0.0       0.0       0.0       0.0         6\n"
                                    "       103       2.0       0.0       0.0       0.0       0.0       0.0         5\n"));
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(fixed(a.m, 0), std::set<int>{});
  EXPECT_EQ(fixed(a.m, 1), std::set<int>{101});
  EXPECT_EQ(fixed(a.m, 2), std::set<int>{116});  // system 7 is the global one (nodes along x, y)
  const auto v = node_velocities(a.m);
  const double h = std::sqrt(2.0);  // 2 along the local x of system 6 = (1, 1, 0) / sqrt 2
  EXPECT_NEAR(v[std::size_t(node_of(a.m, 102))][0], h, 1e-15);
  EXPECT_NEAR(v[std::size_t(node_of(a.m, 102))][1], h, 1e-15);
  EXPECT_NEAR(v[std::size_t(node_of(a.m, 103))][0], 0, 1e-15);
  EXPECT_NEAR(v[std::size_t(node_of(a.m, 103))][1], 2, 1e-15);
  // skew: one DOF is not supported, all three are
  const std::string skew = with(systems + "*BOUNDARY_SPC_NODE\n       101         6         1         0         0\n"
                                                "       102         6         1         1         1\n");
  Read b = read_text(skew);
  EXPECT_FALSE(b.ok);
  ASSERT_EQ(b.count(1102), 1) << b.messages();
  EXPECT_EQ(b.first(1102)->where.field, "CID");
  EXPECT_EQ(b.first(1102)->where.line, line_of(skew, "       101         6"));
  // undefined system; a system given in another one (CIDL) that does not exist
  Read c = read_text(with("*BOUNDARY_SPC_NODE\n       101         9         1\n"
                          "*DEFINE_COORDINATE_SYSTEM\n         5       0.0       0.0       0.0       1.0       0.0       0.0        12\n"
                          "       0.0       1.0       0.0\n"));
  EXPECT_EQ(c.count(1310), 2) << c.messages();
}

// A *DEFINE_COORDINATE_SYSTEM given in another system (CIDL) and a *DEFINE_VECTOR in a system:
// the table the loads code uses turns both into global directions.
TEST(KeywordSystems, VelocityGenerationInANestedSystem) {
  // system 2: 90 degrees about z (local x = global y); system 3 given in 2 the same way: its
  // local x is system 2's y = -global x
  Read r = read_text(with("*DEFINE_COORDINATE_SYSTEM\n         3       0.0       0.0       0.0       0.0       1.0       0.0         2\n"
                          "      -1.0       0.0       0.0\n"
                          "*DEFINE_COORDINATE_SYSTEM\n         2       0.0       0.0       0.0       0.0       1.0       0.0\n"
                          "      -1.0       0.0       0.0\n"
                          "*INITIAL_VELOCITY_GENERATION\n         8         2       0.0       4.0       0.0       0.0         0         3\n"
                          "       0.0       0.0       0.0       0.0       0.0       0.0         0         0\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  const auto v = node_velocities(r.m);
  const auto& vr = v[std::size_t(node_of(r.m, nid(3, 0, 0)))];
  EXPECT_NEAR(vr[0], -4, 1e-15);
  EXPECT_NEAR(vr[1], 0, 1e-15);
}

// ---------------------------------------------------------------------------- deck layout

TEST(KeywordLayout, KeywordOptionsKeywordIdAndIncludePath) {
  std::string deck = base_deck();
  deck.replace(0, 9, "*KEYWORD 90000000 MEMORY=200m NCPU=4\n*KEYWORD_ID\nproject           12stage\n");
  Read r = read_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.count(1312), 0);
  EXPECT_EQ(r.count(2008), 2) << r.messages();  // MEMORY=, *KEYWORD_ID
  EXPECT_EQ(r.m.deck_threads, 4);  // NCPU=4: the default of ncpu=
  // *INCLUDE_PATH_RELATIVE: the include is found in the directory it names
  const fs::path dir = fs::temp_directory_path() / ("impact3d_kwsets_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "mesh");
  std::string main = base_deck();
  const std::size_t n0 = main.find("*NODE\n"), n1 = main.find("*END\n");
  std::ofstream(dir / "mesh" / "mesh.k") << main.substr(n0, n1 - n0);
  main = main.substr(0, n0) + "*INCLUDE_PATH_RELATIVE\nmesh\n*INCLUDE\nmesh.k\n*END\n";
  std::ofstream(dir / "main.k") << main;
  Read inc;
  inc.ok = read_and_check_deck((dir / "main.k").string(), inc.m, inc.d);
  EXPECT_TRUE(inc.ok) << inc.messages();
  EXPECT_EQ(inc.m.num_hexes(), 3);
  fs::remove_all(dir);
}

// Several ID card + data card pairs under one _ID keyword, as ANSA writes them: each ID card
// (an id and a heading, or an id alone) starts a new definition; an error on a data card names
// that card's line.
TEST(KeywordLayout, SeveralIdAndDataPairsUnderOneIdKeyword) {
  Read r = read_text(with("*SET_NODE_LIST\n        20\n       101       102\n*SET_NODE_LIST\n        21\n       116\n"
                          "*BOUNDARY_SPC_SET_ID\n$#      id                                                             heading\n"
                          "         1fix x\n$#    nsid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz\n"
                          "        20         0         1         0         0         0         0         0\n"
                          "         2\n"
                          "        21         0         0         1         0         0         0         0\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(fixed(r.m, 0), (std::set<int>{101, 102}));
  EXPECT_EQ(fixed(r.m, 1), (std::set<int>{116}));
  const std::string bad_deck = with("*SET_NODE_LIST\n        20\n       101\n"
                                    "*BOUNDARY_SPC_SET_ID\n         1first\n        20         0         1\n"
                                    "         2second\n        20         0         x\n");
  Read bad = read_text(bad_deck);
  ASSERT_EQ(bad.count(1001), 1) << bad.messages();
  EXPECT_EQ(bad.first(1001)->where.field, "DOFX");
  EXPECT_EQ(bad.first(1001)->where.line, line_of(bad_deck, "        20         0         x"));
}

// *ELEMENT_SOLID in the ten-node layout: N9 N10 zero (padded) is an 8-node solid; real 10-node
// tetrahedra are refused in one message with their count, and the cards after them are named
// right.
TEST(KeywordLayout, TenNodeElementCards) {
  std::string tets = "*ELEMENT_SOLID\n";
  char buf[200];
  for (int k = 0; k < 500; ++k) {
    std::snprintf(buf, sizeof buf, "%8d%8d\n%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", 1000 + k, 7, 101, 102, 105, 109, 103, 104, 106, 107, 108, 110);
    tets += buf;
  }
  tets += "     777       7\n     101     102     106     105     109     110     114      1x       0       0\n";
  Read r = read_text(with(tets));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.count(1102), 1) << r.messages();
  EXPECT_NE(r.first(1102)->detail.find("500 element(s) are 10-node tetrahedra"), std::string::npos) << r.messages();
  EXPECT_EQ(r.first(1102)->where.card, "*ELEMENT_SOLID element 1000");
  ASSERT_EQ(r.count(1001), 1) << r.messages();
  EXPECT_EQ(r.first(1001)->where.field, "N8");
  EXPECT_EQ(r.first(1001)->where.card, "*ELEMENT_SOLID element 777 node card");
  EXPECT_LT(r.d.error_count(), 5);
}

// A number anywhere in its 10 columns reads the same (LS-DYNA reads fixed fields by columns,
// blanks around the number ignored), and an integer field written as a real with no fraction.
TEST(KeywordLayout, ShiftedNumbersInTheirColumns) {
  Read a = read_text(with("*SET_NODE_LIST\n        20\n       101\n*BOUNDARY_SPC_SET\n20        0         1.        \n"));
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(fixed(a.m, 0), std::set<int>{101});
}

// *INCLUDE_TRANSFORM: the same mesh file included twice, the second time with id offsets and a
// *DEFINE_TRANSFORMATION (rotation 90 degrees about z through the origin, then a translation):
// the copy's nodes are the originals mapped, its elements, sets and constraints renumbered.
TEST(KeywordLayout, IncludeTransformOffsetsAndMovesTheCopy) {
  const fs::path dir = fs::temp_directory_path() / ("impact3d_kwxform_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string main = base_deck();
  const std::size_t n0 = main.find("*NODE\n"), n1 = main.find("*END\n");
  std::ofstream(dir / "mesh.k") << main.substr(n0, n1 - n0)
                                << "*SET_NODE_LIST\n        20\n       101\n*BOUNDARY_SPC_SET\n        20         0         1\n";
  main = main.substr(0, n0) +
         "*DEFINE_TRANSFORMATION\n$#  tranid\n         4\n$#  option        a1        a2        a3        a4        a5        a6        a7\n"
         "ROTATE          0.0       0.0       1.0       0.0       0.0       0.0      90.0\n"
         "TRANSL         10.0       0.0       0.0\n"
         "*INCLUDE\nmesh.k\n"
         "*INCLUDE_TRANSFORM\n$# filename\nmesh.k\n"
         "$#  idnoff    ideoff    idpoff    idmoff    idsoff    idfoff    iddoff\n"
         "      1000       100         0         0        50         0         0\n"
         "$#  idroff\n         0\n$#  fctmas    fcttim    fctlen    fcttem   incout1\n       1.0       1.0       1.0       1.0         0\n"
         "$#  tranid\n         4\n*END\n";
  std::ofstream(dir / "main.k") << main;
  Read r;
  r.ok = read_and_check_deck((dir / "main.k").string(), r.m, r.d);
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.num_nodes(), 32);
  ASSERT_EQ(r.m.num_hexes(), 6);
  EXPECT_EQ(r.m.hex_user_id.back(), 113);
  // node 116 at (3, 1, 1) -> rotated (-1, 3, 1) -> (9, 3, 1) as node 1116
  const int k = node_of(r.m, 1116);
  EXPECT_NEAR(r.m.x[std::size_t(k)], 9.0, 1e-14);
  EXPECT_NEAR(r.m.y[std::size_t(k)], 3.0, 1e-14);
  EXPECT_NEAR(r.m.z[std::size_t(k)], 1.0, 1e-14);
  EXPECT_EQ(fixed(r.m, 0), (std::set<int>{101, 1101}));  // set 20 and its copy, set 70
  // FCTLEN scales the coordinates (mm -> m: 1e-3): node 1116 at (9, 3, 1) mm -> 1e-3 x that;
  // a material in such a file is not supported (its units are not converted)
  std::string scaled = main;
  scaled.replace(scaled.find("       1.0       1.0       1.0       1.0         0\n"), 51, "       1.0       1.0     0.001       1.0         0\n");
  std::ofstream(dir / "main.k") << scaled;
  Read s;
  s.ok = read_and_check_deck((dir / "main.k").string(), s.m, s.d);
  ASSERT_TRUE(s.ok) << s.messages();
  const int ks = node_of(s.m, 1116);
  EXPECT_NEAR(s.m.x[std::size_t(ks)], 10.0 - 1e-3, 1e-14);  // (3, 1, 1) x 1e-3, turned: (-1e-3, 3e-3), + 10 in x
  EXPECT_NEAR(s.m.y[std::size_t(ks)], 3e-3, 1e-16);
  std::ofstream(dir / "mesh.k", std::ios::app) << "*MAT_ELASTIC\n         2    7.8E-9   2.1E+05       0.3\n";
  Read m;
  m.ok = read_and_check_deck((dir / "main.k").string(), m.m, m.d);
  EXPECT_EQ(m.count(1102), 1) << m.messages();
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------- *CASE

namespace {
Read read_case(const std::string& text, int case_id) {
  Read r;
  DeckFile deck;
  deck.load_from_string("deck.k", text);
  InputOptions o;
  o.case_id = case_id;
  r.ok = read_deck(deck, r.m, r.d, o);
  if (r.ok) r.ok = check_model(r.m, r.d);
  return r;
}
double kinetic_energy(const Model& m) {  // of the initial velocities: 1/2 rho V v^2 per element share
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  double ke = 0;
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    ke += 0.5 * s.mass[k] * (s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k] + s.vz[k] * s.vz[k]);
  }
  return ke;
}
}  // namespace

// A deck with master cases as LS-PrePost writes them (CASEID JOBID; a command line; the child
// case ids) and child sections, nested, and a keyword with CID=: the base case has none of the
// sections; each case has the main model and its children, and its own kinetic energy
// 1/2 rho V v^2 (rho 7.8e-9, V 3: m = 2.34e-8; exact to rounding, 1e-12 relative).
TEST(KeywordCase, BaseCaseAndNamedCasesEachWithTheirOwnCards) {
  const std::string deck = with(
      "*CASE\n$#  caseid     jobid\n       101      fast\nMEMORY=20M\n         1\n"
      "*CASE\n       102\nNCPU=2\n         2         3\n"
      "*INITIAL_VELOCITY\n         0\n       1.0\n"
      "*CASE_BEGIN_1\n*INITIAL_VELOCITY\n         0\n     100.0\n*CASE_END_1\n"
      "*CASE_BEGIN_2\n*CASE_BEGIN_3\n*INITIAL_VELOCITY\n         0\n      50.0\n*CASE_END_3\n*CASE_END_2\n"
      "*SET_NODE_LIST CID=3\n        20\n       101\n" +
      std::string(kSpcX20));
  const double mass = 7.8e-9 * 3.0;
  Read base = read_case(deck, 0);
  // the base case: the SPC names set 20, which only case 3 defines
  EXPECT_FALSE(base.ok);
  EXPECT_EQ(base.count(1309), 1) << base.messages();
  Read base_ok = read_case(deck.substr(0, deck.find("*SET_NODE_LIST CID=3")) + "*END\n", 0);
  ASSERT_TRUE(base_ok.ok) << base_ok.messages();
  EXPECT_EQ(base_ok.m.case_job, "");
  EXPECT_NEAR(kinetic_energy(base_ok.m), 0.5 * mass * 1.0, 1e-12 * mass);
  Read c101 = read_case(deck.substr(0, deck.find("*SET_NODE_LIST CID=3")) + "*END\n", 101);
  ASSERT_TRUE(c101.ok) << c101.messages();
  EXPECT_EQ(c101.m.case_job, "fast");
  EXPECT_NEAR(kinetic_energy(c101.m), 0.5 * mass * 1e4, 1e-12 * mass * 1e4);
  EXPECT_EQ(c101.count(2006), 1) << c101.messages();  // MEMORY=20M: give options on the command line
  Read c102 = read_case(deck, 102);
  ASSERT_TRUE(c102.ok) << c102.messages();
  EXPECT_EQ(c102.m.case_job, "case102");
  // node 101 (a corner: 1/24 of the mass) is fixed in x by the SPC of case 3: it does not move
  EXPECT_NEAR(kinetic_energy(c102.m), 0.5 * mass * 2500 * 23 / 24, 1e-12 * mass * 2500);
  EXPECT_EQ(fixed(c102.m), std::set<int>{101});
  Read none = read_case(deck, 5);
  EXPECT_FALSE(none.ok);
  ASSERT_EQ(none.count(1310), 1) << none.messages();
  EXPECT_NE(none.first(1310)->detail.find("its cases: 101, 102"), std::string::npos) << none.messages();
  // unbalanced sections
  Read open = read_case(with("*CASE_BEGIN_4\n*CASE_END_5\n"), 0);
  EXPECT_EQ(open.count(1006), 1) << open.messages();
  EXPECT_EQ(open.count(1316), 1) << open.messages();
}

// A card after one whose field asks for something not read (here *INITIAL_VELOCITY NSIDEX with
// its card 3) is read as what it is: an error on the next definition's card 1 names that card
// and its line, and a box that only a refused keyword defines names that keyword.
TEST(KeywordLayout, TheCardAfterAnOptionalCardIsNamedRight) {
  const std::string deck = with("*SET_NODE_LIST\n        40\n       104\n"
                                "*INITIAL_VELOCITY\n         0        40\n       1.0\n       2.0\n"
                                "        4x\n       3.0\n");
  Read r = read_text(deck);
  ASSERT_EQ(r.count(1001), 1) << r.messages();
  EXPECT_EQ(r.first(1001)->where.card, "*INITIAL_VELOCITY card 1");
  EXPECT_EQ(r.first(1001)->where.field, "NSID");
  EXPECT_EQ(r.first(1001)->where.line, line_of(deck, "        4x"));
  EXPECT_EQ(r.count(1316), 0) << r.messages();
  Read box = read_text(with("*DEFINE_BOX_LOCAL\n         3\n*INITIAL_VELOCITY\n         0         0         3\n       1.0\n"));
  EXPECT_FALSE(box.ok);
  ASSERT_EQ(box.count(1310), 1) << box.messages();
  EXPECT_NE(box.first(1310)->detail.find("it is defined by *DEFINE_BOX_LOCAL"), std::string::npos) << box.messages();
}

// SABOXID / SBBOXID: a contact side keeps the segments whose centroid is in its box.  Part 8
// (one hexahedron, x 2..3) has 6 exterior faces, one with its centroid at x = 3; part 7 (x 0..2)
// has 10, one at x = 2 (the face it shares with part 8 is exterior to part 7 alone).
TEST(KeywordSets, ContactBoxesKeepTheSegmentsInside) {
  const std::string contact =
      "*CONTACT_SURFACE_TO_SURFACE\n$#   surfa     surfb  surfatyp  surfbtyp   saboxid   sbboxid      sapr      sbpr\n"
      "         8         7         3         3         1         2         0         0\n";
  Read all = read_text(with(replaced_once(contact, "         1         2", "         0         0")));
  ASSERT_TRUE(all.ok) << all.messages();
  ASSERT_EQ(all.m.interfaces.size(), 1u);
  EXPECT_EQ(all.m.interfaces[0].slave.size(), 6u);
  EXPECT_EQ(all.m.interfaces[0].master.size(), 10u);
  Read boxed = read_text(with("*DEFINE_BOX\n         1       2.9       3.1      -1.0       2.0      -1.0       2.0\n"
                              "*DEFINE_BOX\n         2       1.9       2.1      -1.0       2.0      -1.0       2.0\n" +
                              contact));
  ASSERT_TRUE(boxed.ok) << boxed.messages();
  ASSERT_EQ(boxed.m.interfaces[0].slave.size(), 1u);
  ASSERT_EQ(boxed.m.interfaces[0].master.size(), 1u);
  for (int v : boxed.m.interfaces[0].slave[0]) EXPECT_EQ(boxed.m.x[std::size_t(v)], 3.0);
  for (int v : boxed.m.interfaces[0].master[0]) EXPECT_EQ(boxed.m.x[std::size_t(v)], 2.0);
  Read empty = read_text(with("*DEFINE_BOX\n         1      10.0      11.0      -1.0       2.0      -1.0       2.0\n"
                              "*DEFINE_BOX\n         2       1.9       2.1      -1.0       2.0      -1.0       2.0\n" +
                              contact));
  ASSERT_EQ(empty.count(1314), 1) << empty.messages();
  EXPECT_EQ(empty.first(1314)->where.field, "SABOXID");
}

// The same definitions as a script writes them, comma separated: a box, a general node set and
// a coordinate system in free format give the model the fixed-column cards give.
TEST(KeywordSets, FreeFormatSetsBoxesAndSystems) {
  Read fixed_cols = read_text(with("*DEFINE_BOX\n         1       2.5       3.5      -1.0       2.0      -1.0       2.0\n"
                                   "*SET_NODE_GENERAL\n        20\nBOX                1\nNODE             101\n"
                                   "*DEFINE_COORDINATE_SYSTEM\n         5       0.0       0.0       0.0       0.0       1.0       0.0\n"
                                   "      -1.0       0.0       0.0\n"
                                   "*BOUNDARY_SPC_SET\n        20         5         1\n"));
  Read commas = read_text(with("*DEFINE_BOX\n1,2.5,3.5,-1.,2.,-1.,2.\n*SET_NODE_GENERAL\n20\nBOX,1\nNODE,101\n"
                               "*DEFINE_COORDINATE_SYSTEM\n5,0,0,0,0,1,0\n-1,0,0\n*BOUNDARY_SPC_SET\n20,5,1\n"));
  ASSERT_TRUE(fixed_cols.ok) << fixed_cols.messages();
  ASSERT_TRUE(commas.ok) << commas.messages();
  std::set<int> expect = nodes_at_x({3});
  expect.insert(101);
  EXPECT_EQ(fixed(commas.m, 1), expect);  // local x of system 5 is global y
  EXPECT_EQ(fixed(fixed_cols.m, 1), expect);
  EXPECT_EQ(commas.m.bc, fixed_cols.m.bc);
}

// *SET_SEGMENT_GENERAL PART (the part's exterior faces, as a contact side of type 3) and
// SET_SOLID, and *SET_SEGMENT_ADD of segment sets, as contact sides.
TEST(KeywordSets, SegmentSetsAddAndGeneral) {
  const std::string contact = "*CONTACT_SURFACE_TO_SURFACE\n        41        42         0         0\n";
  Read r = read_text(with("*SET_SEGMENT\n        40\n       101       105       113       109\n"
                          "*SET_SEGMENT_GENERAL\n        39\nPART               8\n"
                          "*SET_SEGMENT_ADD\n        41\n        39        40\n"
                          "*SET_SOLID\n        30\n        11\n"
                          "*SET_SEGMENT_GENERAL_TITLE\nleft end\n        42\nSET_SOLID         30\n" +
                          contact));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.interfaces.size(), 1u);
  EXPECT_EQ(r.m.interfaces[0].slave.size(), 7u);   // 6 faces of element 13 and the listed face (x = 0)
  EXPECT_EQ(r.m.interfaces[0].master.size(), 6u);  // the 6 faces of element 11
  Read bad = read_text(with("*SET_SEGMENT_ADD\n        41\n        41\n*SET_SEGMENT_GENERAL\n        42\nBOX                1\n" + contact));
  EXPECT_EQ(bad.count(1309), 1) << bad.messages();
  EXPECT_EQ(bad.count(1102), 1) << bad.messages();
}
