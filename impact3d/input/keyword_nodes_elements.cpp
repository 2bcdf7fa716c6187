// Keyword decks: *NODE, *ELEMENT_SOLID, *ELEMENT_SHELL (_THICKNESS) and *ELEMENT_BEAM
// (_THICKNESS), read by their tables (keyword_cards.cpp) into the node and element records that
// the reader resolves (ids renumbered, elements -> parts and nodes).  Nodes and solids are the
// bulk of a deck: a plain card (plain_keyword_card) whose fields all read and pass the table's
// checks takes a fast path by the same columns; any other card is read by its table, with every
// message.

#include "impact3d/input/keyword_families.h"

#include <algorithm>
#include <cstdint>
#include <functional>

namespace impact3d::kw {

namespace {

const KeywordSpec& spec(const char* name) { return *find_keyword_spec(name); }

// Room for up to `more` records (one per data line at most), growing geometrically.
template <class V>
void reserve_for(V& v, std::size_t more) {
  if (v.capacity() - v.size() < more) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
}

// The columns of an element id in this block's format.
int id_width(const Block& b) { return b.long_fmt ? 20 : b.i10 ? 10 : 8; }

void read_nodes(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordMesh& m) {
  const std::uint8_t format = b.long_fmt ? 1 : b.i10 ? 2 : 0;
  const std::vector<int>& w = node_widths(format);
  reserve_for(m.nodes, b.data.size());
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
        m.nodes.push_back(n);
        continue;
      }
    }
    KeywordValues v = ctx.fields(b, k, s.card(""));
    RNode n;
    n.id = int(v.integer("NID"));
    v.card().set_card(b.keyword + " node " + std::to_string(n.id));
    n.format = format;
    n.card = b.data[k];
    v.rest();
    n.x = v["X"];
    n.y = v["Y"];
    n.z = v["Z"];
    if (!v.check("NID")) continue;
    n.tc = std::int8_t(v.check("TC") ? v.integer("TC") : 0);
    if (v.check("RC") && v.integer("RC") != 0) m.node_rc.push_back({n.id, bc_bits(int(v.integer("RC")))});
    m.nodes.push_back(n);
  }
}

// A 4-node tetrahedron written with N5-N8 blank (LS-PrePost): LS-DYNA's degenerate hexahedron
// N1 N2 N3 N4 N4 N4 N4 N4
void complete_tetrahedron(std::array<int, 8>& n) {
  if (n[3] != 0 && n[4] == 0 && n[5] == 0 && n[6] == 0 && n[7] == 0)
    for (int j = 4; j < 8; ++j) n[std::size_t(j)] = n[3];
}

// The fast path of a solid (see plain_keyword_card): true if the card (and the node card of the
// two-line form) read as numbers with no message to give; e then holds the element.
bool plain_solid(const Block& b, std::size_t k, bool legacy, int idw, RElem& e) {
  const std::string_view t = b.data[k].line->text;
  if (legacy) {
    const PlainFields f(t, id_widths(10, idw));
    bool ok = f.i(0, e.id) && f.i(1, e.pid);
    for (int j = 0; j < 8 && ok; ++j) ok = f.i(2 + j, e.n[std::size_t(j)]);
    return ok && e.id >= 1;
  }
  if (k + 1 >= b.data.size() || is_keyword_line(b.data[k + 1].line->text) || !plain_keyword_card(b.data[k + 1].line->text))
    return false;
  const PlainFields f1(t, id_widths(2, idw));
  const PlainFields f2(b.data[k + 1].line->text, id_widths(10, idw));
  int n9 = 0, n10 = 0;
  bool ok = f1.i(0, e.id) && f1.i(1, e.pid) && f2.i(8, n9) && f2.i(9, n10) && n9 == 0 && n10 == 0;
  for (int j = 0; j < 8 && ok; ++j) ok = f2.i(j, e.n[std::size_t(j)]);
  e.node_card = b.data[k + 1].line;
  return ok && e.id >= 1;
}

void read_solids(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordMesh& m) {
  const int idw = id_width(b);
  reserve_for(m.elems, b.data.size());
  std::size_t k = 0;
  while (k < b.data.size()) {
    if (is_blank(b.data[k].line->text)) { ++k; continue; }
    const std::string_view t = b.data[k].line->text;
    const bool free = t.find(',') != std::string::npos;
    const bool legacy = free ? std::count(t.begin(), t.end(), ',') >= 2 : rtrim(t).size() > std::size_t(2 * idw);
    RElem e;
    e.idw = std::uint8_t(idw);
    e.card = b.data[k];
    if (!free && plain_keyword_card(t) && plain_solid(b, k, legacy, idw, e)) {
      complete_tetrahedron(e.n);
      m.elems.push_back(e);
      k += legacy ? 1 : 2;
      continue;
    }
    e = RElem();
    e.idw = std::uint8_t(idw);
    e.card = b.data[k];
    KeywordValues v = ctx.fields(b, k, s.card("", legacy ? "one-line form" : "two-line form"));
    e.id = int(v.integer("EID"));
    v.card().set_card(b.keyword + " element " + std::to_string(e.id));
    e.pid = int(v.integer("PID"));
    bool ok = true;
    if (legacy) {
      for (std::size_t j = 0; j < 8; ++j) e.n[j] = int(v.nth(2 + j));
      ++k;
    } else {
      if (k + 1 >= b.data.size() || is_keyword_line(b.data[k + 1].line->text)) {
        v.card().error(1316, -1, nullptr, "the node card (N1-N8) of the two-line form is missing");
        break;
      }
      const std::string label = "element " + std::to_string(e.id) + " node card";
      KeywordValues v2 = ctx.fields(b, k + 1, s.card("node card"), &label);
      e.node_card = b.data[k + 1].line;
      for (std::size_t j = 0; j < 8; ++j) e.n[j] = int(v2.nth(j));
      for (const char* n : {"N9", "N10"}) {
        if (v2[n] != 0 && ok) {  // a 10-node tetrahedron: counted, refused once
          ok = false;
          if (m.tet10_count++ == 0) m.tet10_first = {v2.ref(n), e.id};
        }
      }
      k += 2;
    }
    if (!v.check("EID")) continue;
    complete_tetrahedron(e.n);
    if (ok) m.elems.push_back(e);
  }
}

// An option card of an element (card k + 1: `which`, "thickness card" or "orientation card"),
// named by the element, given to `read`; false (error 1316 on the element's card) if the block
// ends before it.
bool option_card(const Block& b, std::size_t k, KeywordContext& ctx, const KeywordSpec& s, KeywordValues& v, int id,
                 const char* which, const char* missing, const std::function<void(KeywordValues&)>& read) {
  if (k + 1 >= b.data.size() || is_keyword_line(b.data[k + 1].line->text)) {
    v.card().error(1316, -1, nullptr, missing);
    return false;
  }
  const std::string label = "element " + std::to_string(id) + " " + which;
  KeywordValues v2 = ctx.fields(b, k + 1, s.card(which), &label);
  read(v2);
  return true;
}

// The place of field j of a card in fixed columns (as KCard::ref gives it).
Ref fixed_ref(const KLine& l, const std::vector<int>& widths, std::size_t j) {
  int c1 = 1;
  for (std::size_t k = 0; k < j; ++k) c1 += widths[k];
  return {l.file, l.line, c1, c1 + widths[j] - 1};
}

// The fast path of a 4-node shell (see plain_keyword_card): true if the card reads as numbers
// with no message to give (EID >= 1, N5-N8 blank or 0); e then holds the element.
bool plain_shell(const KLine& l, int idw, RShell& e) {
  const std::vector<int>& w = id_widths(10, idw);
  const PlainFields f(l.line->text, w);
  bool ok = f.i(0, e.id) && f.i(1, e.pid) && e.id >= 1;
  for (std::size_t j = 0; j < 4 && ok; ++j) ok = f.i(int(2 + j), e.n[j]);
  for (int j = 6, x = 0; j < 10 && ok; ++j) ok = f.i(j, x) && x == 0;
  if (!ok) return false;
  e.ref = fixed_ref(l, w, 0);
  e.pid_ref = fixed_ref(l, w, 1);
  for (std::size_t j = 0; j < 4; ++j) e.node_refs[j] = fixed_ref(l, w, 2 + j);
  e.line = l.line->number;
  e.file = l.file;
  if (e.n[3] == 0) e.n[3] = e.n[2];  // triangle given with three nodes
  return true;
}

// The first card of a shell or beam: EID (the card then named by it), PID and the element's
// nodes N1... with their places.
template <class R>
KeywordValues element_card(const Block& b, std::size_t k, KeywordContext& ctx, const KeywordSpec& s, R& e) {
  KeywordValues v = ctx.fields(b, k, s.card(""));
  e.id = int(v.integer("EID"));
  v.card().set_card(b.keyword + " element " + std::to_string(e.id));
  e.pid = int(v.integer("PID"));
  e.ref = v.ref("EID");
  e.pid_ref = v.ref("PID");
  e.line = v.card().line();
  e.file = b.data[k].file;
  for (std::size_t j = 0; j < e.n.size(); ++j) {
    e.n[j] = int(v.nth(2 + j));
    e.node_refs[j] = v.card().ref(int(2 + j));
  }
  return v;
}

// The four sizes of a thickness card (each checked as read; ok false if one is refused), then
// the rest of the card.
void read_sizes(KeywordValues& v2, const char* const (&names)[4], std::array<double, 4>& t, bool& ok) {
  for (std::size_t j = 0; j < 4; ++j) {
    t[j] = v2[names[j]];
    ok = v2.passed(names[j]) && ok;
  }
  v2.rest();
}

// A shell or beam card at k and, with _THICKNESS, its thickness card (the four sizes `sizes`;
// k then at it): own(v, e, ok) reads the fields of the kind's own; more(v, k, e, ok) reads the
// cards of the kind's further options (k then at the last; false: the block ended before one,
// reported); the element goes to `out` when every field passed and its EID checks.  False when
// the block ends before an option card.
template <class R, class Out, class Own, class More>
bool read_element(const Block& b, std::size_t& k, KeywordContext& ctx, const KeywordSpec& s, bool thickness, const char* missing,
                  const char* const (&sizes)[4], Out& out, Own&& own, More&& more) {
  R e;
  KeywordValues v = element_card(b, k, ctx, s, e);
  bool ok = true;
  own(v, e, ok);
  if (thickness) {
    if (!option_card(b, k, ctx, s, v, e.id, "thickness card", missing, [&](KeywordValues& v2) { read_sizes(v2, sizes, e.t, ok); }))
      return false;
    ++k;
  }
  if (!more(v, k, e, ok)) return false;
  if (v.check("EID") && ok) out.push_back(e);
  return true;
}

// *ELEMENT_SHELL (_THICKNESS): EID PID N1-N8 (N5-N8 refused); _THICKNESS: THIC1-THIC4 BETA.
void read_shells(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordMesh& m, bool thickness) {
  if (!thickness) reserve_for(m.shells, b.data.size());
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    if (!thickness && plain_keyword_card(b.data[k].line->text)) {  // fast path (see plain_keyword_card)
      RShell e;
      if (plain_shell(b.data[k], id_width(b), e)) {
        m.shells.push_back(e);
        continue;
      }
    }
    static const char* const kT[4] = {"THIC1", "THIC2", "THIC3", "THIC4"};
    const bool read = read_element<RShell>(b, k, ctx, s, thickness, "the thickness card (THIC1-THIC4 BETA) is missing", kT, m.shells,
                                           [](KeywordValues& v, RShell& e, bool& ok) {
                                             for (const char* n : {"N5", "N6", "N7", "N8"}) ok = v.passed(n) && ok;
                                             if (e.n[3] == 0) e.n[3] = e.n[2];  // triangle given with three nodes
                                           },
                                           [](KeywordValues&, std::size_t&, RShell&, bool&) { return true; });
    if (!read) break;
  }
}

// *ELEMENT_BEAM (_THICKNESS) (_ORIENTATION): EID PID N1 N2 N3 RT1 RR1 RT2 RR2 LOCAL (releases
// refused); _THICKNESS: PARM1-PARM5 (the Hughes-Liu sizes TS1 TS2 TT1 TT2 of this element);
// _ORIENTATION: VX VY VZ (the vector from N1 to a virtual orientation node, where N3 is 0).
void read_beams(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordMesh& m, bool thickness, bool orientation) {
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    static const char* const kParm[4] = {"PARM1", "PARM2", "PARM3", "PARM4"};
    const bool read = read_element<RBeam>(
        b, k, ctx, s, thickness, "the thickness card (PARM1-PARM5) is missing", kParm, m.beams,
        [](KeywordValues& v, RBeam&, bool& ok) {
          for (const char* r : {"RT1", "RR1", "RT2", "RR2"}) ok = v.passed(r) && ok;
          v.rest();  // LOCAL
        },
        [&](KeywordValues& v, std::size_t& k2, RBeam& e, bool& ok) {
          if (!orientation) return true;
          if (!option_card(b, k2, ctx, s, v, e.id, "orientation card", "the orientation card (VX VY VZ) is missing",
                           [&](KeywordValues& v2) {
                             int j = 0;
                             for (const char* f : {"VX", "VY", "VZ"}) {
                               e.v[std::size_t(j++)] = v2[f];
                               ok = v2.passed(f) && ok;
                             }
                             v2.rest();
                           }))
            return false;
          ++k2;
          return true;
        });
    if (!read) break;
  }
}

}  // namespace

const std::vector<int>& node_widths(int format) {
  static const std::array<std::vector<int>, 3> w = [] {
    const KeywordCardLayout& c = spec("NODE").card("");
    return std::array<std::vector<int>, 3>{c.columns(false, false), c.columns(true, false), c.columns(false, true)};
  }();
  return w[std::size_t(format)];
}

const std::vector<int>& id_widths(int n, int idw) {
  static const std::array<std::array<std::vector<int>, 3>, 2> w = [] {
    const KeywordSpec& s = spec("ELEMENT_SOLID");
    std::array<std::array<std::vector<int>, 3>, 2> t;
    const KeywordCardLayout* cards[2] = {&s.card("", "two-line form"), &s.card("node card")};
    for (std::size_t a = 0; a < 2; ++a)
      t[a] = {cards[a]->columns(false, false), cards[a]->columns(false, true), cards[a]->columns(true, false)};
    return t;
  }();
  return w[n == 2 ? 0 : 1][idw == 8 ? 0 : idw == 10 ? 1 : 2];
}

int bc_bits(int code) {
  return (bc_fixes_x(code) ? 1 : 0) | (bc_fixes_y(code) ? 2 : 0) | (bc_fixes_z(code) ? 4 : 0);
}

bool read_nodes_elements(const Block& b, KeywordContext& ctx, KeywordMesh& m) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || s->family != KeywordFamily::nodes_elements) return false;
  if (b.name == "NODE") read_nodes(b, ctx, *s, m);
  else if (b.name == "ELEMENT_SOLID") read_solids(b, ctx, *s, m);
  else if (b.name.rfind("ELEMENT_SHELL", 0) == 0) read_shells(b, ctx, *s, m, b.name == "ELEMENT_SHELL_THICKNESS");
  else read_beams(b, ctx, *s, m, b.name.find("THICKNESS") != std::string::npos, b.name.find("ORIENTATION") != std::string::npos);
  return true;
}

}  // namespace impact3d::kw
