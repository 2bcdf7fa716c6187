// Mesh ordering (impact3d/init/mesh_order.h): the starter's renumbering of nodes and solids for
// memory locality.
//   * a Taylor bar whose node and solid numbers are shuffled (fixed-format and keyword decks)
//     runs to the same final coordinates per deck id with the mesh renumbered and without: the
//     nodes sum their corner forces and masses in deck order either way, so the coordinates
//     agree bit for bit; the energies are summed per block of solids in the new order and agree
//     to round-off (1e-12 relative);
//   * automatic mode keeps an ordered deck and renumbers a shuffled one;
//   * the renumbering is a permutation that model_in_deck_order undoes exactly;
//   * a renumbered 16,000-solid bar gives the same bits on 1 and 2 threads.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/init/mesh_order.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "tests/support/box_mesh.h"
#include "tests/support/shuffle_mesh.h"

using namespace impact3d;
using test_support::ScopedThreads;

namespace {

const std::string kTaylor = IMPACT3D_SOURCE_DIR "/decks/taylor_bar.dyn";

Model read_model(const std::string& path) {
  Model m;
  Diagnostics d;
  EXPECT_TRUE(read_and_check_deck(path, m, d)) << path;
  return m;
}

// A model written as a deck (keyword or fixed format) and read back and checked.
Model through_deck(const Model& m, bool keyword) {
  std::ostringstream os;
  if (keyword) write_keyword_deck(os, m);
  else write_fixed_deck(os, m);
  DeckFile f;
  f.load_from_string(keyword ? "shuffled.k" : "shuffled.dyn", os.str());
  Model back;
  Diagnostics d;
  EXPECT_TRUE(read_deck(f, back, d)) << (d.all().empty() ? "" : render(d.all().front()));
  EXPECT_TRUE(check_model(back, d));
  return back;
}

struct Final {
  std::vector<int> node_ids;  // per internal node
  std::vector<double> x, y, z, eps_p;
  std::vector<int> hex_ids;
  double kinetic = 0, internal = 0, hourglass = 0, wall_work = 0;
  int cycle = 0;
  std::vector<int> index_of_id;  // internal index by deck id
  std::array<double, 3> at(int id) const {
    const std::size_t k = std::size_t(index_of_id.at(std::size_t(id)));
    return {x.at(k), y.at(k), z.at(k)};
  }
};

Final run(const Model& m, int cycles = -1) {
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  if (cycles < 0) EXPECT_EQ(eng.run_to_end(), StepStatus::finished);
  else
    for (int c = 0; c < cycles; ++c) EXPECT_EQ(eng.step(), StepStatus::ok);
  const State& s = eng.state();
  Final f;
  for (int i = 0; i < m.num_nodes(); ++i) f.node_ids.push_back(m.node_id(i));
  f.index_of_id.assign(std::size_t(*std::max_element(f.node_ids.begin(), f.node_ids.end())) + 1, -1);
  for (int i = 0; i < m.num_nodes(); ++i) f.index_of_id[std::size_t(f.node_ids[std::size_t(i)])] = i;
  for (int e = 0; e < m.num_hexes(); ++e) f.hex_ids.push_back(m.hex_id(e));
  f.x = s.x, f.y = s.y, f.z = s.z, f.eps_p = s.eps_p;
  f.kinetic = s.kinetic, f.internal = s.internal, f.hourglass = s.hourglass, f.wall_work = s.wall_work;
  f.cycle = s.cycle;
  return f;
}

double rel(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

void expect_same_run(const Final& a, const Final& b) {
  ASSERT_EQ(a.cycle, b.cycle);
  ASSERT_EQ(a.x.size(), b.x.size());
  // final coordinates by deck id: the same bits
  int differing = 0;
  for (std::size_t k = 0; k < b.x.size(); ++k) {
    const auto p = a.at(b.node_ids[k]);
    differing += p[0] != b.x[k] || p[1] != b.y[k] || p[2] != b.z[k];
  }
  EXPECT_EQ(differing, 0) << "nodes whose final coordinates differ";
  // plastic strain by deck id
  std::vector<double> eps_a(a.hex_ids.size() + 1), eps_b(b.hex_ids.size() + 1);
  ASSERT_EQ(eps_a.size(), eps_b.size());
  for (std::size_t e = 0; e < a.hex_ids.size(); ++e) eps_a.at(std::size_t(a.hex_ids[e])) = a.eps_p[e];
  for (std::size_t e = 0; e < b.hex_ids.size(); ++e) eps_b.at(std::size_t(b.hex_ids[e])) = b.eps_p[e];
  EXPECT_EQ(eps_a, eps_b);
  // energies: summed per block of solids in another order, round-off apart
  EXPECT_LT(rel(a.kinetic, b.kinetic), 1e-12);
  EXPECT_LT(rel(a.internal, b.internal), 1e-12);
  EXPECT_LT(rel(a.hourglass, b.hourglass), 1e-11);
  EXPECT_LT(rel(a.wall_work, b.wall_work), 1e-12);
}

}  // namespace

// A shuffled Taylor bar (fixed format and keyword) renumbered and not: the same final
// coordinates and plastic strains per deck id, energies within round-off; the mushroomed
// impact end of the shuffled deck is the ordered deck's (1e-12 relative: the shuffled deck sums
// corner forces in its own order).
TEST(MeshOrder, ShuffledTaylorBarRenumberedOrNotGivesTheSameResults) {
  ScopedThreads t(1);
  const Model ordered = read_model(kTaylor);
  Model shuffled = ordered;
  test_support::shuffle_mesh_numbering(shuffled, 20261125);
  ASSERT_GT(mesh_locality_cost(shuffled), 10 * mesh_locality_cost(ordered));
  const Final reference = run(ordered);
  for (bool keyword : {false, true}) {
    SCOPED_TRACE(keyword ? "keyword deck" : "fixed-format deck");
    const Model deck = through_deck(shuffled, keyword);
    ASSERT_EQ(deck.num_nodes(), 1369);
    Model off = deck, on = deck;
    const MeshOrderReport roff = order_mesh_for_locality(off, MeshOrderMode::off);
    const MeshOrderReport ron = order_mesh_for_locality(on, MeshOrderMode::on);
    EXPECT_FALSE(roff.renumbered);
    EXPECT_FALSE(off.renumbered());
    ASSERT_TRUE(ron.renumbered);
    EXPECT_LT(ron.ordered_cost * 20, ron.deck_cost) << ron.deck_cost << " -> " << ron.ordered_cost;
    EXPECT_LT(mesh_locality_cost(on), 2 * mesh_locality_cost(ordered));
    // ids: every deck id still there, on the node that has the deck's coordinates
    for (int i = 0; i < on.num_nodes(); ++i) {
      const int d = on.node_id(i) - 1;
      ASSERT_EQ(on.x[std::size_t(i)], deck.x[std::size_t(d)]);
      ASSERT_EQ(on.z[std::size_t(i)], deck.z[std::size_t(d)]);
      ASSERT_EQ(on.node_of_deck_number(d + 1), i);
    }
    // back in deck order it is the deck's model (what a restart dump's deck text is written from)
    EXPECT_TRUE(model_differences(model_in_deck_order(on), deck).empty());
    const Final a = run(off), b = run(on);
    expect_same_run(b, a);
    // the shuffled deck against the ordered one: the same bar, round-off apart
    double worst = 0, length = 0.0324;
    // by initial position (unique per node): the ordered deck's node with the same start point
    for (int i = 0; i < deck.num_nodes(); ++i) {
      int j = -1;
      for (int q = 0; q < ordered.num_nodes() && j < 0; ++q)
        if (ordered.x[std::size_t(q)] == deck.x[std::size_t(i)] && ordered.y[std::size_t(q)] == deck.y[std::size_t(i)] &&
            ordered.z[std::size_t(q)] == deck.z[std::size_t(i)])
          j = q;
      ASSERT_GE(j, 0);
      worst = std::max({worst, std::fabs(a.x[std::size_t(i)] - reference.x[std::size_t(j)]),
                        std::fabs(a.y[std::size_t(i)] - reference.y[std::size_t(j)]),
                        std::fabs(a.z[std::size_t(i)] - reference.z[std::size_t(j)])});
    }
    std::printf("%s: locality cost %.1f -> %.1f (ordered deck %.1f); shuffled vs ordered deck: largest coordinate "
                "difference %.3g of the length, internal energy %.3g relative\n",
                keyword ? "keyword" : "fixed", ron.deck_cost, ron.ordered_cost, mesh_locality_cost(ordered), worst / length,
                rel(a.internal, reference.internal));
    EXPECT_LT(worst / length, 1e-12) << "shuffled deck against the ordered one";
    EXPECT_LT(rel(a.internal, reference.internal), 1e-10);
  }
}

// Automatic mode: the Taylor bar (972 solids, below the size limit) and an ordered 16,000-solid
// bar keep the deck's order; the same bar shuffled is renumbered.
TEST(MeshOrder, AutomaticModeKeepsOrderedDecksAndRenumbersShuffledOnes) {
  Model taylor = read_model(kTaylor);
  MeshOrderReport r = order_mesh_for_locality(taylor, MeshOrderMode::automatic);
  EXPECT_FALSE(r.renumbered);
  EXPECT_FALSE(taylor.renumbered());
  EXPECT_TRUE(taylor.node_user_id.empty());
  EXPECT_NE(mesh_order_line(r).find("below 8192"), std::string::npos) << mesh_order_line(r);

  Model bar;
  bar.materials.push_back(MaterialData{});
  test_support::Box b;
  b.nx = b.ny = 20;
  b.nz = 40;
  test_support::add_box(bar, b, 0);
  ASSERT_EQ(bar.num_hexes(), 16000);
  const Model bar0 = bar;
  r = order_mesh_for_locality(bar, MeshOrderMode::automatic);
  EXPECT_FALSE(r.renumbered) << mesh_order_line(r);
  EXPECT_NEAR(r.deck_cost, 21 * 21 + 21 + 2, 2.0);  // n^2 + n + 2 (mesh_order.h)
  EXPECT_LT(r.deck_cost, r.local_bound);            // within 2 N^(2/3): no other numbering computed
  EXPECT_EQ(r.ordered_cost, 0.0);
  EXPECT_EQ(bar.hex_nodes, bar0.hex_nodes);
  EXPECT_EQ(bar.x, bar0.x);
  EXPECT_NE(mesh_order_line(r).find("the deck's (reorder=auto: locality cost 46"), std::string::npos) << mesh_order_line(r);
  {
    Model rcm = bar0;  // and indeed reverse Cuthill-McKee would not do better on it
    const MeshOrderReport forced = order_mesh_for_locality(rcm, MeshOrderMode::on);
    EXPECT_GT(forced.ordered_cost, 0.5 * forced.deck_cost) << mesh_order_line(forced);
  }

  Model shuffled = bar0;
  test_support::shuffle_mesh_numbering(shuffled, 7);
  r = order_mesh_for_locality(shuffled, MeshOrderMode::automatic);
  EXPECT_TRUE(r.renumbered) << mesh_order_line(r);
  EXPECT_LT(r.ordered_cost * 10, r.deck_cost);
  EXPECT_NE(mesh_order_line(r).find("renumbered for locality"), std::string::npos) << mesh_order_line(r);

  Model forced = bar0;
  EXPECT_FALSE(order_mesh_for_locality(forced, MeshOrderMode::off).renumbered);
  EXPECT_TRUE(order_mesh_for_locality(forced, MeshOrderMode::on).renumbered);
}

// The renumbering moves every node reference with its node: walls on node lists, interface
// segments, loads, prescribed motions; model_in_deck_order gives back the deck's model.
TEST(MeshOrder, RenumberingIsAPermutationThatModelInDeckOrderUndoes) {
  Model m;
  m.materials.push_back(MaterialData{});
  m.materials[0].number = 1;
  test_support::Box b;
  b.nx = 3, b.ny = 2, b.nz = 4;
  test_support::Box box = test_support::add_box(m, b, 0);
  test_support::shuffle_mesh_numbering(m, 3);
  StoneWall w;
  w.nodes = {5, 2, 9};
  m.walls.push_back(w);
  SlidingInterface si;
  si.slave = {{0, 1, 2, 3}};
  si.master = {{4, 5, 6, 6}};
  m.interfaces.push_back(si);
  NodalLoad nl;
  nl.node = 7;
  m.nodal_loads.push_back(nl);
  PressureLoad pl;
  pl.nodes = {8, 9, 10, 11};
  m.pressure_loads.push_back(pl);
  PrescribedMotion pm;
  pm.node = 12;
  m.prescribed_motions.push_back(pm);
  ForceTransducer ft;
  ft.a_nodes = {1, 3, 20};
  m.force_transducers.push_back(ft);
  m.node_th_blocks = {{3, 6}};
  m.solid_th_blocks = {{2, 2}};
  (void)box;
  const Model deck = m;
  ASSERT_TRUE(order_mesh_for_locality(m, MeshOrderMode::on).renumbered);
  auto deck_node = [&](int i) { return m.node_id(i) - 1; };
  EXPECT_EQ(deck_node(m.walls[0].nodes[1]), 2);
  EXPECT_EQ(deck_node(m.interfaces[0].master[0][3]), 6);
  EXPECT_EQ(deck_node(m.nodal_loads[0].node), 7);
  EXPECT_EQ(deck_node(m.pressure_loads[0].nodes[2]), 10);
  EXPECT_EQ(deck_node(m.prescribed_motions[0].node), 12);
  EXPECT_TRUE(std::is_sorted(m.force_transducers[0].a_nodes.begin(), m.force_transducers[0].a_nodes.end()));
  for (int e = 0; e < m.num_hexes(); ++e)
    for (int j = 0; j < 8; ++j)
      EXPECT_EQ(deck_node(m.hex_nodes[std::size_t(e)][std::size_t(j)]),
                deck.hex_nodes[std::size_t(m.hex_id(e) - 1)][std::size_t(j)]);
  EXPECT_EQ(m.hex_id(m.hex_of_deck_number(2)), 2);
  const Model back = model_in_deck_order(m);
  EXPECT_EQ(back.x, deck.x);
  EXPECT_EQ(back.z, deck.z);
  EXPECT_EQ(back.bc, deck.bc);
  EXPECT_EQ(back.interfaces[0].slave, deck.interfaces[0].slave);
  EXPECT_EQ(back.interfaces[0].master, deck.interfaces[0].master);
  EXPECT_EQ(back.nodal_loads[0].node, 7);
  EXPECT_EQ(back.pressure_loads[0].nodes, deck.pressure_loads[0].nodes);
  EXPECT_EQ(back.prescribed_motions[0].node, 12);
  EXPECT_EQ(back.hex_nodes, deck.hex_nodes);
  EXPECT_EQ(back.walls[0].nodes, deck.walls[0].nodes);
  EXPECT_EQ(back.force_transducers[0].a_nodes, deck.force_transducers[0].a_nodes);
  EXPECT_TRUE(back.node_user_id.empty());
  EXPECT_FALSE(back.renumbered());
}

// A shuffled 16,000-solid bar, renumbered: the same bits on 1 and 2 threads (every pass uses
// both above 8192 solids / 16384 nodes), and the same coordinates as the deck's order.
TEST(MeshOrder, RenumberedBarGivesTheSameBitsOnOneAndTwoThreads) {
  Model m;
  MaterialData mat;
  mat.number = 1;
  mat.type = 3;
  mat.rho = 8930;
  mat.E = 117e9;
  mat.nu = 0.35;
  mat.sigma_y = 4e8;
  mat.E_tan = 1e9;
  mat.beta = 1;
  m.materials.push_back(mat);
  test_support::Box b;
  b.nx = b.ny = 40;
  b.nz = 10;
  b.lx = b.ly = 0.04;
  b.lz = 0.01;
  b.z0 = 1e-4;
  test_support::add_box(m, b, 0);
  InitialVelocity iv;
  iv.v = {5, -3, -200};
  m.init_velocities.push_back(iv);
  StoneWall w;
  w.head = {0, 0, 1};
  m.walls.push_back(w);
  m.control.nmmat = 1;
  m.control.num_walls = 1;
  m.control.num_init_velocity_cards = 1;
  m.control.end_time = 1;
  test_support::shuffle_mesh_numbering(m, 11);
  Model on = m;
  ASSERT_TRUE(order_mesh_for_locality(on, MeshOrderMode::automatic).renumbered);
  Final one, two, off;
  {
    ScopedThreads t(1);
    one = run(on, 40);
    off = run(m, 40);
  }
  {
    ScopedThreads t(2);
    two = run(on, 40);
  }
  ASSERT_GT(*std::max_element(one.eps_p.begin(), one.eps_p.end()), 0.0);
  EXPECT_EQ(one.x, two.x);
  EXPECT_EQ(one.y, two.y);
  EXPECT_EQ(one.z, two.z);
  EXPECT_EQ(one.eps_p, two.eps_p);
  EXPECT_EQ(one.kinetic, two.kinetic);
  EXPECT_EQ(one.internal, two.internal);
  EXPECT_EQ(one.wall_work, two.wall_work);
  expect_same_run(one, off);
}
