// Keyword decks: the boxes (*DEFINE_BOX), coordinate systems and vectors (*DEFINE_COORDINATE_...,
// *DEFINE_VECTOR (_NODES)) and *DEFINE_TRANSFORMATION, read by their tables (keyword_cards.cpp)
// into the records that sets, initial velocities, rigid walls, contacts, loads and
// *INCLUDE_TRANSFORM refer to.  The sets are still read by keyword_reader.cpp.

#include "impact3d/input/keyword_families.h"

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
  if (b.name == "DEFINE_BOX") read_box(b, ctx, *spec, s);
  else if (b.name == "DEFINE_TRANSFORMATION") read_transformation(b, ctx, *spec, s);
  else read_systems(b, ctx, *spec, s);
  return true;
}

}  // namespace impact3d::kw
