// Shells in the time histories and the printed echo: *DATABASE_HISTORY_SHELL (and the fixed
// format's shell time-history blocks) put the listed shells into the d3thdt family (their nodes,
// deck ids, the d3plot shell words) and into elout (mid-surface, inner and outer stresses and
// plastic strains); the printed echo summarises the shells.  Everything is read back here.

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

std::string I(long v, int w) {
  char b[32];
  std::snprintf(b, sizeof b, "%*ld", w, v);
  return b;
}
std::string E(double v, int w) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.8e", w, v);
  return b;
}

// A clamped plastic strip of 12 x 1 shells with deck ids 101-112, shells 103, 105 and 106 and
// node 7 in the time histories.
std::string strip_deck() {
  const int nx = 12;
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nshell strip with shell time histories\n*CONTROL_TERMINATION\n 4.000e-04\n"
    << "*DATABASE_BINARY_D3PLOT\n 1.000e-04\n*DATABASE_GLSTAT\n 2.000e-05\n"
    << "*DATABASE_HISTORY_SHELL\n     103     105     106\n*DATABASE_HISTORY_NODE\n       7\n"
    << "*PART\nstrip\n         1         1         1\n"
    << "*SECTION_SHELL\n         1         2  0.833333         3\n    0.0100\n"
    << "*MAT_PLASTIC_KINEMATIC\n         1    7850.0   2.1e+11       0.3   2.5e+08   2.0e+09       1.0\n*NODE\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= nx; ++i) d << I(1 + i + (nx + 1) * j, 8) << E(0.5 * i / nx, 16) << E(0.02 * j, 16) << E(0, 16) << "\n";
  d << "*ELEMENT_SHELL\n";
  for (int i = 0; i < nx; ++i)
    d << I(101 + i, 8) << I(1, 8) << I(1 + i, 8) << I(2 + i, 8) << I(2 + i + nx + 1, 8) << I(1 + i + nx + 1, 8) << "\n";
  d << "*SET_NODE_LIST\n         1\n         1" << I(nx + 2, 10) << "\n"
    << "*BOUNDARY_SPC_SET\n         1         0         1         1         1         1         1         1\n"
    << "*INITIAL_VELOCITY\n         0\n       0.0       0.0      20.0\n*END\n";
  return d.str();
}

Model read_text(const std::string& text, const std::string& name) { return test_support::read_model_text(text, name); }

fs::path run_in(const Model& m, const std::string& name) { return test_support::run_model_in(m, "shell_history_runs", name); }

// elout's shell rows of the last block: id, material, surface, 6 stresses, von Mises, eps
struct EloutShellRow {
  int id = 0, mat = 0;
  std::string surface;
  double v[8] = {};
};
std::vector<EloutShellRow> last_elout_shell_block(const fs::path& file, int* blocks) {
  std::ifstream in(file);
  std::string line;
  std::vector<EloutShellRow> rows;
  *blocks = 0;
  bool in_shells = false;
  while (std::getline(in, line)) {
    if (line.find("s h e l l   e l e m e n t") != std::string::npos) {
      rows.clear();
      ++*blocks;
      in_shells = true;
      std::getline(in, line);  // column heads
      continue;
    }
    if (!in_shells) continue;
    EloutShellRow r;
    char surf[16];
    if (std::sscanf(line.c_str(), "%d %d %15s %lf %lf %lf %lf %lf %lf %lf %lf", &r.id, &r.mat, surf, &r.v[0], &r.v[1],
                    &r.v[2], &r.v[3], &r.v[4], &r.v[5], &r.v[6], &r.v[7]) == 11) {
      r.surface = surf;
      rows.push_back(r);
    } else if (!line.empty()) {
      in_shells = false;
    }
  }
  return rows;
}

}  // namespace

TEST(ShellHistories, D3thdtAndEloutHoldTheListedShells) {
  const Model m = read_text(strip_deck(), "strip.k");
  ASSERT_EQ(m.shell_th_blocks.size(), 2u);  // 103, then 105-106
  const fs::path dir = run_in(m, "keyword");
  // d3thdt: the three shells with their deck ids, their nodes and node 7, the d3plot's words
  PlotReader th;
  th.open((dir / "d3thdt").string());
  const PlotGeometry& g = th.geometry();
  ASSERT_EQ(g.num_shells(), 3);
  EXPECT_EQ(g.num_hexes(), 0);
  EXPECT_EQ(g.shell_user_ids, (std::vector<int>{103, 105, 106}));
  // shells 103, 105, 106: nodes 3 4 17 16, 5 6 19 18, 6 7 20 19 -> 10 nodes, 7 among them
  EXPECT_EQ(g.x0.size(), 3u * 10u);
  ASSERT_EQ(th.num_states(), 21);  // every 2e-5 over 4e-4, and t = 0
  PlotReader pl;
  pl.open((dir / "d3plot").string());
  ASSERT_EQ(pl.num_states(), 5);
  const int nv = kShellPlotVars;
  int compared = 0;
  for (int p = 0; p < pl.num_states(); ++p) {
    const PlotState ps = pl.state(p);
    for (int t = 0; t < th.num_states(); ++t) {
      if (std::fabs(th.time(t) - pl.time(p)) > 1e-12) continue;
      const PlotState ts = th.state(t);
      const int shells[3] = {2, 4, 5};  // 0-based model shells of ids 103, 105, 106
      for (int k = 0; k < 3; ++k)
        for (int w = 0; w < nv; ++w)
          EXPECT_EQ(ts.shell_vars[std::size_t(nv * k + w)], ps.shell_vars[std::size_t(nv * shells[k] + w)])
              << "state " << t << " shell " << k << " word " << w;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 5);
  const PlotState last = th.state(th.num_states() - 1);
  double largest = 0;
  for (double v : last.shell_vars) largest = std::max(largest, std::fabs(v));
  EXPECT_GT(largest, 1e6);  // the strip bends: stresses, not zeros
  // elout: one shell block per history time, three surfaces per shell, the same numbers as the
  // last d3thdt state to its printed digits (%12.4E)
  int blocks = 0;
  const auto rows = last_elout_shell_block(dir / "elout", &blocks);
  EXPECT_EQ(blocks, 21);
  ASSERT_EQ(rows.size(), 9u);
  const char* surfaces[3] = {"mid", "inner", "outer"};
  const int ids[3] = {103, 105, 106};
  for (int k = 0; k < 3; ++k)
    for (int layer = 0; layer < 3; ++layer) {
      const EloutShellRow& r = rows[std::size_t(3 * k + layer)];
      EXPECT_EQ(r.id, ids[k]);
      EXPECT_EQ(r.mat, 1);
      EXPECT_EQ(r.surface, surfaces[layer]);
      const double* w = &last.shell_vars[std::size_t(nv * k + 7 * layer)];
      for (int c = 0; c < 6; ++c) EXPECT_NEAR(r.v[c], w[c], 1e-4 * largest + 6e-5 * std::fabs(w[c])) << k << " " << layer << " " << c;
      EXPECT_NEAR(r.v[7], w[6], 1e-8 + 6e-5 * w[6]);  // plastic strain
      // von Mises of the printed components
      const double* s = r.v;
      const double vm = std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) + (s[2] - s[0]) * (s[2] - s[0])) +
                                  3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
      EXPECT_NEAR(r.v[6], vm, 2e-4 * largest);
    }
  // bending: the outer and inner surfaces of the root-side shell carry opposite axial stresses
  EXPECT_LT(rows[1].v[0] * rows[2].v[0], 0.0);
  // nodout holds node 7
  std::ifstream nod(dir / "nodout");
  std::string all((std::istreambuf_iterator<char>(nod)), std::istreambuf_iterator<char>());
  EXPECT_NE(all.find("\n         7 "), std::string::npos);
}

// The fixed-format twin (shell time-history blocks on control card 3) writes the same shell
// words into d3thdt, with the ids renumbered 1..N as the fixed format numbers shells.
TEST(ShellHistories, FixedFormatShellBlocksGiveTheSameHistories) {
  const Model k = read_text(strip_deck(), "strip.k");
  std::ostringstream fixed;
  write_fixed_deck(fixed, k, nullptr);
  const Model f = read_text(fixed.str(), "strip.dyn");
  ASSERT_EQ(f.shell_th_blocks, (std::vector<std::array<int, 2>>{{3, 3}, {5, 6}}));
  const fs::path dk = run_in(k, "twin_keyword"), df = run_in(f, "twin_fixed");
  PlotReader a, b;
  a.open((dk / "d3thdt").string());
  b.open((df / "d3thdt").string());
  EXPECT_EQ(b.geometry().shell_user_ids, (std::vector<int>{3, 5, 6}));
  ASSERT_EQ(a.num_states(), b.num_states());
  for (int t = 0; t < a.num_states(); t += 5) {
    EXPECT_EQ(a.state(t).shell_vars, b.state(t).shell_vars) << t;
    EXPECT_EQ(a.state(t).coords, b.state(t).coords) << t;
  }
}

// The printed echo: per part counts and ranges, the first ten shells, the rest counted, the
// rotational constraints, the shell time-history blocks by deck id.
TEST(ShellHistories, PrintedEchoSummarisesTheShells) {
  const Model m = read_text(strip_deck(), "strip.k");
  std::ostringstream os;
  write_model_summary(os, m);
  const std::string s = os.str();
  EXPECT_NE(s.find("s h e l l   e l e m e n t s"), std::string::npos) << s;
  EXPECT_NE(s.find("material 1: 12 shell(s), thickness 1.0000e-02 to 1.0000e-02 (length), area 8.3333e-04 to 8.3333e-04"),
            std::string::npos) << s;
  EXPECT_NE(s.find("     101         1         1         2        15        14   1.0000e-02"), std::string::npos) << s;
  EXPECT_NE(s.find("     110 "), std::string::npos) << s;
  EXPECT_EQ(s.find("     111 "), std::string::npos) << s;
  EXPECT_NE(s.find("... and 2 more shell(s)"), std::string::npos) << s;
  EXPECT_NE(s.find("rx ry rz: 2 node(s): 1, 14"), std::string::npos) << s;
  EXPECT_NE(s.find("shells 103 to 103"), std::string::npos) << s;
  EXPECT_NE(s.find("shells 105 to 106"), std::string::npos) << s;
  EXPECT_NE(s.find("shell time-history blocks ............ 2"), std::string::npos) << s;
}
