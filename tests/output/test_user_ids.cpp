// A keyword deck with sparse ids keeps its numbers in what users see: the plot database's
// NARBS section and the model's id accessors.
#include <gtest/gtest.h>

#include <sstream>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/output/plot_output.h"

using namespace impact3d;

TEST(UserIds, SparseKeywordIdsReachThePlotDatabase) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/tests/output/sparse_ids.k", m, diag))
      << [&] { std::ostringstream os; diag.print(os); return os.str(); }();
  ASSERT_EQ(m.num_nodes(), 12);
  ASSERT_EQ(m.num_hexes(), 2);
  EXPECT_EQ(m.node_id(0), 101);
  EXPECT_EQ(m.node_id(11), 112);
  EXPECT_EQ(m.hex_id(0), 701);
  EXPECT_EQ(m.hex_id(1), 702);
  const PlotGeometry g = make_plot_geometry(m);
  ASSERT_EQ(g.node_user_ids.size(), 12u);
  EXPECT_EQ(g.node_user_ids.front(), 101);
  EXPECT_EQ(g.node_user_ids.back(), 112);
  EXPECT_EQ(g.hex_user_ids, (std::vector<int>{701, 702}));
  EXPECT_EQ(g.num_rigid_walls, 1);
}
