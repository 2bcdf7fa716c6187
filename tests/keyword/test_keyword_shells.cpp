// Keyword decks with Belytschko-Tsay shells: *SECTION_SHELL, *ELEMENT_SHELL(_THICKNESS),
// shell parts, *CONTROL_SHELL, rotational constraints and initial rotational velocities, the
// refusals, and a deck that runs to the end.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

namespace {

struct ShellRead {
  Model m;
  Diagnostics d;
  bool ok = false;
  std::string messages() const {
    std::ostringstream os;
    d.print(os);
    return os.str();
  }
};

ShellRead read_shell_text(const std::string& text) {
  ShellRead r;
  DeckFile deck;
  deck.load_from_string("shells.k", text);
  InputOptions o;
  r.ok = read_deck(deck, r.m, r.d, o);
  if (r.ok) r.ok = check_model(r.m, r.d);
  return r;
}

std::string field(double v, int w) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.*g", w, w > 10 ? 9 : 6, v);
  return b;
}
std::string ifield(long v, int w) {
  char b[64];
  std::snprintf(b, sizeof b, "%*ld", w, v);
  return b;
}

// A clamped strip of nx x 1 shells (0.5 m x 20 mm, 10 mm thick, steel), x = 0 clamped
// (translations and rotations), every node at vz = 0.1 m/s; `section` and `extra` replace or
// add cards.
std::string strip_deck(int nx, const std::string& section, const std::string& extra = "",
                       bool thickness_cards = false) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nclamped shell strip\n";
  d << "*CONTROL_TERMINATION\n" << field(2e-3, 10) << "\n";
  d << "*NODE\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= nx; ++i)
      d << ifield(1 + i + (nx + 1) * j, 8) << field(0.5 * i / nx, 16) << field(0.02 * j, 16) << field(0, 16) << "\n";
  d << "*PART\nstrip\n" << ifield(1, 10) << ifield(1, 10) << ifield(1, 10) << "\n";
  d << section;
  d << "*MAT_ELASTIC\n" << ifield(1, 10) << field(7850, 10) << field(2.1e11, 10) << field(0.3, 10) << "\n";
  d << (thickness_cards ? "*ELEMENT_SHELL_THICKNESS\n" : "*ELEMENT_SHELL\n");
  for (int i = 0; i < nx; ++i) {
    d << ifield(i + 1, 8) << ifield(1, 8) << ifield(1 + i, 8) << ifield(2 + i, 8) << ifield(2 + i + nx + 1, 8)
      << ifield(1 + i + nx + 1, 8) << "\n";
    if (thickness_cards) d << field(0.01, 16) << field(0.01, 16) << field(0.01, 16) << field(0.01, 16) << "\n";
  }
  d << "*BOUNDARY_SPC_NODE\n";
  for (int n : {1, nx + 2})
    d << ifield(n, 10) << ifield(0, 10) << ifield(1, 10) << ifield(1, 10) << ifield(1, 10) << ifield(1, 10)
      << ifield(1, 10) << ifield(1, 10) << "\n";
  d << "*INITIAL_VELOCITY\n" << ifield(0, 10) << "\n" << field(0, 10) << field(0, 10) << field(0.1, 10) << "\n";
  d << extra << "*END\n";
  return d.str();
}

const std::string kSection =
    "*SECTION_SHELL\n"
    "         1         2    0.8333         3\n"
    "      0.01\n";

}  // namespace

TEST(KeywordShells, StripReadsIntoShellParts) {
  ShellRead r = read_shell_text(strip_deck(10, kSection, "*CONTROL_SHELL\n         0         0         0         0         2\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  const Model& m = r.m;
  ASSERT_EQ(m.num_shells(), 10);
  EXPECT_EQ(m.num_hexes(), 0);
  ASSERT_EQ(m.materials.size(), 1u);
  const MaterialData& md = m.materials[0];
  EXPECT_TRUE(md.shell);
  EXPECT_EQ(md.shell_section.nip, 3);
  EXPECT_NEAR(md.shell_section.shrf, 0.8333, 1e-12);
  for (double t : m.shell_thickness[3]) EXPECT_DOUBLE_EQ(t, 0.01);  // T2-T4 default to T1
  EXPECT_EQ(m.shell_nodes[0][0], 0);
  EXPECT_EQ(m.shell_nodes[0][2], 12);
  // rotational constraints on the clamped nodes (no warning 2005: they are shell nodes)
  ASSERT_FALSE(m.rot_bc.empty());
  EXPECT_EQ(m.rot_bc[0], 7);
  EXPECT_EQ(m.rot_bc[11], 7);
  EXPECT_EQ(m.rot_bc[1], 0);
  EXPECT_EQ(r.d.count(2005), 0) << r.messages();
  EXPECT_EQ(m.bc[0], 7);
}

TEST(KeywordShells, ElementThicknessCardsAndRotationalVelocities) {
  const std::string extra =
      "*INITIAL_VELOCITY_NODE\n"
      "       3       0.0       0.0       0.0       0.0       2.5       0.0\n";
  ShellRead r = read_shell_text(strip_deck(4, "*SECTION_SHELL\n         1\n\n", extra, true));
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_DOUBLE_EQ(r.m.shell_thickness[2][1], 0.01);
  EXPECT_EQ(r.m.materials[0].shell_section.nip, 2);     // LS-DYNA default
  EXPECT_DOUBLE_EQ(r.m.materials[0].shell_section.shrf, 1.0);
  ASSERT_FALSE(r.m.init_omega.empty());
  EXPECT_DOUBLE_EQ(r.m.init_omega[2][1], 2.5);
  EXPECT_DOUBLE_EQ(r.m.init_omega[1][1], 0.0);
}

TEST(KeywordShells, RefusedSectionFieldsAndMissingThickness) {
  const std::string bad = "*SECTION_SHELL\n" + ifield(1, 10) + ifield(5, 10) + field(1.0, 10) + ifield(12, 10) +
                          std::string(10, ' ') + field(1.0, 10) + ifield(1, 10) + "\n" + field(0.0, 10) + "\n";
  ShellRead r = read_shell_text(strip_deck(2, bad, "*CONTROL_SHELL\n         0         0         0         0         4\n"));
  EXPECT_FALSE(r.ok);
  // ELFORM 5 (16 is the fully integrated shell), NIP 12, QR 1.0, ICOMP 1, THEORY 4: each 1102; the missing thickness 1241
  EXPECT_EQ(r.d.count(1102), 5) << r.messages();
  EXPECT_GE(r.d.count(1241), 1) << r.messages();
  EXPECT_NE(r.messages().find("ELFORM"), std::string::npos);
}

// The strip deck runs: the clamped strip, all nodes at 0.1 m/s in z at t = 0 (the clamped
// ones held), conserves energy with the rotational kinetic energy counted; the clamped nodes'
// rotations stay zero.
TEST(KeywordShells, StripDeckRunsAndConservesEnergy) {
  ShellRead r = read_shell_text(strip_deck(20, kSection));
  ASSERT_TRUE(r.ok) << r.messages();
  Engine eng(r.m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.01);
  EXPECT_GT(s.internal, 0.0);
  const int r0 = s.shells.node_rot[0];
  ASSERT_GE(r0, 0);
  EXPECT_EQ(s.shells.wy[std::size_t(r0)], 0.0);
  EXPECT_NE(s.shells.wy[std::size_t(s.shells.node_rot[10])], 0.0);
}

// The converter writes shells back as a keyword deck that reads into the same Model (sections,
// thicknesses, rotational constraints and velocities); the fixed format refuses the initial
// rotational velocities (tests/input/test_shell_cards.cpp: the fixed shell cards).
TEST(KeywordShells, KeywordRoundTripAndFixedFormatRefusal) {
  const std::string extra =
      "*INITIAL_VELOCITY_NODE\n"
      "       3       0.0       0.0       0.5       0.0       2.5       0.0\n"
      "*CONTROL_SHELL\n         0         0         0         0         2\n      0.75\n";
  ShellRead a = read_shell_text(strip_deck(6, kSection, extra));
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_DOUBLE_EQ(a.m.shell_rotary_scale, 0.75);
  std::ostringstream os;
  std::vector<std::string> notes;
  write_keyword_deck(os, a.m, &notes);
  ShellRead b = read_shell_text(os.str());
  ASSERT_TRUE(b.ok) << b.messages() << os.str();
  const auto diffs = model_differences(a.m, b.m, 50);
  std::string all;
  for (const auto& d : diffs) all += d + "\n";
  EXPECT_TRUE(diffs.empty()) << all;
  EXPECT_EQ(b.m.num_shells(), 6);
  EXPECT_DOUBLE_EQ(b.m.init_omega[2][1], 2.5);
  std::ostringstream log;
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/shell_fixed_refused.dyn";
  EXPECT_EQ(write_converted_decks(a.m, "", fixed, log), exit_code::input_error);
  EXPECT_NE(log.str().find("initial rotational velocities"), std::string::npos) << log.str();
}

// A restart dump of a shell model (stresses and plastic history at the points, hourglass
// resultants, rotations) restores a State that continues bit for bit.
TEST(KeywordShells, RestartDumpContinuesBitForBit) {
  std::string deck = strip_deck(10, kSection);
  deck.replace(deck.find("*MAT_ELASTIC"), std::string("*MAT_ELASTIC").size(), "*MAT_PLASTIC_KINEMATIC");
  deck.replace(deck.find("       0.3\n*ELEMENT_SHELL"), std::string("       0.3\n").size(),
               "       0.3     2.0e5     2.0e9       0.5\n");
  ShellRead r = read_shell_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  Engine a(r.m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  for (int c = 0; c < 150; ++c) ASSERT_EQ(a.step(), StepStatus::ok);
  DumpHeader h;
  h.deck_name = "shells.k";
  h.deck_text = deck;
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/shell_restart_dump";
  write_restart_dump(path, h, a.state(), a.contact().restart_data());
  Engine b(r.m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  for (int c = 0; c < 150; ++c) {
    ASSERT_EQ(a.step(), StepStatus::ok);
    ASSERT_EQ(b.step(), StepStatus::ok);
  }
  EXPECT_GT(*std::max_element(a.state().shells.eps_p.begin(), a.state().shells.eps_p.end()), 0.0);
  EXPECT_EQ(a.state().z, b.state().z);
  EXPECT_EQ(a.state().shells.sig, b.state().shells.sig);
  EXPECT_EQ(a.state().shells.back, b.state().shells.back);
  EXPECT_EQ(a.state().shells.wy, b.state().shells.wy);
  EXPECT_EQ(a.state().internal, b.state().internal);
}

// A contact naming a shell part takes its shells as segments (n1 n2 n3 n4, both sides used;
// tests/contact/test_shell_contact.cpp runs them).
TEST(KeywordShells, ContactOnAShellPartTakesItsShellsAsSegments) {
  const std::string contact =
      "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n"
      "         1         1         3         3\n"
      "       0.0       0.0       0.0\n"
      "       1.0       1.0\n";
  ShellRead r = read_shell_text(strip_deck(2, kSection, contact));
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.interfaces.size(), 1u);
  ASSERT_EQ(r.m.interfaces[0].slave.size(), 2u);
  EXPECT_EQ(r.m.interfaces[0].slave[1], r.m.shell_nodes[1]);
  EXPECT_EQ(r.m.interfaces[0].master, r.m.interfaces[0].slave);
}
