// *PARAMETER_EXPRESSION (issue 25): the evaluator (impact3d/input/parameter_expression.h)
// against the same arithmetic written in C++ (relative 1e-15), its errors (what and where), and
// decks that define parameters by expressions and use them in the cards.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "impact3d/input/parameter_expression.h"
#include "../support/deck_text.h"

using namespace impact3d;
using test_support::F;
using test_support::I;
using test_support::read_deck_text;
using test_support::ReadDeck;

namespace {

const std::map<std::string, double> kParams = {{"A", 2.5}, {"B", -0.75}, {"N", 7}, {"LEN", 0.02}};

ParameterLookup table_lookup() {
  return [](const std::string& n, double& v, ExpressionError& e) {
    auto it = kParams.find(n);
    if (it == kParams.end()) {
      e.id = 1310, e.text = "parameter " + n + " is not defined";
      return false;
    }
    v = it->second;
    return true;
  };
}

double eval(const std::string& text) {
  double v = 0;
  ExpressionError e;
  EXPECT_TRUE(evaluate_expression(text, table_lookup(), v, e)) << text << ": " << e.text << " at " << e.pos;
  return v;
}

ExpressionError error_of(const std::string& text) {
  double v = 0;
  ExpressionError e;
  EXPECT_FALSE(evaluate_expression(text, table_lookup(), v, e)) << text << " gave " << v;
  return e;
}

void expect_value(const std::string& text, double want) {
  const double got = eval(text);
  EXPECT_LE(std::fabs(got - want), 1e-15 * std::fabs(want)) << text << ": " << got << " vs " << want;
}

}  // namespace

TEST(ParameterExpression, ArithmeticPrecedenceAndAssociativity) {
  expect_value("1 + 2 * 3", 7);
  expect_value("(1 + 2) * 3", 9);
  expect_value("10 - 4 - 3", 3);             // left to right
  expect_value("2 ** 3 ** 2", 512);          // right associative
  expect_value("2 ^ 3 ^ 2", 512);
  expect_value("-2 ** 2", -4);               // the power binds tighter than the sign
  expect_value("2 ** -1", 0.5);
  expect_value("7 / 2", 3.5);                // real arithmetic
  expect_value("1.5e3 + 2.d-1 + .25 + 4.", 1504.45);
  expect_value("- - 3", 3);
  expect_value("+3 * -a", -7.5);
  expect_value("a * b / n", 2.5 * -0.75 / 7);
  expect_value("&a + &B * &len", 2.5 + -0.75 * 0.02);  // with or without '&', any case
}

TEST(ParameterExpression, FunctionsAndPi) {
  const double a = 2.5, b = -0.75, len = 0.02;
  expect_value("sin(a) + cos(b) - tan(0.3)", std::sin(a) + std::cos(b) - std::tan(0.3));
  expect_value("asin(0.4) * acos(b) + atan(a)", std::asin(0.4) * std::acos(b) + std::atan(a));
  expect_value("atan2(b, -a)", std::atan2(b, -a));
  expect_value("SQRT(a) * EXP(b) / LOG(a) + log10(1234.5)", std::sqrt(a) * std::exp(b) / std::log(a) + std::log10(1234.5));
  expect_value("abs(b) + sinh(b) * cosh(b) - tanh(a)", std::fabs(b) + std::sinh(b) * std::cosh(b) - std::tanh(a));
  expect_value("min(a, b, 3) + max(a, b) * 10", b + a * 10);
  expect_value("pi * len ** 2 / 4", 3.14159265358979323846 * std::pow(len, 2) / 4);
  expect_value("PI", M_PI);
  expect_value("sqrt(3 * (a + 1) ** 2) / max(1, n / 2)", std::sqrt(3 * std::pow(a + 1, 2)) / std::max(1.0, 7.0 / 2));
}

TEST(ParameterExpression, ErrorsSayWhatAndWhere) {
  struct Case {
    const char* text;
    int id;
    std::size_t pos;
    const char* what;
  };
  const Case cases[] = {
      {"1 +", 1317, 3, "ends where a value"},
      {"2 * (3 + 4", 1317, 10, "')' expected"},
      {"2 * * 3", 1317, 4, "unexpected '*'"},
      {"a b", 1317, 2, "unexpected 'b'"},
      {"1 / (a - 2.5)", 1317, 2, "division by zero"},
      {"sqrt(b)", 1317, 0, "sqrt of a negative"},
      {"log(0)", 1317, 0, "not positive"},
      {"1 + asin(2)", 1317, 4, "outside [-1, 1]"},
      {"(-8) ** (1/3)", 1317, 5, "fractional power"},
      {"0 ** -1", 1317, 2, "negative power"},
      {"exp(1000)", 1317, 0, "not finite"},
      {"foo(1)", 1317, 0, "FOO is not a function"},
      {"atan2(1)", 1317, 0, "ATAN2 takes 2 argument(s), given 1"},
      {"min(1)", 1317, 0, "MIN takes 2 or more"},
      {"2 + width", 1310, 4, "WIDTH is not defined"},
      {"&", 1317, 0, "'&' must be followed"},
      {"1.5e", 1317, 3, "exponent needs digits"},
      {"3 # 4", 1317, 2, "unexpected '#'"},
  };
  // nesting is bounded (a hostile line cannot exhaust the stack)
  const ExpressionError deep = error_of(std::string(100000, '(') + "1");
  EXPECT_EQ(deep.id, 1317);
  EXPECT_NE(deep.text.find("nested more than 200 deep"), std::string::npos) << deep.text;
  EXPECT_EQ(error_of(std::string(5000, '-') + "1").id, 1317);
  expect_value(std::string(150, '(') + "2" + std::string(150, ')') + " ** 2", 4);
  for (const Case& c : cases) {
    const ExpressionError e = error_of(c.text);
    EXPECT_EQ(e.id, c.id) << c.text;
    EXPECT_EQ(e.pos, c.pos) << c.text << ": " << e.text;
    EXPECT_NE(e.text.find(c.what), std::string::npos) << c.text << ": " << e.text;
  }
}

namespace {

// A steel bar of 4 hexahedra along x whose sizes, material, velocity and curve come from
// parameters and expressions (fixed columns, a long-format card and free format mixed).
std::string bar_deck(const std::string& parameters) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nparameter expressions\n" << parameters
    << "*CONTROL_TERMINATION\n      &END\n"
    << "*PART\nbar\n" << I(1) << I(1) << I(1) << "\n*SECTION_SOLID\n" << I(1) << I(1) << "\n"
    << "*MAT_ELASTIC\n" << I(1) << "      &RHO        &E       &NU\n"
    << "*NODE\n";
  int id = 1;
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 4; ++i) d << I(id++, 8) << F(0.005 * i, 16) << F(0.005 * j, 16) << F(0.005 * k, 16) << "\n";
  d << "*ELEMENT_SOLID\n";
  auto n = [](int i, int j, int k) { return 1 + i + 5 * (j + 2 * k); };
  for (int i = 0; i < 4; ++i)
    d << I(i + 1, 8) << I(1, 8) << I(n(i, 0, 0), 8) << I(n(i + 1, 0, 0), 8) << I(n(i + 1, 1, 0), 8) << I(n(i, 1, 0), 8)
      << I(n(i, 0, 1), 8) << I(n(i + 1, 0, 1), 8) << I(n(i + 1, 1, 1), 8) << I(n(i, 1, 1), 8) << "\n";
  d << "*INITIAL_VELOCITY\n" << I(0) << "\n       &VX\n"
    << "*DEFINE_CURVE\n      &LC\n" << F(0.0, 20) << F(0.0, 20) << "\n               &TEND                &AMP\n"
    << "*LOAD_NODE_POINT\n" << I(5) << I(1) << I(3) << "\n*END\n";  // LCID 3 = &LC written out
  return d.str();
}

const char* const kParameters =
    "*PARAMETER\nR E       2.1E11    R NU      0.3\n"
    "*PARAMETER_EXPRESSION\n"
    "$ PRMR   EXPRESSION\n"
    "R RHO     E / C**2 \n"                      // uses C, defined below (any order)
    "R C       sqrt(e / 7850)\n"
    "R END     4 * 0.005 / &c * 2.5\n"
    "I LC      max(3, 7 / 2)\n"                  // 3.5: an I parameter truncates to 3
    "R VX,     -min(10, 5 * atan2(1, 1) * 4 / pi)\n"  // free format: PRMR up to the comma
    "R TEND    end * 2\n"
    "R AMP     1e3 * sin(pi / 6)\n";

}  // namespace

TEST(KeywordParameterExpression, DeckTakesTheValues) {
  ReadDeck r = read_deck_text(bar_deck(kParameters), "expressions.k");
  ASSERT_TRUE(r.ok) << r.messages();
  const double c = std::sqrt(2.1e11 / 7850);
  const MaterialData& mat = r.m.materials[0];
  EXPECT_LE(std::fabs(mat.rho - 2.1e11 / (c * c)), 1e-15 * 7850);
  EXPECT_EQ(mat.E, 2.1e11);
  EXPECT_EQ(mat.nu, 0.3);
  const double end = 4 * 0.005 / c * 2.5;
  EXPECT_LE(std::fabs(r.m.control.end_time - end), 1e-15 * end);
  ASSERT_EQ(r.m.load_curves.size(), 1u);
  ASSERT_EQ(r.m.nodal_loads.size(), 1u);  // its LCID 3 is the curve &LC (3.5 truncated)
  EXPECT_EQ(r.m.nodal_loads[0].curve, 0);
  EXPECT_LE(std::fabs(r.m.load_curves[0].t[1] - 2 * end), 1e-15 * 2 * end);
  EXPECT_LE(std::fabs(r.m.load_curves[0].f[1] - 1e3 * std::sin(M_PI / 6)), 1e-15 * 500);
  ASSERT_FALSE(r.m.init_velocities.empty());
  EXPECT_LE(std::fabs(r.m.init_velocities[0].v[0] - -5.0), 1e-15 * 5);
  EXPECT_EQ(r.count(2004), 0) << r.messages();
}

TEST(KeywordParameterExpression, ErrorsNameTheLineFieldAndPosition) {
  const std::string bad =
      "*PARAMETER\nR E       2.1E11    R NU      0.3       C NAME    steel\n"
      "*PARAMETER_EXPRESSION\n"
      "R RHO     7850\n"
      "R C       sqrt(e / (rho - 7850))\n"          // division by zero: the '/' at column 18
      "R END     1e-5 + \n"                          // ends early
      "R VX      2 * name\n"                         // text parameter
      "R LC      lc + 1\n"                           // itself
      "R AMP     missing * 2\n"                      // undefined
      "X TEND    1\n"                                // not R or I
      "R E       3\n"                                // defined twice
      "R NU2\n";                                     // no expression
  ReadDeck r = read_deck_text(bar_deck(bad), "expressions.k");
  EXPECT_FALSE(r.ok);
  const std::string msg = r.messages();
  auto has = [&](const std::string& s) { return msg.find(s) != std::string::npos; };
  EXPECT_TRUE(has("expressions.k:8: error 1317: *PARAMETER_EXPRESSION, field \"EXPRESSION\" (cols 18-18)")) << msg;
  EXPECT_TRUE(has("character 8 of 'sqrt(e / (rho - 7850))': division by zero")) << msg;
  EXPECT_TRUE(has("expressions.k:9: error 1317")) << msg;
  EXPECT_TRUE(has("expressions.k:10: error 1310")) << msg;
  EXPECT_TRUE(has("parameter NAME is text, not a number")) << msg;
  EXPECT_TRUE(has("expressions.k:11: error 1317")) << msg;
  EXPECT_TRUE(has("parameter LC depends on itself")) << msg;
  EXPECT_TRUE(has("expressions.k:12: error 1310")) << msg;
  EXPECT_TRUE(has("expressions.k:13: error 1006: *PARAMETER_EXPRESSION, field \"PRMR\" (cols 1-10)")) << msg;
  EXPECT_TRUE(has("expressions.k:14: error 1200")) << msg;
  EXPECT_TRUE(has("expressions.k:15: error 1317")) << msg;
  EXPECT_TRUE(has("parameter NU2 has no expression")) << msg;
}

// The converter writes the values (a written deck has no parameters): keyword -> keyword gives
// the same model.
TEST(KeywordParameterExpression, ConverterWritesTheValues) {
  ReadDeck r = read_deck_text(bar_deck(kParameters), "expressions.k");
  ASSERT_TRUE(r.ok) << r.messages();
  std::ostringstream kw;
  std::vector<std::string> notes;
  write_keyword_deck(kw, r.m, &notes);
  ReadDeck k2 = read_deck_text(kw.str(), "expressions_written.k");
  ASSERT_TRUE(k2.ok) << k2.messages();
  std::string diffs;
  for (const auto& x : model_differences(r.m, k2.m, 50)) diffs += x + "\n";
  EXPECT_EQ(diffs, "") << kw.str();
}

// A chain of expressions that name one another shares the nesting bound (a deck of 100,000
// chained parameters overflowed the stack before, 2026-11-27): 150 links evaluate, 100,000 are
// refused with 1317 at the link where the depth runs out, and the reader returns.
TEST(KeywordParameterExpression, ChainsOfExpressionsShareTheNestingBound) {
  auto chain = [](int n) {
    std::string s = "*PARAMETER_EXPRESSION\n";
    char b[64];
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n) std::snprintf(b, sizeof b, "R P%-7d P%d + 1\n", i, i + 1);
      else std::snprintf(b, sizeof b, "R P%-7d 1\n", i);
      s += b;
    }
    return s + "*PARAMETER\nR RHO     7850.0    R E       2.1E11    R NU      0.3\n";
  };
  ReadDeck ok = read_deck_text(bar_deck(chain(150)), "chain.k");
  EXPECT_EQ(ok.count(1317), 0) << ok.messages();
  ReadDeck deep = read_deck_text(bar_deck(chain(100000)), "chain.k");
  EXPECT_FALSE(deep.ok);
  EXPECT_GE(deep.count(1317), 1);
  EXPECT_NE(deep.messages().find("nested more than 200 deep"), std::string::npos);
}
