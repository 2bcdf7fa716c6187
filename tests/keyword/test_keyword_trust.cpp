// Defects found on real keyword decks (issue 25): a shell part's LCSS curve (defect 6), a
// refused DOF that must not change how the next card is read (defect 7), the count of the "N
// keyword block(s)" summary (defect 8), and the final summary of a shell-only model (defect 5).

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "impact3d/material/material_types.h"
#include "impact3d/solve/run.h"
#include "tests/keyword/shell_piecewise_deck.h"
#include "../support/deck_text.h"

using namespace impact3d;
using namespace shell_piecewise_test;

namespace {

// Replaces the one occurrence of `what` in `s` (the test fails if it is not there once).
std::string replace_once(std::string s, const std::string& what, const std::string& by) {
  const std::size_t at = s.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  EXPECT_EQ(s.find(what, at + 1), std::string::npos) << what;
  if (at != std::string::npos) s.replace(at, what.size(), by);
  return s;
}

// The type 24 shell strip with its flow curve given as *DEFINE_CURVE 100 (LCSS = 100): the
// curve id is not its position among the curves, as in real decks.
std::string strip_with_curve_100() {
  std::string d = strip_deck();
  d = replace_once(d, "      40.0       5.0         1         0         0\n",
                   "      40.0       5.0       100         0         0\n");
  d = replace_once(d, "*DEFINE_CURVE\n$#    lcid\n         1\n", "*DEFINE_CURVE\n$#    lcid\n       100\n");
  return d;
}

// A block of one hexahedron (nodes 1..8, part 1) with a node set 30 of its top face and a curve
// 12: `extra` adds keywords.
std::string one_hex_deck(const std::string& extra) {
  std::string s =
      "*KEYWORD\n*CONTROL_TERMINATION\n   1.0E-05\n"
      "*PART\nblock\n         1         1         1\n"
      "*SECTION_SOLID\n         1         1\n"
      "*MAT_ELASTIC\n         17.85000E-9  200000.0       0.3\n"
      "*NODE\n";
  char buf[128];
  for (int k = 0; k < 8; ++k) {
    std::snprintf(buf, sizeof buf, "%8d%16.1f%16.1f%16.1f\n", k + 1, double(k & 1), double((k >> 1) & 1), double(k >> 2));
    s += buf;
  }
  s += "*ELEMENT_SOLID\n       1       1       1       2       4       3       5       6       8       7\n"
       "*SET_NODE_LIST\n        30\n         5         6         7         8\n"
       "*DEFINE_CURVE\n        12\n                 0.0                 0.0\n                 1.0                 1.0\n";
  return s + extra + "*END\n";
}

}  // namespace

// Defect 6: the shell part's LCSS names *DEFINE_CURVE 100, which the deck defines; it was
// refused with 1310 "load curve 100 is not defined" (the solid parts' resolution of curve ids
// was not applied to shell parts).  Read, the curve is the flow curve of the strip's material.
TEST(KeywordTrust, ShellPartTakesItsLcssCurveById) {
  Model m;
  Diagnostics d;
  EXPECT_TRUE(read_text(strip_with_curve_100(), "strip100.k", m, d)) << messages(d);
  EXPECT_FALSE(d.has(1310)) << messages(d);
  ASSERT_EQ(m.materials.size(), 1u);
  const MaterialData& md = m.materials[0];
  const MaterialType* t = find_material_type(md.type);
  ASSERT_NE(t, nullptr);
  const MaterialParam* lcss = find_param(*t, "LCSS");
  ASSERT_NE(lcss, nullptr);
  const int lc = int(param_value(md, *lcss));  // the curve's number 1..NUMLC
  ASSERT_GE(lc, 1);
  ASSERT_LE(std::size_t(lc), m.load_curves.size());
  const LoadCurve& c = m.load_curves[std::size_t(lc - 1)];  // the flow curve, not the ramp
  ASSERT_EQ(c.f.size(), 4u);
  EXPECT_EQ(c.f[0], 2.5e8);
  EXPECT_EQ(c.f[3], 4.2e8);
}

// Defect 7: VAD 4 (relative displacement, LS-DYNA's card 2 OFFSET1 OFFSET2 LRB NODE1 NODE2
// follows; DOF -10 before it was read) is refused by one error on VAD; its card 2 is skipped, and the next motion is
// read from its own cards, with and without the _ID cards.  Before, the card 2 was read as the
// next motion (nine 1001 errors on a real deck).
TEST(KeywordTrust, RefusedMotionDofDoesNotShiftTheNextCards) {
  const std::string with_id =
      "*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n"
      "$#      id                                                             heading\n"
      "         1rotation\n"
      "$#    nsid       dof       vad      lcid        sf       vid     death     birth\n"
      "        30         2         4        12       1.0\n"
      "$# offset1   offset2       lrb     node1     node2\n"
      "       0.5       0.5         0         0         0\n"
      "         2pull\n"
      "        30         3         2        12       1.0\n";
  const std::string without_id =
      "*BOUNDARY_PRESCRIBED_MOTION_SET\n"
      "        30         1         4        12       1.0\n"
      "       0.5       0.5\n"
      "        30         3         2        12       1.0\n";
  for (const std::string& extra : {with_id, without_id}) {
    Model m;
    Diagnostics d;
    EXPECT_FALSE(read_text(one_hex_deck(extra), "motion.k", m, d));
    const std::string msgs = messages(d);
    EXPECT_EQ(d.error_count(), 1) << msgs;
    EXPECT_EQ(d.count(1102), 1) << msgs;
    EXPECT_NE(msgs.find("field \"VAD\""), std::string::npos) << msgs;
    EXPECT_FALSE(d.has(1001)) << msgs;
    EXPECT_FALSE(d.has(1002)) << msgs;
  }
  // the same deck without the refused motion reads, with the z motion on set 30's 4 nodes
  Model m;
  Diagnostics d;
  EXPECT_TRUE(read_text(one_hex_deck("*BOUNDARY_PRESCRIBED_MOTION_SET\n        30         3         2        12       1.0\n"),
                        "motion_ok.k", m, d))
      << messages(d);
  EXPECT_EQ(m.prescribed_motions.size(), 4u);
}

// Defect 8: two unsupported keyword blocks are two errors; the summary line that lists them
// ("2 keyword block(s): ...") is printed but not counted as a third.
TEST(KeywordTrust, KeywordBlockSummaryIsNotAnExtraError) {
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_text(one_hex_deck("*AIRBAG_SIMPLE_PRESSURE_VOLUME\n         1\n*FREQUENCY_DOMAIN_SSD\n         1\n"),
                         "unsupported.k", m, d));
  const std::string msgs = messages(d);
  EXPECT_EQ(d.count(1301), 2) << msgs;
  EXPECT_EQ(d.error_count(), 2) << msgs;
  EXPECT_NE(msgs.find("2 keyword block(s): *AIRBAG_SIMPLE_PRESSURE_VOLUME, *FREQUENCY_DOMAIN_SSD"), std::string::npos) << msgs;
  // with --lenient-keywords they are two warnings (2007), not three (and the deck's 2004)
  DeckFile deck;
  deck.load_from_string("unsupported.k", one_hex_deck("*AIRBAG_SIMPLE_PRESSURE_VOLUME\n         1\n*FREQUENCY_DOMAIN_SSD\n         1\n"));
  InputOptions o;
  o.lenient_keywords = true;
  Model m2;
  Diagnostics d2;
  EXPECT_TRUE(read_deck(deck, m2, d2, o) && check_model(m2, d2)) << messages(d2);
  EXPECT_EQ(d2.count(2007), 2) << messages(d2);
  EXPECT_EQ(d2.warning_count(), 3) << messages(d2);  // and 2004: curve 12 not used
}

// Defect 5: the final summary of a shell-only model (the strip, pulled until shells fail)
// gives the extents of its live shells and the largest plastic strain of a live shell; before,
// the extents came from solids only ([1e300, -1e300]) and the largest strain named "element 0".
TEST(KeywordTrust, FinalSummaryOfAShellOnlyModel) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_text(strip_deck(), "strip_summary.k", m, d)) << messages(d);
  const std::filesystem::path dir = test_support::empty_run_folder("keyword_trust", "strip");
  RunOptions o = test_support::run_options_in(dir);
  {
    std::ofstream printed(o.printed);
    ASSERT_EQ(run_simulation(m, o, printed), 0);
  }
  std::ifstream in(o.printed);
  const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(log.find("1.000000e+300"), std::string::npos) << log;
  EXPECT_EQ(log.find("in element 0"), std::string::npos) << log;
  // two shells fail (tests/keyword/test_keyword_shell_piecewise.cpp): left out, and said so
  EXPECT_NE(log.find(" failed (deleted) shells: 2 of 20 (left out of the extents below)"), std::string::npos) << log;
  // x to the pulled end (0.1 m + 10 m/s x (1.2 ms - 5 us ramp)), from the first nodes a live
  // shell holds (the two failed shells are the held end's: its nodes are left out), y [0, 20 mm]
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  const std::size_t at = log.find(" final extents: x [");
  ASSERT_NE(at, std::string::npos) << log;
  ASSERT_EQ(std::sscanf(log.c_str() + at, " final extents: x [%lf, %lf]  y [%lf, %lf]", &x0, &x1, &y0, &y1), 4) << log;
  EXPECT_GT(x0, 0.01);  // the second column of nodes, stretched
  EXPECT_LT(x0, 0.03);
  EXPECT_NEAR(x1, 0.1 + 10 * (1.2e-3 - 0.5e-5), 2e-4);
  EXPECT_GT(y0, -1e-3);
  EXPECT_LT(y1, 0.021);
  // the largest plastic strain of a live shell: below FAIL (the failed ones are left out)
  double eps = 0;
  int shell = 0;
  const std::size_t e = log.find(" maximum effective plastic strain of shells ");
  ASSERT_NE(e, std::string::npos) << log;
  ASSERT_EQ(std::sscanf(log.c_str() + e, " maximum effective plastic strain of shells %lf in shell %d", &eps, &shell), 2);
  EXPECT_GT(eps, 0.01);
  EXPECT_LT(eps, kFail);
  EXPECT_GE(shell, 1);
  EXPECT_LE(shell, 20);
  EXPECT_EQ(log.find(" maximum effective plastic strain 0"), std::string::npos) << "a solids line in a shell-only model";
}
