// The interface-force database (*DATABASE_BINARY_INTFOR, s=) on the two-bar impact: the keyword
// twin of decks/two_bars.dyn (two elastic copper bars 2 x 2 x 20 mm at +5 / -5 m/s, one sliding
// interface between the end faces) with SAPR = SBPR = 1 on the contact.  The impact3d binary is
// run once with s=; then, from the file alone (our reader):
//   * its geometry: the interface's slave and master segments as 4-node shells (one part per
//     side, ids 1..n in order), their nodes with the deck's ids;
//   * during contact the area-weighted mean contact pressure of each side equals the interface
//     force / the contact area (the same numbers: float words) and 1-D theory's rho c0 v;
//   * after separation every segment's pressure is zero.
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

#include "common/messages.h"
#include "common/plot_database.h"
#include "impact3d/input/deck_reader.h"

namespace fs = std::filesystem;
using namespace impact3d;

namespace {

constexpr double kRho = 8930, kE = 117e9, kArea = 4e-6, kV = 5.0;  // the deck's data

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const fs::path& run_dir() {
  static const fs::path dir = [] {
    const fs::path d = fs::path(IMPACT3D_BINARY_DIR) / ("test_intfor_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    std::string cmd = "cd '" + d.string() + "' && '" IMPACT3D_BINARY_DIR "/impact3d' i='" IMPACT3D_SOURCE_DIR
                      "/decks/two_bars.dyn' --write-keyword=two_bars.k > convert.log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    // SAPR = SBPR = 1 on the contact's card 1, and the database every 0.25 us
    std::istringstream in(slurp(d / "two_bars.k"));
    std::ostringstream out;
    std::string line;
    bool in_contact = false;
    while (std::getline(in, line)) {
      if (line == "*END") out << "*DATABASE_BINARY_INTFOR\n   2.5e-07\n";
      if (in_contact && !line.empty() && line[0] != '$') {
        line.resize(60, ' ');
        line += "         1         1";
        in_contact = false;
      }
      if (line.rfind("*CONTACT_", 0) == 0) in_contact = true;
      out << line << "\n";
    }
    std::ofstream(d / "intfor_bars.k") << out.str();
    cmd = "cd '" + d.string() + "' && SOURCE_DATE_EPOCH=0 '" IMPACT3D_BINARY_DIR
          "/impact3d' i=intfor_bars.k s=contact_db ncpu=1 > run.log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::atexit([] { std::error_code ec; fs::remove_all(run_dir(), ec); });
    return d;
  }();
  return dir;
}

// Area of shell e at the state's coordinates (half the cross product of the diagonals).
double shell_area(const PlotGeometry& g, const PlotState& s, int e) {
  const double* c[4];
  for (int j = 0; j < 4; ++j) c[j] = &s.coords[3 * std::size_t(g.shell_nodes[4 * std::size_t(e) + std::size_t(j)])];
  const double d1[3] = {c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]};
  const double d2[3] = {c[3][0] - c[1][0], c[3][1] - c[1][1], c[3][2] - c[1][2]};
  const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

}  // namespace

TEST(Intfor, GeometryIsTheInterfaceSegments) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_and_check_deck((run_dir() / "intfor_bars.k").string(), m, d));
  ASSERT_EQ(m.interfaces.size(), 1u);
  const SlidingInterface& si = m.interfaces[0];
  EXPECT_TRUE(si.intfor_slave);
  EXPECT_TRUE(si.intfor_master);
  EXPECT_TRUE(fs::exists(run_dir() / "contact_db"));
  EXPECT_TRUE(fs::exists(run_dir() / "contact_db01"));
  EXPECT_FALSE(fs::exists(run_dir() / "intfor"));  // s= names it
  PlotReader r;
  r.open((run_dir() / "contact_db").string());
  const PlotGeometry& g = r.geometry();
  ASSERT_EQ(std::size_t(g.num_shells()), si.slave.size() + si.master.size());
  EXPECT_EQ(g.num_hexes(), 0);
  EXPECT_EQ(g.num_materials, 2);
  EXPECT_EQ(r.control().nintf, 1);
  // shells: the slave segments (part 1), then the master's (part 2), ids 1..n, nodes by deck id
  std::vector<int> ids(std::size_t(g.num_nodes()));
  for (int k = 0; k < g.num_nodes(); ++k) ids[std::size_t(k)] = g.node_user_ids.empty() ? k + 1 : g.node_user_ids[std::size_t(k)];
  for (int e = 0; e < g.num_shells(); ++e) {
    const bool slave = std::size_t(e) < si.slave.size();
    const auto& sg = slave ? si.slave[std::size_t(e)] : si.master[std::size_t(e) - si.slave.size()];
    EXPECT_EQ(g.shell_material[std::size_t(e)], slave ? 1 : 2);
    EXPECT_EQ(g.shell_user_ids.empty() ? e + 1 : g.shell_user_ids[std::size_t(e)], e + 1);
    for (int j = 0; j < 4; ++j)
      EXPECT_EQ(ids[std::size_t(g.shell_nodes[4 * std::size_t(e) + std::size_t(j)])], m.node_id(sg[std::size_t(j)])) << "shell " << e;
  }
  // every node is a segment node, once
  std::vector<int> used(std::size_t(g.num_nodes()), 0);
  for (int n : g.shell_nodes) used[std::size_t(n)] = 1;
  for (int u : used) EXPECT_EQ(u, 1);
  EXPECT_EQ(g.part_titles.size(), 2u);
}

TEST(Intfor, ContactPressureIsTheInterfaceForceOverTheArea) {
  PlotReader r;
  r.open((run_dir() / "contact_db").string());
  const PlotGeometry& g = r.geometry();
  const int n = r.num_states();
  ASSERT_GT(n, 50);
  const PlotLayout& L = r.layout();
  ASSERT_GE(L.layer_stress, 0);
  const std::size_t nv2d = r.state(0).shell_vars.size() / std::size_t(g.num_shells());
  auto pressure = [&](const PlotState& s, int e) { return -s.shell_vars[nv2d * std::size_t(e) + std::size_t(L.layer_stress)]; };
  // the state nearest the middle of the contact (half-maximum of the force)
  double fmax = 0;
  std::vector<double> fz(static_cast<std::size_t>(n)), t(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const PlotState s = r.state(i);
    t[std::size_t(i)] = s.time;
    fz[std::size_t(i)] = s.interface_forces[2];
    fmax = std::max(fmax, std::fabs(fz[std::size_t(i)]));
  }
  ASSERT_GT(fmax, 100.0);
  double ta = -1, tb = -1;
  for (int i = 0; i < n; ++i)
    if (std::fabs(fz[std::size_t(i)]) > 0.5 * fmax) {
      if (ta < 0) ta = t[std::size_t(i)];
      tb = t[std::size_t(i)];
    }
  const double c0 = std::sqrt(kE / kRho), p_exact = kRho * c0 * kV;
  int checked = 0;
  double worst_theory = 0, sum_mean = 0;
  for (int i = 0; i < n; ++i) {
    if (t[std::size_t(i)] < ta + 0.25 * (tb - ta) || t[std::size_t(i)] > tb - 0.25 * (tb - ta)) continue;
    const PlotState s = r.state(i);
    for (int part = 1; part <= 2; ++part) {
      double pa = 0, a = 0, pmin = 1e300, pmax = -1e300;
      for (int e = 0; e < g.num_shells(); ++e) {
        if (g.shell_material[std::size_t(e)] != part) continue;
        const double ae = shell_area(g, s, e), p = pressure(s, e);
        pa += p * ae;
        a += ae;
        pmin = std::min(pmin, p);
        pmax = std::max(pmax, p);
      }
      const double p_mean = pa / a, p_force = std::fabs(fz[std::size_t(i)]) / a;
      if (checked < 2)
        std::printf("t = %.3g us, side %d: mean pressure %.6g Pa, |F| / A %.6g Pa, rho c0 v %.6g Pa; segments %.4g..%.4g Pa; "
                    "area %.6g (4e-6)\n",
                    t[std::size_t(i)] * 1e6, part, p_mean, p_force, p_exact, pmin, pmax, a);
      // the file's pressures carry the interface force (float words: 1e-5)
      EXPECT_NEAR(p_mean / p_force, 1.0, 1e-5) << "state " << i << " side " << part;
      EXPECT_NEAR(a / kArea, 1.0, 0.01);
      worst_theory = std::max(worst_theory, std::fabs(p_mean / p_exact - 1));
      sum_mean += 0.5 * p_mean;
    }
    ++checked;
  }
  EXPECT_GT(checked, 5);
  const double plateau = sum_mean / checked;
  std::printf("mid-contact states: %d, mean pressure over them %.6g Pa = %.4f rho c0 v; largest single-state deviation %.3g\n",
              checked, plateau, plateau / p_exact, worst_theory);
  // 1-D theory: the plateau's mean (single states ring by up to ~8% with the bars' lateral modes)
  EXPECT_NEAR(plateau / p_exact, 1.0, 0.02);
  EXPECT_LT(worst_theory, 0.12);
  // after separation: no pressure anywhere
  const PlotState last = r.state(n - 1);
  ASSERT_LT(std::fabs(last.interface_forces[2]), 1e-9 * fmax);
  for (int e = 0; e < g.num_shells(); ++e) EXPECT_EQ(pressure(last, e), 0.0) << "shell " << e;
}

// A restart from a dump written during the contact continues the database: the same bytes as
// the uninterrupted run's.
TEST(Intfor, RestartContinuesTheDatabaseBitForBit) {
  const fs::path d = run_dir() / "restart";
  fs::create_directories(d);
  std::string deck = slurp(run_dir() / "intfor_bars.k");
  deck.insert(deck.rfind("*END"), "*DATABASE_BINARY_D3DUMP\n       100\n");
  std::ofstream(d / "deck.k") << deck;
  const std::string bin = "SOURCE_DATE_EPOCH=0 '" IMPACT3D_BINARY_DIR "/impact3d' ";
  std::string cmd = "cd '" + d.string() + "' && " + bin + "i=deck.k ncpu=1 > run.log 2>&1 && mkdir -p full && cp intfor intfor01 full/ && " +
                    bin + "r=d3dump01 ncpu=2 > restart.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_NE(slurp(d / "restart.log").find("restart from d3dump01 at cycle 100"), std::string::npos);
  for (const char* f : {"intfor", "intfor01"}) {
    const std::string a = slurp(d / "full" / f), b = slurp(d / f);
    EXPECT_GT(a.size(), 1000u) << f;
    EXPECT_TRUE(a == b) << f << " differs after the restart";
  }
}
