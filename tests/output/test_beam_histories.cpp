// Beams in the time histories: *DATABASE_HISTORY_BEAM (and the fixed format's beam
// time-history blocks, control card 3 field 3) put the listed beams into the d3thdt family
// (their nodes, deck ids, the d3plot's beam records) and into elout (the resultants in the
// beam's axes: axial force, shear forces, bending moments, torsion).  Read back here, against a
// closed form: a clamped bar of five beams pulled at its free end by F = k t carries N = k t in
// every beam (quasi-static: its axial period 4 L / c = 0.39 ms against 20 ms) and no shear,
// bending or torsion.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/printed_output.h"
#include "impact3d/solve/run.h"
#include "tests/support/history_runs.h"

using namespace impact3d;
namespace fs = std::filesystem;

namespace {

constexpr double kRate = 1e6;    // N/s
constexpr double kEnd = 0.02;    // s

// Five Hughes-Liu beams (10 mm square, 0.1 m each, ids 11-15) from node 1 (clamped) to node 6
// along x, oriented by node 7; beams 12, 14 and 15 in the time histories.
std::string bar_deck() {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nbar with beam time histories\n*CONTROL_TERMINATION\n" << kEnd << "\n"
    << "*DATABASE_BINARY_D3PLOT\n 5.000e-03\n*DATABASE_GLSTAT\n 1.000e-03\n"
    << "*DATABASE_HISTORY_BEAM\n      12      14      15\n"
    << "*PART\nbar\n         1         1         1\n"
    << "*SECTION_BEAM\n         1         1  0.833333         2         0\n      0.01      0.01      0.01      0.01\n"
    << "*MAT_ELASTIC\n         1    7850.0   2.1e+11       0.3\n*NODE\n";
  for (int i = 0; i <= 5; ++i) {
    char b[128];
    std::snprintf(b, sizeof b, "%8d%16.6f%16.6f%16.6f%8d%8d\n", i + 1, 0.1 * i, 0.0, 0.0, i == 0 ? 7 : 0, i == 0 ? 7 : 0);
    d << b;
  }
  d << "       7             0.0             1.0             0.0       7\n*ELEMENT_BEAM\n";
  for (int i = 0; i < 5; ++i) {
    char b[96];
    std::snprintf(b, sizeof b, "%8d%8d%8d%8d%8d\n", 11 + i, 1, i + 1, i + 2, 7);
    d << b;
  }
  d << "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n                 1.0               1.0e6\n"
    << "*LOAD_NODE_POINT\n         6         1         1       1.0\n*END\n";
  return d.str();
}

Model read_text(const std::string& text, const std::string& name) { return test_support::read_model_text(text, name); }

fs::path run_in(const Model& m, const std::string& name) { return test_support::run_model_in(m, "beam_history_runs", name); }

// elout's beam rows of the last block: id, material, N, Q_s, Q_t, M_s, M_t, T
struct EloutBeamRow {
  int id = 0, mat = 0;
  double v[6] = {};
};
std::vector<EloutBeamRow> last_elout_beam_block(const fs::path& file, int* blocks) {
  std::ifstream in(file);
  std::string line;
  std::vector<EloutBeamRow> rows;
  *blocks = 0;
  bool in_beams = false;
  while (std::getline(in, line)) {
    if (line.find("r e s u l t a n t s   f o r   b e a m s") != std::string::npos) {
      rows.clear();
      ++*blocks;
      in_beams = true;
      std::getline(in, line);  // column heads
      continue;
    }
    if (!in_beams) continue;
    EloutBeamRow r;
    if (std::sscanf(line.c_str(), "%d %d %lf %lf %lf %lf %lf %lf", &r.id, &r.mat, &r.v[0], &r.v[1], &r.v[2], &r.v[3], &r.v[4],
                    &r.v[5]) == 8)
      rows.push_back(r);
    else if (!line.empty())
      in_beams = false;
  }
  return rows;
}

}  // namespace

TEST(BeamHistories, D3thdtAndEloutHoldTheListedBeams) {
  const Model m = read_text(bar_deck(), "bar.k");
  ASSERT_EQ(m.beam_th_blocks, (std::vector<std::array<int, 2>>{{2, 2}, {4, 5}}));
  const fs::path dir = run_in(m, "keyword");
  PlotReader th;
  th.open((dir / "d3thdt").string());
  const PlotGeometry& g = th.geometry();
  ASSERT_EQ(g.num_beams(), 3);
  EXPECT_EQ(g.beam_user_ids, (std::vector<int>{12, 14, 15}));
  // beams 12, 14, 15: nodes 2 3, 4 5, 5 6 and the orientation node 7 -> 6 nodes
  EXPECT_EQ(g.x0.size(), 3u * 6u);
  ASSERT_EQ(th.num_states(), 21);
  // the d3thdt records are the d3plot's, at the common times
  PlotReader pl;
  pl.open((dir / "d3plot").string());
  // the records' length (NV1D): 6 resultants and 5 words per section point (2x2 Gauss: 26)
  const std::size_t nv = pl.state(0).beam_vars.size() / 5;
  ASSERT_EQ(nv, 26u);
  int compared = 0;
  for (int p = 0; p < pl.num_states(); ++p)
    for (int t = 0; t < th.num_states(); ++t) {
      if (std::fabs(th.time(t) - pl.time(p)) > 1e-12) continue;
      const PlotState ps = pl.state(p), ts = th.state(t);
      ASSERT_EQ(ts.beam_vars.size(), 3 * nv);
      const int beams[3] = {1, 3, 4};
      for (int k = 0; k < 3; ++k)
        for (std::size_t w = 0; w < nv; ++w)
          EXPECT_EQ(ts.beam_vars[nv * std::size_t(k) + w], ps.beam_vars[nv * std::size_t(beams[k]) + w]) << t << " " << k << " " << w;
      ++compared;
    }
  EXPECT_EQ(compared, 5);
  // elout: one beam block per history time; at the end N = k t in each listed beam, no shear,
  // bending or torsion; the same numbers as the last d3thdt record (to the printed digits)
  int blocks = 0;
  const auto rows = last_elout_beam_block(dir / "elout", &blocks);
  EXPECT_EQ(blocks, 21);
  ASSERT_EQ(rows.size(), 3u);
  const PlotState last = th.state(th.num_states() - 1);
  const double N = kRate * th.time(th.num_states() - 1);
  const int ids[3] = {12, 14, 15};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(rows[std::size_t(k)].id, ids[k]);
    EXPECT_EQ(rows[std::size_t(k)].mat, 1);
    EXPECT_NEAR(rows[std::size_t(k)].v[0], N, 0.01 * N) << k;
    for (int c = 1; c < 6; ++c) EXPECT_NEAR(rows[std::size_t(k)].v[c], 0.0, 1e-6 * N) << k << " " << c;
    for (int c = 0; c < 6; ++c)
      EXPECT_NEAR(rows[std::size_t(k)].v[c], last.beam_vars[nv * std::size_t(k) + std::size_t(c)], 6e-5 * N) << k << " " << c;
    std::printf("[ measured ] beam %d: N %.6e at t = %.4f s (closed form k t = %.6e, %+.3f %%)\n", ids[k], rows[std::size_t(k)].v[0],
                th.time(th.num_states() - 1), N, 100 * (rows[std::size_t(k)].v[0] / N - 1));
  }
  // the printed echo lists the blocks by deck id
  std::ostringstream echo;
  write_model_summary(echo, m);
  const std::string all = echo.str();
  EXPECT_NE(all.find("   beams 12 to 12\n"), std::string::npos);
  EXPECT_NE(all.find("   beams 14 to 15\n"), std::string::npos);
}

// The fixed-format twin (beam time-history blocks on control card 3, no longer ignored with
// warning 2040) writes the same beam records into d3thdt, the ids renumbered 1..N.
TEST(BeamHistories, FixedFormatBeamBlocksGiveTheSameHistories) {
  const Model k = read_text(bar_deck(), "bar.k");
  std::ostringstream fixed;
  std::vector<std::string> notes;
  write_fixed_deck(fixed, k, &notes);
  DeckFile deck;
  deck.load_from_string("bar.dyn", fixed.str());
  Model f;
  Diagnostics d;
  ASSERT_TRUE(read_deck(deck, f, d, InputOptions{}) && check_model(f, d)) << fixed.str();
  for (const auto& x : d.all()) EXPECT_NE(x.id, 2040) << x.detail;
  ASSERT_EQ(f.beam_th_blocks, (std::vector<std::array<int, 2>>{{2, 2}, {4, 5}}));
  const fs::path dk = run_in(k, "twin_keyword"), df = run_in(f, "twin_fixed");
  PlotReader a, b;
  a.open((dk / "d3thdt").string());
  b.open((df / "d3thdt").string());
  EXPECT_EQ(b.geometry().beam_user_ids, (std::vector<int>{2, 4, 5}));
  ASSERT_EQ(a.num_states(), b.num_states());
  for (int t = 0; t < a.num_states(); t += 5) {
    EXPECT_EQ(a.state(t).beam_vars, b.state(t).beam_vars) << t;
    EXPECT_EQ(a.state(t).coords, b.state(t).coords) << t;
  }
}
