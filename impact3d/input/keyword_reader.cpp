// LS-DYNA keyword-deck reader.  Two passes: the deck and its *INCLUDE files are cut into
// keyword blocks (keyword line + data lines, '$' comments dropped), every supported block is
// parsed into raw records by fields (fixed columns, long/I10 widths, or comma free format), and
// the records are then resolved into the Model: ids renumbered 1..N, parts -> materials, sets
// -> nodes and segments, contacts -> sliding interfaces.  Every problem is reported, with file,
// line, keyword/card, field and columns, through the message catalog.  README.md ("Keyword
// decks") lists the keywords and fields.

#include "impact3d/input/keyword_reader.h"
#include "impact3d/material/material_types.h"

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/element_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace impact3d {

namespace {

std::string upper(std::string_view v) {
  std::string s(v);
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}
std::string_view trim_sv(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}
std::string rtrim(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.remove_suffix(1);
  return std::string(s);
}
bool is_blank(std::string_view s) { return trim_sv(s).empty(); }

// Frees a vector's storage (v = {} would keep it).
template <class V>
void release(V& v) {
  V().swap(v);
}

// Boundary code 0-7 <-> fixed translational components (bit 0 x, bit 1 y, bit 2 z).
int bc_bits(int code) {
  return (bc_fixes_x(code) ? 1 : 0) | (bc_fixes_y(code) ? 2 : 0) | (bc_fixes_z(code) ? 4 : 0);
}
int bc_code(int bits) {
  static const int code[8] = {0, 1, 2, 4, 3, 6, 5, 7};  // index = bits: x=1, y=2, z=4
  return code[bits & 7];
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

  long long i(int k, const char* field, long long def = 0) {
    long long v = def;
    const std::size_t nbad = bad_.size();
    const std::string t = text(k, field);
    if (bad_.size() != nbad) return def;  // an undefined parameter (reported)
    FieldStatus st = parse_fortran_int(t, v);
    if (st == FieldStatus::ok) return v;
    if (st == FieldStatus::bad) {
      // Some tools write integer fields as reals with a zero fraction ("1.", "0.0").
      double r = 0;
      if (parse_fortran_real(t, r) == FieldStatus::ok && r == std::floor(r) &&
          std::fabs(r) < 2e9)
        return static_cast<long long>(r);
      error(1001, k, field);
      bad_.push_back(k);
    }
    return def;
  }
  double r(int k, const char* field, double def = 0.0) {
    double v = def;
    const std::size_t nbad = bad_.size();
    const std::string t = text(k, field);
    if (bad_.size() != nbad) return def;  // an undefined parameter (reported)
    FieldStatus st = parse_fortran_real(t, v);
    if (st == FieldStatus::ok) return v;
    if (st == FieldStatus::bad) {
      error(1002, k, field);
      bad_.push_back(k);
    }
    return def;
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

Ref field_ref(const KLine& l, const std::vector<int>& widths, int k) {
  Diagnostics quiet;  // the card was read already: anything about it was reported then
  return KCard(l, std::string(), widths, quiet).ref(k);
}

// Fast path for the bulk cards (*NODE, *ELEMENT_SOLID): a card with no comma, no '&'
// (*PARAMETER reference) and only printable ASCII is read by columns without a KCard when every
// field reads as a number (or is blank) and passes its checks, so that no message can come from
// it; anything else is read again, the normal way, by the code that reports every problem.
bool plain_keyword_card(std::string_view t) {
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
  BlockLines data;
};

// Raw records, before resolution.  Nodes and solids are the bulk of a deck: they keep their
// card (file and line) and the widths it was read with, and find the columns of a field again
// (field_ref) only when a message needs them.

// The place of field k of a card read with these widths (or at its commas).
Ref field_ref(const KLine& l, const std::vector<int>& widths, int k);

// *NODE field widths: 0 standard (I8 3E16 I8 I8), 1 long (6 x 20), 2 I10 (I10 3E16 I10 I10).
const std::vector<int>& node_widths(int format) {
  static const std::vector<int> w[3] = {{8, 16, 16, 16, 8, 8}, {20, 20, 20, 20, 20, 20}, {10, 16, 16, 16, 10, 10}};
  return w[format];
}
// *ELEMENT_SOLID widths: n fields (2 or 10) of an id width (8, 10 or 20).
const std::vector<int>& id_widths(int n, int idw) {
  static const std::vector<int> w[2][3] = {
      {std::vector<int>(2, 8), std::vector<int>(2, 10), std::vector<int>(2, 20)},
      {std::vector<int>(10, 8), std::vector<int>(10, 10), std::vector<int>(10, 20)}};
  return w[n == 2 ? 0 : 1][idw == 8 ? 0 : idw == 10 ? 1 : 2];
}

struct RNode {
  int id = 0;
  std::int8_t tc = 0;
  std::uint8_t format = 0;  // node_widths
  double x = 0, y = 0, z = 0;
  KLine card;
  Ref ref() const { return field_ref(card, node_widths(format), 0); }  // id field
};
struct RElem {
  int id = 0, pid = 0;
  std::array<int, 8> n{};
  KLine card;                        // EID PID (and N1-N8 in the one-line form)
  const DeckLine* node_card = nullptr;  // N1-N10 of the two-line form (same file), else null
  std::uint8_t idw = 8;
  const std::vector<int>& widths1() const { return id_widths(node_card ? 2 : 10, idw); }
  Ref ref() const { return field_ref(card, widths1(), 0); }      // id field
  Ref pid_ref() const { return field_ref(card, widths1(), 1); }
  Ref node_ref(int j) const {
    return node_card ? field_ref({card.file, node_card}, id_widths(10, idw), j)
                     : field_ref(card, widths1(), 2 + j);
  }
};
struct RPart {
  int pid = 0, secid = 0, mid = 0, eosid = 0, hgid = 0;
  std::string title;
  Ref ref, sec_ref, mid_ref, eos_ref, hg_ref;
  int line = 0;
};
struct RSection {
  int elform = 1;
  Ref ref;
};
struct RMat {
  const MaterialType* type = nullptr;  // material_types.h
  MaterialData md;                     // type, rho and the type's parameters
  std::vector<Ref> refs;               // where each of the type's parameters was read
  std::string title;
  Ref ref;
};
struct RHourglass {
  int ihq = 0;
  double qm = 0, q1 = 0, q2 = 0;
  bool q1_blank = true, q2_blank = true;
  Ref ref, ihq_ref;
};
struct RIdList {  // node set or part set, or history list
  std::vector<int> ids;
  std::vector<Ref> refs;
  // *SET_NODE_LIST_GENERATE: id ranges BBEG..BEND, kept as ranges (a range may be huge; the
  // nodes it holds are found in the sorted node ids when the set is resolved)
  std::vector<std::array<long long, 2>> ranges;
  Ref ref;
};
struct RSegSet {
  std::vector<std::array<int, 4>> segs;
  std::vector<std::array<Ref, 4>> refs;
  Ref ref;
};
struct RSide {
  int id = 0, type = 0;
  Ref id_ref, type_ref;
};
struct RContact {
  RSide a, b;
  bool symmetric = true;
  double fs = 0, fd = 0, dc = 0;
  double sfsa = 1;
  int soft = 0;
  Ref ref;
  std::string keyword;
};
struct RWall {
  std::string keyword;  // as written (*RIGIDWALL_PLANAR_ID, ...)
  int nsid = 0;
  Ref nsid_ref;
  StoneWall w;
};
struct RVelocity {       // one initial-velocity definition, in deck order
  enum Kind { all, node_set, node, part, part_set } kind = all;
  int id = 0;
  Ref ref;
  std::array<double, 3> v{};
  // *INITIAL_VELOCITY_GENERATION: rotation OMEGA about the axis through xc along n (unit)
  double omega = 0;
  std::array<double, 3> xc{}, n{};
};
struct RSpc {
  std::string keyword;  // as written (*BOUNDARY_SPC_SET_ID, ...)
  bool set = false;
  int id = 0;
  int bits = 0;
  Ref ref;
};
struct RHistory {
  bool solid = false;
  std::vector<int> ids;
  std::vector<Ref> refs;
};

Location loc_of(const Ref& r, const std::string& card, const char* field = nullptr, bool found = true) {
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

std::string at(const Ref& r) {
  if (!r.file || !r.line) return "";
  return r.file->name() + ":" + std::to_string(r.line->number);
}

// Faces of the hexahedron (0-based local nodes), counter-clockwise seen from outside.
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

class KeywordReader {
 public:
  KeywordReader(DeckFile& deck, Model& m, Diagnostics& diag, const KeywordOptions& opt)
      : main_(deck), m_(m), diag_(diag), opt_(opt) {}

  void read() {
    std::vector<std::string> stack;
    check_first_line();
    scan(main_, 0, stack);
    collect_parameters();
    parse_blocks();
    report_unsupported();
    for (Block& b : blocks_) release(b.data);  // read: the lines are not needed by block any more
    resolve();
  }

 private:
  DeckFile& main_;
  Model& m_;
  Diagnostics& diag_;
  KeywordOptions opt_;
  std::deque<std::unique_ptr<DeckFile>> includes_;
  std::vector<Block> blocks_;
  bool global_long_ = false, global_i10_ = false;

  // raw records
  std::vector<RNode, HugePageAllocator<RNode>> nodes_;
  std::vector<RElem, HugePageAllocator<RElem>> elems_;
  std::vector<RPart> parts_;
  std::map<int, RSection> sections_;
  std::map<int, RMat> mats_;
  std::map<int, RHourglass> hourglasses_;
  std::map<int, RIdList> node_sets_, part_sets_;
  ParamTable params_;                    // *PARAMETER values
  std::map<int, RSegSet> seg_sets_;
  std::vector<RContact> contacts_;
  std::vector<RWall> walls_;
  std::vector<RVelocity> velocities_;
  std::vector<RSpc> spcs_;
  std::vector<RHistory> histories_;
  std::vector<LoadCurve> curves_;
  std::vector<Ref> curve_refs_;
  std::vector<const Block*> unsupported_;
  std::map<int, std::string> unsupported_mids_, unsupported_secids_;  // id -> keyword, line
  // sets and parts that refused keywords define (*SET_NODE_GENERAL, *PART_COMPOSITE, ...):
  // kind ('N' node set, 'P' part set, 'S' segment set, 'p' part) and id -> keyword, line
  std::map<std::pair<char, int>, std::string> refused_defs_;

  // "; SET is defined by *KEYWORD at FILE:LINE, which is not supported" when a refused keyword
  // defines what a reference names.
  std::string refused_note(char kind, int id) const {
    auto it = refused_defs_.find({kind, id});
    if (it == refused_defs_.end()) return {};
    return " (it is defined by " + it->second + ", a keyword IMPACT-3D does not support)";
  }
  int rotational_spc_ = 0;
  int reaction_flag_ = -1;
  std::set<int> initially_elastic_;  // part ids
  Ref rotational_ref_;

  // controls
  bool have_termination_ = false;
  double end_time_ = 0, dtmin_ = 0;
  int end_cycle_ = 0;
  Ref end_ref_;
  double dtinit_ = 0, tssfac_ = 0.9;
  double slsfac_ = 0.1;
  int ikedit_ = 100;
  double d3plot_dt_ = 0, nodout_dt_ = -1, elout_dt_ = -1, glstat_dt_ = -1, ncforc_dt_ = 0;
  int spcforc_ = 0;
  int d3dump_ = 0, runrsf_ = 0;
  int ctrl_ihq_ = 0;
  double ctrl_qh_ = 0.1;
  Ref ctrl_ihq_ref_;
  double ctrl_q1_ = 1.5, ctrl_q2_ = 0.06;
  int ctrl_btype_ = 1;
  std::map<std::string, Ref> seen_once_;

  // ---------------------------------------------------------------- pass 1: blocks
  void check_first_line() {
    for (const auto& l : main_.lines()) {
      if (is_blank(l.text) || l.text[0] == '$') continue;
      if (upper(l.text).rfind("*KEYWORD", 0) != 0) {
        Location loc;
        loc.file = main_.name();
        loc.line = l.number;
        diag_.add(2009, loc, "LS-DYNA requires *KEYWORD as the first line; read anyway");
      }
      return;
    }
  }

  void scan(const DeckFile& f, int depth, std::vector<std::string>& stack) {
    long cur = -1;
    bool reported_orphan = false;
    for (const DeckLine& l : f.lines()) {
      const std::string_view t = l.text;
      if (!t.empty() && t[0] == '$') continue;
      if (is_keyword_line(t)) {
        close_block(cur, depth, stack);
        cur = -1;
        Block b;
        std::string first(t.substr(1, t.find_first_of(" \t,", 1) == std::string::npos ? std::string::npos : t.find_first_of(" \t,", 1) - 1));
        b.keyword = "*" + rtrim(first);
        std::string name = upper(rtrim(first));
        bool lng = global_long_, i10 = global_i10_;
        while (!name.empty() && (name.back() == '+' || name.back() == '-' || name.back() == '%')) {
          if (name.back() == '+') lng = true;
          if (name.back() == '-') lng = false;
          if (name.back() == '%') i10 = true;
          name.pop_back();
        }
        // the suffix may also stand apart: "*NODE +"
        for (std::size_t p = t.find_first_of(" \t"); p != std::string::npos && p < t.size();) {
          std::size_t s = t.find_first_not_of(" \t", p);
          if (s == std::string::npos) break;
          std::size_t e = t.find_first_of(" \t", s);
          std::string_view tok = t.substr(s, e == std::string::npos ? std::string::npos : e - s);
          if (tok == "+") lng = true;
          if (tok == "-") lng = false;
          if (tok == "%") i10 = true;
          p = e;
        }
        b.name = name;
        b.kw = {&f, &l};
        if (name == "END") return;  // the rest of this file is not read
        if (name == "KEYWORD") keyword_options(t, f, l);
        b.long_fmt = name == "KEYWORD" ? global_long_ : lng;
        b.i10 = name == "KEYWORD" ? global_i10_ : i10;
        blocks_.push_back(std::move(b));
        cur = long(blocks_.size()) - 1;
        continue;
      }
      if (!t.empty() && t[0] == '*') continue;  // '*' not followed by a letter: comment
      if (cur < 0) {
        if (!is_blank(t) && !reported_orphan) {
          Location loc;
          loc.file = f.name();
          loc.line = l.number;
          loc.found = t;
          loc.show_found = true;
          diag_.add(1305, loc);
          reported_orphan = true;
        }
        continue;
      }
      blocks_[std::size_t(cur)].data.push_back({&f, &l});
    }
    close_block(cur, depth, stack);
  }

  void keyword_options(std::string_view t, const DeckFile& f, const DeckLine& l) {
    std::string u = upper(t);
    std::size_t p = u.find_first_of(" \t");
    while (p != std::string::npos && p < u.size()) {
      std::size_t b = u.find_first_not_of(" \t", p);
      if (b == std::string::npos) break;
      std::size_t e = u.find_first_of(" \t", b);
      std::string tok = u.substr(b, e == std::string::npos ? std::string::npos : e - b);
      p = e;
      if (tok == "LONG=Y") global_long_ = true;
      else if (tok == "LONG=S" || tok == "LONG=N") global_long_ = false;
      else if (tok == "I10=Y") global_i10_ = true;
      else if (tok == "I10=N") global_i10_ = false;
      else if (!tok.empty() && std::all_of(tok.begin(), tok.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == 'M'; })) {
        // memory size: ignored
      } else {
        Location loc;
        loc.file = f.name();
        loc.line = l.number;
        loc.card = "*KEYWORD";
        loc.found = tok;
        loc.show_found = true;
        diag_.add(1312, loc, "supported: LONG=Y, LONG=S, I10=Y, I10=N and a memory size");
      }
    }
  }

  void close_block(long cur, int depth, std::vector<std::string>& stack) {
    if (cur < 0 || blocks_[std::size_t(cur)].name != "INCLUDE") return;
    // copy: including appends to blocks_
    const auto data = blocks_[std::size_t(cur)].data;
    std::string name;
    KLine first{};
    for (const KLine& kl : data) {
      std::string t = rtrim(kl.line->text);
      if (t.empty() && name.empty()) continue;
      if (name.empty()) first = kl;
      // a file name longer than one line continues on the next after " +"
      if (t.size() >= 2 && t.compare(t.size() - 2, 2, " +") == 0) {
        name += t.substr(0, t.size() - 2);
        continue;
      }
      name += t;
      include(std::string(trim_sv(name)), first, depth, stack);
      name.clear();
    }
  }

  void include(const std::string& name, const KLine& where, int depth, std::vector<std::string>& stack) {
    namespace fs = std::filesystem;
    Location loc;
    loc.file = where.file->name();
    loc.line = where.line->number;
    loc.card = "*INCLUDE";
    loc.field = "FILENAME";
    loc.found = name;
    loc.show_found = true;
    std::vector<fs::path> candidates;
    fs::path p(name);
    if (p.is_absolute()) {
      candidates.push_back(p);
    } else {
      candidates.push_back(fs::path(where.file->name()).parent_path() / p);
      candidates.push_back(fs::path(main_.name()).parent_path() / p);
      candidates.push_back(p);
    }
    fs::path found;
    std::error_code ec;
    for (const auto& c : candidates)
      if (fs::is_regular_file(c, ec)) { found = c; break; }
    if (found.empty()) {
      diag_.add(1306, loc, "not found next to " + where.file->name() + ", the main deck or in the working directory");
      return;
    }
    std::string canon = fs::weakly_canonical(found, ec).string();
    if (depth >= 20 || std::find(stack.begin(), stack.end(), canon) != stack.end() ||
        canon == fs::weakly_canonical(main_.name(), ec).string()) {
      diag_.add(1307, loc, depth >= 20 ? "more than 20 levels" : "the file includes itself");
      return;
    }
    auto df = std::make_unique<DeckFile>();
    Diagnostics local;
    if (!df->load(found.string(), local)) {
      diag_.add(1306, loc, local.all().empty() ? std::string() : local.all().front().detail);
      return;
    }
    includes_.push_back(std::move(df));
    stack.push_back(canon);
    scan(*includes_.back(), depth + 1, stack);
    stack.pop_back();
  }

  // ---------------------------------------------------------------- pass 2: parse blocks
  // Field widths for a card of n fields of width w (standard), 20 in long format.
  static std::vector<int> W(const Block& b, int n, int w = 10) { return std::vector<int>(std::size_t(n), b.long_fmt ? 20 : w); }
  static std::vector<int> cat(std::vector<int> a, const std::vector<int>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  KCard card(const Block& b, std::size_t k, const std::string& what, const std::vector<int>& widths) {
    KCard c(b.data[k], b.keyword + (what.empty() ? "" : " " + what), widths, diag_);
    c.set_params(&params_);
    return c;
  }

  // *PARAMETER: cards of four pairs PRMR (10 columns: type R, I or C, then the name) and VAL
  // (10 columns).  Read before every other keyword, so a reference may come before or after
  // its definition; a name defined twice is error 1200.
  void collect_parameters() {
    for (Block& b : blocks_) {
      if (b.name != "PARAMETER") continue;
      for (std::size_t k = 0; k < b.data.size(); ++k) {
        if (is_blank(b.data[k].line->text)) continue;
        KCard c(b.data[k], b.keyword, W(b, 8), diag_);  // no substitution inside *PARAMETER
        for (int f = 0; f + 1 < 8; f += 2) {
          std::string pr = c.literal(f);
          if (pr.empty()) continue;
          const char type = char(std::toupper(static_cast<unsigned char>(pr[0])));
          std::string name = pr.substr(1);
          const std::size_t s = name.find_first_not_of(' ');
          name = s == std::string::npos ? std::string() : name.substr(s);
          for (char& ch : name) ch = char(std::toupper(static_cast<unsigned char>(ch)));
          if ((type != 'R' && type != 'I' && type != 'C') || name.empty() || name.find(' ') != std::string::npos) {
            c.error(1006, f, "PRMR", "a type letter R, I or C followed by the parameter name");
            continue;
          }
          Param p;
          p.type = type;
          if (type == 'C') {
            p.text = c.literal(f + 1);
          } else if (type == 'I') {
            p.value = double(c.i(f + 1, "VAL"));
          } else {
            p.value = c.r(f + 1, "VAL");
          }
          if (!params_.emplace(name, p).second) c.error(1200, f, "PRMR", "parameter " + name + " is defined twice");
        }
      }
    }
  }

  // Option cards (_ID / _TITLE) at the start of a block: returns the number of lines used.
  std::size_t skip_option_card(const Block& b) { return (b.title_opt || b.id_opt) && !b.data.empty() ? 1 : 0; }

  void once(const Block& b) {
    auto it = seen_once_.find(b.name);
    if (it != seen_once_.end()) {
      Location loc;
      loc.file = b.kw.file->name();
      loc.line = b.kw.line->number;
      loc.card = b.keyword;
      diag_.add(2010, loc, "also given at " + at(it->second));
    }
    Ref r;
    r.file = b.kw.file;
    r.line = b.kw.line;
    seen_once_[b.name] = r;
  }

  void missing_card(const Block& b, const char* what) {
    Location loc;
    loc.file = b.kw.file->name();
    loc.line = b.kw.line->number;
    loc.card = b.keyword;
    diag_.add(1316, loc, std::string("missing: ") + what);
  }

  // Strips the _TITLE / _ID options the supported keywords know.
  static std::string base_name(const std::string& n, bool& title, bool& id) {
    auto ends = [&](const char* s) {
      std::size_t k = std::char_traits<char>::length(s);
      return n.size() > k && n.compare(n.size() - k, k, s) == 0;
    };
    static const std::set<std::string> titled = {
        "SECTION_SOLID", "HOURGLASS", "DEFINE_CURVE", "SET_NODE_LIST", "SET_NODE", "SET_PART_LIST",
        "SET_PART", "SET_SEGMENT", "SET_NODE_LIST_GENERATE", "CONTACT_SURFACE_TO_SURFACE",
        "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", "CONTACT_NODES_TO_SURFACE"};
    static const std::set<std::string> with_id = {
        "RIGIDWALL_PLANAR", "RIGIDWALL_PLANAR_MOVING", "CONTACT_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE",
        "CONTACT_NODES_TO_SURFACE", "BOUNDARY_SPC_NODE", "BOUNDARY_SPC_SET"};
    if (ends("_TITLE") && (titled.count(n.substr(0, n.size() - 6)) || find_material_type_by_keyword(n.substr(0, n.size() - 6)))) {
      title = true;
      return n.substr(0, n.size() - 6);
    }
    if (ends("_ID") && with_id.count(n.substr(0, n.size() - 3))) {
      id = true;
      return n.substr(0, n.size() - 3);
    }
    return n;
  }

  static // Keywords read and ignored (warning 2008): they change nothing in IMPACT-3D's physics or
// output.  Returns why, or nullptr for any other keyword.
const char* ignored_keyword_reason(const std::string& n) {
  if (n == "CONTROL_ENERGY") return "IMPACT-3D always computes all energies";
  if (n == "DATABASE_EXTENT_BINARY") return "IMPACT-3D writes its fixed set of plot variables";
  if (n == "CONTROL_PARALLEL") return "threads are set on the command line (ncpu=); results do not depend on them";
  if (n == "CONTROL_ACCURACY") return "no accuracy options for solids here (invariant numbering and objective updates are for shells and fully integrated elements)";
  if (n == "CONTROL_SOLID") return "solids are always the one-point hexahedron (degenerate shapes included)";
  if (n == "CONTROL_SOLUTION") return "structural analysis only (SOLN 0)";
  if (n == "DATABASE_FORMAT") return "the plot database is always the LS-DYNA binary layout (8-byte words: plotwords=8 on the command line)";
  if (n.rfind("CONTROL_MPP_", 0) == 0) return "MPP decomposition controls have no effect on a shared-memory run";
  return nullptr;
}

bool is_ascii_database(const std::string& n) {
    static const std::set<std::string> names = {
        "DATABASE_GLSTAT", "DATABASE_MATSUM", "DATABASE_NODOUT", "DATABASE_ELOUT",
        "DATABASE_RCFORC", "DATABASE_RWFORC", "DATABASE_SPCFORC", "DATABASE_NCFORC",
        "DATABASE_SLEOUT", "DATABASE_RBDOUT", "DATABASE_BNDOUT", "DATABASE_NODFOR",
        "DATABASE_DEFORC", "DATABASE_SECFORC", "DATABASE_ABSTAT", "DATABASE_JNTFORC",
        "DATABASE_SBTOUT", "DATABASE_SWFORC", "DATABASE_SPHOUT", "DATABASE_TPRINT"};
    return names.count(n) > 0;
  }

  void parse_blocks() {
    for (Block& b : blocks_) {
      if (b.name == "PARAMETER") continue;  // read first (collect_parameters)
      std::string n = base_name(b.name, b.title_opt, b.id_opt);
      if (n == "RIGIDWALL_PLANAR_MOVING") {
        n = "RIGIDWALL_PLANAR";
        b.moving_opt = true;
      }
      b.name = n;
      if (n == "KEYWORD" || n == "INCLUDE") continue;
      if (n == "COMMENT") {
        parse_comment(b);
        continue;
      }
      if (n == "TITLE") {
        for (const KLine& l : b.data) {
          m_.title = rtrim(l.line->text.substr(0, std::min<std::size_t>(80, l.line->text.size())));
          break;
        }
      } else if (n == "NODE") {
        parse_node(b);
      } else if (n == "ELEMENT_SOLID") {
        parse_element_solid(b);
      } else if (n == "PART") {
        parse_part(b);
      } else if (n == "SECTION_SOLID") {
        parse_section(b);
      } else if (const MaterialType* mt = find_material_type_by_keyword(n)) {
        parse_mat(b, *mt);
      } else if (n == "HOURGLASS") {
        parse_hourglass(b);
      } else if (n == "CONTROL_HOURGLASS") {
        once(b);
        parse_control_hourglass(b);
      } else if (n == "CONTROL_BULK_VISCOSITY") {
        once(b);
        parse_control_bulk(b);
      } else if (n == "CONTROL_TERMINATION") {
        once(b);
        parse_control_termination(b);
      } else if (n == "CONTROL_TIMESTEP") {
        once(b);
        parse_control_timestep(b);
      } else if (n == "CONTROL_CONTACT") {
        once(b);
        if (!b.data.empty()) {
          KCard c = card(b, 0, "card 1", W(b, 8));
          slsfac_ = c.r(0, "SLSFAC", 0.1);
          if (slsfac_ == 0) slsfac_ = 0.1;
          if (slsfac_ < 0) c.error(1003, 0, "SLSFAC", "must be positive");
        }
      } else if (n == "CONTROL_OUTPUT") {
        once(b);
        if (!b.data.empty()) {
          KCard c = card(b, 0, "card 1", W(b, 8));
          ikedit_ = int(c.i(6, "IKEDIT", 100));
          if (ikedit_ == 0) ikedit_ = 100;
          if (ikedit_ < 0) c.error(1003, 6, "IKEDIT", "must not be negative");
        }
      } else if (n == "DATABASE_BINARY_D3PLOT") {
        once(b);
        if (!b.data.empty()) {
          KCard c = card(b, 0, "card 1", W(b, 5));
          d3plot_dt_ = c.r(0, "DT");
          if (d3plot_dt_ < 0) c.error(1221, 0, "DT");
          if (!c.blank(1) && c.i(1, "LCDT") != 0) c.error(1102, 1, "LCDT", "plot interval from a load curve");
        }
      } else if (n == "DATABASE_BINARY_D3DUMP" || n == "DATABASE_BINARY_RUNRSF") {
        once(b);
        if (!b.data.empty()) {
          KCard c = card(b, 0, "card 1", W(b, 2));
          double cy = c.r(0, "CYCL");
          if (cy < 0 || cy > 2e9) c.error(1003, 0, "CYCL", "cycles between dumps, >= 0");
          else (n == "DATABASE_BINARY_D3DUMP" ? d3dump_ : runrsf_) = int(std::lround(cy));
        }
      } else if (is_ascii_database(n)) {
        if (!b.data.empty()) {
          KCard c = card(b, 0, "card 1", W(b, 4));
          double dt = c.r(0, "DT");
          if (dt < 0) c.error(1221, 0, "DT");
          if (n == "DATABASE_NODOUT") nodout_dt_ = dt;
          if (n == "DATABASE_ELOUT") elout_dt_ = dt;
          if (n == "DATABASE_GLSTAT") glstat_dt_ = dt;
          if (n == "DATABASE_NCFORC") ncforc_dt_ = dt;
          if (n == "DATABASE_SPCFORC") spcforc_ = dt > 0 ? 1 : 0;
        }
      } else if (const char* why = ignored_keyword_reason(n)) {
        if (n == "CONTROL_SOLUTION" && !b.data.empty()) {
          // SOLN 1 (thermal only) and 2 (coupled) change the analysis: refused, not ignored
          KCard c = card(b, 0, "card 1", W(b, 8));
          if (c.i(0, "SOLN") != 0) c.error(1102, 0, "SOLN", "thermal and coupled thermal-structural analysis");
        }
        Location loc;
        loc.file = b.kw.file->name();
        loc.line = b.kw.line->number;
        loc.card = b.keyword;
        diag_.add(2008, loc, why);
      } else if (n == "DATABASE_HISTORY_NODE" || n == "DATABASE_HISTORY_SOLID") {
        RHistory h;
        h.solid = n == "DATABASE_HISTORY_SOLID";
        for (std::size_t k = 0; k < b.data.size(); ++k) {
          if (is_blank(b.data[k].line->text)) continue;
          KCard c = card(b, k, "", W(b, 8));
          for (int f = 0; f < 8; ++f) {
            long long id = c.i(f, h.solid ? "EID" : "NID");
            if (id != 0) { h.ids.push_back(int(id)); h.refs.push_back(c.ref(f)); }
          }
        }
        histories_.push_back(std::move(h));
      } else if (n == "INITIAL_VELOCITY") {
        parse_initial_velocity(b);
      } else if (n == "INITIAL_VELOCITY_NODE") {
        parse_initial_velocity_node(b);
      } else if (n == "INITIAL_VELOCITY_GENERATION") {
        parse_initial_velocity_generation(b);
      } else if (n == "BOUNDARY_SPC_NODE" || n == "BOUNDARY_SPC_SET") {
        parse_spc(b, n == "BOUNDARY_SPC_SET");
      } else if (n == "SET_NODE_LIST" || n == "SET_NODE") {
        parse_id_set(b, node_sets_, "NID", false);
      } else if (n == "SET_NODE_LIST_GENERATE") {
        parse_id_set(b, node_sets_, "B", true);
      } else if (n == "SET_PART_LIST" || n == "SET_PART") {
        parse_id_set(b, part_sets_, "PID", false);
      } else if (n == "SET_SEGMENT") {
        parse_segment_set(b);
      } else if (n == "RIGIDWALL_PLANAR") {
        parse_rigidwall(b);
      } else if (n == "CONTACT_SURFACE_TO_SURFACE" || n == "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE" ||
                 n == "CONTACT_NODES_TO_SURFACE") {
        parse_contact(b, n != "CONTACT_NODES_TO_SURFACE");
      } else if (n == "DEFINE_CURVE") {
        parse_curve(b);
      } else {
        unsupported_.push_back(&b);
        // remember the ids that unsupported material and section keywords define, so that a
        // part using one gets a clear message
        if ((n.rfind("MAT_", 0) == 0 || n.rfind("SECTION_", 0) == 0) && !b.data.empty()) {
          std::size_t k = 0;
          if (n.size() > 6 && n.compare(n.size() - 6, 6, "_TITLE") == 0) k = 1;
          if (k < b.data.size()) {
            Diagnostics quiet;
            KCard c(b.data[k], b.keyword, W(b, 1), quiet);
            long long id = c.i(0, "id", 0);
            (n[0] == 'M' ? unsupported_mids_ : unsupported_secids_)[int(id)] =
                b.keyword + " at " + b.kw.file->name() + ":" + std::to_string(b.kw.line->number);
          }
        }
        // and the sets and parts they define, so that a reference to one names the keyword
        char kind = n.rfind("SET_NODE", 0) == 0      ? 'N'
                    : n.rfind("SET_PART", 0) == 0    ? 'P'
                    : n.rfind("SET_SEGMENT", 0) == 0 ? 'S'
                    : n.rfind("PART", 0) == 0        ? 'p'
                                                     : 0;
        if (kind) {
          const bool titled = n.size() > 6 && n.compare(n.size() - 6, 6, "_TITLE") == 0;
          std::size_t k = kind == 'p' ? 1 : titled ? 1 : 0;  // *PART_...: heading card first
          if (k < b.data.size()) {
            Diagnostics quiet;
            KCard c(b.data[k], b.keyword, W(b, 1), quiet);
            long long id = c.i(0, "id", 0);
            if (quiet.error_count() == 0 && id != 0)
              refused_defs_.emplace(std::make_pair(kind, int(id)),
                                    upper(b.keyword) + " at " + b.kw.file->name() + ":" + std::to_string(b.kw.line->number));
          }
        }
      }
    }
  }

  // *COMMENT is ignored (as by LS-DYNA), except the IMPACT-3D lines the deck writer puts there
  // for fields LS-DYNA has no keyword for.
  void parse_comment(const Block& b) {
    for (const KLine& l : b.data) {
      std::string t = upper(rtrim(l.line->text));
      if (t.rfind("IMPACT-3D ", 0) != 0) continue;
      std::vector<std::string> tok;
      for (std::size_t p = 0; p < t.size();) {
        std::size_t s = t.find_first_not_of(' ', p);
        if (s == std::string::npos) break;
        std::size_t e = t.find(' ', s);
        tok.push_back(t.substr(s, e == std::string::npos ? std::string::npos : e - s));
        p = e == std::string::npos ? t.size() : e;
      }
      long long v = 0;
      const std::string& last = tok.back();
      bool num = parse_fortran_int(last, v) == FieldStatus::ok;
      Location loc;
      loc.file = l.file->name();
      loc.line = l.line->number;
      loc.card = "*COMMENT";
      if (num && tok.size() == 3 && tok[1] == "INTERFACE_SEGMENTS") m_.control.interface_segments_out = int(v);
      else if (num && tok.size() == 3 && tok[1] == "VISCOSITY_FLAG") m_.control.viscosity_flag = int(v);
      else if (num && tok.size() == 3 && tok[1] == "REACTION_PRINT_FLAG") reaction_flag_ = int(v);
      else if (num && tok.size() == 4 && tok[1] == "INITIALLY_ELASTIC" && tok[2] == "PART") initially_elastic_.insert(int(v));
      else diag_.add(1312, loc, "unknown IMPACT-3D line: " + rtrim(l.line->text));
    }
  }

  void parse_node(const Block& b) {
    const std::uint8_t format = b.long_fmt ? 1 : b.i10 ? 2 : 0;
    const std::vector<int>& w = node_widths(format);
    reserve_for(nodes_, b.data.size());
    for (std::size_t k = 0; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      if (plain_keyword_card(b.data[k].line->text)) {  // fast path (see plain_keyword_card)
        const PlainFields f(b.data[k].line->text, w);
        RNode n;
        int tc = 0, rc = 0;
        if (f.i(0, n.id) && f.r(1, n.x) && f.r(2, n.y) && f.r(3, n.z) && f.i(4, tc) && f.i(5, rc) &&
            n.id >= 1 && tc >= 0 && tc <= 7 && rc == 0) {
          n.tc = std::int8_t(tc);
          n.format = format;
          n.card = b.data[k];
          nodes_.push_back(n);
          continue;
        }
      }
      KCard c = card(b, k, "", w);
      RNode n;
      n.id = int(c.i(0, "NID"));
      c.set_card(b.keyword + " node " + std::to_string(n.id));
      n.format = format;
      n.card = b.data[k];
      n.x = c.r(1, "X");
      n.y = c.r(2, "Y");
      n.z = c.r(3, "Z");
      int tc = int(c.i(4, "TC"));
      int rc = int(c.i(5, "RC"));
      if (n.id < 1) { c.error(1201, 0, "NID", "node ids must be positive"); continue; }
      if (tc < 0 || tc > 7) { c.error(1216, 4, "TC"); tc = 0; }
      n.tc = std::int8_t(tc);
      if (rc < 0 || rc > 7) c.error(1216, 5, "RC");
      else if (rc != 0) note_rotational(c.ref(5));
      nodes_.push_back(n);
    }
  }

  // Room for up to `more` records (one per data line at most), growing geometrically.
  template <class V>
  static void reserve_for(V& v, std::size_t more) {
    if (v.capacity() - v.size() < more) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
  }

  void note_rotational(const Ref& r) {
    if (rotational_spc_++ == 0) rotational_ref_ = r;
  }

  void parse_element_solid(const Block& b) {
    const int idw = b.long_fmt ? 20 : b.i10 ? 10 : 8;
    reserve_for(elems_, b.data.size());
    std::size_t k = 0;
    while (k < b.data.size()) {
      if (is_blank(b.data[k].line->text)) { ++k; continue; }
      const std::string_view t = b.data[k].line->text;
      bool free = t.find(',') != std::string::npos;
      bool legacy;
      if (free) {
        legacy = std::count(t.begin(), t.end(), ',') >= 2;
      } else {
        legacy = rtrim(t).size() > std::size_t(2 * idw);
      }
      if (!free && plain_keyword_card(t)) {  // fast path (see plain_keyword_card)
        RElem e;
        e.idw = std::uint8_t(idw);
        e.card = b.data[k];
        bool ok;
        if (legacy) {
          const PlainFields f(t, id_widths(10, idw));
          ok = f.i(0, e.id) && f.i(1, e.pid);
          for (int j = 0; j < 8 && ok; ++j) ok = f.i(2 + j, e.n[std::size_t(j)]);
        } else {
          ok = k + 1 < b.data.size() && !is_keyword_line(b.data[k + 1].line->text) &&
               plain_keyword_card(b.data[k + 1].line->text);
          if (ok) {
            const PlainFields f1(t, id_widths(2, idw));
            const PlainFields f2(b.data[k + 1].line->text, id_widths(10, idw));
            int n9 = 0, n10 = 0;
            ok = f1.i(0, e.id) && f1.i(1, e.pid) && f2.i(8, n9) && f2.i(9, n10) && n9 == 0 && n10 == 0;
            for (int j = 0; j < 8 && ok; ++j) ok = f2.i(j, e.n[std::size_t(j)]);
            e.node_card = b.data[k + 1].line;
          }
        }
        if (ok && e.id >= 1) {
          elems_.push_back(e);
          k += legacy ? 1 : 2;
          continue;
        }
      }
      RElem e;
      e.idw = std::uint8_t(idw);
      e.card = b.data[k];
      std::vector<int> w1 = legacy ? std::vector<int>(10, idw) : std::vector<int>(2, idw);
      KCard c = card(b, k, "", w1);
      e.id = int(c.i(0, "EID"));
      c.set_card(b.keyword + " element " + std::to_string(e.id));
      e.pid = int(c.i(1, "PID"));
      bool ok = true;
      if (legacy) {
        for (int j = 0; j < 8; ++j) {
          std::string f = "N" + std::to_string(j + 1);
          e.n[std::size_t(j)] = int(c.i(2 + j, f.c_str()));
        }
        ++k;
      } else {
        if (k + 1 >= b.data.size() || is_keyword_line(b.data[k + 1].line->text)) {
          c.error(1316, -1, nullptr, "the node card (N1-N8) of the two-line form is missing");
          break;
        }
        KCard c2 = card(b, k + 1, "element " + std::to_string(e.id) + " node card", std::vector<int>(10, idw));
        e.node_card = b.data[k + 1].line;
        for (int j = 0; j < 8; ++j) {
          std::string f = "N" + std::to_string(j + 1);
          e.n[std::size_t(j)] = int(c2.i(j, f.c_str()));
        }
        for (int j = 8; j < 10; ++j) {
          std::string f = "N" + std::to_string(j + 1);
          if (c2.i(j, f.c_str()) != 0) { c2.error(1102, j, f.c_str(), "10-node tetrahedra"); ok = false; }
        }
        k += 2;
      }
      if (e.id < 1) { c.error(1201, 0, "EID", "element ids must be positive"); continue; }
      if (ok) elems_.push_back(e);
    }
  }

  void parse_part(const Block& b) {
    // pairs of cards: heading, then PID SECID MID EOSID HGID GRAV ADPOPT TMID
    std::size_t k = 0;
    while (k < b.data.size()) {
      std::string title = rtrim(b.data[k].line->text.substr(0, std::min<std::size_t>(80, b.data[k].line->text.size())));
      if (k + 1 >= b.data.size()) {
        if (!is_blank(b.data[k].line->text)) missing_card(b, "card 2 (PID SECID MID ...)");
        break;
      }
      KCard c = card(b, k + 1, "card 2", W(b, 8));
      RPart p;
      p.title = title;
      p.pid = int(c.i(0, "PID"));
      c.set_card(b.keyword + " part " + std::to_string(p.pid));
      p.secid = int(c.i(1, "SECID"));
      p.mid = int(c.i(2, "MID"));
      p.eosid = int(c.i(3, "EOSID"));
      p.hgid = int(c.i(4, "HGID"));
      if (c.i(5, "GRAV") != 0) c.error(1102, 5, "GRAV", "body forces");
      c.i(6, "ADPOPT");
      if (c.i(7, "TMID") != 0) c.error(1102, 7, "TMID", "thermal materials");
      p.ref = c.ref(0);
      p.sec_ref = c.ref(1);
      p.mid_ref = c.ref(2);
      p.eos_ref = c.ref(3);
      p.hg_ref = c.ref(4);
      p.line = c.line();
      parts_.push_back(p);
      k += 2;
    }
  }

  void parse_section(const Block& b) {
    for (std::size_t k = skip_option_card(b); k < b.data.size(); ++k) {
      KCard c = card(b, k, "", W(b, 3));
      int id = int(c.i(0, "SECID"));
      RSection s;
      s.elform = int(c.i(1, "ELFORM", 1));
      s.ref = c.ref(1);
      if (sections_.count(id)) c.error(1200, 0, "SECID", "also defined at " + at(sections_[id].ref));
      sections_[id] = s;
      if (c.i(2, "AET") != 0) c.error(1102, 2, "AET", "ambient element types");
      break;  // ELFORM 1 has one card; anything after belongs to other ELFORMs
    }
  }

  // *MAT_...: the cards and fields its type's table names (material_types.h), checked there.
  void parse_mat(const Block& b, const MaterialType& t) {
    std::size_t start = skip_option_card(b);
    if (start >= b.data.size()) { missing_card(b, "card 1"); return; }
    KCard c = card(b, start, "card 1", W(b, 8));
    int mid = int(c.i(0, "MID"));
    c.set_card(b.keyword + " material " + std::to_string(mid));
    RMat m;
    m.type = &t;
    m.ref = c.ref(0);
    m.md.type = t.number;
    set_param_defaults(m.md, t);
    m.md.rho = c.r(1, "RO");
    if (!(m.md.rho > 0)) c.error(1207, 1, "RO");
    std::vector<KCard> cards{c};
    for (int k = 1; k < t.keyword_cards && start + std::size_t(k) < b.data.size(); ++k)
      cards.push_back(card(b, start + std::size_t(k), "material " + std::to_string(mid) + " card " + std::to_string(k + 1), W(b, 8)));
    m.refs.assign(t.params.size(), m.ref);
    for (std::size_t i = 0; i < t.params.size(); ++i) {
      const MaterialParam& p = t.params[i];
      if (p.kcard < 0 || std::size_t(p.kcard) >= cards.size()) continue;
      KCard& kc = cards[std::size_t(p.kcard)];
      double v = kc.r(p.kfield, p.key, p.def);
      if (kc.blank(p.kfield)) v = p.def;
      param_value(m.md, p) = v;
      m.refs[i] = kc.ref(p.kfield);
    }
    check_material_params(m.md, t, [&](const MaterialParam& p, int msg, const std::string& detail) {
      KCard& kc = p.kcard >= 0 && std::size_t(p.kcard) < cards.size() ? cards[std::size_t(p.kcard)] : cards[0];
      kc.error(msg, p.kcard >= 0 ? p.kfield : 0, p.key, detail);
    });
    if (t.extra_card_feature && start + std::size_t(t.keyword_cards) < b.data.size()) {
      Location loc = loc_of(c.ref(-1), b.keyword);
      loc.line = b.data[start + std::size_t(t.keyword_cards)].line->number;
      diag_.add(1102, loc, t.extra_card_feature);
    }
    if (b.title_opt) m.title = rtrim(b.data[0].line->text);
    if (mats_.count(mid)) c.error(1200, 0, "MID", "also defined at " + at(mats_[mid].ref));
    mats_[mid] = m;
  }

  void parse_hourglass(const Block& b) {
    for (std::size_t k = skip_option_card(b); k < b.data.size(); ++k) {
      KCard c = card(b, k, "", W(b, 8));
      int id = int(c.i(0, "HGID"));
      c.set_card(b.keyword + " " + std::to_string(id));
      RHourglass h;
      h.ref = c.ref(0);
      h.ihq = int(c.i(1, "IHQ"));
      h.ihq_ref = c.ref(1);
      h.qm = c.r(2, "QM", 0.1);
      c.i(3, "IBQ");
      h.q1_blank = c.blank(4);
      h.q2_blank = c.blank(5);
      h.q1 = c.r(4, "Q1", 1.5);
      h.q2 = c.r(5, "Q2", 0.06);
      // LS-DYNA knows IHQ 0-10: the types IMPACT-3D lacks are not supported, not invalid
      if (h.ihq >= 6 && h.ihq <= 10) c.error(1102, 1, "IHQ", "hourglass type " + std::to_string(h.ihq) + " (IMPACT-3D has 0 control default, 1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness)");
      else if (h.ihq < 0 || h.ihq > 5) c.error(1006, 1, "IHQ", "0 (control default), 1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness");
      if (h.qm < 0) c.error(1220, 2, "QM");
      if (h.q1 < 0) c.error(1220, 4, "Q1");
      if (h.q2 < 0) c.error(1220, 5, "Q2");
      if (hourglasses_.count(id)) c.error(1200, 0, "HGID", "also defined at " + at(hourglasses_[id].ref));
      hourglasses_[id] = h;
      break;
    }
  }

  void parse_control_hourglass(const Block& b) {
    if (b.data.empty()) return;
    KCard c = card(b, 0, "", W(b, 2));
    ctrl_ihq_ = int(c.i(0, "IHQ"));
    ctrl_ihq_ref_ = c.ref(0);
    ctrl_qh_ = c.r(1, "QH", 0.1);
    if (ctrl_qh_ == 0) ctrl_qh_ = 0.1;
    // LS-DYNA knows IHQ 0-10 and negative values (shell variants): those IMPACT-3D lacks are not
    // supported, not invalid
    if ((ctrl_ihq_ >= 6 && ctrl_ihq_ <= 10) || (ctrl_ihq_ >= -10 && ctrl_ihq_ < 0))
      c.error(1102, 0, "IHQ", "hourglass type " + std::to_string(ctrl_ihq_) + " (IMPACT-3D has 0/1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness)");
    else if (ctrl_ihq_ < 0 || ctrl_ihq_ > 5) c.error(1006, 0, "IHQ", "0/1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness");
    if (ctrl_qh_ < 0) c.error(1220, 1, "QH");
  }

  void parse_control_bulk(const Block& b) {
    if (b.data.empty()) return;
    KCard c = card(b, 0, "", W(b, 5));
    ctrl_q1_ = c.r(0, "Q1", 1.5);
    ctrl_q2_ = c.r(1, "Q2", 0.06);
    int type = int(c.i(2, "TYPE", 1));
    if (ctrl_q1_ < 0) c.error(1220, 0, "Q1");
    if (ctrl_q2_ < 0) c.error(1220, 1, "Q2");
    if (type != 0 && type != 1 && type != -1 && type != -2)
      c.error(1006, 2, "TYPE", "1 standard (-1, -2 differ only for shells)");
    ctrl_btype_ = 1;
  }

  void parse_control_termination(const Block& b) {
    have_termination_ = true;
    if (b.data.empty()) { missing_card(b, "card 1 (ENDTIM)"); return; }
    KCard c = card(b, 0, "", W(b, 6));
    end_time_ = c.r(0, "ENDTIM");
    end_ref_ = c.ref(0);
    if (!(end_time_ > 0)) c.error(1214, 0, "ENDTIM");
    const long long endcyc = c.i(1, "ENDCYC");
    if (endcyc < 0 || endcyc > 2147483647LL) c.error(1003, 1, "ENDCYC", "must be 0 (no limit) or a cycle count");
    else end_cycle_ = int(endcyc);
    dtmin_ = c.r(2, "DTMIN");
    if (dtmin_ < 0 || dtmin_ >= 1) c.error(1003, 2, "DTMIN", "must be in [0, 1)");
    if (c.r(3, "ENDENG") != 0) c.error(1102, 3, "ENDENG", "termination by energy change");
    c.r(4, "ENDMAS");
    c.i(5, "NOSOL");
  }

  void parse_control_timestep(const Block& b) {
    if (b.data.empty()) return;
    KCard c = card(b, 0, "card 1", W(b, 8));
    dtinit_ = c.r(0, "DTINIT");
    if (dtinit_ < 0) c.error(1003, 0, "DTINIT", "must not be negative");
    tssfac_ = c.r(1, "TSSFAC", 0.9);
    if (tssfac_ == 0) tssfac_ = 0.9;
    if (!(tssfac_ > 0 && tssfac_ <= 1)) c.error(1215, 1, "TSSFAC");
    c.i(2, "ISDO");
    if (c.r(3, "TSLIMT") != 0) c.error(2006, 3, "TSLIMT", "shell time-step limit");
    if (c.r(4, "DT2MS") != 0) c.error(1102, 4, "DT2MS", "mass scaling");
    if (c.i(5, "LCTM") != 0) c.error(1102, 5, "LCTM", "time-step limit from a load curve");
    c.i(6, "ERODE");
    c.i(7, "MS1ST");
  }

  void parse_initial_velocity(const Block& b) {
    for (std::size_t k = 0; k < b.data.size(); k += 2) {
      KCard c = card(b, k, "card 1", W(b, 5));
      RVelocity v;
      v.id = int(c.i(0, "NSID"));
      v.kind = v.id == 0 ? RVelocity::all : RVelocity::node_set;
      v.ref = c.ref(0);
      if (c.i(1, "NSIDEX") != 0) c.error(1102, 1, "NSIDEX", "exempted node sets");
      if (c.i(2, "BOXID") != 0) c.error(1102, 2, "BOXID", "boxes");
      c.i(3, "IRIGID");
      if (c.i(4, "ICID") != 0) c.error(1102, 4, "ICID", "local coordinate systems");
      if (k + 1 >= b.data.size()) { missing_card(b, "card 2 (VX VY VZ)"); break; }
      KCard c2 = card(b, k + 1, "card 2", W(b, 6));
      v.v = {c2.r(0, "VX"), c2.r(1, "VY"), c2.r(2, "VZ")};
      for (int f = 3; f < 6; ++f)
        if (c2.r(f, "VR") != 0) { c2.error(2006, f, "VXR/VYR/VZR", "solid nodes have no rotations"); break; }
      velocities_.push_back(v);
    }
  }

  void parse_initial_velocity_node(const Block& b) {
    for (std::size_t k = 0; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      KCard c = card(b, k, "", W(b, 8));
      RVelocity v;
      v.kind = RVelocity::node;
      v.id = int(c.i(0, "NID"));
      v.ref = c.ref(0);
      v.v = {c.r(1, "VX"), c.r(2, "VY"), c.r(3, "VZ")};
      for (int f = 4; f < 7; ++f)
        if (c.r(f, "VR") != 0) { c.error(2006, f, "VXR/VYR/VZR", "solid nodes have no rotations"); break; }
      if (c.i(7, "ICID") != 0) c.error(1102, 7, "ICID", "local coordinate systems");
      velocities_.push_back(v);
    }
  }

  void parse_initial_velocity_generation(const Block& b) {
    for (std::size_t k = 0; k < b.data.size(); k += 2) {
      KCard c = card(b, k, "card 1", W(b, 8));
      RVelocity v;
      v.id = int(c.i(0, "ID"));
      v.ref = c.ref(0);
      int styp = int(c.i(1, "STYP"));
      if (styp == 1) v.kind = RVelocity::part_set;
      else if (styp == 2) v.kind = RVelocity::part;
      else if (styp == 3) v.kind = RVelocity::node_set;
      else c.error(1006, 1, "STYP", "1 part set, 2 part, 3 node set");
      v.omega = c.r(2, "OMEGA");
      v.v = {c.r(3, "VX"), c.r(4, "VY"), c.r(5, "VZ")};
      if (c.i(6, "IVATN") != 0) c.error(1102, 6, "IVATN", "slave parts of rigid bodies");
      if (c.i(7, "ICID") != 0) c.error(1102, 7, "ICID", "local coordinate systems");
      if (k + 1 < b.data.size()) {
        KCard c2 = card(b, k + 1, "card 2", W(b, 8));
        const char* names[] = {"XC", "YC", "ZC", "NX", "NY", "NZ"};
        for (int f = 0; f < 3; ++f) v.xc[std::size_t(f)] = c2.r(f, names[f]);
        for (int f = 0; f < 3; ++f) v.n[std::size_t(f)] = c2.r(3 + f, names[3 + f]);
        if (c2.r(6, "PHASE") != 0) c2.error(2006, 6, "PHASE", "no dynamic relaxation: velocities apply at time 0");
        c2.i(7, "IRIGID");
        const double len = std::sqrt(v.n[0] * v.n[0] + v.n[1] * v.n[1] + v.n[2] * v.n[2]);
        if (v.omega != 0 && !(len > 0)) c2.error(1003, 3, "NX", "the rotation axis NX NY NZ must not be zero when OMEGA is given");
        else if (len > 0) for (double& a : v.n) a /= len;
      } else if (v.omega != 0) {
        c.error(1316, 2, "OMEGA", "OMEGA needs card 2 (the axis: XC YC ZC NX NY NZ)");
      }
      if (styp >= 1 && styp <= 3) velocities_.push_back(v);
    }
  }

  void parse_spc(const Block& b, bool set) {
    for (std::size_t k = skip_option_card(b); k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      KCard c = card(b, k, "", W(b, 8));
      RSpc s;
      s.keyword = upper(b.keyword);
      s.set = set;
      s.id = int(c.i(0, set ? "NSID" : "NID"));
      s.ref = c.ref(0);
      if (c.i(1, "CID") != 0) c.error(1102, 1, "CID", "local coordinate systems");
      const char* names[] = {"DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"};
      for (int f = 0; f < 6; ++f) {
        long long d = c.i(2 + f, names[f]);
        if (d != 0 && d != 1) c.error(1006, 2 + f, names[f], "0 free or 1 fixed");
        if (d == 1 && f < 3) s.bits |= 1 << f;
        if (d == 1 && f >= 3) note_rotational(c.ref(2 + f));
      }
      spcs_.push_back(s);
    }
  }

  void parse_id_set(const Block& b, std::map<int, RIdList>& sets, const char* field, bool generate) {
    std::size_t k = skip_option_card(b);
    if (k >= b.data.size()) { missing_card(b, "card 1 (SID)"); return; }
    KCard c = card(b, k, "card 1", W(b, 6));
    int sid = int(c.i(0, "SID"));
    RIdList s;
    s.ref = c.ref(0);
    if (sid < 1) c.error(1201, 0, "SID", "set ids must be positive");
    for (++k; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      KCard d = card(b, k, "set " + std::to_string(sid), W(b, 8));
      if (generate) {
        for (int f = 0; f + 1 < 8; f += 2) {
          long long b1 = d.i(f, "BBEG"), b2 = d.i(f + 1, "BEND");
          if (b1 == 0 && b2 == 0) continue;
          if (b1 < 1 || b2 < b1 || b2 > 2147483647) { d.error(1003, f + 1, "BEND", "range must be 1 <= BBEG <= BEND <= 2147483647"); continue; }
          // ids in the range that are not nodes are skipped at resolution
          s.ranges.push_back({b1, b2});
        }
      } else {
        for (int f = 0; f < 8; ++f) {
          long long id = d.i(f, field);
          if (id != 0) { s.ids.push_back(int(id)); s.refs.push_back(d.ref(f)); }
        }
      }
    }
    if (sets.count(sid)) c.error(1200, 0, "SID", "also defined at " + at(sets[sid].ref));
    sets[sid] = std::move(s);
  }

  void parse_segment_set(const Block& b) {
    std::size_t k = skip_option_card(b);
    if (k >= b.data.size()) { missing_card(b, "card 1 (SID)"); return; }
    KCard c = card(b, k, "card 1", W(b, 6));
    int sid = int(c.i(0, "SID"));
    RSegSet s;
    s.ref = c.ref(0);
    for (++k; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      KCard d = card(b, k, "set " + std::to_string(sid) + " segment", W(b, 8));
      std::array<int, 4> seg{};
      std::array<Ref, 4> refs;
      const char* names[] = {"N1", "N2", "N3", "N4"};
      for (int f = 0; f < 4; ++f) {
        seg[std::size_t(f)] = int(d.i(f, names[f]));
        refs[std::size_t(f)] = d.ref(f);
      }
      if (seg[3] == 0) { seg[3] = seg[2]; refs[3] = refs[2]; }  // triangle
      s.segs.push_back(seg);
      s.refs.push_back(refs);
    }
    if (seg_sets_.count(sid)) c.error(1200, 0, "SID", "also defined at " + at(seg_sets_[sid].ref));
    seg_sets_[sid] = std::move(s);
  }

  void parse_rigidwall(const Block& b) {
    std::size_t k = 0;
    while (k < b.data.size()) {
      if (b.id_opt) ++k;  // RWID, heading
      if (k + 1 >= b.data.size()) { missing_card(b, "cards 1 and 2"); return; }
      KCard c = card(b, k, "card 1", W(b, 7));
      RWall w;
      w.keyword = upper(b.keyword);
      w.nsid = int(c.i(0, "NSID"));
      w.nsid_ref = c.ref(0);
      if (c.i(1, "NSIDEX") != 0) c.error(1102, 1, "NSIDEX", "exempted node sets");
      if (c.i(2, "BOXID") != 0) c.error(1102, 2, "BOXID", "boxes");
      if (c.r(3, "OFFSET") != 0) c.error(1102, 3, "OFFSET", "wall offset");
      if (c.r(4, "BIRTH") != 0) c.error(1102, 4, "BIRTH", "wall birth time");
      double death = c.r(5, "DEATH");
      if (death != 0 && death < 1e20) c.error(1102, 5, "DEATH", "wall death time");
      c.r(6, "RWKSF");
      KCard c2 = card(b, k + 1, "card 2", W(b, 8));
      const char* names[] = {"XT", "YT", "ZT", "XH", "YH", "ZH"};
      for (int f = 0; f < 3; ++f) w.w.tail[std::size_t(f)] = c2.r(f, names[f]);
      for (int f = 0; f < 3; ++f) w.w.head[std::size_t(f)] = c2.r(3 + f, names[3 + f]);
      w.w.friction = c2.r(6, "FRIC");
      if (c2.r(7, "WVEL") != 0) c2.error(2006, 7, "WVEL", "critical velocity for stick (IMPACT-3D sticks for FRIC = 1)");
      double dx = w.w.head[0] - w.w.tail[0], dy = w.w.head[1] - w.w.tail[1], dz = w.w.head[2] - w.w.tail[2];
      double scale = 0;
      for (int f = 0; f < 3; ++f) scale = std::max({scale, std::fabs(w.w.head[std::size_t(f)]), std::fabs(w.w.tail[std::size_t(f)])});
      double len = std::sqrt(dx * dx + dy * dy + dz * dz);
      if (!(len > 1e-12 * scale) || len == 0) c2.error(1213, 0, "XT-ZH");
      if (!(w.w.friction >= 0 && w.w.friction <= 1)) c2.error(1219, 6, "FRIC");
      w.w.line = c.line();
      k += 2;
      if (b.moving_opt) {
        if (k >= b.data.size()) { missing_card(b, "card 3 (MASS, V0)"); return; }
        KCard c3 = card(b, k, "card 3", W(b, 2));
        w.w.mass = c3.r(0, "MASS");
        w.w.v0 = c3.r(1, "V0");
        if (!(w.w.mass > 0)) c3.error(1003, 0, "MASS", "a moving wall needs a positive mass");
        ++k;
      }
      walls_.push_back(std::move(w));
    }
  }

  void parse_contact(const Block& b, bool symmetric) {
    std::size_t k = skip_option_card(b);
    if (k >= b.data.size()) { missing_card(b, "card 1"); return; }
    RContact ct;
    ct.symmetric = symmetric;
    ct.keyword = b.keyword;
    KCard c = card(b, k, "card 1", W(b, 8));
    ct.ref = c.ref(0);
    ct.a.id = int(c.i(0, "SURFA"));
    ct.b.id = int(c.i(1, "SURFB"));
    ct.a.type = int(c.i(2, "SURFATYP"));
    ct.b.type = int(c.i(3, "SURFBTYP"));
    ct.a.id_ref = c.ref(0);
    ct.b.id_ref = c.ref(1);
    ct.a.type_ref = c.ref(2);
    ct.b.type_ref = c.ref(3);
    if (c.i(4, "SABOXID") != 0) c.error(1102, 4, "SABOXID", "boxes");
    if (c.i(5, "SBBOXID") != 0) c.error(1102, 5, "SBBOXID", "boxes");
    c.i(6, "SAPR");
    c.i(7, "SBPR");
    bool ok_a = ct.a.type == 0 || ct.a.type == 2 || ct.a.type == 3 || (ct.a.type == 4 && !symmetric);
    bool ok_b = ct.b.type == 0 || ct.b.type == 2 || ct.b.type == 3;
    if (!ok_a) c.error(1104, 2, "SURFATYP", symmetric ? "0 segment set, 2 part set, 3 part" : "0 segment set, 2 part set, 3 part, 4 node set");
    if (!ok_b) c.error(1104, 3, "SURFBTYP", "0 segment set, 2 part set, 3 part");
    if (k + 1 < b.data.size()) {
      KCard c2 = card(b, k + 1, "card 2", W(b, 8));
      ct.fs = c2.r(0, "FS");
      ct.fd = c2.r(1, "FD");
      ct.dc = c2.r(2, "DC");
      if (ct.fs < 0) c2.error(1219, 0, "FS");
      if (ct.fd < 0) c2.error(1219, 1, "FD");
      if (ct.dc < 0) c2.error(1003, 2, "DC", "must not be negative");
      if (c2.r(3, "VC") != 0) c2.error(2006, 3, "VC", "viscous friction limit");
      if (c2.r(4, "VDC") != 0) c2.error(2006, 4, "VDC", "viscous contact damping");
      c2.i(5, "PENCHK");
      if (c2.r(6, "BT") != 0) c2.error(1102, 6, "BT", "contact birth time");
      double dt = c2.r(7, "DT");
      if (dt != 0 && dt < 1e20) c2.error(1102, 7, "DT", "contact death time");
    }
    if (k + 2 < b.data.size()) {
      KCard c3 = card(b, k + 2, "card 3", W(b, 8));
      ct.sfsa = c3.r(0, "SFSA", 1.0);
      double sfsb = c3.r(1, "SFSB", 1.0);
      if (ct.sfsa == 0) ct.sfsa = 1;
      if (sfsb == 0) sfsb = 1;
      if (ct.sfsa < 0) c3.error(1003, 0, "SFSA", "must be positive");
      if (sfsb != ct.sfsa) c3.error(2006, 1, "SFSB", "one penalty scale per interface: SFSA is used for both sides");
      for (int f = 2; f < 8; ++f) c3.r(f, "SAST/SBST/SFSAT/SFSBT/FSF/VSF");
    }
    if (k + 3 < b.data.size()) {
      KCard ca = card(b, k + 3, "optional card A", W(b, 8));
      ct.soft = int(ca.i(0, "SOFT"));
      if (ct.soft == 2 || ct.soft == 4 || ct.soft == 6) ca.error(1102, 0, "SOFT", "contact formulation SOFT = " + std::to_string(ct.soft) + " (IMPACT-3D has 0 penalty and 1 soft constraint)");
      else if (ct.soft != 0 && ct.soft != 1) ca.error(1006, 0, "SOFT", "0 penalty (DYNA3D), 1 soft constraint (IMPACT-3D maximum stable stiffness)");
    }
    contacts_.push_back(ct);
  }

  void parse_curve(const Block& b) {
    std::size_t k = skip_option_card(b);
    if (k >= b.data.size()) { missing_card(b, "card 1 (LCID)"); return; }
    KCard c = card(b, k, "card 1", W(b, 8));
    LoadCurve lc;
    int lcid = int(c.i(0, "LCID"));
    c.set_card(b.keyword + " " + std::to_string(lcid));
    if (c.i(1, "SIDR") != 0) c.error(2006, 1, "SIDR", "dynamic relaxation");
    double sfa = c.r(2, "SFA", 1.0), sfo = c.r(3, "SFO", 1.0);
    if (sfa == 0) sfa = 1;
    if (sfo == 0) sfo = 1;
    double offa = c.r(4, "OFFA"), offo = c.r(5, "OFFO");
    c.i(6, "DATTYP");
    lc.number = lcid;
    std::vector<int> w = {b.long_fmt ? 20 : 20, b.long_fmt ? 20 : 20};
    for (++k; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      KCard p = card(b, k, "curve " + std::to_string(lcid) + " point", w);
      double t = p.r(0, "A") * sfa + offa;
      double f = p.r(1, "O") * sfo + offo;
      if (!lc.t.empty() && !(t > lc.t.back())) p.error(1217, 0, "A");
      lc.t.push_back(t);
      lc.f.push_back(f);
    }
    for (std::size_t j = 0; j < curves_.size(); ++j)
      if (curves_[j].number == lcid) c.error(1200, 0, "LCID", "also defined at " + at(curve_refs_[j]));
    curves_.push_back(std::move(lc));
    curve_refs_.push_back(c.ref(0));
  }

  // Keywords whose absence changes what the rest of the deck means: --lenient-keywords cannot
  // ignore them (*CASE blocks select cards per case; ignoring them applied every case's cards
  // at once).
  static bool changes_meaning(const std::string& name) { return name == "CASE" || name.rfind("CASE_", 0) == 0; }

  void report_unsupported() {
    if (unsupported_.empty()) return;
    std::map<std::string, int> ignorable, refused;  // keyword as written, upper case -> blocks
    int n_ignorable = 0, n_refused = 0;
    for (const Block* b : unsupported_) {
      const bool refuse = !opt_.lenient || changes_meaning(b->name);
      ++(refuse ? refused : ignorable)[upper(b->keyword.substr(1))];
      ++(refuse ? n_refused : n_ignorable);
      Location loc;
      loc.file = b->kw.file->name();
      loc.line = b->kw.line->number;
      loc.card = b->keyword;
      diag_.add(refuse ? 1301 : 2007, loc,
                opt_.lenient && refuse ? "the cards of every case would apply at once: a deck with *CASE is refused even with --lenient-keywords" : "");
    }
    auto summary = [&](int id, int blocks, const std::map<std::string, int>& count) {
      if (count.empty()) return;
      std::string list;
      for (const auto& [n, c] : count) list += (list.empty() ? "*" : ", *") + n + (c > 1 ? " (" + std::to_string(c) + "x)" : "");
      Location loc;
      loc.file = main_.name();
      diag_.add(id, loc, std::to_string(blocks) + " keyword block(s): " + list);
    };
    summary(2007, n_ignorable, ignorable);
    summary(1301, n_refused, refused);
  }

  // ---------------------------------------------------------------- pass 3: resolve
  std::vector<int> node_ids_;  // sorted user ids
  std::vector<int> elem_ids_;
  std::map<int, int> part_index_;      // pid -> index in parts_
  std::vector<int> part_material_;     // part index -> material index or -1
  std::vector<std::vector<int>> part_elems_;  // part index -> element indices

  bool node_ids_identity_ = false;  // node_ids_ is 1..N: the index is id - 1

  int node_index(int id) const {
    if (node_ids_identity_) return id >= 1 && id <= int(node_ids_.size()) ? id - 1 : -1;
    auto it = std::lower_bound(node_ids_.begin(), node_ids_.end(), id);
    return it != node_ids_.end() && *it == id ? int(it - node_ids_.begin()) : -1;
  }

  void err(int id, const Ref& r, const std::string& card, const char* field, std::string detail = {}) {
    diag_.add(id, loc_of(r, card, field), std::move(detail));
  }

  void resolve() {
    resolve_nodes();
    resolve_parts_and_elements();
    resolve_materials();
    resolve_control();
    resolve_spc();
    resolve_history();
    resolve_curves();
    resolve_walls();
    resolve_velocities();
    resolve_contacts();
  }

  void resolve_nodes() {
    std::vector<std::uint32_t> order(nodes_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
    const auto by_id = [&](std::uint32_t a, std::uint32_t b) { return nodes_[a].id < nodes_[b].id; };
    if (!std::is_sorted(order.begin(), order.end(), by_id)) std::stable_sort(order.begin(), order.end(), by_id);
    // the first of each id is kept (order is filtered in place)
    std::size_t nn = 0;
    for (std::size_t q = 0; q < order.size(); ++q) {
      const RNode& n = nodes_[order[q]];
      if (nn > 0 && nodes_[order[nn - 1]].id == n.id) {
        err(1200, n.ref(), "*NODE node " + std::to_string(n.id), "NID", "node " + std::to_string(n.id) + " also defined at " + at(nodes_[order[nn - 1]].ref()));
        continue;
      }
      order[nn++] = order[q];
    }
    const auto kept = [&](std::size_t k) { return &nodes_[order[k]]; };
    assign_huge(m_.x, nn, 0.0);
    assign_huge(m_.y, nn, 0.0);
    assign_huge(m_.z, nn, 0.0);
    assign_huge(m_.bc, nn, 0);
    node_ids_.resize(nn);
    bool identity = true;
    for (std::size_t k = 0; k < nn; ++k) {
      const RNode& n = *kept(k);
      node_ids_[k] = n.id;
      m_.x[k] = n.x;
      m_.y[k] = n.y;
      m_.z[k] = n.z;
      m_.bc[k] = n.tc;
      identity = identity && n.id == int(k) + 1;
    }
    m_.node_user_id.clear();
    if (!identity) m_.node_user_id = node_ids_;
    node_ids_identity_ = identity;
    release(order);
    release(nodes_);  // the raw nodes are not needed any more
    if (nn == 0) {
      Location loc;
      loc.file = main_.name();
      diag_.add(1311, loc, "*NODE: the deck defines no nodes");
    }
  }

  void resolve_parts_and_elements() {
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      auto [it, fresh] = part_index_.emplace(parts_[k].pid, int(k));
      if (!fresh) err(1200, parts_[k].ref, "*PART " + std::to_string(parts_[k].pid), "PID", "also defined at " + at(parts_[it->second].ref));
    }
    part_elems_.assign(parts_.size(), {});
    std::vector<std::uint32_t> order(elems_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
    const auto by_id = [&](std::uint32_t a, std::uint32_t b) { return elems_[a].id < elems_[b].id; };
    if (!std::is_sorted(order.begin(), order.end(), by_id)) std::stable_sort(order.begin(), order.end(), by_id);
    // the first of each id is kept (order is filtered in place)
    std::size_t ne = 0;
    for (std::size_t q = 0; q < order.size(); ++q) {
      const RElem& e = elems_[order[q]];
      if (ne > 0 && elems_[order[ne - 1]].id == e.id) {
        err(1200, e.ref(), "*ELEMENT_SOLID element " + std::to_string(e.id), "EID", "element " + std::to_string(e.id) + " also defined at " + at(elems_[order[ne - 1]].ref()));
        continue;
      }
      order[ne++] = order[q];
    }
    std::array<int, 8> undefined;
    undefined.fill(-1);
    assign_huge(m_.hex_nodes, ne, undefined);
    assign_huge(m_.hex_material, ne, -1);
    assign_huge(m_.hex_line, ne, 0);
    assign_huge(m_.hex_file, ne, -1);
    elem_ids_.resize(ne);
    bool identity = true;
    const DeckFile* last_file = nullptr;
    int last_file_index = -1;
    int last_pid = 0;
    auto last_part = part_index_.end();
    for (std::size_t k = 0; k < ne; ++k) {
      const RElem& e = elems_[order[k]];
      elem_ids_[k] = e.id;
      identity = identity && e.id == int(k) + 1;
      m_.hex_line[k] = e.card.line ? e.card.line->number : 0;
      if (e.card.file != last_file || !last_file) {
        last_file = e.card.file;
        last_file_index = file_index(e.card.file);
      }
      m_.hex_file[k] = last_file_index;
      const auto card = [&] { return "*ELEMENT_SOLID element " + std::to_string(e.id); };
      bool ok = true;
      std::array<int, 8> n{};
      for (int j = 0; j < 8; ++j) {
        int idx = node_index(e.n[std::size_t(j)]);
        if (idx < 0) {
          std::string f = "N" + std::to_string(j + 1);
          err(1202, e.node_ref(j), card(), f.c_str(), "node " + std::to_string(e.n[std::size_t(j)]) + " is not defined by *NODE");
          ok = false;
        }
        n[std::size_t(j)] = idx;
      }
      if (last_part == part_index_.end() || e.pid != last_pid) {
        last_part = part_index_.find(e.pid);
        last_pid = e.pid;
      }
      auto pit = last_part;
      if (pit == part_index_.end()) {
        err(1308, e.pid_ref(), card(), "PID", "part " + std::to_string(e.pid) + " is not defined by *PART" + refused_note('p', e.pid));
        ok = false;
      } else {
        part_elems_[std::size_t(pit->second)].push_back(int(k));
      }
      if (ok && !is_valid_solid_node_pattern(n)) {
        Ref r = e.node_ref(0);
        r.c2 = e.node_ref(7).c2;
        err(1222, r, card(), "N1-N8");
        ok = false;
      }
      if (ok) {
        make_canonical_solid_node_pattern(n);
        m_.hex_nodes[k] = n;
        m_.hex_material[k] = -2 - pit->second;  // part index, replaced by the material index
      }
    }
    release(order);
    release(elems_);  // the raw elements are not needed any more
    m_.hex_user_id.clear();
    if (!identity) m_.hex_user_id = elem_ids_;
    if (ne == 0) {
      Location loc;
      loc.file = main_.name();
      diag_.add(1311, loc, "*ELEMENT_SOLID: the deck defines no solid elements");
    }
  }


  void resolve_materials() {
    part_material_.assign(parts_.size(), -1);
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const RPart& p = parts_[k];
      if (part_index_[p.pid] != int(k)) continue;  // duplicate
      std::string card = "*PART " + std::to_string(p.pid);
      bool used = !part_elems_[k].empty();
      auto sit = sections_.find(p.secid);
      auto mit = mats_.find(p.mid);
      if (!used && (sit == sections_.end() || mit == mats_.end())) {
        Location loc = loc_of(p.ref, card, "PID");
        diag_.add(2011, loc, "no *ELEMENT_SOLID uses it and its section or material is not a supported solid one");
        continue;
      }
      MaterialData md;
      md.number = int(m_.materials.size()) + 1;
      md.title = p.title;
      md.line = p.line;
      if (sit == sections_.end()) {
        auto u = unsupported_secids_.find(p.secid);
        if (u != unsupported_secids_.end()) err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is " + u->second + "; solids need *SECTION_SOLID");
        else err(1310, p.sec_ref, card, "SECID", "*SECTION_SOLID " + std::to_string(p.secid) + " is not defined");
      } else if (sit->second.elform != 0 && sit->second.elform != 1) {
        err(1102, sit->second.ref, "*SECTION_SOLID " + std::to_string(p.secid), "ELFORM", "only ELFORM 1 (one-point constant-stress hexahedron)");
      }
      if (mit == mats_.end()) {
        auto u = unsupported_mids_.find(p.mid);
        if (u != unsupported_mids_.end()) err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is " + u->second + "; supported: " + supported_material_keywords());
        else err(1310, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is not defined by a *MAT keyword");
      } else {
        const RMat& r = mit->second;
        const MaterialData keep = md;
        md = r.md;
        md.number = keep.number;
        md.title = keep.title;
        md.line = keep.line;
        // the IMPACT-3D comment line INITIALLY_ELASTIC PART sets the type's switch, if it has one
        if (const MaterialParam* ie = find_param(*r.type, "IE")) {
          md.initially_elastic = initially_elastic_.count(p.pid) > 0;
          param_value(md, *ie) = md.initially_elastic ? 1.0 : 0.0;
        }
        // curve references: *DEFINE_CURVE ids -> the curves' numbers 1..NUMLC (resolve_curves)
        for (std::size_t i = 0; i < r.type->params.size(); ++i) {
          const MaterialParam& q = r.type->params[i];
          if (q.check != ParamCheck::curve || param_value(md, q) == 0) continue;
          const int id = int(param_value(md, q));
          std::size_t k = 0;
          while (k < curves_.size() && curves_[k].number != id) ++k;
          if (k < curves_.size()) param_value(md, q) = double(k + 1);
          else err(1310, r.refs[i], "*MAT material " + std::to_string(p.mid), q.key, "*DEFINE_CURVE " + std::to_string(id) + " is not defined");
        }
      }
      if (p.eosid != 0) err(1102, p.eos_ref, card, "EOSID", "equations of state");
      // hourglass and bulk viscosity
      int ihq = ctrl_ihq_;
      double qm = ctrl_qh_;
      md.q1 = ctrl_q1_;
      md.q2 = ctrl_q2_;
      if (p.hgid != 0) {
        auto hit = hourglasses_.find(p.hgid);
        if (hit == hourglasses_.end()) {
          err(1310, p.hg_ref, card, "HGID", "*HOURGLASS " + std::to_string(p.hgid) + " is not defined");
        } else {
          const RHourglass& h = hit->second;
          if (h.ihq != 0) ihq = h.ihq;
          if (h.qm > 0) qm = h.qm;
          if (!h.q1_blank) md.q1 = h.q1;
          if (!h.q2_blank) md.q2 = h.q2;
        }
      }
      md.hourglass_type = ihq == 0 ? 1 : ihq;
      md.hourglass_coef = qm > 0 ? qm : 0.10;
      md.bulk_type = ctrl_btype_;
      part_material_[k] = int(m_.materials.size());
      m_.materials.push_back(md);
    }
    for (int& hm : m_.hex_material) {
      if (hm <= -2) {
        int mat = part_material_[std::size_t(-2 - hm)];
        hm = mat;
        if (mat < 0) {
          // the part was refused above
        }
      }
    }
    // elements of a refused part keep -1: mark them undefined so the checks skip them
    for (std::size_t e = 0; e < m_.hex_material.size(); ++e)
      if (m_.hex_material[e] < 0) m_.hex_nodes[e].fill(-1);
  }

  void resolve_control() {
    ControlData& k = m_.control;
    k.nmmat = int(m_.materials.size());
    k.numnp = m_.num_nodes();
    k.numelh = m_.num_hexes();
    if (!have_termination_) {
      Location loc;
      loc.file = main_.name();
      diag_.add(1311, loc, "*CONTROL_TERMINATION (ENDTIM) is required");
    }
    k.end_time = end_time_;
    k.end_cycle = end_cycle_;
    k.min_step_factor = dtmin_;
    k.initial_dt = dtinit_;
    k.tssf = tssfac_;
    k.penalty_scale = slsfac_;
    k.report_interval = ikedit_;
    k.plot_interval = d3plot_dt_ > 0 ? d3plot_dt_ : end_time_ / 20;
    double th = nodout_dt_ > 0 ? nodout_dt_ : elout_dt_ > 0 ? elout_dt_ : glstat_dt_ > 0 ? glstat_dt_ : 0;
    k.th_interval = th > 0 ? th : end_time_ / 1000;
    k.interface_out_interval = ncforc_dt_;
    k.reaction_print_flag = reaction_flag_ >= 0 ? reaction_flag_ : spcforc_;
    k.restart_dump_cycles = d3dump_;
    k.running_restart_cycles = runrsf_;
  }

  // Node set members as 0-based node indices (undefined nodes reported).
  std::vector<int> set_nodes(const RIdList& s, const std::string& card) {
    std::vector<int> out;
    for (const auto& r : s.ranges) {  // _GENERATE: the nodes whose ids lie in each range
      auto lo = std::lower_bound(node_ids_.begin(), node_ids_.end(), r[0]);
      auto hi = std::upper_bound(node_ids_.begin(), node_ids_.end(), r[1]);
      for (auto it = lo; it < hi; ++it) out.push_back(int(it - node_ids_.begin()));
    }
    for (std::size_t j = 0; j < s.ids.size(); ++j) {
      int idx = node_index(s.ids[j]);
      if (idx < 0) {
        err(1202, s.refs[j], card, "NID", "node " + std::to_string(s.ids[j]) + " is not defined by *NODE");
        continue;
      }
      out.push_back(idx);
    }
    return out;
  }

  const RIdList* find_node_set(int sid, const Ref& r, const std::string& card, const char* field) {
    auto it = node_sets_.find(sid);
    if (it == node_sets_.end()) {
      err(1309, r, card, field, "*SET_NODE_LIST " + std::to_string(sid) + " is not defined" + refused_note('N', sid));
      return nullptr;
    }
    return &it->second;
  }

  // Parts of a part or part set, as part indices.
  std::vector<int> parts_of(bool is_set, int id, const Ref& r, const std::string& card, const char* field) {
    std::vector<int> out;
    if (is_set) {
      auto it = part_sets_.find(id);
      if (it == part_sets_.end()) {
        err(1309, r, card, field, "*SET_PART_LIST " + std::to_string(id) + " is not defined" + refused_note('P', id));
        return out;
      }
      for (std::size_t j = 0; j < it->second.ids.size(); ++j) {
        auto p = part_index_.find(it->second.ids[j]);
        if (p == part_index_.end()) err(1308, it->second.refs[j], "*SET_PART_LIST " + std::to_string(id), "PID", "part " + std::to_string(it->second.ids[j]) + " is not defined" + refused_note('p', it->second.ids[j]));
        else out.push_back(p->second);
      }
    } else {
      auto p = part_index_.find(id);
      if (p == part_index_.end()) err(1308, r, card, field, "part " + std::to_string(id) + " is not defined" + refused_note('p', id));
      else out.push_back(p->second);
    }
    return out;
  }

  std::vector<int> nodes_of_parts(const std::vector<int>& parts) {
    std::vector<char> mark(std::size_t(m_.num_nodes()), 0);
    for (int p : parts)
      for (int e : part_elems_[std::size_t(p)]) {
        const auto& n = m_.hex_nodes[std::size_t(e)];
        if (n[0] < 0) continue;
        for (int v : n) mark[std::size_t(v)] = 1;
      }
    std::vector<int> out;
    for (std::size_t k = 0; k < mark.size(); ++k)
      if (mark[k]) out.push_back(int(k));
    return out;
  }

  void resolve_spc() {
    for (const RSpc& s : spcs_) {
      std::vector<int> nodes;
      const std::string& card = s.keyword;
      if (s.set) {
        if (const RIdList* set = find_node_set(s.id, s.ref, card, "NSID")) nodes = set_nodes(*set, card);
      } else {
        int idx = node_index(s.id);
        if (idx < 0) err(1202, s.ref, card, "NID", "node " + std::to_string(s.id) + " is not defined by *NODE");
        else nodes.push_back(idx);
      }
      for (int n : nodes) m_.bc[std::size_t(n)] = bc_code(bc_bits(m_.bc[std::size_t(n)]) | s.bits);
    }
    if (rotational_spc_) {
      Location loc = loc_of(rotational_ref_, "", nullptr, false);
      diag_.add(2005, loc, std::to_string(rotational_spc_) + " rotational constraint(s) (*NODE RC, *BOUNDARY_SPC DOFR*)");
    }
  }

  void resolve_history() {
    for (const RHistory& h : histories_) {
      std::vector<int> idx;
      for (std::size_t j = 0; j < h.ids.size(); ++j) {
        int v = -1;
        if (h.solid) {
          auto it = std::lower_bound(elem_ids_.begin(), elem_ids_.end(), h.ids[j]);
          if (it != elem_ids_.end() && *it == h.ids[j]) v = int(it - elem_ids_.begin());
          else err(1201, h.refs[j], "*DATABASE_HISTORY_SOLID", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_SOLID");
        } else {
          v = node_index(h.ids[j]);
          if (v < 0) err(1202, h.refs[j], "*DATABASE_HISTORY_NODE", "NID", "node " + std::to_string(h.ids[j]) + " is not defined by *NODE");
        }
        if (v >= 0) idx.push_back(v);
      }
      auto& blocks = h.solid ? m_.solid_th_blocks : m_.node_th_blocks;
      for (std::size_t j = 0; j < idx.size();) {
        std::size_t e = j;
        while (e + 1 < idx.size() && idx[e + 1] == idx[e] + 1) ++e;
        blocks.push_back({idx[j] + 1, idx[e] + 1});
        j = e + 1;
      }
    }
    m_.control.node_th_blocks = int(m_.node_th_blocks.size());
    m_.control.solid_th_blocks = int(m_.solid_th_blocks.size());
  }

  void resolve_curves() {
    // renumbered 1..NUMLC in deck order (the fixed format needs 1..NUMLC)
    for (std::size_t k = 0; k < curves_.size(); ++k) {
      LoadCurve lc = curves_[k];
      const std::string card = "*DEFINE_CURVE " + std::to_string(lc.number);
      if (lc.t.size() < 2) err(1003, curve_refs_[k], card, "LCID", "a curve needs at least 2 points");
      lc.number = int(k) + 1;
      m_.load_curves.push_back(std::move(lc));
      // one line for all curves (Diagnostics folds the repeats, naming the curves); a curve a
      // material uses (a flow stress curve: the *MAT card still holds the deck's id) is used
      bool used = false;
      for (const auto& [mid, r] : mats_) used = used || material_uses_curve(r.md, curves_[k].number);
      if (!used) diag_.add(2004, loc_of(curve_refs_[k], card, nullptr, false), "no supported feature uses load curves yet");
    }
    m_.control.numlc = int(m_.load_curves.size());
  }

  void resolve_walls() {
    for (RWall& w : walls_) {
      if (w.nsid != 0) {
        if (const RIdList* s = find_node_set(w.nsid, w.nsid_ref, w.keyword, "NSID")) {
          w.w.nodes = set_nodes(*s, "*SET_NODE_LIST " + std::to_string(w.nsid));
          remove_repeated_nodes(w.w.nodes);
          if (w.w.nodes.empty()) err(1314, w.nsid_ref, w.keyword, "NSID", "the node set has no nodes (0 = all nodes)");
        }
      }
      m_.walls.push_back(w.w);
    }
    m_.control.num_walls = int(m_.walls.size());
  }

  // Appends the nodes as initial-velocity ranges: arithmetic runs first..last by increment.
  void add_velocity_nodes(const std::vector<int>& nodes, const std::array<double, 3>& v) {
    for (std::size_t j = 0; j < nodes.size();) {
      InitialVelocity iv;
      iv.first = nodes[j] + 1;
      iv.last = iv.first;
      iv.increment = 1;
      iv.v = v;
      std::size_t e = j;
      if (j + 1 < nodes.size() && nodes[j + 1] > nodes[j]) {
        int inc = nodes[j + 1] - nodes[j];
        e = j + 1;
        while (e + 1 < nodes.size() && nodes[e + 1] - nodes[e] == inc) ++e;
        iv.increment = inc;
        iv.last = nodes[e] + 1;
      }
      m_.init_velocities.push_back(iv);
      j = e + 1;
    }
  }

  // translation v.v plus, with OMEGA, the rotation OMEGA n x (x - xc): node by node
  void add_generated_velocities(const std::vector<int>& nodes, const RVelocity& v) {
    if (v.omega == 0) {
      add_velocity_nodes(nodes, v.v);
      return;
    }
    for (int i : nodes) {
      const double r[3] = {m_.x[std::size_t(i)] - v.xc[0], m_.y[std::size_t(i)] - v.xc[1], m_.z[std::size_t(i)] - v.xc[2]};
      const std::array<double, 3> vi = {v.v[0] + v.omega * (v.n[1] * r[2] - v.n[2] * r[1]),
                                        v.v[1] + v.omega * (v.n[2] * r[0] - v.n[0] * r[2]),
                                        v.v[2] + v.omega * (v.n[0] * r[1] - v.n[1] * r[0])};
      add_velocity_nodes({i}, vi);
    }
  }

  void resolve_velocities() {
    for (const RVelocity& v : velocities_) {
      switch (v.kind) {
        case RVelocity::all: {
          InitialVelocity iv;
          iv.first = 0;
          iv.last = 0;
          iv.v = v.v;
          m_.init_velocities.push_back(iv);
          break;
        }
        case RVelocity::node: {
          int idx = node_index(v.id);
          if (idx < 0) err(1202, v.ref, "*INITIAL_VELOCITY_NODE", "NID", "node " + std::to_string(v.id) + " is not defined by *NODE");
          else add_velocity_nodes({idx}, v.v);
          break;
        }
        case RVelocity::node_set:
          if (const RIdList* s = find_node_set(v.id, v.ref, "*INITIAL_VELOCITY", "NSID"))
            add_generated_velocities(set_nodes(*s, "*SET_NODE_LIST " + std::to_string(v.id)), v);
          break;
        case RVelocity::part:
        case RVelocity::part_set:
          add_generated_velocities(nodes_of_parts(parts_of(v.kind == RVelocity::part_set, v.id, v.ref, "*INITIAL_VELOCITY_GENERATION", "ID")), v);
          break;
      }
    }
    m_.control.num_init_velocity_cards = int(m_.init_velocities.size());
  }

  // index of a file in Model::source_files (registered on first use)
  int file_index(const DeckFile* f) {
    if (!f) return -1;
    for (std::size_t k = 0; k < m_.source_files.size(); ++k)
      if (m_.source_files[k] == f->name()) return int(k);
    m_.source_files.push_back(f->name());
    return int(m_.source_files.size()) - 1;
  }

  // Exterior faces of the elements of the parts (faces not shared by two of those elements),
  // in element and face order, outward counter-clockwise; triangles as n1 n2 n3 n3.
  void exterior_faces(const std::vector<int>& parts, const std::vector<char>* node_filter,
                      std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files) {
    std::vector<int> elems;
    for (int p : parts) elems.insert(elems.end(), part_elems_[std::size_t(p)].begin(), part_elems_[std::size_t(p)].end());
    if (node_filter) {
      elems.clear();
      for (int e = 0; e < m_.num_hexes(); ++e) elems.push_back(e);
    }
    std::sort(elems.begin(), elems.end());
    elems.erase(std::unique(elems.begin(), elems.end()), elems.end());
    std::map<std::array<int, 4>, int> count;
    auto key = [](std::array<int, 4> f) {
      std::sort(f.begin(), f.end());
      auto end = std::unique(f.begin(), f.end());
      for (auto it = end; it != f.end(); ++it) *it = -1;
      return f;
    };
    auto face = [&](int e, int f) {
      const auto& n = m_.hex_nodes[std::size_t(e)];
      return std::array<int, 4>{n[std::size_t(kHexFaces[f][0])], n[std::size_t(kHexFaces[f][1])],
                                n[std::size_t(kHexFaces[f][2])], n[std::size_t(kHexFaces[f][3])]};
    };
    for (int e : elems) {
      if (m_.hex_nodes[std::size_t(e)][0] < 0) continue;
      for (int f = 0; f < 6; ++f) ++count[key(face(e, f))];
    }
    for (int e : elems) {
      if (m_.hex_nodes[std::size_t(e)][0] < 0) continue;
      for (int f = 0; f < 6; ++f) {
        std::array<int, 4> s = face(e, f);
        std::array<int, 4> k = key(s);
        if (k[2] < 0) continue;  // collapsed face (edge or point)
        if (count[k] != 1) continue;
        if (k[3] < 0) {
          // triangle: rotate the cycle so that the repeated node is n3 = n4
          for (int r = 0; r < 4 && s[2] != s[3]; ++r) s = {s[1], s[2], s[3], s[0]};
          if (s[2] != s[3]) continue;
        }
        if (node_filter) {
          bool all = true;
          for (int v : s) all = all && (*node_filter)[std::size_t(v)];
          if (!all) continue;
        }
        out.push_back(s);
        lines.push_back(m_.hex_line[std::size_t(e)]);
        files.push_back(m_.hex_file.empty() ? -1 : m_.hex_file[std::size_t(e)]);
      }
    }
  }

  void resolve_side(const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                    std::vector<int>& lines, std::vector<int>& files) {
    const int errors_before = diag_.error_count();
    const char* field = slave ? "SURFA" : "SURFB";
    if (side.type == 0) {
      auto it = seg_sets_.find(side.id);
      if (it == seg_sets_.end()) {
        err(1309, side.id_ref, card, field, "*SET_SEGMENT " + std::to_string(side.id) + " is not defined" + refused_note('S', side.id));
        return;
      }
      const RSegSet& s = it->second;
      for (std::size_t j = 0; j < s.segs.size(); ++j) {
        std::array<int, 4> seg{};
        bool ok = true;
        for (int q = 0; q < 4; ++q) {
          int idx = node_index(s.segs[j][std::size_t(q)]);
          if (idx < 0) {
            std::string f = "N" + std::to_string(q + 1);
            err(1202, s.refs[j][std::size_t(q)], "*SET_SEGMENT " + std::to_string(side.id), f.c_str(), "node " + std::to_string(s.segs[j][std::size_t(q)]) + " is not defined by *NODE");
            ok = false;
          }
          seg[std::size_t(q)] = idx;
        }
        if (ok) {
          out.push_back(seg);
          lines.push_back(s.refs[j][0].line ? s.refs[j][0].line->number : 0);
          files.push_back(file_index(s.refs[j][0].file));
        }
      }
    } else if (side.type == 2 || side.type == 3) {
      exterior_faces(parts_of(side.type == 2, side.id, side.id_ref, card, field), nullptr, out, lines, files);
    } else if (side.type == 4) {
      if (const RIdList* s = find_node_set(side.id, side.id_ref, card, field)) {
        std::vector<char> mark(std::size_t(m_.num_nodes()), 0);
        for (int n : set_nodes(*s, "*SET_NODE_LIST " + std::to_string(side.id))) mark[std::size_t(n)] = 1;
        exterior_faces({}, &mark, out, lines, files);
      }
    }
    if (out.empty() && diag_.error_count() == errors_before &&
        (side.type == 0 || side.type == 2 || side.type == 3 || side.type == 4))
      err(1314, side.id_ref, card, field, "no segments");
  }

  void resolve_contacts() {
    for (const RContact& c : contacts_) {
      SlidingInterface si;
      si.type = 3;
      si.fs = c.fs;
      si.fd = c.fd;
      si.decay = c.dc;
      si.penalty_scale = c.sfsa == 1 ? 0 : c.sfsa * slsfac_;
      si.stiffness_method = c.soft;
      si.symmetric = c.symmetric;
      si.line = c.ref.line ? c.ref.line->number : 0;
      resolve_side(c.a, true, c.keyword, si.slave, si.slave_line, si.slave_file);
      resolve_side(c.b, false, c.keyword, si.master, si.master_line, si.master_file);
      m_.interfaces.push_back(std::move(si));
    }
    m_.control.num_interfaces = int(m_.interfaces.size());
  }
};

}  // namespace

bool is_keyword_deck(const DeckFile& deck) {
  for (const auto& l : deck.lines()) {
    if (is_blank(l.text) || l.text[0] == '$') continue;
    if (upper(l.text.substr(0, 8)) == "*KEYWORD") return true;
    break;
  }
  for (const auto& l : deck.lines())
    if (is_keyword_line(l.text)) return true;
  return false;
}

bool read_keyword_deck(DeckFile& deck, Model& model, Diagnostics& diag, const KeywordOptions& options) {
  model.deck_file = deck.name();
  model.large_format = true;
  model.keyword_deck = true;
  const int before = diag.error_count();
  KeywordReader r(deck, model, diag, options);
  r.read();
  return diag.error_count() == before;
}

bool read_deck(DeckFile& deck, Model& model, Diagnostics& diag, const InputOptions& options) {
  if (is_keyword_deck(deck)) {
    KeywordOptions ko;
    ko.lenient = options.lenient_keywords;
    return read_keyword_deck(deck, model, diag, ko);
  }
  return read_dyna3d_deck(deck, model, diag);
}

}  // namespace impact3d
