// *CONTACT_FORCE_TRANSDUCER_PENALTY on the two-bar impact (the keyword twin of
// decks/two_bars.dyn, written by the converter: two elastic copper bars 2 x 2 x 20 mm at +5 / -5
// m/s, one symmetric sliding interface, slave = top of bar 1 = part 1).  A transducer on part 1
// (side A: every exterior face of bar 1) measures the contact force the interface puts on bar 1:
//   * cycle by cycle it equals the interface's slave-side resultant to round-off, with or
//     without a side B (part 2), and a transducer on bar 1 against itself measures nothing;
//   * its impulse sum F^n dt_n equals the change of bar 1's momentum (bar 1 is free: the
//     contact is the only external force on it) and -2 m v of 1-D theory;
//   * it adds nothing: positions, velocities and energies are the same bits as without it;
//   * the impact3d binary writes it to rcforc as interface 2 and to the plot globals
//     (NINTF = 2), the same bits for ncpu=1 and ncpu=3, and the keyword converter writes it back.
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
#include "impact3d/solve/engine.h"

namespace fs = std::filesystem;
using namespace impact3d;

namespace {

constexpr double kRho = 8930, kL = 20e-3, kArea = 4e-6, kV = 5.0;  // the deck's data

const fs::path& work_dir() {
  static const fs::path dir = [] {
    const fs::path d = fs::path(IMPACT3D_BINARY_DIR) / ("test_force_transducer_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    const std::string cmd = "cd '" + d.string() + "' && '" IMPACT3D_BINARY_DIR "/impact3d' i='" IMPACT3D_SOURCE_DIR
                            "/decks/two_bars.dyn' --write-keyword=two_bars.k > convert.log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::atexit([] { std::error_code ec; fs::remove_all(work_dir(), ec); });
    return d;
  }();
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The keyword twin with `extra` keywords inserted before *END, written to NAME.k.
fs::path deck_with(const std::string& name, const std::string& extra) {
  std::string text = slurp(work_dir() / "two_bars.k");
  const std::size_t end = text.rfind("*END");
  EXPECT_NE(end, std::string::npos);
  text.insert(end, extra);
  const fs::path p = work_dir() / (name + ".k");
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

const char* kOnBar1 =
    "*CONTACT_FORCE_TRANSDUCER_PENALTY\n"
    "$#   surfa     surfb  surfatyp  surfbtyp\n"
    "         1         0         3\n";
const char* kBar1FromBar2AndItself =
    "*CONTACT_FORCE_TRANSDUCER_PENALTY_ID\n"
    "        77\n"
    "         1         2         3         3\n"
    "*CONTACT_FORCE_TRANSDUCER_PENALTY\n"
    "         1         1         3         3\n";

struct TransducerRun {
  Model m;
  std::vector<std::array<double, 3>> f_iface, f_trans, f_trans2, f_self;
  double impulse_z = 0;  // sum F_transducer,z dt_n
  double p0 = 0, p1 = 0; // bar 1's z momentum before and after
  std::vector<double> x, vz;
  double contact = 0, ratio = 0, kinetic = 0;
};

double bar1_momentum(const Model& m, const State& s) {
  std::vector<char> in1(std::size_t(s.nn), 0);
  for (int e = 0; e < m.num_hexes(); ++e)
    if (m.hex_material[std::size_t(e)] == 0)
      for (int n : m.hex_nodes[std::size_t(e)]) in1[std::size_t(n)] = 1;
  double p = 0;
  for (int n = 0; n < s.nn; ++n)
    if (in1[std::size_t(n)]) p += s.mass[std::size_t(n)] * s.vz[std::size_t(n)];
  return p;
}

void run(const fs::path& deck, TransducerRun& r) {
  Diagnostics d;
  ASSERT_TRUE(read_and_check_deck(deck.string(), r.m, d)) << deck;
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  State& s = e.state();
  r.p0 = bar1_momentum(r.m, s);
  const std::size_t nif = r.m.interfaces.size();
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double dt_half_before = s.dt_half;
    const int cycle = s.cycle;
    st = e.step();
    const double dt_next = s.dt_half;
    const double dt_n = cycle == 0 ? 0.5 * dt_next : 0.5 * (dt_half_before + dt_next);
    const auto& f = e.interface_forces();
    r.f_iface.push_back(f[0]);
    if (f.size() > nif) {
      r.f_trans.push_back(f[nif]);
      r.impulse_z += f[nif][2] * dt_n;
    }
    if (f.size() > nif + 1) r.f_self.push_back(f[nif + 1]);
  }
  ASSERT_EQ(st, StepStatus::finished);
  r.p1 = bar1_momentum(r.m, s);
  r.x = s.x;
  r.x.insert(r.x.end(), s.y.begin(), s.y.end());
  r.x.insert(r.x.end(), s.z.begin(), s.z.end());
  r.vz = s.vz;
  r.contact = s.contact;
  r.ratio = s.energy_ratio();
  r.kinetic = s.kinetic;
}

}  // namespace

TEST(ForceTransducer, ReadIntoTheModel) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_and_check_deck(deck_with("read", kBar1FromBar2AndItself).string(), m, d));
  ASSERT_EQ(m.force_transducers.size(), 2u);
  EXPECT_EQ(m.force_transducers[0].id, 77);
  EXPECT_TRUE(m.force_transducers[0].has_b);
  // side A: the nodes of bar 1's exterior faces (2 x 2 x 20 mm, 4 x 4 x 10 hexahedra here: all
  // nodes but the interior ones)
  int bar1_nodes = 0;
  {
    std::vector<char> in1(std::size_t(m.num_nodes()), 0);
    for (int e = 0; e < m.num_hexes(); ++e)
      if (m.hex_material[std::size_t(e)] == 0)
        for (int n : m.hex_nodes[std::size_t(e)]) in1[std::size_t(n)] = 1;
    for (char c : in1) bar1_nodes += c;
  }
  EXPECT_GT(int(m.force_transducers[0].a_nodes.size()), bar1_nodes / 2);
  EXPECT_LE(int(m.force_transducers[0].a_nodes.size()), bar1_nodes);
  EXPECT_EQ(m.force_transducers[1].a_nodes, m.force_transducers[1].b_nodes);
  // the keyword converter writes them back (as node sets) and they read back the same
  const fs::path back = work_dir() / "back.k";
  {
    const std::string cmd = "'" IMPACT3D_BINARY_DIR "/impact3d' i='" + deck_with("read", kBar1FromBar2AndItself).string() +
                            "' --write-keyword='" + back.string() + "' > '" + (work_dir() / "back.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  }
  Model b;
  Diagnostics db;
  ASSERT_TRUE(read_and_check_deck(back.string(), b, db));
  ASSERT_EQ(b.force_transducers.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    EXPECT_EQ(b.force_transducers[t].a_nodes, m.force_transducers[t].a_nodes);
    EXPECT_EQ(b.force_transducers[t].b_nodes, m.force_transducers[t].b_nodes);
    EXPECT_EQ(b.force_transducers[t].has_b, m.force_transducers[t].has_b);
    EXPECT_EQ(b.force_transducers[t].id, m.force_transducers[t].id);
  }
}

TEST(ForceTransducer, MeasuresTheInterfaceForceAndAddsNothing) {
  TransducerRun plain, with, with_b;
  run(deck_with("plain", ""), plain);
  run(deck_with("with", kOnBar1), with);
  run(deck_with("with_b", kBar1FromBar2AndItself), with_b);
  ASSERT_EQ(with.f_trans.size(), with.f_iface.size());
  ASSERT_EQ(with_b.f_trans.size(), with.f_iface.size());
  ASSERT_EQ(with_b.f_self.size(), with.f_iface.size());
  double fmax = 0;
  for (const auto& f : with.f_iface) fmax = std::max(fmax, std::fabs(f[2]));
  ASSERT_GT(fmax, 100.0);  // there is contact
  double worst = 0, worst_b = 0, self = 0;
  for (std::size_t c = 0; c < with.f_iface.size(); ++c)
    for (int a = 0; a < 3; ++a) {
      worst = std::max(worst, std::fabs(with.f_trans[c][std::size_t(a)] - with.f_iface[c][std::size_t(a)]));
      worst_b = std::max(worst_b, std::fabs(with_b.f_trans[c][std::size_t(a)] - with.f_trans[c][std::size_t(a)]));
      self = std::max(self, std::fabs(with_b.f_self[c][std::size_t(a)]));
    }
  const double m_bar = kRho * kArea * kL;
  std::printf("max |F_transducer - F_interface| %.3g N of %.5g N; with side B %.3g N; bar 1 on itself %.3g N\n"
              "impulse %.9g N s, bar 1 momentum change %.9g N s (rel. %.2g), -2 m v %.6g; energy ratio %.9g\n",
              worst, fmax, worst_b, self, with.impulse_z, with.p1 - with.p0,
              with.impulse_z / (with.p1 - with.p0) - 1, -2 * m_bar * kV, with.ratio);
  EXPECT_LE(worst, 1e-12 * fmax);
  EXPECT_LE(worst_b, 1e-12 * fmax);
  EXPECT_LE(self, 1e-12 * fmax);  // forces within one body cancel
  EXPECT_NEAR(with.impulse_z / (with.p1 - with.p0), 1.0, 1e-9);
  EXPECT_NEAR(with.impulse_z / (-2 * m_bar * kV), 1.0, 0.03);  // the bars rebound at ~4.93 m/s
  // the transducer changes nothing: the same bits
  EXPECT_EQ(plain.f_iface.size(), with.f_iface.size());
  EXPECT_TRUE(plain.x == with.x);
  EXPECT_TRUE(plain.vz == with.vz);
  EXPECT_TRUE(plain.x == with_b.x);
  EXPECT_EQ(plain.contact, with.contact);
  EXPECT_EQ(plain.ratio, with.ratio);
  EXPECT_EQ(plain.kinetic, with_b.kinetic);
}

TEST(ForceTransducer, RcforcLineAndPlotGlobalsForAnyThreadCount) {
  const fs::path deck = deck_with("bin", kOnBar1);
  std::string rc[2];
  for (int k = 0; k < 2; ++k) {
    const fs::path d = work_dir() / ("ncpu" + std::to_string(k));
    fs::create_directories(d);
    const std::string cmd = "cd '" + d.string() + "' && SOURCE_DATE_EPOCH=0 '" IMPACT3D_BINARY_DIR "/impact3d' i='" +
                            deck.string() + "' ncpu=" + (k ? "3" : "1") + " > run.log 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    rc[k] = slurp(d / "rcforc");
  }
  EXPECT_EQ(rc[0], rc[1]);
  // every time has line 1 (the interface) and line 2 (the transducer), the same numbers
  std::istringstream in(rc[0]);
  std::string line;
  int pairs = 0, contact = 0;
  double t1 = -1, f1[3] = {0, 0, 0};
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    double t, f[3];
    int id;
    if (!(ls >> t >> id >> f[0] >> f[1] >> f[2])) continue;
    if (id == 1) {
      t1 = t;
      for (int a = 0; a < 3; ++a) f1[a] = f[a];
    } else if (id == 2) {
      ASSERT_EQ(t, t1);
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(f[a], f1[a], 1e-6 * std::fabs(f1[a]) + 1e-9) << line;
      ++pairs;
      if (std::fabs(f[2]) > 100) ++contact;
    }
  }
  EXPECT_GT(pairs, 100);
  EXPECT_GT(contact, 20);
  PlotReader r;
  r.open((work_dir() / "ncpu0" / "d3plot").string());
  EXPECT_EQ(r.control().nintf, 2);
  EXPECT_EQ(r.geometry().num_interfaces, 2);
}
