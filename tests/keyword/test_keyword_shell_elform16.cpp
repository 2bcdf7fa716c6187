// *SECTION_SHELL ELFORM 16 (the fully integrated shell, element/shell_fi.h) in keyword decks:
// read as LS-DYNA reads it (the part's hourglass control ignored), the other formulations refused
// (1102), the type 24 strip of test_keyword_shell_piecewise.cpp run with it to failure (its
// d3plot's plastic strain words the mean of the Gauss points, deleted shells at FAIL), and the
// converter: the keyword deck keeps ELFORM 16, the fixed format (which has no such element) gets
// a Belytschko-Tsay shell and a note.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/run.h"
#include "tests/keyword/shell_piecewise_deck.h"
#include "../support/deck_text.h"

using namespace impact3d;
namespace fs = std::filesystem;
using namespace shell_piecewise_test;

namespace {

// The strip deck with *SECTION_SHELL ELFORM elform and *HOURGLASS IHQ 4 QM 0.05 on its part.
std::string strip_with(int elform) {
  std::string d = strip_deck();
  const std::string sec = "         1         2  0.833333\n";
  const std::size_t at = d.find(sec);
  d.replace(at, sec.size(), "         1" + I(elform, 10) + "  0.833333\n");
  const std::string part = "         1         1         1\n";
  d.replace(d.find(part), part.size(), "         1         1         1         0         1\n");
  d.replace(d.find("*NODE\n"), 6, "*HOURGLASS\n         1         4      0.05\n*NODE\n");
  return d;
}

}  // namespace

TEST(KeywordShellElform16, ReadWithTheHourglassControlIgnored) {
  for (int elform : {16, 2}) {
    Model m;
    Diagnostics d;
    ASSERT_TRUE(read_text(strip_with(elform), "strip16.k", m, d)) << messages(d);
    EXPECT_EQ(m.materials[0].shell_section.elform, elform);
    EXPECT_EQ(m.materials[0].hourglass_coef, elform == 16 ? 0.0 : 0.05);
  }
}

TEST(KeywordShellElform16, OtherFormulationsRefused) {
  for (int elform : {1, 5, 10}) {
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_text(strip_with(elform), "strip.k", m, d));
    const std::string msg = messages(d);
    EXPECT_NE(msg.find("1102"), std::string::npos) << msg;
    EXPECT_NE(msg.find("shell formulation " + std::to_string(elform) + "; only ELFORM 2 (Belytschko-Tsay) and 16"),
              std::string::npos)
        << msg;
  }
}

// The strip pulled to failure with ELFORM 16: normal end; in the d3plot live shells below FAIL,
// deleted ones at it (the words are the layers' means over the four Gauss points), some deleted.
TEST(KeywordShellElform16, PulledStripRunsToFailure) {
  Model m;
  Diagnostics dg;
  ASSERT_TRUE(read_text(strip_with(16), "strip16.k", m, dg)) << messages(dg);
  const fs::path dir = test_support::empty_run_folder("shell_elform16_runs", "strip");
  RunOptions o = test_support::run_options_in(dir);
  {
    std::ofstream printed(o.printed);
    ASSERT_EQ(run_simulation(m, o, printed), 0);
  }
  PlotReader pl;
  pl.open((dir / "d3plot").string());
  ASSERT_EQ(pl.geometry().num_shells(), 20);
  const int nv = kShellPlotVars;
  double most = 0;
  int deleted_last = 0;
  for (int t = 0; t < pl.num_states(); ++t) {
    const PlotState ps = pl.state(t);
    for (int k = 0; k < 20; ++k) {
      const double in = ps.shell_vars[std::size_t(nv * k + 7 + 6)], out = ps.shell_vars[std::size_t(nv * k + 14 + 6)];
      most = std::max({most, in, out});
      if (ps.shell_alive[std::size_t(k)]) {
        EXPECT_LT(std::min(in, out), kFail) << "state " << t << " shell " << k;
      } else {
        EXPECT_GE(std::min(in, out), kFail) << "state " << t << " shell " << k;
        if (t + 1 == pl.num_states()) ++deleted_last;
      }
    }
  }
  std::printf("ELFORM 16 strip: largest plastic strain word %.4f, %d deleted at the end\n", most, deleted_last);
  EXPECT_GT(most, 0.03);
  EXPECT_GT(deleted_last, 0);
}

// The converter: the keyword deck keeps ELFORM 16 (the same Model back); the fixed format writes
// a Belytschko-Tsay shell (hourglass type 1, 0.1) and says so in a note.
TEST(KeywordShellElform16, ConverterKeepsItInKeywordAndNotesItInFixedFormat) {
  Model k;
  Diagnostics dk;
  ASSERT_TRUE(read_text(strip_with(16), "strip16.k", k, dk)) << messages(dk);
  std::ostringstream kw;
  std::vector<std::string> notes;
  write_keyword_deck(kw, k, &notes);
  Model k2;
  Diagnostics dk2;
  ASSERT_TRUE(read_text(kw.str(), "back.k", k2, dk2)) << messages(dk2) << kw.str();
  std::string diff;
  for (const auto& s : model_differences(k, k2, 50)) diff += s + "\n";
  EXPECT_EQ(diff, "");
  EXPECT_EQ(k2.materials[0].shell_section.elform, 16);
  EXPECT_TRUE(notes.empty());
  std::ostringstream fixed;
  write_fixed_deck(fixed, k, &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("ELFORM 16"), std::string::npos) << notes[0];
  Model f;
  Diagnostics df;
  ASSERT_TRUE(read_text(fixed.str(), "strip.dyn", f, df)) << messages(df);
  EXPECT_EQ(f.materials[0].shell_section.elform, 2);
  EXPECT_EQ(f.materials[0].hourglass_type, 1);
  EXPECT_EQ(f.materials[0].hourglass_coef, 0.1);
}
