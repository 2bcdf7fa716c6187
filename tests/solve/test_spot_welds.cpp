// Spot welds, against closed forms: *CONSTRAINED_SPOTWELD and *CONSTRAINED_GENERALIZED_WELD_SPOT
// (rigid links with force- and time-based failure) and *MAT_SPOTWELD beams (resultant-based
// failure, the beam deleted); the bad fields each get their numbered message.
//
// The weld tests pull two elastic steel cubes (1 m, one solid each) apart with a force that
// grows linearly, F(t) = k t on each cube (k / 4 on each of its four far corners).  Four welds
// join the facing corners.  The cubes are stiff (axial period 4 L / c ~ 7e-4 s) against the
// ramp (t_f ~ 0.04 s), so each weld carries F / 4 (the cubes barely accelerate) until its
// failure force: t_f = 4 SN / k.  After the release each cube moves freely: its momentum is
// the load's impulse since t_f, k (t^2 - t_f^2) / 2.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/beam_processing.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/spot_weld.h"
#include "tests/support/box_mesh.h"
#include "../support/deck_text.h"
#include "tests/support/threaded_run.h"

using namespace impact3d;

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& text) { return test_support::read_deck_text(text, "welds.k"); }

constexpr double kRate = 1e6;  // N/s on each cube

// Two unit cubes of elastic steel, cube B from x = x0 on; each pulled away from the other along
// `pull_dof` (1 x, 2 y) by k t (the ramp reaches k at t = 1 s): on their far faces, or with
// `at_welds` on their facing corners (the welds' own nodes: no lever arm).  `welds`: the weld
// keywords.
std::string two_cubes(double x0, int pull_dof, const std::string& welds, double end_time = 0.06, bool at_welds = false) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\ntwo welded cubes\n*CONTROL_TERMINATION\n" << end_time << "\n";
  // a free single hexahedron needs a smaller step factor than a mesh (as tests/cli/one_hex_*)
  d << "*CONTROL_TIMESTEP\n       0.0       0.5\n";
  d << "*PART\ncube A\n         1         1         1\n*PART\ncube B\n         2         1         1\n";
  d << "*SECTION_SOLID\n         1         1\n";
  d << "*MAT_ELASTIC\n         1    7850.0   2.1e+11       0.3\n";
  d << "*NODE\n";
  const double p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < 8; ++j) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%8d%16.6f%16.6f%16.6f\n", 8 * c + j + 1, p[j][0] + (c ? x0 : 0.0), p[j][1], p[j][2]);
      d << buf;
    }
  d << "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7       8\n";
  d << "       2       2       9      10      11      12      13      14      15      16\n";
  d << "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n                 1.0               1.0e6\n";
  // cube A's far face (x = 0: nodes 1 4 5 8) pulled one way, cube B's (nodes 10 11 14 15) the other
  d << "*LOAD_NODE_POINT\n";
  const std::array<int, 4> a_far = {1, 4, 5, 8}, b_far = {10, 11, 14, 15}, a_near = {2, 3, 6, 7}, b_near = {9, 12, 13, 16};
  for (int c = 0; c < 2; ++c)
    for (int n : c == 0 ? (at_welds ? a_near : a_far) : (at_welds ? b_near : b_far)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%10d%10d%10d%10.4f\n", n, pull_dof, 1, c == 0 ? -0.25 : 0.25);
      d << buf;
    }
  d << welds << "*END\n";
  return d.str();
}

// The four corner pairs of the facing faces: A's x = 1 corners and B's x = x0 corners.
constexpr int kPairs[4][2] = {{2, 9}, {3, 12}, {6, 13}, {7, 16}};

std::string spotwelds(double sn, double ss, double n, double m, double tf = 0) {
  std::ostringstream d;
  d << "*CONSTRAINED_SPOTWELD\n";
  for (const auto& pr : kPairs) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%10d%10d%10.4g%10.4g%10.4g%10.4g%10.4g\n", pr[0], pr[1], sn, ss, n, m, tf);
    d << buf;
  }
  return d.str();
}

// Momentum of cube c (nodes 8c .. 8c + 7) along axis a.
double cube_momentum(const Model& m, const State& s, int c, int a) {
  double p = 0;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const int id = m.node_id(i);
    if (id < 8 * c + 1 || id > 8 * c + 8) continue;
    const double v = a == 0 ? s.vx[std::size_t(i)] : a == 1 ? s.vy[std::size_t(i)] : s.vz[std::size_t(i)];
    p += s.mass[std::size_t(i)] * v;
  }
  return p;
}

struct PullResult {
  double t_release = -1;       // time at the end of the cycle that released the welds
  double weld_force_half = 0;  // weld 1's normal (or shear) constraint force at t_f / 2
  double t_half = 0;
  double pA = 0, pB = 0, t_end = 0;
  double worst_ratio = 1;      // energy ratio, worst deviation from 1
  int released = 0;
};

// Runs the deck; `check_t`: when to sample weld 1's force (its component along `axis`); the
// energy ratio from t_ratio on (while the welds hold, the cubes' elastic energy and the load's
// work are ~1e-4 J: their ratio says nothing; after the release the work is ~100 J).
PullResult run_pull(const Model& m, double check_t, int axis, int pull_axis, double t_ratio) {
  PullResult r;
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  StepStatus st = StepStatus::ok;
  bool sampled = false;
  while (st == StepStatus::ok) {
    const double t0 = s.time;
    st = e.step();
    if (!sampled && s.time >= check_t && !s.rigid.empty() && !s.rigid[0].released) {
      // the constraint force of this cycle at t0 (dt_n: the mean of the two half steps, equal
      // here: the cubes' step does not change)
      const double dtn = s.dt_half;
      const std::array<double, 3> f = spot_weld_constraint_force(s, s.rigid[0], 1, dtn);
      r.weld_force_half = f[std::size_t(axis)];
      r.t_half = t0;
      sampled = true;
    }
    if (!s.newly_released.empty()) {
      r.released += int(s.newly_released.size());
      if (r.t_release < 0) r.t_release = s.time;
    }
    if (s.time >= t_ratio && std::fabs(s.energy_ratio() - 1) > std::fabs(r.worst_ratio - 1)) r.worst_ratio = s.energy_ratio();
  }
  EXPECT_EQ(st, StepStatus::finished);
  r.pA = cube_momentum(m, s, 0, pull_axis);
  r.pB = cube_momentum(m, s, 1, pull_axis);
  r.t_end = s.time;
  return r;
}

}  // namespace

// Four welds pulled in tension: each carries F / 4 = k t / 4 until SN; all four fail at
// t_f = 4 SN / k; then each cube's momentum is the load's impulse since t_f.
TEST(SpotWeld, PulledApartFailsAtItsNormalForce) {
  const double sn = 1e4, tf = 4 * sn / kRate;  // 0.04 s
  Read r = read_text(two_cubes(1.1, 1, spotwelds(sn, 0, 2, 2)));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.spot_welds.size(), 4u);
  PullResult p = run_pull(r.m, 0.5 * tf, 0, 0, 1.1 * tf);
  // before the failure: node 9 (cube B's corner) is held back by -F/4
  EXPECT_NEAR(p.weld_force_half, -kRate * p.t_half / 4, 0.02 * kRate * p.t_half / 4);
  EXPECT_EQ(p.released, 4);
  EXPECT_NEAR(p.t_release, tf, 0.02 * tf) << "released at " << p.t_release;
  const double impulse = kRate * (p.t_end * p.t_end - tf * tf) / 2;
  EXPECT_NEAR(p.pB, impulse, 0.03 * impulse);
  EXPECT_NEAR(p.pA, -impulse, 0.03 * impulse);
  EXPECT_NEAR(p.pA + p.pB, 0.0, 1e-9 * impulse);  // momentum balance: the welds' forces are internal
  EXPECT_NEAR(p.worst_ratio, 1.0, 0.01);
  std::printf("[ measured ] normal weld: force at %.4f s %.6e (closed form %.6e), released at %.6f s (closed form %.6f), "
              "p_B %.6e (closed form %.6e), worst energy ratio %.6f\n",
              p.t_half, -p.weld_force_half, kRate * p.t_half / 4, p.t_release, tf, p.pB, impulse, p.worst_ratio);
}

// Without a failure force the welds hold: the cubes move as one (no momentum of their own: the
// loads cancel), the weld nodes keep their distance, the energy balance holds.
TEST(SpotWeld, RigidLinkKeepsItsNodesRigid) {
  // shear the pair: cube A pushed -y, cube B +y; the four links carry the couple
  Read r = read_text(two_cubes(1.1, 2, spotwelds(0, 0, 0, 0), 0.02));
  ASSERT_TRUE(r.ok) << r.messages();
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  auto dist = [&](int w) {
    const auto& n = r.m.spot_welds[std::size_t(w)].nodes;
    const std::size_t a = std::size_t(n[0]), b = std::size_t(n[1]);
    return std::sqrt((s.x[a] - s.x[b]) * (s.x[a] - s.x[b]) + (s.y[a] - s.y[b]) * (s.y[a] - s.y[b]) + (s.z[a] - s.z[b]) * (s.z[a] - s.z[b]));
  };
  double worst_len = 0, worst_rate = 0, worst_ratio = 0;
  StepStatus st = StepStatus::ok;
  std::vector<double> x0(s.x), y0(s.y), z0(s.z);
  while (st == StepStatus::ok) {
    x0 = s.x, y0 = s.y, z0 = s.z;  // x^n: the velocities v^{n+1/2} are the body's motion about it
    st = e.step();
    for (int w = 0; w < 4; ++w) {
      worst_len = std::max(worst_len, std::fabs(dist(w) - 0.1) / 0.1);
      const auto& n = r.m.spot_welds[std::size_t(w)].nodes;
      const std::size_t a = std::size_t(n[0]), b = std::size_t(n[1]);
      const double d[3] = {x0[b] - x0[a], y0[b] - y0[a], z0[b] - z0[a]};
      const double dv[3] = {s.vx[b] - s.vx[a], s.vy[b] - s.vy[a], s.vz[b] - s.vz[a]};
      const double dvm = std::sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
      if (dvm > 1e-12) worst_rate = std::max(worst_rate, std::fabs(d[0] * dv[0] + d[1] * dv[1] + d[2] * dv[2]) / (0.1 * dvm));
    }
    if (s.time >= 0.005) worst_ratio = std::max(worst_ratio, std::fabs(s.energy_ratio() - 1));
  }
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_LT(worst_len, 1e-12);   // positions from the body's rotation: no drift
  EXPECT_LT(worst_rate, 1e-12);  // the relative velocity is normal to the link (cosine)
  EXPECT_LT(worst_ratio, 0.01);  // from 5 ms on (before, the work is too small to compare)
  double p = cube_momentum(r.m, s, 0, 1) + cube_momentum(r.m, s, 1, 1);
  EXPECT_NEAR(p, 0.0, 1e-6);
  std::printf("[ measured ] rigid link: |d| - d0 worst %.3e (relative), d.(v2 - v1) worst %.3e, energy ratio worst %.3e from 1\n",
              worst_len, worst_rate, worst_ratio);
}

// The generalized weld's spot form on coincident nodes (cubes touching), the normal from CID
// (local z = global x): the facing corners pulled in shear (y, F / 4 on each node), each weld
// carries F / 4 of shear until SS: t_f = 4 SS / k.
TEST(SpotWeld, GeneralizedWeldFailsInShearAndByTime) {
  const double ss = 2e4, tf = 4 * ss / kRate;  // 0.08 s
  std::ostringstream w;
  w << "*DEFINE_COORDINATE_SYSTEM\n         7       0.0       0.0       0.0       0.0       1.0       0.0\n       0.0       0.0       1.0\n";
  for (int k = 0; k < 4; ++k) {
    w << "*SET_NODE_LIST\n" << 10 + k << "\n" << std::string(10 - std::to_string(kPairs[k][0]).size(), ' ') << kPairs[k][0]
      << std::string(10 - std::to_string(kPairs[k][1]).size(), ' ') << kPairs[k][1] << "\n";
    w << "*CONSTRAINED_GENERALIZED_WELD_SPOT\n" << std::string(10 - std::to_string(10 + k).size(), ' ') << 10 + k << "         7\n";
    w << "       0.0       0.0       0.0   2.0e+04       2.0       2.0\n";
  }
  Read r = read_text(two_cubes(1.0, 2, w.str(), 0.1, true));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.spot_welds.size(), 4u);
  EXPECT_TRUE(r.m.spot_welds[0].has_axis);
  EXPECT_NEAR(r.m.spot_welds[0].axis[0], 1.0, 1e-12);
  PullResult p = run_pull(r.m, 0.5 * tf, 1, 1, 1.1 * tf);
  EXPECT_NEAR(p.weld_force_half, -kRate * p.t_half / 4, 0.02 * kRate * p.t_half / 4);
  EXPECT_EQ(p.released, 4);
  EXPECT_NEAR(p.t_release, tf, 0.02 * tf);
  const double impulse = kRate * (p.t_end * p.t_end - tf * tf) / 2;
  EXPECT_NEAR(p.pB, impulse, 0.05 * impulse);
  EXPECT_NEAR(p.worst_ratio, 1.0, 0.01);
  std::printf("[ measured ] shear weld (generalized, CID): force at %.4f s %.6e (closed form %.6e), released at %.6f s (closed form %.6f), "
              "p_B %.6e (closed form %.6e), worst energy ratio %.6f\n",
              p.t_half, -p.weld_force_half, kRate * p.t_half / 4, p.t_release, tf, p.pB, impulse, p.worst_ratio);

  // TFAIL: the same welds without failure forces, released at 0.03 s
  std::string timed = w.str();
  for (std::size_t q = timed.find("       0.0       0.0       0.0   2.0e+04"); q != std::string::npos;
       q = timed.find("       0.0       0.0       0.0   2.0e+04", q + 1))
    timed.replace(q, 40, "      0.03       0.0       0.0       0.0");
  Read r2 = read_text(two_cubes(1.0, 2, timed, 0.05, true));
  ASSERT_TRUE(r2.ok) << r2.messages();
  PullResult p2 = run_pull(r2.m, 1.0, 1, 1, 1.0);
  EXPECT_EQ(p2.released, 4);
  EXPECT_GE(p2.t_release, 0.03);
  EXPECT_LT(p2.t_release, 0.03 + 2e-4);  // within the cycle after TFAIL (dt ~ 8e-5 s)
  std::printf("[ measured ] TFAIL 0.03 s: released at the end of the cycle at %.6f s\n", p2.t_release);
}

// *MAT_SPOTWELD beam: one Hughes-Liu beam (10 mm square, 0.1 m) clamped at node 1 and pulled
// along its axis at node 2 by k t: N = k t (the end mass's oscillation is 1/(omega t) ~ 1e-3 of
// it) until NRR; the beam is deleted at t_f = NRR / k, flagged in the plot state, and node 2
// then takes the load's impulse k (t^2 - t_f^2) / 2.
TEST(SpotWeldBeam, FailsAtItsAxialResultantAndIsDeleted) {
  const double nrr = 1e4, tf = nrr / kRate;  // 0.01 s
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nspot weld beam\n*CONTROL_TERMINATION\n0.015\n";
  d << "*PART\nweld\n         1         1         1\n";
  d << "*SECTION_BEAM\n         1         1       1.0         2         0\n      0.01      0.01      0.01      0.01\n";
  d << "*MAT_SPOTWELD\n         1    7850.0   2.1e+11       0.3   5.0e+08       0.0       0.0       0.0\n";
  d << "       0.0   1.0e+04       0.0       0.0       0.0       0.0       0.0\n";
  d << "*NODE\n       1             0.0             0.0             0.0       7       7\n";
  d << "       2             0.1             0.0             0.0\n       3             0.0             1.0             0.0       7\n";
  d << "*ELEMENT_BEAM\n       1       1       1       2       3\n";
  d << "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n                 1.0               1.0e6\n";
  d << "*LOAD_NODE_POINT\n         2         1         1       1.0\n*END\n";
  Read r = read_text(d.str());
  ASSERT_TRUE(r.ok) << r.messages();
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  double t_fail = -1, n_before = 0, t_before = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = e.step();
    if (!s.beams.newly_failed.empty() && t_fail < 0) t_fail = s.time;
    if (t_fail < 0 && s.time < 0.5 * tf) n_before = s.beams.res[0], t_before = s.time;
  }
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_NEAR(n_before, kRate * t_before, 0.01 * kRate * t_before);
  EXPECT_NEAR(t_fail, tf, 0.01 * tf);
  EXPECT_EQ(s.beams.failed[0], 1);
  PlotState ps;
  fill_plot_state(r.m, s, InterfaceForces{}, ps);
  ASSERT_EQ(ps.beam_alive.size(), 1u);
  EXPECT_EQ(ps.beam_alive[0], 0);
  const std::size_t n2 = 1;
  const double impulse = kRate * (s.time * s.time - tf * tf) / 2;
  EXPECT_NEAR(s.mass[n2] * s.vx[n2], impulse, 0.02 * impulse);
  // no force in the deleted beam
  EXPECT_EQ(s.cfx[s.beams.corner_base + 1], 0.0);
  std::printf("[ measured ] spot-weld beam: N at %.5f s %.6e (closed form %.6e), deleted at %.6f s (closed form %.6f), "
              "node 2 momentum %.6e (closed form %.6e)\n",
              t_before, n_before, kRate * t_before, t_fail, tf, s.mass[n2] * s.vx[n2], impulse);

  // the rule itself: quadratic in the resultants, the axial force in tension only
  MaterialConstants mc = s.mats[0];
  const double res_c[6] = {-2e4, 0, 0, 0, 0, 0};
  EXPECT_FALSE(spot_weld_beam_fails(mc, res_c, nullptr, 0, 0.0));
  mc.k[kSpotWeldNRR + 1] = 1e3;  // NRS
  const double res_m[6] = {0.8e4, 0.5e3, 0, 0, 0, 0};  // 0.64 + 0.25 < 1
  EXPECT_FALSE(spot_weld_beam_fails(mc, res_m, nullptr, 0, 0.0));
  const double res_f[6] = {0.8e4, 0.61e3, 0, 0, 0, 0};  // 0.64 + 0.3721 > 1
  EXPECT_TRUE(spot_weld_beam_fails(mc, res_f, nullptr, 0, 0.0));
}

// Bad fields: each its numbered message naming the card, the field and its columns.
TEST(SpotWeldInput, BadFieldsGetNumberedMessages) {
  auto expect = [](const std::string& welds, int id, const char* field) -> std::string {
    Read r = read_text(two_cubes(1.1, 1, welds));
    EXPECT_FALSE(r.ok) << welds;
    const Diagnostic* g = r.first(id);
    EXPECT_NE(g, nullptr) << "no message " << id << " for\n" << welds << r.messages();
    if (g && field) {
      EXPECT_EQ(g->where.field, field) << r.messages();
    }
    return r.messages();
  };
  expect("*CONSTRAINED_SPOTWELD\n         2         9   -1.0e+4\n", 1003, "SN");
  expect("*CONSTRAINED_SPOTWELD\n         2         9    1.0e+4       0.0       0.0\n", 1003, "N");
  expect("*CONSTRAINED_SPOTWELD\n         2         9       0.0       0.0       0.0       0.0       0.0      -0.2\n", 1003, "EP");
  expect("*SET_NODE_LIST\n        55\n         2         9\n*CONSTRAINED_GENERALIZED_WELD_SPOT\n        55\n"
         "       0.0      -0.1\n",
         1003, "EPSF");
  expect("*CONSTRAINED_SPOTWELD\n         2        99\n", 1202, "N2");
  expect("*CONSTRAINED_SPOTWELD\n         2         9\n         9         3\n", 1253, nullptr);
  expect("*CONSTRAINED_GENERALIZED_WELD_SPOT\n        55\n       0.0       0.0       0.0       0.0\n", 1309, "NSID");
  expect("*SET_NODE_LIST\n        55\n         2         9\n*CONSTRAINED_GENERALIZED_WELD_SPOT\n        55         0         2\n"
         "       0.0       0.0       0.0       0.0\n",
         1102, "FILTER");
  const std::string s = expect("*CONSTRAINED_SPOTWELD\n         2         9   -1.0e+4\n", 1003, "SN");
  EXPECT_NE(s.find("cols 21-30"), std::string::npos) << s;
  // coincident nodes with a failure force and no CID: no normal direction
  {
    Read r = read_text(two_cubes(1.0, 1, "*SET_NODE_LIST\n        55\n         2         9\n*CONSTRAINED_GENERALIZED_WELD_SPOT\n        55\n"
                                            "       0.0       0.0    1.0e+4       0.0       2.0\n"));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.first(1252), nullptr) << r.messages();
  }
  // *MAT_SPOTWELD: NF above 30 (1003) and a negative failure resultant (a curve, 1102) are refused by field
  {
    std::string deck = two_cubes(1.1, 1, "");
    const std::string elastic = "*MAT_ELASTIC\n         1    7850.0   2.1e+11       0.3\n";
    deck.replace(deck.find(elastic), elastic.size(),
                 "*MAT_SPOTWELD\n         1    7850.0   2.1e+11       0.3    2.0e+8\n       0.0   -1.0e+4       0.0       0.0       0.0       0.0       0.0        31\n");
    Read r = read_text(deck);
    EXPECT_FALSE(r.ok);
    bool nrr = false, nf = false;
    for (const auto& x : r.d.all()) {
      nrr = nrr || (x.id == 1102 && x.where.field == "NRR");
      nf = nf || (x.id == 1003 && x.where.field == "NF");
    }
    EXPECT_TRUE(nrr) << r.messages();
    EXPECT_TRUE(nf) << r.messages();
  }
}

// The converter writes the welds back (keyword decks): the same nodes, forces, exponents, times,
// ductile failure strains (EPSF, EP) and axes after a round trip.
TEST(SpotWeldInput, ConverterRoundTrip) {
  std::ostringstream w;
  w << "*DEFINE_COORDINATE_SYSTEM\n         7       0.0       0.0       0.0       0.0       1.0       0.0\n       0.0       0.0       1.0\n";
  w << "*SET_NODE_LIST\n        10\n         3        12\n";
  w << "*CONSTRAINED_GENERALIZED_WELD_SPOT_ID\n        44\n        10         7\n      0.03      0.15    1.0e+4    2.0e+4       2.0       3.0\n";
  w << "*CONSTRAINED_SPOTWELD\n         2         9    5.0e+3    6.0e+3       1.5       2.5      0.04      0.25\n";
  Read a = read_text(two_cubes(1.1, 1, w.str()));
  ASSERT_TRUE(a.ok) << a.messages();
  std::ostringstream out;
  std::vector<std::string> notes;
  write_keyword_deck(out, a.m, &notes);
  Read b = read_text(out.str());
  ASSERT_TRUE(b.ok) << b.messages() << out.str();
  ASSERT_EQ(b.m.spot_welds.size(), 2u);
  auto same = [](const SpotWeld& x, const SpotWeld& y) {
    EXPECT_EQ(x.nodes, y.nodes);
    EXPECT_EQ(x.sn, y.sn);
    EXPECT_EQ(x.ss, y.ss);
    EXPECT_EQ(x.n, y.n);
    EXPECT_EQ(x.m, y.m);
    EXPECT_EQ(x.tfail, y.tfail);
    EXPECT_EQ(x.epsf, y.epsf);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.has_axis, y.has_axis);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(x.axis[std::size_t(c)], y.axis[std::size_t(c)], 1e-12);
  };
  same(a.m.spot_welds[0], b.m.spot_welds[0]);
  same(a.m.spot_welds[1], b.m.spot_welds[1]);
  EXPECT_EQ(a.m.spot_welds[0].epsf, 0.15);
  EXPECT_EQ(a.m.spot_welds[1].epsf, 0.25);
}

// The same bits for 1 and 2 threads (the welds are checked in weld order, the bodies updated
// serially; the element and node passes' reductions do not depend on the thread count).
TEST(SpotWeld, SameBitsForOneAndTwoThreads) {
  Read r = read_text(two_cubes(1.1, 1, spotwelds(1e4, 0, 2, 2)));
  ASSERT_TRUE(r.ok) << r.messages();
  const State a = test_support::run_to_end_on_threads(r.m, 1), b = test_support::run_to_end_on_threads(r.m, 2);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_EQ(a.kinetic, b.kinetic);
  EXPECT_TRUE(a.rigid[0].released);
}

// NF (*MAT_SPOTWELD card 2 field 8): the failure rule takes the mean of the beam's last NF
// resultant vectors.  On the ramp N = k t the mean of the last NF samples lags the current one
// by (NF - 1) / 2 steps, so the weld fails (NF - 1) / 2 steps later than without filtering (the
// step is constant here); the run's forces are the same until then (the filter touches only
// the rule); the restart dump carries the stored resultants (SpotWeldPeel.RestartBefore...).
TEST(SpotWeldBeam, FilteredResultantsFailLaterByHalfTheWindow) {
  auto deck = [](int nf) {
    std::ostringstream d;
    d << "*KEYWORD\n*TITLE\nspot weld beam\n*CONTROL_TERMINATION\n0.012\n";
    d << "*PART\nweld\n         1         1         1\n";
    d << "*SECTION_BEAM\n         1         1       1.0         2         0\n      0.01      0.01      0.01      0.01\n";
    d << "*MAT_SPOTWELD\n         1    7850.0   2.1e+11       0.3   5.0e+08       0.0       0.0       0.0\n";
    char buf[16];
    std::snprintf(buf, sizeof buf, "%10d", nf);
    d << "       0.0   1.0e+04       0.0       0.0       0.0       0.0       0.0" << buf << "\n";
    d << "*NODE\n       1             0.0             0.0             0.0       7       7\n";
    d << "       2             0.1             0.0             0.0\n       3             0.0             1.0             0.0       7\n";
    d << "*ELEMENT_BEAM\n       1       1       1       2       3\n";
    d << "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n                 1.0               1.0e6\n";
    d << "*LOAD_NODE_POINT\n         2         1         1       1.0\n*END\n";
    return d.str();
  };
  struct Out {
    int cycle = -1;
    double time = -1, dt = 0;
    std::vector<double> x;
  };
  auto run = [&](int nf, int stop_cycle) {
    Read r = read_text(deck(nf));
    EXPECT_TRUE(r.ok) << r.messages();
    Engine e(r.m);
    EXPECT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    Out o;
    while (e.step() == StepStatus::ok && (stop_cycle < 0 || s.cycle < stop_cycle))
      if (!s.beams.newly_failed.empty() && o.cycle < 0) o.cycle = s.cycle, o.time = s.time, o.dt = s.dt_half;
    o.x = s.x;
    return o;
  };
  const Out plain = run(0, -1), filtered = run(10, -1);
  ASSERT_GE(plain.cycle, 0);
  ASSERT_GE(filtered.cycle, 0);
  std::printf("[ measured ] NF 10: failed at cycle %d (%.7f s), NF 0: cycle %d (%.7f s): %d cycles later (closed form "
              "(NF - 1) / 2 = 4.5)\n",
              filtered.cycle, filtered.time, plain.cycle, plain.time, filtered.cycle - plain.cycle);
  EXPECT_GE(filtered.cycle - plain.cycle, 4);
  EXPECT_LE(filtered.cycle - plain.cycle, 5);
  // the same motion until the plain weld fails
  const Out a = run(0, plain.cycle - 1), b = run(10, plain.cycle - 1);
  EXPECT_EQ(a.x, b.x);
  // NF not whole: error 1003 naming NF (above 30: SpotWeldInput.BadFieldsGetNumberedMessages)
  std::string half = deck(10);
  half.replace(half.find("        10\n*NODE"), 10, "       2.5");
  Read bad = read_text(half);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.messages().find("error 1003"), std::string::npos) << bad.messages();
  EXPECT_NE(bad.messages().find("\"NF\""), std::string::npos) << bad.messages();
}
