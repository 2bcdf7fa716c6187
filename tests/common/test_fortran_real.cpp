// parse_fortran_real reads with std::from_chars (strtod only for what from_chars leaves out of
// range).  These tests hold it to the reference it replaced, kept here: the field normalised
// into a std::string and read with strtod.  Same status and the same bits (-0.0 included) on
// hand-picked Fortran forms and on many generated strings.

#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "common/cards.h"

using namespace impact3d;

namespace {

// The implementation before the from_chars fast path (reference).
FieldStatus reference_parse_fortran_real(std::string_view text, double& value) {
  std::size_t b = 0, e = text.size();
  while (b < e && text[b] == ' ') ++b;
  while (e > b && text[e - 1] == ' ') --e;
  const std::string_view s = text.substr(b, e - b);
  if (s.empty()) return FieldStatus::blank;
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  std::string norm;
  std::size_t p = 0;
  if (s[p] == '+' || s[p] == '-') norm += s[p++];
  int mant_digits = 0;
  while (p < s.size() && is_digit(s[p])) { norm += s[p++]; ++mant_digits; }
  if (p < s.size() && s[p] == '.') {
    norm += s[p++];
    while (p < s.size() && is_digit(s[p])) { norm += s[p++]; ++mant_digits; }
  }
  if (mant_digits == 0) return FieldStatus::bad;
  if (p < s.size()) {
    char c = s[p];
    if (c == 'e' || c == 'E' || c == 'd' || c == 'D') {
      ++p;
    } else if (c != '+' && c != '-') {
      return FieldStatus::bad;
    }
    norm += 'e';
    if (p < s.size() && (s[p] == '+' || s[p] == '-')) norm += s[p++];
    int exp_digits = 0;
    while (p < s.size() && is_digit(s[p])) { norm += s[p++]; ++exp_digits; }
    if (exp_digits == 0 || exp_digits > 4 || p != s.size()) return FieldStatus::bad;
  }
  errno = 0;
  char* end = nullptr;
  double v = std::strtod(norm.c_str(), &end);
  if (end != norm.c_str() + norm.size()) return FieldStatus::bad;
  if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0)) return FieldStatus::bad;
  value = v;
  return FieldStatus::ok;
}

std::uint64_t bits(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

// Same status, and on ok the same bits; on blank/bad the value is left alone by both.
void expect_same(const std::string& s) {
  double a = 12345.0, b = 12345.0;
  const FieldStatus sa = parse_fortran_real(s, a);
  const FieldStatus sb = reference_parse_fortran_real(s, b);
  ASSERT_EQ(int(sa), int(sb)) << '"' << s << '"';
  ASSERT_EQ(bits(a), bits(b)) << '"' << s << "\" " << a << " vs " << b;
}

}  // namespace

TEST(FortranReal, SameBitsAsStrtodOnFortranForms) {
  const std::vector<std::string> cases = {
      "", " ", "          ", "0", "-0", "+0", "0.", "-0.", ".0", "-.0", "0.0", "-0.0e0", "1",
      "15", "-15", "+15", "1.", ".5", "-.5", "+.5", "5.", "1.5", "  1.5  ", "1.5e3", "1.5E+03",
      "1.5e-3", "2.5D-3", "2.5d+3", "2.5D3", "1.0-5", "1.0+5", "1-5", "-1.0-05", ".5-3", "5.+2",
      "1.5e", "1.5e+", "1.5-", "e5", "d5", ".", "-.", "+", "-", "+-1", "1..5", "1.5.", "1,5",
      "1.5x", "x1.5", "1 5", "1.5 e3", "1.5e 3", "1.5e3 ", "1.5e12345", "1.5e1234", "1e308",
      "1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308", "2e308",
      "-1e309", "1e-307", "2.2250738585072014e-308", "2.2250738585072011e-308", "4.9e-324",
      "5e-324", "2.4703282292062327e-324", "2.4703282292062328e-324", "1e-325", "-1e-400",
      "1e-9999", "9e9999", "0e9999", "0.000000000000000000000000000001", "123456789012345678901234567890",
      "0.1", "0.2", "0.3", "0.7", "1.1", "8.0e-5", "9.0000e-01", "-2.270e+02", "1.234567890e-03",
      "-1.234567890123e-03", "3.14159265358979323846264338327950288", "9007199254740993",
      "9007199254740992.5", "0.1000000000000000055511151231257827", "1.00000000000000011102230246251565404236316680908203125",
      "1.000000000000000111022302462515654042363166809082031250001", "117.0e9", "1.17e11", "8930.",
      "0.01.000000E8", ".000000E8", "1.000000E8", "inf", "nan", "-inf", "Infinity", "0x1p3",
      "1e+", "1e-", "1d", "1D+", "1.5\t", "\t1.5", "1.5\r"};
  for (const auto& s : cases) expect_same(s);
}

TEST(FortranReal, SameBitsAsStrtodOnGeneratedStrings) {
  std::mt19937_64 rng(20261124);
  const auto pick = [&](int n) { return int(rng() % std::uint64_t(n)); };
  const auto digits = [&](int n) {
    std::string d;
    for (int k = 0; k < n; ++k) d += char('0' + pick(10));
    return d;
  };
  for (int k = 0; k < 200000; ++k) {
    std::string s;
    if (pick(8) == 0) s += std::string(std::size_t(pick(4)), ' ');
    const int sign = pick(4);
    if (sign == 1) s += '-';
    if (sign == 2) s += '+';
    const int form = pick(4);
    if (form == 0) s += digits(1 + pick(20));
    else if (form == 1) s += digits(pick(10)) + "." + digits(pick(20));
    else if (form == 2) s += digits(1 + pick(3)) + "." + digits(1 + pick(17));
    else s += "." + digits(1 + pick(25));
    const int ex = pick(6);
    if (ex > 0) {
      static const char* marks[] = {"e", "E", "d", "D", ""};
      const std::string mark = marks[pick(5)];
      int v = pick(3) == 0 ? pick(400) : pick(40);
      std::string e = std::to_string(v);
      if (pick(3) == 0) e = std::string(std::size_t(pick(3)), '0') + e;
      const int es = pick(3);
      const std::string esign = es == 0 ? "-" : es == 1 ? "+" : "";
      if (mark.empty() && esign.empty()) s += "-" + e;  // bare exponent needs its sign
      else s += mark + esign + e;
    }
    if (pick(50) == 0) s[std::size_t(pick(int(s.size())))] = "x.+-eD 9"[pick(8)];
    if (pick(8) == 0) s += std::string(std::size_t(pick(4)), ' ');
    expect_same(s);
  }
}

TEST(FortranReal, SameBitsOnShortestAndPrintfForms) {
  // what the deck writers produce: %.17g, %.12e, %10.4e of random doubles over many decades
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mant(-10.0, 10.0);
  std::uniform_int_distribution<int> dec(-320, 306);
  char buf[64];
  for (int k = 0; k < 50000; ++k) {
    const double v = mant(rng) * std::pow(10.0, dec(rng));
    for (const char* f : {"%.17g", "%.12e", "%10.4e", "%.9e", "%g"}) {
      std::snprintf(buf, sizeof buf, f, v);
      expect_same(buf);
    }
  }
}
