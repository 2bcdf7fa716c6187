// What a distributed run refuses (message 3007, impact3d/parallel/distributed_cycle.h): the
// list names each feature the distributed cycle does not carry yet; decks of solids, shells and
// beams with fixed stonewalls run.
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
  EXPECT_EQ(refusal("tests/parallel/shell_tube.k", 3), "");        // shells and solids
  EXPECT_EQ(refusal("tests/parallel/shell_tube_beams.k", 3), "");  // and beams
}

TEST(DistributedRefusal, LoadsAndPrescribedMotionsRun) {
  EXPECT_EQ(refusal("tests/parallel/free_bar_loads.k", 3), "");    // nodal, pressure, body loads, damping
  EXPECT_EQ(refusal("tests/parallel/free_bar_motions.k", 3), "");  // prescribed motions and a stonewall
  EXPECT_EQ(refusal("tests/parallel/shell_tube_loads.k", 3), "");  // on shells, a rotation too
  EXPECT_EQ(refusal("decks/thick_cylinder.dyn", 2), "");            // fixed-format pressure cards
  EXPECT_EQ(refusal("decks/keyword/thick_cylinder.k", 2), "");
  EXPECT_EQ(refusal("decks/keyword/bar_pulled.k", 2), "");          // a prescribed motion, pressures, a body load
  EXPECT_EQ(refusal("decks/keyword/scordelis_lo_roof.k", 2), "");   // shells under a body load, damped
  EXPECT_EQ(refusal("tests/keyword/beam_frame.k", 2), "");          // beams under an end load
}

TEST(DistributedRefusal, NamesWhatIsNotCarried) {
  EXPECT_NE(refusal("decks/two_bars.dyn", 2).find("sliding interfaces"), std::string::npos);
  // one solid: one block, so at most one rank
  EXPECT_EQ(refusal("decks/one_hex.dyn", 1), "");
  EXPECT_EQ(refusal("decks/one_hex.dyn", 2),
            "1 blocks of solids, shells and beams for 2 ranks (one block of 8 elements per rank at least)");
}

namespace {

// A deck of tests/parallel with one card replaced, read and checked; its refusal on 2 ranks.
std::string refusal_with(const std::string& deck, const std::string& card, const std::string& by) {
  std::ifstream in(std::string(IMPACT3D_SOURCE_DIR) + "/tests/parallel/" + deck);
  std::stringstream text;
  text << in.rdbuf();
  std::string k = text.str();
  const std::size_t at = k.find(card);
  EXPECT_NE(at, std::string::npos) << card;
  if (at == std::string::npos) return "";
  k.replace(at, card.size(), by);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "impact3d_refusal_with";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / deck) << k;
  Model m;
  Diagnostics d;
  EXPECT_TRUE(read_and_check_deck((dir / deck).string(), m, d));
  std::filesystem::remove_all(dir);
  return parallel::distributed_refusal(m, 2);
}

}  // namespace

TEST(DistributedRefusal, ShellFailureIsNamed) {
  // the shell tube with a failure strain FS on its elastic-plastic copper shells
  EXPECT_EQ(refusal_with("shell_tube.k", "       0.0       0.0       0.0       0.0\n",
                         "       0.0       0.0       0.3       0.0\n"),
            "shell failure (FS, FAIL, TDEL)");
}

TEST(DistributedRefusal, SpotWeldBeamsAreNamed) {
  // the Hughes-Liu ring of the tube with beams of *MAT_SPOTWELD (its failure rule deletes beams)
  EXPECT_EQ(refusal_with("shell_tube_beams.k",
                         "*MAT_PLASTIC_KINEMATIC\n         5    7850.0   2.10e11      0.30     2.0e8     1.0e9       1.0\n",
                         "*MAT_SPOTWELD\n         5    7850.0   2.10e11      0.30     5.0e8       0.0       0.0       0.0\n"),
            "spot-weld beams (*MAT_SPOTWELD)");
}
