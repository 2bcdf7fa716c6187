// *PARAMETER and *PARAMETER_EXPRESSION (docs/keyword-decks.md), read before every other keyword.
// *PARAMETER_EXPRESSION: one parameter a card, PRMR (the table's columns, keyword_cards.cpp:
// R or I, then the name) and EXPRESSION (the rest of the card); with a comma in
// the PRMR columns the card is free format, PRMR up to the first comma.  The expressions are
// evaluated after the plain *PARAMETER values, each when first needed, so they may refer to
// one another in any order; a cycle is an error.  I parameters take the value truncated toward
// zero (a Fortran assignment).

#include <cctype>
#include <cmath>
#include <map>

#include "impact3d/input/keyword_blocks.h"
#include "impact3d/input/keyword_families.h"
#include "impact3d/input/parameter_expression.h"

namespace impact3d::kw {

namespace {

struct ExpressionDef {
  std::string name;
  char type = 'R';
  std::string text;      // the expression
  Ref ref;               // the card (c1: the column of text[0])
  std::string keyword;   // as written
  enum State { pending, evaluating, done, failed } state = pending;
};

class ExpressionSet {
 public:
  ExpressionSet(ParamTable& params, Diagnostics& diag)
      : layout_(find_keyword_spec("PARAMETER_EXPRESSION")->card("")), params_(params), diag_(diag) {}

  void read_block(const Block& b) {
    for (std::size_t k = 0; k < b.data.size(); ++k)
      if (!is_blank(b.data[k].line->text)) read_card(b, b.data[k]);
  }

  void evaluate_all() {
    for (std::size_t j = 0; j < defs_.size(); ++j) evaluate(j);
  }

 private:
  void report(int id, const ExpressionDef& d, int c1, int c2, const char* field, const std::string& detail) {
    Ref r = d.ref;
    r.c1 = c1, r.c2 = c2;
    diag_.add(id, loc_of(r, d.keyword, field, false), detail);
  }

  // PRMR: the type letter and the name (upper case); false (reported) when it is not R or I
  // followed by a name.
  bool read_prmr(ExpressionDef& d, const std::string& prmr, int width) {
    const std::string t(trim_sv(prmr));
    std::string name = t.empty() ? std::string() : std::string(trim_sv(std::string_view(t).substr(1)));
    for (char& ch : name) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    d.type = t.empty() ? ' ' : char(std::toupper(static_cast<unsigned char>(t[0])));
    if ((d.type == 'R' || d.type == 'I') && !name.empty() && name.find(' ') == std::string::npos) {
      d.name = name;
      return true;
    }
    report(1006, d, 1, width, "PRMR", "'" + t + "': the type letter R or I followed by the parameter name");
    return false;
  }

  void read_card(const Block& b, const KLine& l) {
    const std::string_view line = l.line->text;
    const int width = layout_.columns(b.long_fmt, b.i10)[0];  // PRMR's columns (the table's)
    const std::size_t comma = line.find(',');
    const bool free = comma != std::string_view::npos && comma < std::size_t(width);
    const std::size_t split = free ? comma : std::min(line.size(), std::size_t(width));
    ExpressionDef d;
    d.ref.file = l.file;
    d.ref.line = l.line;
    d.keyword = b.keyword;
    if (!read_prmr(d, std::string(line.substr(0, split)), free ? int(comma) : width)) return;
    const std::size_t from = std::min(line.size(), free ? split + 1 : split);
    std::string_view rest = line.substr(from);
    const std::size_t lead = rest.find_first_not_of(' ');
    d.text = lead == std::string_view::npos ? std::string() : std::string(rtrim(rest.substr(lead)));
    d.ref.c1 = int(from + (lead == std::string_view::npos ? 0 : lead)) + 1;
    if (d.text.empty()) {
      report(1317, d, int(from) + 1, int(line.size() > from ? line.size() : from + 1), "EXPRESSION", "parameter " + d.name + " has no expression");
      return;
    }
    if (params_.count(d.name) || index_.count(d.name)) {
      report(1200, d, 1, width, "PRMR", "parameter " + d.name + " is defined twice");
      return;
    }
    index_.emplace(d.name, defs_.size());
    defs_.push_back(std::move(d));
  }

  // The lookup of the evaluator: a plain *PARAMETER, or another expression (evaluated now).
  bool value_of(const std::string& name, double& v, ExpressionError& e) {
    if (auto p = params_.find(name); p != params_.end()) {
      if (p->second.type == 'C') {
        e.id = 1310, e.text = "parameter " + name + " is text, not a number";
        return false;
      }
      v = p->second.value;
      return true;
    }
    auto it = index_.find(name);
    if (it == index_.end()) {
      e.id = 1310, e.text = "parameter " + name + " is not defined by *PARAMETER or *PARAMETER_EXPRESSION";
      return false;
    }
    const ExpressionDef& d = defs_[it->second];
    if (d.state == ExpressionDef::evaluating) {
      e.id = 1317, e.text = "parameter " + name + " depends on itself";
      return false;
    }
    evaluate(it->second);
    if (d.state == ExpressionDef::failed) {
      e.id = 0;  // (its own error is reported)
      return false;
    }
    v = params_.at(name).value;
    return true;
  }

  void evaluate(std::size_t j) {
    if (defs_[j].state != ExpressionDef::pending) return;
    defs_[j].state = ExpressionDef::evaluating;
    double v = 0;
    ExpressionError e;
    const ParameterLookup lookup = [this](const std::string& n, double& x, ExpressionError& err) { return value_of(n, x, err); };
    const bool ok = evaluate_expression(defs_[j].text, lookup, v, e);
    ExpressionDef& d = defs_[j];  // (the recursion may have grown nothing: defs_ is fixed by now)
    if (!ok) {
      d.state = ExpressionDef::failed;
      const int col = d.ref.c1 + int(e.pos);
      if (e.id != 0)
        report(e.id, d, col, col, "EXPRESSION",
               "character " + std::to_string(e.pos + 1) + " of '" + d.text + "': " + e.text);
      return;
    }
    Param p;
    p.type = d.type;
    p.value = d.type == 'I' ? std::trunc(v) : v;
    params_[d.name] = p;
    d.state = ExpressionDef::done;
  }

  const KeywordCardLayout& layout_;  // PRMR, EXPRESSION (keyword_cards.cpp)
  ParamTable& params_;
  Diagnostics& diag_;
  std::vector<ExpressionDef> defs_;
  std::map<std::string, std::size_t> index_;
};

}  // namespace

// *PARAMETER: cards of four pairs PRMR (type R, I or C, then the name) and VAL, by the table
// (keyword_cards.cpp), then *PARAMETER_EXPRESSION.  Read before every other keyword, so a
// reference may come before or after its definition; a name defined twice is error 1200.
void read_parameters(const std::vector<Block>& blocks, ParamTable& params, Diagnostics& diag) {
  const KeywordCardLayout& layout = find_keyword_spec("PARAMETER")->card("");
  for (const Block& b : blocks) {
    if (b.name != "PARAMETER") continue;
    for (std::size_t k = 0; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      KeywordValues v(b, k, layout, diag, nullptr);  // no substitution inside *PARAMETER
      KCard& c = v.card();
      for (std::size_t f = 0; f + 1 < layout.fields.size(); f += 2) {
        const KeywordField &prmr = layout.fields[f], &val = layout.fields[f + 1];
        std::string pr = c.literal(prmr.index);
        if (pr.empty()) continue;
        const char type = char(std::toupper(static_cast<unsigned char>(pr[0])));
        std::string name = pr.substr(1);
        const std::size_t s = name.find_first_not_of(' ');
        name = s == std::string::npos ? std::string() : name.substr(s);
        for (char& ch : name) ch = char(std::toupper(static_cast<unsigned char>(ch)));
        if ((type != 'R' && type != 'I' && type != 'C') || name.empty() || name.find(' ') != std::string::npos) {
          c.error(1006, prmr.index, prmr.name, "a type letter R, I or C followed by the parameter name");
          continue;
        }
        Param p;
        p.type = type;
        if (type == 'C') {
          p.text = c.literal(val.index);
        } else if (type == 'I') {
          p.value = double(c.i(val.index, val.name));
        } else {
          p.value = c.r(val.index, val.name);
        }
        if (!params.emplace(name, p).second) c.error(1200, prmr.index, prmr.name, "parameter " + name + " is defined twice");
      }
    }
  }
  // *PARAMETER_EXPRESSION
  ExpressionSet set(params, diag);
  for (const Block& b : blocks)
    if (b.name == "PARAMETER_EXPRESSION") set.read_block(b);
  set.evaluate_all();
}

}  // namespace impact3d::kw
