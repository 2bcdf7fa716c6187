// Beams in contact (issue 24): beam nodes are contact nodes (slave nodes of node-to-surface and
// surface-to-surface contacts, nodes of a single surface whose parts include beams); beams are
// never segments, so beam-to-beam contact is refused (error 1255).
// Closed forms: a rigid beam bar striking a rigid block through one penalty spring k is a
// harmonic oscillator of the reduced mass mu = m1 m2 / (m1 + m2): contact time pi sqrt(mu/k),
// largest penetration v0 sqrt(mu/k), elastic-collision velocities after; the force is k p; the
// momentum exchanged is the impulse of the interface force.  Steel, SI units.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"
#include "contact_test_util.h"

using namespace impact3d;

namespace {

constexpr double kE = 210e9, kNu = 0.3, kRho = 7850;
const double kBulk = kE / (3 * (1 - 2 * kNu));

using contact_test::fld;
using contact_test::ifld;

// Bodies of a keyword deck, each a part with its own node range (0-based [first, last)).
struct Deck {
  std::ostringstream nodes, beams, shells, solids, parts, extra;
  int nid = 0, eid = 0;
  struct Body { int first = 0, last = 0, pid = 0; };

  int node(double x, double y, double z) {
    ++nid;
    nodes << ifld(nid, 8) << fld(x, 16) << fld(y, 16) << fld(z, 16) << "\n";
    return nid;
  }
  void material(int pid, bool rigid) {
    parts << (rigid ? "*MAT_RIGID\n" : "*MAT_ELASTIC\n") << ifld(pid, 10) << fld(kRho, 10) << fld(kE, 10) << fld(kNu, 10) << "\n";
  }
  void part(int pid) { parts << "*PART\nbody " << pid << "\n" << ifld(pid, 10) << ifld(pid, 10) << ifld(pid, 10) << "\n"; }
  // a straight bar of n Hughes-Liu beams (square section a x a) from (x, y, z0) to (x, y, z0 + l)
  Body bar(int pid, bool rigid, double x, double y, double z0, double l, int n, double a) {
    part(pid);
    parts << "*SECTION_BEAM\n" << ifld(pid, 10) << ifld(1, 10) << fld(5.0 / 6.0, 10) << ifld(2, 10) << ifld(0, 10) << "\n"
          << fld(a, 10) << fld(a, 10) << fld(a, 10) << fld(a, 10) << "\n";
    material(pid, rigid);
    Body b{nid, 0, pid};
    const int base = nid + 1;
    for (int i = 0; i <= n; ++i) node(x, y, z0 + l * i / n);
    for (int i = 0; i < n; ++i) beams << ifld(++eid, 8) << ifld(pid, 8) << ifld(base + i, 8) << ifld(base + i + 1, 8) << "\n";
    b.last = nid;
    return b;
  }
  // an n x n x n block of hexahedra, side l, corner (x0, y0, z0)
  Body block(int pid, bool rigid, double x0, double y0, double z0, double l, int n) {
    part(pid);
    parts << "*SECTION_SOLID\n" << ifld(pid, 10) << ifld(1, 10) << "\n";
    material(pid, rigid);
    Body b{nid, 0, pid};
    const int base = nid + 1;
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) node(x0 + l * i / n, y0 + l * j / n, z0 + l * k / n);
    auto id = [&](int i, int j, int k) { return base + i + (n + 1) * (j + (n + 1) * k); };
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          solids << ifld(++eid, 8) << ifld(pid, 8);
          for (int v : {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                        id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)})
            solids << ifld(v, 8);
          solids << "\n";
        }
    b.last = nid;
    return b;
  }
  // n x n shells of thickness t over [x0, x0 + l]^2 at height z
  Body plate(int pid, bool rigid, double t, double x0, double y0, double z, double l, int n) {
    part(pid);
    parts << "*SECTION_SHELL\n" << ifld(pid, 10) << ifld(2, 10) << fld(1.0, 10) << ifld(2, 10) << "\n" << fld(t, 10) << "\n";
    material(pid, rigid);
    Body b{nid, 0, pid};
    const int base = nid + 1;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) node(x0 + l * i / n, y0 + l * j / n, z);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int n1 = base + i + (n + 1) * j;
        shells << ifld(++eid, 8) << ifld(pid, 8) << ifld(n1, 8) << ifld(n1 + 1, 8) << ifld(n1 + n + 2, 8) << ifld(n1 + n + 1, 8) << "\n";
      }
    b.last = nid;
    return b;
  }
  int nsets = 0;
  int node_set(const Body& b) {
    const int sid = 100 + ++nsets;
    extra << "*SET_NODE_LIST\n" << ifld(sid, 10) << "\n";
    int c = 0;
    for (int n = b.first + 1; n <= b.last; ++n) {
      extra << ifld(n, 10);
      if (++c % 8 == 0) extra << "\n";
    }
    if (c % 8) extra << "\n";
    return sid;
  }
  void velocity(const Body& b, double vz) {
    const int sid = node_set(b);
    extra << "*INITIAL_VELOCITY\n" << ifld(sid, 10) << "\n" << fld(0, 10) << fld(0, 10) << fld(vz, 10) << "\n";
  }
  std::string text(double end_time, const std::string& contact) const {
    std::ostringstream d;
    d << "*KEYWORD\n*TITLE\nbeam contact test\n*CONTROL_TERMINATION\n" << fld(end_time, 10) << "\n";
    d << "*NODE\n" << nodes.str() << parts.str();
    if (!beams.str().empty()) d << "*ELEMENT_BEAM\n" << beams.str();
    if (!shells.str().empty()) d << "*ELEMENT_SHELL\n" << shells.str();
    if (!solids.str().empty()) d << "*ELEMENT_SOLID\n" << solids.str();
    d << extra.str() << contact << "*END\n";
    return d.str();
  }
};

// *CONTACT_<kind>: SURFA a (type atype), SURFB b (type btype), penalty scale SFSA
std::string contact_card(const std::string& kind, int a, int b, double sfsa, int atype = 3, int btype = 3) {
  return "*CONTACT_" + kind + "\n" + ifld(a, 10) + ifld(b, 10) + ifld(atype, 10) + ifld(btype, 10) + "\n" + fld(0, 10) +
         "\n" + fld(sfsa, 10) + fld(sfsa, 10) + "\n";
}

using Read = test_support::ReadDeck;

Read read_text(const std::string& text) { return test_support::read_deck_text(text, "beam_contact.k", InputOptions{}, true); }

double momentum_z(const State& s, const Deck::Body& b) {
  double p = 0;
  for (int n = b.first; n < b.last; ++n) p += s.mass[std::size_t(n)] * s.vz[std::size_t(n)];
  return p;
}
double mass_of(const State& s, const Deck::Body& b) {
  double m = 0;
  for (int n = b.first; n < b.last; ++n) m += s.mass[std::size_t(n)];
  return m;
}

// One run, cycle by cycle: the interface force on the slave side (interface 0), its impulse,
// the time in contact, the largest penetration, force / penetration, the energy ratio's range.
struct Trace {
  double impulse_z = 0, contact_time = 0, first = -1, last = -1, max_pen = 0;
  double k_min = 1e300, k_max = 0, force_after = 0, ratio_min = 1, ratio_max = 1;
  bool finished = false;
};

Trace run(Engine& e, int iface = 0) {
  Trace t;
  State& s = e.state();
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double dt_before = s.dt_half, time = s.time;
    const int cycle = s.cycle;
    st = e.step();
    const double dt_n = cycle == 0 ? 0.5 * s.dt_half : 0.5 * (dt_before + s.dt_half);
    const auto& f = e.interface_forces()[std::size_t(iface)];
    const double fabs = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    const double pen = e.contact().max_penetration();
    t.impulse_z += f[2] * dt_n;
    if (fabs > 0) {
      if (t.first < 0) t.first = time;
      t.last = time;
      t.contact_time += dt_n;
      t.force_after = 0;
      if (pen > 0) {
        t.k_min = std::min(t.k_min, fabs / pen);
        t.k_max = std::max(t.k_max, fabs / pen);
      }
    } else if (t.first >= 0) {
      t.force_after = std::max(t.force_after, fabs);
    }
    t.max_pen = std::max(t.max_pen, pen);
    t.ratio_min = std::min(t.ratio_min, s.energy_ratio());
    t.ratio_max = std::max(t.ratio_max, s.energy_ratio());
  }
  t.finished = st == StepStatus::finished;
  return t;
}

// A bar of 10 beams (0.2 m, 10 mm square) standing on its end node over the centre of the top
// face of a 50 mm block of one hexahedron, gap 0.1 mm, falling at 5 m/s; a 1 mm elastic cube far
// away sets the step (about 0.1 us).
struct BarOnBlock {
  Deck d;
  Deck::Body bar, block, timer;
  static constexpr double L = 0.2, a = 0.01, h = 0.05, gap = 1e-4, v0 = 5;
  // lift: more gap (an automatic contact's beam node touches at half its section size)
  BarOnBlock(bool rigid_bar, bool rigid_block, double lift = 0) {
    block = d.block(1, rigid_block, 0, 0, -h, h, 1);
    bar = d.bar(2, rigid_bar, h / 2, h / 2, gap + lift, L, 10, a);
    timer = d.block(3, false, 1, 1, 1, 0.001, 1);
    d.velocity(bar, -v0);
  }
};

}  // namespace

// A rigid beam bar strikes a free rigid block: its end node is the one slave node in contact,
// on the block's top face (SOFT 0: k = mu K A^2 / V of the face, mu = SFSA x 0.1; N = 1/4 at
// each of the face's nodes).  Both the one-way and the symmetric contact give the oscillator's
// closed form; the block's nodes find no segment on the bar's side (beams are no segments).
TEST(BeamContact, RigidBarStrikesRigidBlockAsTheOscillatorSays) {
  for (const char* kind : {"NODES_TO_SURFACE", "SURFACE_TO_SURFACE", "AUTOMATIC_NODES_TO_SURFACE"}) {
    SCOPED_TRACE(kind);
    // automatic: the bar's end node touches at half its section's size, a/2 (lifted by as much)
    const bool automatic = std::string(kind).rfind("AUTOMATIC", 0) == 0;
    BarOnBlock u(true, true, automatic ? BarOnBlock::a / 2 : 0.0);
    const double sfsa = 0.1;
    Read r = read_text(u.d.text(2.4e-4, contact_card(kind, 2, 1, sfsa)));
    ASSERT_TRUE(r.ok) << r.messages();
    ASSERT_EQ(r.m.interfaces.size(), 1u);
    const SlidingInterface& si = r.m.interfaces[0];
    EXPECT_TRUE(si.slave.empty());
    EXPECT_EQ(si.slave_nodes.size(), 11u);  // the bar's nodes
    EXPECT_EQ(si.master.size(), 6u);        // the block's faces
    Engine e(r.m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    const State& s = e.state();
    const double m1 = mass_of(s, u.bar), m2 = mass_of(s, u.block);
    EXPECT_NEAR(m1 / (kRho * BarOnBlock::a * BarOnBlock::a * BarOnBlock::L), 1.0, 1e-12);
    EXPECT_NEAR(m2 / (kRho * std::pow(BarOnBlock::h, 3)), 1.0, 1e-12);
    const double pb0 = momentum_z(s, u.bar), pk0 = momentum_z(s, u.block);
    const double A = BarOnBlock::h * BarOnBlock::h, k = sfsa * 0.1 * kBulk * A * A / (A * BarOnBlock::h);
    const double mu = m1 * m2 / (m1 + m2), T = M_PI * std::sqrt(mu / k), pmax = BarOnBlock::v0 * std::sqrt(mu / k);
    const Trace tr = run(e);
    ASSERT_TRUE(tr.finished);
    const double dt = s.dt_half;
    const double pb1 = momentum_z(s, u.bar), pk1 = momentum_z(s, u.block);
    const double v1 = pb1 / m1, v2 = pk1 / m2;
    const double v1x = -BarOnBlock::v0 * (m1 - m2) / (m1 + m2), v2x = -2 * m1 * BarOnBlock::v0 / (m1 + m2);
    std::printf("%s: contact %.5g us (closed form %.5g us, dt %.3g us), first force %.5g us (surface reached %.5g us), "
                "penetration %.5g um (%.5g um), k %.6g..%.6g (%.6g N/m), bar %.6g m/s (%.6g), block %.6g m/s (%.6g), "
                "energy ratio %.6f..%.6f\n",
                kind, tr.contact_time * 1e6, T * 1e6, dt * 1e6, tr.first * 1e6, BarOnBlock::gap / BarOnBlock::v0 * 1e6,
                tr.max_pen * 1e6, pmax * 1e6, tr.k_min, tr.k_max, k, v1, v1x, v2, v2x, tr.ratio_min, tr.ratio_max);
    EXPECT_NEAR(tr.k_min / k, 1.0, 1e-6);  // F = k p in every cycle in contact
    EXPECT_NEAR(tr.k_max / k, 1.0, 1e-6);
    EXPECT_NEAR(tr.contact_time, T, 2 * dt);
    EXPECT_NEAR(tr.max_pen / pmax, 1.0, 0.01);
    EXPECT_NEAR(tr.first, BarOnBlock::gap / BarOnBlock::v0, 0.01 * BarOnBlock::gap / BarOnBlock::v0 + 2 * dt);
    EXPECT_EQ(tr.force_after, 0.0);
    EXPECT_NEAR(v1 / v1x, 1.0, 0.005);  // elastic collision
    EXPECT_NEAR(v2 / v2x, 1.0, 0.005);
    EXPECT_NEAR((pb1 - pb0) / tr.impulse_z, 1.0, 1e-10);  // impulse = the bar's momentum change
    EXPECT_NEAR((pb1 + pk1 - pb0 - pk0) / (m1 * BarOnBlock::v0), 0.0, 1e-12);
    EXPECT_NEAR(tr.ratio_min, 1.0, 0.005);
    EXPECT_NEAR(tr.ratio_max, 1.0, 0.005);
  }
}

// An elastic Hughes-Liu bar (10 beams) strikes the free rigid block axially: the impulse of the
// interface force is the bar's momentum change, the total momentum is kept, the energy books
// balance (KE + IE + contact = KE0), and nothing acts after the bar has left.  The spring (k =
// 8.75e6 N/m, SFSA 0.01) is twelve times softer than the bar (EA/L = 1.05e8 N/m): the bar
// rebounds almost as a rigid body, v = -v0 (m1 - m2)/(m1 + m2) for its centre of mass, with a
// little of the energy left in its axial vibration.
TEST(BeamContact, ElasticBarReboundsWithBalancedBooks) {
  BarOnBlock u(false, true);
  const double sfsa = 0.01;
  Read r = read_text(u.d.text(6e-4, contact_card("SURFACE_TO_SURFACE", 2, 1, sfsa)));
  ASSERT_TRUE(r.ok) << r.messages();
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  const double m1 = mass_of(s, u.bar), m2 = mass_of(s, u.block);
  const double pb0 = momentum_z(s, u.bar), pk0 = momentum_z(s, u.block);
  const double A = BarOnBlock::h * BarOnBlock::h, k = sfsa * 0.1 * kBulk * A * A / (A * BarOnBlock::h);
  const double mu = m1 * m2 / (m1 + m2), T = M_PI * std::sqrt(mu / k);
  const Trace tr = run(e);
  ASSERT_TRUE(tr.finished);
  const double pb1 = momentum_z(s, u.bar), pk1 = momentum_z(s, u.block);
  const double v1 = pb1 / m1, v1x = -BarOnBlock::v0 * (m1 - m2) / (m1 + m2);
  std::printf("elastic bar: contact %.5g us (rigid-bar oscillator %.5g us), rebound %.6g m/s (rigid %.6g), "
              "impulse %.6g N s vs momentum change %.6g, energy ratio %.6f..%.6f, contact energy %.3g J of KE0 %.4g J\n",
              tr.contact_time * 1e6, T * 1e6, v1, v1x, tr.impulse_z, pb1 - pb0, tr.ratio_min, tr.ratio_max, s.contact,
              0.5 * m1 * BarOnBlock::v0 * BarOnBlock::v0);
  EXPECT_NEAR((pb1 - pb0) / tr.impulse_z, 1.0, 1e-10);
  EXPECT_NEAR((pb1 + pk1 - pb0 - pk0) / (m1 * BarOnBlock::v0), 0.0, 1e-12);
  EXPECT_EQ(tr.force_after, 0.0);
  EXPECT_NEAR(v1 / v1x, 1.0, 0.02);
  EXPECT_NEAR(tr.contact_time / T, 1.0, 0.05);
  EXPECT_GT(tr.ratio_min, 0.99);
  EXPECT_LT(tr.ratio_max, 1.01);
  EXPECT_NEAR(s.contact, 0.0, 1e-3 * 0.5 * m1 * BarOnBlock::v0 * BarOnBlock::v0);  // springs unloaded
}

// A single surface of every part (SURFA 0) with a beam bar and a shell plate: the bar's end node
// strikes the plate at a shell's centre; both contact surfaces are offset (the beam's a/2, the
// shell's t/2): the first force when the node is a/2 + t/2 from the mid-surface, then the
// oscillator on the shell segment's k = mu K A / (longest diagonal).
TEST(BeamContact, SingleSurfaceOfBeamsAndShells) {
  Deck d;
  const double t = 0.002, l = 0.1, a = 0.01, gap = 1e-4, v0 = 5, sfsa = 0.1;
  const int n = 5;  // the bar over the centre of the middle shell
  Deck::Body plate = d.plate(1, true, t, 0, 0, 0, l, n);
  Deck::Body bar = d.bar(2, true, l / 2, l / 2, t / 2 + a / 2 + gap, 0.1, 10, a);  // half the plate's mass
  d.block(3, false, 1, 1, 1, 0.001, 1);  // the step
  d.velocity(bar, -v0);
  const std::string single = "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n" + ifld(0, 10) + "\n" + fld(0, 10) + "\n" + fld(sfsa, 10) + "\n";
  Read r = read_text(d.text(2.4e-4, single));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.interfaces.size(), 1u);
  EXPECT_EQ(r.m.interfaces[0].slave_nodes.size(), 11u);
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  const double m1 = mass_of(s, bar), m2 = mass_of(s, plate);
  const double h = l / n, k = sfsa * 0.1 * kBulk * h * h / (h * std::sqrt(2.0));
  const double mu = m1 * m2 / (m1 + m2), T = M_PI * std::sqrt(mu / k), pmax = v0 * std::sqrt(mu / k);
  const Trace tr = run(e);
  ASSERT_TRUE(tr.finished);
  const double dt = s.dt_half;
  const double v1 = momentum_z(s, bar) / m1, v1x = -v0 * (m1 - m2) / (m1 + m2);
  std::printf("single surface, beam on shells: first force %.5g us (%.5g), contact %.5g us (%.5g), penetration %.5g um "
              "(%.5g), bar %.6g m/s (%.6g), plate %.6g m/s, k %.6g..%.6g (%.6g), m1 %.6g m2 %.6g, energy ratio %.6f..%.6f\n",
              tr.first * 1e6, gap / v0 * 1e6, tr.contact_time * 1e6, T * 1e6, tr.max_pen * 1e6, pmax * 1e6, v1, v1x,
              momentum_z(s, plate) / m2, tr.k_min, tr.k_max, k, m1, m2, tr.ratio_min, tr.ratio_max);
  EXPECT_NEAR(tr.first, gap / v0, 0.01 * gap / v0 + 2 * dt);
  EXPECT_NEAR(tr.contact_time, T, 2 * dt);
  EXPECT_NEAR(tr.max_pen / pmax, 1.0, 0.01);
  EXPECT_NEAR(v1 / v1x, 1.0, 0.005);
  EXPECT_NEAR(tr.ratio_min, 1.0, 0.005);
  EXPECT_NEAR(tr.ratio_max, 1.0, 0.005);
}

// Beams are no contact segments: a master side of beams only, or a single surface of beams only,
// is refused with error 1255 naming the contact's card and field; a node set of beam nodes is a
// slave side (*CONTACT_NODES_TO_SURFACE SURFATYP 4); a side of beams and solids keeps the
// solids' faces as segments and the beam nodes that are not on them.
TEST(BeamContact, BeamToBeamContactIsRefusedAndNodeSetsTakeBeamNodes) {
  auto messages_of = [](const std::string& contact) {
    BarOnBlock u(true, true);
    u.d.bar(4, false, 0.5, 0.5, 0.5, 0.1, 2, 0.01);  // a second bar: part 4
    return read_text(u.d.text(1e-4, contact));
  };
  {
    Read r = messages_of(contact_card("SURFACE_TO_SURFACE", 1, 2, 1.0));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.messages().find("error 1255"), std::string::npos) << r.messages();
    EXPECT_NE(r.messages().find("SURFB"), std::string::npos) << r.messages();
    EXPECT_NE(r.messages().find("beam_contact.k:"), std::string::npos) << r.messages();  // file and line
    std::printf("%s", r.messages().c_str());
  }
  {
    Read r = messages_of(contact_card("NODES_TO_SURFACE", 4, 2, 1.0));
    EXPECT_NE(r.messages().find("error 1255"), std::string::npos) << r.messages();
  }
  {  // single surface of the two bars (a part set of beam parts)
    Read r = messages_of("*SET_PART_LIST\n" + ifld(7, 10) + "\n" + ifld(2, 10) + ifld(4, 10) + "\n" +
                         "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n" + ifld(7, 10) + ifld(0, 10) + ifld(2, 10) + "\n");
    EXPECT_NE(r.messages().find("error 1255"), std::string::npos) << r.messages();
    EXPECT_NE(r.messages().find("single surface"), std::string::npos) << r.messages();
  }
  {  // the bar's nodes as a node set: the slave nodes
    BarOnBlock u(true, true);
    const int sid = u.d.node_set(u.bar);
    Read r = read_text(u.d.text(1e-4, contact_card("NODES_TO_SURFACE", sid, 1, 1.0, 4, 3)));
    ASSERT_TRUE(r.ok) << r.messages();
    EXPECT_TRUE(r.m.interfaces[0].slave.empty());
    EXPECT_EQ(r.m.interfaces[0].slave_nodes.size(), 11u);
  }
  {  // a part set of the bar and the small cube: the cube's faces and the bar's nodes
    BarOnBlock u(true, true);
    Read r = read_text(u.d.text(1e-4, "*SET_PART_LIST\n" + ifld(8, 10) + "\n" + ifld(2, 10) + ifld(3, 10) + "\n" +
                                          contact_card("SURFACE_TO_SURFACE", 8, 1, 1.0, 2, 3)));
    ASSERT_TRUE(r.ok) << r.messages();
    EXPECT_EQ(r.m.interfaces[0].slave.size(), 6u);
    EXPECT_EQ(r.m.interfaces[0].slave_nodes.size(), 11u);
    EXPECT_TRUE(r.m.interfaces[0].master_nodes.empty());
  }
}

// The converter writes a side's beam nodes as a *CONTACT_NODES_TO_SURFACE of their node set
// against the other side's segment set; read back, the same run to the bit (positions,
// velocities) for the one-way contact, and the fixed format refuses the model.
TEST(BeamContact, ConverterWritesBeamNodesAsANodeSetContact) {
  BarOnBlock u(true, true);
  Read r = read_text(u.d.text(1.5e-4, contact_card("NODES_TO_SURFACE", 2, 1, 0.1)));
  ASSERT_TRUE(r.ok) << r.messages();
  std::ostringstream out;
  std::vector<std::string> notes;
  write_keyword_deck(out, r.m, &notes);
  EXPECT_EQ(notes.size(), 1u);  // the beam nodes' contact
  Read back = read_text(out.str());
  ASSERT_TRUE(back.ok) << back.messages() << out.str();
  ASSERT_EQ(back.m.interfaces.size(), 1u);
  EXPECT_EQ(back.m.interfaces[0].slave_nodes, r.m.interfaces[0].slave_nodes);
  EXPECT_EQ(back.m.interfaces[0].master, r.m.interfaces[0].master);
  Engine e1(r.m), e2(back.m);
  ASSERT_EQ(e1.initialize(), StepStatus::ok);
  ASSERT_EQ(e2.initialize(), StepStatus::ok);
  run(e1);
  run(e2);
  const State &s1 = e1.state(), &s2 = e2.state();
  for (int n = 0; n < s1.nn; ++n) {
    EXPECT_EQ(s1.z[std::size_t(n)], s2.z[std::size_t(n)]);
    EXPECT_EQ(s1.vz[std::size_t(n)], s2.vz[std::size_t(n)]);
  }
  EXPECT_GT(s1.vz[std::size_t(u.bar.first)], 0.0);  // (the bar rebounds: it was struck)
  std::ostringstream log;
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/beam_contact_refused.dyn";
  EXPECT_EQ(write_converted_decks(r.m, "", fixed, log), exit_code::input_error);
  EXPECT_NE(log.str().find("has beam nodes"), std::string::npos) << log.str();
}
