#pragma once
// The expressions of *PARAMETER_EXPRESSION (docs/keyword-decks.md): numbers (Fortran forms:
// 1, 2.5, 1.e3, 4d-2), parameter names with or without '&', + - * /, ** and ^ (power, right
// associative, binding tighter than a leading sign: -2**2 = -4), parentheses, pi, and the
// functions sin cos tan asin acos atan atan2(y, x) sinh cosh tanh sqrt exp log log10 abs
// min(a, b, ...) max(a, b, ...) (angles in radians).  Names are case-insensitive.  Evaluated in
// double precision with the C library's functions, left to right.
//
// A small recursive-descent parser that evaluates as it parses; an error stops it and says
// where (0-based offset in the text) and why.

#include <functional>
#include <string>
#include <string_view>

namespace impact3d {

struct ExpressionError {
  int id = 0;            // message id (1317 bad expression, 1310 undefined name; 0: already reported)
  std::size_t pos = 0;   // 0-based offset of the offending character in the text
  std::string text;      // what is wrong
};

// The value of a parameter named `upper_name` (upper case): true with `value`, or false with
// `err.id` and `err.text` set (err.pos is filled in by the evaluator).
using ParameterLookup = std::function<bool(const std::string& upper_name, double& value, ExpressionError& err)>;

// Evaluates `text`; false with `err` on a syntax error, an undefined name, a math error
// (division by zero, a function outside its domain) or a result that is not finite.
bool evaluate_expression(std::string_view text, const ParameterLookup& lookup, double& value, ExpressionError& err);

}  // namespace impact3d
