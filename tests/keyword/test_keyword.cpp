// LS-DYNA keyword decks (issue 7): the reader (fixed columns, abutting fields, free format,
// long and I10 formats, includes, sparse ids, two-line *ELEMENT_SOLID as LS-PrePost writes it),
// unsupported keywords refused in one pass or warned with --lenient-keywords, the mapping onto
// the Model, the writers and round trips, the shipped keyword twins of the seed decks, and
// bitwise-equal runs of a fixed deck and its keyword twin.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/input/keyword_reader.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;
namespace fs = std::filesystem;

namespace {

const std::string kSource = IMPACT3D_SOURCE_DIR;

using Read = test_support::ReadDeck;

// Reads deck text as read_and_check_deck does (content decides the reader; then the checks).
Read read_text(const std::string& text, bool lenient = false, const std::string& name = "deck.k") {
  InputOptions o;
  o.lenient_keywords = lenient;
  return test_support::read_deck_text(text, name, o);
}

Read read_path(const std::string& path, bool lenient = false) {
  Read r;
  InputOptions o;
  o.lenient_keywords = lenient;
  r.ok = read_and_check_deck(path, r.m, r.d, o);
  return r;
}

std::string keyword_text(const Model& m) {
  std::ostringstream os;
  write_keyword_deck(os, m);
  return os.str();
}
std::string fixed_text(const Model& m, std::vector<std::string>* notes = nullptr) {
  std::ostringstream os;
  write_fixed_deck(os, m, notes);
  return os.str();
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

fs::path temp_dir(const std::string& name) {
  fs::path p = fs::temp_directory_path() / ("impact3d_kw_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// --------------------------------------------------------------------------------------------
// A small deck the way LS-PrePost writes one: $# column comments, *PART with a heading line,
// sparse ids, two-line *ELEMENT_SOLID, *NODE in I8/E16, abutting fields in
// *CONTROL_TERMINATION, a box of two hexahedra (x 0..2, y 0..1, z 0..1; unit: mm, t, s).
std::string node_line(int id, double x, double y, double z, int tc = 0, int rc = 0) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%8d%16.1f%16.1f%16.1f%8d%8d", id, x, y, z, tc, rc);
  return buf;
}
int nid(int ix, int iy, int iz) { return 1001 + ix + 3 * iy + 6 * iz; }

std::string prepost_nodes() {
  std::string s = "*NODE\n$#   nid               x               y               z      tc      rc  \n";
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 3; ++ix) s += node_line(nid(ix, iy, iz), ix, iy, iz) + "\n";
  return s;
}

std::string prepost_elements() {
  std::string s = "*ELEMENT_SOLID\n$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n";
  for (int ix = 0; ix < 2; ++ix) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%8d%8d\n", 501 + 7 * ix, 7);
    s += buf;
    std::snprintf(buf, sizeof buf, "%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", nid(ix, 0, 0), nid(ix + 1, 0, 0),
                  nid(ix + 1, 1, 0), nid(ix, 1, 0), nid(ix, 0, 1), nid(ix + 1, 0, 1), nid(ix + 1, 1, 1),
                  nid(ix, 1, 1), 0, 0);
    s += buf;
  }
  return s;
}

const char* kPrePostHead =
    "*KEYWORD\n"
    "*TITLE\n"
    "$# title\n"
    "two-hex block on a rigid wall\n"
    "*CONTROL_TERMINATION\n"
    "$#  endtim    endcyc     dtmin    endeng    endmas     nosol     \n"
    "   8.0E-05         0       0.0       0.01.000000E8         0\n"
    "*CONTROL_TIMESTEP\n"
    "$#  dtinit    tssfac      isdo    tslimt     dt2ms      lctm     erode     ms1st\n"
    "       0.0       0.0         0       0.0       0.0         0         0         0\n"
    "*CONTROL_HOURGLASS\n"
    "$#     ihq        qh  \n"
    "         4      0.05\n"
    "*CONTROL_BULK_VISCOSITY\n"
    "$#      q1        q2      type     btype    tstype      \n"
    "       1.2      0.05         1         0         0\n"
    "*DATABASE_BINARY_D3PLOT\n"
    "$#      dt      lcdt      beam     npltc    psetid      \n"
    "  4.0E-6           0         0         0         0\n"
    "*DATABASE_GLSTAT\n"
    "$#      dt    binary      lcur     ioopt     \n"
    "   1.0E-7         0         0         1\n"
    "*PART\n"
    "$#                                                                         title\n"
    "block\n"
    "$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid\n"
    "         7         3        12         0         0         0         0         0\n"
    "*SECTION_SOLID\n"
    "$#   secid    elform       aet    unused    unused    unused    cohoff   gaskeit\n"
    "         3         1         0\n"
    "*MAT_PLASTIC_KINEMATIC_TITLE\n"
    "steel\n"
    "$#     mid        ro         e        pr      sigy      etan      beta    \n"
    "        127.85000E-9  150000.0      0.34     390.0      90.0       0.0\n"
    "$#     src       srp        fs        vp  \n"
    "       0.0       0.0       0.0       0.0\n"
    "*SET_NODE_LIST\n"
    "$#     sid       da1       da2       da3       da4    solver      \n"
    "        20       0.0       0.0       0.0       0.0MECH\n"
    "$#    nid1      nid2      nid3      nid4      nid5      nid6      nid7      nid8\n"
    "      1001      1004      1007      1010         0         0         0         0\n"
    "*BOUNDARY_SPC_SET\n"
    "$#    nsid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz\n"
    "        20         0         0         1         0         0         0         0\n"
    "*BOUNDARY_SPC_NODE\n"
    "$#     nid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz\n"
    "      1001         0         0         0         1         0         0         0\n"
    "*RIGIDWALL_PLANAR_ID\n"
    "$#      id                                                                 title\n"
    "         1wall\n"
    "$#    nsid    nsidex     boxid    offset     birth     death     rwksf     \n"
    "        20         0         0       0.0       0.0       0.0       1.0\n"
    "$#      xt        yt        zt        xh        yh        zh      fric      wvel\n"
    "      -0.1       0.0       0.0       1.0       0.0       0.0       0.0       0.0\n"
    "*INITIAL_VELOCITY_GENERATION\n"
    "$#nsid/pid      styp     omega        vx        vy        vz     ivatn      icid\n"
    "         7         2       0.0  -2.75E+4       0.0       0.0         0         0\n"
    "$#      xc        yc        zc        nx        ny        nz     phase    irigid\n"
    "       0.0       0.0       0.0       0.0       0.0       0.0         0         0\n";

std::string prepost_deck() { return std::string(kPrePostHead) + prepost_nodes() + prepost_elements() + "*END\n"; }

}  // namespace

// ---------------------------------------------------------------------------- detection

TEST(KeywordDetect, ByContentNotExtension) {
  fs::path dir = temp_dir("detect");
  write_file(dir / "block.dyn", prepost_deck());  // keyword deck with a fixed-format name
  Read r = read_path((dir / "block.dyn").string());
  EXPECT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.m.num_hexes(), 2);
  // a fixed-format deck named .k
  fs::copy_file(kSource + "/decks/one_hex.dyn", dir / "one_hex.k");
  Read f = read_path((dir / "one_hex.k").string());
  EXPECT_TRUE(f.ok) << f.messages();
  EXPECT_EQ(f.m.num_hexes(), 1);
  fs::remove_all(dir);
}

TEST(KeywordDetect, Rules) {
  DeckFile a, b, c;
  a.load_from_string("a", "$ comment\n\n*KEYWORD\n*END\n");
  b.load_from_string("b", "title\n*NODE\n");
  c.load_from_string("c", "title   88 large\n*---- comment\n* comment\n    1\n");
  EXPECT_TRUE(is_keyword_deck(a));
  EXPECT_TRUE(is_keyword_deck(b));
  EXPECT_FALSE(is_keyword_deck(c));
}

// ---------------------------------------------------------------------------- LS-PrePost deck

TEST(KeywordRead, PrePostStyleDeckMapsOntoModel) {
  Read r = read_text(prepost_deck());
  ASSERT_TRUE(r.ok) << r.messages();
  const Model& m = r.m;
  EXPECT_EQ(m.title, "two-hex block on a rigid wall");
  ASSERT_EQ(m.num_nodes(), 12);
  ASSERT_EQ(m.num_hexes(), 2);
  // sparse ids renumbered 1..N in increasing order, user ids kept
  ASSERT_EQ(m.node_user_id.size(), 12u);
  EXPECT_EQ(m.node_user_id.front(), 1001);
  EXPECT_EQ(m.node_user_id.back(), 1012);
  EXPECT_EQ(m.hex_user_id, (std::vector<int>{501, 508}));
  EXPECT_EQ(m.hex_nodes[1][0], 1);  // node 1002
  EXPECT_EQ(m.hex_nodes[1][6], 11); // node 1012
  // controls: abutting fields, TSSFAC 0 -> 0.9, plot interval, time-history interval
  EXPECT_EQ(m.control.end_time, 8.0e-5);
  EXPECT_EQ(m.control.tssf, 0.9);
  EXPECT_EQ(m.control.plot_interval, 4.0e-6);
  EXPECT_EQ(m.control.th_interval, 1.0e-7);
  // part -> material 1 with *CONTROL_HOURGLASS and *CONTROL_BULK_VISCOSITY
  ASSERT_EQ(m.materials.size(), 1u);
  const MaterialData& md = m.materials[0];
  EXPECT_EQ(md.number, 1);
  EXPECT_EQ(md.type, 3);
  EXPECT_EQ(md.title, "block");
  EXPECT_EQ(md.rho, 7.85e-9);  // "127.85000E-9": MID 12 abutting RO
  EXPECT_EQ(md.E, 150000.0);
  EXPECT_EQ(md.nu, 0.34);
  EXPECT_EQ(md.sigma_y, 390.0);
  EXPECT_EQ(md.E_tan, 90.0);
  EXPECT_EQ(md.beta, 0.0);
  EXPECT_EQ(md.hourglass_type, 4);
  EXPECT_EQ(md.hourglass_coef, 0.05);
  EXPECT_EQ(md.q1, 1.2);
  EXPECT_EQ(md.q2, 0.05);
  EXPECT_EQ(m.hex_material, (std::vector<int>{0, 0}));
  // SPC: set 20 (x = 0 nodes) fixed in y -> code 2; node 1001 also z -> y+z = 5
  EXPECT_EQ(m.bc[0], 5);
  EXPECT_EQ(m.bc[3], 2);
  EXPECT_EQ(m.bc[1], 0);
  // rigid wall with the node set
  ASSERT_EQ(m.walls.size(), 1u);
  EXPECT_EQ(m.walls[0].nodes, (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(m.walls[0].tail[0], -0.1);
  EXPECT_EQ(m.walls[0].head[0], 1.0);
  // initial velocity of part 7: all 12 nodes, one range
  ASSERT_EQ(m.init_velocities.size(), 1u);
  EXPECT_EQ(m.init_velocities[0].first, 1);
  EXPECT_EQ(m.init_velocities[0].last, 12);
  EXPECT_EQ(m.init_velocities[0].increment, 1);
  EXPECT_EQ(m.init_velocities[0].v[0], -2.75e4);
}

// *SET_NODE_LIST_GENERATE ranges hold the nodes whose ids lie in them, ids that are not nodes
// skipped; a range may be huge (it is never expanded id by id: a 2e9-id range costs nothing).
TEST(KeywordRead, NodeListGenerateRangesEvenHugeOnes) {
  const std::string list = "*SET_NODE_LIST\n"
                           "$#     sid       da1       da2       da3       da4    solver      \n"
                           "        20       0.0       0.0       0.0       0.0MECH\n"
                           "$#    nid1      nid2      nid3      nid4      nid5      nid6      nid7      nid8\n"
                           "      1001      1004      1007      1010         0         0         0         0\n";
  std::string deck = prepost_deck();
  const std::size_t at = deck.find(list);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, list.size(),
               "*SET_NODE_LIST_GENERATE\n        20\n"
               "         1      1001      1004      1004      1007      1007      1010      1010\n"
               "      1013 2000000000\n");
  Read g = read_text(deck);
  ASSERT_TRUE(g.ok) << g.messages();
  Read l = read_text(prepost_deck());
  ASSERT_TRUE(l.ok);
  EXPECT_TRUE(model_differences(l.m, g.m).empty()) << join(model_differences(l.m, g.m));
  deck.replace(deck.find("      1013 2000000000"), 21, "      1013 -5");
  Read bad = read_text(deck);
  EXPECT_FALSE(bad.ok);
  EXPECT_EQ(bad.count(1003), 1) << bad.messages();
}

// *INITIAL_VELOCITY_GENERATION with OMEGA: v = (VX, VY, VZ) + OMEGA n x (x - xc) node by node
// (axis through XC YC ZC along NX NY NZ, normalised); the kinetic energy is then exactly
// 1/2 sum m |v|^2 of that field, and a free spinning block keeps its angular momentum about the
// axis through a run (no wall, no constraint).
TEST(KeywordRead, InitialVelocityGenerationWithOmega) {
  std::string deck = prepost_deck();
  const std::string gen = "         7         2       0.0  -2.75E+4       0.0       0.0         0         0\n"
                          "$#      xc        yc        zc        nx        ny        nz     phase    irigid\n"
                          "       0.0       0.0       0.0       0.0       0.0       0.0         0         0\n";
  const std::size_t at = deck.find(gen);
  ASSERT_NE(at, std::string::npos);
  // spin 1000 rad/time about the z axis through (1, 0.5, 0) (units of the deck), plus vx 10
  deck.replace(at, gen.size(),
               "         7         2    1000.0      10.0       0.0       0.0         0         0\n"
               "$#      xc        yc        zc        nx        ny        nz     phase    irigid\n"
               "       1.0       0.5       0.0       0.0       0.0       2.0         0         0\n");
  // TSSFAC 0.6: a body one element thick needs <= 0.67 (docs/physics.md, "Physics")
  const std::string ts = "       0.0       0.0         0       0.0       0.0         0         0         0\n";
  ASSERT_NE(deck.find(ts), std::string::npos);
  deck.replace(deck.find(ts), ts.size(), "       0.0       0.6         0       0.0       0.0         0         0         0\n");
  // no wall and no constraints: a free body
  deck.replace(deck.find("*BOUNDARY_SPC_SET"), deck.find("*INITIAL_VELOCITY_GENERATION") - deck.find("*BOUNDARY_SPC_SET"), "");
  Read r = read_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  Engine eng(r.m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    EXPECT_DOUBLE_EQ(s.vx[k], 10.0 - 1000.0 * (s.y[k] - 0.5)) << "node " << i;
    EXPECT_DOUBLE_EQ(s.vy[k], 1000.0 * (s.x[k] - 1.0)) << "node " << i;
    EXPECT_EQ(s.vz[k], 0.0);
  }
  auto lz = [&] {  // angular momentum about z through the centre of mass
    double m = 0, cx = 0, cy = 0;
    for (int i = 0; i < s.nn; ++i) m += s.mass[std::size_t(i)], cx += s.mass[std::size_t(i)] * s.x[std::size_t(i)], cy += s.mass[std::size_t(i)] * s.y[std::size_t(i)];
    cx /= m, cy /= m;
    double l = 0;
    for (int i = 0; i < s.nn; ++i) {
      const std::size_t k = std::size_t(i);
      l += s.mass[k] * ((s.x[k] - cx) * s.vy[k] - (s.y[k] - cy) * s.vx[k]);
    }
    return l;
  };
  const double l0 = lz();
  ASSERT_GT(std::abs(l0), 0.0);
  for (int c = 0; c < 200; ++c) ASSERT_EQ(eng.step(), StepStatus::ok);
  std::printf("spinning block: L_z %.9g -> %.9g (%.2e)\n", l0, lz(), lz() / l0 - 1);
  EXPECT_NEAR(lz() / l0, 1.0, 1e-6);
  // OMEGA without an axis is an error naming the field
  std::string bad = deck;
  bad.replace(bad.find("       0.0       0.0       2.0         0         0"), 50, "       0.0       0.0       0.0         0         0");
  Read rb = read_text(bad);
  EXPECT_FALSE(rb.ok);
  EXPECT_EQ(rb.count(1003), 1) << rb.messages();
}

// *PARAMETER: R / I values referenced as &name or -&name in any numeric field, before or after
// their definition, in any case; an undefined name is error 1310 naming the field; a name
// defined twice is error 1200.
TEST(KeywordRead, ParametersSubstituteIntoFields) {
  std::string deck = prepost_deck();
  const std::string mat = "        127.85000E-9  150000.0      0.34     390.0      90.0       0.0\n";
  ASSERT_NE(deck.find(mat), std::string::npos);
  deck.replace(deck.find(mat), mat.size(), "        127.85000E-9      &E        0.34    &sigy      90.0       0.0\n");
  const std::string vel = "  -2.75E+4       0.0       0.0";
  ASSERT_NE(deck.find(vel), std::string::npos);
  deck.replace(deck.find(vel), vel.size(), "     -&V0       0.0       0.0");
  deck.insert(deck.find("*PART"), "*PARAMETER\n$#   prmr1      val1     prmr2      val2\nR e         150000.0R sigy         390.0\nI v0           27500\n");
  Read r = read_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  Read plain = read_text(prepost_deck());
  ASSERT_TRUE(plain.ok);
  EXPECT_EQ(join(model_differences(plain.m, r.m)), "");
  // undefined and duplicated names
  std::string bad = deck;
  bad.replace(bad.find("&sigy"), 5, "&sigx");
  bad.insert(bad.find("*PART"), "*PARAMETER\nR E              1.0\n");
  Read rb = read_text(bad);
  EXPECT_FALSE(rb.ok);
  EXPECT_EQ(rb.count(1310), 1) << rb.messages();
  EXPECT_NE(rb.messages().find("SIGY"), std::string::npos) << rb.messages();
  EXPECT_NE(rb.messages().find("&SIGX"), std::string::npos) << rb.messages();
  EXPECT_EQ(rb.count(1200), 1) << rb.messages();
}

TEST(KeywordRead, HourglassKeywordOverridesControl) {
  std::string deck = prepost_deck();
  std::string from = "         7         3        12         0         0         0         0         0\n";
  std::string to = "         7         3        12         0         5         0         0         0\n";
  deck.replace(deck.find(from), from.size(), to);
  deck.insert(deck.find("*END"),
              "*HOURGLASS\n$#    hgid       ihq        qm       ibq        q1        q2\n"
              "         5         2      0.12         0       1.7\n");
  Read r = read_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.m.materials[0].hourglass_type, 2);
  EXPECT_EQ(r.m.materials[0].hourglass_coef, 0.12);
  EXPECT_EQ(r.m.materials[0].q1, 1.7);
  EXPECT_EQ(r.m.materials[0].q2, 0.05);  // blank: *CONTROL_BULK_VISCOSITY
}

TEST(KeywordRead, FreeFormatLongAndI10GiveTheSameModel) {
  Read base = read_text(prepost_deck());
  ASSERT_TRUE(base.ok) << base.messages();
  // free format: *NODE and the material as comma-separated values
  std::string free_deck = prepost_deck();
  {
    std::string nodes = "*NODE\n";
    for (int iz = 0; iz < 2; ++iz)
      for (int iy = 0; iy < 2; ++iy)
        for (int ix = 0; ix < 3; ++ix)
          nodes += std::to_string(nid(ix, iy, iz)) + ", " + std::to_string(ix) + ".0," + std::to_string(iy) + "," +
                   std::to_string(iz) + ".\n";
    std::size_t a = free_deck.find("*NODE"), b = free_deck.find("*ELEMENT_SOLID");
    free_deck.replace(a, b - a, nodes);
    std::string mat = "        127.85000E-9  150000.0      0.34     390.0      90.0       0.0\n";
    free_deck.replace(free_deck.find(mat), mat.size(), "12,7.85e-9,1.5e5,0.34,390,90,0\n");
  }
  Read fr = read_text(free_deck);
  ASSERT_TRUE(fr.ok) << fr.messages();
  EXPECT_EQ(join(model_differences(base.m, fr.m)), "");

  // long format for the nodes and elements ('+' suffix): 20-column fields
  std::string long_deck = std::string(kPrePostHead);
  long_deck += "*NODE +\n";
  char buf[256];
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 3; ++ix) {
        std::snprintf(buf, sizeof buf, "%20d%20.1f%20.1f%20.1f%20d%20d\n", nid(ix, iy, iz), double(ix), double(iy), double(iz), 0, 0);
        long_deck += buf;
      }
  long_deck += "*ELEMENT_SOLID +\n";
  for (int ix = 0; ix < 2; ++ix) {
    std::snprintf(buf, sizeof buf, "%20d%20d\n", 501 + 7 * ix, 7);
    long_deck += buf;
    std::snprintf(buf, sizeof buf, "%20d%20d%20d%20d%20d%20d%20d%20d\n", nid(ix, 0, 0), nid(ix + 1, 0, 0),
                  nid(ix + 1, 1, 0), nid(ix, 1, 0), nid(ix, 0, 1), nid(ix + 1, 0, 1), nid(ix + 1, 1, 1), nid(ix, 1, 1));
    long_deck += buf;
  }
  long_deck += "*END\n";
  Read lr = read_text(long_deck);
  ASSERT_TRUE(lr.ok) << lr.messages();
  EXPECT_EQ(join(model_differences(base.m, lr.m)), "");

  // I10=Y: *NODE I10/3E16/2I10, *ELEMENT_SOLID legacy one-line form with I10 fields
  std::string i10 = std::string(kPrePostHead);
  i10.replace(0, 8, "*KEYWORD I10=Y");
  i10 += "*NODE\n";
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 3; ++ix) {
        std::snprintf(buf, sizeof buf, "%10d%16.1f%16.1f%16.1f%10d%10d\n", nid(ix, iy, iz), double(ix), double(iy), double(iz), 0, 0);
        i10 += buf;
      }
  i10 += "*ELEMENT_SOLID\n";
  for (int ix = 0; ix < 2; ++ix) {
    std::snprintf(buf, sizeof buf, "%10d%10d%10d%10d%10d%10d%10d%10d%10d%10d\n", 501 + 7 * ix, 7, nid(ix, 0, 0),
                  nid(ix + 1, 0, 0), nid(ix + 1, 1, 0), nid(ix, 1, 0), nid(ix, 0, 1), nid(ix + 1, 0, 1),
                  nid(ix + 1, 1, 1), nid(ix, 1, 1));
    i10 += buf;
  }
  i10 += "*END\ntext after *END is not read\n";
  Read ir = read_text(i10);
  ASSERT_TRUE(ir.ok) << ir.messages();
  EXPECT_EQ(join(model_differences(base.m, ir.m)), "");
}

TEST(KeywordRead, LegacyOneLineElementForm) {
  std::string deck = std::string(kPrePostHead) + prepost_nodes() + "*ELEMENT_SOLID\n";
  char buf[160];
  for (int ix = 0; ix < 2; ++ix) {
    std::snprintf(buf, sizeof buf, "%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", 501 + 7 * ix, 7, nid(ix, 0, 0), nid(ix + 1, 0, 0),
                  nid(ix + 1, 1, 0), nid(ix, 1, 0), nid(ix, 0, 1), nid(ix + 1, 0, 1), nid(ix + 1, 1, 1), nid(ix, 1, 1));
    deck += buf;
  }
  deck += "*END\n";
  Read a = read_text(deck), b = read_text(prepost_deck());
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(join(model_differences(a.m, b.m)), "");
}

// *NODE and *ELEMENT_SOLID cards that are plain (fixed columns, numbers only) are read on a
// fast path; any other card (a *PARAMETER reference, commas, an integer written as a real, a
// tab) is read the normal way.  Both give the same model, and the messages of the normal way.
TEST(KeywordRead, BulkCardsGiveTheSameModelOnEveryPath) {
  Read base = read_text(prepost_deck());
  ASSERT_TRUE(base.ok) << base.messages();
  std::string deck = prepost_deck();
  const auto replace_line = [&](const std::string& from, const std::string& to) {
    const std::size_t p = deck.find(from);
    ASSERT_NE(p, std::string::npos) << from;
    deck.replace(p, from.size(), to);
  };
  char buf[128];
  std::snprintf(buf, sizeof buf, "%8d%16s%16s%16s%8d%8d", nid(1, 0, 0), "&XONE", "0.0", "0.0", 0, 0);
  replace_line(node_line(nid(1, 0, 0), 1, 0, 0), buf);
  replace_line(node_line(nid(2, 0, 0), 2, 0, 0), "1003,2.0,0.0,0.0");
  std::snprintf(buf, sizeof buf, "%8s%16s%16s%16s%8d%8d", "1004.", "0.0", "1.0", "0.0", 0, 0);
  replace_line(node_line(nid(0, 1, 0), 0, 1, 0), buf);
  deck.insert(deck.find("*NODE"), "*PARAMETER\nRXONE           1.0\n");
  Read mixed = read_text(deck);
  ASSERT_TRUE(mixed.ok) << mixed.messages();
  EXPECT_EQ(join(model_differences(base.m, mixed.m)), "");

  // errors on plain cards are reported as the normal way reports them
  std::string bad = prepost_deck();
  const std::string n1 = node_line(nid(1, 1, 1), 1, 1, 1);
  bad.replace(bad.find(n1), n1.size(), n1 + "\n" + n1);  // a node defined twice
  Read b = read_text(bad);
  EXPECT_FALSE(b.ok);
  ASSERT_EQ(b.count(1200), 1) << b.messages();
  EXPECT_EQ(b.first(1200)->where.col_first, 1);
  EXPECT_EQ(b.first(1200)->where.col_last, 8);
  EXPECT_NE(b.messages().find("*NODE node 1011, field \"NID\" (cols 1-8)"), std::string::npos) << b.messages();
}

// ---------------------------------------------------------------------------- includes

TEST(KeywordInclude, NestedRelativePathsAndErrorsNameTheIncludeFile) {
  fs::path dir = temp_dir("include");
  std::string head = kPrePostHead;
  write_file(dir / "main.k", head + "*INCLUDE\nmesh/nodes.k\n*END\n");
  write_file(dir / "mesh" / "nodes.k", "*KEYWORD\n" + prepost_nodes() + "*INCLUDE\nelements.k\n*END\n");
  write_file(dir / "mesh" / "elements.k", "$ elements\n" + prepost_elements() + "*END\n");
  Read r = read_path((dir / "main.k").string());
  ASSERT_TRUE(r.ok) << r.messages();
  Read direct = read_text(prepost_deck());
  EXPECT_EQ(join(model_differences(r.m, direct.m)), "");

  // a bad field in the nested include: file, line, keyword, field and columns
  std::string bad = prepost_elements();
  std::size_t p = bad.find("    1002    1003");
  bad.replace(p, 8, "    1x02");
  write_file(dir / "mesh" / "elements.k", "$ elements\n" + bad + "*END\n");
  Read e = read_path((dir / "main.k").string());
  EXPECT_FALSE(e.ok);
  const Diagnostic* d = e.first(1001);
  ASSERT_NE(d, nullptr) << e.messages();
  EXPECT_EQ(fs::path(d->where.file).filename(), "elements.k");
  EXPECT_EQ(d->where.line, 7);  // node card of element 508
  EXPECT_EQ(d->where.field, "N1");
  EXPECT_EQ(d->where.col_first, 1);
  EXPECT_EQ(d->where.col_last, 8);
  EXPECT_NE(d->where.card.find("*ELEMENT_SOLID"), std::string::npos);

  // missing include and a self-include
  write_file(dir / "main.k", head + "*INCLUDE\nnot_there.k\n*INCLUDE\nmain.k\n" + prepost_nodes() + prepost_elements() + "*END\n");
  Read m = read_path((dir / "main.k").string());
  EXPECT_FALSE(m.ok);
  EXPECT_EQ(m.count(1306), 1) << m.messages();
  EXPECT_EQ(m.count(1307), 1) << m.messages();
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------- unsupported

// Segment messages (warning 2013, reversed segment) name the include file the *SET_SEGMENT
// card is in, with its line there.
TEST(KeywordInclude, SegmentMessagesNameTheIncludeFile) {
  fs::path dir = temp_dir("include_segments");
  std::ifstream in(fs::path(IMPACT3D_SOURCE_DIR) / "decks/keyword/crossed_cylinders.k", std::ios::binary);
  const std::string deck((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t a = deck.find("*SET_SEGMENT"), b = deck.find("*CONTACT_SURFACE_TO_SURFACE");
  ASSERT_TRUE(a != std::string::npos && b != std::string::npos && a < b);
  std::string segs = deck.substr(a, b - a);
  const std::string first = "        15        34        35        16\n";
  ASSERT_EQ(segs.find(first), segs.find("$#      n1        n2        n3        n4\n") + 41);
  segs.replace(segs.find(first), first.size(), "        15        16        35        34\n");  // reversed
  write_file(dir / "main.k", deck.substr(0, a) + "*INCLUDE\nseg.k\n" + deck.substr(b));
  write_file(dir / "seg.k", segs + "*END\n");
  Read r = read_path((dir / "main.k").string());
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.count(2013), 1) << r.messages();
  const Diagnostic* w = r.first(2013);
  EXPECT_NE(w->where.file.find("seg.k"), std::string::npos) << r.messages();
  EXPECT_EQ(w->where.line, 5) << r.messages();
}

TEST(KeywordUnsupported, ListedInOnePassOrWarnedWhenLenient) {
  std::string deck = std::string(kPrePostHead) + prepost_nodes() + prepost_elements() +
                     "*CONTROL_ADAPTIVE\n$# adpfreq\n      20.0\n"
                     "*SECTION_DISCRETE\n         9         0\n       0.0\n"
                     "*PART\nbeam\n         8         9        12\n"
                     "*ELEMENT_DISCRETE\n       1       8    1001    1002\n"
                     "*AIRBAG_SIMPLE_AIRBAG_MODEL\n         1         1\n"
                     "*END\n";
  Read strict = read_text(deck);
  EXPECT_FALSE(strict.ok);
  // one 1301 per block; the summary line is printed but not counted (issue 25 defect 8)
  EXPECT_EQ(strict.count(1301), 4) << strict.messages();
  EXPECT_EQ(strict.d.error_count(), 4) << strict.messages();
  std::vector<int> lines;
  for (const auto& d : strict.d.all())
    if (d.id == 1301 && d.where.line > 0) lines.push_back(d.where.line);
  std::size_t base_lines = std::count(deck.begin(), deck.begin() + long(deck.find("*CONTROL_ADAPTIVE")), '\n');
  EXPECT_EQ(lines, (std::vector<int>{int(base_lines) + 1, int(base_lines) + 4, int(base_lines) + 10, int(base_lines) + 12}));
  std::string all = strict.messages();
  EXPECT_NE(all.find("*AIRBAG_SIMPLE_AIRBAG_MODEL"), std::string::npos);
  EXPECT_NE(all.find("*ELEMENT_DISCRETE"), std::string::npos);

  Read lenient = read_text(deck, true);
  EXPECT_TRUE(lenient.ok) << lenient.messages();
  EXPECT_EQ(lenient.count(2007), 4);
  EXPECT_EQ(lenient.count(2011), 1);  // the beam part is left out
  EXPECT_EQ(lenient.m.materials.size(), 1u);
}

TEST(KeywordUnsupported, PartWithUnsupportedMaterialIsAnErrorEvenWhenLenient) {
  std::string deck = prepost_deck();
  std::string mat = deck.substr(deck.find("*MAT_PLASTIC_KINEMATIC_TITLE"), deck.find("*SET_NODE_LIST") - deck.find("*MAT_PLASTIC_KINEMATIC_TITLE"));
  deck.replace(deck.find(mat), mat.size(), "*MAT_ORTHOTROPIC_ELASTIC\n        127.85000E-9  150000.0      0.34\n");
  Read r = read_text(deck, true);
  EXPECT_FALSE(r.ok);
  const Diagnostic* d = r.first(1103);
  ASSERT_NE(d, nullptr) << r.messages();
  EXPECT_EQ(d->where.field, "MID");
  EXPECT_NE(d->detail.find("*MAT_ORTHOTROPIC_ELASTIC"), std::string::npos);
}

// ---------------------------------------------------------------------------- errors

TEST(KeywordErrors, ReferencesAndFields) {
  std::string deck = prepost_deck();
  // element 501 node N7 1011 -> 1099 (undefined), a node set that does not exist, a bad real
  std::size_t p = deck.rfind("    1011    1010");
  deck.replace(p, 8, "    1099");
  std::string spc = "        20         0         0         1";
  deck.replace(deck.find(spc), spc.size(), "        21         0         0         1");
  std::string e = "  150000.0";
  deck.replace(deck.find(e), e.size(), "  150000.x");
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  const Diagnostic* d = r.first(1202);
  ASSERT_NE(d, nullptr) << r.messages();
  EXPECT_EQ(d->where.field, "N7");
  EXPECT_EQ(d->where.col_first, 49);
  EXPECT_EQ(d->where.col_last, 56);
  EXPECT_EQ(d->where.card, "*ELEMENT_SOLID element 501");
  EXPECT_EQ(r.count(1309), 1) << r.messages();
  const Diagnostic* b = r.first(1002);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->where.field, "E");
  EXPECT_EQ(b->where.col_first, 21);
  EXPECT_EQ(b->where.col_last, 30);
  // rendered with the file name and line
  EXPECT_NE(r.messages().find("deck.k:"), std::string::npos);
}

TEST(KeywordErrors, MissingTerminationAndUndefinedPart) {
  std::string deck = prepost_deck();
  std::size_t a = deck.find("*CONTROL_TERMINATION"), b = deck.find("*CONTROL_TIMESTEP");
  deck.erase(a, b - a);
  std::string el = "     501       7\n";
  deck.replace(deck.find(el), el.size(), "     501       8\n");
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.count(1311), 1) << r.messages();
  EXPECT_EQ(r.count(1308), 1) << r.messages();
}

TEST(KeywordRead, RotationalConstraintsWarn) {
  std::string deck = prepost_deck();
  std::string spc = "      1001         0         0         0         1         0         0         0";
  deck.replace(deck.find(spc), spc.size(), "      1001         0         0         0         1         1         0         0");
  Read r = read_text(deck);
  EXPECT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.count(2005), 1);
}

// ---------------------------------------------------------------------------- contact

TEST(KeywordContact, PartSurfacesAreExteriorFaces) {
  std::string deck = prepost_deck();
  deck.insert(deck.find("*END"),
              "*SET_PART_LIST\n        30\n         7\n"
              "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID\n$# cid title\n         1contact\n"
              "         7        30         3         2\n"
              "       0.2       0.1\n"
              "       1.0       1.0\n"
              "*CONTACT_NODES_TO_SURFACE\n"
              "         7         7         3         3\n");
  Read r = read_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  ASSERT_EQ(r.m.interfaces.size(), 2u);
  const SlidingInterface& si = r.m.interfaces[0];
  EXPECT_EQ(si.slave.size(), 10u);  // 2 hexes: 12 faces, 2 shared
  EXPECT_EQ(si.master.size(), 10u);
  EXPECT_TRUE(si.symmetric);
  EXPECT_EQ(si.fs, 0.2);
  EXPECT_EQ(si.fd, 0.1);
  EXPECT_EQ(si.penalty_scale, 0.0);
  EXPECT_FALSE(r.m.interfaces[1].symmetric);
}

// ---------------------------------------------------------------------------- round trips

TEST(KeywordRoundTrip, PrePostDeckThroughBothFormats) {
  Read a = read_text(prepost_deck());
  ASSERT_TRUE(a.ok) << a.messages();
  Read k = read_text(keyword_text(a.m));
  ASSERT_TRUE(k.ok) << k.messages();
  EXPECT_EQ(join(model_differences(a.m, k.m)), "");
  std::vector<std::string> notes;
  std::string fixed = fixed_text(a.m, &notes);
  ASSERT_EQ(notes.size(), 1u) << join(notes);  // the renumbering
  Read f = read_text(fixed, false, "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages();
  Model renumbered = a.m;
  renumbered.node_user_id.clear();
  renumbered.hex_user_id.clear();
  EXPECT_EQ(join(model_differences(renumbered, f.m)), "");
  // and back to keyword
  Read k2 = read_text(keyword_text(f.m));
  ASSERT_TRUE(k2.ok) << k2.messages();
  EXPECT_EQ(join(model_differences(f.m, k2.m)), "");
}

TEST(KeywordRoundTrip, ValuesThatDoNotFitAreWrittenFreeFormat) {
  Read a = read_text(prepost_deck());
  ASSERT_TRUE(a.ok);
  a.m.x[1] = 1.0 / 3.0;  // 17 digits do not fit E16
  a.m.materials[0].E = 2.0e11 / 3.0;
  std::string text = keyword_text(a.m);
  EXPECT_NE(text.find(",0.3333333333333333,"), std::string::npos);
  Read k = read_text(text);
  ASSERT_TRUE(k.ok) << k.messages();
  EXPECT_EQ(join(model_differences(a.m, k.m)), "");
}

class SeedDeck : public ::testing::TestWithParam<const char*> {};

TEST_P(SeedDeck, KeywordTwinGivesTheSameModel) {
  std::string name = GetParam();
  Read fixed = read_path(kSource + "/decks/" + name + ".dyn");
  ASSERT_TRUE(fixed.ok) << fixed.messages();
  Read kw = read_path(kSource + "/decks/keyword/" + name + ".k");
  ASSERT_TRUE(kw.ok) << kw.messages();
  EXPECT_EQ(kw.d.warning_count(), fixed.d.warning_count()) << kw.messages();
  EXPECT_EQ(join(model_differences(fixed.m, kw.m)), "");
}

TEST_P(SeedDeck, ShippedKeywordDeckIsWhatTheConverterWrites) {
  std::string name = GetParam();
  Read fixed = read_path(kSource + "/decks/" + name + ".dyn");
  ASSERT_TRUE(fixed.ok);
  std::ifstream in(kSource + "/decks/keyword/" + name + ".k", std::ios::binary);
  std::string shipped((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(keyword_text(fixed.m) == shipped) << "regenerate: impact3d i=decks/" << name
                                                << ".dyn --write-keyword=decks/keyword/" << name << ".k";
}

TEST_P(SeedDeck, RoundTripFixedKeywordFixed) {
  std::string name = GetParam();
  Read fixed = read_path(kSource + "/decks/" + name + ".dyn");
  ASSERT_TRUE(fixed.ok);
  std::vector<std::string> notes;
  std::string kw_text = keyword_text(fixed.m);
  Read kw = read_text(kw_text);
  ASSERT_TRUE(kw.ok) << kw.messages();
  std::string fx_text = fixed_text(kw.m, &notes);
  EXPECT_EQ(join(notes), "");
  Read fx = read_text(fx_text, false, name + ".dyn");
  ASSERT_TRUE(fx.ok) << fx.messages();
  EXPECT_EQ(join(model_differences(fixed.m, fx.m)), "");
  // the fixed deck written from the model reads back as the same model, and writes the same
  EXPECT_EQ(fixed_text(fx.m), fx_text);
}

INSTANTIATE_TEST_SUITE_P(Seeds, SeedDeck, ::testing::Values("taylor_bar", "oblique_rod", "crossed_cylinders"));

// ---------------------------------------------------------------------------- same run

TEST(KeywordRun, TaylorBarKeywordTwinRunsBitwiseTheSame) {
  Read fixed = read_path(kSource + "/decks/taylor_bar.dyn");
  Read kw = read_path(kSource + "/decks/keyword/taylor_bar.k");
  ASSERT_TRUE(fixed.ok && kw.ok);
  Engine a(fixed.m), b(kw.m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  for (int c = 0; c < 300; ++c) {
    ASSERT_EQ(a.step(), StepStatus::ok);
    ASSERT_EQ(b.step(), StepStatus::ok);
  }
  const State &sa = a.state(), &sb = b.state();
  EXPECT_EQ(sa.time, sb.time);
  EXPECT_TRUE(sa.x == sb.x && sa.y == sb.y && sa.z == sb.z);
  EXPECT_TRUE(sa.vx == sb.vx && sa.vy == sb.vy && sa.vz == sb.vz);
  EXPECT_TRUE(sa.sig == sb.sig && sa.eps_p == sb.eps_p);
}

// ---------------------------------------------------------------------------- real-world layout

// A deck laid out as pydyna's test deck mech.k (written by LS-PrePost): multi-card
// *CONTROL_CONTACT, bulk viscosity TYPE -2, ASCII databases with BINARY/IOOPT, *PART with a
// blank heading, a "$# cid title" comment line in a contact without _ID, *RIGIDWALL_PLANAR_ID
// with DEATH 0.0 and RWKSF 0.0 (defaults), abutting "0.01.000000E8", *SET_PART_LIST with SOLVER
// "MECH" and trailing zeros; plus shells and an airbag, which IMPACT-3D does not support.
TEST(KeywordRealWorld, MechStyleDeckIsRefusedWithTheList) {
  const std::string deck =
      "*KEYWORD\n"
      "*CONTROL_ACCURACY\n$#     osu       inn    pidosu      iacc     exacc\n         1         4         0         1       0.0\n"
      "*CONTROL_BULK_VISCOSITY\n$#      q1        q2      type     btype    tstype\n       1.5      0.06        -2         0         0\n"
      "*CONTROL_CONTACT\n$#  slsfac    rwpnal    islchk    shlthk    penopt    thkchg     orien    enmass\n"
      "       0.0       1.0         0         0         0         0         1         0\n"
      "$#  usrstr    usrfrc     nsbcs    interm     xpene     ssthk      ecdt   tiedprj\n"
      "         0         0         0         0       0.0         0         0         0\n"
      "*CONTROL_HOURGLASS\n$#     ihq        qh\n         2       0.0\n"
      "*CONTROL_TERMINATION\n$#  endtim    endcyc     dtmin    endeng    endmas     nosol\n"
      "      0.03         0       0.0       0.01.000000E8         0\n"
      "*DATABASE_GLSTAT\n$#      dt    binary      lcur     ioopt\n2.00000E-4         1         0         1\n"
      "*DATABASE_BINARY_D3PLOT\n$#      dt      lcdt      beam     npltc    psetid\n5.00000E-4         0         0         0         0\n"
      "*DATABASE_EXTENT_BINARY\n$#   neiph     neips    maxint    strflg\n         0         0         3         0\n"
      "*CONTACT_NODES_TO_SURFACE\n$#     cid                                                                 title\n"
      "$#   surfa     surfb  surfatyp  surfbtyp   saboxid   sbboxid      sapr      sbpr\n"
      "         3         2         3         3         0         0         0         0\n"
      "$#      fs        fd        dc        vc       vdc    penchk        bt        dt\n"
      "       0.5       0.5       0.0       0.0       0.0         0       0.0       0.0\n"
      "$#    sfsa      sfsb      sast      sbst     sfsat     sfsbt       fsf       vsf\n"
      "       1.0       1.0       0.0       0.0       1.0       1.0       1.0       1.0\n"
      "*PART\n$#                                                                         title\n\n"
      "$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid\n"
      "         1         0         0         0         0         0         0         0\n"
      "*RIGIDWALL_PLANAR_ID\n$#      id                                                                 title\n"
      "         1                                                                     \n"
      "$#    nsid    nsidex     boxid    offset     birth     death     rwksf\n"
      "         0         0         0       0.0       0.0       0.0       0.0\n"
      "$#      xt        yt        zt        xh        yh        zh      fric      wvel\n"
      "       0.0       0.0       0.0       0.0       1.0       0.0       0.5       0.0\n"
      "*DEFINE_CURVE\n$#    lcid      sidr       sfa       sfo      offa      offo    dattyp     lcint\n"
      "         1         0       1.0       1.0       0.0       0.0         0         0\n"
      "$#                a1                  o1\n                 0.0                 0.0\n               0.032                26.0\n"
      "*AIRBAG_SIMPLE_AIRBAG_MODEL\n$#     sid    sidtyp\n         1         1\n"
      "*SET_PART_LIST\n$#     sid       da1       da2       da3       da4    solver\n         1                                        MECH\n"
      "$#    pid1      pid2      pid3      pid4      pid5      pid6      pid7      pid8\n"
      "         3         0         0         0         0         0         0         0\n"
      "*ELEMENT_DISCRETE\n$#   eid     pid      n1      n2\n"
      "       1       1       1       3       4\n"
      "*NODE\n$#   nid               x               y               z      tc      rc\n"
      "       1             0.0             0.0             0.0       0       0\n"
      "       2            16.0             0.0             0.0       0       0\n"
      "*END\n";
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  std::vector<std::string> refused;
  for (const auto& d : r.d.all())
    if (d.id == 1301 && d.where.line > 0) refused.push_back(d.where.card);
  EXPECT_EQ(refused, (std::vector<std::string>{"*AIRBAG_SIMPLE_AIRBAG_MODEL", "*ELEMENT_DISCRETE"}))
      << r.messages();
  EXPECT_EQ(r.count(2008), 2) << r.messages();  // *CONTROL_ACCURACY, *DATABASE_EXTENT_BINARY: read, ignored
  // the supported keywords read without field errors
  EXPECT_EQ(r.count(1001) + r.count(1002) + r.count(1006), 0) << r.messages();
  EXPECT_EQ(r.m.control.end_time, 0.03);
  EXPECT_EQ(r.m.control.plot_interval, 5.0e-4);
  EXPECT_EQ(r.m.control.th_interval, 2.0e-4);
  EXPECT_EQ(r.m.control.penalty_scale, 0.1);  // SLSFAC 0.0 -> default
  ASSERT_EQ(r.m.walls.size(), 1u);
  EXPECT_EQ(r.m.walls[0].friction, 0.5);
  ASSERT_EQ(r.m.load_curves.size(), 1u);
  EXPECT_EQ(r.m.load_curves[0].t[1], 0.032);
  EXPECT_EQ(r.count(1311), 1);  // no solid elements
  EXPECT_EQ(r.count(2011), 1);  // the beam part
}

// ---------------------------------------------------------------------------- refusals

namespace {
std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}
std::size_t lines_with(const std::string& text, const std::string& what) {
  std::size_t n = 0, p = 0;
  while ((p = text.find(what, p)) != std::string::npos) ++n, p += what.size();
  return n;
}
}  // namespace

TEST(KeywordRead, D3thdtIntervalIsTheTimeHistoryInterval) {
  // *DATABASE_BINARY_D3THDT DT sets the one time-history interval (d3thdt and the ASCII
  // tables), ahead of *DATABASE_GLSTAT's; LCDT asks for a curve-driven interval: 1102
  const std::string base = prepost_deck();
  Read r = read_text(replaced(base, "*DATABASE_GLSTAT\n", "*DATABASE_BINARY_D3THDT\n$#      dt      lcdt\n   2.5E-7\n*DATABASE_GLSTAT\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.m.control.th_interval, 2.5e-7);
  EXPECT_EQ(r.count(1301) + r.count(2008), 0) << r.messages();
  Read lc = read_text(replaced(base, "*DATABASE_GLSTAT\n", "*DATABASE_BINARY_D3THDT\n   2.5E-7         3\n*DATABASE_GLSTAT\n"));
  EXPECT_FALSE(lc.ok);
  ASSERT_EQ(lc.count(1102), 1) << lc.messages();
  EXPECT_EQ(lc.first(1102)->where.card, "*DATABASE_BINARY_D3THDT card 1");
  Read neg = read_text(replaced(base, "*DATABASE_GLSTAT\n", "*DATABASE_BINARY_D3THDT\n  -2.5E-7\n*DATABASE_GLSTAT\n"));
  EXPECT_FALSE(neg.ok);
  EXPECT_EQ(neg.count(1221), 1) << neg.messages();
}

TEST(KeywordRefusals, MessagesAreNeverDroppedOnALargeRefusedDeck) {
  // 1500 bad *NODE cards, an unsupported keyword after them and no elements: every kind of
  // error and the required-keyword message appear, with the count of all errors
  std::string deck = "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*NODE\n";
  for (int k = 0; k < 1500; ++k) deck += "     " + std::to_string(k + 1) + "x           0.0             0.0             0.0\n";
  deck += "*ELEMENT_DISCRETE\n       1       1       1       2\n*END\n";
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  const std::string out = r.messages();
  EXPECT_NE(out.find("error 1311: required keyword missing: *ELEMENT_SOLID"), std::string::npos) << out.substr(out.size() - 2000);
  EXPECT_NE(out.find("error 1301: keyword not supported by IMPACT-3D (impact3d --lenient-keywords turns this into a warning): 1 keyword block(s): *ELEMENT_DISCRETE"),
            std::string::npos);
  EXPECT_EQ(out.find("not shown)"), std::string::npos);
  EXPECT_GE(r.d.error_count(), 1502);
  EXPECT_LT(std::count(out.begin(), out.end(), '\n'), 300);  // bounded: one number, one summary line past 200
}

TEST(KeywordRefusals, RepeatsOfOneCauseAreOneLineNamingTheRefusedKeyword) {
  // 400 solids of a part that only a refused keyword (*PART_COMPOSITE) defines
  std::string deck = prepost_deck();
  std::string extra = "*PART_COMPOSITE\nshell part\n        99         2\n*ELEMENT_SOLID\n";
  for (int k = 0; k < 400; ++k) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%8d%8d\n%8d%8d%8d%8d%8d%8d%8d%8d\n", 9000 + k, 99, nid(0, 0, 0), nid(1, 0, 0),
                  nid(1, 1, 0), nid(0, 1, 0), nid(0, 0, 1), nid(1, 0, 1), nid(1, 1, 1), nid(0, 1, 1));
    extra += buf;
  }
  deck = replaced(deck, "*END\n", extra + "*END\n");
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.count(1308), 400);
  const std::string out = r.messages();
  EXPECT_EQ(lines_with(out, "error 1308"), 1u) << out;
  EXPECT_NE(out.find("part 99 is not defined by *PART (it is defined by *PART_COMPOSITE at deck.k:"), std::string::npos) << out;
  EXPECT_NE(out.find("(400 times; also 9001, 9002, 9003, 9004, 9005, 9006, 9007, 9008, 9009, 9010, ...)"), std::string::npos) << out;
}

TEST(KeywordRefusals, ReferenceToASetOfARefusedKeywordNamesItAndTheExactVariant) {
  std::string deck = replaced(prepost_deck(), "*SET_NODE_LIST\n", "*SET_NODE_INTERSECT\n");
  Read r = read_text(deck);
  EXPECT_FALSE(r.ok);
  const std::string out = r.messages();
  EXPECT_NE(out.find("*RIGIDWALL_PLANAR_ID, field \"NSID\" (cols 1-10): reference to an undefined set: *SET_NODE_LIST 20 is not defined "
                     "(it is defined by *SET_NODE_INTERSECT at deck.k:"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("*BOUNDARY_SPC_SET, field \"NSID\""), std::string::npos) << out;
  EXPECT_NE(out.find("1 keyword block(s): *SET_NODE_INTERSECT"), std::string::npos) << out;
}

TEST(KeywordRefusals, ValidLsDynaChoicesNotImplementedAreNotSupported) {
  Read a = read_text(replaced(prepost_deck(), "         4      0.05\n", "         6      0.05\n"));
  EXPECT_FALSE(a.ok);
  EXPECT_EQ(a.count(1006), 0) << a.messages();
  ASSERT_EQ(a.count(1102), 1) << a.messages();
  EXPECT_EQ(a.first(1102)->where.field, "IHQ");
  Read b = read_text(replaced(prepost_deck(), "         4      0.05\n", "        11      0.05\n"));
  EXPECT_EQ(b.count(1006), 1) << b.messages();  // not an LS-DYNA type either
  std::string deck = replaced(prepost_deck(), "*END\n",
                              "*HOURGLASS\n         5         8       0.1\n*END\n");
  Read c = read_text(deck);
  EXPECT_EQ(c.count(1006), 0) << c.messages();
  EXPECT_EQ(c.count(1102), 1) << c.messages();
}

TEST(KeywordRefusals, CaseVariantsOtherThanBeginEndStayRefusedWhenLenient) {
  // *CASE_BEGIN_n / *CASE_END_n are read (tests/keyword/test_keyword_sets.cpp); another *CASE_
  // keyword would change which cards apply, so it stays an error with --lenient-keywords
  Read lenient = read_text(replaced(prepost_deck(), "*END\n", "*CASE_OTHER\n         0\n*END\n"), true);
  EXPECT_FALSE(lenient.ok) << lenient.messages();
  EXPECT_EQ(lenient.count(1301), 1) << lenient.messages();
  EXPECT_NE(lenient.messages().find("refused even with --lenient-keywords"), std::string::npos) << lenient.messages();
  // other unsupported keywords are still only warnings with --lenient-keywords
  Read other = read_text(replaced(prepost_deck(), "*END\n", "*CONTROL_ADAPTIVE\n         0\n*END\n"), true);
  EXPECT_TRUE(other.ok) << other.messages();
  EXPECT_EQ(other.count(2007), 1);
}

TEST(KeywordRefusals, RigidBodyWithNodalVelocitiesThatAreNotARigidMotionWarns) {
  std::string deck = replaced(prepost_deck(), "*MAT_PLASTIC_KINEMATIC_TITLE\nsteel\n", "*MAT_RIGID_TITLE\nball\n");
  deck = replaced(deck, "        127.85000E-9  150000.0      0.34     390.0      90.0       0.0\n",
                  "        127.85000E-9  150000.0      0.34\n");
  deck = replaced(deck, "$#     src       srp        fs        vp  \n       0.0       0.0       0.0       0.0\n",
                  "       0.0       0.0       0.0\n");
  Read rigid = read_text(deck);
  EXPECT_EQ(rigid.count(2014), 0) << rigid.messages();
  Read moved = read_text(replaced(deck, "*END\n", "*INITIAL_VELOCITY_NODE\n    1001     100.0       0.0       0.0\n*END\n"));
  EXPECT_EQ(moved.count(2014), 1) << moved.messages();
}

// Control and output keywords that change nothing here are read and listed as ignored (2008),
// once each, with their lines; *CONTROL_SOLUTION with a thermal SOLN is refused (1102).
TEST(KeywordIgnored, ControlCardsThatChangeNothingAreReadAndListed) {
  const std::string extra =
      "*CONTROL_PARALLEL\n         2         0         1\n"
      "*CONTROL_ACCURACY\n         1         4\n"
      "*CONTROL_SOLID\n         1\n"
      "*CONTROL_SOLUTION\n         0\n"
      "*DATABASE_FORMAT\n         0         0\n"
      "*CONTROL_MPP_IO_NODUMP\n"
      "*CONTROL_CPU\n     100.0         0\n"
      "*CONTROL_UNITS\n        mm        ms        kg\n"
      "*DATABASE_NODAL_FORCE_GROUP\n         1         0\n"
      "*END\n";
  Read r = read_text(replaced(prepost_deck(), "*END\n", extra));
  EXPECT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.count(2008), 9) << r.messages();
  for (const char* kw : {"*CONTROL_PARALLEL", "*CONTROL_ACCURACY", "*CONTROL_SOLID", "*CONTROL_SOLUTION",
                         "*DATABASE_FORMAT", "*CONTROL_MPP_IO_NODUMP", "*CONTROL_CPU", "*CONTROL_UNITS",
                         "*DATABASE_NODAL_FORCE_GROUP"})
    EXPECT_NE(r.messages().find(kw), std::string::npos) << kw << "\n" << r.messages();
  // they change nothing: the same model runs to the same bits with them and without
  Read plain = read_text(prepost_deck());
  ASSERT_TRUE(plain.ok) << plain.messages();
  Engine with(r.m), without(plain.m);
  ASSERT_EQ(with.initialize(), StepStatus::ok);
  ASSERT_EQ(without.initialize(), StepStatus::ok);
  for (int c = 0; c < 20; ++c) {
    ASSERT_EQ(with.step(), without.step());
  }
  EXPECT_EQ(with.state().kinetic, without.state().kinetic);
  EXPECT_EQ(with.state().internal, without.state().internal);
  EXPECT_EQ(with.state().x, without.state().x);
  Read thermal = read_text(replaced(prepost_deck(), "*END\n", "*CONTROL_SOLUTION\n         2\n*END\n"));
  EXPECT_FALSE(thermal.ok);
  EXPECT_EQ(thermal.count(1102), 1) << thermal.messages();
}

// *CONTROL_TERMINATION ENDCYC: the run stops after that many cycles (normal termination), before
// ENDTIM; the converter writes it back (keyword) or says the fixed format cannot hold it.
TEST(KeywordTermination, EndCycleStopsTheRunAndRoundTrips) {
  const std::string end0 = "   8.0E-05         0       0.0       0.01.000000E8         0\n";
  std::string deck = prepost_deck();
  ASSERT_NE(deck.find(end0), std::string::npos);
  deck.replace(deck.find(end0), end0.size(), "   8.0E-05        25       0.0       0.01.000000E8         0\n");
  Read r = read_text(deck);
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.m.control.end_cycle, 25);
  Engine eng(r.m);
  StepStatus st = eng.run_to_end();
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_EQ(eng.state().cycle, 25);
  EXPECT_LT(eng.state().time, r.m.control.end_time);
  Read back = read_text(keyword_text(r.m));
  ASSERT_TRUE(back.ok) << back.messages();
  EXPECT_EQ(back.m.control.end_cycle, 25);
  std::vector<std::string> notes;
  fixed_text(r.m, &notes);
  EXPECT_NE(join(notes).find("ENDCYC 25"), std::string::npos) << join(notes);
  std::string bad = deck;
  bad.replace(bad.find("        25       0.0"), 10, "        -1");
  Read neg = read_text(bad);
  EXPECT_FALSE(neg.ok);
  EXPECT_EQ(neg.count(1003), 1) << neg.messages();
}

namespace {
// One tetrahedron (node 4 above the triangle 1-2-3) written as `elem`, an *ELEMENT_SOLID card.
std::string tet_deck(const std::string& elem) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n   1.0e-06\n*NODE\n"
         "       1             0.0             0.0             0.0\n"
         "       2           0.002             0.0             0.0\n"
         "       3             0.0           0.002             0.0\n"
         "       4             0.0             0.0           0.002\n"
         "*PART\ntet\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
         "*MAT_ELASTIC\n         1    7850.0   2.0e+11       0.3\n*ELEMENT_SOLID\n" + elem + "*END\n";
}
}  // namespace

// A 4-node tetrahedron written by LS-PrePost with N5-N8 blank reads as LS-DYNA's degenerate
// hexahedron N1 N2 N3 N4 N4 N4 N4 N4 (the same Model as the card that repeats N4), one-line and
// two-line forms; the element's volume is the tetrahedron's, L^3/6.
TEST(KeywordElements, TetrahedronWithBlankN5ToN8IsTheDegenerateHexahedron) {
  const Read repeated = read_text(tet_deck("       1       1       1       2       3       4       4       4       4       4\n"));
  ASSERT_TRUE(repeated.ok) << repeated.messages();
  for (const std::string& blank : {std::string("       1       1       1       2       3       4\n"),
                                   std::string("       1       1\n       1       2       3       4\n")}) {
    const Read r = read_text(tet_deck(blank));
    ASSERT_TRUE(r.ok) << r.messages();
    ASSERT_EQ(r.m.num_hexes(), 1);
    EXPECT_EQ(r.m.hex_nodes[0], repeated.m.hex_nodes[0]);
    Engine e(r.m);
    ASSERT_EQ(e.initialize(), StepStatus::ok);
    EXPECT_NEAR(e.state().vol0[0], 0.002 * 0.002 * 0.002 / 6, 1e-12 * 0.002 * 0.002 * 0.002);
  }
}
