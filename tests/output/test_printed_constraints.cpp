// The printed output echoes the nodal constraints (node-card codes and *BOUNDARY_SPC_*): one
// line per code with the node count and the first node numbers, however many nodes; and long
// per-node initial-velocity lists as one line per velocity.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "impact3d/output/printed_output.h"
#include "../support/box_mesh.h"

using namespace impact3d;

TEST(PrintedOutput, ConstraintsEchoedOneLinePerCode) {
  Model m;
  MaterialData mat;
  mat.number = 1;
  mat.type = 1;
  mat.rho = 7800;
  mat.E = 2e11;
  mat.nu = 0.3;
  m.materials = {mat};
  test_support::Box b;
  b.nx = b.ny = b.nz = 10;  // 1331 nodes
  test_support::add_box(m, b, 0);
  m.bc.assign(std::size_t(m.num_nodes()), 0);
  for (int i = 0; i < 121; ++i) m.bc[std::size_t(i)] = 3;  // the z = 0 face
  m.bc[std::size_t(m.num_nodes() - 1)] = 7;
  std::ostringstream os;
  write_model_summary(os, m);
  const std::string out = os.str();
  EXPECT_NE(out.find(" c o n s t r a i n t s"), std::string::npos) << out;
  EXPECT_NE(out.find("code 3 (z fixed) ...................... 121 node(s): 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, ...\n"),
            std::string::npos) << out;
  EXPECT_NE(out.find("code 7 (x, y, z fixed) ................ 1 node(s): 1331\n"), std::string::npos) << out;
  EXPECT_EQ(out.find("code 1 "), std::string::npos) << out;
  // no constraints: no section
  m.bc.assign(std::size_t(m.num_nodes()), 0);
  std::ostringstream none;
  write_model_summary(none, m);
  EXPECT_EQ(none.str().find("c o n s t r a i n t s"), std::string::npos);
}

TEST(PrintedOutput, PerNodeInitialVelocitiesSummarised) {
  Model m;
  MaterialData mat;
  mat.number = 1;
  mat.type = 1;
  mat.rho = 7800;
  mat.E = 2e11;
  mat.nu = 0.3;
  m.materials = {mat};
  test_support::Box b;
  b.nx = b.ny = b.nz = 10;
  test_support::add_box(m, b, 0);
  // every other node of the first 1000 (500 ranges of one node), then one range of another
  // velocity: two lines
  for (int n = 1; n <= 1000; n += 2) {
    InitialVelocity iv;
    iv.first = iv.last = n;
    iv.v = {0, 0, -50};
    m.init_velocities.push_back(iv);
  }
  InitialVelocity other;
  other.first = 1001;
  other.last = 1331;
  other.v = {1, 0, 0};
  m.init_velocities.push_back(other);
  std::ostringstream os;
  write_model_summary(os, m);
  const std::string out = os.str();
  EXPECT_NE(out.find("   500 nodes in 500 ranges (1 to 1 step 1, 3 to 3 step 1, 5 to 5 step 1, ...): (0, 0, -50) (length/time)\n"
                     "   nodes 1001 to 1331 step 1: (1, 0, 0) (length/time)\n\n"),
            std::string::npos)
      << out;
}
