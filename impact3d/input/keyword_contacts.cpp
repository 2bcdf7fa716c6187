// Keyword decks: the contacts (*CONTACT_...), read by their tables (keyword_cards.cpp) into
// RContact records; the reader resolves their sides once the sets and parts are known.

#include "impact3d/input/keyword_families.h"

namespace impact3d::kw {

namespace {

// The kind of contact a keyword (upper case, options stripped) is.
struct ContactKind {
  bool symmetric = false;   // both sides are surfaces
  bool transducer = false;  // *CONTACT_FORCE_TRANSDUCER_PENALTY
  bool single = false;      // one surface against itself
  bool eroding = false;     // the _ERODING_ card follows card 3
  int tied = 0;             // 1 *CONTACT_TIED_{NODES,SURFACE,SHELL_EDGE}_TO_SURFACE, 2 *CONTACT_SPOTWELD, 3 _SPOTWELD_WITH_TORSION
  int offset = 0;           // the tied forms' _OFFSET (1) and _CONSTRAINED_OFFSET (2)
};

// LS-DYNA's older and forming names read as the contact LS-DYNA treats them as
// (docs/keyword-decks.md): *CONTACT_SINGLE_SURFACE as the automatic single surface; the one-way
// surface-to-surface contacts (_ONE_WAY_, _AUTOMATIC_ONE_WAY_, _FORMING_ONE_WAY_) as
// nodes-to-surface of the slave surface's nodes; forming contacts are automatic (both sides
// of a shell, +-t/2).
ContactKind contact_kind(const std::string& n) {
  ContactKind k;
  k.eroding = n.rfind("CONTACT_ERODING_", 0) == 0;
  k.single = n == "CONTACT_AUTOMATIC_SINGLE_SURFACE" || n == "CONTACT_ERODING_SINGLE_SURFACE" || n == "CONTACT_SINGLE_SURFACE";
  k.transducer = n == "CONTACT_FORCE_TRANSDUCER_PENALTY";
  k.tied = n == "CONTACT_SPOTWELD_WITH_TORSION" ? 3 : n == "CONTACT_SPOTWELD" ? 2 : 0;
  for (const char* f : {"CONTACT_TIED_NODES_TO_SURFACE", "CONTACT_TIED_SURFACE_TO_SURFACE", "CONTACT_TIED_SHELL_EDGE_TO_SURFACE"})
    if (n == f) k.tied = 1;
  for (const char* f : {"CONTACT_TIED_NODES_TO_SURFACE", "CONTACT_TIED_SURFACE_TO_SURFACE"}) {
    if (n == std::string(f) + "_OFFSET") k.tied = 1, k.offset = 1;
    if (n == std::string(f) + "_CONSTRAINED_OFFSET") k.tied = 1, k.offset = 2;
  }
  k.symmetric = n == "CONTACT_SURFACE_TO_SURFACE" || n == "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE" ||
                n == "CONTACT_ERODING_SURFACE_TO_SURFACE";
  return k;
}

// Card 1: the sides, and the types the keyword allows (error 1104), a single surface's side B
// and the force transducer's interface-force flags (warning 2006).
void read_sides(KeywordValues& c, const ContactKind& kind, RContact& ct) {
  ct.ref = c.ref("SURFA");
  ct.a.id = int(c.integer("SURFA"));
  ct.b.id = int(c.integer("SURFB"));
  ct.a.type = int(c.integer("SURFATYP"));
  ct.b.type = int(c.integer("SURFBTYP"));
  ct.a.id_ref = c.ref("SURFA");
  ct.b.id_ref = c.ref("SURFB");
  ct.a.type_ref = c.ref("SURFATYP");
  ct.b.type_ref = c.ref("SURFBTYP");
  ct.a.boxid = int(c.integer("SABOXID"));
  ct.b.boxid = int(c.integer("SBBOXID"));
  ct.a.box_ref = c.ref("SABOXID");
  ct.b.box_ref = c.ref("SBBOXID");
  ct.sapr = c.integer("SAPR") == 1;
  ct.sbpr = c.integer("SBPR") == 1;
  const int ta = ct.a.type, tb = ct.b.type;
  const bool ok_a = ta == 0 || ta == 2 || ta == 3 || (ta == 4 && !kind.symmetric && !kind.single) || (ta == 5 && kind.single);
  bool ok_b = tb == 0 || tb == 2 || tb == 3;
  if (kind.single) {
    // one surface against itself: SURFA = 0 (or SURFATYP 5) is every part; side B unused
    if (ok_a && ct.a.id == 0) ct.a.type = 5;
    if (ct.b.id != 0 || ct.b.type != 0) c.error(2006, ct.b.id != 0 ? "SURFB" : "SURFBTYP", "a single-surface contact has only side A");
    if (ct.sbpr) c.error(2006, "SBPR", "a single-surface contact has only side A");
    ct.sbpr = false;
    ct.b = RSide{};
    ok_b = true;
  }
  if (!ok_a)
    c.error(1104, "SURFATYP", kind.single      ? "0 segment set, 2 part set, 3 part, 5 all parts (single surface)"
                              : kind.symmetric ? "0 segment set, 2 part set, 3 part"
                                               : "0 segment set, 2 part set, 3 part, 4 node set");
  if (!ok_b && !(kind.transducer && ct.b.type == 4))
    c.error(1104, "SURFBTYP", kind.transducer ? "0 segment set, 2 part set, 3 part, 4 node set" : "0 segment set, 2 part set, 3 part");
  if (kind.tied && (ct.sapr || ct.sbpr))
    c.error(2006, ct.sapr ? "SAPR" : "SBPR", "a tied contact's forces are not in the interface-force database");
  if (kind.transducer && (ct.sapr || ct.sbpr))
    c.error(2006, ct.sapr ? "SAPR" : "SBPR", "a force transducer has no contact segments in the interface-force database");
}

// Card 3: SFSA is used for both sides (SFSB other than it: warning 2006); a tied contact's SAST.
void read_penalty_scales(KeywordValues& c, RContact& ct) {
  ct.sfsa = c["SFSA"];
  if (c["SFSB"] != ct.sfsa) c.error(2006, "SFSB", "one penalty scale per interface: SFSA is used for both sides");
  if (ct.tied) ct.sast = c["SAST"];
  c.rest();
}

// Optional card A: SOFT (the formulations IMPACT-3D has), SOFSCL, and SOFT 2's SBOPT and DEPTH
// as far as IMPACT-3D implements them; the table checks the rest.  SOFT 2 (segment-based
// contact) is LS-DYNA's for surface-to-surface and single-surface contacts only.
void read_optional_card_a(KeywordValues& c, const ContactKind& kind, RContact& ct) {
  ct.soft = int(c.integer("SOFT"));
  const bool segment_based_ok = kind.symmetric || kind.single;
  if (ct.soft == 2 && !segment_based_ok && !ct.tied && !kind.transducer)
    c.error(1102, "SOFT", "segment-based contact SOFT = 2 on a nodes-to-surface contact (IMPACT-3D has it for the "
                          "surface-to-surface and single-surface contacts, as LS-DYNA)");
  else if (ct.soft == 4 || ct.soft == 6)
    c.error(1102, "SOFT", "contact formulation SOFT = " + std::to_string(ct.soft) +
                              " (IMPACT-3D has 0 penalty, 1 soft constraint, 2 segment-based, -1 maximum stable stiffness)");
  else if (ct.soft != 0 && ct.soft != 1 && ct.soft != -1 && ct.soft != 2)
    c.error(1006, "SOFT", "0 penalty, 1 soft constraint (LS-DYNA), 2 segment-based (LS-DYNA), -1 IMPACT-3D maximum stable stiffness");
  ct.sofscl = c["SOFSCL"];
  const int sbopt = int(c.integer("SBOPT")), depth = int(c.integer("DEPTH"));
  if (ct.soft == 2) {
    // SBOPT 0 / 2 (planar segments) and 3 (warped segments): IMPACT-3D's segments are bilinear
    // patches either way; 1 (old pinball edge check), 4 and 5 (sliding option) are not here
    if (sbopt != 0 && sbopt != 2 && sbopt != 3)
      c.error(1102, "SBOPT", "segment-based contact option SBOPT = " + std::to_string(sbopt) +
                                 " (IMPACT-3D has 0, 2 and 3: segments as bilinear patches, no sliding option)");
    // DEPTH 0 / 1 / 2: surface penetrations; edge-to-edge and the other depths are not here
    if (depth != 0 && depth != 1 && depth != 2)
      c.error(1102, "DEPTH", "segment-based search depth DEPTH = " + std::to_string(depth) +
                                 " (IMPACT-3D has 0, 1 and 2: surface penetrations only, no edge-to-edge contact)");
  }
  c.rest();
}

// Optional card B: THKOPT and SHLTHK (the shells' contact thickness, docs/contact.md) and ISYM
// (symmetry-plane faces left out of part sides); the table checks the rest.
void read_optional_card_b(KeywordValues& c, RContact& ct) {
  c["PENMAX"];
  ct.thkopt = int(c.integer("THKOPT"));
  if (ct.thkopt < 0 || ct.thkopt > 2) c.error(1006, "THKOPT", "0 *CONTROL_CONTACT's SHLTHK, 1 SHLTHK of this card, 2 no shell thickness");
  ct.shlthk = int(c.integer("SHLTHK"));
  if (ct.shlthk < 0 || ct.shlthk > 2) c.error(1006, "SHLTHK", "0 shells at their mid-surface, 1 at +-t/2 except rigid shells, 2 at +-t/2");
  c["SNLOG"];
  if (c.integer("ISYM") == 1) ct.isym = true;
  c.rest();
}

// One contact a block: [ID card], card 1, then cards 2 and 3, the _ERODING_ card and the
// optional cards A and B as far as they are given.
void read_contact(const Block& b, KeywordContext& ctx, const KeywordSpec& s, std::vector<RContact>& out) {
  std::size_t k = 0;
  if (!ctx.first_card(b, k)) return;
  const ContactKind kind = contact_kind(b.name);
  RContact ct;
  ct.symmetric = kind.symmetric;
  ct.transducer = kind.transducer;
  ct.single = kind.single;
  ct.tied = kind.tied;
  ct.offset = kind.offset;
  ct.keyword = b.keyword;
  ct.name = b.name;
  ct.automatic = kind.single || kind.eroding || b.name.find("AUTOMATIC") != std::string::npos || b.name.find("FORMING") != std::string::npos;
  if (b.id_opt && k == 1) ct.cid = int(ctx.values(b, 0, s.card("ID card")).integer("CID"));
  KeywordValues c1 = ctx.fields(b, k, s.card("card 1"));
  read_sides(c1, kind, ct);
  if (k + 1 < b.data.size()) {
    KeywordValues c2 = ctx.values(b, k + 1, s.card("card 2"));
    ct.fs = c2["FS"];
    ct.fd = c2["FD"];
    ct.dc = c2["DC"];
  }
  if (k + 2 < b.data.size()) {
    KeywordValues c3 = ctx.fields(b, k + 2, s.card("card 3"));
    read_penalty_scales(c3, ct);
  }
  std::size_t ka = k + 3;  // optional card A
  if (kind.eroding) {
    // LS-DYNA: EROSOP 0 keeps the exterior only
    if (k + 3 >= b.data.size()) {
      ctx.missing_card(b, "the _ERODING_ card (ISYM EROSOP IADJ)");
      return;
    }
    KeywordValues ce = ctx.values(b, k + 3, s.card("eroding card"));
    ct.isym = ce.integer("ISYM") == 1;
    ct.eroding = ce.integer("EROSOP") == 1;
    ka = k + 4;
  }
  if (ka < b.data.size()) {
    KeywordValues ca = ctx.fields(b, ka, s.card("optional card A"));
    read_optional_card_a(ca, kind, ct);
  }
  if (ka + 1 < b.data.size()) {
    KeywordValues cb = ctx.fields(b, ka + 1, s.card("optional card B"));
    read_optional_card_b(cb, ct);
  }
  out.push_back(ct);
}

}  // namespace

bool read_contacts(const Block& b, KeywordContext& ctx, std::vector<RContact>& out) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || s->family != KeywordFamily::contacts) return false;
  read_contact(b, ctx, *s, out);
  return true;
}

}  // namespace impact3d::kw
