// Keyword decks: *PART, *SECTION_SOLID, *SECTION_SHELL, *SECTION_BEAM and *HOURGLASS, read by
// their tables (keyword_cards.cpp) into the part and section records that the reader resolves
// (parts -> materials, sections, hourglass controls).

#include "impact3d/input/keyword_families.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace impact3d::kw {

namespace {

// pairs of cards: heading, then PID SECID MID EOSID HGID GRAV ADPOPT TMID
void read_parts(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordParts& p) {
  std::size_t k = 0;
  while (k < b.data.size()) {
    std::string title = rtrim(b.data[k].line->text.substr(0, std::min<std::size_t>(80, b.data[k].line->text.size())));
    if (k + 1 >= b.data.size()) {
      if (!is_blank(b.data[k].line->text)) ctx.missing_card(b, "card 2 (PID SECID MID ...)");
      break;
    }
    KeywordValues v = ctx.fields(b, k + 1, s.card("card 2"));
    RPart r;
    r.title = title;
    r.pid = int(v.integer("PID"));
    v.card().set_card(b.keyword + " part " + std::to_string(r.pid));
    v.rest();
    r.secid = int(v.integer("SECID"));
    r.mid = int(v.integer("MID"));
    r.eosid = int(v.integer("EOSID"));
    r.hgid = int(v.integer("HGID"));
    r.ref = v.ref("PID");
    r.sec_ref = v.ref("SECID");
    r.mid_ref = v.ref("MID");
    r.eos_ref = v.ref("EOSID");
    r.hg_ref = v.ref("HGID");
    r.line = v.card().line();
    p.parts.push_back(r);
    k += 2;
  }
}

// ELFORM 1 has one card; anything after belongs to other ELFORMs
void read_solid_section(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordParts& p) {
  const std::size_t k = option_cards(b);
  if (k >= b.data.size()) return;
  KeywordValues v = ctx.fields(b, k, s.card(""));
  const int id = ctx.xid(int(v.integer("SECID")), b, 'r');
  RSection r;
  r.elform = int(v.integer("ELFORM"));
  r.ref = v.ref("ELFORM");
  if (p.sections.count(id)) v.error(1200, "SECID", "also defined at " + at(p.sections[id].ref));
  p.sections[id] = r;
  v.rest();
}

// Card 1 of *SECTION_SHELL / _BEAM (after the _TITLE card), named by its SECID once that is
// read, given to `read` with the id and the card's index; error 1316 when the block ends before it.
void with_section_card1(const Block& b, KeywordContext& ctx, const KeywordSpec& s,
                        const std::function<void(KeywordValues& v, int id, std::size_t k)>& read) {
  const std::size_t k = option_cards(b);
  if (k >= b.data.size()) {
    ctx.missing_card(b, "card 1");
    return;
  }
  KeywordValues v = ctx.fields(b, k, s.card("card 1"));
  const int id = int(v.integer("SECID"));
  v.card().set_card(b.keyword + " " + std::to_string(id));
  read(v, id, k);
}

void read_shell_section(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordParts& p, KeywordValues& v,
                        int id, std::size_t k) {
  RShellSection sec;
  sec.ref = v.ref("SECID");
  v.rest();  // ELFORM 2 (Belytschko-Tsay, LS-DYNA's default: blank or 0 reads as 2) or 16
  sec.elform = v.integer("ELFORM") == 16 ? 16 : 2;
  sec.shrf = v["SHRF"];
  const double nip = v["NIP"];
  sec.nip = v.passed("NIP") ? int(nip) : 2;  // (refused: 1003/1102; not converted, it may not fit an int)
  if (k + 1 >= b.data.size()) {
    ctx.missing_card(b, "card 2 (T1 T2 T3 T4 NLOC MAREA IDOF EDGSET)");
  } else {
    KeywordValues v2 = ctx.fields(b, k + 1, s.card("card 2"));
    v2.card().set_card(b.keyword + " " + std::to_string(id));
    v2.rest();
    static const char* const kT[4] = {"T1", "T2", "T3", "T4"};
    for (std::size_t j = 0; j < 4; ++j) sec.t[j] = v2[kT[j]];
    // LS-DYNA: T2-T4 default to T1
    for (std::size_t j = 1; j < 4; ++j)
      if (sec.t[j] == 0) sec.t[j] = sec.t[0];
  }
  if (p.shell_sections.count(id) || p.sections.count(id)) v.error(1200, "SECID", "section also defined earlier");
  p.shell_sections[id] = sec;
}

// Card 2 of *SECTION_BEAM by ELFORM: 1 TS1 TS2 TT1 TT2 NSLOC NTLOC, 2 A ISS ITT J SA IST, 3 A
// RAMPT STRESS.
void read_beam_section_card2(KeywordValues& v, BeamSectionData& sec) {
  v.rest();
  if (sec.elform == 2) {
    sec.area = v["A"];
    sec.iss = v["ISS"];
    sec.itt = v["ITT"];
    sec.jt = v["J"];
    sec.sa = v["SA"];
  } else if (sec.elform == 3) {
    sec.area = v["A"];
  } else {
    sec.ts1 = v["TS1"];
    sec.ts2 = v["TS2"];
    sec.tt1 = v["TT1"];
    sec.tt2 = v["TT2"];
    if (sec.ts2 == 0) sec.ts2 = sec.ts1;  // IMPACT-3D: a blank node-2 size is node 1's
    if (sec.tt2 == 0) sec.tt2 = sec.tt1;
  }
}

void read_beam_section(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordParts& p, KeywordValues& v,
                       int id, std::size_t k) {
  RBeamSection r;
  r.ref = v.ref("SECID");
  BeamSectionData& sec = r.sec;
  sec.line = v.card().line();
  v.rest();
  sec.elform = int(v.integer("ELFORM"));
  const bool spot_weld_beam = sec.elform == 9;  // LS-DYNA's spot-weld beam: card 2 as ELFORM 1, and ITOFF
  sec.shrf = v["SHRF"];
  const double qr = v["QR/IRID"];
  sec.qr = v.passed("QR/IRID") ? int(qr) : 2;  // (refused: 1102/1003; not converted, it may not fit an int)
  if (v.passed("CST")) sec.cst = v.integer("CST") == 0 ? BeamCrossSection::rectangular : BeamCrossSection::tubular;
  if (k + 1 >= b.data.size() || is_keyword_line(b.data[k + 1].line->text)) {
    ctx.missing_card(b, sec.elform == 3   ? "card 2 (A RAMPT STRESS)"
                        : sec.elform == 2 ? "card 2 (A ISS ITT J SA IST)"
                                          : "card 2 (TS1 TS2 TT1 TT2 NSLOC NTLOC)");
  } else {
    KeywordValues v2 = ctx.fields(b, k + 1, s.card("card 2", spot_weld_beam    ? "ELFORM 9"
                                                             : sec.elform == 2 ? "ELFORM 2"
                                                             : sec.elform == 3 ? "ELFORM 3"
                                                                               : "ELFORM 1"));
    v2.card().set_card(b.keyword + " " + std::to_string(id));
    read_beam_section_card2(v2, sec);
  }
  if (spot_weld_beam) {  // the Hughes-Liu kernel with the card's (round) section
    sec.elform = 1;
    sec.spot_weld_beam = true;
  }
  if (p.beam_sections.count(id) || p.shell_sections.count(id) || p.sections.count(id))
    v.error(1200, "SECID", "section also defined earlier");
  p.beam_sections[id] = r;
}

void read_hourglass(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordParts& p) {
  const std::size_t k = option_cards(b);
  if (k >= b.data.size()) return;
  KeywordValues v = ctx.fields(b, k, s.card(""));
  const int id = ctx.xid(int(v.integer("HGID")), b, 'r');
  v.card().set_card(b.keyword + " " + std::to_string(id));
  RHourglass h;
  h.ref = v.ref("HGID");
  h.ihq_ref = v.ref("IHQ");
  h.q1_blank = v.blank("Q1");
  h.q2_blank = v.blank("Q2");
  v.rest();
  h.ihq = int(v.integer("IHQ"));
  h.qm = v["QM"];
  h.q1 = v["Q1"];
  h.q2 = v["Q2"];
  if (p.hourglasses.count(id)) v.error(1200, "HGID", "also defined at " + at(p.hourglasses[id].ref));
  p.hourglasses[id] = h;
}

}  // namespace

bool read_parts_sections(const Block& b, KeywordContext& ctx, KeywordParts& p) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || s->family != KeywordFamily::parts_sections) return false;
  if (b.name == "PART") read_parts(b, ctx, *s, p);
  else if (b.name == "SECTION_SOLID") read_solid_section(b, ctx, *s, p);
  else if (b.name == "SECTION_SHELL")
    with_section_card1(b, ctx, *s, [&](KeywordValues& v, int id, std::size_t k) { read_shell_section(b, ctx, *s, p, v, id, k); });
  else if (b.name == "SECTION_BEAM")
    with_section_card1(b, ctx, *s, [&](KeywordValues& v, int id, std::size_t k) { read_beam_section(b, ctx, *s, p, v, id, k); });
  else read_hourglass(b, ctx, *s, p);
  return true;
}

}  // namespace impact3d::kw
