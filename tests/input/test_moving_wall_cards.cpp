// Moving stonewalls in the input: fixed format card 1 columns 6-10 = 1 and a card with MASS
// (1-10) and V0 (11-20) (IMPACT-3D choice); *RIGIDWALL_PLANAR_MOVING (and _MOVING_ID) card 3
// MASS, V0; the converter both ways; errors with card and columns.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "tests/input/input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

const std::string kWall = "    0    00.0000e+000.0000e+00-1.000e-040.0000e+000.0000e+001.0000e+000.0000e+00\n";

std::string tiny_with_wall(const std::string& flag, const std::string& card2) {
  std::string t = tiny_deck();
  const std::size_t at = t.find(kWall);
  EXPECT_NE(at, std::string::npos);
  std::string wall = kWall;
  wall.replace(5, 5, flag);
  return t.replace(at, kWall.size(), wall + card2);
}

}  // namespace

TEST(MovingWallCards, FixedFormatKeywordAndBack) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(tiny_with_wall("    1", "1.0000e+02-5.000e+00\n"), m, d)) << all_messages(d);
  ASSERT_EQ(m.walls.size(), 1u);
  EXPECT_EQ(m.walls[0].mass, 100.0);
  EXPECT_EQ(m.walls[0].v0, -5.0);
  std::ostringstream kw;
  write_keyword_deck(kw, m);
  EXPECT_NE(kw.str().find("*RIGIDWALL_PLANAR_MOVING\n"), std::string::npos);
  Model k;
  Diagnostics dk;
  ASSERT_TRUE(read_any(kw.str(), k, dk, "w.k")) << all_messages(dk);
  EXPECT_TRUE(model_differences(m, k).empty());
  std::ostringstream fx;
  write_fixed_deck(fx, k);
  Model back;
  Diagnostics db;
  ASSERT_TRUE(read_any(fx.str(), back, db, "w.dyn")) << all_messages(db);
  EXPECT_TRUE(model_differences(m, back).empty());
  // _MOVING_ID: the id card first
  std::string text = kw.str();
  text.replace(text.find("*RIGIDWALL_PLANAR_MOVING\n"), 25, "*RIGIDWALL_PLANAR_MOVING_ID\n         7floor\n");
  Model id;
  Diagnostics di;
  ASSERT_TRUE(read_any(text, id, di, "id.k")) << all_messages(di);
  EXPECT_EQ(id.walls[0].mass, 100.0);
}

TEST(MovingWallCards, ErrorsNameCardAndColumns) {
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_string(tiny_with_wall("    1", "0.0000e+00-5.000e+00\n"), m, d));
  const std::string msg = all_messages(d);
  EXPECT_TRUE(d.has(1003)) << msg;
  EXPECT_NE(msg.find("MASS"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cols 1-10"), std::string::npos) << msg;
  Model m2;
  Diagnostics d2;
  EXPECT_FALSE(read_string(tiny_with_wall("    2", ""), m2, d2));
  EXPECT_TRUE(d2.has(1006)) << all_messages(d2);
  EXPECT_NE(all_messages(d2).find("cols 6-10"), std::string::npos) << all_messages(d2);
}

// A wall's node list is a set: a node listed twice counts once (its mass would otherwise count
// twice for a moving wall).
TEST(MovingWallCards, RepeatedWallNodesCountOnce) {
  std::string wall = kWall;
  wall.replace(0, 5, "    3");
  std::string t = tiny_deck();
  t.replace(t.find(kWall), kWall.size(), wall + "       1       2       1\n");
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(t, m, d)) << all_messages(d);
  EXPECT_EQ(m.walls[0].nodes, (std::vector<int>{0, 1}));
}

// A model the fixed format cannot hold (a count beyond its I5 columns) is not written: the
// converter fails with exit code 2 and leaves no file.
TEST(MovingWallCards, ConverterRefusesCountsThatDoNotFit) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(tiny_deck(), m, d));
  InitialVelocity iv;
  iv.first = iv.last = 1;
  m.init_velocities.assign(100000, iv);
  m.control.num_init_velocity_cards = 100000;
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/too_many_cards.dyn";
  std::remove(path.c_str());
  std::ostringstream log;
  EXPECT_EQ(write_converted_decks(m, "", path, log), 2) << log.str();
  EXPECT_NE(log.str().find("does not fit columns"), std::string::npos) << log.str();
  EXPECT_FALSE(std::ifstream(path).good());
}
