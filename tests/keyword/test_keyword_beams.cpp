// Keyword decks with beams: *SECTION_BEAM (ELFORM 1 rectangular and tubular, ELFORM 3),
// *ELEMENT_BEAM(_THICKNESS), beam parts, rotational constraints on beam nodes, the refusals,
// the converter's round trip, a restart that continues bit for bit, and the shipped example
// deck running to the end.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/init/mesh_order.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

namespace {

struct BeamRead {
  Model m;
  Diagnostics d;
  bool ok = false;
  std::string messages() const {
    std::ostringstream os;
    d.print(os);
    return os.str();
  }
  int count(int id) const {
    int n = 0;
    for (const auto& x : d.all()) n += x.id == id;
    return n;
  }
  const Diagnostic* first(int id) const {
    for (const auto& x : d.all())
      if (x.id == id) return &x;
    return nullptr;
  }
};

BeamRead read_beam_text(const std::string& text) {
  BeamRead r;
  DeckFile deck;
  deck.load_from_string("beams.k", text);
  InputOptions o;
  r.ok = read_deck(deck, r.m, r.d, o);
  if (r.ok) r.ok = check_model(r.m, r.d);
  return r;
}

std::string frame_deck() {
  std::ifstream f(std::string(IMPACT3D_SOURCE_DIR) + "/tests/keyword/beam_frame.k");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

}  // namespace

// The example frame: 10 rectangular Hughes-Liu beams, 4 tubes (sizes on _THICKNESS cards), a
// truss; sections, parts, orientation nodes and the rotational constraint of the clamped node.
TEST(KeywordBeams, FrameDeckReadsIntoTheModel) {
  BeamRead r = read_beam_text(frame_deck());
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.num_beams(), 15);
  ASSERT_EQ(r.m.materials.size(), 3u);
  const MaterialData& cant = r.m.materials[std::size_t(r.m.beam_material[0])];
  EXPECT_TRUE(cant.beam);
  EXPECT_EQ(cant.type, 3);
  EXPECT_EQ(cant.beam_section.elform, 1);
  EXPECT_EQ(cant.beam_section.qr, 3);
  EXPECT_EQ(cant.beam_section.cst, BeamCrossSection::rectangular);
  EXPECT_DOUBLE_EQ(cant.beam_section.ts1, 0.02);
  EXPECT_DOUBLE_EQ(cant.beam_section.tt2, 0.01);
  EXPECT_NEAR(cant.beam_section.shrf, 0.833333, 1e-12);
  const MaterialData& tube = r.m.materials[std::size_t(r.m.beam_material[10])];
  EXPECT_EQ(tube.beam_section.cst, BeamCrossSection::tubular);
  EXPECT_EQ(tube.beam_section.qr, 2);
  EXPECT_DOUBLE_EQ(r.m.beam_thickness[10][2], 0.016);
  EXPECT_EQ(r.m.beam_nodes[10][2], -1);  // N3 0: none
  const MaterialData& truss = r.m.materials[std::size_t(r.m.beam_material[14])];
  EXPECT_EQ(truss.beam_section.elform, 3);
  EXPECT_DOUBLE_EQ(truss.beam_section.area, 1e-5);
  EXPECT_EQ(r.m.beam_nodes[0], (std::array<int, 3>{0, 1, 16}));
  ASSERT_FALSE(r.m.rot_bc.empty());
  EXPECT_EQ(r.m.rot_bc[0], 7);  // the clamped beam node's rotations (DOFRX-DOFRZ)
  EXPECT_EQ(r.m.rot_bc[15], 0);  // the truss anchor: a truss node has no rotations
}

// Refusals name the keyword, card and field: formulations other than 1-3, arbitrary
// sections (CST 2), user integration rules, end releases, a material without a beam form,
// coincident end nodes and an orientation node on the beam's axis.
TEST(KeywordBeams, RefusalsNameTheField) {
  const std::string base = frame_deck();
  {
    BeamRead r = read_beam_text(replaced(base, "         1         1  0.833333         3         0", "         1         4  0.833333         3         0"));
    EXPECT_FALSE(r.ok);
    ASSERT_GE(r.count(1102), 1) << r.messages();
    EXPECT_EQ(r.first(1102)->where.field, "ELFORM");
    EXPECT_NE(r.messages().find("Belytschko-Schwer"), std::string::npos);
  }
  {  // ELFORM 2 takes elastic (and rigid) materials only: the plastic cantilever's part is refused
    BeamRead r = read_beam_text(replaced(base, "         1         1  0.833333         3         0\n$      TS1       TS2       TT1       TT2\n      0.02      0.02      0.01      0.01",
                                         "         1         2\n    2.0e-4  1.67e-9  6.67e-9  4.5e-9"));
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.count(1103), 1) << r.messages();
    EXPECT_NE(r.messages().find("ELFORM 2"), std::string::npos);
  }
  {
    BeamRead r = read_beam_text(replaced(base, "         1         1  0.833333         3         0", "         1         1  0.833333         3         2"));
    EXPECT_FALSE(r.ok);
    ASSERT_GE(r.count(1102), 1) << r.messages();
    EXPECT_EQ(r.first(1102)->where.field, "CST");
  }
  {
    BeamRead r = read_beam_text(replaced(base, "         1         1  0.833333         3         0", "         1         1  0.833333        -1         0"));
    EXPECT_FALSE(r.ok);
    ASSERT_GE(r.count(1102), 1) << r.messages();
    EXPECT_EQ(r.first(1102)->where.field, "QR/IRID");
  }
  {
    BeamRead r = read_beam_text(replaced(base, "       1       1       1       2      17", "       1       1       1       2      17       1"));
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.count(1102), 1) << r.messages();
    EXPECT_EQ(r.first(1102)->where.field, "RT1");
  }
  {
    BeamRead r = read_beam_text(replaced(base, "*MAT_ELASTIC\n         2", "*MAT_NULL\n         2"));
    EXPECT_FALSE(r.ok);
    EXPECT_GE(r.count(1103), 1) << r.messages();
  }
  {
    BeamRead r = read_beam_text(replaced(base, "       1       1       1       2      17", "       1       1       1       1      17"));
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.count(1250), 1) << r.messages();
    EXPECT_EQ(r.first(1250)->where.field, "N1-N2");
  }
  {  // orientation node 3 (on the x axis) for beam 1 along x
    BeamRead r = read_beam_text(replaced(base, "       1       1       1       2      17", "       1       1       1       2       3"));
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.count(1250), 1) << r.messages();
    EXPECT_EQ(r.first(1250)->where.card, "beam element 1");
  }
  {
    BeamRead r = read_beam_text(replaced(base, "    1.0e-5", "   -1.0e-5"));
    EXPECT_FALSE(r.ok);
    EXPECT_GE(r.count(1251), 1) << r.messages();
  }
}

// The converter writes beams back as a keyword deck that reads into the same Model; the fixed
// format refuses them.
TEST(KeywordBeams, KeywordRoundTripAndFixedFormatRefusal) {
  BeamRead a = read_beam_text(frame_deck());
  ASSERT_TRUE(a.ok) << a.messages();
  std::ostringstream os;
  std::vector<std::string> notes;
  write_keyword_deck(os, a.m, &notes);
  BeamRead b = read_beam_text(os.str());
  ASSERT_TRUE(b.ok) << b.messages() << os.str();
  const auto diffs = model_differences(a.m, b.m, 50);
  std::string all;
  for (const auto& d : diffs) all += d + "\n";
  EXPECT_TRUE(diffs.empty()) << all;
  EXPECT_EQ(b.m.num_beams(), 15);
  std::ostringstream log;
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/beam_fixed_refused.dyn";
  EXPECT_EQ(write_converted_decks(a.m, "", fixed, log), exit_code::input_error);
  EXPECT_NE(log.str().find("beam"), std::string::npos) << log.str();
}

// The frame runs to its end time with the energy balanced (the ramped tip load's work), the
// cantilever yielding at its root; a restart dump halfway continues bit for bit.
TEST(KeywordBeams, FrameRunsAndRestartsBitForBit) {
  BeamRead r = read_beam_text(frame_deck());
  ASSERT_TRUE(r.ok) << r.messages();
  Engine a(r.m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  for (int c = 0; c < 110; ++c) ASSERT_EQ(a.step(), StepStatus::ok);
  DumpHeader h;
  h.deck_name = "beams.k";
  h.deck_text = frame_deck();
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/beam_restart_dump";
  write_restart_dump(path, h, a.state(), a.contact().restart_data());
  Engine b(r.m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  StepStatus sa = StepStatus::ok, sb = StepStatus::ok;
  while (sa == StepStatus::ok) {
    sa = a.step();
    sb = b.step();
  }
  EXPECT_EQ(sa, StepStatus::finished);
  EXPECT_EQ(sb, StepStatus::finished);
  EXPECT_EQ(a.state().z, b.state().z);
  EXPECT_EQ(a.state().beams.sig, b.state().beams.sig);
  EXPECT_EQ(a.state().beams.e2, b.state().beams.e2);
  EXPECT_EQ(a.state().shells.wy, b.state().shells.wy);
  EXPECT_EQ(a.state().internal, b.state().internal);
  EXPECT_NEAR(a.state().energy_ratio(), 1.0, 0.01);
  EXPECT_GT(*std::max_element(a.state().beams.eps_p.begin(), a.state().beams.eps_p.end()), 0.0);
}

// The plot database holds the beams as LS-DYNA lays them out: IX2 (n1 n2 n3, two unused words,
// part), NV1D = 6 + 5 x the most points of any section (the tube's 2 x 8), per beam the
// resultants N Q_s Q_t M_s M_t T and per point tau_rs tau_tr sigma_rr eps_p eps_rr, beam
// deletion flags after the shells'; PlotReader reads back what the State holds (the VTK check:
// CTest deck_run_beam_frame_vtk_probe).
TEST(KeywordBeams, PlotDatabaseHoldsBeamsAsLsDyna) {
  BeamRead r = read_beam_text(frame_deck());
  ASSERT_TRUE(r.ok) << r.messages();
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  for (int c = 0; c < 300; ++c) ASSERT_EQ(e.step(), StepStatus::ok);
  const std::string root = std::string(IMPACT3D_BINARY_DIR) + "/beam_plot/d3plot";
  std::filesystem::create_directories(std::string(IMPACT3D_BINARY_DIR) + "/beam_plot");
  {
    PlotOutput out;
    out.open(r.m, root, 4);
    out.write(r.m, e.state(), {});
  }
  PlotReader rd;
  rd.open(root);
  EXPECT_EQ(rd.control().nel2, 15);
  EXPECT_EQ(rd.control().nummat2, 3);
  EXPECT_EQ(rd.control().nv1d, 6 + 5 * 16);
  EXPECT_EQ(rd.layout().beam_points, 16);
  const PlotGeometry& g = rd.geometry();
  ASSERT_EQ(g.num_beams(), 15);
  EXPECT_EQ(g.beam_nodes[0], r.m.beam_nodes[0][0]);
  EXPECT_EQ(g.beam_nodes[1], r.m.beam_nodes[0][1]);
  EXPECT_EQ(g.beam_user_ids[14], 15);
  ASSERT_EQ(rd.num_states(), 1);
  const PlotState ps = rd.state(0);
  ASSERT_EQ(ps.beam_vars.size(), std::size_t(15 * 86));
  const State& s = e.state();
  for (int b : {0, 9, 12, 14}) {
    const double* v = &ps.beam_vars[std::size_t(86 * b)];
    const double* res = &s.beams.res[6 * std::size_t(b)];
    const double want[6] = {res[0], res[1], res[2], res[4], res[5], res[3]};
    for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(float(v[k]), float(want[k])) << "beam " << b << " word " << k;
    const std::size_t ip = std::size_t(s.beams.ip_start[std::size_t(b)]);
    EXPECT_FLOAT_EQ(float(v[6 + 2]), float(s.beams.sig[3 * ip]));  // sigma_rr of point 1
    EXPECT_FLOAT_EQ(float(v[6 + 0]), float(s.beams.sig[3 * ip + 1]));
  }
  // the truss: one point, sigma_rr = N / A; the words of points 2-16 are zeros
  const double* t = &ps.beam_vars[std::size_t(86 * 14)];
  EXPECT_NEAR(t[6 + 2], t[0] / 1e-5, 1e-4 * std::fabs(t[6 + 2]));
  EXPECT_EQ(t[6 + 5 + 2], 0.0);
  EXPECT_GT(std::fabs(t[0]), 0.0);
}

// The starter's renumbering for locality moves the beams' node references: the frame renumbered
// (reorder on) and not runs to the same bits node by node (by deck id), the model back in deck
// order is the deck's.
TEST(KeywordBeams, RenumberedFrameGivesTheSameBits) {
  BeamRead r = read_beam_text(frame_deck());
  ASSERT_TRUE(r.ok) << r.messages();
  Model off = r.m, on = r.m;
  ASSERT_FALSE(order_mesh_for_locality(off, MeshOrderMode::off).renumbered);
  ASSERT_TRUE(order_mesh_for_locality(on, MeshOrderMode::on).renumbered);
  EXPECT_TRUE(model_differences(model_in_deck_order(on), r.m).empty());
  Engine a(off), b(on);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  StepStatus sa = StepStatus::ok, sb = StepStatus::ok;
  while (sa == StepStatus::ok) {
    sa = a.step();
    sb = b.step();
  }
  ASSERT_EQ(sa, StepStatus::finished);
  ASSERT_EQ(sb, StepStatus::finished);
  bool moved = false;
  for (int k = 1; k <= r.m.num_nodes(); ++k) {
    const std::size_t i = std::size_t(k - 1), j = std::size_t(on.node_of_deck_number(k));
    moved = moved || j != i;
    EXPECT_EQ(a.state().x[i], b.state().x[j]) << "node " << k;
    EXPECT_EQ(a.state().z[i], b.state().z[j]) << "node " << k;
  }
  EXPECT_TRUE(moved);
  EXPECT_EQ(a.state().beams.sig, b.state().beams.sig);
}

// ELFORM 2 (Belytschko-Schwer) in a deck: card 2 A ISS ITT J SA; the converter writes it back,
// and the frame with a resultant cantilever runs to its end with the energy balanced.
TEST(KeywordBeams, ResultantBeamReadsWritesAndRuns) {
  std::string deck = replaced(frame_deck(), "         1         1  0.833333         3         0\n$      TS1       TS2       TT1       TT2\n      0.02      0.02      0.01      0.01",
                              "         1         2\n    2.0e-4   1.67e-9   6.67e-9    4.5e-9   1.67e-4");
  deck = replaced(deck, "$      PID     SECID       MID\n         1         1         1", "$      PID     SECID       MID\n         1         1         2");
  BeamRead a = read_beam_text(deck);
  ASSERT_TRUE(a.ok) << a.messages();
  const BeamSectionData& sec = a.m.materials[std::size_t(a.m.beam_material[0])].beam_section;
  EXPECT_EQ(sec.elform, 2);
  EXPECT_DOUBLE_EQ(sec.area, 2.0e-4);
  EXPECT_DOUBLE_EQ(sec.iss, 1.67e-9);
  EXPECT_DOUBLE_EQ(sec.itt, 6.67e-9);
  EXPECT_DOUBLE_EQ(sec.jt, 4.5e-9);
  EXPECT_DOUBLE_EQ(sec.sa, 1.67e-4);
  std::ostringstream os;
  std::vector<std::string> notes;
  write_keyword_deck(os, a.m, &notes);
  BeamRead b = read_beam_text(os.str());
  ASSERT_TRUE(b.ok) << b.messages() << os.str();
  EXPECT_TRUE(model_differences(a.m, b.m, 50).empty());
  Engine e(a.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = e.step();
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_NEAR(e.state().energy_ratio(), 1.0, 0.01);
  EXPECT_LT(e.state().z[10], -1e-3);  // the loaded tip went down
}

// A rigid part of beams (*MAT_RIGID) at the cantilever's tip: the cantilever's end moment at the
// shared node turns the rigid body (the body's torque takes the nodes' moments), so the energy
// stays balanced (without the moments: ratio 1.39).
TEST(KeywordBeams, RigidBeamPartTakesTheMomentsOfItsNodes) {
  std::string deck = replaced(frame_deck(), "*PART\ntube branch\n         2         2         2", "*PART\ntube branch\n         2         2         3");
  deck = replaced(deck, "*MAT_ELASTIC\n", "*MAT_RIGID\n         3    7850.0   2.1e+11       0.3\n*MAT_ELASTIC\n");
  BeamRead r = read_beam_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  Engine e(r.m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  ASSERT_EQ(e.state().rigid.size(), 1u);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = e.step();
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_NEAR(e.state().energy_ratio(), 1.0, 0.01);
}

// *ELEMENT_BEAM_ORIENTATION: the frame's ten rectangular beams with the vector VX VY VZ = 0 1 0
// (N3 0) in place of their orientation node 17 at (0, 1, 0): the same s axes, so the same bits
// after 200 cycles; the keyword round trip keeps the vectors; the fixed format, whose beam card
// holds an orientation node only, refuses them; a vector along a beam's axis is error 1250, a
// block that ends before an orientation card error 1316.
TEST(KeywordBeams, OrientationVectorTakesTheOrientationNodesPlace) {
  const std::string plain = frame_deck();
  std::string oriented = replaced(plain, "*ELEMENT_BEAM\n$    eid     pid      n1      n2      n3\n",
                                  "*ELEMENT_BEAM_ORIENTATION\n$    eid     pid      n1      n2      n3\n");
  for (int e = 1; e <= 10; ++e) {
    char from[80], to[160];
    std::snprintf(from, sizeof from, "%8d%8d%8d%8d%8d\n", e, 1, e, e + 1, 17);
    std::snprintf(to, sizeof to, "%8d%8d%8d%8d%8d\n%16.1f%16.1f%16.1f\n", e, 1, e, e + 1, 0, 0.0, 1.0, 0.0);
    oriented = replaced(oriented, from, to);
  }
  BeamRead a = read_beam_text(plain), b = read_beam_text(oriented);
  ASSERT_TRUE(a.ok) << a.messages();
  ASSERT_TRUE(b.ok) << b.messages() << oriented;
  ASSERT_EQ(b.m.beam_orientation.size(), 15u);
  EXPECT_EQ(b.m.beam_nodes[0][2], -1);
  EXPECT_EQ(b.m.beam_orientation[0], (std::array<double, 3>{0, 1, 0}));
  Engine ea(a.m), eb(b.m);
  ASSERT_EQ(ea.initialize(), StepStatus::ok);
  ASSERT_EQ(eb.initialize(), StepStatus::ok);
  for (int c = 0; c < 200; ++c) {
    ASSERT_EQ(ea.step(), StepStatus::ok);
    ASSERT_EQ(eb.step(), StepStatus::ok);
  }
  EXPECT_EQ(ea.state().z, eb.state().z);
  EXPECT_EQ(ea.state().beams.sig, eb.state().beams.sig);
  EXPECT_EQ(ea.state().beams.e2, eb.state().beams.e2);

  std::ostringstream os;
  write_keyword_deck(os, b.m, nullptr);
  EXPECT_NE(os.str().find("*ELEMENT_BEAM_THICKNESS_ORIENTATION"), std::string::npos);
  BeamRead c = read_beam_text(os.str());
  ASSERT_TRUE(c.ok) << c.messages() << os.str();
  std::string all;
  for (const auto& d : model_differences(b.m, c.m, 50)) all += d + "\n";
  EXPECT_TRUE(all.empty()) << all;
  std::ostringstream log;
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/beam_orientation_refused.dyn";
  EXPECT_EQ(write_converted_decks(b.m, "", fixed, log), exit_code::input_error);
  EXPECT_NE(log.str().find("beam orientation vectors (*ELEMENT_BEAM_ORIENTATION"), std::string::npos) << log.str();

  BeamRead along = read_beam_text(replaced(oriented, "       1       1       1       2       0\n             0.0             1.0             0.0\n",
                                           "       1       1       1       2       0\n             2.0             0.0             0.0\n"));
  EXPECT_FALSE(along.ok);
  EXPECT_EQ(along.count(1250), 1) << along.messages();
  const std::size_t cut = oriented.find("             0.0             1.0             0.0\n*ELEMENT_BEAM_THICKNESS");
  ASSERT_NE(cut, std::string::npos);
  std::string truncated = oriented;
  truncated.erase(cut, std::string("             0.0             1.0             0.0\n").size());
  BeamRead missing = read_beam_text(truncated);
  EXPECT_FALSE(missing.ok);
  EXPECT_EQ(missing.count(1316), 1) << missing.messages();
}
