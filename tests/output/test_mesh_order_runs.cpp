// impact3d's reorder= (init/mesh_order.h) from the command line, on a Taylor bar deck (40 us)
// whose node and solid numbers are shuffled, written as a fixed-format and a keyword deck:
//   * reorder=on renumbers (the printed output says so), reorder=off and auto (972 solids,
//     below the size limit) keep the deck's order;
//   * the renumbered run's plot database carries the deck's ids (NARBS) and its final
//     coordinates per node id are the bits of the reorder=off run's (4-byte words);
//   * a restart from a dump of the renumbered run renumbers identically and writes the plot
//     database of the uninterrupted run byte for byte; reorder= on a restart is refused (exit 3).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "tests/support/shuffle_mesh.h"

namespace fs = std::filesystem;
using namespace impact3d;

namespace {

const std::string kImpact3d = IMPACT3D_BINARY_DIR "/impact3d";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("impact3d_mesh_order_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

struct CliRun {
  int code = -1;
  std::string out;
};

CliRun run_impact3d(const fs::path& dir, const std::string& args) {
  const std::string cmd = "cd '" + dir.string() + "' && SOURCE_DATE_EPOCH=1700000000 '" + kImpact3d + "' " + args +
                          " ncpu=1 > run.out 2>&1";
  CliRun r;
  const int st = std::system(cmd.c_str());
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  r.out = slurp(dir / "run.out");
  return r;
}

// The Taylor bar to 40 us (about 2300 cycles) with a dump every 1000 cycles, numbers shuffled.
std::string shuffled_taylor_deck(bool keyword) {
  Model m;
  Diagnostics d;
  EXPECT_TRUE(read_and_check_deck(IMPACT3D_SOURCE_DIR "/decks/taylor_bar.dyn", m, d));
  m.control.end_time = 4e-5;
  m.control.restart_dump_cycles = 1000;
  test_support::shuffle_mesh_numbering(m, 20261125);
  std::ostringstream os;
  if (keyword) write_keyword_deck(os, m);
  else write_fixed_deck(os, m);
  return os.str();
}

// Final coordinates by node id (the plot database's user ids).
std::map<int, std::array<double, 3>> final_coordinates(const fs::path& root, std::vector<int>* ids = nullptr) {
  PlotReader r;
  r.open(root.string());
  const PlotGeometry& g = r.geometry();
  const PlotState s = r.state(r.num_states() - 1);
  std::map<int, std::array<double, 3>> at;
  for (int n = 0; n < g.num_nodes(); ++n) {
    const int id = g.node_user_ids.empty() ? n + 1 : g.node_user_ids[std::size_t(n)];
    at[id] = {s.coords[std::size_t(3 * n)], s.coords[std::size_t(3 * n + 1)], s.coords[std::size_t(3 * n + 2)]};
  }
  if (ids) *ids = g.node_user_ids;
  return at;
}

}  // namespace

TEST(MeshOrderRuns, RenumberedShuffledTaylorBarKeepsDeckIdsAndResultsAndRestarts) {
  for (bool keyword : {false, true}) {
    SCOPED_TRACE(keyword ? "keyword deck" : "fixed-format deck");
    const std::string deck = shuffled_taylor_deck(keyword);
    const std::string name = keyword ? "deck.k" : "deck.dyn";
    const fs::path on = fresh_dir(keyword ? "on_k" : "on"), off = fresh_dir(keyword ? "off_k" : "off"),
                   deflt = fresh_dir(keyword ? "auto_k" : "auto");
    for (const fs::path& d : {on, off, deflt}) std::ofstream(d / name) << deck;

    const CliRun a = run_impact3d(on, "i=" + name + " reorder=on");
    ASSERT_EQ(a.code, 0) << a.out;
    EXPECT_NE(a.out.find("mesh order: nodes and solids renumbered for locality (reverse Cuthill-McKee, reorder=on)"),
              std::string::npos) << a.out;
    EXPECT_NE(slurp(on / "d3hsp").find("renumbered for locality"), std::string::npos);
    const CliRun b = run_impact3d(off, "i=" + name + " reorder=off");
    ASSERT_EQ(b.code, 0) << b.out;
    EXPECT_NE(b.out.find("mesh order: the deck's (reorder=off)"), std::string::npos) << b.out;
    const CliRun c = run_impact3d(deflt, "i=" + name);
    ASSERT_EQ(c.code, 0) << c.out;
    EXPECT_NE(c.out.find("mesh order: the deck's (reorder=auto: below 8192 solids and shells)"), std::string::npos) << c.out;

    // the plot database shows the deck's ids; the final coordinates per id are the same bits
    std::vector<int> ids;
    const auto xa = final_coordinates(on / "d3plot", &ids);
    const auto xb = final_coordinates(off / "d3plot");
    ASSERT_EQ(ids.size(), 1369u) << "the renumbered run writes the deck's node ids (NARBS)";
    std::vector<int> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    for (int k = 0; k < 1369; ++k) ASSERT_EQ(sorted[std::size_t(k)], k + 1);
    EXPECT_NE(ids, sorted) << "renumbered: the ids are not in internal order";
    EXPECT_EQ(xa, xb);
    EXPECT_EQ(slurp(deflt / "d3plot"), slurp(off / "d3plot")) << "auto kept the deck's order: the same database";
    // the ASCII time histories name the same nodes and solids (deck ids) with the same values
    EXPECT_EQ(slurp(on / "nodout"), slurp(off / "nodout"));

    // restart from the first dump: the same plot database, byte for byte
    std::map<std::string, std::string> uninterrupted;
    for (const auto& f : fs::directory_iterator(on))
      if (f.path().filename().string().rfind("d3plot", 0) == 0) uninterrupted[f.path().filename().string()] = slurp(f.path());
    ASSERT_GE(uninterrupted.size(), 2u);
    const CliRun r = run_impact3d(on, "r=d3dump01");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("renumbered for locality (reverse Cuthill-McKee, reorder=on): locality cost"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("(as the run that wrote the dump)"), std::string::npos) << r.out;
    for (const auto& [file, bytes] : uninterrupted) EXPECT_TRUE(slurp(on / file) == bytes) << file << " differs after the restart";
    const CliRun bad = run_impact3d(on, "r=d3dump01 reorder=off");
    EXPECT_EQ(bad.code, 3) << bad.out;
    EXPECT_NE(bad.out.find("reorder= cannot change on a restart"), std::string::npos) << bad.out;
  }
  const CliRun bad = run_impact3d(fresh_dir("bad"), "i=deck.dyn reorder=maybe");
  EXPECT_EQ(bad.code, 3);
  EXPECT_NE(bad.out.find("reorder must be auto, on or off"), std::string::npos) << bad.out;
  if (!HasFailure()) fs::remove_all(fresh_dir("bad").parent_path());
}
