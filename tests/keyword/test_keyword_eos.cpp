// Equations of state in both deck formats: *EOS_LINEAR_POLYNOMIAL / *EOS_GRUNEISEN named by
// *PART EOSID (keyword) or by the material set's EOS type with its two EOS cards (fixed
// format), *MAT_NULL; read, echoed, through the converter both ways, and the refusals.

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/material/eos.h"
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

// One unit hexahedron of part 1 with material 7 and EOS eosid (the given cards).
std::string deck(const std::string& cards, const std::string& eosid = "3") {
  return "*KEYWORD\n*CONTROL_TERMINATION\n   1.0E-05\n*DATABASE_BINARY_D3PLOT\n    5.0E-7\n"
         "*PART\nblock\n         1         1         7" + std::string(10 - eosid.size(), ' ') + eosid + "\n"
         "*SECTION_SOLID\n         1         1\n" + cards +
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

const std::string kNull =
    "*MAT_NULL\n$#     mid        ro        pc        mu     terod     cerod        ym        pr\n"
    "         7    8930.0    -1.0E9    1.0E-3\n";
const std::string kGruneisen =
    "*EOS_GRUNEISEN_TITLE\ncopper\n$#   eosid         c        s1        s2        s3    gamma0         a        e0\n"
    "         3    3940.0      1.49       0.0       0.0      2.02      0.47     1.0E5\n$#      v0\n       0.0\n";
const std::string kLinear =
    "*EOS_LINEAR_POLYNOMIAL\n         3       0.0    1.4E11    2.0E11       0.0      2.02       0.0       0.0\n"
    "       0.0       1.0\n";

void round_trips(const Read& a) {
  std::ostringstream kw, fx;
  write_keyword_deck(kw, a.m);
  Read k = read_text(kw.str());
  ASSERT_TRUE(k.ok) << k.messages() << kw.str();
  EXPECT_EQ(join(model_differences(a.m, k.m)), "") << kw.str();
  EXPECT_EQ(k.m.materials[0].eos.form, a.m.materials[0].eos.form);
  write_fixed_deck(fx, a.m, nullptr);
  Read f = read_text(fx.str(), "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages() << fx.str();
  EXPECT_EQ(join(model_differences(a.m, f.m)), "") << fx.str();
}

}  // namespace

TEST(KeywordEos, NullWithGruneisenIsReadEchoedAndRoundTrips) {
  Read a = read_text(deck(kNull + kGruneisen));
  ASSERT_TRUE(a.ok) << a.messages();
  const MaterialData& md = a.m.materials[0];
  EXPECT_EQ(md.type, 9);
  EXPECT_EQ(md.eos.form, 4);
  EXPECT_EQ(md.eos.c[0], 3940.0);
  EXPECT_EQ(md.eos.c[4], 2.02);
  EXPECT_EQ(md.eos.c[5], 0.47);
  EXPECT_EQ(md.eos.e0, 1e5);
  EXPECT_EQ(md.eos.v0, 1.0);  // 0: 1
  EXPECT_EQ(param_value(md, *find_param(material_type(9), "PC")), -1e9);
  EXPECT_EQ(param_value(md, *find_param(material_type(9), "MU")), 1e-3);
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("Gruneisen (form 4, EOSID 3)"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("EOS GAMMA0"), std::string::npos) << echo.str();
  round_trips(a);
}

TEST(KeywordEos, JohnsonCookWithLinearPolynomialIsReadAndRoundTrips) {
  const std::string jc =
      "*MAT_JOHNSON_COOK\n"
      "         7    8930.0    46.0E9   124.0E9      0.34\n"
      "     90.E6    292.E6      0.31     0.025      1.09    1356.0     293.0       1.0\n"
      "     383.0       0.0       0.0       0.0\n"
      "       0.0\n";
  Read a = read_text(deck(jc + kLinear));
  ASSERT_TRUE(a.ok) << a.messages();
  EXPECT_EQ(a.m.materials[0].type, 15);
  EXPECT_EQ(a.m.materials[0].eos.form, 1);
  EXPECT_EQ(a.m.materials[0].eos.c[2], 2e11);
  round_trips(a);
}

TEST(KeywordEos, ElasticPlasticHydroWithItsTableIsReadEchoedAndRoundTrips) {
  // type 10: G, SIGY, EH, PC, FS; the 16-point table on cards 2-5 (EPS1-8, EPS9-16, ES1-8, ES9-16)
  std::string eps[2], es[2];
  for (int i = 0; i < 16; ++i) {
    char b[16];
    std::snprintf(b, sizeof b, "%10.4f", 0.01 * i * i);
    eps[i / 8] += b;
    std::snprintf(b, sizeof b, "%10.3e", 1e8 * (2 + 0.1 * i));
    es[i / 8] += b;
  }
  const std::string hydro = "*MAT_ELASTIC_PLASTIC_HYDRO_TITLE\naluminium\n"
                            "         7    2700.0    26.0E9     2.0E8     1.0E9    -1.0E8      0.85\n" +
                            eps[0] + "\n" + eps[1] + "\n" + es[0] + "\n" + es[1] + "\n";
  Read a = read_text(deck(hydro + kLinear));
  ASSERT_TRUE(a.ok) << a.messages();
  const MaterialData& md = a.m.materials[0];
  const MaterialType& t = material_type(10);
  EXPECT_EQ(md.type, 10);
  EXPECT_EQ(md.eos.form, 1);
  EXPECT_EQ(param_value(md, *find_param(t, "G")), 26e9);
  EXPECT_EQ(md.sigma_y, 2e8);
  EXPECT_EQ(param_value(md, *find_param(t, "EH")), 1e9);
  EXPECT_EQ(param_value(md, *find_param(t, "PC")), -1e8);
  EXPECT_EQ(md.fail_strain, 0.85);
  EXPECT_EQ(param_value(md, *find_param(t, "EPS16")), 0.01 * 15 * 15);
  EXPECT_EQ(param_value(md, *find_param(t, "ES9")), 2.8e8);
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("flow stress point 16"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("linear polynomial (form 1, EOSID 3)"), std::string::npos) << echo.str();
  round_trips(a);
  // without a table: SIGY and EH, and the fixed format's card 3 (G SIGY EH PC FS)
  const std::string plain = "*MAT_010\n         7    2700.0    26.0E9     2.0E8     1.0E9\n";
  Read b = read_text(deck(plain + kLinear));
  ASSERT_TRUE(b.ok) << b.messages();
  round_trips(b);
  std::ostringstream fx;
  write_fixed_deck(fx, b.m, nullptr);
  EXPECT_NE(fx.str().find("\n    2.6e10     2.0e8     1.0e9       0.0\n"), std::string::npos) << fx.str();
  // no EOS: 1204; CHARL: 1102; FS < 0: 1102
  Read c = read_text(deck(plain, "0"));
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.d.count(1204), 1) << c.messages();
  Read d = read_text(deck("*MAT_010\n         7    2700.0    26.0E9     2.0E8     1.0E9       0.0      -1.0       0.1\n" + kLinear));
  EXPECT_FALSE(d.ok);
  EXPECT_EQ(d.d.count(1102), 2) << d.messages();
}

// *EOS_TABULATED: card 1 EOSID GAMA E0 V0; cards 2-7 EV, C, T (5 E16 each).
const std::string kTabulated =
    "*EOS_TABULATED_TITLE\nwater-like\n"
    "$#   eosid      gama        e0        v0\n"
    "         3       0.3     2.0E5      0.98\n"
    "             0.0          -0.025           -0.05           -0.08           -0.12\n"
    "           -0.17\n"
    "             0.0          5.6E07          1.25E8          2.35E8          4.40E8\n"
    "          8.00E8\n"
    "             1.0             1.0             1.1             1.2             1.3\n"
    "             1.4\n";

TEST(KeywordEos, TabulatedIsReadEchoedAndRoundTrips) {
  Read a = read_text(deck(kNull + kTabulated));
  ASSERT_TRUE(a.ok) << a.messages();
  const EosData& e = a.m.materials[0].eos;
  EXPECT_EQ(e.form, 9);
  EXPECT_EQ(e.c[30], 0.3);
  EXPECT_EQ(e.e0, 2e5);
  EXPECT_EQ(e.v0, 0.98);
  EXPECT_EQ(e.c[5], -0.17);   // EV6
  EXPECT_EQ(e.c[13], 2.35e8);  // C4
  EXPECT_EQ(e.c[25], 1.4);    // T6
  EXPECT_EQ(e.c[6], 0.0);     // EV7 blank
  EXPECT_EQ(eos_table_points(e), 6);
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("tabulated (form 9, EOSID 3)"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("EOS EV6"), std::string::npos) << echo.str();
  EXPECT_EQ(echo.str().find("EOS EV7"), std::string::npos) << echo.str();  // past the table
  round_trips(a);
  // the fixed format: EOS type 9 in card 1 columns 21-25, 7 EOS cards after card 8
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  EXPECT_NE(fx.str().find("\n       0.3     2.0e5      0.98\n"), std::string::npos) << fx.str();
  EXPECT_NE(fx.str().find("\n           -0.17             0.0"), std::string::npos) << fx.str();
  // refusals: EV not decreasing; a point after the table's last; V0 negative
  auto refused = [&](const std::string& from, const std::string& to, const char* field) {
    std::string t = kTabulated;
    ASSERT_NE(t.find(from), std::string::npos) << from;
    t.replace(t.find(from), from.size(), to);
    Read r = read_text(deck(kNull + t));
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.d.count(1003), 1) << r.messages();
    EXPECT_NE(r.messages().find(field), std::string::npos) << r.messages();
  };
  refused("          -0.025", "           0.025", "EV2");
  refused("           -0.17\n", "           -0.17            0.01\n", "EV7");
  refused("      0.98\n", "     -0.98\n", "V0");
}

// *EOS_JWL (form 2) and *EOS_SACK_TUESDAY (form 3): one card each, read, echoed, through the
// converter both ways (fixed format: EOS type 2 / 3 in card 1 columns 21-25, one EOS card);
// JWL's R1 <= 0 refused.
TEST(KeywordEos, JwlAndSackTuesdayAreReadEchoedAndRoundTrip) {
  const std::string jwl =
      "*EOS_JWL\n$#   eosid         a         b        r1        r2      omeg        e0        v0\n"
      "         3  3.712E11  3.231E09      4.15      0.95       0.3     7.0E9       1.0\n";
  Read a = read_text(deck(kNull + jwl));
  ASSERT_TRUE(a.ok) << a.messages();
  const EosData& e = a.m.materials[0].eos;
  EXPECT_EQ(e.form, 2);
  EXPECT_EQ(e.c[0], 3.712e11);
  EXPECT_EQ(e.c[1], 3.231e9);
  EXPECT_EQ(e.c[2], 4.15);
  EXPECT_EQ(e.c[3], 0.95);
  EXPECT_EQ(e.c[4], 0.3);
  EXPECT_EQ(e.e0, 7e9);
  EXPECT_EQ(e.v0, 1.0);
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("JWL (form 2, EOSID 3)"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("EOS OMEG"), std::string::npos) << echo.str();
  round_trips(a);
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  const std::string text = fx.str();
  const std::size_t at = text.find("*----- MATERIALS\n") + 17;
  EXPECT_EQ(text.substr(at + 20, 5), "    2") << text;
  std::string r1 = jwl;
  r1.replace(r1.find("      4.15"), 10, "       0.0");
  Read b = read_text(deck(kNull + r1));
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.d.count(1003), 1) << b.messages();
  EXPECT_NE(b.messages().find("R1"), std::string::npos) << b.messages();

  const std::string sack =
      "*EOS_SACK_TUESDAY_TITLE\nproducts\n         3     2.0E9       1.2       0.5       0.1       0.4     1.0E8       1.0\n";
  Read s = read_text(deck(kNull + sack));
  ASSERT_TRUE(s.ok) << s.messages();
  EXPECT_EQ(s.m.materials[0].eos.form, 3);
  EXPECT_EQ(s.m.materials[0].eos.c[3], 0.1);
  EXPECT_EQ(s.m.materials[0].eos.c[4], 0.4);
  EXPECT_EQ(s.m.materials[0].eos.e0, 1e8);
  std::ostringstream se;
  write_model_summary(se, s.m);
  EXPECT_NE(se.str().find("Sack Tuesday (form 3, EOSID 3)"), std::string::npos) << se.str();
  round_trips(s);
}

TEST(KeywordEos, RefusalsNameTheField) {
  auto count = [](const std::string& text, int msg) {
    Read r = read_text(text);
    EXPECT_FALSE(r.ok) << text;
    if (r.d.count(msg) != 1) ADD_FAILURE() << r.messages();
    return r.d.count(msg);
  };
  // an EOSID nothing defines; *MAT_NULL without one; an EOS on a material that takes none
  EXPECT_EQ(count(deck(kNull + kGruneisen, "4"), 1310), 1);
  EXPECT_EQ(count(deck(kNull, "0"), 1204), 1);
  const std::string elastic = "*MAT_ELASTIC\n         7    8930.0   117.0E9      0.35\n";
  EXPECT_EQ(count(deck(elastic + kGruneisen), 1102), 1);
  // a refused EOS keyword: the keyword (1301) and the part naming it (1102)
  const std::string tab = "*EOS_IGNITION_AND_GROWTH_OF_REACTION_IN_HE\n         3     3.7E11\n";
  EXPECT_EQ(count(deck(kNull + tab), 1102), 1);
  // V0 negative, LCID, TEROD below 1, C <= 0
  std::string v0 = kGruneisen;
  v0.replace(v0.find("       0.0\n"), 11, "      -0.9\n");
  EXPECT_EQ(count(deck(kNull + v0), 1003), 1);
  std::string lcid = kGruneisen;
  lcid.replace(lcid.find("       0.0\n"), 11, "       0.0         0        12\n");
  EXPECT_EQ(count(deck(kNull + lcid), 1102), 1);
  std::string terod = kNull;
  terod.replace(terod.find("1.0E-3\n"), 7, "1.0E-3       0.8\n");  // TEROD must exceed 1
  EXPECT_EQ(count(deck(terod + kGruneisen), 1003), 1);
  std::string c0 = kGruneisen;
  c0.replace(c0.find("    3940.0"), 10, "       0.0");
  EXPECT_GE(count(deck(kNull + c0), 1003), 1);
}

TEST(KeywordEos, FixedFormatEosTypeAndCards) {
  Read a = read_text(deck(kNull + kGruneisen));
  ASSERT_TRUE(a.ok) << a.messages();
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  const std::string text = fx.str();
  // card 1 columns 21-25: the form; the two EOS cards after card 8
  const std::size_t at = text.find("*----- MATERIALS\n") + 17;
  const std::string card1 = text.substr(at, text.find('\n', at) - at);
  EXPECT_EQ(card1.substr(20, 5), "    4") << card1;
  EXPECT_NE(text.find("    3940.0      1.49       0.0       0.0      2.02      0.47     1.0e5"), std::string::npos) << text;
  // an EOS form IMPACT-3D lacks, an EOS with type 1, a null material without one
  auto refused = [&](const std::string& from, const std::string& to, int msg) {
    std::string t = text;
    const std::size_t c1 = t.find("*----- MATERIALS\n") + 17;
    ASSERT_EQ(t.substr(c1, 25).substr(20, 5), from);
    t.replace(c1 + 20, 5, to);
    Read r = read_text(t, "deck.dyn");
    EXPECT_FALSE(r.ok);
    EXPECT_GE(r.d.count(msg), 1) << r.messages();
  };
  refused("    4", "    7", 1102);  // ignition and growth
  std::string t1 = text;
  {
    const std::size_t c1 = t1.find("*----- MATERIALS\n") + 17;
    t1.replace(c1 + 9, 1, "1");  // type 9 -> 1 (E and nu blank: 1208 as well)
    Read r = read_text(t1, "deck.dyn");
    EXPECT_FALSE(r.ok);
    EXPECT_GE(r.d.count(1102), 1) << r.messages();
  }
}

namespace {

// *EOS_RATIO_OF_POLYNOMIALS (form 5): card 1 EOSID; cards 2-8 A_i0-A_i3 (4 E20 each); card 9
// A14 A24; card 10 ALPHA BETA E0 V0.
std::string ratio_of_polynomials(const std::string& a10 = "                 0.0") {
  return "*EOS_RATIO_OF_POLYNOMIALS\n         3\n" + a10 +
         "              2.0E09              5.0E09              1.0E10\n"
         "                 0.5                 0.3                 0.0                 0.0\n"
         "              1.0E-9                 0.0                 0.0                 0.0\n"
         "                 0.0                 0.0                 0.0                 0.0\n"
         "                 1.0                 0.1                 0.0                 0.0\n"
         "             1.0E-10                 0.0                 0.0                 0.0\n"
         "                 0.0                 0.0                 0.0                 0.0\n"
         "              2.0E10                0.02\n"
         "                 0.1               1.0E9               2.0E8                 1.0\n";
}

// *EOS_LINEAR_POLYNOMIAL_WITH_ENERGY_LEAK (form 6): form 1's cards, card 2 E0 V0 LCID; and the
// curve it names.
std::string energy_leak(const std::string& lcid = "        11", const std::string& rate = "             1.0E13") {
  return "*EOS_LINEAR_POLYNOMIAL_WITH_ENERGY_LEAK\n         3       0.0    2.2E09       0.0       0.0       0.4       0.0       0.0\n"
         "     1.0E8       1.0" + lcid + "\n"
         "*DEFINE_CURVE\n        11\n                 0.0" + rate + "\n              1.0E-5              2.0E13\n";
}

// *EOS_TABULATED_COMPACTION (form 8): card 1 EOSID GAMA E0 V0 LCC LCT LCK LCID; cards 2-9 EV,
// C, T, K (5 E16 each).
const std::string kCompaction =
    "*EOS_TABULATED_COMPACTION_TITLE\nsand-like\n"
    "$#   eosid      gama        e0        v0       lcc       lct       lck      lcid\n"
    "         3       0.5       0.0       1.0\n"
    "             0.0           -0.05            -0.1            -0.2            -0.3\n"
    "\n"
    "             0.0          5.0E07          1.5E08          5.0E08          1.2E09\n"
    "\n"
    "             1.0             1.0             0.9             0.8             0.8\n"
    "\n"
    "          2.0E09          3.0E09          5.0E09          8.0E09          1.2E10\n"
    "\n";

}  // namespace

// Forms 5, 6 and 8: read (the table's columns in their places), echoed, through the converter
// both ways (fixed format: the form in card 1 columns 21-25, its cards after card 8).
TEST(KeywordEos, RatioOfPolynomialsEnergyLeakAndCompactionAreReadEchoedAndRoundTrip) {
  Read a = read_text(deck(kNull + ratio_of_polynomials()));
  ASSERT_TRUE(a.ok) << a.messages();
  const EosData& e = a.m.materials[0].eos;
  EXPECT_EQ(e.form, 5);
  EXPECT_EQ(e.c[1], 2e9);     // A11
  EXPECT_EQ(e.c[4], 2e10);    // A14
  EXPECT_EQ(e.c[5], 0.5);     // A20
  EXPECT_EQ(e.c[9], 0.02);    // A24
  EXPECT_EQ(e.c[kEosRpF3], 1e-9);           // A30
  EXPECT_EQ(e.c[kEosRpF3 + 4 * 2 + 1], 0.1);  // A51
  EXPECT_EQ(e.c[kEosRpF3 + 4 * 3], 1e-10);  // A60
  EXPECT_EQ(e.c[kEosRpAlpha], 0.1);
  EXPECT_EQ(e.c[kEosRpBeta], 1e9);
  EXPECT_EQ(e.e0, 2e8);
  std::ostringstream echo;
  write_model_summary(echo, a.m);
  EXPECT_NE(echo.str().find("ratio of polynomials (form 5, EOSID 3)"), std::string::npos) << echo.str();
  EXPECT_NE(echo.str().find("EOS BETA"), std::string::npos) << echo.str();
  round_trips(a);
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  EXPECT_NE(fx.str().find("\n                 0.1               1.0e9               2.0e8                 1.0\n"), std::string::npos) << fx.str();

  Read b = read_text(deck(kNull + energy_leak()));
  ASSERT_TRUE(b.ok) << b.messages();
  EXPECT_EQ(b.m.materials[0].eos.form, 6);
  EXPECT_EQ(b.m.materials[0].eos.c[4], 0.4);
  EXPECT_EQ(eos_curve(b.m.materials[0].eos), 1);  // *DEFINE_CURVE 11: the deck's first curve
  EXPECT_EQ(b.d.count(2004), 0) << b.messages();  // the curve is used
  std::ostringstream be;
  write_model_summary(be, b.m);
  EXPECT_NE(be.str().find("linear polynomial with energy deposition (form 6, EOSID 3)"), std::string::npos) << be.str();
  round_trips(b);

  Read c = read_text(deck(kNull + kCompaction));
  ASSERT_TRUE(c.ok) << c.messages();
  const EosData& t = c.m.materials[0].eos;
  EXPECT_EQ(t.form, 8);
  EXPECT_EQ(t.c[kEosTabGamma], 0.5);
  EXPECT_EQ(t.c[3], -0.2);              // EV4
  EXPECT_EQ(t.c[kEosTabC + 4], 1.2e9);  // C5
  EXPECT_EQ(t.c[kEosTabT + 2], 0.9);    // T3
  EXPECT_EQ(t.c[kEosTabK + 1], 3e9);    // K2
  EXPECT_EQ(eos_table_points(t), 5);
  EXPECT_EQ(material_history_count(c.m.materials[0]), 2);  // E and the most compacted ln V
  std::ostringstream ce;
  write_model_summary(ce, c.m);
  EXPECT_NE(ce.str().find("tabulated compaction (form 8, EOSID 3)"), std::string::npos) << ce.str();
  EXPECT_NE(ce.str().find("EOS K5"), std::string::npos) << ce.str();
  EXPECT_EQ(ce.str().find("EOS K6"), std::string::npos) << ce.str();  // past the table
  round_trips(c);
}

// The new forms' refusals name the field: a non-monotonic EV table and a K <= 0 (1003), the
// curve fields LCC-LCID (1102), A10 = 1 (1102), an undefined or negative deposition curve
// (1310, 1003).
TEST(KeywordEos, RatioLeakAndCompactionRefusalsNameTheField) {
  auto refused = [&](const std::string& text, int msg, const char* field) {
    Read r = read_text(text);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.d.count(msg), 1) << r.messages();
    EXPECT_NE(r.messages().find(field), std::string::npos) << r.messages();
  };
  auto swap = [](std::string t, const std::string& from, const std::string& to) {
    EXPECT_NE(t.find(from), std::string::npos) << from;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  refused(deck(kNull + swap(kCompaction, "            -0.1", "           -0.01")), 1003, "EV3");  // -0.05, -0.01: not decreasing
  refused(deck(kNull + swap(kCompaction, "          3.0E09", "         -3.0E09")), 1003, "K2");
  refused(deck(kNull + swap(kCompaction, "       1.0\n", "       1.0         5\n")), 1102, "LCC");
  refused(deck(kNull + ratio_of_polynomials("                 1.0")), 1102, "A10");
  refused(deck(kNull + energy_leak("        12")), 1310, "LCID");
  refused(deck(kNull + energy_leak("        11", "            -1.0E13")), 1003, "LCID");
}

// Form 6 in the fixed format: LCID (card 2 columns 21-30) is a load-curve number; one the deck
// lacks is refused (1310 naming LCID), the deck's own reads.
TEST(KeywordEos, FixedFormatEnergyLeakCurve) {
  Read a = read_text(deck(kNull + energy_leak()));
  ASSERT_TRUE(a.ok) << a.messages();
  std::ostringstream fx;
  write_fixed_deck(fx, a.m, nullptr);
  std::string text = fx.str();
  const std::string card2 = "\n     1.0e8       1.0         1\n";
  ASSERT_NE(text.find(card2), std::string::npos) << text;
  Read f = read_text(text, "deck.dyn");
  ASSERT_TRUE(f.ok) << f.messages();
  EXPECT_EQ(eos_curve(f.m.materials[0].eos), 1);
  text.replace(text.find(card2), card2.size(), "\n     1.0e8       1.0         5\n");
  Read r = read_text(text, "deck.dyn");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.d.count(1310), 1) << r.messages();
  EXPECT_NE(r.messages().find("LCID"), std::string::npos) << r.messages();
}
