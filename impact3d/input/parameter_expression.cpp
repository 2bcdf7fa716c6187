#include "impact3d/input/parameter_expression.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace impact3d {

namespace {

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_exponent_letter(char c) { return c == 'e' || c == 'E' || c == 'd' || c == 'D'; }

// A function of the expression language: its name, how many arguments (max_args -1: any
// number from min_args on) and its value; `domain` is empty or says why the arguments are bad.
struct Function {
  const char* name;
  int min_args, max_args;
  double (*eval)(const std::vector<double>& a, std::string& domain);
};

double f_sin(const std::vector<double>& a, std::string&) { return std::sin(a[0]); }
double f_cos(const std::vector<double>& a, std::string&) { return std::cos(a[0]); }
double f_tan(const std::vector<double>& a, std::string&) { return std::tan(a[0]); }
double f_sinh(const std::vector<double>& a, std::string&) { return std::sinh(a[0]); }
double f_cosh(const std::vector<double>& a, std::string&) { return std::cosh(a[0]); }
double f_tanh(const std::vector<double>& a, std::string&) { return std::tanh(a[0]); }
double f_atan(const std::vector<double>& a, std::string&) { return std::atan(a[0]); }
double f_exp(const std::vector<double>& a, std::string&) { return std::exp(a[0]); }
double f_abs(const std::vector<double>& a, std::string&) { return std::fabs(a[0]); }
double f_asin(const std::vector<double>& a, std::string& d) {
  if (!(std::fabs(a[0]) <= 1)) d = "asin of a value outside [-1, 1]";
  return std::asin(a[0]);
}
double f_acos(const std::vector<double>& a, std::string& d) {
  if (!(std::fabs(a[0]) <= 1)) d = "acos of a value outside [-1, 1]";
  return std::acos(a[0]);
}
double f_atan2(const std::vector<double>& a, std::string& d) {
  if (a[0] == 0 && a[1] == 0) d = "atan2(0, 0) is undefined";
  return std::atan2(a[0], a[1]);
}
double f_sqrt(const std::vector<double>& a, std::string& d) {
  if (a[0] < 0) d = "sqrt of a negative value";
  return std::sqrt(a[0]);
}
double f_log(const std::vector<double>& a, std::string& d) {
  if (!(a[0] > 0)) d = "log of a value that is not positive";
  return std::log(a[0]);
}
double f_log10(const std::vector<double>& a, std::string& d) {
  if (!(a[0] > 0)) d = "log10 of a value that is not positive";
  return std::log10(a[0]);
}
double f_min(const std::vector<double>& a, std::string&) {
  double v = a[0];
  for (double x : a) v = x < v ? x : v;
  return v;
}
double f_max(const std::vector<double>& a, std::string&) {
  double v = a[0];
  for (double x : a) v = x > v ? x : v;
  return v;
}

const Function kFunctions[] = {
    {"SIN", 1, 1, f_sin},     {"COS", 1, 1, f_cos},     {"TAN", 1, 1, f_tan},       {"ASIN", 1, 1, f_asin},
    {"ACOS", 1, 1, f_acos},   {"ATAN", 1, 1, f_atan},   {"ATAN2", 2, 2, f_atan2},   {"SINH", 1, 1, f_sinh},
    {"COSH", 1, 1, f_cosh},   {"TANH", 1, 1, f_tanh},   {"SQRT", 1, 1, f_sqrt},     {"EXP", 1, 1, f_exp},
    {"LOG", 1, 1, f_log},     {"LOG10", 1, 1, f_log10}, {"ABS", 1, 1, f_abs},       {"MIN", 2, -1, f_min},
    {"MAX", 2, -1, f_max},
};

const Function* find_function(const std::string& upper) {
  for (const Function& f : kFunctions)
    if (upper == f.name) return &f;
  return nullptr;
}

// The parser: one method per grammar rule, each evaluating as it goes.
//   expr    := term {('+' | '-') term}
//   term    := unary {('*' | '/') unary}
//   unary   := ('+' | '-') unary | power
//   power   := primary [('**' | '^') unary]
//   primary := number | name | name '(' expr {',' expr} ')' | '(' expr ')'   (name: ['&'] letters...)
class Parser {
 public:
  Parser(std::string_view t, const ParameterLookup& lookup, ExpressionError& err) : t_(t), lookup_(lookup), err_(err) {}

  bool whole(double& v) {
    if (!expr(v)) return false;
    skip();
    if (p_ < t_.size()) return fail(p_, "unexpected '" + std::string(1, t_[p_]) + "'");
    if (!std::isfinite(v)) return fail(0, "the value is not finite (overflow)");
    return true;
  }

 private:
  void skip() {
    while (p_ < t_.size() && (t_[p_] == ' ' || t_[p_] == '\t')) ++p_;
  }
  bool at(char c) {
    skip();
    return p_ < t_.size() && t_[p_] == c;
  }
  bool at_power() {
    skip();
    if (p_ < t_.size() && t_[p_] == '^') return true;
    return p_ + 1 < t_.size() && t_[p_] == '*' && t_[p_ + 1] == '*';
  }
  bool fail(std::size_t pos, std::string why, int id = 1317) {
    err_.id = id;
    err_.pos = pos;
    err_.text = std::move(why);
    return false;
  }

  bool expr(double& v) {
    if (!term(v)) return false;
    while (at('+') || at('-')) {
      const char op = t_[p_++];
      double r = 0;
      if (!term(r)) return false;
      v = op == '+' ? v + r : v - r;
    }
    return true;
  }

  bool term(double& v) {
    if (!unary(v)) return false;
    while ((at('*') && !at_power()) || at('/')) {
      const std::size_t op_pos = p_;
      const char op = t_[p_++];
      double r = 0;
      if (!unary(r)) return false;
      if (op == '/' && r == 0) return fail(op_pos, "division by zero");
      v = op == '*' ? v * r : v / r;
    }
    return true;
  }

  // (every nesting passes here: the depth is bounded, so a hostile line cannot exhaust the stack;
  // the depth is the thread's, shared by the expressions a lookup evaluates inside this one, so a
  // chain of expressions that name one another counts too)
  bool unary(double& v) {
    if (depth_ >= kMaxDepth)
      return fail(p_, "nested more than " + std::to_string(kMaxDepth) +
                          " deep (signs and parentheses, and the expressions of the parameters it names, together)");
    ++depth_;
    bool ok = true;
    if (at('+') || at('-')) {
      const char op = t_[p_++];
      ok = unary(v);
      if (ok && op == '-') v = -v;
    } else {
      ok = power(v);
    }
    --depth_;
    return ok;
  }

  bool power(double& v) {
    if (!primary(v)) return false;
    if (!at_power()) return true;
    const std::size_t op_pos = p_;
    p_ += t_[p_] == '^' ? 1 : 2;
    double e = 0;
    if (!unary(e)) return false;  // right associative: a ** b ** c = a ** (b ** c); a ** -b
    if (v == 0 && e < 0) return fail(op_pos, "zero to a negative power");
    if (v < 0 && e != std::floor(e)) return fail(op_pos, "a negative value to a fractional power");
    v = std::pow(v, e);
    return true;
  }

  bool primary(double& v) {
    skip();
    if (p_ >= t_.size()) return fail(p_, "the expression ends where a value is expected");
    const char c = t_[p_];
    if (c == '(') {
      ++p_;
      if (!expr(v)) return false;
      if (!at(')')) return fail(p_, "')' expected");
      ++p_;
      return true;
    }
    if (is_digit(c) || c == '.') return number(v);
    if (c == '&' || is_name_start(c)) return name(v);
    return fail(p_, "unexpected '" + std::string(1, c) + "' where a value is expected");
  }

  // A Fortran number: digits [. digits] [(e | d) [sign] digits].
  bool number(double& v) {
    const std::size_t start = p_;
    while (p_ < t_.size() && is_digit(t_[p_])) ++p_;
    if (p_ < t_.size() && t_[p_] == '.') ++p_;
    while (p_ < t_.size() && is_digit(t_[p_])) ++p_;
    if (p_ == start + 1 && t_[start] == '.') return fail(start, "a number needs a digit");
    if (p_ < t_.size() && is_exponent_letter(t_[p_])) {
      std::size_t q = p_ + 1;
      if (q < t_.size() && (t_[q] == '+' || t_[q] == '-')) ++q;
      if (q >= t_.size() || !is_digit(t_[q])) return fail(p_, "an exponent needs digits");
      p_ = q;
      while (p_ < t_.size() && is_digit(t_[p_])) ++p_;
    }
    std::string s(t_.substr(start, p_ - start));
    for (char& ch : s)
      if (ch == 'd' || ch == 'D') ch = 'e';
    v = std::strtod(s.c_str(), nullptr);
    return true;
  }

  // A parameter (with or without '&'), pi, or a function call.
  bool name(double& v) {
    const std::size_t start = p_;
    const bool amp = t_[p_] == '&';
    if (amp) ++p_;
    if (p_ >= t_.size() || !is_name_start(t_[p_])) return fail(start, "'&' must be followed by a parameter name");
    std::string n;
    while (p_ < t_.size() && is_name_char(t_[p_])) n += char(std::toupper(static_cast<unsigned char>(t_[p_++])));
    if (!amp && at('(')) return call(n, start, v);
    if (lookup_(n, v, err_)) return true;
    if (!amp && n == "PI" && err_.id == 1310) {  // pi, unless a parameter PI is defined
      err_ = {};
      v = 3.14159265358979323846;
      return true;
    }
    err_.pos = start;
    return false;
  }

  bool call(const std::string& n, std::size_t start, double& v) {
    const Function* f = find_function(n);
    if (!f) return fail(start, n + " is not a function (sin cos tan asin acos atan atan2 sinh cosh tanh sqrt exp log log10 abs min max)");
    ++p_;  // '('
    std::vector<double> args;
    while (true) {
      double a = 0;
      if (!expr(a)) return false;
      args.push_back(a);
      if (at(',')) {
        ++p_;
        continue;
      }
      if (!at(')')) return fail(p_, "',' or ')' expected");
      ++p_;
      break;
    }
    const int n_args = int(args.size());
    if (n_args < f->min_args || (f->max_args >= 0 && n_args > f->max_args))
      return fail(start, n + " takes " + (f->max_args < 0 ? std::to_string(f->min_args) + " or more" : std::to_string(f->min_args)) +
                             " argument(s), given " + std::to_string(n_args));
    std::string domain;
    v = f->eval(args, domain);
    if (!domain.empty()) return fail(start, domain);
    return true;
  }

  static constexpr int kMaxDepth = 200;
  std::string_view t_;
  const ParameterLookup& lookup_;
  ExpressionError& err_;
  std::size_t p_ = 0;
  static thread_local int depth_;
};

thread_local int Parser::depth_ = 0;

}  // namespace

bool evaluate_expression(std::string_view text, const ParameterLookup& lookup, double& value, ExpressionError& err) {
  err = {};
  Parser p(text, lookup, err);
  return p.whole(value);
}

}  // namespace impact3d
