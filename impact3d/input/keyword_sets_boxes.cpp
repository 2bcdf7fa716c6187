// Keyword decks: the boxes (*DEFINE_BOX), read by their table (keyword_cards.cpp) into the box
// records that sets, initial velocities, rigid walls and contacts refer to.  The sets, the
// coordinate systems and *DEFINE_TRANSFORMATION are still read by keyword_reader.cpp.

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

}  // namespace

bool read_sets_boxes(const Block& b, KeywordContext& ctx, KeywordSetsBoxes& s) {
  const KeywordSpec* spec = find_keyword_spec(b.name);
  if (!spec || spec->family != KeywordFamily::sets_boxes) return false;
  read_box(b, ctx, *spec, s);
  return true;
}

}  // namespace impact3d::kw
