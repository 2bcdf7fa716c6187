// Ductile failure of spot welds (issue 24): *CONSTRAINED_SPOTWELD EP and
// *CONSTRAINED_GENERALIZED_WELD_SPOT EPSF, the effective plastic strain at a weld's node at which
// the weld fails (LS-DYNA's ductile rule: the sheet tears around the weld).  The node's strain
// is the plastic strain of the shells on it projected to the node (their area-weighted mean,
// each shell's strain integrated through its thickness).
//
// Two identical steel strips (100 x 10 mm, t = 1 mm, 10 x 1 Belytschko-Tsay shells, isotropic
// linear hardening: sigma_y 250 MPa, E_t = E / 100), one 1 mm above the other, are joined at
// their mid-length by two welds (one at each edge) and stretched together: clamped along x at
// x = 0, the ends x = L pulled at v(t) (a ramp to V = 1 m/s over 0.5 ms, then V).  Both strips
// stretch alike, so the welds carry no force and do not disturb the uniform uniaxial stress:
// the true strain is eps = ln(1 + u / L), u = V (t - t_r / 2), and with sigma = sigma_y + H eps_p
// (H = E E_t / (E - E_t)) the plastic strain is eps_p = (eps - sigma_y / E) / (1 + H / E).  The
// welds fail when eps_p reaches EP: t_f = t_r / 2 + L (exp(sigma_y / E + EP (1 + H / E)) - 1) / V.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/spot_weld.h"
#include "../support/deck_text.h"
#include "../support/box_mesh.h"
#include "tests/support/threaded_run.h"

using namespace impact3d;

namespace {

constexpr int kN = 10;                               // shells along a strip
constexpr double kL = 0.1, kW = 0.01, kT = 0.001;    // strip length, width, thickness (m)
constexpr double kE = 2.1e11, kSy = 2.5e8, kEt = 2.1e9;
constexpr double kV = 1.0, kRamp = 5e-4;              // pull velocity (m/s), its ramp (s)
constexpr double kEp = 0.05;                          // the welds' failure plastic strain
constexpr double kH = kE * kEt / (kE - kEt);          // plastic modulus

int node_id(int sheet, int i, int j) { return sheet * 100 + 1 + i + (kN + 1) * j; }

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// The closed form: the time the strips' plastic strain reaches ep, and the plastic strain at t.
double failure_time(double ep) { return kRamp / 2 + kL * (std::exp(kSy / kE + ep * (1 + kH / kE)) - 1) / kV; }
double plastic_strain_at(double t) {
  const double u = t < kRamp ? kV * t * t / (2 * kRamp) : kV * (t - kRamp / 2);
  return std::max(0.0, (std::log(1 + u / kL) - kSy / kE) / (1 + kH / kE));
}

// weld: "spotweld" (two *CONSTRAINED_SPOTWELD, EP) or "generalized" (two
// *CONSTRAINED_GENERALIZED_WELD_SPOT of two-node sets, EPSF); ep 0: the field left blank;
// sy: the strips' yield stress.
std::string strips_deck(const std::string& weld, double ep, double end_time, double sy = kSy) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\ntwo welded strips stretched together\n*CONTROL_TERMINATION\n" << fmt("%10.4g\n", end_time);
  d << "*PART\nstrips\n         1         1         1\n";
  d << "*SECTION_SHELL\n         1         2       1.0         2\n" << fmt("%10.4g\n", kT);
  d << "*MAT_PLASTIC_KINEMATIC\n         1    7850.0" << fmt("%10.4g       0.3%10.4g%10.4g       1.0\n", kE, sy, kEt);
  d << "*NODE\n";
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= kN; ++i)
        d << fmt("%8.0f", node_id(sheet, i, j)) << fmt("%16.8g%16.8g%16.8g\n", kL * i / kN, kW * j, sheet * 0.001);
  d << "*ELEMENT_SHELL\n";
  int eid = 0;
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int i = 0; i < kN; ++i)
      d << fmt("%8.0f       1", ++eid) << fmt("%8.0f%8.0f", node_id(sheet, i, 0), node_id(sheet, i + 1, 0))
        << fmt("%8.0f%8.0f\n", node_id(sheet, i + 1, 1), node_id(sheet, i, 1));
  // z held everywhere (membrane); y at the edge y = 0; x at the clamp x = 0
  d << "*BOUNDARY_SPC_NODE\n";
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= kN; ++i)
        d << fmt("%10.0f         0", node_id(sheet, i, j)) << fmt("%10.0f%10.0f         1\n", i == 0 ? 1 : 0, j == 0 ? 1 : 0);
  d << "*DEFINE_CURVE\n         2\n                 0.0                 0.0\n" << fmt("%20.6g%20.6g\n", kRamp, kV)
    << fmt("%20.6g%20.6g\n", 1.0, kV);
  d << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j <= 1; ++j) d << fmt("%10.0f         1         0         2\n", node_id(sheet, kN, j));
  const std::string ep_field = ep > 0 ? fmt("%10.4g", ep) : "          ";
  for (int j = 0; j <= 1; ++j) {
    const int a = node_id(0, kN / 2, j), b = node_id(1, kN / 2, j);
    if (weld == "spotweld") {
      d << "*CONSTRAINED_SPOTWELD\n" << fmt("%10.0f%10.0f", a, b) << "       0.0       0.0       0.0       0.0       0.0" << ep_field
        << "\n";
    } else {
      d << "*SET_NODE_LIST\n" << fmt("%10.0f\n", 50 + j) << fmt("%10.0f%10.0f\n", a, b);
      d << "*CONSTRAINED_GENERALIZED_WELD_SPOT\n" << fmt("%10.0f\n", 50 + j) << "       0.0" << ep_field << "\n";
    }
  }
  d << "*END\n";
  return d.str();
}

using Read = test_support::ReadDeck;
Read read_text(const std::string& text) { return test_support::read_deck_text(text, "strips.k"); }

int index_of(const Model& m, int id) {
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_id(i) == id) return i;
  return -1;
}

struct Outcome {
  double t_fail = -1;            // when the welds were released (-1: never)
  int released = 0;              // welds released in that cycle
  int release_cycles = 0;        // cycles in which any weld was released
  double ep_mid = 0, t_mid = 0;  // the weld node's plastic strain at about half of t_f
  double ep_trigger = 0;         // ... that the release step's check saw (the last element pass's)
  double ep_prior = 0;           // ... one step earlier
  double shell_ep_trigger = 0;   // a shell on the weld node (its points' mean) at the release step
};

Outcome run_strips(const Read& r, double t_expect) {
  Engine e(r.m);
  Outcome o;
  if (e.initialize() != StepStatus::ok) return o;
  const State& s = e.state();
  const int weld_node = index_of(r.m, node_id(0, kN / 2, 0));
  StepStatus st = StepStatus::ok;
  double ep_last = 0;
  while (st == StepStatus::ok) {
    // the strains of the last element pass: what this step's release check reads (the element
    // pass ends a step, after the positions move)
    const double ep = spot_weld_node_plastic_strain(s, weld_node);
    const double shell_ep = s.shells.eps_p.empty() ? 0.0 : 0.5 * (s.shells.eps_p[shell_point_at(s.shells, 0, 0)] + s.shells.eps_p[shell_point_at(s.shells, 0, 1)]);
    const double t0 = s.time;
    st = e.step();
    if (!s.newly_released.empty()) {
      ++o.release_cycles;
      if (o.t_fail < 0) {
        o.t_fail = s.time;
        o.released = int(s.newly_released.size());
        o.ep_trigger = ep;
        o.ep_prior = ep_last;
        o.shell_ep_trigger = shell_ep;
      }
    }
    ep_last = ep;
    if (t0 <= 0.5 * t_expect) o.ep_mid = ep, o.t_mid = t0;
  }
  return o;
}

}  // namespace

// The welds fail when the strips' plastic strain at their nodes reaches EP (EPSF): at the
// closed form's t_f within 1 %, both in the same cycle, once; the node's strain follows the
// closed form (2 %); the strain the release step saw has reached EP, the one a step earlier
// had not.
TEST(SpotWeldDuctile, WeldsFailWhenTheSheetsPlasticStrainReachesEp) {
  const double tf = failure_time(kEp);
  for (const std::string weld : {"spotweld", "generalized"}) {
    SCOPED_TRACE(weld);
    Read r = read_text(strips_deck(weld, kEp, 1.2 * tf));
    ASSERT_TRUE(r.ok) << r.messages();
    ASSERT_EQ(r.m.spot_welds.size(), 2u);
    EXPECT_EQ(r.m.spot_welds[0].epsf, kEp);
    const Outcome o = run_strips(r, tf);
    const double ep_mid = plastic_strain_at(o.t_mid);
    std::printf("[ measured ] %s: welds released at %.6f ms (closed form %.6f ms, %+.3f %%), %d in that cycle; weld node's "
                "plastic strain at %.4f ms %.6f (closed form %.6f, %+.3f %%), at the release %.6f, a step before %.6f (EP %.3f), "
                "a shell on it %.6f\n",
                weld.c_str(), o.t_fail * 1e3, tf * 1e3, 100 * (o.t_fail / tf - 1), o.released, o.t_mid * 1e3, o.ep_mid, ep_mid,
                100 * (o.ep_mid / ep_mid - 1), o.ep_trigger, o.ep_prior, kEp, o.shell_ep_trigger);
    EXPECT_NEAR(o.t_fail / tf, 1.0, 0.01);
    EXPECT_EQ(o.released, 2);
    EXPECT_EQ(o.release_cycles, 1);
    EXPECT_NEAR(o.ep_mid / ep_mid, 1.0, 0.02);
    EXPECT_GE(o.ep_trigger, kEp);
    EXPECT_LT(o.ep_prior, kEp);
    EXPECT_NEAR(o.shell_ep_trigger / o.ep_trigger, 1.0, 0.01);  // uniform: the node's mean is its shells'
  }
}

// EP blank (LS-DYNA's default 1e20), EPSF blank (0): no ductile failure; nor with sheets that
// stay elastic.
TEST(SpotWeldDuctile, NoFailureWithoutEpOrPlasticStrain) {
  const double tf = failure_time(kEp);
  for (const std::string weld : {"spotweld", "generalized"}) {
    SCOPED_TRACE(weld);
    Read blank = read_text(strips_deck(weld, 0, 1.2 * tf));
    ASSERT_TRUE(blank.ok) << blank.messages();
    EXPECT_EQ(blank.m.spot_welds[0].epsf, 0.0);
    EXPECT_LT(run_strips(blank, tf).t_fail, 0);
    Read elastic = read_text(strips_deck(weld, kEp, 1.2 * tf, 1e10));
    ASSERT_TRUE(elastic.ok) << elastic.messages();
    EXPECT_LT(run_strips(elastic, tf).t_fail, 0);
  }
}

// The run log names the rule: message 5006 with the node's plastic strain and EP, once per weld.
TEST(SpotWeldDuctile, ReleaseIsReportedWithThePlasticStrain) {
  const double tf = failure_time(kEp);
  Read r = read_text(strips_deck("spotweld", kEp, 1.1 * tf));
  ASSERT_TRUE(r.ok) << r.messages();
  const auto dir = test_support::empty_run_folder("spot_weld_ductile");
  RunOptions o;
  o.printed = (dir / "d3hsp").string();
  o.plot = (dir / "d3plot").string();
  o.dump = (dir / "d3dump").string();
  o.quiet = true;
  o.threads = 1;
  std::ostringstream log;
  EXPECT_EQ(run_simulation(r.m, o, log), 0);
  const std::string text = log.str();
  std::size_t n = 0;
  for (std::size_t at = text.find("info 5006"); at != std::string::npos; at = text.find("info 5006", at + 1)) ++n;
  EXPECT_EQ(n, 2u) << text;
  EXPECT_NE(text.find("reached its failure strain 5.000000e-02"), std::string::npos) << text;
}

// The same bits for 1 and 2 threads.
TEST(SpotWeldDuctile, SameBitsForOneAndTwoThreads) {
  const double tf = failure_time(kEp);
  Read r = read_text(strips_deck("generalized", kEp, 1.1 * tf));
  ASSERT_TRUE(r.ok) << r.messages();
  const State a = test_support::run_to_end_on_threads(r.m, 1), b = test_support::run_to_end_on_threads(r.m, 2);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.shells.eps_p, b.shells.eps_p);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_TRUE(a.rigid[0].released && a.rigid[1].released);
}
