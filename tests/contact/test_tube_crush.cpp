// A square steel tube crushed axially on a rigid wall with single-surface contact (issue 14's
// verification): folds form, the energy balance holds (the external work of the crushing end =
// internal + kinetic + hourglass + contact + wall energy), and the mean crush force is compared
// with Wierzbicki and Abramowicz's super-folding element for the square tube (Wierzbicki T,
// Abramowicz W, "On the crushing mechanics of thin-walled structures", J Appl Mech 50 (1983)
// 727-734): Pm = 9.56 sigma0 t^(5/3) b^(1/3), b the side, t the wall, sigma0 the flow stress.
// The test is a short, coarse version that runs in CI time; DISABLED_ the full one (a manual
// benchmark: --gtest_also_run_disabled_tests).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"
#include "contact_test_util.h"

using namespace impact3d;

namespace {

using contact_test::fld;
using contact_test::ifld;

struct Tube {
  double b = 0.04, t = 0.001, L = 0.08;  // side (mid-surface), wall, length
  int per_side = 10, nz = 20;            // shells along a side, along the length
  double sigy = 250e6, v = 15, crush = 0.03;  // flow stress, crushing speed, crush distance
  int nip = 5;
};

// The tube's keyword deck: plastic-kinematic steel (ETAN 0: sigma0 = SIGY), z = 0 end on a
// sticking rigid wall, z = L end driven down at v (ramped over 0.1 ms) and held laterally and in
// rotation; a 2 % inward-outward imperfection of the sides' middles one shell below the top
// starts the folds there; *CONTACT_AUTOMATIC_SINGLE_SURFACE on every part.
std::string tube_deck(const Tube& T) {
  const int nc = 4 * T.per_side;  // nodes around
  std::ostringstream d;
  const double end = T.crush / T.v + 0.5e-4;
  d << "*KEYWORD\n*TITLE\nsquare tube crush\n*CONTROL_TERMINATION\n" << fld(end, 10) << "\n";
  d << "*NODE\n";
  for (int k = 0; k <= T.nz; ++k)
    for (int i = 0; i < nc; ++i) {
      const int side = i / T.per_side;
      const double s = double(i % T.per_side) / T.per_side;  // along the side
      double x = 0, y = 0;
      const double h = T.b / 2;
      switch (side) {
        case 0: x = -h + T.b * s, y = -h; break;
        case 1: x = h, y = -h + T.b * s; break;
        case 2: x = h - T.b * s, y = h; break;
        default: x = -h, y = h - T.b * s; break;
      }
      if (k == T.nz - 2 && i % T.per_side == T.per_side / 2) {  // imperfection: alternate sides in / out
        const double a = (side % 2 == 0 ? -1 : 1) * 0.02 * T.b;
        if (side == 0 || side == 2) y += (side == 0 ? -a : a);
        else x += (side == 1 ? a : -a);
      }
      d << ifld(1 + i + nc * k, 8) << fld(x, 16) << fld(y, 16) << fld(T.L * k / T.nz, 16) << "\n";
    }
  d << "*PART\ntube\n" << ifld(1, 10) << ifld(1, 10) << ifld(1, 10) << "\n";
  d << "*SECTION_SHELL\n" << ifld(1, 10) << ifld(2, 10) << fld(0.8333, 10) << ifld(T.nip, 10) << "\n" << fld(T.t, 10) << "\n";
  d << "*MAT_PLASTIC_KINEMATIC\n" << ifld(1, 10) << fld(7850, 10) << fld(210e9, 10) << fld(0.3, 10) << fld(T.sigy, 10)
    << fld(0, 10) << fld(0, 10) << "\n" << fld(0, 10) << fld(0, 10) << fld(0, 10) << "\n";
  d << "*ELEMENT_SHELL\n";
  int eid = 0;
  for (int k = 0; k < T.nz; ++k)
    for (int i = 0; i < nc; ++i) {
      const int n1 = 1 + i + nc * k, n2 = 1 + (i + 1) % nc + nc * k;
      d << ifld(++eid, 8) << ifld(1, 8) << ifld(n1, 8) << ifld(n2, 8) << ifld(n2 + nc, 8) << ifld(n1 + nc, 8) << "\n";
    }
  auto node_set = [&](int sid, int k) {
    d << "*SET_NODE_LIST\n" << ifld(sid, 10) << "\n";
    for (int i = 0; i < nc; ++i) d << ifld(1 + i + nc * k, 10) << ((i + 1) % 8 == 0 || i + 1 == nc ? "\n" : "");
  };
  node_set(1, 0);
  node_set(2, T.nz);
  d << "*RIGIDWALL_PLANAR\n" << ifld(1, 10) << "\n" << fld(0, 10) << fld(0, 10) << fld(0, 10) << fld(0, 10) << fld(0, 10)
    << fld(1, 10) << fld(1, 10) << "\n";
  d << "*BOUNDARY_SPC_SET\n" << ifld(2, 10) << ifld(0, 10) << ifld(1, 10) << ifld(1, 10) << ifld(0, 10) << ifld(1, 10)
    << ifld(1, 10) << ifld(1, 10) << "\n";
  d << "*DEFINE_CURVE\n" << ifld(1, 10) << "\n" << fld(0, 20) << fld(0, 20) << "\n" << fld(1e-4, 20) << fld(1, 20) << "\n"
    << fld(1, 20) << fld(1, 20) << "\n";
  d << "*BOUNDARY_PRESCRIBED_MOTION_SET\n" << ifld(2, 10) << ifld(3, 10) << ifld(0, 10) << ifld(1, 10) << fld(-T.v, 10) << "\n";
  d << "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n" << ifld(0, 10) << "\n" << fld(0, 10) << "\n" << fld(1, 10) << fld(1, 10) << "\n";
  d << "*END\n";
  return d.str();
}

struct CrushResult {
  double crush = 0, work = 0, mean_force = 0, wa = 0, aj = 0;
  double mean_force_folds = 0;  // from a crush of 10 mm on (past the first fold's peak)
  double ratio_min = 1, ratio_max = 1, internal = 0, kinetic = 0, contact = 0, hourglass = 0, wall = 0;
  long cycles = 0, contact_node_cycles = 0;
  double max_pen = 0;
};

CrushResult crush(const Tube& T) {
  CrushResult r;
  Model m;
  Diagnostics diag;
  DeckFile deck;
  deck.load_from_string("tube.k", tube_deck(T));
  bool ok = read_deck(deck, m, diag, InputOptions{});
  if (ok) ok = check_model(m, diag);
  std::ostringstream msg;
  diag.print(msg);
  EXPECT_TRUE(ok) << msg.str();
  if (!ok) return r;
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  State& s = e.state();
  const int top = 4 * T.per_side * T.nz;  // first top node (0-based)
  const double z0 = s.z[std::size_t(top)];
  StepStatus st = StepStatus::ok;
  double w10 = -1, c10 = 0;
  while (st == StepStatus::ok) {
    st = e.step();
    const double c = z0 - s.z[std::size_t(top)];
    if (w10 < 0 && c >= 0.01) w10 = s.external_work, c10 = c;
    // (the ratio is meaningful once the external work is not round-off: from 1 mm of crush on)
    if (c >= 0.001) {
      r.ratio_min = std::min(r.ratio_min, s.energy_ratio());
      r.ratio_max = std::max(r.ratio_max, s.energy_ratio());
    }
    r.contact_node_cycles += e.contact().search_stats().contacts;
    r.max_pen = std::max(r.max_pen, e.contact().max_penetration());
    ++r.cycles;
  }
  EXPECT_EQ(st, StepStatus::finished);
  r.crush = z0 - s.z[std::size_t(top)];
  r.work = s.external_work;
  r.mean_force = r.work / r.crush;
  r.mean_force_folds = (r.work - w10) / (r.crush - c10);
  r.wa = 9.56 * T.sigy * std::pow(T.t, 5.0 / 3.0) * std::cbrt(T.b);
  // Abramowicz and Jones (Int J Impact Eng 2 (1984) 179-208): the same mechanism over the
  // effective crushing distance 0.73 x 2H, Pm = 52.22 M0 (b/t)^(1/3), M0 = sigma0 t^2 / 4
  r.aj = 52.22 * T.sigy * T.t * T.t / 4 * std::cbrt(T.b / T.t);
  r.internal = s.internal;
  r.kinetic = s.kinetic;
  r.contact = s.contact;
  r.hourglass = s.hourglass;
  r.wall = s.wall_work;
  std::printf("square tube b %.0f mm, t %.1f mm, %d x %d shells, %.0f m/s: crush %.2f mm in %ld cycles; external work %.2f J "
              "= internal %.2f + kinetic %.3f + hourglass %.3f + contact %.3f + wall %.3f (energy ratio %.4f..%.4f); "
              "mean force %.3f kN (from 10 mm on: %.3f kN), Wierzbicki-Abramowicz 9.56 s0 t^5/3 b^1/3 = %.3f kN "
              "(ratio %.3f, from 10 mm on %.3f), Abramowicz-Jones 13.06 s0 t^5/3 b^1/3 = %.3f kN (ratio %.3f, %.3f); "
              "%ld contact node-cycles, max penetration %.3g mm\n",
              T.b * 1e3, T.t * 1e3, 4 * T.per_side, T.nz, T.v, r.crush * 1e3, r.cycles, r.work, r.internal, r.kinetic,
              r.hourglass, r.contact, r.wall, r.ratio_min, r.ratio_max, r.mean_force / 1e3, r.mean_force_folds / 1e3,
              r.wa / 1e3, r.mean_force / r.wa, r.mean_force_folds / r.wa, r.aj / 1e3, r.mean_force / r.aj,
              r.mean_force_folds / r.aj, r.contact_node_cycles, r.max_pen * 1e3);
  return r;
}

}  // namespace

TEST(TubeCrush, ShortCoarseTubeFoldsWithSingleSurfaceContact) {
  Tube T;
  const CrushResult r = crush(T);
  EXPECT_NEAR(r.crush, T.crush, 0.02 * T.crush);
  EXPECT_GT(r.contact_node_cycles, 0);  // the folds touch
  EXPECT_LT(r.max_pen, T.t / 2);        // no fold gets to another's mid-surface (offsets t/2 + t/2)
  // energy balance: measured 1.0000..1.0044 (full version 1.0027)
  EXPECT_GT(r.ratio_min, 0.99);
  EXPECT_LT(r.ratio_max, 1.01);
  // mean force past the first fold's peak: measured 1.19 x Abramowicz-Jones, 1.63 x
  // Wierzbicki-Abramowicz (full version 1.14, 1.56); 15 m/s adds the folds' inertia
  EXPECT_GT(r.mean_force_folds / r.aj, 0.9);
  EXPECT_LT(r.mean_force_folds / r.aj, 1.4);
}

// The full version (manual benchmark): 2.5 mm shells (16 per side, 32 along 80 mm).
Tube full_tube() {
  Tube T;
  T.per_side = 16;
  T.nz = 32;
  return T;
}
TEST(TubeCrush, DISABLED_FullTube) { crush(full_tube()); }

// The full version is also shipped as a deck for the command line
// (tests/contact/square_tube_crush.k: impact3d i=square_tube_crush.k); it is this generator's
// text (IMPACT3D_WRITE_TUBE_DECK=1 rewrites it).
TEST(TubeCrush, ShippedDeckIsTheFullTube) {
  const std::string path = std::string(IMPACT3D_SOURCE_DIR) + "/tests/contact/square_tube_crush.k";
  const std::string text = tube_deck(full_tube());
  if (std::getenv("IMPACT3D_WRITE_TUBE_DECK")) {
    std::ofstream(path) << text;
  }
  std::ifstream in(path);
  ASSERT_TRUE(in.good()) << path;
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_TRUE(ss.str() == text) << path << " differs from tube_deck(full_tube())";
}
