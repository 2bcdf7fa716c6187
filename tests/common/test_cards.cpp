// Fixed-column card reading (common/cards.*) and the message catalog (common/messages.*):
// every field kind, comment rules, line numbering, card-level character errors and the
// one-line rendering of a message.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include "common/cards.h"
#include "common/messages.h"

using namespace impact3d;

namespace {

FieldStatus int_of(const std::string& s, long long& v) { return parse_fortran_int(s, v); }

long long int_ok(const std::string& s) {
  long long v = -999;
  EXPECT_EQ(parse_fortran_int(s, v), FieldStatus::ok) << "\"" << s << "\"";
  return v;
}

double real_ok(const std::string& s) {
  double v = -999;
  EXPECT_EQ(parse_fortran_real(s, v), FieldStatus::ok) << "\"" << s << "\"";
  return v;
}

void real_bad(const std::string& s) {
  double v = 42;
  EXPECT_EQ(parse_fortran_real(s, v), FieldStatus::bad) << "\"" << s << "\"";
  EXPECT_EQ(v, 42) << "a bad field must not change the value: \"" << s << "\"";
}

void int_bad(const std::string& s) {
  long long v = 42;
  EXPECT_EQ(parse_fortran_int(s, v), FieldStatus::bad) << "\"" << s << "\"";
  EXPECT_EQ(v, 42) << "\"" << s << "\"";
}

}  // namespace

// ---------------------------------------------------------------- integers

TEST(FortranInt, BlankIsBlank) {
  long long v = 7;
  EXPECT_EQ(int_of("", v), FieldStatus::blank);
  EXPECT_EQ(int_of("     ", v), FieldStatus::blank);
  EXPECT_EQ(v, 7);
}

TEST(FortranInt, SignsAndJustification) {
  EXPECT_EQ(int_ok("12"), 12);
  EXPECT_EQ(int_ok("   12"), 12);   // right-justified
  EXPECT_EQ(int_ok("12   "), 12);   // left-justified
  EXPECT_EQ(int_ok("  12 "), 12);
  EXPECT_EQ(int_ok("+12"), 12);
  EXPECT_EQ(int_ok("  -12"), -12);
  EXPECT_EQ(int_ok("0"), 0);
  EXPECT_EQ(int_ok("-0"), 0);
  EXPECT_EQ(int_ok("00042"), 42);
  EXPECT_EQ(int_ok("2147483647"), 2147483647LL);
}

TEST(FortranInt, BadForms) {
  int_bad("1 2");          // embedded blank
  int_bad(" 1 2 ");
  int_bad("- 1");          // blank between sign and digits
  int_bad("+");
  int_bad("-");
  int_bad("12a");          // letters
  int_bad("abc");
  int_bad("1.0");          // a real in an integer field
  int_bad("1e3");
  int_bad("--1");
  int_bad("2147483648");   // beyond int
  int_bad("99999999999999999999999999");  // overflow of any integer type
  int_bad("\t1");          // tab is not a blank
}

// ---------------------------------------------------------------- reals

TEST(FortranReal, FortranForms) {
  EXPECT_DOUBLE_EQ(real_ok("1.5"), 1.5);
  EXPECT_DOUBLE_EQ(real_ok("1.5e3"), 1500.0);
  EXPECT_DOUBLE_EQ(real_ok("1.5E+03"), 1500.0);
  EXPECT_DOUBLE_EQ(real_ok("2.5D-3"), 2.5e-3);
  EXPECT_DOUBLE_EQ(real_ok("2.5d-3"), 2.5e-3);
  EXPECT_DOUBLE_EQ(real_ok("1.0-5"), 1.0e-5);   // exponent without a letter
  EXPECT_DOUBLE_EQ(real_ok("1.0+5"), 1.0e5);
  EXPECT_DOUBLE_EQ(real_ok("15"), 15.0);        // no decimal point
  EXPECT_DOUBLE_EQ(real_ok(".5"), 0.5);
  EXPECT_DOUBLE_EQ(real_ok("-.5e-2"), -0.005);
  EXPECT_DOUBLE_EQ(real_ok("1.e3"), 1000.0);
  EXPECT_DOUBLE_EQ(real_ok("5."), 5.0);
  EXPECT_DOUBLE_EQ(real_ok("+3.25"), 3.25);
  EXPECT_DOUBLE_EQ(real_ok("   7.8500e+03"), 7850.0);
  EXPECT_DOUBLE_EQ(real_ok("7.8500e+03   "), 7850.0);
  EXPECT_DOUBLE_EQ(real_ok("-1.000e-04"), -1.0e-4);
  EXPECT_DOUBLE_EQ(real_ok("0"), 0.0);
}

TEST(FortranReal, BlankIsBlank) {
  double v = 3;
  EXPECT_EQ(parse_fortran_real("", v), FieldStatus::blank);
  EXPECT_EQ(parse_fortran_real("          ", v), FieldStatus::blank);
  EXPECT_EQ(v, 3);
}

TEST(FortranReal, BadForms) {
  real_bad("1.5x");
  real_bad("e5");
  real_bad(".");
  real_bad("1e");
  real_bad("1.5e+");
  real_bad("1.5D");
  real_bad("inf");
  real_bad("-inf");
  real_bad("nan");
  real_bad("NaN");
  real_bad("1e999");    // overflow
  real_bad("-1e999");
  real_bad("1.5 e3");   // embedded blank
  real_bad("1 .5");
  real_bad("1.0.0");
  real_bad("0x10");
  real_bad("+");
  real_bad("-");
  real_bad("1,5");
}

// ---------------------------------------------------------------- fields read by columns

namespace {
struct OneCard {
  DeckFile deck;
  Diagnostics diag;
  explicit OneCard(const std::string& text) { deck.load_from_string("deck.dyn", text); }
  Card card(const char* name = "test card") { return Card(deck.name(), *deck.next_card(), name, diag); }
};
}  // namespace

TEST(CardFields, AbuttingFieldsAreReadByColumns) {
  OneCard t("0.01.000000E8\n");
  Card c = t.card();
  // the same characters give different numbers depending on the columns of the fields
  EXPECT_DOUBLE_EQ(c.e(1, 4, "a"), 0.01);
  EXPECT_DOUBLE_EQ(c.e(5, 13, "b"), 0.0);   // ".000000E8"
  EXPECT_DOUBLE_EQ(c.e(1, 3, "c"), 0.0);    // "0.0"
  EXPECT_DOUBLE_EQ(c.e(4, 13, "d"), 1.0e8); // "1.000000E8"
  EXPECT_EQ(t.diag.error_count(), 0);

  // Control card 6 of the shipped decks: three E10 fields with no blank between them.
  OneCard t6("1.0000e-051.0000e-071.0000e-06    0    0                        0    09.0000e-01\n");
  Card c6 = t6.card();
  EXPECT_DOUBLE_EQ(c6.e(1, 10, "t"), 1e-5);
  EXPECT_DOUBLE_EQ(c6.e(11, 20, "th"), 1e-7);
  EXPECT_DOUBLE_EQ(c6.e(21, 30, "plot"), 1e-6);
  EXPECT_EQ(c6.i(61, 65, "thermal"), 0);
  EXPECT_DOUBLE_EQ(c6.e(71, 80, "tssf"), 0.9);
  EXPECT_EQ(t6.diag.error_count(), 0);
}

TEST(CardFields, VisItControlCard4) {
  // Control card 4 as VisIt/TrueGrid write it: the A5 format field abuts the I5 before it.
  OneCard t("    0e20.0    0\n");
  Card c = t.card();
  EXPECT_EQ(c.i(1, 5, "n"), 0);
  EXPECT_EQ(c.a(6, 10), "e20.0");
  EXPECT_EQ(c.i(11, 15, "m"), 0);
  EXPECT_EQ(t.diag.error_count(), 0);
}

TEST(CardFields, BlankFieldsTakeTheDefault) {
  OneCard t("    3          \n");
  Card c = t.card();
  EXPECT_EQ(c.i(1, 5, "a", 9), 3);
  EXPECT_EQ(c.i(6, 10, "b", 9), 9);
  EXPECT_DOUBLE_EQ(c.e(11, 20, "c", 0.9), 0.9);
  // beyond the end of the line: blank, default
  EXPECT_EQ(c.i(70, 80, "d", 100), 100);
  EXPECT_DOUBLE_EQ(c.e(71, 80, "e", 0.1), 0.1);
  EXPECT_TRUE(c.blank(6, 80));
  EXPECT_EQ(c.a(4, 7), " 3  ");
  EXPECT_EQ(t.diag.error_count(), 0);
  EXPECT_FALSE(c.had_error());
}

TEST(CardFields, BadFieldReportsAndGivesDefault) {
  OneCard t("  1x5  2.0e\n");
  Card c = t.card("control card 3");
  EXPECT_EQ(c.i(1, 5, "NMMAT", 4), 4);
  EXPECT_DOUBLE_EQ(c.e(6, 11, "rho", 8.0), 8.0);
  ASSERT_EQ(t.diag.all().size(), 2u);
  EXPECT_EQ(t.diag.all()[0].id, 1001);
  EXPECT_EQ(t.diag.all()[0].where.col_first, 1);
  EXPECT_EQ(t.diag.all()[0].where.col_last, 5);
  EXPECT_EQ(t.diag.all()[0].where.field, "NMMAT");
  EXPECT_EQ(t.diag.all()[0].where.found, "1x5");
  EXPECT_EQ(t.diag.all()[1].id, 1002);
  EXPECT_EQ(t.diag.all()[1].where.found, "2.0e");
  EXPECT_TRUE(c.had_error());
}

TEST(CardFields, SecondErrorOnAFieldThatDidNotParseIsNotRepeated) {
  OneCard t("  1x5\n");
  Card c = t.card();
  long long v = c.i(1, 5, "NUMNP", 0);
  c.error(1003, 1, 5, "NUMNP", "at least 1 node");  // about the default value: not shown
  c.error(1003, 6, 10, "other");                      // another field: shown
  ASSERT_EQ(t.diag.all().size(), 2u);
  EXPECT_EQ(v, 0);
  EXPECT_EQ(t.diag.all()[0].id, 1001);
  EXPECT_EQ(t.diag.all()[1].id, 1003);
  EXPECT_EQ(t.diag.all()[1].where.col_first, 6);
}

// ---------------------------------------------------------------- comments and keywords

TEST(Comments, Rules) {
  EXPECT_TRUE(is_comment_line("*"));
  EXPECT_TRUE(is_comment_line("* text"));
  EXPECT_TRUE(is_comment_line("*---"));
  EXPECT_TRUE(is_comment_line("*----- CONTROL CARD #2 -----*"));
  EXPECT_TRUE(is_comment_line("**"));
  EXPECT_TRUE(is_comment_line("$ x"));
  EXPECT_TRUE(is_comment_line("$"));
  EXPECT_TRUE(is_comment_line("$#   nid"));
  EXPECT_FALSE(is_comment_line("*NODE"));
  EXPECT_FALSE(is_comment_line("*keyword"));
  EXPECT_FALSE(is_comment_line(""));         // a blank line is a card of blanks
  EXPECT_FALSE(is_comment_line("     "));
  EXPECT_FALSE(is_comment_line(" * text"));  // '*' must be in column 1
  EXPECT_FALSE(is_comment_line("1.0"));

  EXPECT_TRUE(is_keyword_line("*NODE"));
  EXPECT_TRUE(is_keyword_line("*KEYWORD"));
  EXPECT_TRUE(is_keyword_line("*keyword"));
  EXPECT_FALSE(is_keyword_line("* text"));
  EXPECT_FALSE(is_keyword_line("*"));
  EXPECT_FALSE(is_keyword_line("$ x"));
  EXPECT_FALSE(is_keyword_line("NODE"));
}

// ---------------------------------------------------------------- DeckFile

TEST(DeckFile, LineNumbersSkipCommentsButCountThem) {
  DeckFile d;
  d.load_from_string("d.dyn", "title\n* comment\n$ another\n\ncard 5\n*---\ncard 7");
  ASSERT_EQ(d.lines().size(), 7u);
  const DeckLine* l = d.next_card();
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->number, 1);
  EXPECT_EQ(l->text, "title");
  l = d.next_card();  // the blank line is a card
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->number, 4);
  EXPECT_EQ(l->text, "");
  EXPECT_EQ(d.peek_card()->number, 5);
  l = d.next_card();
  EXPECT_EQ(l->number, 5);
  EXPECT_EQ(l->text, "card 5");
  l = d.next_card();
  EXPECT_EQ(l->number, 7);
  EXPECT_EQ(l->text, "card 7");  // no terminator on the last line
  EXPECT_TRUE(d.at_end());
  EXPECT_EQ(d.next_card(), nullptr);
  EXPECT_EQ(d.last_line_number(), 7);
}

TEST(DeckFile, CrLfLineEndings) {
  DeckFile d;
  d.load_from_string("d.dyn", "title\r\n*\r\n    1    2\r\n1.5\r\n");
  ASSERT_EQ(d.lines().size(), 4u);  // a final terminator does not add a line
  EXPECT_EQ(d.next_card()->text, "title");
  const DeckLine* l = d.next_card();
  EXPECT_EQ(l->number, 3);
  EXPECT_EQ(l->text, "    1    2");
  Diagnostics diag;
  Card c(d.name(), *l, "card", diag);
  EXPECT_EQ(c.i(6, 10, "b"), 2);
  l = d.next_card();
  EXPECT_EQ(l->number, 4);
  Card c4(d.name(), *l, "card", diag);
  EXPECT_DOUBLE_EQ(c4.e(1, 10, "x"), 1.5);
  EXPECT_EQ(diag.error_count(), 0);  // the \r is not a non-printable character
}

TEST(DeckFile, EmptyContent) {
  DeckFile d;
  d.load_from_string("e.dyn", "");
  EXPECT_TRUE(d.lines().empty());
  EXPECT_TRUE(d.at_end());
  EXPECT_EQ(d.last_line_number(), 0);
}

TEST(DeckFile, MissingFileReports3003) {
  DeckFile d;
  Diagnostics diag;
  EXPECT_FALSE(d.load("/nonexistent/dir/deck.dyn", diag));
  EXPECT_TRUE(diag.has(3003));
  EXPECT_EQ(diag.all()[0].where.file, "/nonexistent/dir/deck.dyn");
}

// ---------------------------------------------------------------- card-level errors

TEST(CardErrors, TextBeyondColumn80) {
  std::string line(80, ' ');
  line[4] = '1';
  line += "  xyz";
  OneCard t(line + "\n");
  Card c = t.card("control card 6");
  ASSERT_EQ(t.diag.all().size(), 1u);
  const Diagnostic& d = t.diag.all()[0];
  EXPECT_EQ(d.id, 1010);
  EXPECT_EQ(d.where.line, 1);
  EXPECT_EQ(d.where.col_first, 81);
  EXPECT_EQ(d.where.col_last, 85);
  EXPECT_EQ(d.where.found, "  xyz");
  EXPECT_TRUE(c.had_error());
}

TEST(CardErrors, BlanksBeyondColumn80AreAllowed) {
  std::string line(80, ' ');
  line += "      ";
  OneCard t(line + "\n");
  Card c = t.card();
  EXPECT_EQ(t.diag.error_count(), 0);
  EXPECT_FALSE(c.had_error());
}

TEST(CardErrors, Tab) {
  OneCard t("* comment\n    1\t   2\n");
  Card c = t.card("control card 3");
  ASSERT_GE(t.diag.all().size(), 1u);
  const Diagnostic& d = t.diag.all()[0];
  EXPECT_EQ(d.id, 1011);
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.where.col_first, 6);
  EXPECT_EQ(d.where.col_last, 6);
  EXPECT_EQ(d.where.card, "control card 3");
}

TEST(CardErrors, NonPrintable) {
  std::string s = "    1    2";
  s[7] = '\x01';
  OneCard t(s + "\n");
  Card c = t.card();
  ASSERT_GE(t.diag.all().size(), 1u);
  EXPECT_EQ(t.diag.all()[0].id, 1012);
  EXPECT_EQ(t.diag.all()[0].where.col_first, 8);
  EXPECT_NE(t.diag.all()[0].detail.find("byte 1"), std::string::npos);
  OneCard u("caf\xc3\xa9\n");  // non-ASCII is not printable in a deck either
  Card cu = u.card();
  ASSERT_GE(u.diag.all().size(), 1u);
  EXPECT_EQ(u.diag.all()[0].id, 1012);
  EXPECT_EQ(u.diag.all()[0].where.col_first, 4);
}

TEST(CardErrors, RenderedMessageNamesEverything) {
  OneCard t("* a comment\n* another\n1.0000e-05  abc     \n");
  Card c = t.card("control card 6");
  c.e(11, 20, "time-history interval");
  ASSERT_EQ(t.diag.all().size(), 1u);
  std::string r = render(t.diag.all()[0]);
  EXPECT_EQ(r, "deck.dyn:3: error 1002: control card 6, field \"time-history interval\" (cols 11-20): "
               "not a real number [found \"abc\"]");
}

TEST(Render, Forms) {
  Diagnostic d{1204, Severity::error, {}, "node 3 is never defined"};
  d.where.file = "x.dyn";
  EXPECT_EQ(render(d), "x.dyn: error 1204: missing definition: node 3 is never defined");
  Diagnostic w{2001, Severity::warning, {}, ""};
  w.where.file = "x.dyn";
  w.where.line = 12;
  w.where.card = "material 1 card 3";
  w.where.col_first = 1;
  w.where.col_last = 80;
  EXPECT_EQ(render(w), "x.dyn:12: warning 2001: material 1 card 3 (cols 1-80): " +
                           std::string(message_def(2001).text));
  Diagnostic g{1001, Severity::error, {}, ""};
  g.where.found = std::string("a\tb\x89") + std::string(50, 'z');
  g.where.show_found = true;
  std::string r = render(g);
  // control and non-ASCII bytes are escaped, long texts cut at 40 characters
  EXPECT_NE(r.find("[found \"a\\x09b\\x89zzz"), std::string::npos) << r;
  EXPECT_NE(r.find("...\"]"), std::string::npos) << r;
  for (char ch : r) EXPECT_TRUE(ch >= 32 && ch < 127) << r;
}

// ---------------------------------------------------------------- the message catalog

TEST(MessageCatalog, NumbersUniqueSortedAndInRanges) {
  const auto& cat = message_catalog();
  ASSERT_FALSE(cat.empty());
  std::set<int> seen;
  for (std::size_t k = 0; k < cat.size(); ++k) {
    const MessageDef& m = cat[k];
    EXPECT_TRUE(seen.insert(m.id).second) << "duplicate " << m.id;
    if (k > 0) {
      EXPECT_LT(cat[k - 1].id, m.id) << "catalog not sorted at " << m.id;
    }
    EXPECT_GE(m.id, 1000);
    EXPECT_LT(m.id, 6000);
    ASSERT_NE(m.text, nullptr);
    EXPECT_GT(std::string(m.text).size(), 3u) << m.id;
    // the ranges documented in messages.h
    Severity want = m.id < 2000   ? Severity::error
                    : m.id < 3000 ? Severity::warning
                    : m.id < 5000 ? Severity::error
                    : m.id < 5100 ? Severity::info
                    : m.id < 5110 ? Severity::warning  // run checks
                                  : Severity::info;    // their verdict
    EXPECT_EQ(m.severity, want) << m.id;
    EXPECT_EQ(&message_def(m.id), &m);
  }
}

TEST(MessageCatalog, NumbersTheInputPhaseDependsOn) {
  // Scripts grep for these numbers; their meaning must not change.
  struct { int id; const char* word; } keep[] = {
      {1001, "integer"}, {1002, "real"}, {1004, "end of file"}, {1005, "left over"},
      {1010, "column 80"}, {1011, "tab"}, {1012, "non-printable"}, {1101, "format"},
      {1102, "feature"}, {1103, "material type"}, {1104, "sliding interface"},
      {1200, "duplicate"}, {1202, "undefined node"}, {1203, "undefined material"},
      {1206, "volume"}, {1207, "density"}, {1208, "Young"}, {1209, "Poisson"},
      {1210, "tangent"}, {1211, "yield"}, {1212, "beta"}, {1213, "normal"},
      {1214, "termination"}, {1215, "scale factor"}, {1216, "boundary"}, {1218, "face"},
      {2001, "packed"}, {3003, "open"}};
  for (const auto& k : keep)
    EXPECT_NE(std::string(message_def(k.id).text).find(k.word), std::string::npos) << k.id;
}

TEST(Diagnostics, CountsAndBound) {
  Diagnostics d;
  d.add(2002, {});
  d.add(1001, {});
  EXPECT_EQ(d.error_count(), 1);
  EXPECT_EQ(d.warning_count(), 1);
  EXPECT_TRUE(d.has(1001));
  EXPECT_FALSE(d.has(1002));
  // different messages of one number: kMaxDistinctPerNumber lines, then one summary line
  const int n = Diagnostics::kMaxDistinctPerNumber + 1500;
  for (int k = 0; k < n; ++k) {
    Location l;
    l.file = "deck.k";
    l.line = k + 1;
    d.add(1002, l, "value " + std::to_string(k));
  }
  EXPECT_EQ(static_cast<int>(d.all().size()), Diagnostics::kMaxDistinctPerNumber + 2);
  EXPECT_EQ(d.error_count(), n + 1);
  EXPECT_EQ(d.count(1002), n);
  EXPECT_EQ(d.summarised(), 1500);
  // messages after the flood are kept, and every number appears in the printed text
  Location l;
  l.file = "deck.k";
  d.add(1311, l, "*NODE");
  std::ostringstream os;
  d.print(os);
  const std::string out = os.str();
  EXPECT_NE(out.find("error 1311: required keyword missing: *NODE"), std::string::npos);
  EXPECT_NE(out.find("1500 further message(s) of this number"), std::string::npos) << out.substr(out.size() - 400);
  EXPECT_EQ(out.find("not shown)"), std::string::npos);
}

TEST(Diagnostics, RepeatsOfOneCauseAreOneLine) {
  Diagnostics d;
  for (int e = 1; e <= 768; ++e) {
    Location l;
    l.file = "deck.k";
    l.line = 100 + e;
    l.card = "*ELEMENT_SOLID element " + std::to_string(e);
    l.field = "PID";
    d.add(1308, l, "part 3 is not defined by *PART");
  }
  Location l;
  l.file = "deck.k";
  l.line = 900;
  l.card = "*ELEMENT_SOLID element 900";
  l.field = "PID";
  d.add(1308, l, "part 4 is not defined by *PART");
  ASSERT_EQ(d.all().size(), 2u);
  EXPECT_EQ(d.times(0), 768);
  EXPECT_EQ(d.times(1), 1);
  EXPECT_EQ(d.count(1308), 769);
  EXPECT_EQ(d.error_count(), 769);
  std::ostringstream os;
  d.print(os);
  EXPECT_EQ(os.str(),
            "deck.k:101: error 1308: *ELEMENT_SOLID element 1, field \"PID\": reference to an undefined part: "
            "part 3 is not defined by *PART (768 times; also 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, ...)\n"
            "deck.k:900: error 1308: *ELEMENT_SOLID element 900, field \"PID\": reference to an undefined part: "
            "part 4 is not defined by *PART\n");
}
