// *MAT_RIGID constraints (CMO, CON1, CON2; fixed format cards 5-7 of type 20): a rigid cube
// thrown with a translation and a spin keeps exactly the free components of its motion, the
// constrained ones stay zero from the start; CMO = -1 in a local system whose axes are global
// axes maps onto global codes; the refusals (skew systems, bad codes, CMO = -1 in the fixed
// format); the converter round trip.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/solve/engine.h"
#include "../support/deck_text.h"

using namespace impact3d;

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& name, const std::string& text) { return test_support::read_deck_text(text, name); }

// A rigid steel cube of 0.1 m (2 x 2 x 2 solids, nodes id 1 + ix + 3 iy + 9 iz) thrown at
// (3, 4, 5) m/s spinning at 10 rad/s about the vertical axis through its centre; card 2 of
// *MAT_RIGID is `card2`; `extra` adds keywords.
std::string cube_deck(const std::string& card2, const std::string& extra = "") {
  std::string s =
      "*KEYWORD\n*TITLE\nrigid cube with constraints\n*CONTROL_TERMINATION\n   2.0E-03\n"
      "*PART\nrigid cube\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
      "*MAT_RIGID\n$#     mid        ro         e        pr\n         1    7800.0   2.0E+11       0.3\n"
      "$#     cmo      con1      con2\n" + card2 + "\n\n*NODE\n";
  char buf[128];
  for (int iz = 0; iz < 3; ++iz)
    for (int iy = 0; iy < 3; ++iy)
      for (int ix = 0; ix < 3; ++ix) {
        std::snprintf(buf, sizeof buf, "%8d%16.4f%16.4f%16.4f\n", 1 + ix + 3 * iy + 9 * iz, 0.05 * ix, 0.05 * iy, 0.05 * iz);
        s += buf;
      }
  s += "*ELEMENT_SOLID\n";
  int e = 1;
  for (int iz = 0; iz < 2; ++iz)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 2; ++ix) {
        auto n = [&](int i, int j, int k) { return 1 + (ix + i) + 3 * (iy + j) + 9 * (iz + k); };
        std::snprintf(buf, sizeof buf, "%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", e++, 1, n(0, 0, 0), n(1, 0, 0), n(1, 1, 0),
                      n(0, 1, 0), n(0, 0, 1), n(1, 0, 1), n(1, 1, 1), n(0, 1, 1));
        s += buf;
      }
  s += "*INITIAL_VELOCITY_GENERATION\n"
       "$#     pid      styp     omega        vx        vy        vz     ivatn      icid\n"
       "         1         2      10.0       3.0       4.0       5.0         0         0\n"
       "$#      xc        yc        zc        nx        ny        nz     phase    irigid\n"
       "      0.05      0.05      0.05       0.0       0.0       1.0         0         0\n";
  return s + extra + "*END\n";
}

struct Motion {
  std::array<double, 3> com_shift{}, vcom{}, omega{};
  double turn = 0;        // angle turned about z (from node 1's position about the centre)
  double max_z_err = 0;   // largest |z - (z0 + 5 t)| of the nodes
  double energy_ratio = 0;
};

Motion run(const Model& m) {
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = e.step();
  EXPECT_EQ(st, StepStatus::finished);
  const State& s = e.state();
  Motion out;
  const RigidBody& rb = s.rigid.at(0);
  for (int a = 0; a < 3; ++a) {
    out.com_shift[std::size_t(a)] = rb.com[std::size_t(a)] - rb.com0[std::size_t(a)];
    out.vcom[std::size_t(a)] = rb.vcom[std::size_t(a)];
    out.omega[std::size_t(a)] = rb.omega[std::size_t(a)];
  }
  // node 1 starts at (-0.05, -0.05) from the axis: its angle about z now
  const double rx = s.x[0] - rb.com[0], ry = s.y[0] - rb.com[1];
  out.turn = std::atan2(ry, rx) - std::atan2(-0.05, -0.05);
  for (int n = 0; n < s.nn; ++n)
    out.max_z_err = std::max(out.max_z_err, std::fabs(s.z[std::size_t(n)] - (m.z[std::size_t(n)] + 5.0 * s.time)));
  out.energy_ratio = s.energy_ratio();
  return out;
}

}  // namespace

// CMO 1, CON1 4 (x and y), CON2 3 (z rotation): the cube only rises, at 5 m/s, without turning;
// x, y and the spin are zero from the start (the kinetic energy is the rising cube's).
TEST(RigidConstraints, GlobalCodesHoldTranslationsAndRotations) {
  Read r = read_text("cube.k", cube_deck("         1         4         3"));
  ASSERT_TRUE(r.ok) << r.messages();
  Motion mo = run(r.m);
  EXPECT_EQ(mo.com_shift[0], 0.0);
  EXPECT_EQ(mo.com_shift[1], 0.0);
  EXPECT_NEAR(mo.com_shift[2], 5.0 * 2e-3, 1e-12);
  EXPECT_EQ(mo.omega[2], 0.0);
  EXPECT_NEAR(mo.turn, 0.0, 1e-15);
  EXPECT_LT(mo.max_z_err, 1e-12);
  EXPECT_NEAR(mo.energy_ratio, 1.0, 1e-12);
  // the same cube without constraints translates at (3, 4, 5) and turns 10 t about z
  Read free = read_text("cube.k", cube_deck("         0         0         0"));
  ASSERT_TRUE(free.ok) << free.messages();
  Motion fm = run(free.m);
  EXPECT_NEAR(fm.com_shift[0], 3.0 * 2e-3, 1e-12);
  EXPECT_NEAR(fm.com_shift[1], 4.0 * 2e-3, 1e-12);
  EXPECT_NEAR(fm.turn, 10.0 * 2e-3, 1e-9);
  // CON2 1 (x rotation only): the spin about z is free and kept
  Read xrot = read_text("cube.k", cube_deck("         1         0         1"));
  ASSERT_TRUE(xrot.ok) << xrot.messages();
  Motion xm = run(xrot.m);
  EXPECT_NEAR(xm.omega[2], 10.0, 1e-9);
  EXPECT_EQ(xm.omega[0], 0.0);
  EXPECT_NEAR(xm.turn, 10.0 * 2e-3, 1e-9);
  EXPECT_NEAR(xm.com_shift[0], 3.0 * 2e-3, 1e-12);
}

// CMO -1: CON1 names a system, CON2 six digits in it.  A system turned 90 degrees about z (local
// x = global y) with 100000 fixes the global y translation; 000001 (local z rotation) the spin.
TEST(RigidConstraints, LocalSystemWithGlobalAxesMapsOntoGlobalCodes) {
  const std::string cs =
      "*DEFINE_COORDINATE_SYSTEM\n$#     cid        xo        yo        zo        xl        yl        zl\n"
      "         7       0.0       0.0       0.0       0.0       1.0       0.0\n"
      "$#      xp        yp        zp\n      -1.0       0.0       0.0\n";
  Read r = read_text("cube.k", cube_deck("        -1         7    100001", cs));
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_EQ(r.m.materials[0].par[3], 1.0);
  EXPECT_EQ(r.m.materials[0].par[4], 2.0);  // global y
  EXPECT_EQ(r.m.materials[0].par[5], 3.0);  // global z rotation
  Motion mo = run(r.m);
  EXPECT_NEAR(mo.com_shift[0], 3.0 * 2e-3, 1e-12);
  EXPECT_EQ(mo.com_shift[1], 0.0);
  EXPECT_NEAR(mo.com_shift[2], 5.0 * 2e-3, 1e-12);
  EXPECT_EQ(mo.omega[2], 0.0);
  // a skew system is refused unless it fixes all or none; so are bad codes
  const std::string skew =
      "*DEFINE_COORDINATE_SYSTEM\n         8       0.0       0.0       0.0       1.0       1.0       0.0\n"
      "      -1.0       1.0       0.0\n";
  Read bad = read_text("cube.k", cube_deck("        -1         8    100000", skew));
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.messages().find("error 1102"), std::string::npos) << bad.messages();
  EXPECT_NE(bad.messages().find("skew local axes"), std::string::npos) << bad.messages();
  Read all = read_text("cube.k", cube_deck("        -1         8    111000", skew));
  ASSERT_TRUE(all.ok) << all.messages();
  EXPECT_EQ(all.m.materials[0].par[4], 7.0);
  for (const char* c : {"         2         0         0", "         1         8         0", "         1         0        -1",
                        "        -1         7    100201"}) {
    Read b = read_text("cube.k", cube_deck(c, cs));
    EXPECT_FALSE(b.ok) << c;
    EXPECT_NE(b.messages().find("error 1006"), std::string::npos) << c << "\n" << b.messages();
  }
  Read undefined = read_text("cube.k", cube_deck("        -1         9    100000"));
  EXPECT_FALSE(undefined.ok);
  EXPECT_NE(undefined.messages().find("error 1310"), std::string::npos) << undefined.messages();
}

// The converter writes the constraints in both formats (fixed: cards 5-7 of the type 20 set) and
// reads them back as the same model; CMO = -1 in a fixed-format deck is refused by name.
TEST(RigidConstraints, ConverterRoundTripAndFixedFormatRefusal) {
  std::string deck = cube_deck("         1         4         3");
  deck.replace(deck.find("      10.0       3.0"), 10, "       0.0");  // no spin: the fixed format has no rotational velocities
  Read r = read_text("cube.k", deck);
  ASSERT_TRUE(r.ok) << r.messages();
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/rigid_constraints.dyn";
  const std::string kw = std::string(IMPACT3D_BINARY_DIR) + "/rigid_constraints.k";
  std::ostringstream log;
  ASSERT_EQ(write_converted_decks(r.m, kw, fixed, log), exit_code::ok) << log.str();
  for (const std::string& path : {fixed, kw}) {
    Read b;
    DeckFile deck;
    ASSERT_TRUE(deck.load(path, b.d));
    InputOptions o;
    b.ok = read_deck(deck, b.m, b.d, o) && check_model(b.m, b.d);
    ASSERT_TRUE(b.ok) << path << "\n" << b.messages();
    std::string diff;
    for (const auto& l : model_differences(r.m, b.m)) diff += l + "\n";
    EXPECT_EQ(diff, "") << path;
    EXPECT_EQ(b.m.materials[0].par[5], 3.0) << path;
  }
  // the fixed deck with CMO -1 on card 5
  std::ifstream in(fixed);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::size_t title = 0;
  while (title < lines.size() && lines[title].rfind("*----- MATERIALS", 0) != 0) ++title;
  while (title < lines.size() && lines[title].rfind("rigid cube", 0) != 0) ++title;
  ASSERT_LT(title + 3, lines.size());
  lines[title + 3] = "      -1.0";
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  Read bad = read_text("cube.dyn", text);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.messages().find("CMO = -1"), std::string::npos) << bad.messages();
}
