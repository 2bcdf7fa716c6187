// A keyword deck as LS-DYNA users write it: a steel strip of shells (*PART, *SECTION_SHELL,
// *MAT_PIECEWISE_LINEAR_PLASTICITY with its flow curve as *DEFINE_CURVE LCSS, Cowper-Symonds C
// and P, FAIL) pulled at one end by *BOUNDARY_PRESCRIBED_MOTION_SET.  It runs through
// run_simulation (what impact3d runs); its d3plot opens with the shells' plastic strains and
// deletion flags (a deleted shell has every point at FAIL, a live one not); the same curve as an
// EPS/ES table runs to the same bits; the converter writes it in both formats and reads it back
// as the same Model (test_keyword_shell_refusals.cpp: what shells refuse).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "common/plot_database.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/material/material_types.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "tests/keyword/shell_piecewise_deck.h"
#include "../support/deck_text.h"

using namespace impact3d;
namespace fs = std::filesystem;

using namespace shell_piecewise_test;

TEST(KeywordShellPiecewise, PulledStripRunsAndItsD3plotHoldsPlasticStrainAndDeletion) {
  Model m;
  Diagnostics dg;
  ASSERT_TRUE(read_text(strip_deck(), "strip24.k", m, dg)) << messages(dg);
  ASSERT_EQ(m.num_shells(), 20);
  ASSERT_EQ(m.materials[0].type, 24);
  EXPECT_TRUE(m.materials[0].shell);
  const fs::path dir = test_support::empty_run_folder("shell_piecewise_runs", "strip");
  RunOptions o = test_support::run_options_in(dir);
  {
    std::ofstream printed(o.printed);
    ASSERT_EQ(run_simulation(m, o, printed), 0);
  }
  PlotReader pl;
  pl.open((dir / "d3plot").string());
  ASSERT_EQ(pl.geometry().num_shells(), 20);
  ASSERT_EQ(pl.num_states(), 13);  // every 1e-4 to 1.2e-3, and t = 0
  const int nv = kShellPlotVars;
  double most = 0;
  int deleted_last = 0, first_deleted_state = -1;
  for (int t = 0; t < pl.num_states(); ++t) {
    const PlotState ps = pl.state(t);
    ASSERT_EQ(ps.shell_alive.size(), 20u);
    for (int k = 0; k < 20; ++k) {
      // plastic strain words of the inner and outer surfaces (NIP 2: the two points)
      const double in = ps.shell_vars[std::size_t(nv * k + 7 + 6)], out = ps.shell_vars[std::size_t(nv * k + 14 + 6)];
      most = std::max({most, in, out});
      if (ps.shell_alive[std::size_t(k)]) {
        EXPECT_LT(std::min(in, out), kFail) << "state " << t << " shell " << k;
      } else {
        EXPECT_GE(std::min(in, out), kFail) << "state " << t << " shell " << k;
        if (first_deleted_state < 0) first_deleted_state = t;
        if (t + 1 == pl.num_states()) ++deleted_last;
      }
    }
  }
  EXPECT_GT(most, 0.03);
  EXPECT_GT(deleted_last, 0);
  EXPECT_GT(first_deleted_state, 3);
  RecordProperty("largest_plastic_strain_word", std::to_string(most));
  RecordProperty("deleted_at_end", std::to_string(deleted_last));
}

// The curve as an EPS/ES table is the same model to the engine: the same bits after 300 cycles.
TEST(KeywordShellPiecewise, CurveAndTableRunToTheSameBits) {
  Model a, b;
  Diagnostics da, db;
  ASSERT_TRUE(read_text(strip_deck(false), "curve.k", a, da)) << messages(da);
  ASSERT_TRUE(read_text(strip_deck(true), "table.k", b, db)) << messages(db);
  Engine ea(a), eb(b);
  ASSERT_EQ(ea.initialize(), StepStatus::ok);
  ASSERT_EQ(eb.initialize(), StepStatus::ok);
  for (int c = 0; c < 300; ++c) {
    ASSERT_EQ(ea.step(), StepStatus::ok);
    ASSERT_EQ(eb.step(), StepStatus::ok);
  }
  EXPECT_EQ(ea.state().shells.sig, eb.state().shells.sig);
  EXPECT_EQ(ea.state().shells.eps_p, eb.state().shells.eps_p);
  EXPECT_EQ(ea.state().x, eb.state().x);
  EXPECT_GT(*std::max_element(ea.state().shells.eps_p.begin(), ea.state().shells.eps_p.end()), 0.0);
}

// A restart dump taken after the first deletions (the points' plastic strains and the deletion
// flags in it) restores a State that continues to the end bit for bit.
TEST(KeywordShellPiecewise, RestartDumpAfterDeletionContinuesBitForBit) {
  Model m;
  Diagnostics dg;
  ASSERT_TRUE(read_text(strip_deck(), "strip24.k", m, dg)) << messages(dg);
  Engine a(m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  auto deleted = [](const State& s) { return std::count(s.shells.failed.begin(), s.shells.failed.end(), 1); };
  while (deleted(a.state()) == 0) ASSERT_EQ(a.step(), StepStatus::ok);
  DumpHeader h;
  h.deck_name = "strip24.k";
  h.deck_text = strip_deck();
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/shell_piecewise_restart_dump";
  write_restart_dump(path, h, a.state(), a.contact().restart_data());
  Engine b(m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  EXPECT_EQ(b.state().shells.failed, a.state().shells.failed);
  StepStatus sa = StepStatus::ok, sb = StepStatus::ok;
  while (sa == StepStatus::ok) {
    sa = a.step();
    sb = b.step();
    ASSERT_EQ(sa, sb);
  }
  EXPECT_EQ(sa, StepStatus::finished);
  EXPECT_EQ(a.state().shells.eps_p, b.state().shells.eps_p);
  EXPECT_EQ(a.state().shells.sig, b.state().shells.sig);
  EXPECT_EQ(a.state().shells.failed, b.state().shells.failed);
  EXPECT_EQ(a.state().x, b.state().x);
}

// The converter: keyword -> fixed format -> keyword, the same Model each time (the material's
// table or curve, FAIL, C and P travel as the type's parameters; the shell section card).
TEST(KeywordShellPiecewise, ConverterRoundTripsBothFormats) {
  for (bool table : {false, true}) {
    Model k;
    Diagnostics dk;
    ASSERT_TRUE(read_text(strip_deck(table), "strip.k", k, dk)) << messages(dk);
    std::ostringstream fixed;
    std::vector<std::string> notes;
    write_fixed_deck(fixed, k, &notes);
    Model f;
    Diagnostics df;
    ASSERT_TRUE(read_text(fixed.str(), "strip.dyn", f, df)) << messages(df) << fixed.str();
    std::string diff;
    for (const auto& s : model_differences(k, f, 50)) diff += s + "\n";
    EXPECT_EQ(diff, "") << "table " << table;
    EXPECT_EQ(f.materials[0].type, 24);
    EXPECT_TRUE(f.materials[0].shell);
    std::ostringstream kw;
    write_keyword_deck(kw, f, &notes);
    Model k2;
    Diagnostics dk2;
    ASSERT_TRUE(read_text(kw.str(), "strip2.k", k2, dk2)) << messages(dk2);
    diff.clear();
    for (const auto& s : model_differences(f, k2, 50)) diff += s + "\n";
    EXPECT_EQ(diff, "") << "table " << table;
  }
}
