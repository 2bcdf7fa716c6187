// What a distributed run refuses (message 3007, impact3d/parallel/distributed_cycle.h): the
// list names each feature the distributed cycle does not carry yet; solid-only decks with
// fixed stonewalls run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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
  EXPECT_EQ(refusal("tests/parallel/shell_tube.k", 3), "");  // shells and solids
}

TEST(DistributedRefusal, NamesWhatIsNotCarried) {
  EXPECT_NE(refusal("decks/two_bars.dyn", 2).find("sliding interfaces"), std::string::npos);
  EXPECT_NE(refusal("decks/thick_cylinder.dyn", 2).find("loads or prescribed motions"), std::string::npos);
  // shells run; the roof's load and supports do not yet
  EXPECT_EQ(refusal("decks/keyword/scordelis_lo_roof.k", 2).find("shells"), std::string::npos);
  EXPECT_NE(refusal("decks/keyword/scordelis_lo_roof.k", 2).find("loads or prescribed motions"), std::string::npos);
  // one solid: one block, so at most one rank
  EXPECT_EQ(refusal("decks/one_hex.dyn", 1), "");
  EXPECT_EQ(refusal("decks/one_hex.dyn", 2),
            "1 blocks of solids and shells for 2 ranks (one block of 8 solids or 8 shells per rank at least)");
}

TEST(DistributedRefusal, ShellFailureIsNamed) {
  // the shell tube with a failure strain FS on its elastic-plastic copper shells
  std::ifstream in(std::string(IMPACT3D_SOURCE_DIR) + "/tests/parallel/shell_tube.k");
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  const std::string card2 = "       0.0       0.0       0.0       0.0\n";
  const std::size_t at = deck.find(card2);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, card2.size(), "       0.0       0.0       0.3       0.0\n");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "impact3d_refusal_shell_fs";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tube_fs.k") << deck;
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_and_check_deck((dir / "tube_fs.k").string(), m, d));
  EXPECT_EQ(parallel::distributed_refusal(m, 2), "shell failure (FS, FAIL, TDEL)");
  std::filesystem::remove_all(dir);
}
