// *RIGIDWALL_GEOMETRIC_CYLINDER: a steel block dropped at 50 m/s onto a fixed cylinder lying
// along x (radius 50 mm):
//  - the impulse the wall gives the nodes, the sum of -(wall force) dt over the cycles, equals
//    the block's momentum change (no other external force) to round-off;
//  - centred over the axis, the impulse is vertical (y to round-off), and it stops and throws
//    back the block; the impulses are radial, so the block keeps its angular momentum about the
//    axis (centred and moved 10 mm along +y, where it tips over the top);
//  - no node ever ends inside the cylinder;
//  - _DISPLAY reads its card 4; _MOTION, a zero radius and NSEGS are refused by field; the
//    converter writes the wall back as the same keyword.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
using test_support::read_deck_text;
using test_support::ReadDeck;
using test_support::F;
using test_support::I;

namespace {

constexpr double kR = 0.05, kV = 50;

// A 4 x 4 x 2 block of elastic steel solids, 40 x 40 x 20 mm, centred at (0, y0), its bottom 1 mm
// above the cylinder's top, falling at kV; the wall keyword `kw` with its cards `wall`.
std::string drop_deck(double y0, const std::string& kw, const std::string& wall) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nblock dropped on a cylinder\n*CONTROL_TERMINATION\n" << F(1e-4) << "\n"
    << "*PART\nblock\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n"
    << "*MAT_ELASTIC\n" << I(1) << F(7850) << F(210e9) << F(0.3) << "\n*NODE\n";
  const int nx = 4, ny = 4, nz = 2;
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        d << I(id(i, j, k), 8) << F(-0.02 + 0.01 * i, 16) << F(y0 - 0.02 + 0.01 * j, 16) << F(kR + 0.001 + 0.01 * k, 16) << "\n";
  d << "*ELEMENT_SOLID\n";
  int e = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        d << I(++e, 8) << I(1, 8) << I(id(i, j, k), 8) << I(id(i + 1, j, k), 8) << I(id(i + 1, j + 1, k), 8) << I(id(i, j + 1, k), 8)
          << I(id(i, j, k + 1), 8) << I(id(i + 1, j, k + 1), 8) << I(id(i + 1, j + 1, k + 1), 8) << I(id(i, j + 1, k + 1), 8) << "\n";
  d << "*INITIAL_VELOCITY\n" << I(0) << "\n" << F(0.0) << F(0.0) << F(-kV) << "\n"
    << "*" << kw << "\n" << wall << "*END\n";
  return d.str();
}

// card 1 (all nodes), card 2 (the axis along x through the origin, frictionless), card 3
std::string cylinder_cards(double radius = kR, double length = 0, int nsegs = 0) {
  return I(0) + "\n" + F(-1.0) + F(0.0) + F(0.0) + F(1.0) + F(0.0) + F(0.0) + F(0.0) + "\n" + F(radius) + F(length) + I(nsegs) + "\n";
}

struct Drop {
  double p0[3] = {0, 0, 0}, p1[3] = {0, 0, 0};  // block momentum before and after
  double impulse[3] = {0, 0, 0};                // sum of the wall's impulse on the nodes
  double deepest = 0;                           // largest (R - rho) over nodes and cycles
  double mass = 0;
  double L0 = 0, L1 = 0;                        // angular momentum about the axis (x) before and after
};

Drop drop(double y0, const std::string& kw = "RIGIDWALL_GEOMETRIC_CYLINDER", const std::string& wall = cylinder_cards()) {
  Drop out;
  ReadDeck r = read_deck_text(drop_deck(y0, kw, wall), "cylinder.k");
  EXPECT_TRUE(r.ok) << r.messages();
  if (!r.ok) return out;
  EXPECT_EQ(r.m.walls.size(), 1u);
  Engine e(r.m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  auto momentum = [&](double p[3]) {
    p[0] = p[1] = p[2] = 0;
    for (int n = 0; n < s.nn; ++n) {
      const std::size_t k = std::size_t(n);
      p[0] += s.mass[k] * s.vx[k], p[1] += s.mass[k] * s.vy[k], p[2] += s.mass[k] * s.vz[k];
    }
  };
  // about the x axis: sum m (y vz - z vy), with x^{n+1} and v^{n+1/2} after a cycle (which is
  // sum m x^n x v^{n+1/2}: the wall's impulses act at x^n)
  auto angular = [&]() {
    double L = 0;
    for (int n = 0; n < s.nn; ++n) {
      const std::size_t k = std::size_t(n);
      L += s.mass[k] * (s.y[k] * s.vz[k] - s.z[k] * s.vy[k]);
    }
    return L;
  };
  momentum(out.p0);
  out.L0 = angular();
  for (double m : s.mass) out.mass += m;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok && !e.finished()) {
    st = e.step();
    for (int a = 0; a < 3; ++a) out.impulse[a] -= s.wall_force[0][std::size_t(a)] * s.dt_vel;
    for (int n = 0; n < s.nn; ++n) {
      const std::size_t k = std::size_t(n);
      out.deepest = std::max(out.deepest, kR - std::hypot(s.y[k], s.z[k]));
    }
  }
  EXPECT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << int(st);
  momentum(out.p1);
  out.L1 = angular();
  return out;
}

}  // namespace

TEST(CylinderWall, DroppedBlockTakesTheWallsImpulseAsItsMomentumChange) {
  for (double y0 : {0.0, 0.01}) {
    const Drop d = drop(y0);
    const double mv = d.mass * kV;
    double worst = 0;
    for (int a = 0; a < 3; ++a) worst = std::max(worst, std::fabs((d.p1[a] - d.p0[a]) - d.impulse[a]));
    std::printf("y0 %.3f m: momentum change (%.6e, %.6e, %.6e) vs wall impulse (%.6e, %.6e, %.6e) N s, largest "
                "difference %.2e of m v %.6e; end vz %.3f m/s; deepest node %.2e m inside; angular momentum about "
                "the axis %.6e -> %.6e (change %.2e of m v R)\n",
                y0, d.p1[0] - d.p0[0], d.p1[1] - d.p0[1], d.p1[2] - d.p0[2], d.impulse[0], d.impulse[1], d.impulse[2],
                worst / mv, mv, d.p1[2] / d.mass, d.deepest, d.L0, d.L1, std::fabs(d.L1 - d.L0) / (mv * kR));
    EXPECT_LT(worst, 1e-12 * mv);
    EXPECT_LT(std::fabs(d.impulse[0]), 1e-12 * mv);  // no friction: nothing along the axis
    if (y0 == 0) {
      EXPECT_GT(d.impulse[2], 1.0 * mv);               // stopped and thrown back up
      EXPECT_LT(std::fabs(d.impulse[1]), 1e-12 * mv);  // centred: vertical
    } else {
      EXPECT_GT(d.impulse[2], 0.5 * mv);               // slowed as it tips over the top
    }
    // the impulses are radial: no moment about the axis, whose angular momentum the block keeps
    EXPECT_LT(std::fabs(d.L1 - d.L0), 1e-3 * mv * kR);
    EXPECT_LT(d.deepest, 1e-12);  // no node ends inside (the tangent plane lies outside)
  }
}

TEST(CylinderWall, DisplayCardIsReadAndOptionsRefusedByField) {
  // _DISPLAY: card 4 read, the same run as without it
  const Drop a = drop(0), b = drop(0, "RIGIDWALL_GEOMETRIC_CYLINDER_DISPLAY", cylinder_cards() + I(9) + F(7850) + F(2e11) + F(0.3) + "\n");
  EXPECT_EQ(a.p1[2], b.p1[2]);
  struct Case {
    std::string kw, cards;
    int id;
    const char* field;
  };
  const Case cases[] = {
      {"RIGIDWALL_GEOMETRIC_CYLINDER", cylinder_cards(0.0), 1003, "RADCYL"},
      {"RIGIDWALL_GEOMETRIC_CYLINDER", cylinder_cards(kR, -1), 1003, "LENCYL"},
      {"RIGIDWALL_GEOMETRIC_CYLINDER", cylinder_cards(kR, 0, 3), 1102, "NSEGS"},
      {"RIGIDWALL_GEOMETRIC_CYLINDER", I(0) + F(0.0) + F(0.0) + F(1e-5) + "\n" + cylinder_cards().substr(11), 1102, "BIRTH"},
  };
  for (const Case& c : cases) {
    ReadDeck r = read_deck_text(drop_deck(0, c.kw, c.cards), "cylinder.k");
    EXPECT_FALSE(r.ok);
    const Diagnostic* x = r.first(c.id);
    ASSERT_NE(x, nullptr) << c.field << "\n" << r.messages();
    EXPECT_EQ(x->where.field, c.field) << r.messages();
    EXPECT_GT(x->where.line, 0);
  }
  ReadDeck m = read_deck_text(drop_deck(0, "RIGIDWALL_GEOMETRIC_CYLINDER_MOTION", cylinder_cards() + I(1) + I(0) + "\n"), "cylinder.k");
  EXPECT_FALSE(m.ok);
  EXPECT_EQ(m.count(1312), 1) << m.messages();
}

TEST(CylinderWall, ConverterWritesTheCylinderBack) {
  ReadDeck r = read_deck_text(drop_deck(0.01, "RIGIDWALL_GEOMETRIC_CYLINDER", cylinder_cards(kR, 0.3)), "cylinder.k");
  ASSERT_TRUE(r.ok) << r.messages();
  std::ostringstream k;
  write_keyword_deck(k, r.m, nullptr);
  ASSERT_NE(k.str().find("*RIGIDWALL_GEOMETRIC_CYLINDER"), std::string::npos) << k.str();
  ReadDeck back = read_deck_text(k.str(), "back.k");
  ASSERT_TRUE(back.ok) << back.messages();
  ASSERT_EQ(back.m.walls.size(), 1u);
  EXPECT_EQ(back.m.walls[0].radius, kR);
  EXPECT_EQ(back.m.walls[0].length, 0.3);
  EXPECT_EQ(back.m.walls[0].tail, r.m.walls[0].tail);
  EXPECT_EQ(back.m.walls[0].head, r.m.walls[0].head);
}
