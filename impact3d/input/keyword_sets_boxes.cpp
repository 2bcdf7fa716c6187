// Keyword decks: the sets (*SET_NODE / _PART / _SOLID / _SHELL in their forms, *SET_SEGMENT
// (_ADD, _GENERAL)), the boxes (*DEFINE_BOX), coordinate systems and vectors
// (*DEFINE_COORDINATE_..., *DEFINE_VECTOR (_NODES)) and *DEFINE_TRANSFORMATION, read by their
// tables (keyword_cards.cpp) into the records that loads, initial velocities, rigid walls,
// contacts, histories and *INCLUDE_TRANSFORM refer to; the sets are resolved (lists, ranges,
// _ADD and _GENERAL terms) by the reader once every definition is known.

#include "impact3d/input/keyword_families.h"

#include <set>

namespace impact3d::kw {

namespace {

// BOXID XMN XMX YMN YMX ZMN ZMX: one box per keyword, as in LS-DYNA.
void read_box(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordSetsBoxes& out) {
  for (std::size_t k = option_cards(b); k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues v = ctx.fields(b, k, s.card(""));
    const int id = ctx.xid(int(v.integer("BOXID")), b, 'd');
    v.card().set_card(b.keyword + " " + std::to_string(id));
    RBox r;
    r.ref = v.ref("BOXID");
    static const char* const names[] = {"XMN", "XMX", "YMN", "YMX", "ZMN", "ZMX"};
    for (std::size_t a = 0; a < 3; ++a) {
      r.box.lo[a] = v[names[2 * a]];
      r.box.hi[a] = v[names[2 * a + 1]];
      if (r.box.hi[a] < r.box.lo[a]) v.error(1003, names[2 * a + 1], std::string("must not be below ") + names[2 * a]);
    }
    if (id < 1) v.error(1201, "BOXID", "box ids must be positive");
    if (out.boxes.count(id)) v.error(1200, "BOXID", "also defined at " + at(out.boxes[id].ref));
    out.boxes[id] = r;
    break;
  }
}

// Card 1 of a set (SID, with its *INCLUDE_TRANSFORM offset; k: its index once found), named by
// it where `named`; false (error 1316) if the block has no card.
bool set_card1(const Block& b, KeywordContext& ctx, const KeywordSpec& s, std::size_t& k, bool named,
               const std::function<void(KeywordValues& c, int sid)>& read) {
  if (!ctx.first_card(b, k, "card 1 (SID)")) return false;
  KeywordValues c = ctx.fields(b, k, s.card("card 1"));
  const int sid = ctx.xid(int(c.integer("SID")), b, 's');
  if (named) {
    c.card().set_card(b.keyword + " " + std::to_string(sid));
    if (sid < 1) c.error(1201, "SID", "set ids must be positive");
  }
  read(c, sid);
  return true;
}

// The ids of a card (table fields from..to-1) that are not 0, with their places.
void nonzero_ids(KeywordValues& d, std::size_t from, std::size_t to, std::vector<int>& ids, std::vector<Ref>& refs) {
  for (std::size_t f = from; f < to; ++f) {
    const long long id = d.integer_at(f);
    if (id != 0) {
      ids.push_back(int(id));
      refs.push_back(d.card().ref(int(f)));
    }
  }
}

// A card of a *SET_..._GENERAL: OPTION and 7 ids; a card whose first field is a number or
// blank continues the option before it with 8 ids.  The options are checked when the set is
// resolved (they differ between node and element sets).
void read_general_set_card(const Block& b, std::size_t k, KeywordContext& ctx, const KeywordSpec& s, const std::string& label,
                           RIdList& set) {
  Diagnostics quiet;  // the first field decides the card's table
  std::string opt = upper(KCard(b.data[k], b.keyword, std::vector<int>(8, b.long_fmt ? 20 : 10), quiet).literal(0));
  long long dummy = 0;
  const bool continuation = opt.empty() || parse_fortran_int(opt, dummy) == FieldStatus::ok;
  KeywordValues d = ctx.fields(b, k, s.card(continuation ? "continuation card" : "option card"), &label);
  if (continuation && set.terms.empty()) {
    d.card().error(1006, 0, "OPTION", "a *SET_..._GENERAL card starts with its option (ALL, NODE, ELEM, PART, BOX, SET_SOLID, ...)");
    return;
  }
  if (!continuation) {
    RSetTerm t;
    t.ref = d.ref("OPTION");
    // the removing options are the adding ones with a D in front (DNODE, DPART, DBOX, ...)
    static const std::set<std::string> adding = {"ALL", "NODE", "ELEM", "PART", "BOX", "SET_SOLID", "SET_SHELL",
                                                  "SET_BEAM", "SET_TSHELL", "SET_DISCRETE", "SET_NODE", "SET_PART"};
    if (opt.size() > 1 && opt[0] == 'D' && adding.count(opt.substr(1))) {
      t.remove = true;
      opt = opt.substr(1);
    }
    t.option = opt;
    set.terms.push_back(std::move(t));
  }
  RSetTerm& t = set.terms.back();
  nonzero_ids(d, continuation ? 0 : 1, 8, t.ids, t.refs);
}

// _GENERATE (pairs BBEG BEND) and _GENERATE_INCREMENT (triples BBEG BEND INCR): the ranges.
void read_ranges(KeywordValues& d, bool increment, RIdList& set) {
  const std::size_t step = increment ? 3 : 2;
  for (std::size_t f = 0; f + step - 1 < 8; f += step) {
    const long long b1 = d.integer_at(f), b2 = d.integer_at(f + 1);
    long long inc = increment ? d.integer_at(f + 2) : 1;
    if (b1 == 0 && b2 == 0) continue;
    if (inc == 0) inc = 1;
    if (b1 < 1 || b2 < b1 || b2 > 2147483647) {
      d.card().error(1003, int(f + 1), "BEND", "range must be 1 <= BBEG <= BEND <= 2147483647");
      continue;
    }
    if (inc < 0) {
      d.card().error(1003, int(f + 2), "INCR", "the increment must be positive");
      continue;
    }
    set.ranges.push_back({b1, b2, inc});  // ids in the range that are not defined are skipped at resolution
  }
}

// *SET_NODE / _PART / _SOLID / _SHELL (_LIST), _GENERATE (_INCREMENT), _ADD and _GENERAL.
void read_id_set(const Block& b, KeywordContext& ctx, const KeywordSpec& s, std::map<int, RIdList>& sets) {
  const std::string& n = b.name;
  auto ends = [&](const char* e) { return n.size() >= std::char_traits<char>::length(e) && n.compare(n.size() - std::char_traits<char>::length(e), std::string::npos, e) == 0; };
  const bool increment = ends("_GENERATE_INCREMENT"), generate = !increment && ends("_GENERATE");
  const bool add = ends("_ADD"), general = ends("_GENERAL");
  const char* data_card = increment || generate ? "range card" : add ? "set card" : "id card";
  std::size_t k = 0;
  set_card1(b, ctx, s, k, true, [&](KeywordValues& c, int sid) {
    RIdList set;
    set.ref = c.ref("SID");
    set.keyword = upper(b.keyword);
    const std::string label = "set " + std::to_string(sid);
    for (++k; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      if (general) {
        read_general_set_card(b, k, ctx, s, label, set);
        continue;
      }
      KeywordValues d = ctx.fields(b, k, s.card(data_card), &label);
      if (generate || increment) {
        read_ranges(d, increment, set);
      } else if (add) {
        RSetTerm t;
        t.option = "SET";
        t.ref = d.card().ref(0);
        nonzero_ids(d, 0, 8, t.ids, t.refs);
        set.terms.push_back(std::move(t));
      } else {
        nonzero_ids(d, 0, 8, set.ids, set.refs);
      }
    }
    if (sets.count(sid)) c.error(1200, "SID", "also defined at " + at(sets[sid].ref));
    sets[sid] = std::move(set);
  });
}

// *SET_SEGMENT (N1-N4 a card; card 1 not named by SID), _ADD (segment sets 8 a card) and
// _GENERAL (OPTION cards as for the other _GENERAL sets).
void read_segment_set(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordSetsBoxes& out) {
  const bool plain = b.name == "SET_SEGMENT", general = b.name == "SET_SEGMENT_GENERAL";
  std::size_t k = 0;
  set_card1(b, ctx, s, k, !plain, [&](KeywordValues& c, int sid) {
    RSegSet set;
    set.ref = c.ref("SID");
    RIdList terms;
    const std::string label = "set " + std::to_string(sid) + (plain ? " segment" : "");
    for (++k; k < b.data.size(); ++k) {
      if (is_blank(b.data[k].line->text)) continue;
      if (general) {
        read_general_set_card(b, k, ctx, s, label, terms);
        continue;
      }
      KeywordValues d = ctx.fields(b, k, s.card(plain ? "segment card" : "set card"), &label);
      if (!plain) {
        RSetTerm t;
        t.option = "SET";
        t.ref = d.card().ref(0);
        nonzero_ids(d, 0, 8, t.ids, t.refs);
        set.terms.push_back(std::move(t));
        continue;
      }
      std::array<int, 4> seg{};
      std::array<Ref, 4> refs;
      for (std::size_t f = 0; f < 4; ++f) {
        seg[f] = int(d.integer_at(f));
        refs[f] = d.card().ref(int(f));
      }
      if (seg[3] == 0) {  // triangle
        seg[3] = seg[2];
        refs[3] = refs[2];
      }
      set.segs.push_back(seg);
      set.refs.push_back(refs);
    }
    if (general) set.terms = std::move(terms.terms);
    if (out.seg_sets.count(sid)) c.error(1200, "SID", "also defined at " + at(out.seg_sets[sid].ref));
    out.seg_sets[sid] = std::move(set);
  });
}

// A coordinate system or vector a card defines: its kind's fields (the card named by its id).
void read_system_fields(const Block& b, KeywordValues& c, RCoordSystem& r) {
  const std::string& n = b.name;
  if (n == "DEFINE_COORDINATE_SYSTEM" || n == "DEFINE_COORDINATE_VECTOR" || n == "DEFINE_VECTOR") {
    r.kind = n == "DEFINE_COORDINATE_SYSTEM" ? RCoordSystem::points : n == "DEFINE_VECTOR" ? RCoordSystem::vector : RCoordSystem::vectors;
    for (std::size_t f = 0; f < 6; ++f) r.v[f] = c.nth(1 + f);
    if (r.kind != RCoordSystem::vectors) {
      const char* cid = r.kind == RCoordSystem::points ? "CIDL" : "CID";
      r.cid = int(c.integer(cid));
      r.cid_ref = c.ref(cid);
    }
    c.rest();  // NID of _VECTOR (warning 2006)
    return;
  }
  const bool is_vector = n == "DEFINE_VECTOR_NODES";
  r.kind = is_vector ? RCoordSystem::vector : RCoordSystem::nodes;
  for (std::size_t f = 0; f < (is_vector ? 2u : 3u); ++f) {
    r.n[f] = int(c.nth(1 + f));
    r.node_refs[f] = c.card().ref(int(1 + f));
  }
  if (is_vector) return;
  c["FLAG"];  // warning 2006
  const std::string dir = c.text("DIR");
  if (!dir.empty() && dir != "X" && dir != "1") c.error(1102, "DIR", "local axes along N1-N2 other than x");
}

// *DEFINE_COORDINATE_SYSTEM (card 2 XP YP ZP after each card 1), _NODES, _VECTOR, *DEFINE_VECTOR
// and *DEFINE_VECTOR_NODES: several definitions may follow one keyword.
void read_systems(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordSetsBoxes& out) {
  const bool is_vector = b.name.rfind("DEFINE_VECTOR", 0) == 0;
  const char* id_field = is_vector ? "VID" : "CID";
  for (std::size_t k = option_cards(b); k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues c = ctx.fields(b, k, s.card("card 1"));
    RCoordSystem r;
    r.keyword = b.keyword;
    r.id = ctx.xid(int(c.integer(id_field)), b, 'd');
    c.card().set_card(b.keyword + " " + std::to_string(r.id));
    r.ref = c.ref(id_field);
    if (r.id < 1) c.error(1201, id_field, "ids must be positive");
    read_system_fields(b, c, r);
    if (r.kind == RCoordSystem::points) {
      if (k + 1 >= b.data.size()) {
        ctx.missing_card(b, "card 2 (XP YP ZP)");
        return;
      }
      const std::string label = "system " + std::to_string(r.id) + " card 2";
      KeywordValues c2 = ctx.fields(b, ++k, s.card("card 2"), &label);
      for (std::size_t f = 0; f < 3; ++f) r.v[6 + f] = c2.nth(f);
    }
    for (const RCoordSystem& o : out.systems)
      if (o.id == r.id && (o.kind == RCoordSystem::vector) == (r.kind == RCoordSystem::vector))
        c.error(1200, id_field, "also defined at " + at(o.ref));
    out.systems.push_back(r);
  }
}

// *DEFINE_TRANSFORMATION: TRANID, then option cards OPTION A1-A7 composed in order.
void read_transformation(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordSetsBoxes& out) {
  std::size_t k = option_cards(b);
  while (k < b.data.size() && is_blank(b.data[k].line->text)) ++k;
  if (k >= b.data.size()) {
    ctx.missing_card(b, "card 1 (TRANID)");
    return;
  }
  KeywordValues c = ctx.fields(b, k, s.card("card 1"));
  const int id = int(c.integer("TRANID"));
  c.card().set_card(b.keyword + " " + std::to_string(id));
  RTransformation t;
  t.ref = c.ref("TRANID");
  c.check("TRANID");
  const std::string label = "transformation " + std::to_string(id);
  for (++k; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues d = ctx.fields(b, k, s.card("option card"), &label);
    const std::string opt = d.text("OPTION");
    double a[7];
    for (std::size_t f = 0; f < 7; ++f) a[f] = d.nth(1 + f);
    if (opt == "TRANSL") {
      t.map = t.map.then(AffineMap::translation({a[0], a[1], a[2]}));
    } else if (opt == "SCALE") {
      const Vec3 sc = {a[0] == 0 ? 1 : a[0], a[1] == 0 ? 1 : a[1], a[2] == 0 ? 1 : a[2]};
      t.map = t.map.then(AffineMap::scaling(sc));
    } else if (opt == "ROTATE") {
      if (a[0] == 0 && a[1] == 0 && a[2] == 0) d.card().error(1003, 1, "A1-A3", "the rotation axis must not be zero");
      else t.map = t.map.then(AffineMap::rotation({a[0], a[1], a[2]}, {a[3], a[4], a[5]}, a[6]));
    } else if (opt == "MIRROR" || opt == "POINT" || opt == "POS6P" || opt == "POS6N" || opt == "ROTATE3NA" || opt == "ROTATE3NB") {
      d.error(1102, "OPTION", opt + " transformations (IMPACT-3D has TRANSL, SCALE, ROTATE)");
    } else {
      d.error(1006, "OPTION", "TRANSL, SCALE or ROTATE");
    }
  }
  if (out.transformations.count(id)) c.error(1200, "TRANID", "also defined at " + at(out.transformations[id].ref));
  out.transformations[id] = t;
}

}  // namespace

bool read_sets_boxes(const Block& b, KeywordContext& ctx, KeywordSetsBoxes& s) {
  const KeywordSpec* spec = find_keyword_spec(b.name);
  if (!spec || spec->family != KeywordFamily::sets_boxes) return false;
  const std::string& n = b.name;
  if (n.rfind("SET_SEGMENT", 0) == 0) read_segment_set(b, ctx, *spec, s);
  else if (n.rfind("SET_NODE", 0) == 0) read_id_set(b, ctx, *spec, s.node_sets);
  else if (n.rfind("SET_PART", 0) == 0) read_id_set(b, ctx, *spec, s.part_sets);
  else if (n.rfind("SET_SOLID", 0) == 0) read_id_set(b, ctx, *spec, s.solid_sets);
  else if (n.rfind("SET_SHELL", 0) == 0) read_id_set(b, ctx, *spec, s.shell_sets);
  else if (b.name == "DEFINE_BOX") read_box(b, ctx, *spec, s);
  else if (b.name == "DEFINE_TRANSFORMATION") read_transformation(b, ctx, *spec, s);
  else read_systems(b, ctx, *spec, s);
  return true;
}

}  // namespace impact3d::kw
