// Prescribed motions of rigid bodies (issue 25) read from keyword decks and run against closed
// forms (*BOUNDARY_PRESCRIBED_MOTION_RIGID, the axis of a rotation through the body's centre of
// mass, the vectors fixed in space, as LS-DYNA's manual has them):
//  - DOF 7, velocity: a rigid block spun up about z by a ramp, then at constant omega: its
//    nodes on the exact rotation (the bound: the midpoint rule's error on the ramp's corner),
//    its kinetic energy 1/2 I omega^2 of the lumped masses, booked as the moment's work;
//  - DOF 5 (acceleration): theta = alpha t^2 / 2 exactly; DOF 6 (displacement): the angle of
//    the curve at each step;
//  - DOF -8 (displacement about *DEFINE_VECTOR, the other rotations held) on a block given a
//    spin about another axis: that spin is removed, the nodes end on the exact rotation;
//  - DOF 4 and -4 (velocity along *DEFINE_VECTOR): the centre moves along the vector, with its
//    normal velocity kept (4) or removed (-4);
//  - a deformable part tied to a spun rigid part (shared nodes) follows the rigid rotation
//    to its elastic deflection;
//  - refusals (DOF 9-11 read past with their card 2), and the converters.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
using test_support::F;
using test_support::I;
using test_support::read_deck_text;
using test_support::ReadDeck;

namespace {

// A block of nx x 2 x 2 hexahedra, x in [x0, x0 + 0.01 nx], y and z in [-0.01, 0.01] (SI,
// steel); elements with i < rigid_cols are part `part` (rigid), the others part 9 (elastic).
struct Block {
  int nx = 2, part = 1, rigid_cols = 2, first_node = 1, first_elem = 1;
  double x0 = 0;
  int id(int i, int j, int k) const { return first_node + i + (nx + 1) * (j + 3 * k); }
};

std::string mesh(const Block& g) {
  std::ostringstream d;
  d << "*NODE\n";
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= g.nx; ++i)
        d << I(g.id(i, j, k), 8) << F(g.x0 + 0.01 * i, 16) << F(-0.01 + 0.01 * j, 16) << F(-0.01 + 0.01 * k, 16) << "\n";
  d << "*ELEMENT_SOLID\n";
  int e = g.first_elem;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < g.nx; ++i)
        d << I(e++, 8) << I(i < g.rigid_cols ? g.part : 9, 8) << I(g.id(i, j, k), 8) << I(g.id(i + 1, j, k), 8)
          << I(g.id(i + 1, j + 1, k), 8) << I(g.id(i, j + 1, k), 8) << I(g.id(i, j, k + 1), 8) << I(g.id(i + 1, j, k + 1), 8)
          << I(g.id(i + 1, j + 1, k + 1), 8) << I(g.id(i, j + 1, k + 1), 8) << "\n";
  return d.str();
}

// Rigid parts 1 and 2 (*MAT_RIGID 1) and the elastic part 9, then `body`.
std::string deck(double t_end, const std::string& body) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nrigid motions\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*PART\nrigid one\n" << I(1) << I(1) << I(1) << "\n*PART\nrigid two\n" << I(2) << I(1) << I(2) << "\n"
    << "*PART\nelastic\n" << I(9) << I(1) << I(9) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n"
    << "*MAT_RIGID\n" << I(1) << F(7850) << F(2.1e11) << F(0.3) << "\n"
    << "*MAT_RIGID\n" << I(2) << F(7850) << F(2.1e11) << F(0.3) << "\n"
    << "*MAT_ELASTIC\n" << I(9) << F(7850) << F(2.1e11) << F(0.3) << "\n"
    << body << "*END\n";
  return d.str();
}

std::string curve(int id, const std::vector<std::pair<double, double>>& pts) {
  std::ostringstream d;
  d << "*DEFINE_CURVE\n" << I(id) << "\n";
  for (const auto& p : pts) d << F(p.first, 20) << F(p.second, 20) << "\n";
  return d.str();
}

std::string motion(int pid, int dof, int vad, int lcid, double sf = 1, int vid = 0) {
  std::ostringstream d;
  d << "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n" << I(pid) << I(dof) << I(vad) << I(lcid) << F(sf) << I(vid) << "\n";
  return d.str();
}

std::string vector_card(int vid, double x, double y, double z) {
  std::ostringstream d;
  d << "*DEFINE_VECTOR\n" << I(vid) << F(0.0) << F(0.0) << F(0.0) << F(x) << F(y) << F(z) << "\n";
  return d.str();
}

// Runs the deck's model to its end (one thread); the engine is kept for inspection.
struct RigidRun {
  ReadDeck r;
  std::unique_ptr<Engine> eng;
  explicit RigidRun(const std::string& text) : r(read_deck_text(text, "rigid_motion.k")) {
    if (!r.ok) return;
    eng = std::make_unique<Engine>(r.m);
    status = eng->run_to_end();
  }
  StepStatus status = StepStatus::ok;
  const State& s() const { return eng->state(); }
};

using Vec = std::array<double, 3>;

// x rotated by angle a about the unit axis n through c (Rodrigues).
Vec rotate(const Vec& x, const Vec& c, const Vec& n, double a) {
  const Vec r = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  const double nr = n[0] * r[0] + n[1] * r[1] + n[2] * r[2];
  const Vec nxr = {n[1] * r[2] - n[2] * r[1], n[2] * r[0] - n[0] * r[2], n[0] * r[1] - n[1] * r[0]};
  Vec out;
  for (std::size_t q = 0; q < 3; ++q)
    out[q] = c[q] + r[q] * std::cos(a) + nxr[q] * std::sin(a) + n[q] * nr * (1 - std::cos(a));
  return out;
}

// The largest distance of the body's nodes from where the exact rotation puts them.
double rotation_error(const RigidRun& run, const RigidBody& rb, const Vec& n, double angle) {
  const Model& m = run.r.m;
  const State& s = run.s();
  double worst = 0;
  for (int k : rb.nodes) {
    const std::size_t q = std::size_t(k);
    const Vec want = rotate({m.x[q], m.y[q], m.z[q]}, rb.com0, n, angle);
    worst = std::max(worst, std::hypot(s.x[q] - want[0], s.y[q] - want[1], s.z[q] - want[2]));
  }
  return worst;
}

// I n . n of the body's lumped nodal masses about its centre (the rigid body's inertia).
double inertia_about(const State& s, const RigidBody& rb, const Vec& n) {
  double I = 0;
  for (int k : rb.nodes) {
    const std::size_t q = std::size_t(k);
    const Vec r = {s.x[q] - rb.com[0], s.y[q] - rb.com[1], s.z[q] - rb.com[2]};
    const double along = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
    I += s.mass[q] * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] - along * along);
  }
  return I;
}

}  // namespace

// DOF 7, VAD 0: omega ramps to 1000 rad/s over 0.2 ms, then stays.  theta(t) = w0 (t - tr/2)
// after the ramp; the velocity form takes omega at the half steps (the midpoint rule: exact on
// each linear piece, off by at most alpha dt^2 / 8 on the step across the corner; measured
// 1.0e-7 rad, the bound 1.4e-6).
TEST(KeywordRigidMotion, BlockSpunAboutZFollowsTheExactRotation) {
  const double w0 = 1000, tr = 2e-4, t_end = 1.5e-3;
  RigidRun run(deck(t_end, mesh(Block{}) + curve(1, {{0, 0}, {tr, w0}, {1, w0}}) + motion(1, 7, 0, 1)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.s();
  ASSERT_EQ(s.rigid.size(), 1u);
  const RigidBody& rb = s.rigid[0];
  const double t = s.time, dt = t_end / 1000;  // (the step of a model of rigid bodies alone is at most t_end / 1000)
  const double bound = 0.0173 * (w0 / tr * dt * dt / 8 + 1e-13);  // largest arm 0.0173 m (sqrt(3) x 0.01)
  EXPECT_LT(rotation_error(run, rb, {0, 0, 1}, w0 * (t - tr / 2)), bound) << "angle off by " << s.motion_angle[0] - w0 * (t - tr / 2);
  EXPECT_NEAR(rb.omega[2], w0, 1e-12 * w0);
  EXPECT_NEAR(rb.omega[0], 0, 1e-12 * w0);
  EXPECT_NEAR(rb.omega[1], 0, 1e-12 * w0);
  // the centre stays; the kinetic energy is 1/2 I w^2, all of it the prescription's work
  for (std::size_t q = 0; q < 3; ++q) EXPECT_NEAR(rb.com[q], rb.com0[q], 1e-15);
  const double ke = 0.5 * inertia_about(s, rb, {0, 0, 1}) * w0 * w0;
  EXPECT_NEAR(s.kinetic, ke, 1e-12 * ke);
  EXPECT_NEAR(s.external_work, ke, 1e-9 * ke);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// DOF 5 with VAD 1 (angular acceleration 2e6 rad/s^2 about x): theta = alpha t^2 / 2 (central
// differences integrate a constant acceleration exactly); DOF 6 with VAD 2 on a second body:
// the angle of the curve at every step.
TEST(KeywordRigidMotion, AccelerationAndAngleForms) {
  const double alpha = 2e6, t_end = 1e-3;
  Block b2;
  b2.part = 2, b2.first_node = 101, b2.first_elem = 101, b2.x0 = 0.1;
  RigidRun run(deck(t_end, mesh(Block{}) + mesh(b2) + curve(1, {{0, alpha}, {1, alpha}}) + curve(2, {{0, 0}, {1e-3, 0.8}, {1, 0.8}}) +
                          motion(1, 5, 1, 1) + motion(2, 6, 2, 2)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.s();
  ASSERT_EQ(s.rigid.size(), 2u);
  const double t = s.time;
  EXPECT_LT(rotation_error(run, s.rigid[0], {1, 0, 0}, 0.5 * alpha * t * t), 1e-12 * 0.0173) << "theta " << 0.5 * alpha * t * t;
  EXPECT_NEAR(s.rigid[0].omega[0], alpha * (t - 0.5 * s.dt_half), 1e-9 * alpha * t);
  EXPECT_LT(rotation_error(run, s.rigid[1], {0, 1, 0}, 0.8 * std::min(t, 1e-3) / 1e-3), 1e-12 * 0.0173);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// DOF -8 with VAD 2 about *DEFINE_VECTOR (1, 1, 1): the angle 1.2 rad in 0.8 ms, then held;
// the body was given 300 rad/s about y (*INITIAL_VELOCITY_GENERATION), which -8 removes at the
// first step: the nodes end on the rotation about (1, 1, 1) alone.  Energy: the removed spin's
// kinetic energy is the reaction's (negative) work.
TEST(KeywordRigidMotion, RotationAboutAVectorWithTheOtherRotationsHeld) {
  const double t_end = 1e-3;
  const std::string spin = "*INITIAL_VELOCITY_GENERATION\n" + I(1) + I(2) + F(300.0) + "\n" + F(0.01) + F(0.0) + F(0.0) + F(0.0) + F(1.0) + F(0.0) + "\n";
  RigidRun run(deck(t_end, mesh(Block{}) + spin + vector_card(3, 1, 1, 1) + curve(1, {{0, 0}, {8e-4, 1.2}, {1, 1.2}}) + motion(1, -8, 2, 1, 1, 3)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.s();
  const double c = 1 / std::sqrt(3.0);
  EXPECT_LT(rotation_error(run, s.rigid[0], {c, c, c}, 1.2), 1e-12 * 0.0173);
  for (double w : s.rigid[0].omega) EXPECT_NEAR(w, 0, 1e-9);
  // the initial spin's energy 1/2 I_y 300^2 went out as the reaction's work (the body ends at
  // rest: the energy ratio is 0 / 0 here)
  const double ke0 = s.initial_total;
  EXPECT_NEAR(ke0, 0.5 * inertia_about(s, s.rigid[0], {0, 1, 0}) * 300 * 300, 1e-12 * ke0);
  EXPECT_NEAR(s.kinetic, 0, 1e-12 * ke0);
  EXPECT_NEAR(s.external_work, -ke0, 1e-9 * ke0);
}

// DOF 4 and -4 (velocity 10 m/s along (1, 2, 2) / 3) on two bodies that start at (0, 0, 5)
// m/s: the first keeps its normal velocity (0, 0, 5) - (10 / 3) (1, 2, 2) / 3, the second
// loses it; both centres move on straight lines at those velocities.
TEST(KeywordRigidMotion, TranslationAlongAVector) {
  const double t_end = 1e-3, v = 10;
  Block b2;
  b2.part = 2, b2.first_node = 101, b2.first_elem = 101, b2.x0 = 0.1;
  const std::string init = "*INITIAL_VELOCITY\n" + I(0) + "\n" + F(0.0) + F(0.0) + F(5.0) + "\n";
  RigidRun run(deck(t_end, mesh(Block{}) + mesh(b2) + init + vector_card(4, 1, 2, 2) + curve(1, {{0, v}, {1, v}}) +
                          motion(1, 4, 0, 1, 1, 4) + motion(2, -4, 0, 1, 1, 4)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.s();
  const double t = s.time;
  const Vec d = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  const Vec keep = {5 * 0 - 10.0 / 3 * d[0], -10.0 / 3 * d[1], 5 - 10.0 / 3 * d[2]};  // (0,0,5) minus its part along d
  for (std::size_t q = 0; q < 3; ++q) {
    EXPECT_NEAR(s.rigid[0].vcom[q], v * d[q] + keep[q], 1e-12 * v);
    EXPECT_NEAR(s.rigid[0].com[q] - s.rigid[0].com0[q], (v * d[q] + keep[q]) * t, 1e-12 * v * t);
    EXPECT_NEAR(s.rigid[1].vcom[q], v * d[q], 1e-12 * v);
    EXPECT_NEAR(s.rigid[1].com[q] - s.rigid[1].com0[q], v * d[q] * t, 1e-12 * v * t);
  }
  for (int k : s.rigid[1].nodes) EXPECT_NEAR(s.vz[std::size_t(k)], v * d[2], 1e-12 * v);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// DOF -4 on the nodes of a deformable block (*BOUNDARY_PRESCRIBED_MOTION_SET): every node moves
// at 10 m/s along (1, 2, 2) / 3 and its initial (0, 0, 5) m/s normal to it is removed; the
// block moves as a rigid translation, unstrained, the removed energy booked as work.
TEST(KeywordRigidMotion, NodesAlongAVectorWithTheNormalPlaneHeld) {
  const double t_end = 2e-5, v = 10;
  Block b;
  b.rigid_cols = 0;
  std::string set = "*SET_NODE_LIST\n" + I(5) + "\n";
  for (int n = 1; n <= 27; ++n) set += I(n) + (n % 8 == 0 || n == 27 ? "\n" : "");
  const std::string init = "*INITIAL_VELOCITY\n" + I(0) + "\n" + F(0.0) + F(0.0) + F(5.0) + "\n";
  RigidRun run(deck(t_end, mesh(b) + set + init + vector_card(4, 1, 2, 2) + curve(1, {{0, v}, {1, v}}) +
                              "*BOUNDARY_PRESCRIBED_MOTION_SET\n" + I(5) + I(-4) + I(0) + I(1) + F(1.0) + I(4) + "\n"));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.s();
  const Model& m = run.r.m;
  const Vec d = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  const double t = s.time;
  for (int k = 0; k < m.num_nodes(); ++k) {
    const std::size_t q = std::size_t(k);
    ASSERT_NEAR(s.vx[q], v * d[0], 1e-12 * v);
    ASSERT_NEAR(s.vy[q], v * d[1], 1e-12 * v);
    ASSERT_NEAR(s.vz[q], v * d[2], 1e-12 * v);
    ASSERT_NEAR(s.z[q] - m.z[q], v * d[2] * t, 1e-12 * v * t);
  }
  EXPECT_LT(std::fabs(s.internal), 1e-12 * s.kinetic);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-9);
}

// A deformable part tied to a spun rigid part: a 4 x 2 x 2 steel bar, its first two columns
// rigid, spun about z through the rigid part's centre by a 1 ms ramp to 200 rad/s, its centre
// held (DOF 1 and 2 at zero velocity: the spinning elastic part would pull it round).  The
// shared nodes are the rigid body's (exact); the elastic part's far end follows the rigid
// rotation to its elastic response: the ramp's angular acceleration 2e5 rad/s^2 loads the
// 20 mm arm with 5.6e3 m/s^2 at its tip, a slender-beam static deflection 12 rho a L^4 /
// (8 E h^2) = 1.3e-7 m (centrifugal stretch 1e-8 m), which the coarse one-point mesh and the
// ramp's sudden start and stop multiply: measured 1.06e-6 m, 3.8e-5 of the tip's radius.
// Bound 3e-6 m (1e-4 of the radius: 0.3 rad turned, a wrong axis or rate is off by 1e-3 m); the
// far end turns at 200 rad/s within 1%, and the energy balance holds to 1e-3.
TEST(KeywordRigidMotion, DeformablePartTiedToASpunRigidPart) {
  const double w0 = 200, tr = 1e-3, t_end = 2e-3;
  Block b;
  b.nx = 4;
  RigidRun run(deck(t_end, mesh(b) + curve(1, {{0, 0}, {tr, w0}, {1, w0}}) + curve(2, {{0, 0}, {1, 0}}) + motion(1, 7, 0, 1) +
                              motion(1, 1, 0, 2) + motion(1, 2, 0, 2)));
  ASSERT_TRUE(run.r.ok) << run.r.messages();
  ASSERT_EQ(run.status, StepStatus::finished);
  const State& s = run.s();
  const Model& m = run.r.m;
  const RigidBody& rb = s.rigid[0];
  const double t = s.time, theta = w0 * (t - tr / 2);
  EXPECT_LT(rotation_error(run, rb, {0, 0, 1}, theta), 0.0173 * (w0 / tr * 1.5e-6 * 1.5e-6 / 8 + 1e-13));
  double worst = 0, w_min = 1e300, w_max = -1e300;
  for (int k = 0; k < m.num_nodes(); ++k) {
    const std::size_t q = std::size_t(k);
    if (m.x[q] < 0.035) continue;  // the far end x = 0.04
    const Vec want = rotate({m.x[q], m.y[q], m.z[q]}, rb.com0, {0, 0, 1}, theta);
    worst = std::max(worst, std::hypot(s.x[q] - want[0], s.y[q] - want[1], s.z[q] - want[2]));
    // the angular velocity of the node about the axis: (r x v)_z / r^2 in the xy plane
    const double rx = s.x[q] - rb.com[0], ry = s.y[q] - rb.com[1];
    const double w = (rx * s.vy[q] - ry * s.vx[q]) / (rx * rx + ry * ry);
    w_min = std::min(w_min, w), w_max = std::max(w_max, w);
  }
  EXPECT_LT(worst, 3e-6) << "far end off the rigid rotation by " << worst << " m";
  EXPECT_NEAR(w_min, w0, 0.01 * w0);
  EXPECT_NEAR(w_max, w0, 0.01 * w0);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-3) << "w " << w_min << " " << w_max << " far end " << worst;
}

// DOF 9-11 (nodes rotating about an axis; LS-DYNA's manual: not for rigid bodies) are refused
// by field and their card 2 is read past: the next motion is read from its own card.  DOF 0 and
// -5 are not DOFs.  Rigid DOF 8 without VID is error 1003.
TEST(KeywordRigidMotion, RefusalsNameTheFieldAndKeepTheCards) {
  const std::string body = mesh(Block{}) + curve(1, {{0, 1}, {1, 1}}) +
                           "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n" + I(1) + I(10) + I(0) + I(1) + "\n" + F(0.0) + F(0.0) + "\n" +
                           I(1) + I(7) + I(0) + I(1) + "\n" + I(1) + I(0) + I(0) + I(1) + "\n" + I(1) + I(-5) + I(0) + I(1) + "\n" +
                           I(1) + I(8) + I(0) + I(1) + "\n";
  ReadDeck r = read_deck_text(deck(1e-4, body), "rigid_motion.k");
  EXPECT_FALSE(r.ok);
  const std::string msg = r.messages();
  EXPECT_EQ(r.count(1102), 1) << msg;
  EXPECT_NE(msg.find("not for rigid bodies"), std::string::npos) << msg;
  EXPECT_EQ(r.count(1006), 2) << msg;
  EXPECT_EQ(r.count(1003), 1) << msg;
  EXPECT_EQ(r.count(1001), 0) << msg;  // no card read as the wrong one
}

// The keyword writer keeps every rigid motion (axes as DOF 5-7, vectors as *DEFINE_VECTOR with
// DOF 4 / -4 / 8 / -8); the fixed format has no card for them (noted).
TEST(KeywordRigidMotion, ConvertersKeepOrNoteThem) {
  Block b2;
  b2.part = 2, b2.first_node = 101, b2.first_elem = 101, b2.x0 = 0.1;
  const std::string body = mesh(Block{}) + mesh(b2) + vector_card(3, 1, 1, 0) + curve(1, {{0, 1}, {1, 1}}) +
                           motion(1, 7, 0, 1, 2.5) + motion(1, -8, 2, 1, 1, 3) + motion(2, -4, 1, 1, 1, 3) + motion(2, 8, 0, 1, 1, 3) +
                           motion(2, 4, 0, 1, 1, 3) + motion(2, 2, 0, 1);
  ReadDeck r = read_deck_text(deck(1e-4, body), "rigid_motion.k");
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.prescribed_motions.size(), 6u);
  const PrescribedMotion& p0 = r.m.prescribed_motions[0];
  EXPECT_TRUE(p0.rotation);
  EXPECT_FALSE(p0.hold_normal);
  EXPECT_EQ(p0.dir, (Vec{0, 0, 1}));
  const PrescribedMotion& p1 = r.m.prescribed_motions[1];
  EXPECT_TRUE(p1.rotation && p1.hold_normal);
  EXPECT_NEAR(p1.dir[0], std::sqrt(0.5), 1e-15);
  EXPECT_TRUE(!r.m.prescribed_motions[2].rotation && r.m.prescribed_motions[2].hold_normal);
  std::ostringstream kw;
  std::vector<std::string> notes;
  write_keyword_deck(kw, r.m, &notes);
  ReadDeck k2 = read_deck_text(kw.str(), "rigid_motion_written.k");
  ASSERT_TRUE(k2.ok) << k2.messages() << kw.str();
  std::string diffs;
  for (const auto& x : model_differences(r.m, k2.m, 50)) diffs += x + "\n";
  EXPECT_EQ(diffs, "") << kw.str();
  EXPECT_TRUE(notes.empty());
  std::ostringstream fx;
  notes.clear();
  write_fixed_deck(fx, r.m, &notes);
  bool noted = false;
  for (const auto& n : notes) noted = noted || n.find("prescribed motions of rigid bodies have no fixed-format card") != std::string::npos;
  EXPECT_TRUE(noted);
}
