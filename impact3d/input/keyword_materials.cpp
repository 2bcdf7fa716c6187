// Keyword decks: *MAT_... (the types of the material table, material_types.h), *EOS_... (the
// forms of the EOS table, material/eos.h) and *MAT_ADD_EROSION, read by their tables
// (keyword_cards.cpp builds the *MAT_ and *EOS_ tables from those two tables) into the material
// records that the reader gives to the parts.  A material's parameters are checked by its
// type's table once its cards are read (check_material_params, the fixed format's checks too);
// an equation of state's by its form's (check_eos).

#include "impact3d/input/keyword_families.h"

#include <cmath>

namespace impact3d::kw {

namespace {

// The table positions of parameters read in the table's order: params[i] is field pos[i] of
// its card (names may repeat on a card, as the two LCID of *EOS_GRUNEISEN).
template <class Param>
std::vector<std::size_t> positions(const std::vector<Param>& params, std::vector<std::size_t> next) {
  std::vector<std::size_t> pos(params.size(), 0);
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].kcard >= 0 && std::size_t(params[i].kcard) < next.size()) pos[i] = next[std::size_t(params[i].kcard)]++;
  return pos;
}

// *MAT_...: card 1 MID RO and the type's parameters on the cards given (up to the type's).
void read_material(const Block& b, KeywordContext& ctx, const KeywordSpec& s, const MaterialType& t, KeywordMaterials& out) {
  std::size_t start = 0;
  if (!ctx.first_card(b, start)) return;
  std::vector<KeywordValues> cards;
  cards.reserve(s.cards.size());
  cards.push_back(ctx.fields(b, start, s.card("card 1")));
  KeywordValues& c = cards[0];
  const int mid = ctx.xid(int(c.integer("MID")), b, 'm');
  c.card().set_card(b.keyword + " material " + std::to_string(mid));
  RMat m;
  m.type = &t;
  m.ref = c.ref("MID");
  m.md.type = t.number;
  set_param_defaults(m.md, t);
  m.md.rho = c["RO"];
  for (std::size_t k = 1; k < s.cards.size() && start + k < b.data.size(); ++k) {
    const std::string label = "material " + std::to_string(mid) + " " + s.cards[k].card;
    cards.push_back(ctx.fields(b, start + k, s.cards[k], &label));
  }
  std::vector<std::size_t> next(s.cards.size(), 0);
  next[0] = 2;  // after MID and RO
  const std::vector<std::size_t> pos = positions(t.params, next);
  m.refs.assign(t.params.size(), m.ref);
  for (std::size_t i = 0; i < t.params.size(); ++i) {
    const MaterialParam& p = t.params[i];
    if (p.kcard < 0 || std::size_t(p.kcard) >= cards.size()) continue;
    KeywordValues& v = cards[std::size_t(p.kcard)];
    param_value(m.md, p) = v.nth(pos[i]);
    m.refs[i] = v.card().ref(p.kfield);
  }
  check_material_params(m.md, t, [&](const MaterialParam& p, int msg, const std::string& detail) {
    KeywordValues& v = p.kcard >= 0 && std::size_t(p.kcard) < cards.size() ? cards[std::size_t(p.kcard)] : cards[0];
    v.card().error(msg, p.kcard >= 0 ? p.kfield : 0, p.key, detail);
  });
  if (t.extra_card_feature && start + std::size_t(t.keyword_cards) < b.data.size()) {
    Location loc = loc_of(c.card().ref(-1), b.keyword);
    loc.line = b.data[start + std::size_t(t.keyword_cards)].line->number;
    ctx.diag.add(1102, loc, t.extra_card_feature);
  }
  if (b.title_opt) m.title = rtrim(b.data[0].line->text);
  if (out.mats.count(mid)) c.error(1200, "MID", "also defined at " + at(out.mats[mid].ref));
  out.mats[mid] = m;
}

// *EOS_... (_TITLE): the form's cards; a *PART's EOSID gives it to the part's material.
void read_eos(const Block& b, KeywordContext& ctx, const KeywordSpec& s, const EosForm& f, KeywordMaterials& out) {
  std::size_t start = 0;
  if (!ctx.first_card(b, start)) return;
  std::vector<KeywordValues> cards;
  cards.reserve(s.cards.size());
  for (std::size_t k = 0; k < s.cards.size() && start + k < b.data.size(); ++k) cards.push_back(ctx.fields(b, start + k, s.cards[k]));
  const int id = ctx.xid(int(cards[0].integer("EOSID")), b, 'r');
  for (std::size_t k = 0; k < cards.size(); ++k)
    cards[k].card().set_card(b.keyword + " " + std::to_string(id) + (k ? std::string(" ") + s.cards[k].card : std::string()));
  REos r;
  r.eos.form = f.form;
  r.eos.id = id;
  r.ref = cards[0].ref("EOSID");
  std::vector<std::size_t> next(s.cards.size(), 0);
  next[0] = 1;  // after EOSID
  const std::vector<std::size_t> pos = positions(f.params, next);
  for (std::size_t i = 0; i < f.params.size(); ++i) {
    const EosParam& p = f.params[i];
    if (std::size_t(p.kcard) >= cards.size()) continue;
    KeywordValues& v = cards[std::size_t(p.kcard)];
    const double x = v.nth(pos[i]);  // a refused field (slot < 0) is checked by its table
    if (p.slot < 0) continue;
    eos_value(r.eos, p) = x;
    if (r.eos.form == 6 && p.slot == kEosLeakCurve) {
      r.lcid_ref = v.card().ref(p.kfield);
      if (x > 0 && x == std::floor(x) && x < 1e9) eos_value(r.eos, p) = ctx.xid(int(x), b, 'f');
    }
  }
  check_eos(r.eos, 1.0, [&](const EosParam& p, int msg, const std::string& detail) {
    cards[std::min(std::size_t(p.kcard), cards.size() - 1)].card().error(msg, p.kfield, p.key, detail);
  });
  if (out.eos.count(id)) cards[0].error(1200, "EOSID", "also defined at " + at(out.eos[id].ref));
  out.eos[id] = r;
}

// *MAT_ADD_EROSION: the criteria of a material (MID); SIGTH, IMPULSE and IDAM refused unless
// blank, 0 or EXCL.
void read_erosion(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordMaterials& out) {
  std::size_t start = 0;
  if (!ctx.first_card(b, start)) return;
  KeywordValues c = ctx.fields(b, start, s.card("card 1"));
  const int mid = ctx.xid(int(c.integer("MID")), b, 'm');
  c.card().set_card(b.keyword + " material " + std::to_string(mid));
  ErosionData e;
  e.active = true;
  e.line = b.data[start].line->number;
  c.rest();
  e.excl = c["EXCL"];
  e.mxpres = c["MXPRES"];
  e.mneps = c["MNEPS"];
  e.effeps = c["EFFEPS"];
  e.voleps = c["VOLEPS"];
  const long long ncs = c.integer("NCS");
  e.ncs = ncs <= 0 ? 1 : int(ncs);
  auto unsupported = [&](KeywordValues& v, const char* name, const char* what) {
    const double x = v[name];
    if (!v.blank(name) && x != e.excl && x != 0) v.error(1102, name, what);
  };
  if (start + 1 < b.data.size()) {
    const std::string label = "material " + std::to_string(mid) + " card 2";
    KeywordValues d = ctx.fields(b, start + 1, s.card("card 2"), &label);
    e.mnpres = d["MNPRES"];
    e.sigp1 = d["SIGP1"];
    e.sigvm = d["SIGVM"];
    e.mxeps = d["MXEPS"];
    e.epssh = d["EPSSH"];
    unsupported(d, "SIGTH", "Tuler-Butcher erosion");
    unsupported(d, "IMPULSE", "Tuler-Butcher erosion");
    e.failtm = d["FAILTM"];
  }
  if (start + 2 < b.data.size()) {
    const std::string label = "material " + std::to_string(mid) + " card 3";
    KeywordValues d = ctx.fields(b, start + 2, s.card("card 3"), &label);
    unsupported(d, "IDAM", "damage models of *MAT_ADD_EROSION");
  }
  if (out.erosion.count(mid)) c.error(1200, "MID", "*MAT_ADD_EROSION of this material also given at " + at(out.erosion[mid].second));
  out.erosion[mid] = {e, c.ref("MID")};
}

}  // namespace

bool read_materials(const Block& b, KeywordContext& ctx, KeywordMaterials& m) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || s->family != KeywordFamily::materials) return false;
  if (const MaterialType* t = find_material_type_by_keyword(b.name)) read_material(b, ctx, *s, *t, m);
  else if (const EosForm* f = find_eos_form_by_keyword(b.name)) read_eos(b, ctx, *s, *f, m);
  else read_erosion(b, ctx, *s, m);
  return true;
}

}  // namespace impact3d::kw
