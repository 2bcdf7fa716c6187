// Material type 3's strain-rate (Cowper-Symonds C, P) and failure-strain parameters: fixed
// format card 8 columns 11-40 (IMPACT-3D choice), *MAT_PLASTIC_KINEMATIC card 2 (SRC, SRP, FS,
// VP); errors name the card and columns; the converter carries them both ways.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "tests/input/input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

// tiny.dyn with material 1's card 8 (the blank line after beta) replaced by `card8`
std::string tiny_with_card8(const std::string& card8) {
  std::string t = tiny_deck();
  const std::string beta = "1.0000e+00\n\n";
  const std::size_t at = t.find(beta);
  EXPECT_NE(at, std::string::npos);
  return t.replace(at, beta.size(), "1.0000e+00\n" + card8 + "\n");
}

}  // namespace

TEST(RateAndFailureCards, FixedFormatCard8Columns11To40) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_string(tiny_with_card8("          4.0400e+015.0000e+001.5000e+00"), m, d)) << all_messages(d);
  EXPECT_EQ(m.materials[0].rate_c, 40.4);
  EXPECT_EQ(m.materials[0].rate_p, 5.0);
  EXPECT_EQ(m.materials[0].fail_strain, 1.5);
  EXPECT_FALSE(d.has(2006)) << all_messages(d);
  // blank: no rate effect, no failure (the seed decks)
  Model plain;
  Diagnostics d2;
  ASSERT_TRUE(read_string(tiny_deck(), plain, d2));
  EXPECT_EQ(plain.materials[0].rate_c, 0.0);
  EXPECT_EQ(plain.materials[0].fail_strain, 0.0);
}

TEST(RateAndFailureCards, BadValuesAreReportedWithColumnsInOnePass) {
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_string(tiny_with_card8("          -1.000e+00          -2.000e+00"), m, d));
  EXPECT_EQ(d.error_count(), 2) << all_messages(d);
  const std::string msg = all_messages(d);
  EXPECT_NE(msg.find("strain-rate parameter C"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cols 11-20"), std::string::npos) << msg;
  EXPECT_NE(msg.find("failure plastic strain"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cols 31-40"), std::string::npos) << msg;
  Model m2;
  Diagnostics d2;
  EXPECT_FALSE(read_string(tiny_with_card8("          4.0400e+01"), m2, d2));  // C without P
  ASSERT_EQ(d2.error_count(), 1) << all_messages(d2);
  EXPECT_NE(all_messages(d2).find("cols 21-30"), std::string::npos) << all_messages(d2);
}

TEST(RateAndFailureCards, KeywordCard2AndConverterBothWays) {
  Model fixed;
  Diagnostics d;
  ASSERT_TRUE(read_string(tiny_with_card8("          4.0400e+015.0000e+001.5000e+00"), fixed, d));
  std::ostringstream kw;
  write_keyword_deck(kw, fixed);
  Model from_kw;
  Diagnostics dk;
  ASSERT_TRUE(read_any(kw.str(), from_kw, dk, "t.k")) << all_messages(dk) << kw.str();
  EXPECT_TRUE(model_differences(fixed, from_kw).empty());
  EXPECT_EQ(from_kw.materials[0].rate_c, 40.4);
  EXPECT_EQ(from_kw.materials[0].fail_strain, 1.5);
  std::ostringstream fx;
  write_fixed_deck(fx, from_kw);
  Model back;
  Diagnostics db;
  ASSERT_TRUE(read_any(fx.str(), back, db, "t.dyn")) << all_messages(db) << fx.str();
  EXPECT_TRUE(model_differences(fixed, back).empty());

  // keyword card 2 variants: FS = 1e20 (LS-DYNA's default) means no failure; VP = 1 and a
  // negative SRC are errors naming the field
  std::string text = kw.str();
  const std::string head = "$#     src       srp        fs        vp\n";
  const std::size_t at = text.find(head);
  ASSERT_NE(at, std::string::npos);
  const std::size_t eol = text.find('\n', at + head.size());
  auto with_card2 = [&](const std::string& c2) {
    std::string t = text;
    return t.replace(at + head.size(), eol - (at + head.size()), c2);
  };
  Model a;
  Diagnostics da;
  ASSERT_TRUE(read_any(with_card2("       0.0       0.0     1.e20         0"), a, da, "a.k")) << all_messages(da);
  EXPECT_EQ(a.materials[0].fail_strain, 0.0);
  EXPECT_EQ(a.materials[0].rate_c, 0.0);
  Model b;
  Diagnostics dbb;
  EXPECT_FALSE(read_any(with_card2("      -1.0       5.0       0.0         1"), b, dbb, "b.k"));
  const std::string mb = all_messages(dbb);
  EXPECT_TRUE(dbb.has(1003) && dbb.has(1102)) << mb;
  EXPECT_NE(mb.find("SRC"), std::string::npos) << mb;
  EXPECT_NE(mb.find("VP"), std::string::npos) << mb;
}
