// What a distributed run refuses (message 3007, impact3d/parallel/distributed_cycle.h): the
// list names each feature the distributed cycle does not carry yet; solid-only decks with
// fixed stonewalls run.
#include <gtest/gtest.h>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/parallel/distributed_cycle.h"

using namespace impact3d;

namespace {

std::string refusal(const std::string& deck, int nranks) {
  Model m;
  Diagnostics d;
  EXPECT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/" + deck, m, d)) << deck;
  return parallel::distributed_refusal(m, nranks);
}

}  // namespace

TEST(DistributedRefusal, SolidDecksWithFixedWallsRun) {
  EXPECT_EQ(refusal("decks/taylor_bar.dyn", 4), "");
  EXPECT_EQ(refusal("decks/keyword/taylor_bar.k", 3), "");
  EXPECT_EQ(refusal("decks/bar_wall_elastic.dyn", 2), "");
  EXPECT_EQ(refusal("tests/parallel/free_bar.k", 3), "");
  EXPECT_EQ(refusal("tests/parallel/free_bar_elform2.k", 3), "");
}

TEST(DistributedRefusal, NamesWhatIsNotCarried) {
  EXPECT_NE(refusal("decks/two_bars.dyn", 2).find("sliding interfaces"), std::string::npos);
  EXPECT_NE(refusal("decks/thick_cylinder.dyn", 2).find("loads or prescribed motions"), std::string::npos);
  EXPECT_NE(refusal("decks/keyword/scordelis_lo_roof.k", 2).find("shells"), std::string::npos);
  // one solid: one block, so at most one rank
  EXPECT_EQ(refusal("decks/one_hex.dyn", 1), "");
  EXPECT_EQ(refusal("decks/one_hex.dyn", 2), "1 blocks of solids for 2 ranks (one block of 8 solids per rank at least)");
}
