// Constraints of keyword decks that real decks use and the engine checks against closed forms:
//  - *CONSTRAINED_GLOBAL (symmetry planes): a plastic block hit on its end, modelled whole
//    and as its half y >= 0 with the plane y = 0 held by *CONSTRAINED_GLOBAL, gives the same
//    motion on the half (round-off); the plane takes the nodes within TOL of it, and TOL 0 is
//    1e-3 of the shortest edge; bad fields are refused by field;
//  - *BOUNDARY_SPC_SET_BIRTH_DEATH: a block under a constant body acceleration g, held in x from
//    BIRTH to DEATH, falls freely before BIRTH, stands still between, and after DEATH moves at
//    g (t - DEATH) (the impulse of the body force since the release over the mass).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
using test_support::read_deck_text;
using test_support::ReadDeck;
using test_support::F;
using test_support::I;

namespace {

// A block of nx x ny x nz hexahedra, x in [0, 0.06], y in [y0, y1], z in [0, 0.02] (SI, steel
// type 3), node ids 1 + i + (nx+1) (j + (ny+1) k); `body` goes after the mesh.
struct Block {
  int nx = 6, ny = 4, nz = 2;
  double y0 = -0.02, y1 = 0.02;
  int id(int i, int j, int k) const { return 1 + i + (nx + 1) * (j + (ny + 1) * k); }
  double x(int i) const { return 0.06 * i / nx; }
  double y(int j) const { return y0 + (y1 - y0) * j / ny; }
  double z(int k) const { return 0.02 * k / nz; }
};

std::string block_deck(const Block& g, double t_end, const std::string& body) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nconstraints\n*CONTROL_TERMINATION\n" << F(t_end) << "\n"
    << "*PART\nblock\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n"
    << "*MAT_PLASTIC_KINEMATIC\n" << I(1) << F(7850) << F(210e9) << F(0.3) << F(400e6) << F(1e9) << F(1.0) << "\n\n"
    << "*NODE\n";
  for (int k = 0; k <= g.nz; ++k)
    for (int j = 0; j <= g.ny; ++j)
      for (int i = 0; i <= g.nx; ++i) d << I(g.id(i, j, k), 8) << F(g.x(i), 16) << F(g.y(j), 16) << F(g.z(k), 16) << "\n";
  d << "*ELEMENT_SOLID\n";
  int e = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        d << I(++e, 8) << I(1, 8) << I(g.id(i, j, k), 8) << I(g.id(i + 1, j, k), 8) << I(g.id(i + 1, j + 1, k), 8)
          << I(g.id(i, j + 1, k), 8) << I(g.id(i, j, k + 1), 8) << I(g.id(i + 1, j, k + 1), 8) << I(g.id(i + 1, j + 1, k + 1), 8)
          << I(g.id(i, j + 1, k + 1), 8) << "\n";
      }
  d << body << "*END\n";
  return d.str();
}

// The end x = 0 held in x, everything else moving at -v in x; the plane z = 0 held in z by
// *CONSTRAINED_GLOBAL in every variant.
std::string impact_cards(const Block& g, double v) {
  std::ostringstream d;
  d << "*SET_NODE_LIST\n" << I(1) << "\n";
  int n = 0;
  for (int k = 0; k <= g.nz; ++k)
    for (int j = 0; j <= g.ny; ++j) {
      d << I(g.id(0, j, k));
      if (++n % 8 == 0) d << "\n";
    }
  d << "\n*BOUNDARY_SPC_SET\n" << I(1) << I(0) << I(1) << I(0) << I(0) << "\n"
    << "*INITIAL_VELOCITY\n" << I(0) << "\n" << F(-v) << F(0.0) << F(0.0) << "\n"
    << "*CONSTRAINED_GLOBAL\n$#      tc        rc       dir         x         y         z       tol\n"
    << I(3) << I(0) << I(3) << F(0.0) << F(0.0) << F(0.0) << "\n";
  return d.str();
}

struct Result {
  std::map<int, std::array<double, 3>> x;  // node id -> position at the end
  double max_eps_p = 0;
};

Result run_deck(const std::string& text) {
  ReadDeck r = read_deck_text(text, "constraints.k");
  EXPECT_TRUE(r.ok) << r.messages();
  Result out;
  if (!r.ok) return out;
  Engine e(r.m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  const StepStatus st = e.run_to_end();
  EXPECT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << int(st);
  const State& s = e.state();
  for (int n = 0; n < s.nn; ++n)
    out.x[r.m.node_id(n)] = {s.x[std::size_t(n)], s.y[std::size_t(n)], s.z[std::size_t(n)]};
  for (double p : s.eps_p) out.max_eps_p = std::max(out.max_eps_p, p);
  return out;
}

}  // namespace

TEST(ConstrainedGlobal, HalfModelWithTheSymmetryPlaneMovesAsTheWholeModel) {
  const double v = 150, t_end = 3e-5;
  Block whole;
  Block half;
  half.ny = 2, half.y0 = 0;
  const Result w = run_deck(block_deck(whole, t_end, impact_cards(whole, v)));
  // the half: y = 0 held in y (RC 5 as symmetry planes are written: no effect on solid nodes)
  const std::string plane = "*CONSTRAINED_GLOBAL\n" + I(2) + I(5) + I(2) + F(0.0) + F(0.0) + F(0.0) + "\n";
  const Result h = run_deck(block_deck(half, t_end, impact_cards(half, v) + plane));
  ASSERT_FALSE(w.x.empty());
  ASSERT_FALSE(h.x.empty());
  EXPECT_GT(w.max_eps_p, 0.01);  // it yields: a nonlinear answer
  double max_disp = 0, worst = 0, worst_plane = 0, half_plane = 0;
  for (int k = 0; k <= half.nz; ++k)
    for (int j = 0; j <= half.ny; ++j)
      for (int i = 0; i <= half.nx; ++i) {
        const auto& a = w.x.at(whole.id(i, j + 2, k));  // the same point of the whole model
        const auto& b = h.x.at(half.id(i, j, k));
        const double x0[3] = {half.x(i), half.y(j), half.z(k)};
        for (int c = 0; c < 3; ++c) {
          max_disp = std::max(max_disp, std::fabs(a[std::size_t(c)] - x0[c]));
          worst = std::max(worst, std::fabs(a[std::size_t(c)] - b[std::size_t(c)]));
        }
        if (j == 0) {
          worst_plane = std::max(worst_plane, std::fabs(a[1]));
          half_plane = std::max(half_plane, std::fabs(b[1]));
        }
      }
  std::printf("largest displacement %.6e m; half vs whole: largest difference %.3e m (%.2e of it); "
              "whole model's mid-plane |y| %.3e m; half model's plane |y| %.3e m\n",
              max_disp, worst, worst / max_disp, worst_plane, half_plane);
  EXPECT_GT(max_disp, 1e-4);
  EXPECT_LT(worst, 1e-9 * max_disp);
  EXPECT_EQ(half_plane, 0.0);  // held exactly
  EXPECT_LT(worst_plane, 1e-12 * max_disp);
}

TEST(ConstrainedGlobal, NodesWithinTolOfThePlaneAreHeld) {
  Block g;
  g.nx = 2, g.ny = 2, g.nz = 1;
  // TOL 1e-4: the plane x = 0.0301 takes the nodes at x = 0.03 (1e-4 off), not those 0.03 away;
  // TOL 0: 1e-3 of the shortest edge (0.02 here: 2e-5), the plane x = 0.03001 takes them, 0.0301 not
  for (const auto& [at, tol, held] : {std::tuple{0.0301, 1.0001e-4, true}, std::tuple{0.0301, 0.0, false},
                                      std::tuple{0.03001, 0.0, true}, std::tuple{0.0302, 1e-4, false}}) {
    const std::string cards = "*CONSTRAINED_GLOBAL\n" + I(7) + I(0) + I(1) + F(at) + F(0.0) + F(0.0) + F(tol) + "\n";
    ReadDeck r = read_deck_text(block_deck(g, 1e-6, cards), "global.k");
    ASSERT_TRUE(r.ok) << r.messages();
    int fixed = 0;
    for (int n = 0; n < r.m.num_nodes(); ++n) {
      const bool on = std::fabs(r.m.x[std::size_t(n)] - 0.03) < 1e-12;
      if (r.m.bc[std::size_t(n)] == 7) ++fixed;
      EXPECT_EQ(r.m.bc[std::size_t(n)], on && held ? 7 : 0) << "node " << r.m.node_id(n) << " plane " << at << " tol " << tol;
    }
    EXPECT_EQ(fixed, held ? 6 : 0);
  }
}

TEST(ConstrainedGlobal, BadFieldsAreRefusedByField) {
  Block g;
  g.nx = 1, g.ny = 1, g.nz = 1;
  struct Case {
    std::string card;
    int id;
    const char* field;
    int col;
  };
  const Case cases[] = {
      {I(2) + I(0) + I(4) + F(0.0) + F(0.0) + F(0.0), 1006, "DIR", 21},
      {I(2) + I(0) + I(0), 1006, "DIR", 21},
      {I(8) + I(0) + I(2), 1006, "TC", 1},
      {I(2) + I(9) + I(2), 1006, "RC", 11},
      {I(2) + I(0) + I(2) + F(0.0) + F(0.0) + F(0.0) + F(-1.0), 1003, "TOL", 61},
  };
  for (const Case& c : cases) {
    ReadDeck r = read_deck_text(block_deck(g, 1e-6, "*CONSTRAINED_GLOBAL\n" + c.card + "\n"), "global.k");
    EXPECT_FALSE(r.ok);
    const Diagnostic* x = r.first(c.id);
    ASSERT_NE(x, nullptr) << c.field << "\n" << r.messages();
    EXPECT_EQ(x->where.field, c.field);
    EXPECT_EQ(x->where.col_first, c.col);
    EXPECT_EQ(x->where.file, "global.k");
    EXPECT_GT(x->where.line, 0);
  }
}

namespace {

// The block of 2 x 2 x 2 solids under *LOAD_BODY_X g (toward -x), every node in set 1 held in x
// by *BOUNDARY_SPC_SET_BIRTH_DEATH (keyword spelled `kw`) from birth to death.
std::string held_block(double g, double birth, double death, const std::string& kw, double t_end) {
  Block b;
  b.nx = 2, b.ny = 2, b.nz = 2, b.y0 = 0;
  std::ostringstream d;
  d << "*SET_NODE_LIST_GENERATE\n" << I(1) << "\n" << I(1) << I(27) << "\n"
    << "*DEFINE_CURVE\n" << I(7) << "\n" << F(0.0, 20) << F(1.0, 20) << "\n" << F(1.0, 20) << F(1.0, 20) << "\n"
    << "*LOAD_BODY_X\n" << I(7) << F(g) << "\n"
    << "*" << kw << "\n";
  if (kw.find("_ID") != std::string::npos) d << I(5) << "held block\n";
  d << I(1) << I(0) << I(1) << I(0) << I(0) << "\n" << F(birth) << F(death) << "\n";
  return block_deck(b, t_end, d.str());
}

}  // namespace

TEST(SpcBirthDeath, BlockHeldThenReleasedFliesAtTheImpulseOverTheMass) {
  const double g = 1000, birth = 2e-5, death = 6e-5, t_end = 1e-4;
  for (const std::string kw : {"BOUNDARY_SPC_SET_BIRTH_DEATH", "BOUNDARY_SPC_SET_ID_BIRTH_DEATH", "BOUNDARY_SPC_SET_BIRTH_DEATH_ID"}) {
    ReadDeck r = read_deck_text(held_block(g, birth, death, kw, t_end), "held.k");
    ASSERT_TRUE(r.ok) << kw << "\n" << r.messages();
    Engine e(r.m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    double mass = 0;
    for (double m : s.mass) mass += m;
    double worst_before = 0, worst_held = 0, worst_after = 0, dt_max = 0, v_at_birth = 0, impulse = 0;
    StepStatus st = StepStatus::ok;
    while (st == StepStatus::ok && !e.finished()) {
      const double t_n = s.time;
      st = e.step();
      dt_max = std::max(dt_max, s.dt_half);
      // v^{n+1/2} after the cycle at t_n: every node alike (a rigid motion)
      double vmin = 1e300, vmax = -1e300;
      for (double v : s.vx) vmin = std::min(vmin, v), vmax = std::max(vmax, v);
      EXPECT_LT(vmax - vmin, 1e-12 * g * t_end);
      const double v = s.vx[0];
      if (t_n < birth) {
        v_at_birth = v;
        worst_before = std::max(worst_before, std::fabs(v + g * (t_n + 0.5 * s.dt_half)));
      } else if (t_n <= death) {
        worst_held = std::max(worst_held, std::fabs(v));
      } else {
        impulse += -mass * g * s.dt_vel;  // the body force's impulse since the release
        worst_after = std::max(worst_after, std::fabs(v - impulse / mass));
      }
    }
    ASSERT_TRUE(st == StepStatus::ok || st == StepStatus::finished) << int(st);
    const double v_end = s.vx[0];
    const double closed = -g * (s.time - death);
    std::printf("%s: before birth |v + g t| <= %.2e, held |v| <= %.2e, after death |v - impulse/mass| <= %.2e m/s; "
                "end v %.6f vs -g (t - DEATH) %.6f m/s (step %.3e s, g dt %.3e m/s); v at birth %.4f\n",
                kw.c_str(), worst_before, worst_held, worst_after, v_end, closed, dt_max, g * dt_max, v_at_birth);
    EXPECT_LT(v_at_birth, -0.9 * g * birth);   // it fell before BIRTH
    EXPECT_LT(worst_before, 1e-9 * g * birth);
    EXPECT_EQ(worst_held, 0.0);                 // held exactly
    EXPECT_LT(worst_after, 1e-9 * g * t_end);   // v = impulse / mass
    EXPECT_LT(std::fabs(v_end - closed), 1.0001 * g * dt_max);  // the release lands within a step of DEATH
  }
}

TEST(SpcBirthDeath, DeathBeforeBirthAndAMissingCard2AreRefused) {
  ReadDeck r = read_deck_text(held_block(1, 2e-5, 1e-5, "BOUNDARY_SPC_SET_BIRTH_DEATH", 1e-4), "held.k");
  EXPECT_FALSE(r.ok);
  const Diagnostic* x = r.first(1003);
  ASSERT_NE(x, nullptr) << r.messages();
  EXPECT_EQ(x->where.field, "DEATH");
  EXPECT_EQ(x->where.col_first, 11);
  Block b;
  b.nx = b.ny = b.nz = 1;
  ReadDeck m = read_deck_text(block_deck(b, 1e-6, "*BOUNDARY_SPC_NODE_BIRTH_DEATH\n" + I(1) + I(0) + I(1) + "\n"), "held.k");
  EXPECT_FALSE(m.ok);
  EXPECT_EQ(m.count(1316), 1) << m.messages();
}
