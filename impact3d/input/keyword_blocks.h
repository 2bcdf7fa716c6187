#pragma once
// The keyword reader's cards and blocks (internal to impact3d/input/keyword_*.cpp): a keyword
// block (its keyword line and data lines, options, *CASE sections), one data card read by
// fields (fixed columns, long format, or at its commas; *PARAMETER references replaced) with
// every message naming file, line, card, field and columns, and the places of fields (Ref) for
// messages after the cards were read.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/cards.h"
#include "common/messages.h"
#include "impact3d/input/keyword_cards.h"

namespace impact3d::kw {

inline std::string upper(std::string_view v) {
  std::string s(v);
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}
inline std::string_view trim_sv(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}
inline std::string rtrim(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.remove_suffix(1);
  return std::string(s);
}
inline bool is_blank(std::string_view s) { return trim_sv(s).empty(); }

// Frees a vector's storage (v = {} would keep it).
template <class V>
void release(V& v) {
  V().swap(v);
}

// A place in a deck: file, line and columns of a field.
struct Ref {
  const DeckFile* file = nullptr;
  const DeckLine* line = nullptr;
  int c1 = 0, c2 = 0;
};

struct KLine {
  const DeckFile* file = nullptr;
  const DeckLine* line = nullptr;
};

// One data card of a keyword: fields by index, in fixed columns (widths) or, when the line has
// a comma, by comma-separated tokens.
// *PARAMETER values, by upper-case name: 'R' real, 'I' integer, 'C' text.
struct Param {
  char type = 'R';
  double value = 0;
  std::string text;
};
using ParamTable = std::map<std::string, Param>;

class KCard {
 public:
  KCard(const KLine& l, std::string card, const std::vector<int>& widths, Diagnostics& diag)
      : l_(l), card_(std::move(card)), diag_(diag) {
    const std::string_view t = l.line->text;
    free_ = t.find(',') != std::string::npos;
    if (free_) {
      std::size_t start = 0;
      while (true) {
        std::size_t comma = t.find(',', start);
        std::size_t end = comma == std::string::npos ? t.size() : comma;
        cols_.emplace_back(int(start) + 1, int(end));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    } else {
      int c = 1;
      for (int w : widths) {
        cols_.emplace_back(c, c + w - 1);
        c += w;
      }
    }
    for (std::size_t k = 0; k < t.size(); ++k) {
      unsigned char ch = static_cast<unsigned char>(t[k]);
      if (ch == '\t') {
        report(1011, int(k) + 1, int(k) + 1, nullptr, {}, false);
        break;
      }
      if ((ch < 32 || ch >= 127) && !(ch == '\r' && k + 1 == t.size())) {
        report(1012, int(k) + 1, int(k) + 1, nullptr, "byte " + std::to_string(int(ch)), false);
        break;
      }
    }
  }

  int fields() const { return int(cols_.size()); }
  void set_params(const ParamTable* p) { params_ = p; }
  // The field's text, with a *PARAMETER reference "&name" or "-&name" replaced by the value
  // (an undefined name is error 1310; the text is then left as it is, and fails as a number).
  std::string text(int k, const char* field = nullptr) {
    std::string t = literal(k);
    if (!params_ || t.empty()) return t;
    const bool neg = t[0] == '-' && t.size() > 1 && t[1] == '&';
    if (t[0] != '&' && !neg) return t;
    std::string name = t.substr(neg ? 2 : 1);
    for (char& ch : name) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    auto it = params_->find(name);
    if (it == params_->end() || it->second.type == 'C') {
      error(1310, k, field, it == params_->end() ? "parameter &" + name + " is not defined by *PARAMETER"
                                                   : "parameter &" + name + " is text, not a number");
      bad_.push_back(k);
      return {};
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", neg ? -it->second.value : it->second.value);
    return buf;
  }
  std::string literal(int k) const {
    if (k >= fields()) return {};
    const std::string_view t = l_.line->text;
    auto [c1, c2] = cols_[std::size_t(k)];
    if (std::size_t(c1 - 1) >= t.size()) return {};
    return std::string(trim_sv(std::string_view(t).substr(std::size_t(c1 - 1), std::size_t(c2 - c1 + 1))));
  }
  std::string raw(int k) const {  // untrimmed (titles)
    if (k >= fields()) return {};
    const std::string_view t = l_.line->text;
    auto [c1, c2] = cols_[std::size_t(k)];
    if (std::size_t(c1 - 1) >= t.size()) return {};
    return rtrim(t.substr(std::size_t(c1 - 1), std::size_t(c2 - c1 + 1)));
  }
  bool blank(int k) const { return literal(k).empty(); }
  // Field k failed to read (1001, 1002 or 1310 reported): later messages about it are left out.
  bool bad(int k) const { return std::find(bad_.begin(), bad_.end(), k) != bad_.end(); }

  long long i(int k, const char* field, long long def = 0) {
    std::string t;
    if (!number_text(k, field, t)) return def;
    long long v = def;
    const FieldStatus st = parse_fortran_int(t, v);
    if (st == FieldStatus::ok) return v;
    double r = 0;  // some tools write integer fields as reals with a zero fraction ("1.", "0.0")
    if (st == FieldStatus::bad && parse_fortran_real(t, r) == FieldStatus::ok && r == std::floor(r) && std::fabs(r) < 2e9)
      return static_cast<long long>(r);
    if (st == FieldStatus::bad) refuse(1001, k, field);
    return def;
  }
  double r(int k, const char* field, double def = 0.0) {
    std::string t;
    if (!number_text(k, field, t)) return def;
    double v = def;
    const FieldStatus st = parse_fortran_real(t, v);
    if (st == FieldStatus::bad) refuse(1002, k, field);
    return st == FieldStatus::ok ? v : def;
  }
  Ref ref(int k) const {
    Ref r;
    r.file = l_.file;
    r.line = l_.line;
    if (k >= 0 && k < fields()) {
      r.c1 = cols_[std::size_t(k)].first;
      r.c2 = cols_[std::size_t(k)].second;
    }
    return r;
  }
  void error(int id, int k, const char* field, std::string detail = {}) {
    if (id != 1001 && id != 1002 && std::find(bad_.begin(), bad_.end(), k) != bad_.end()) return;
    int c1 = 0, c2 = 0;
    if (k >= 0 && k < fields()) {
      c1 = cols_[std::size_t(k)].first;
      c2 = cols_[std::size_t(k)].second;
    }
    report(id, c1, c2, field, std::move(detail), k >= 0);
  }
  void note(int id, std::string detail = {}) { report(id, 0, 0, nullptr, std::move(detail), false); }
  const std::string& card() const { return card_; }
  void set_card(std::string c) { card_ = std::move(c); }
  int line() const { return l_.line->number; }
  const KLine& kline() const { return l_; }

 private:
  // The text of numeric field k, *PARAMETER references replaced; false if one is undefined
  // (reported).
  bool number_text(int k, const char* field, std::string& t) {
    const std::size_t nbad = bad_.size();
    t = text(k, field);
    return bad_.size() == nbad;
  }
  // A field that is not a number: the message, and no later one about it.
  void refuse(int id, int k, const char* field) {
    error(id, k, field);
    bad_.push_back(k);
  }
  void report(int id, int c1, int c2, const char* field, std::string detail, bool show_found) {
    Location loc;
    loc.file = l_.file->name();
    loc.line = l_.line->number;
    loc.card = card_;
    if (field) loc.field = field;
    loc.col_first = c1;
    loc.col_last = c2;
    if (show_found && c1 > 0) {
      const std::string_view t = l_.line->text;
      if (std::size_t(c1 - 1) < t.size())
        loc.found = std::string(trim_sv(std::string_view(t).substr(std::size_t(c1 - 1), std::size_t(c2 - c1 + 1))));
      loc.show_found = true;
    }
    diag_.add(id, loc, std::move(detail));
  }

  KLine l_;
  std::string card_;
  Diagnostics& diag_;
  bool free_ = false;
  std::vector<std::pair<int, int>> cols_;
  std::vector<int> bad_;
  const ParamTable* params_ = nullptr;
};

inline Ref field_ref(const KLine& l, const std::vector<int>& widths, int k) {
  Diagnostics quiet;  // the card was read already: anything about it was reported then
  return KCard(l, std::string(), widths, quiet).ref(k);
}

// Fast path for the bulk cards (*NODE, *ELEMENT_SOLID): a card with no comma, no '&'
// (*PARAMETER reference) and only printable ASCII is read by columns without a KCard when every
// field reads as a number (or is blank) and passes its checks, so that no message can come from
// it; anything else is read again, the normal way, by the code that reports every problem.
inline bool plain_keyword_card(std::string_view t) {
  unsigned bad = 0;  // no early exit: the loop vectorises
  for (char ch : t) {
    const unsigned char c = static_cast<unsigned char>(ch);
    bad |= static_cast<unsigned>(c - 32u >= 95u) | static_cast<unsigned>(c == ',') | static_cast<unsigned>(c == '&');
  }
  return bad == 0;
}
// Field k (0-based) of a plain card with these widths, as KCard::i / KCard::r read it: blank is 0.
struct PlainFields {
  std::string_view t;
  const std::vector<int>& widths;
  int c1[20] = {};
  PlainFields(std::string_view text, const std::vector<int>& w) : t(text), widths(w) {
    int c = 1;
    for (std::size_t k = 0; k < w.size() && k < 20; ++k) {
      c1[k] = c;
      c += w[k];
    }
  }
  std::string_view field(int k) const { return card_columns(t, c1[k], c1[k] + widths[std::size_t(k)] - 1); }
  bool i(int k, int& v) const {
    long long x = 0;
    const FieldStatus st = parse_fortran_int(field(k), x);
    if (st == FieldStatus::bad) return false;
    v = st == FieldStatus::ok ? int(x) : 0;
    return true;
  }
  bool r(int k, double& v) const {
    double x = 0;
    const FieldStatus st = parse_fortran_real(field(k), x);
    if (st == FieldStatus::bad) return false;
    v = st == FieldStatus::ok ? x : 0.0;
    return true;
  }
};

// The data lines of a block, all in one file: 4-byte indices into the file's lines (a block
// may hold millions of lines), read back as KLine values.
class BlockLines {
 public:
  void push_back(const KLine& l) {
    file_ = l.file;
    idx_.push_back(std::uint32_t(l.line - l.file->lines().data()));
  }
  std::size_t size() const { return idx_.size(); }
  bool empty() const { return idx_.empty(); }
  KLine operator[](std::size_t k) const { return {file_, file_->lines().data() + idx_[k]}; }
  void swap(BlockLines& o) noexcept {
    std::swap(file_, o.file_);
    idx_.swap(o.idx_);
  }

  class iterator {
   public:
    iterator(const BlockLines* b, std::size_t k) : b_(b), k_(k) {}
    KLine operator*() const { return (*b_)[k_]; }
    iterator& operator++() {
      ++k_;
      return *this;
    }
    bool operator!=(const iterator& o) const { return k_ != o.k_; }

   private:
    const BlockLines* b_;
    std::size_t k_;
  };
  iterator begin() const { return {this, 0}; }
  iterator end() const { return {this, idx_.size()}; }

 private:
  const DeckFile* file_ = nullptr;
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> idx_;
};

struct Block {
  std::string name;     // upper case, suffix removed
  std::string keyword;  // as written (for messages)
  KLine kw;
  bool long_fmt = false, i10 = false;
  bool title_opt = false, id_opt = false;  // _TITLE / _ID option cards
  bool moving_opt = false;                 // *RIGIDWALL_PLANAR_MOVING: card 3 MASS, V0
  std::vector<int> cases;                  // the *CASE_BEGIN_n sections (and CID=n) it is in
  BlockLines data;
};

inline Location loc_of(const Ref& r, const std::string& card, const char* field = nullptr, bool found = true) {
  Location loc;
  if (r.file) loc.file = r.file->name();
  if (r.line) loc.line = r.line->number;
  loc.card = card;
  if (field) loc.field = field;
  if (field) {  // columns only with a field
    loc.col_first = r.c1;
    loc.col_last = r.c2;
  }
  if (found && field && r.line && r.c1 > 0) {
    const std::string_view t = r.line->text;
    if (std::size_t(r.c1 - 1) < t.size())
      loc.found = std::string(trim_sv(std::string_view(t).substr(std::size_t(r.c1 - 1), std::size_t(r.c2 - r.c1 + 1))));
    loc.show_found = true;
  }
  return loc;
}

inline std::string at(const Ref& r) {
  if (!r.file || !r.line) return "";
  return r.file->name() + ":" + std::to_string(r.line->number);
}

// One card of a block read by its table (keyword_cards.h) into named values: a field is read
// when first asked for (rest(): every field not read yet, in the table's order), with
// 1001/1002/1310 for bad text; a blank field (and a 0 where the table says so) takes its blank
// value; once the field at a check point is read, the table's checks of the fields checked
// there give their messages.  So the messages come in the order the family reads the fields,
// its own checks between them.  The card is named in messages as the keyword and the table's
// card label (card().set_card renames it, e.g. once its id is read).
class KeywordValues {
 public:
  // label: the card's name after the keyword in messages (default: the table's card label)
  KeywordValues(const Block& b, std::size_t k, const KeywordCardLayout& layout, Diagnostics& diag, const ParamTable* params,
                const std::string* label = nullptr);
  double operator[](std::string_view name) { return value(index(name)); }
  double nth(std::size_t k) { return value(k); }  // the table's k-th field (names that repeat)
  long long integer_at(std::size_t k) { return static_cast<long long>(value(k)); }
  long long integer(std::string_view name) { return static_cast<long long>(value(index(name))); }
  bool blank(std::string_view name) const { return card_.blank(layout_.fields[index(name)].index); }
  // A text field (FieldKind::text), upper case and trimmed.
  std::string text(std::string_view name) const { return upper(card_.literal(layout_.fields[index(name)].index)); }
  // Read; no check of the table held for the field (its value may be used as it is).
  bool passed(std::string_view name) { return value(index(name)), passed_[index(name)] != 0; }
  Ref ref(std::string_view name) const { return card_.ref(layout_.fields[index(name)].index); }
  // The table's checks of a field checked where the reader says (kByReader): read, checked
  // now; true if none held.
  bool check(std::string_view name);
  void error(int id, std::string_view name, std::string detail = {});
  KeywordValues& rest();
  KCard& card() { return card_; }

 private:
  std::size_t index(std::string_view name) const;
  double value(std::size_t k);
  void check_field(std::size_t k);
  const KeywordCardLayout& layout_;
  KCard card_;
  std::vector<double> values_;
  std::vector<char> read_, passed_;
};

// The option cards (_ID / _TITLE) at the start of a block: the number of lines they use.
inline std::size_t option_cards(const Block& b) { return (b.title_opt || b.id_opt) && !b.data.empty() ? 1 : 0; }

// An ID card (ID, HEADING) among the data cards of an _ID keyword, as ANSA and LS-PrePost
// write several definitions under one keyword: the first card of the block, or an integer id
// followed by blank columns or by a heading that starts with a letter in column 11 (a data
// card has a number or a blank there).
inline bool is_id_card(const Block& b, std::size_t k) {
  if (!b.id_opt) return false;
  std::size_t first = 0;
  while (first < b.data.size() && is_blank(b.data[first].line->text)) ++first;
  if (k == first) return true;
  Diagnostics quiet;
  KCard c(b.data[k], b.keyword, std::vector<int>(8, b.long_fmt ? 20 : 10), quiet);
  long long id = 0;
  if (parse_fortran_int(c.literal(0), id) != FieldStatus::ok) return false;
  const std::string heading = c.literal(1);
  if (!heading.empty()) return std::isalpha(static_cast<unsigned char>(heading[0])) != 0;
  for (int f = 2; f < c.fields(); ++f)
    if (!c.literal(f).empty()) return false;
  return true;
}

// The state every family reader shares: messages, *PARAMETER values, the keywords given once.
struct KeywordContext {
  Diagnostics& diag;
  const ParamTable& params;
  std::map<std::string, Ref> seen_once;
  // The card's values, every field read (values) or each when first asked for (fields).
  KeywordValues values(const Block& b, std::size_t k, const KeywordCardLayout& layout) {
    KeywordValues v(b, k, layout, diag, &params);
    v.rest();
    return v;
  }
  KeywordValues fields(const Block& b, std::size_t k, const KeywordCardLayout& layout, const std::string* label = nullptr) {
    return KeywordValues(b, k, layout, diag, &params, label);
  }
  // An id a keyword defines, with the *INCLUDE_TRANSFORM offset of its file (the reader's).
  std::function<int(int id, const Block& b, char kind)> xid;
  // A keyword that is read once: warning 2010 naming the earlier one when given again.
  void once(const Block& b);
  // Error 1316: the block ends before a required card.
  void missing_card(const Block& b, const char* what);
  // k: the block's first card after its option cards (_ID / _TITLE); false (error 1316 naming
  // `what`) if there is none.
  bool first_card(const Block& b, std::size_t& k, const char* what = "card 1") {
    k = option_cards(b);
    if (k < b.data.size()) return true;
    missing_card(b, what);
    return false;
  }
};

}  // namespace impact3d::kw
