// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET with DOF 9-11 (issue 25): nodes turning about an axis
// along x, y or z through card 2's (OFFSET1, OFFSET2), their distance from the axis kept, free
// along it (docs/keyword-decks.md).  Closed forms on an elastic block whose every node turns
// about z through (x0, y0): a rigid rotation, so
//  - VAD 0 (angular velocity w): each node ends on the exact rotation by w t (the chord steps
//    keep the radius: no drift), z unchanged, no strain energy;
//  - VAD 2 (the angle theta(t)): each node ends at theta(t_end);
//  - the kinetic energy is that of the chord velocities, all of it the reactions' work;
//  - VAD 1 (angular acceleration alpha): each node ends turned by alpha t^2 / 2;
//  - DOF -11 (its distance from the axis free): a block too soft to matter, set turning at w,
//    is a bead on a turning rod: each node's distance from the axis grows as r0 cosh(w t);
// refusals (LRB, DOF 5 on a solid's nodes), the converter's round trip and the fixed format's note.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
using test_support::F;
using test_support::I;
using test_support::read_deck_text;
using test_support::ReadDeck;

namespace {

constexpr double kX0 = 0.05, kY0 = -0.02;  // the axis (along z)

// An elastic steel block of 2 x 2 x 2 solids (20 mm) at the origin, node set 1 all its nodes,
// turned by `motion` (the *BOUNDARY_PRESCRIBED_MOTION_SET cards after the keyword line).
// `extra`: more keyword blocks (after *MAT_ELASTIC, whose Young's modulus is `young`).
std::string block_deck(double t_end, const std::string& curve_points, const std::string& motion, double young = 2.1e11,
                       const std::string& extra = "") {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nnodes turning about an axis\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*PART\nblock\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n"
    << "*MAT_ELASTIC\n" << I(1) << F(7850) << F(young) << F(0.3) << "\n" << extra << "*NODE\n";
  auto id = [](int i, int j, int k) { return 1 + i + 3 * (j + 3 * k); };
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) d << I(id(i, j, k), 8) << F(0.01 * i, 16) << F(0.01 * j, 16) << F(0.01 * k, 16) << "\n";
  d << "*ELEMENT_SOLID\n";
  int e = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        d << I(e++, 8) << I(1, 8) << I(id(i, j, k), 8) << I(id(i + 1, j, k), 8) << I(id(i + 1, j + 1, k), 8) << I(id(i, j + 1, k), 8)
          << I(id(i, j, k + 1), 8) << I(id(i + 1, j, k + 1), 8) << I(id(i + 1, j + 1, k + 1), 8) << I(id(i, j + 1, k + 1), 8) << "\n";
  d << "*SET_NODE_LIST\n" << I(1) << "\n";
  for (int n = 1; n <= 27; ++n) d << I(n) << (n % 8 == 0 ? "\n" : "");
  d << "\n*DEFINE_CURVE\n" << I(1) << "\n" << curve_points << "*BOUNDARY_PRESCRIBED_MOTION_SET\n" << motion << "*END\n";
  return d.str();
}

std::string orbit_cards(int dof, int vad, double sf = 1) {
  return I(1) + I(dof) + I(vad) + I(1) + F(sf) + "\n" + F(kX0) + F(kY0) + "\n";
}

struct OrbitRun {
  ReadDeck r;
  Engine* e = nullptr;
  StepStatus status = StepStatus::ok;
  explicit OrbitRun(const std::string& text) : r(read_deck_text(text, "orbit.k")) {
    if (!r.ok) return;
    e = new Engine(r.m);
    status = e->run_to_end();
  }
  ~OrbitRun() { delete e; }
  OrbitRun(const OrbitRun&) = delete;
  OrbitRun& operator=(const OrbitRun&) = delete;
};

// The largest distance of the nodes from their initial positions turned by `angle` about z
// through (kX0, kY0), and the largest change of z.
void expect_turned(const OrbitRun& run, double angle, double tol, double tol_z = 1e-15) {
  const Model& m = run.r.m;
  const State& s = run.e->state();
  double worst = 0, worst_z = 0;
  for (std::size_t q = 0; q < m.x.size(); ++q) {
    const double rx = m.x[q] - kX0, ry = m.y[q] - kY0;
    const double wx = kX0 + rx * std::cos(angle) - ry * std::sin(angle), wy = kY0 + rx * std::sin(angle) + ry * std::cos(angle);
    worst = std::max(worst, std::hypot(s.x[q] - wx, s.y[q] - wy));
    worst_z = std::max(worst_z, std::fabs(s.z[q] - m.z[q]));
  }
  EXPECT_LT(worst, tol) << "angle " << angle;
  EXPECT_LT(worst_z, tol_z);
}

}  // namespace

// VAD 0, w = 400 rad/s from t = 0 for 2 ms (0.8 rad, about 1,000 steps): on the exact rotation
// (the velocity of each step is the chord of its arc) to 1e-14 m at arms of 40-86 mm; the
// block unstrained; KE = 1/2 sum m |chord / dt|^2, booked as external work.
TEST(KeywordNodeOrbit, VelocityTurnsTheBlockRigidlyAboutTheAxis) {
  const double w = 400, t_end = 2e-3;
  OrbitRun run(block_deck(t_end, F(0.0, 20) + F(w, 20) + "\n" + F(1.0, 20) + F(w, 20) + "\n", orbit_cards(11, 0)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  ASSERT_EQ(run.r.m.prescribed_motions.size(), 27u);
  EXPECT_TRUE(run.r.m.prescribed_motions[0].orbit);
  const State& s = run.e->state();
  expect_turned(run, w * s.time, 1e-14);
  EXPECT_LT(std::fabs(s.internal), 1e-12 * s.kinetic);
  // the chord velocity: |v| = 2 r sin(w dt / 2) / dt
  const double dt = s.dt_half;
  double ke = 0;
  for (std::size_t q = 0; q < run.r.m.x.size(); ++q) {
    const double r = std::hypot(run.r.m.x[q] - kX0, run.r.m.y[q] - kY0), v = 2 * r * std::sin(0.5 * w * dt) / dt;
    ke += 0.5 * s.mass[q] * v * v;
  }
  EXPECT_NEAR(s.kinetic, ke, 1e-12 * ke);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// VAD 2, theta(t) = 600 t^2 (rad, t in s) to 1.5 ms: each node at theta(t_end) about the axis.
TEST(KeywordNodeOrbit, AngleCurvePlacesTheNodesAtItsAngle) {
  const double t_end = 1.5e-3;
  std::string pts;
  for (int k = 0; k <= 40; ++k) {
    const double t = 2e-3 * k / 40;
    pts += F(t, 20) + F(600 * t * t, 20) + "\n";
  }
  OrbitRun run(block_deck(t_end, pts, orbit_cards(11, 2)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.e->state();
  const double k = std::floor(s.time / 5e-5);  // the curve is linear between its points
  const double t0 = 5e-5 * k, t1 = t0 + 5e-5;
  const double theta = 600 * (t0 * t0 + (s.time - t0) / (t1 - t0) * (t1 * t1 - t0 * t0));
  expect_turned(run, theta, 1e-14);
  EXPECT_LT(std::fabs(s.internal), 1e-12 * s.kinetic);
}

// VAD 1, alpha = 2e5 rad/s^2 from rest for 2 ms (0.4 rad): omega^{n+1/2} = omega^{n-1/2} +
// dt alpha, the angle of the last step recovered from x^n and x^{n-1}: each node on the rotation
// by alpha t^2 / 2 (exact for central differences at a constant step) to 1e-12 m at arms of
// 40-86 mm (measured 7e-14), z to 1e-13 m (2.6e-14: the round-off strains of the recovered
// angle); the block unstrained, its kinetic energy booked as work (ratio 1 + 1.9e-14).
TEST(KeywordNodeOrbit, AccelerationTurnsTheBlockByHalfAlphaTSquared) {
  const double alpha = 2e5, t_end = 2e-3;
  OrbitRun run(block_deck(t_end, F(0.0, 20) + F(alpha, 20) + "\n" + F(1.0, 20) + F(alpha, 20) + "\n", orbit_cards(11, 1)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.e->state();
  expect_turned(run, 0.5 * alpha * s.time * s.time, 1e-12, 1e-13);
  EXPECT_LT(std::fabs(s.internal), 1e-12 * s.kinetic);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// DOF -11 at w = 1 rad/s for 2 s on a block of E = 1e-6 Pa (its elastic forces 1e-6 of the
// centrifugal ones; TSSFAC 1e-6 makes the step 8.7e-4 s, w dt 8.7e-4), the nodes set turning
// at w by their initial velocities: each node's distance from the axis follows the bead on a
// turning rod, r0 cosh(w t) (3.76 r0 at the end), to 5e-6 relative (measured 5.4e-7); its angle
// w t to 1e-12 rad (2.7e-15); z within 1e-6 m (6.4e-8: the soft block's own Poisson response to
// its 3.76-fold stretch); the kinetic energy 1/2 m (w^2 r^2 + r-dot^2) at the end to 2e-4
// (7.9e-5: the half-step velocities); the reactions' work (the tangential force that keeps the
// node turning as it moves out) books it: energy ratio 1 to 1e-9 (1 + 9.8e-12).
TEST(KeywordNodeOrbit, RadialFreedomIsABeadOnATurningRod) {
  const double w = 1, t_end = 2;
  std::string init = "*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i)
        init += I(1 + i + 3 * (j + 3 * k)) + F(-w * (0.01 * j - kY0)) + F(w * (0.01 * i - kX0)) + F(0.0) + "\n";
  const std::string extra = "*CONTROL_TIMESTEP\n" + F(0.0) + F(1e-6) + "\n" + init;
  OrbitRun run(block_deck(t_end, F(0.0, 20) + F(w, 20) + "\n" + F(10.0, 20) + F(w, 20) + "\n", orbit_cards(-11, 0), 1e-6, extra));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  ASSERT_TRUE(run.r.m.prescribed_motions[0].radial_free);
  const Model& m = run.r.m;
  const State& s = run.e->state();
  const double grow = std::cosh(w * s.time);
  double worst_r = 0, worst_a = 0, worst_z = 0, ke = 0;
  for (std::size_t q = 0; q < m.x.size(); ++q) {
    const double r0 = std::hypot(m.x[q] - kX0, m.y[q] - kY0), r = std::hypot(s.x[q] - kX0, s.y[q] - kY0);
    worst_r = std::max(worst_r, std::fabs(r / (r0 * grow) - 1));
    const double turned = std::atan2(s.y[q] - kY0, s.x[q] - kX0) - std::atan2(m.y[q] - kY0, m.x[q] - kX0);
    worst_a = std::max(worst_a, std::fabs(std::remainder(turned - w * s.time, 2 * M_PI)));
    worst_z = std::max(worst_z, std::fabs(s.z[q] - m.z[q]));
    const double rdot = r0 * w * std::sinh(w * s.time), vt = w * r;
    ke += 0.5 * s.mass[q] * (rdot * rdot + vt * vt);
  }
  EXPECT_LT(worst_r, 5e-6);
  EXPECT_LT(worst_a, 1e-12);
  EXPECT_LT(worst_z, 1e-6);
  EXPECT_NEAR(s.kinetic, ke, 2e-4 * ke);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// Refused by field: LRB not 0, a rotation (DOF 5) of nodes with no rotations (a solid's); the
// cards after them read as theirs.  (VAD 1 with DOF 9-11 and DOF -11 to -9 are read since.)
TEST(KeywordNodeOrbit, RefusalsNameTheField) {
  const std::string motions = I(1) + I(9) + I(0) + I(1) + "\n" + F(0.0) + F(0.0) + I(3) + "\n" +
                              I(1) + I(5) + I(0) + I(1) + "\n" + I(1) + I(3) + I(0) + I(1) + "\n";
  ReadDeck r = read_deck_text(block_deck(1e-4, F(0.0, 20) + F(0.0, 20) + "\n" + F(1.0, 20) + F(1.0, 20) + "\n", motions), "orbit.k");
  EXPECT_FALSE(r.ok);
  const std::string msg = r.messages();
  EXPECT_EQ(r.count(1102), 2) << msg;
  EXPECT_NE(msg.find("27 node(s) with no rotations"), std::string::npos) << msg;
  EXPECT_NE(msg.find("field \"LRB\""), std::string::npos) << msg;
  EXPECT_EQ(r.count(1001), 0) << msg;
  EXPECT_EQ(r.count(1006), 0) << msg;
}

// The keyword writer writes DOF 9-11 with card 2, read back the same; the fixed format has no
// card for them (a note, the motion left out).
TEST(KeywordNodeOrbit, ConvertersKeepOrNoteThem) {
  for (int dof : {9, 10, 11, -9, -10, -11}) {
    ReadDeck a = read_deck_text(block_deck(1e-4, F(0.0, 20) + F(0.0, 20) + "\n" + F(1.0, 20) + F(1.0, 20) + "\n", orbit_cards(dof, 2, 2.5)), "orbit.k");
    ASSERT_TRUE(a.ok) << a.messages();
    const PrescribedMotion& pm = a.m.prescribed_motions[0];
    const std::size_t axis = std::size_t(std::abs(dof) - 9);
    EXPECT_EQ(pm.dir[axis], 1.0);
    EXPECT_EQ(pm.radial_free, dof < 0);
    EXPECT_EQ(pm.center[(axis + 1) % 3], kX0);
    EXPECT_EQ(pm.center[(axis + 2) % 3], kY0);
    std::ostringstream k;
    write_keyword_deck(k, a.m);
    ReadDeck b = read_deck_text(k.str(), "orbit_back.k");
    ASSERT_TRUE(b.ok) << b.messages() << k.str();
    const auto diff = model_differences(a.m, b.m, 10);
    EXPECT_TRUE(diff.empty()) << diff.front();
    std::ostringstream f;
    std::vector<std::string> notes;
    write_fixed_deck(f, a.m, &notes);
    bool noted = false;
    for (const std::string& n : notes) noted = noted || n.find("turning about an axis") != std::string::npos;
    EXPECT_TRUE(noted);
  }
}
