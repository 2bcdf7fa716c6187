// Rigid-wall normal forces travel in the plot database's globals (one word per wall after the
// per-part block, as LS-DYNA writes for VERSION < 971), then three words per sliding interface
// (their count in control word 63), and come back through our reader.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/plot_database.h"

using namespace impact3d;

TEST(PlotGlobals, RigidWallForcesRoundTrip) {
  const std::string dir = std::string(IMPACT3D_BINARY_DIR) + "/test_rigid_wall_globals";
  std::filesystem::create_directories(dir);
  PlotGeometry g;
  g.title = "one hex, two walls";
  g.num_materials = 1;
  g.num_rigid_walls = 2;
  g.x0 = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  g.hex_nodes = {0, 1, 2, 3, 4, 5, 6, 7};
  g.hex_material = {1};
  for (int ws : {4, 8}) {
    PlotWriter w;
    w.open(dir + "/d3plot", g, ws);
    PlotState s;
    s.time = 1.5e-6;
    s.rigid_wall_forces = {1234.5, -0.25};
    w.write_state(s);
    w.close();
    PlotReader r;
    r.open(dir + "/d3plot");
    EXPECT_EQ(r.control().nglbv, 6 + 7 + 2);
    EXPECT_EQ(r.geometry().num_rigid_walls, 2);
    ASSERT_EQ(r.num_states(), 1);
    const PlotState back = r.state(0);
    ASSERT_EQ(back.rigid_wall_forces.size(), 2u);
    // exact in 8-byte words; float rounding (relative 6e-8) in 4-byte words
    EXPECT_NEAR(back.rigid_wall_forces[0], 1234.5, ws == 8 ? 0.0 : 1234.5 * 6e-8);
    EXPECT_NEAR(back.rigid_wall_forces[1], -0.25, ws == 8 ? 0.0 : 0.25 * 6e-8);
  }
}

TEST(PlotGlobals, InterfaceForcesFollowTheWallsAndWord63SaysHowMany) {
  const std::string dir = std::string(IMPACT3D_BINARY_DIR) + "/test_interface_globals";
  std::filesystem::create_directories(dir);
  PlotGeometry g;
  g.title = "one hex, one wall, two interfaces";
  g.num_materials = 1;
  g.num_rigid_walls = 1;
  g.num_interfaces = 2;
  g.x0 = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  g.hex_nodes = {0, 1, 2, 3, 4, 5, 6, 7};
  g.hex_material = {1};
  const std::vector<double> f = {1.5, -2.5, 3.5, 0.0, 0.0, -650.25};
  for (int ws : {4, 8}) {
    PlotWriter w;
    w.open(dir + "/d3plot", g, ws);
    PlotState s;
    s.rigid_wall_forces = {99.0};
    s.interface_forces = f;
    w.write_state(s);
    PlotState wrong = s;
    wrong.interface_forces.pop_back();
    EXPECT_THROW(w.write_state(wrong), std::invalid_argument);
    w.close();
    PlotReader r;
    r.open(dir + "/d3plot");
    EXPECT_EQ(r.control().nglbv, 6 + 7 + 1 + 6);
    EXPECT_EQ(r.control().nintf, 2);
    EXPECT_EQ(r.geometry().num_rigid_walls, 1);
    EXPECT_EQ(r.geometry().num_interfaces, 2);
    ASSERT_EQ(r.num_states(), 1);
    const PlotState back = r.state(0);
    ASSERT_EQ(back.rigid_wall_forces.size(), 1u);
    EXPECT_EQ(back.rigid_wall_forces[0], 99.0);
    EXPECT_EQ(back.interface_forces, f);  // all exact in floats
  }
  // A file whose word 63 cannot be ours (more interfaces than words after the parts: an
  // LS-DYNA database of another kind): every word after the per-part block is a rigid wall.
  {
    std::fstream io(dir + "/d3plot", std::ios::in | std::ios::out | std::ios::binary);
    const std::int64_t big = 1000;  // the last file written has 8-byte words
    io.seekp(63 * 8);
    io.write(reinterpret_cast<const char*>(&big), 8);
  }
  PlotReader r;
  r.open(dir + "/d3plot");
  EXPECT_EQ(r.geometry().num_interfaces, 0);
  EXPECT_EQ(r.geometry().num_rigid_walls, 7);
  EXPECT_EQ(r.state(0).rigid_wall_forces.size(), 7u);
  // a word 63 whose triple overflows 64 bits (3 x 0x5555555555555556 wraps to 2) is not ours
  // either
  {
    std::fstream io(dir + "/d3plot", std::ios::in | std::ios::out | std::ios::binary);
    const std::int64_t wraps = 0x5555555555555556LL;
    io.seekp(63 * 8);
    io.write(reinterpret_cast<const char*>(&wraps), 8);
  }
  PlotReader r2;
  r2.open(dir + "/d3plot");
  EXPECT_EQ(r2.geometry().num_interfaces, 0);
  EXPECT_EQ(r2.geometry().num_rigid_walls, 7);
  EXPECT_EQ(r2.state(0).rigid_wall_forces.size(), 7u);
}
