// Material keywords through the table of material types: *MAT_PIECEWISE_LINEAR_PLASTICITY read
// (table, LCSS curve mapped to its number), checked, echoed, and through the converter both
// ways; an unknown fixed-format type refused.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/material/material_types.h"
#include "impact3d/output/printed_output.h"
#include "../support/deck_text.h"

using namespace impact3d;

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& text, const std::string& name = "deck.k") { return test_support::read_deck_text(text, name); }

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// One unit hexahedron of part 1 with material 7 (the given *MAT keyword and its cards).
std::string one_hex_deck(const std::string& mat) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n   1.0E-05\n*DATABASE_BINARY_D3PLOT\n    5.0E-7\n"
         "*PART\nblock\n         1         1         7\n"
         "*SECTION_SOLID\n         1         1\n" +
         mat +
         "*DEFINE_CURVE\n        33\n                 0.0               250.0\n"
         "                 0.1               300.0\n                 1.0               400.0\n"
         "*NODE\n"
         "       1             0.0             0.0             0.0\n"
         "       2             1.0             0.0             0.0\n"
         "       3             1.0             1.0             0.0\n"
         "       4             0.0             1.0             0.0\n"
         "       5             0.0             0.0             1.0\n"
         "       6             1.0             0.0             1.0\n"
         "       7             1.0             1.0             1.0\n"
         "       8             0.0             1.0             1.0\n"
         "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7       8\n"
         "*END\n";
}

const std::string kMat24 =
    "*MAT_PIECEWISE_LINEAR_PLASTICITY_TITLE\nsteel\n"
    "$#     mid        ro         e        pr      sigy      etan      fail      tdel\n"
    "         7    7.8E-9  200000.0       0.3     250.0       0.0       0.8     1e-12\n"
    "$#       c         p      lcss      lcsr        vp\n"
    "      40.0       5.0         0         0       0.0\n"
    "       0.0      0.01      0.05       0.2\n"
    "     250.0     300.0     350.0     380.0\n";

double par(const Model& m, const char* key) {
  return param_value(m.materials[0], *find_param(material_type(24), key));
}

}  // namespace

TEST(KeywordMaterials, PiecewiseLinearTableIsReadCheckedAndRoundTrips) {
  Read a = read_text(one_hex_deck(kMat24));
  ASSERT_TRUE(a.ok) << a.messages();
  const MaterialData& md = a.m.materials[0];
  EXPECT_EQ(md.type, 24);
  EXPECT_EQ(md.E, 200000.0);
  EXPECT_EQ(md.fail_strain, 0.8);
  EXPECT_EQ(md.rate_c, 40.0);
  EXPECT_EQ(md.rate_p, 5.0);
  EXPECT_EQ(par(a.m, "TDEL"), 1e-12);
  EXPECT_EQ(par(a.m, "EPS3"), 0.05);
  EXPECT_EQ(par(a.m, "ES4"), 380.0);
  EXPECT_EQ(a.d.count(2004), 1) << a.messages();  // the curve no material uses
  // the printed echo names the table points
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("piecewise-linear plasticity (type 24)"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("flow stress point 4 "), std::string::npos) << echo.str();
  // keyword -> keyword, keyword -> fixed -> keyword: the same model
  std::ostringstream kw, fx;
  write_keyword_deck(kw, a.m);
  Read k = read_text(kw.str());
  ASSERT_TRUE(k.ok) << k.messages() << kw.str();
  EXPECT_EQ(join(model_differences(a.m, k.m)), "");
  write_fixed_deck(fx, a.m, nullptr);
  Read f = read_text(fx.str(), "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages() << fx.str();
  EXPECT_EQ(join(model_differences(a.m, f.m)), "") << fx.str();
}

TEST(KeywordMaterials, PiecewiseLinearCurveIsMappedAndChecked) {
  std::string deck = one_hex_deck(kMat24);
  deck.replace(deck.find("         0         0       0.0\n"), 31, "        33         0       0.0\n");
  Read a = read_text(deck);
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(par(a.m, "LCSS"), 1.0);  // curve 33 is the deck's first curve: number 1
  EXPECT_EQ(a.d.count(2004), 0) << a.messages();  // the curve is used
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  Read f = read_text(fx.str(), "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages() << fx.str();
  EXPECT_EQ(join(model_differences(a.m, f.m)), "");
  EXPECT_EQ(f.d.count(2004), 0) << f.messages();
  // an undefined curve (LCSS and LCSR), VP = 2 and a decreasing table: errors naming the fields
  std::string bad = one_hex_deck(kMat24);
  bad.replace(bad.find("         0         0       0.0\n"), 31, "        34        12       2.0\n");
  bad.replace(bad.find("     250.0     300.0     350.0     380.0"), 40, "     250.0     300.0     290.0     380.0");
  Read b = read_text(bad);
  EXPECT_FALSE(b.ok);
  const std::string msg = b.messages();
  EXPECT_NE(msg.find("LCSS"), std::string::npos) << msg;
  EXPECT_NE(msg.find("LCSR"), std::string::npos) << msg;
  EXPECT_NE(msg.find("VP"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ES3"), std::string::npos) << msg;
  EXPECT_EQ(b.d.count(1102), 1) << msg;  // VP = 2
}

// Rate effects: LCSR names a curve (rate -> factor; mapped to its number), VP = 1 the
// viscoplastic form; C and P beside LCSR draw warning 2006; echo and converter both ways.
TEST(KeywordMaterials, PiecewiseLinearRateCurveAndViscoplasticRoundTrip) {
  std::string deck = one_hex_deck(kMat24);
  deck.replace(deck.find("         0         0       0.0\n"), 31, "         0        33       1.0\n");
  Read a = read_text(deck);
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(par(a.m, "LCSR"), 1.0);
  EXPECT_EQ(par(a.m, "VP"), 1.0);
  EXPECT_EQ(a.d.count(2004), 0) << a.messages();  // the curve is used
  EXPECT_EQ(a.d.count(2006), 1) << a.messages();  // C and P are not used
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("load curve 1 (rate -> factor)"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("plastic strain rate (VP = 1, viscoplastic)"), std::string::npos) << echo.str();
  std::ostringstream kw, fx;
  write_keyword_deck(kw, a.m);
  Read k = read_text(kw.str());
  ASSERT_TRUE(k.ok) << k.messages() << kw.str();
  EXPECT_EQ(join(model_differences(a.m, k.m)), "");
  write_fixed_deck(fx, a.m, nullptr);
  Read f = read_text(fx.str(), "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages() << fx.str();
  EXPECT_EQ(join(model_differences(a.m, f.m)), "") << fx.str();
  EXPECT_EQ(par(f.m, "LCSR"), 1.0);
  EXPECT_EQ(par(f.m, "VP"), 1.0);
}

// A fixed-format deck with a type the table does not have: error 1103 listing the types.
TEST(KeywordMaterials, UnknownFixedFormatTypeIsRefused) {
  Read a = read_text(one_hex_deck(kMat24));
  ASSERT_TRUE(a.ok);
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  std::string text = fx.str();
  const std::size_t at = text.find("\n    1   24");  // material card 1: number, type
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 6, 5, "   22");
  Read f = read_text(text, "deck.dyn");
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.d.count(1103), 1) << f.messages();
  EXPECT_NE(f.messages().find("24 piecewise-linear plasticity"), std::string::npos) << f.messages();
}

// *MAT_JOHNSON_COOK (OFHC copper, Johnson and Cook 1985, in mm, t, s, MPa) and
// *MAT_SIMPLIFIED_JOHNSON_COOK: read into the table's places, and the same model after the
// converter both ways.
TEST(KeywordMaterials, JohnsonCookTypesAreReadAndRoundTrip) {
  const std::string jc =
      "*MAT_JOHNSON_COOK\n"
      "$#     mid        ro         g         e        pr       dtf        vp    rateop\n"
      "         7   8.96E-9   46000.0  124000.0      0.34       0.0       0.0       0.0\n"
      "$#       a         b         n         c         m        tm        tr      epso\n"
      "      90.0     292.0      0.31     0.025      1.09    1356.0     293.0       1.0\n"
      "$#      cp        pc     spall        it        d1        d2        d3        d4\n"
      "   383.0E6   -1000.0       1.0       0.0      0.54      4.89     -3.03     0.014\n"
      "$#      d5      c2/p      erod     efmin    numint\n"
      "      1.12       0.0       0.0       0.0       0.0\n";
  const std::string sjc =
      "*MAT_SIMPLIFIED_JOHNSON_COOK\n"
      "         7   8.96E-9  124000.0      0.34       0.0\n"
      "      90.0     292.0      0.31     0.025       2.0     600.0       0.0       1.0\n";
  for (const std::string& mat : {jc, sjc}) {
    Read a = read_text(one_hex_deck(mat));
    ASSERT_TRUE(a.ok) << a.messages();
    const MaterialData& md = a.m.materials[0];
    const MaterialType& t = material_type(md.type);
    EXPECT_EQ(param_value(md, *find_param(t, "B")), 292.0);
    EXPECT_EQ(param_value(md, *find_param(t, "EPSO")), 1.0);
    if (md.type == 15) {
      EXPECT_EQ(param_value(md, *find_param(t, "G")), 46000.0);
      EXPECT_EQ(param_value(md, *find_param(t, "D3")), -3.03);
      EXPECT_EQ(param_value(md, *find_param(t, "D5")), 1.12);
    } else {
      EXPECT_EQ(md.type, 98);
      EXPECT_EQ(md.fail_strain, 2.0);
      EXPECT_EQ(param_value(md, *find_param(t, "SIGMAX")), 600.0);
      EXPECT_EQ(param_value(md, *find_param(t, "SIGSAT")), 1e28);  // 0: none
    }
    std::ostringstream kw, fx;
    write_keyword_deck(kw, a.m);
    Read k = read_text(kw.str());
    ASSERT_TRUE(k.ok) << k.messages() << kw.str();
    EXPECT_EQ(join(model_differences(a.m, k.m)), "");
    write_fixed_deck(fx, a.m, nullptr);
    Read f = read_text(fx.str(), "deck.dyn");
    ASSERT_TRUE(f.ok) << f.messages() << fx.str();
    EXPECT_EQ(join(model_differences(a.m, f.m)), "") << fx.str();
  }
  // spall type 3, VP = 1, RATEOP = 1 with C2, EROD = 1: read, and the same after both converters
  std::string opt = jc;
  opt.replace(opt.find("       1.0       0.0      0.54"), 10, "       3.0");
  opt.replace(opt.find("      0.34       0.0       0.0       0.0\n"), 41, "      0.34       0.0       1.0       1.0\n");
  opt.replace(opt.find("      1.12       0.0       0.0"), 30, "      1.12     0.002       1.0");
  Read o = read_text(one_hex_deck(opt));
  ASSERT_TRUE(o.ok) << o.messages();
  {
    const MaterialData& md = o.m.materials[0];
    const MaterialType& t = material_type(15);
    EXPECT_EQ(param_value(md, *find_param(t, "SPALL")), 3.0);
    EXPECT_EQ(param_value(md, *find_param(t, "VP")), 1.0);
    EXPECT_EQ(param_value(md, *find_param(t, "RATEOP")), 1.0);
    EXPECT_EQ(param_value(md, *find_param(t, "C2/P")), 0.002);
    EXPECT_EQ(param_value(md, *find_param(t, "EROD")), 1.0);
    std::ostringstream kw, fx;
    write_keyword_deck(kw, o.m);
    Read k = read_text(kw.str());
    ASSERT_TRUE(k.ok) << k.messages() << kw.str();
    EXPECT_EQ(join(model_differences(o.m, k.m)), "");
    write_fixed_deck(fx, o.m, nullptr);
    Read f = read_text(fx.str(), "deck.dyn");
    ASSERT_TRUE(f.ok) << f.messages() << fx.str();
    EXPECT_EQ(join(model_differences(o.m, f.m)), "") << fx.str();
  }
  // RATEOP 4 (nonlinear rate coefficient): not supported (1102); SPALL 5, VP 2, RATEOP 3 with
  // P = 0: out of range (1003)
  std::string bad = jc;
  bad.replace(bad.find("       1.0       0.0      0.54"), 10, "       5.0");
  bad.replace(bad.find("      0.34       0.0       0.0       0.0\n"), 41, "      0.34       0.0       2.0       4.0\n");
  Read b = read_text(one_hex_deck(bad));
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.d.count(1102), 1) << b.messages();
  EXPECT_EQ(b.d.count(1003), 2) << b.messages();
  EXPECT_NE(b.messages().find("RATEOP"), std::string::npos) << b.messages();
  std::string cs = jc;
  cs.replace(cs.find("      0.34       0.0       0.0       0.0\n"), 41, "      0.34       0.0       0.0       3.0\n");
  Read c = read_text(one_hex_deck(cs));
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.d.count(1003), 1) << c.messages();
  EXPECT_NE(c.messages().find("Cowper-Symonds"), std::string::npos) << c.messages();
}

// *MAT_POWER_LAW_PLASTICITY: read into the table's places and the same model after the
// converter both ways.
TEST(KeywordMaterials, PowerLawIsReadAndRoundTrips) {
  const std::string mat =
      "*MAT_POWER_LAW_PLASTICITY\n"
      "$#     mid        ro         e        pr         k         n       src       srp\n"
      "         7    7.8E-9  200000.0       0.3    1200.0      0.25      40.0       5.0\n"
      "$#    sigy        vp      epsf\n"
      "     250.0       0.0       0.9\n";
  Read a = read_text(one_hex_deck(mat));
  ASSERT_TRUE(a.ok) << a.messages();
  const MaterialData& md = a.m.materials[0];
  const MaterialType& t = material_type(18);
  EXPECT_EQ(md.type, 18);
  EXPECT_EQ(param_value(md, *find_param(t, "K")), 1200.0);
  EXPECT_EQ(param_value(md, *find_param(t, "SIGY")), 250.0);
  EXPECT_EQ(md.rate_c, 40.0);
  EXPECT_EQ(md.fail_strain, 0.9);
  std::ostringstream kw, fx;
  write_keyword_deck(kw, a.m);
  Read k = read_text(kw.str());
  ASSERT_TRUE(k.ok) << k.messages() << kw.str();
  EXPECT_EQ(join(model_differences(a.m, k.m)), "");
  write_fixed_deck(fx, a.m, nullptr);
  Read f = read_text(fx.str(), "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages() << fx.str();
  EXPECT_EQ(join(model_differences(a.m, f.m)), "") << fx.str();
}
