// Two welded steel sheets pulled apart (issue 24): a cross-tension peel.  Two square sheets of
// 4 x 4 Belytschko-Tsay shells (40 mm, t = 1 mm, elastic), their mid-surfaces 1 mm apart, are
// joined at their centre nodes by one spot weld: a *MAT_SPOTWELD beam (NRR; a square Hughes-Liu
// section, or LS-DYNA's spot-weld beam ELFORM 9 with a round one of the same area) or a
// *CONSTRAINED_SPOTWELD (SN).  The upper sheet is pulled up at its edges y = 0 and y = 40 mm, the
// lower one down at its edges x = 0 and x = 40 mm, each by F = k t in all (the sheets cross, as
// in a cross-tension specimen): the sheets bend, and by equilibrium the weld carries N = F in
// tension (the sheets barely accelerate: the ramp to failure takes about 20 of the sheets' first
// bending periods, 0.5 ms).  The weld fails when N reaches the card's force: t_f = NRR / k; the
// run log says so once; after it each sheet takes its load's impulse k (t^2 - t_f^2) / 2 and the
// sheets separate.
// A run stopped halfway (a restart dump) and restarted ends with the same bits as the
// uninterrupted run, the weld failing after the restart point.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/spot_weld.h"
#include "../support/deck_text.h"

using namespace impact3d;
namespace fs = std::filesystem;

namespace {

constexpr int kN = 4;                      // shells along a side
constexpr double kSide = 0.04, kT = 0.001;  // sheet side and thickness (m)
constexpr double kGap = 0.001;              // between the mid-surfaces
constexpr double kFail = 500;               // NRR or SN (N)
constexpr double kRate = 5e4;               // k (N/s): t_f = 10 ms
constexpr double kTf = kFail / kRate;

int node_id(int sheet, int i, int j) { return sheet * 100 + 1 + i + (kN + 1) * j; }

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// The deck; weld: "beam" (*MAT_SPOTWELD) or "constraint" (*CONSTRAINED_SPOTWELD); dump_cycles:
// *DATABASE_BINARY_D3DUMP (0: none); nf: the weld beam's NF (its failure rule on the mean of
// its last NF resultant vectors).
std::string peel_deck(const std::string& weld, double end_time, int dump_cycles = 0, int nf = 0) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nspot-welded sheets pulled apart\n*CONTROL_TERMINATION\n" << fmt("%10.4g\n", end_time);
  d << "*DATABASE_BINARY_D3PLOT\n" << fmt("%10.4g\n", end_time / 6);
  if (dump_cycles > 0) d << "*DATABASE_BINARY_D3DUMP\n" << fmt("%10.0f\n", dump_cycles);
  d << "*PART\nsheets\n         1         1         1\n";
  d << "*SECTION_SHELL\n         1         2       1.0         2\n" << fmt("%10.4g\n", kT);
  d << "*MAT_ELASTIC\n         1    7850.0   2.1e+11       0.3\n";
  d << "*NODE\n";
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j <= kN; ++j)
      for (int i = 0; i <= kN; ++i)
        d << fmt("%8.0f", node_id(sheet, i, j)) << fmt("%16.8g%16.8g%16.8g\n", kSide * i / kN, kSide * j / kN, sheet * kGap);
  d << "*ELEMENT_SHELL\n";
  int eid = 0;
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i)
        d << fmt("%8.0f       1", ++eid) << fmt("%8.0f%8.0f", node_id(sheet, i, j), node_id(sheet, i + 1, j))
          << fmt("%8.0f%8.0f\n", node_id(sheet, i + 1, j + 1), node_id(sheet, i, j + 1));
  const int c0 = node_id(0, kN / 2, kN / 2), c1 = node_id(1, kN / 2, kN / 2);
  if (weld == "beam" || weld == "beam9") {
    // a 5 mm square weld beam between the centre nodes; NRR = kFail (axial force only); beam9:
    // LS-DYNA's spot-weld beam (ELFORM 9, CST 1) of the same area, diameter 5.642 mm
    d << "*PART\nweld\n         2         2         2\n";
    if (weld == "beam9")
      d << "*SECTION_BEAM\n         2         9       1.0         2         1\n  0.005642  0.005642\n";
    else
      d << "*SECTION_BEAM\n         2         1       1.0         2         0\n     0.005     0.005     0.005     0.005\n";
    d << "*MAT_SPOTWELD\n         2    7850.0   2.1e+11       0.3   5.0e+08       0.0       0.0       0.0\n";
    d << "       0.0" << fmt("%10.4g", kFail) << "       0.0       0.0       0.0       0.0       0.0" << fmt("%10.0f\n", nf);
    d << "*ELEMENT_BEAM\n" << fmt("%8.0f       2", 1000) << fmt("%8.0f%8.0f%8.0f\n", c0, c1, node_id(0, kN, kN / 2));
  } else {
    d << "*CONSTRAINED_SPOTWELD\n" << fmt("%10.0f%10.0f", c0, c1) << fmt("%10.4g       0.0       2.0       2.0\n", kFail);
  }
  // F = k t on each sheet: its two loaded edges, k / (2 (n + 1)) per node
  d << "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n" << fmt("%20.6g%20.6g\n", 1.0, kRate);
  d << "*LOAD_NODE_POINT\n";
  const double share = 1.0 / (2 * (kN + 1));
  for (int q = 0; q <= kN; ++q) {
    for (int e : {0, kN}) {
      d << fmt("%10.0f         3         1", node_id(1, q, e)) << fmt("%10.6f\n", share);    // upper: y edges, up
      d << fmt("%10.0f         3         1", node_id(0, e, q)) << fmt("%10.6f\n", -share);   // lower: x edges, down
    }
  }
  d << "*END\n";
  return d.str();
}

using Read = test_support::ReadDeck;

Read read_text(const std::string& text) { return test_support::read_deck_text(text, "peel.k"); }

// Momentum along z of sheet `sheet` (its node ids sheet * 100 + 1 ...).
double sheet_momentum(const Model& m, const State& s, int sheet) {
  double p = 0;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_id(i) / 100 == sheet && m.node_id(i) < 1000) p += s.mass[std::size_t(i)] * s.vz[std::size_t(i)];
  return p;
}

int index_of(const Model& m, int id) {
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_id(i) == id) return i;
  return -1;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(IMPACT3D_BINARY_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

// The weld carries N = F (the load on one sheet) until the card's force, fails at t_f = F/k
// (within 2 %: the sheets' inertia), the run log reports it once, and the sheets separate with
// equal and opposite momenta, each its load's impulse since t_f.
TEST(SpotWeldPeel, WeldFailsAtItsCardForceAndTheSheetsSeparate) {
  for (const std::string weld : {"beam", "beam9", "constraint"}) {
    SCOPED_TRACE(weld);
    const double end = 1.2 * kTf;
    Read r = read_text(peel_deck(weld, end));
    ASSERT_TRUE(r.ok) << r.messages();
    Engine e(r.m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    const int c0 = index_of(r.m, node_id(0, kN / 2, kN / 2)), c1 = index_of(r.m, node_id(1, kN / 2, kN / 2));
    double t_fail = -1, n_half = 0, t_half = 0, n_last = 0;
    int failures = 0;
    StepStatus st = StepStatus::ok;
    while (st == StepStatus::ok) {
      const double t0 = s.time;
      st = e.step();
      const bool failed_now = weld != "constraint" ? !s.beams.newly_failed.empty() : !s.newly_released.empty();
      if (failed_now) {
        ++failures;
        if (t_fail < 0) t_fail = s.time;
      }
      if (t_fail >= 0) continue;
      // the weld's tension: the beam's axial resultant, or the constraint force on the upper
      // node along the weld (the node is pulled down by the weld: -f_z)
      const double n = weld != "constraint" ? s.beams.res[0] : -spot_weld_constraint_force(s, s.rigid[0], 1, s.dt_half)[2];
      if (t0 <= 0.5 * kTf) n_half = n, t_half = t0;
      n_last = n;
    }
    ASSERT_EQ(st, StepStatus::finished);
    const double p_up = sheet_momentum(r.m, s, 1), p_down = sheet_momentum(r.m, s, 0);
    const double impulse = kRate * (s.time * s.time - kTf * kTf) / 2;
    const double gap = s.z[std::size_t(c1)] - s.z[std::size_t(c0)];
    std::printf("[ measured ] %s weld: N at %.5f s %.6g N (F = k t %.6g N), last N before failure %.6g N (card %.6g N), "
                "failed at %.6f s (F/k %.6f s), sheet momenta %.6g / %.6g N s (impulse %.6g), centre gap %.4g mm (%.4g)\n",
                weld.c_str(), t_half, n_half, kRate * t_half, n_last, kFail, t_fail, kTf, p_up, p_down, impulse, gap * 1e3,
                kGap * 1e3);
    EXPECT_EQ(failures, 1);
    EXPECT_NEAR(n_half / (kRate * t_half), 1.0, 0.02);  // N = F before the failure
    EXPECT_NEAR(t_fail / kTf, 1.0, 0.02);               // fails at the card's force
    EXPECT_NEAR(n_last / kFail, 1.0, 0.02);
    EXPECT_NEAR(p_up / impulse, 1.0, 0.03);             // the sheets separate, each with its load's impulse
    EXPECT_NEAR(p_down / -impulse, 1.0, 0.03);
    EXPECT_NEAR((p_up + p_down) / impulse, 0.0, 1e-9);
    EXPECT_GT(gap, 5 * kGap);
  }
}

// The run log (run_simulation) reports the failure once: message 5005 for the beam, 5006 for
// the constraint.
TEST(SpotWeldPeel, FailureIsReportedOnce) {
  for (const std::string weld : {"beam", "constraint"}) {
    SCOPED_TRACE(weld);
    Read r = read_text(peel_deck(weld, 1.2 * kTf));
    ASSERT_TRUE(r.ok) << r.messages();
    const fs::path dir = fresh_dir("peel_log_" + weld);
    RunOptions o;
    o.printed = (dir / "d3hsp").string();
    o.plot = (dir / "d3plot").string();
    o.dump = (dir / "d3dump").string();
    o.quiet = true;
    o.threads = 1;
    std::ostringstream log;
    EXPECT_EQ(run_simulation(r.m, o, log), 0);
    const std::string code = weld == "beam" ? "info 5005" : "info 5006";
    EXPECT_EQ(count_of(log.str(), code), 1u) << log.str();
  }
}

// A restart dump written at about half the run's time (6 ms of 12; cycle 34000 of about 69000
// with the beam weld, whose 1 mm length sets the step; cycle 3600 of about 7200 with the
// constraint), before the weld fails (t_f = 10 ms), continues to the same bits: the plot database
// (8-byte words) of the restarted run is the uninterrupted run's, byte for byte; the restarted
// run reports the failure once.  The weld beam filters its failure rule over its last 5
// resultants (NF 5): the dump carries them.
TEST(SpotWeldPeel, RestartBeforeTheFailureEndsWithTheSameBits) {
  for (const std::string weld : {"beam", "constraint"}) {
    SCOPED_TRACE(weld);
    const int dump_every = weld == "beam" ? 34000 : 3600;  // about half the run (6 ms)
    const std::string deck = peel_deck(weld, 1.2 * kTf, dump_every, 5);  // (the beam's last 5 resultants in the dump)
    Read r = read_text(deck);
    ASSERT_TRUE(r.ok) << r.messages();
    const fs::path dir = fresh_dir("peel_restart_" + weld);
    RunOptions o;
    o.printed = (dir / "d3hsp").string();
    o.plot = (dir / "d3plot").string();
    o.dump = (dir / "d3dump").string();
    o.quiet = true;
    o.threads = 1;
    o.plot_word_size = 8;
    o.deck_text = deck;
    std::ostringstream log1;
    ASSERT_EQ(run_simulation(r.m, o, log1), 0) << log1.str();
    ASSERT_TRUE(fs::exists(dir / "d3dump01")) << log1.str();
    std::vector<std::string> plots;
    for (const auto& f : fs::directory_iterator(dir))
      if (f.path().filename().string().rfind("d3plot", 0) == 0) plots.push_back(f.path().filename().string());
    std::sort(plots.begin(), plots.end());
    std::vector<std::string> ref;
    for (const auto& p : plots) ref.push_back(file_bytes(dir / p));
    // the dump is before the failure
    const std::size_t dump_at = log1.str().find("restart dump " + (dir / "d3dump01").string() + " written at cycle");
    const std::size_t fail_at = log1.str().find(weld == "beam" ? "info 5005" : "info 5006");
    ASSERT_NE(dump_at, std::string::npos) << log1.str();
    ASSERT_NE(fail_at, std::string::npos);
    EXPECT_LT(dump_at, fail_at) << log1.str();
    int dump_cycle = 0;
    double dump_time = 0;
    ASSERT_EQ(std::sscanf(log1.str().c_str() + log1.str().find("written at cycle", dump_at), "written at cycle %d, time %lf",
                          &dump_cycle, &dump_time),
              2);
    EXPECT_GT(dump_time, 0.4 * kTf);  // about half the run's time, before the failure
    EXPECT_LT(dump_time, 0.8 * kTf);
    RunOptions o2 = o;
    o2.restart = (dir / "d3dump01").string();
    std::ostringstream log2;
    ASSERT_EQ(run_simulation(r.m, o2, log2), 0) << log2.str();
    EXPECT_EQ(count_of(log2.str(), weld == "beam" ? "info 5005" : "info 5006"), 1u) << log2.str();
    for (std::size_t k = 0; k < plots.size(); ++k) EXPECT_TRUE(file_bytes(dir / plots[k]) == ref[k]) << plots[k];
    std::printf("[ measured ] %s weld: restart from d3dump01 (cycle %d, %.4g ms; the weld fails at %.4g ms, the run ends at "
                "%.4g ms): %zu plot files the same bytes\n",
                weld.c_str(), dump_cycle, dump_time * 1e3, kTf * 1e3, 1.2 * kTf * 1e3, plots.size());
  }
}
