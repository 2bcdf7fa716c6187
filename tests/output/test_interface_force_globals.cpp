// Interface forces in the plot database's globals (decks/two_bars.dyn: two elastic copper bars
// 2 x 2 x 20 mm at +5 / -5 m/s, one sliding interface, slave = top of bar 1, master = bottom of
// bar 2).  The impact3d binary is run once; then:
//   * the layout: NGLBV = 6 + 7 NMMAT + NUMRW + 3 NINTF, control word 63 = NINTF, our reader
//     splits the words after the per-part block into walls and interfaces;
//   * the d3thdt globals hold, state for state, the forces printed in rcforc, and every d3plot
//     state written at a d3thdt time holds the same force bits;
//   * physics, from the database alone: the impulse of the slave-side force equals the change of
//     bar 1's momentum (the per-part globals; the interface is the only force on bar 1), and the
//     1-D bar-wave answer -2 m v; the force during contact is rho c0 v A; no lateral force.
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/plot_database.h"

namespace fs = std::filesystem;
using impact3d::PlotReader;
using impact3d::PlotState;

namespace {

constexpr double kRho = 8930, kE = 117e9, kL = 20e-3, kArea = 4e-6, kV = 5.0;  // the deck's data

struct Rc { double t, fx, fy, fz; };

// rcforc lines "time interface# fx fy fz" (header lines skipped)
std::vector<Rc> read_rcforc(const fs::path& p) {
  std::ifstream in(p);
  std::vector<Rc> out;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    Rc r{};
    int id = 0;
    if (ls >> r.t >> id >> r.fx >> r.fy >> r.fz && id == 1) out.push_back(r);
  }
  return out;
}

const fs::path& run_dir() {
  static const fs::path dir = [] {
    // one run per test process (CTest runs each test in its own process, maybe in parallel)
    const fs::path d = fs::path(IMPACT3D_BINARY_DIR) / ("test_interface_force_globals_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    const std::string cmd = "cd '" + d.string() + "' && SOURCE_DATE_EPOCH=0 '" IMPACT3D_BINARY_DIR
                            "/impact3d' i='" IMPACT3D_SOURCE_DIR "/decks/two_bars.dyn' ncpu=1 > run.log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::atexit([] { std::error_code ec; fs::remove_all(run_dir(), ec); });
    return d;
  }();
  return dir;
}

}  // namespace

TEST(InterfaceForceGlobals, LayoutHeaderAndReaderSplit) {
  PlotReader r;
  r.open((run_dir() / "d3plot").string());
  EXPECT_EQ(r.control().nintf, 1);
  EXPECT_EQ(r.control().nglbv, 6 + 7 * 2 + 0 + 3 * 1);
  EXPECT_EQ(r.geometry().num_interfaces, 1);
  EXPECT_EQ(r.geometry().num_rigid_walls, 0);
  ASSERT_GT(r.num_states(), 10);
  const PlotState s = r.state(r.num_states() - 1);
  EXPECT_EQ(s.interface_forces.size(), 3u);
  EXPECT_TRUE(s.rigid_wall_forces.empty());
}

TEST(InterfaceForceGlobals, TimeHistoryGlobalsEqualRcforcAndPlotStates) {
  const std::vector<Rc> rc = read_rcforc(run_dir() / "rcforc");
  PlotReader th;
  th.open((run_dir() / "d3thdt").string());
  ASSERT_EQ(th.geometry().num_interfaces, 1);
  ASSERT_EQ(static_cast<std::size_t>(th.num_states()), rc.size());
  double fmax = 0;
  for (const Rc& x : rc) fmax = std::max(fmax, std::fabs(x.fz));
  ASSERT_GT(fmax, 100.0);  // there is contact
  int in_contact = 0;
  for (int i = 0; i < th.num_states(); ++i) {
    const PlotState s = th.state(i);
    const Rc& x = rc[static_cast<std::size_t>(i)];
    // rcforc prints 7 digits, the database holds floats: agree to both roundings
    EXPECT_NEAR(s.time, x.t, 1e-5 * std::fabs(x.t) + 1e-15) << "state " << i;
    EXPECT_NEAR(s.interface_forces[2], x.fz, 1e-6 * fmax) << "state " << i;
    EXPECT_NEAR(s.interface_forces[0], x.fx, 1e-6 * fmax) << "state " << i;
    EXPECT_NEAR(s.interface_forces[1], x.fy, 1e-6 * fmax) << "state " << i;
    if (std::fabs(x.fz) > 0.5 * fmax) ++in_contact;
  }
  EXPECT_GT(in_contact, 20);
  // d3plot states at a d3thdt time (the same cycle): the same words
  PlotReader pl;
  pl.open((run_dir() / "d3plot").string());
  int matched = 0, matched_in_contact = 0;
  for (int i = 0, j = 0; i < pl.num_states(); ++i) {
    while (j < th.num_states() && th.time(j) < pl.time(i)) ++j;
    if (j == th.num_states() || th.time(j) != pl.time(i)) continue;
    const PlotState a = pl.state(i), b = th.state(j);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.interface_forces[std::size_t(k)], b.interface_forces[std::size_t(k)]);
    ++matched;
    if (std::fabs(a.interface_forces[2]) > 0.5 * fmax) ++matched_in_contact;
  }
  EXPECT_GT(matched, 10);
  EXPECT_GT(matched_in_contact, 2);
}

TEST(InterfaceForceGlobals, ImpulseAndContactForceFromTheDatabase) {
  PlotReader th;
  th.open((run_dir() / "d3thdt").string());
  const int n = th.num_states();
  ASSERT_GT(n, 50);
  std::vector<double> t(static_cast<std::size_t>(n)), fz(static_cast<std::size_t>(n));
  double flat = 0, fmax = 0;
  for (int i = 0; i < n; ++i) {
    const PlotState s = th.state(i);
    t[std::size_t(i)] = s.time;
    fz[std::size_t(i)] = s.interface_forces[2];
    flat = std::max({flat, std::fabs(s.interface_forces[0]), std::fabs(s.interface_forces[1])});
    fmax = std::max(fmax, std::fabs(s.interface_forces[2]));
  }
  double impulse = 0;
  for (std::size_t i = 1; i < t.size(); ++i) impulse += 0.5 * (fz[i] + fz[i - 1]) * (t[i] - t[i - 1]);
  const PlotState first = th.state(0), last = th.state(n - 1);
  // part 1 = bar 1 (slave): momentum = mass x mean velocity
  const double dp_bar1 = last.mat_mass[0] * last.mat_velocity[2] - first.mat_mass[0] * first.mat_velocity[2];
  const double m_bar = kRho * kArea * kL;
  const double c0 = std::sqrt(kE / kRho);
  const double f_exact = kRho * c0 * kV * kArea;  // 1-D: sigma = rho c0 v on the contact face
  // mean force over the middle half of the contact (half-maximum width)
  double ta = -1, tb = -1;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::fabs(fz[i]) > 0.5 * fmax) {
      if (ta < 0) ta = t[i];
      tb = t[i];
    }
  double sum = 0;
  int cnt = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] > ta + 0.25 * (tb - ta) && t[i] < tb - 0.25 * (tb - ta)) sum += -fz[i], ++cnt;
  const double f_plateau = cnt ? sum / cnt : 0;
  std::printf("impulse %.6g N s, bar 1 momentum change %.6g, -2 m v %.6g; contact %.3g us (2L/c0 %.3g us); "
              "plateau %.5g N vs rho c0 v A %.5g N; max lateral %.3g N\n",
              impulse, dp_bar1, -2 * m_bar * kV, (tb - ta) * 1e6, 2 * kL / c0 * 1e6, f_plateau, f_exact, flat);
  // the sampled force integrates to bar 1's momentum change (sampling error of the trapezoid rule)
  EXPECT_NEAR(impulse / dp_bar1, 1.0, 0.005);  // measured 4e-5
  // ... which is the exchange of velocities of 1-D theory
  EXPECT_NEAR(impulse / (-2 * m_bar * kV), 1.0, 0.03);  // measured -1.3% (the bars rebound at 4.93 m/s)
  EXPECT_NEAR((tb - ta) / (2 * kL / c0), 1.0, 0.05);  // measured -2.7% (half-maximum width, sampled)
  EXPECT_NEAR(f_plateau / f_exact, 1.0, 0.02);  // measured +0.05%
  EXPECT_LT(flat, 1e-3 * fmax);  // head-on: the resultant is axial
}
