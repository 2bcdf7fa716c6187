// Keyword loads and prescribed motions (issue 16): *LOAD_NODE_POINT / _SET, *LOAD_SEGMENT /
// _SET, *LOAD_BODY_X/Y/Z/VECTOR, *LOAD_BODY_PARTS, *LOAD_RIGID_BODY and
// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET / _RIGID read onto the Model as LS-PrePost writes
// them (column comments, _ID pairs), with their refusals.  (The physics: tests/solve/test_loads.cpp.)

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "../support/deck_text.h"

using namespace impact3d;

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& text) { return test_support::read_deck_text(text, "loads.k"); }

// A 2 x 1 x 1 block of unit hexahedra (part 7, elastic steel, mm-t-s), nodes 1..12
// (node ix + 3 iy + 6 iz + 1), and a rigid cube (part 8) of nodes 101..108.
std::string block_deck(const std::string& extra) {
  std::string s =
      "*KEYWORD\n*TITLE\nloads\n"
      "*CONTROL_TERMINATION\n$#  endtim\n   1.0E-05\n"
      "*PART\nblock\n$#     pid     secid       mid\n         7         1         1\n"
      "*PART\nrigid\n         8         1         2\n"
      "*SECTION_SOLID\n         1         1\n"
      "*MAT_ELASTIC\n$#     mid        ro         e        pr\n         17.85000E-9  200000.0       0.3\n"
      "*MAT_RIGID\n         27.85000E-9  200000.0       0.3\n"
      "*NODE\n";
  char buf[128];
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 3; ++ix) {
        std::snprintf(buf, sizeof buf, "%8d%16.1f%16.1f%16.1f\n", ix + 3 * iy + 6 * iz + 1, double(ix), double(iy), double(iz));
        s += buf;
      }
  for (int k = 0; k < 8; ++k) {
    std::snprintf(buf, sizeof buf, "%8d%16.1f%16.1f%16.1f\n", 101 + k, 10.0 + (k & 1), double((k >> 1) & 1), double(k >> 2));
    s += buf;
  }
  s += "*ELEMENT_SOLID\n"
       "       1       7       1       2       5       4       7       8      11      10\n"
       "       2       7       2       3       6       5       8       9      12      11\n"
       "       3       8     101     102     104     103     105     106     108     107\n";
  s += "*DEFINE_CURVE\n$#    lcid      sidr       sfa       sfo\n        11         0       1.0       2.0\n"
       "                 0.0                 0.0\n               1.0-5                 1.0\n";
  s += "*DEFINE_CURVE\n        12\n                 0.0                 1.0\n                 1.0                 1.0\n";
  return s + extra + "*END\n";
}

}  // namespace

TEST(KeywordLoads, ReadsEveryLoadAndMotion) {
  const std::string extra =
      "*SET_NODE_LIST\n        30\n         3         6         9        12\n"
      "*SET_SEGMENT\n        40\n         3         6        12         9\n"
      "*SET_PART_LIST\n        50\n         7\n"
      "*LOAD_NODE_POINT\n$#     nid       dof      lcid        sf\n         3         1        11     250.0\n"
      "*LOAD_NODE_SET\n        30         2        12      -1.5\n"
      "*LOAD_SEGMENT\n$#    lcid        sf        at        n1        n2        n3        n4\n"
      "        11       3.0     1.0-6         1         4         5         2\n"
      "*LOAD_SEGMENT_SET\n        40        12       5.0\n"
      "*LOAD_BODY_Z\n        12      9.81\n"
      "*LOAD_BODY_VECTOR\n        12       2.0\n       1.0       1.0       0.0\n"
      "*LOAD_BODY_PARTS\n        50\n"
      "*LOAD_RIGID_BODY\n         8         3        12     100.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n         1first\n        30         1         2        11       0.5         0     2.0-5     1.0-6\n"
      "         2second\n        30         3         0        12       1.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         8         2         1        12      -3.0\n";
  Read r = read_text(block_deck(extra));
  ASSERT_TRUE(r.ok) << r.messages();
  const Model& m = r.m;
  ASSERT_EQ(m.load_curves.size(), 2u);
  // curves renumbered in deck order: 11 -> index 0, 12 -> index 1; SFO applied
  EXPECT_DOUBLE_EQ(m.load_curves[0].f[1], 2.0);
  ASSERT_EQ(m.nodal_loads.size(), 1u + 4u);
  EXPECT_EQ(m.nodal_loads[0].node, 2);  // node 3
  EXPECT_EQ(m.nodal_loads[0].dir, (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(m.nodal_loads[0].curve, 0);
  EXPECT_DOUBLE_EQ(m.nodal_loads[0].scale, 250.0);
  EXPECT_EQ(m.nodal_loads[4].node, 11);  // node 12 of set 30
  EXPECT_EQ(m.nodal_loads[4].dir, (std::array<double, 3>{0, 1, 0}));
  EXPECT_DOUBLE_EQ(m.nodal_loads[4].scale, -1.5);
  ASSERT_EQ(m.pressure_loads.size(), 2u);
  EXPECT_EQ(m.pressure_loads[0].nodes, (std::array<int, 4>{0, 3, 4, 1}));
  EXPECT_DOUBLE_EQ(m.pressure_loads[0].birth, 1e-6);
  EXPECT_EQ(m.pressure_loads[1].nodes, (std::array<int, 4>{2, 5, 11, 8}));
  EXPECT_EQ(m.pressure_loads[1].curve, 1);
  ASSERT_EQ(m.body_loads.size(), 2u);
  EXPECT_EQ(m.body_loads[0].dir, (std::array<double, 3>{0, 0, 1}));
  EXPECT_NEAR(m.body_loads[1].dir[0], std::sqrt(0.5), 1e-15);
  ASSERT_EQ(m.body_load_materials.size(), 1u);
  ASSERT_EQ(m.rigid_body_loads.size(), 1u);
  EXPECT_EQ(m.rigid_body_loads[0].dir, (std::array<double, 3>{0, 0, 1}));
  ASSERT_EQ(m.prescribed_motions.size(), 4u + 4u + 1u);
  const PrescribedMotion& p0 = m.prescribed_motions[0];
  EXPECT_EQ(p0.node, 2);
  EXPECT_EQ(p0.kind, MotionKind::displacement);
  EXPECT_DOUBLE_EQ(p0.scale, 0.5);
  EXPECT_DOUBLE_EQ(p0.death, 2e-5);
  EXPECT_DOUBLE_EQ(p0.birth, 1e-6);
  EXPECT_EQ(m.prescribed_motions[4].kind, MotionKind::velocity);
  EXPECT_EQ(m.prescribed_motions[4].dir, (std::array<double, 3>{0, 0, 1}));
  EXPECT_EQ(m.prescribed_motions[4].death, 1e28);  // blank DEATH: never
  const PrescribedMotion& pr = m.prescribed_motions[8];
  EXPECT_EQ(pr.node, -1);
  EXPECT_GE(pr.rigid_material, 0);
  EXPECT_EQ(pr.kind, MotionKind::acceleration);
  // every curve is used: no 2004
  EXPECT_EQ(r.d.count(2004), 0) << r.messages();
}

TEST(KeywordLoads, RefusalsNameTheField) {
  const std::string extra =
      "*LOAD_NODE_POINT\n         3         5        11\n"           // moment: 1102
      "*LOAD_NODE_POINT\n         3         1        99\n"           // curve 99 undefined: 1310
      "*LOAD_NODE_POINT\n         3         1         0\n"           // no curve: 1003
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         3         1         4        11\n"   // VAD 4: 1102
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         3         4         0        11       1.0         5\n"  // VID 5 undefined: 1310
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n       101         1         0        11\n"   // rigid node: 1226
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         7         1         0        11\n"  // not rigid: 1006
      "*LOAD_SEGMENT\n        11       1.0       0.0         1         2         3         4         5\n";  // N5: 1102
  Read r = read_text(block_deck(extra));
  EXPECT_FALSE(r.ok);
  const std::string msg = r.messages();
  EXPECT_GE(r.d.count(1102), 3) << msg;
  EXPECT_EQ(r.d.count(1310), 2) << msg;
  EXPECT_NE(msg.find("vector 5 is not defined"), std::string::npos) << msg;
  EXPECT_EQ(r.d.count(1226), 1) << msg;
  EXPECT_EQ(r.d.count(1006), 1) << msg;
  EXPECT_NE(msg.find("*DEFINE_CURVE 99 is not defined"), std::string::npos) << msg;
  EXPECT_NE(msg.find("DOF"), std::string::npos) << msg;
  EXPECT_NE(msg.find("*BOUNDARY_PRESCRIBED_MOTION_RIGID"), std::string::npos) << msg;
  // curve 12 is used by nothing: one 2004 warning
  EXPECT_EQ(r.d.count(2004), 1) << msg;
}

namespace {
Read read_fixed_text(const std::string& text) {
  Read r;
  DeckFile deck;
  deck.load_from_string("loads.dyn", text);
  InputOptions o;
  r.ok = read_deck(deck, r.m, r.d, o);
  if (r.ok) r.ok = check_model(r.m, r.d);
  return r;
}
std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}
}  // namespace

// The converters both ways: every load and motion the fixed format can hold comes back the
// same (nodal loads, pressures with their multipliers and arrival time, prescribed node
// motions, one base acceleration per axis); the keyword writer keeps everything.
TEST(KeywordLoads, ConvertersRoundTrip) {
  const std::string extra =
      "*SET_NODE_LIST\n        30\n         3         6         9        12\n"
      "*LOAD_NODE_POINT\n         3         1        11     250.0\n"
      "*LOAD_NODE_SET\n        30         2        12      -1.5\n"
      "*LOAD_SEGMENT\n        11       3.0     1.0-6         1         4         5         2\n"
      "*LOAD_BODY_Z\n        12      9.81\n"
      "*BOUNDARY_PRESCRIBED_MOTION_SET\n        30         1         2        11       0.5         0     2.0-5     1.0-6\n"
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         1         3         1        12      -2.0\n"
      "*DATABASE_BINARY_D3PLOT\n    1.0E-6\n";
  Read r = read_text(block_deck(extra));
  ASSERT_TRUE(r.ok) << r.messages();
  // keyword -> keyword
  std::ostringstream kw;
  std::vector<std::string> notes;
  write_keyword_deck(kw, r.m, &notes);
  Read k2 = read_text(kw.str());
  ASSERT_TRUE(k2.ok) << k2.messages() << kw.str();
  EXPECT_EQ(join(model_differences(r.m, k2.m, 50)), "") << kw.str();
  EXPECT_EQ(join(notes), "");
  // keyword -> fixed -> keyword model
  std::ostringstream fx;
  notes.clear();
  write_fixed_deck(fx, r.m, &notes);
  Read f2 = read_fixed_text(fx.str());
  ASSERT_TRUE(f2.ok) << f2.messages() << fx.str();
  // (the fixed format numbers nodes 1..N: the user ids differ; DYNA3D's large-format pressure
  // card has no arrival time: it is noted and lost)
  EXPECT_EQ(join(model_differences(r.m, f2.m, 50)), "node ids: 20 vs 0\npressure load 1 birth: 1.0e-6 vs 0.0\n") << fx.str();
  EXPECT_EQ(join(notes), "node and element ids renumbered 1..N (the fixed format needs 1..N)\n"
                         "pressure arrival time 1.0e-6 has no field in DYNA3D's pressure card: not written\n");
  EXPECT_EQ(f2.d.count(2004), 0) << f2.messages();
}

// Directions in local systems: *LOAD_NODE_POINT DOF 1 in a system whose x axis is global y,
// *LOAD_BODY_X in that system, and a prescribed motion DOF 4 along a *DEFINE_VECTOR.
TEST(KeywordLoads, LocalSystemsAndVectors) {
  const std::string extra =
      "*DEFINE_COORDINATE_SYSTEM\n"
      "$#     cid        xo        yo        zo        xl        yl        zl\n"
      "         5       0.0       0.0       0.0       0.0       1.0       0.0\n"
      "$#      xp        yp        zp\n"
      "      -1.0       0.0       0.0\n"
      "*DEFINE_VECTOR\n         9       0.0       0.0       0.0       3.0       0.0       4.0\n"
      "*LOAD_NODE_POINT\n         3         1        11     250.0         5\n"
      "*LOAD_BODY_X\n        12      9.81         0       0.0       0.0       0.0         5\n"
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         1         4         0        12       2.0         9\n";
  Read r = read_text(block_deck(extra));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.nodal_loads.size(), 1u);
  EXPECT_NEAR(r.m.nodal_loads[0].dir[0], 0.0, 1e-15);
  EXPECT_NEAR(r.m.nodal_loads[0].dir[1], 1.0, 1e-15);
  ASSERT_EQ(r.m.body_loads.size(), 1u);
  EXPECT_NEAR(r.m.body_loads[0].dir[1], 1.0, 1e-15);
  ASSERT_EQ(r.m.prescribed_motions.size(), 1u);
  EXPECT_NEAR(r.m.prescribed_motions[0].dir[0], 0.6, 1e-15);
  EXPECT_NEAR(r.m.prescribed_motions[0].dir[2], 0.8, 1e-15);
}

// The shipped loads example: decks/keyword/bar_pulled.k (prescribed velocity ramp, a side
// pressure, gravity, an SPC set) and its fixed-format twin decks/bar_pulled.dyn (written by
// impact3d --write-fixed) are the same model.
TEST(KeywordLoads, ShippedBarPulledTwinsAreTheSameModel) {
  const std::string src = IMPACT3D_SOURCE_DIR;
  Read k, f;
  InputOptions o;
  k.ok = read_and_check_deck(src + "/decks/keyword/bar_pulled.k", k.m, k.d, o);
  f.ok = read_and_check_deck(src + "/decks/bar_pulled.dyn", f.m, f.d, o);
  ASSERT_TRUE(k.ok) << k.messages();
  ASSERT_TRUE(f.ok) << f.messages();
  EXPECT_EQ(join(model_differences(k.m, f.m, 50)), "");
  EXPECT_EQ(k.m.prescribed_motions.size(), 9u);
  EXPECT_EQ(k.m.pressure_loads.size(), 40u);
  EXPECT_EQ(k.m.body_loads.size(), 1u);
}

// *DAMPING_GLOBAL: VALDMP or a curve LCID, STX STY STZ (all six factors 0: all 1), refusals,
// and the keyword converter round trip (the fixed format has no card for it: noted).
TEST(KeywordLoads, DampingGlobal) {
  Read c = read_text(block_deck("*DAMPING_GLOBAL\n$#    lcid    valdmp       stx       sty       stz       srx       sry       srz\n"
                                "         0     250.0\n"));
  ASSERT_TRUE(c.ok) << c.messages();
  EXPECT_TRUE(c.m.damping.active);
  EXPECT_EQ(c.m.damping.curve, -1);
  EXPECT_EQ(c.m.damping.d, 250.0);
  EXPECT_EQ(c.m.damping.factor, (std::array<double, 3>{1, 1, 1}));
  Read k = read_text(block_deck("*DAMPING_GLOBAL\n        12       0.0       1.0       0.5       0.0\n"));
  ASSERT_TRUE(k.ok) << k.messages();
  EXPECT_EQ(k.m.damping.curve, 1);  // the second curve (id 12)
  EXPECT_EQ(k.m.damping.factor, (std::array<double, 3>{1, 0.5, 0}));
  EXPECT_EQ(k.d.count(2004), 1) << k.messages();  // curve 11 unused; 12 is the damping's
  std::ostringstream kw;
  std::vector<std::string> notes;
  write_keyword_deck(kw, k.m, &notes);
  Read k2 = read_text(kw.str());
  ASSERT_TRUE(k2.ok) << k2.messages() << kw.str();
  EXPECT_EQ(join(model_differences(k.m, k2.m, 50)), "") << kw.str();
  std::ostringstream fx;
  notes.clear();
  write_fixed_deck(fx, k.m, &notes);
  EXPECT_NE(join(notes).find("*DAMPING_GLOBAL"), std::string::npos);
  // no damping: a blank card, or VALDMP 0 without a curve
  Read none = read_text(block_deck("*DAMPING_GLOBAL\n         0       0.0\n"));
  ASSERT_TRUE(none.ok) << none.messages();
  EXPECT_FALSE(none.m.damping.active);
  // refusals: negative constant or factor, undefined curve
  Read bad = read_text(block_deck("*DAMPING_GLOBAL\n        99    -250.0      -1.0\n"));
  EXPECT_FALSE(bad.ok);
  EXPECT_EQ(bad.d.count(1003), 2) << bad.messages();
  EXPECT_EQ(bad.d.count(1310), 1) << bad.messages();
}
