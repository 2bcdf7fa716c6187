// Keyword decks: the loads (*LOAD_NODE_POINT / _SET, *LOAD_RIGID_BODY, *LOAD_SEGMENT (_SET),
// *LOAD_BODY_...), their curves (*DEFINE_CURVE), *DAMPING_GLOBAL, the prescribed motions (*BOUNDARY_PRESCRIBED_MOTION_...), the
// constraints (*BOUNDARY_SPC_...) and the initial conditions (*INITIAL_VELOCITY...,
// *INITIAL_TEMPERATURE_...), read by their tables (keyword_cards.cpp) into records that the
// reader resolves once the sets, curves and coordinate systems are known.

#include "impact3d/input/keyword_families.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace impact3d::kw {

namespace {

// The data cards of a load keyword: every card, or with _ID every second one after its ID card.
std::vector<std::size_t> load_data_cards(const Block& b) {
  std::vector<std::size_t> out;
  const std::size_t step = b.id_opt ? 2 : 1;
  for (std::size_t k = b.id_opt ? 1 : option_cards(b); k < b.data.size(); k += step)
    if (!is_blank(b.data[k].line->text)) out.push_back(k);
  return out;
}

// LCID of a load card (required: checked by the table)
void read_load_curve(const Block& b, KeywordContext& ctx, KeywordValues& v, RLoad& l) {
  l.lcid = ctx.xid(int(v.integer("LCID")), b, 'f');
  l.lc_ref = v.ref("LCID");
}

// A load or motion of a node, set or part: its id (field idf, id kind for the include offset)
// and DOF, read from the card's first two fields.
RLoad load_record(const Block& b, KeywordContext& ctx, KeywordValues& v, RLoad::Kind kind, const char* idf, char id_kind) {
  RLoad l;
  l.kind = kind;
  l.keyword = upper(b.keyword);
  l.id = ctx.xid(int(v.integer(idf)), b, id_kind);
  l.ref = v.ref(idf);
  l.dof = int(v.integer("DOF"));
  return l;
}

// *LOAD_NODE_POINT / _SET: NID|NSID DOF LCID SF CID M1 M2 M3; *LOAD_RIGID_BODY: PID ...
void read_load_node(const Block& b, KeywordContext& ctx, const KeywordSpec& s, RLoad::Kind kind, KeywordLoads& out) {
  const char* idf = kind == RLoad::node ? "NID" : kind == RLoad::node_set ? "NSID" : "PID";
  for (std::size_t k : load_data_cards(b)) {
    KeywordValues v = ctx.fields(b, k, s.card(""));
    RLoad l = load_record(b, ctx, v, kind, idf, kind == RLoad::node ? 'n' : kind == RLoad::node_set ? 's' : 'p');
    read_load_curve(b, ctx, v, l);
    l.sf = v["SF"];
    l.cid = ctx.xid(int(v.integer("CID")), b, 'd');  // DOF along that system's axis
    l.cid_ref = v.ref("CID");
    v.rest();
    out.loads.push_back(l);
  }
}

// *LOAD_SEGMENT: LCID SF AT N1 N2 N3 N4 (N5..N8 of higher-order faces refused);
// *LOAD_SEGMENT_SET: SSID LCID SF AT DT
void read_load_segment(const Block& b, KeywordContext& ctx, const KeywordSpec& s, bool set, KeywordLoads& out) {
  for (std::size_t k : load_data_cards(b)) {
    KeywordValues v = ctx.fields(b, k, s.card(""));
    RLoad l;
    l.kind = set ? RLoad::segment_set : RLoad::segment;
    l.keyword = upper(b.keyword);
    if (set) {
      l.id = ctx.xid(int(v.integer("SSID")), b, 's');
      l.ref = v.ref("SSID");
    }
    read_load_curve(b, ctx, v, l);
    l.sf = v["SF"];
    l.birth = v["AT"];
    if (set) {
      const double dt = v["DT"];
      if (dt > 0) l.death = dt;
    } else {
      static const char* const names[] = {"N1", "N2", "N3", "N4"};
      for (std::size_t q = 0; q < 4; ++q) {
        l.nodes[q] = ctx.xid(int(v.integer(names[q])), b, 'n');
        l.node_refs[q] = v.ref(names[q]);
      }
      if (l.nodes[3] == 0) l.nodes[3] = l.nodes[2];  // a triangle
      v.rest();
    }
    out.loads.push_back(l);
  }
}

// *LOAD_BODY_X / _Y / _Z: LCID SF LCIDDR XC YC ZC CID; *LOAD_BODY_VECTOR: the same, then V1 V2 V3
void read_load_body(const Block& b, KeywordContext& ctx, const KeywordSpec& s, int axis, KeywordLoads& out) {
  if (b.data.empty()) {
    ctx.missing_card(b, "card 1 (LCID)");
    return;
  }
  KeywordValues v = ctx.fields(b, 0, s.card("card 1"));
  RLoad l;
  l.kind = RLoad::body;
  l.keyword = upper(b.keyword);
  l.ref = v.ref("LCID");
  read_load_curve(b, ctx, v, l);
  l.sf = v["SF"];
  v.rest();
  l.cid = ctx.xid(int(v.integer("CID")), b, 'd');  // the direction in that system
  l.cid_ref = v.ref("CID");
  if (axis < 3) {
    l.dir[std::size_t(axis)] = 1;
  } else if (b.data.size() < 2) {
    ctx.missing_card(b, "card 2 (V1 V2 V3)");
    return;
  } else {
    KeywordValues v2 = ctx.values(b, 1, s.card("card 2"));
    l.dir = {v2["V1"], v2["V2"], v2["V3"]};
    const double len = std::sqrt(l.dir[0] * l.dir[0] + l.dir[1] * l.dir[1] + l.dir[2] * l.dir[2]);
    if (!(len > 0)) {
      v2.error(1003, "V1", "the direction V1 V2 V3 must not be zero");
      return;
    }
    for (double& a : l.dir) a /= len;
  }
  out.loads.push_back(l);
}

// *DAMPING_GLOBAL: LCID VALDMP STX STY STZ SRX SRY SRZ (all six factors 0: all 1, as LS-DYNA)
void read_damping(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  if (b.data.empty()) return;  // a card of defaults: no damping
  KeywordValues v = ctx.values(b, 0, s.card("card 1"));
  RLoad& d = out.damping;
  d = RLoad();
  d.kind = RLoad::body;
  d.keyword = upper(b.keyword);
  d.lcid = ctx.xid(int(v.integer("LCID")), b, 'f');
  d.lc_ref = v.ref("LCID");
  d.ref = v.ref("LCID");
  d.sf = v["VALDMP"];
  static const char* const names[6] = {"STX", "STY", "STZ", "SRX", "SRY", "SRZ"};
  double f[6];
  bool any = false;
  for (std::size_t k = 0; k < 6; ++k) {
    f[k] = v[names[k]];
    any = any || f[k] != 0;
  }
  if (!any)
    for (double& x : f) x = 1;
  d.dir = {f[0], f[1], f[2]};
  if (f[3] != 0 || f[4] != 0 || f[5] != 0) out.damping_rotations = true;
  out.damping_given = d.lcid != 0 || d.sf > 0;
}

// Whether a motion with these DOF and VAD has LS-DYNA's card 2 (OFFSET1 OFFSET2 LRB NODE1 NODE2).
bool motion_has_card2(long long dof, long long vad) {
  return (dof >= 9 && dof <= 11) || (dof >= -11 && dof <= -9) || vad == 4;
}

// Card 1 of a prescribed motion at data card k; true when card 2 follows it.
bool read_motion(const Block& b, KeywordContext& ctx, const KeywordSpec& s, std::size_t k, RLoad::Kind kind,
                 KeywordLoads& out) {
  const char* idf = kind == RLoad::motion_node ? "NID" : kind == RLoad::motion_set ? "NSID" : "PID";
  KeywordValues v = ctx.fields(b, k, s.card(""));
  RLoad l = load_record(b, ctx, v, kind, idf, kind == RLoad::motion_node ? 'n' : kind == RLoad::motion_set ? 's' : 'p');
  const long long vad = v.integer("VAD");
  if (vad == 0) l.vad = MotionKind::velocity;
  else if (vad == 1) l.vad = MotionKind::acceleration;
  else if (vad == 2) l.vad = MotionKind::displacement;
  read_load_curve(b, ctx, v, l);
  l.sf = v["SF"];
  l.vid = ctx.xid(int(v.integer("VID")), b, 'd');  // the direction of DOF 4 and 8 (*DEFINE_VECTOR)
  l.vid_ref = v.ref("VID");
  if (motion_along_vector(l.dof) && l.vid == 0)
    v.error(1003, "VID", "DOF " + std::to_string(l.dof) + " moves along or about a vector: VID (*DEFINE_VECTOR) is required");
  const double death = v["DEATH"];
  l.death = death > 0 ? death : 1e28;
  l.birth = v["BIRTH"];
  if (l.death < l.birth) v.error(1003, "DEATH", "the death time comes before the birth time");
  const bool card2 = motion_has_card2(l.dof, vad);
  if (card2 && kind != RLoad::motion_rigid && motion_is_orbit(l.dof) && vad != 4 && k + 1 < b.data.size()) {
    KeywordValues c2 = ctx.values(b, k + 1, s.card("card 2"));  // (LRB, NODE1, NODE2 not 0: error 1102)
    l.offset1 = c2["OFFSET1"];
    l.offset2 = c2["OFFSET2"];
  }
  out.loads.push_back(l);
  return card2;
}

}  // namespace

void set_node_motion_kind(const RLoad& l, PrescribedMotion& pm) {
  pm.rotation = motion_is_rotation(l.dof);
  pm.orbit = motion_is_orbit(l.dof);
  pm.radial_free = pm.orbit && l.dof < 0;
  if (pm.orbit) {  // OFFSET1, OFFSET2: (y, z) about x, (z, x) about y, (x, y) about z
    const std::size_t a = std::size_t(std::abs(l.dof) - 9);
    pm.center[(a + 1) % 3] = l.offset1;
    pm.center[(a + 2) % 3] = l.offset2;
  }
}

namespace {

// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET / _RIGID: per motion [the _ID card], card 1, and card
// 2 when |DOF| is 9-11 or VAD is 4, as LS-DYNA reads them: a refused DOF or VAD still takes its
// card 2, so the next motion is read from the card it starts on.
void read_motions(const Block& b, KeywordContext& ctx, const KeywordSpec& s, RLoad::Kind kind, KeywordLoads& out) {
  const std::size_t id_cards = b.id_opt ? 1 : 0;
  std::size_t k = b.id_opt ? 1 : option_cards(b);
  while (k < b.data.size()) {
    std::size_t next = k + 1 + id_cards;
    if (!is_blank(b.data[k].line->text) && read_motion(b, ctx, s, k, kind, out)) {
      if (k + 1 >= b.data.size()) ctx.missing_card(b, "card 2 (OFFSET1 OFFSET2 LRB NODE1 NODE2), read with |DOF| 9-11 or VAD 4");
      ++next;
    }
    k = next;
  }
}

// *BOUNDARY_SPC_NODE / _SET: NID|NSID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ; with _BIRTH_DEATH
// each such card is followed by card 2 BIRTH DEATH.
void read_spc(const Block& b, KeywordContext& ctx, const KeywordSpec& s, bool set, bool birth_death, KeywordLoads& out) {
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text) || is_id_card(b, k)) continue;
    KeywordValues v = ctx.values(b, k, s.card(birth_death ? "card 1" : ""));
    RSpc r;
    if (birth_death) {
      r.birth_death = true;
      if (k + 1 >= b.data.size()) {
        ctx.missing_card(b, "card 2 (BIRTH DEATH)");
      } else {
        KeywordValues v2 = ctx.values(b, k + 1, s.card("card 2"));
        r.birth = v2["BIRTH"];
        r.death = v2["DEATH"];
        if (r.death < r.birth) v2.error(1003, "DEATH", "the death time comes before the birth time");
      }
    }
    r.keyword = upper(b.keyword);
    r.set = set;
    r.id = int(v.integer(set ? "NSID" : "NID"));
    r.ref = v.ref(set ? "NSID" : "NID");
    r.cid = int(v.integer("CID"));  // DOFX-DOFZ are along the axes of this system
    r.cid_ref = v.ref("CID");
    static const char* const names[] = {"DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"};
    for (int f = 0; f < 6; ++f) {
      if (v.integer(names[f]) != 1) continue;
      if (f < 3) r.bits |= 1 << f;
      if (f >= 3 && r.rbits == 0) out.rot_refs.push_back(v.ref(names[f]));
      if (f >= 3) r.rbits |= 1 << (f - 3);
    }
    out.spcs.push_back(r);
    if (birth_death) ++k;  // card 2
  }
}

// *CONSTRAINED_GLOBAL: TC RC DIR X Y Z TOL, one plane a card
void read_constrained_global(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues v = ctx.values(b, k, s.card(""));
    RGlobalConstraint g;
    g.tc = int(v.integer("TC"));
    g.ref = v.ref("TC");
    g.rc = int(v.integer("RC"));
    g.dir = int(v.integer("DIR"));
    const double at[3] = {v["X"], v["Y"], v["Z"]};
    g.at = g.dir >= 1 && g.dir <= 3 ? at[g.dir - 1] : 0;
    g.tol = v["TOL"];
    out.globals.push_back(g);
  }
}

// A wall's keyword and card 1 NSID NSIDEX BOXID; `id` gives an id its *INCLUDE_TRANSFORM
// offset (kind 's' sets, 'd' boxes) where the family gives it.
template <class Id>
RWall wall_nodes(const Block& b, KeywordValues& v, Id id) {
  RWall w;
  w.keyword = upper(b.keyword);
  w.nsid = id(int(v.integer("NSID")), 's');
  w.nsid_ref = v.ref("NSID");
  w.nsidex = id(int(v.integer("NSIDEX")), 's');
  w.nsidex_ref = v.ref("NSIDEX");
  w.boxid = id(int(v.integer("BOXID")), 'd');
  w.boxid_ref = v.ref("BOXID");
  return w;
}

// A wall's card 2 XT YT ZT XH YH ZH into its tail and head; false if they coincide (to 1e-12
// of the coordinates).
bool read_wall_axis(KeywordValues& v2, StoneWall& w) {
  static const char* const names[] = {"XT", "YT", "ZT", "XH", "YH", "ZH"};
  double len2 = 0, scale = 0;
  for (std::size_t f = 0; f < 3; ++f) {
    w.tail[f] = v2[names[f]];
    w.head[f] = v2[names[3 + f]];
    len2 += (w.head[f] - w.tail[f]) * (w.head[f] - w.tail[f]);
    scale = std::max({scale, std::fabs(w.head[f]), std::fabs(w.tail[f])});
  }
  return std::sqrt(len2) > 1e-12 * scale && len2 != 0;
}

// *RIGIDWALL_GEOMETRIC_CYLINDER (_DISPLAY), with _ID an ID card before each wall: card 1 NSID
// NSIDEX BOXID BIRTH DEATH, card 2 XT YT ZT XH YH ZH FRIC, card 3 RADCYL LENCYL NSEGS, and with
// _DISPLAY card 4 PID RO E PR (the display part: read, no effect).
void read_geometric_walls(const Block& b, KeywordContext& ctx, const KeywordSpec& s, bool display, KeywordLoads& out) {
  std::size_t k = 0;
  while (k < b.data.size()) {
    if (is_blank(b.data[k].line->text)) {
      ++k;
      continue;
    }
    if (b.id_opt) ++k;  // RWID, heading
    if (k + 2 >= b.data.size()) {
      ctx.missing_card(b, "cards 1-3 (NSID ...; XT ... FRIC; RADCYL LENCYL)");
      return;
    }
    KeywordValues v = ctx.values(b, k, s.card("card 1"));
    RWall g = wall_nodes(b, v, [&](int id, char kind) { return ctx.xid(id, b, kind); });
    const double death = v["DEATH"];
    if (death != 0 && death < 1e20) v.error(1102, "DEATH", "wall death time");
    KeywordValues v2 = ctx.values(b, k + 1, s.card("card 2"));
    const bool axis = read_wall_axis(v2, g.w);
    g.w.friction = v2["FRIC"];
    if (!axis) v2.error(1213, "XT", "the cylinder's axis (tail to head) has no length");
    KeywordValues v3 = ctx.values(b, k + 2, s.card("card 3"));
    g.w.radius = v3["RADCYL"];
    g.w.length = v3["LENCYL"];
    g.w.line = b.data[k].line->number;
    k += 3;
    if (display) {
      if (k >= b.data.size()) {
        ctx.missing_card(b, "card 4 (PID RO E PR), read with _DISPLAY");
        return;
      }
      ctx.values(b, k, s.card("card 4"));
      ++k;
    }
    out.geometric_walls.push_back(g);
  }
}

// *RIGIDWALL_PLANAR (_MOVING) (_ID): per wall [ID card, not read], card 1 NSID NSIDEX BOXID
// OFFSET BIRTH DEATH RWKSF, card 2 XT YT ZT XH YH ZH FRIC WVEL, with _MOVING card 3 MASS V0.
// The ids get their *INCLUDE_TRANSFORM offsets once the deck is read (the reader's).
void read_planar_walls(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  std::size_t k = 0;
  while (k < b.data.size()) {
    if (b.id_opt) ++k;  // RWID, heading
    if (k + 1 >= b.data.size()) {
      ctx.missing_card(b, "cards 1 and 2");
      return;
    }
    KeywordValues v = ctx.values(b, k, s.card("card 1"));
    RWall w = wall_nodes(b, v, [](int id, char) { return id; });
    KeywordValues v2 = ctx.values(b, k + 1, s.card("card 2"));
    w.w.friction = v2["FRIC"];
    if (!read_wall_axis(v2, w.w)) v2.card().error(1213, 0, "XT-ZH");
    v2.check("FRIC");
    w.w.line = v.card().line();
    k += 2;
    if (b.moving_opt) {
      if (k >= b.data.size()) {
        ctx.missing_card(b, "card 3 (MASS, V0)");
        return;
      }
      KeywordValues v3 = ctx.values(b, k, s.card("card 3"));
      w.w.mass = v3["MASS"];
      w.w.v0 = v3["V0"];
      ++k;
    }
    out.walls.push_back(std::move(w));
  }
}

// The failure fields SN SS N M of a spot weld's card: the exponents must be positive where
// their force is given.
void read_weld_failure(KeywordValues& v, RWeld& w) {
  w.sn = v["SN"];
  w.ss = v["SS"];
  w.n = v["N"];
  w.m = v["M"];
  if (w.sn > 0 && !(w.n > 0)) v.error(1003, "N", "the exponent of the normal force must be positive when SN is given");
  if (w.ss > 0 && !(w.m > 0)) v.error(1003, "M", "the exponent of the shear force must be positive when SS is given");
}

// EP / EPSF as the weld keeps it: 0 or >= 1e19 (blank: 1e20) is no ductile failure.
double ductile_failure_strain(double e) { return e > 0 && e < 1e19 ? e : 0.0; }

// *CONSTRAINED_SPOTWELD(_ID): per weld ([WID]) N1 N2 SN SS N M TF EP.
void read_spot_welds(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  int wid = 0;
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    if (is_id_card(b, k)) {
      wid = int(ctx.values(b, k, s.card("ID card")).integer("WID"));
      continue;
    }
    KeywordValues v = ctx.fields(b, k, s.card(""));
    RWeld w;
    w.keyword = upper(b.keyword);
    w.wid = wid;
    wid = 0;
    w.n1 = int(v.integer("N1"));
    w.n2 = int(v.integer("N2"));
    w.ref = v.ref("N1");
    w.ref2 = v.ref("N2");
    read_weld_failure(v, w);
    w.tfail = v["TF"];
    w.epsf = ductile_failure_strain(v["EP"]);
    v.rest();
    out.welds.push_back(w);
  }
}

// *CONSTRAINED_GENERALIZED_WELD_SPOT(_ID): per weld ([WID]) card 1 NSID CID FILTER WINDOW NPRT,
// card 2 TFAIL EPSF SN SS N M.
void read_generalized_welds(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  int wid = 0;
  std::vector<std::size_t> cards;
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    if (is_id_card(b, k) && cards.size() % 2 == 0) {
      wid = int(ctx.values(b, k, s.card("ID card")).integer("WID"));
      continue;
    }
    cards.push_back(k);
    if (cards.size() % 2 == 1) continue;
    KeywordValues v1 = ctx.fields(b, cards[cards.size() - 2], s.card("card 1"));
    KeywordValues v2 = ctx.fields(b, k, s.card("card 2"));
    RWeld w;
    w.keyword = upper(b.keyword);
    w.generalized = true;
    w.wid = wid;
    wid = 0;
    w.nsid = int(v1.integer("NSID"));
    w.ref = v1.ref("NSID");
    w.cid = int(v1.integer("CID"));
    w.cid_ref = v1.ref("CID");
    v1.rest();
    w.tfail = v2["TFAIL"];
    w.epsf = ductile_failure_strain(v2["EPSF"]);
    read_weld_failure(v2, w);
    out.welds.push_back(w);
  }
  if (cards.size() % 2 == 1) ctx.missing_card(b, "card 2 (TFAIL EPSF SN SS N M)");
}

// *INITIAL_TEMPERATURE_NODE (NID TEMP LOC per card) and _SET (NSID TEMP LOC; NSID 0: every
// node): the nodes' initial temperatures, in deck order (a later card wins); LOC (a shell
// surface) is warning 2006: the temperature holds through the thickness.
void read_temperatures(const Block& b, KeywordContext& ctx, const KeywordSpec& s, bool set, KeywordLoads& out) {
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues v = ctx.values(b, k, s.card(""));
    RTemperature t;
    t.set = set;
    t.id = int(v.integer(set ? "NSID" : "NID"));
    t.ref = v.ref(set ? "NSID" : "NID");
    t.temp = v["TEMP"];
    out.temperatures.push_back(t);
  }
}

// An initial-velocity record: its keyword, and its id from field idf; ICID when the card has it.
RVelocity velocity_record(const Block& b, KeywordValues& v, const char* idf) {
  RVelocity r;
  r.keyword = upper(b.keyword);
  r.id = int(v.integer(idf));
  r.ref = v.ref(idf);
  return r;
}
void read_icid(KeywordValues& v, RVelocity& r) {
  r.icid = int(v.integer("ICID"));
  r.icid_ref = v.ref("ICID");
}

// VX VY VZ and VXR VYR VZR of an initial velocity (a rotational one remembered for the message
// when no shell node takes it).
void read_velocities(KeywordValues& v, RVelocity& r, KeywordLoads& out) {
  r.v = {v["VX"], v["VY"], v["VZ"]};
  r.w = {v["VXR"], v["VYR"], v["VZR"]};
  r.has_w = r.w[0] != 0 || r.w[1] != 0 || r.w[2] != 0;
  if (r.has_w) out.w_ref = v.ref("VXR");
}

void read_velocity_nodes(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues v = ctx.values(b, k, s.card(""));
    RVelocity r = velocity_record(b, v, "NID");
    r.kind = RVelocity::node;
    read_velocities(v, r, out);
    read_icid(v, r);
    out.velocities.push_back(r);
  }
}

// *INITIAL_VELOCITY: card 1 NSID NSIDEX BOXID IRIGID ICID, card 2 VX VY VZ (VXR-VZR), and with
// NSIDEX card 3 VXE VYE VZE (VXRE-VZRE): the velocity of the exempted nodes.
void read_initial_velocity(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  for (std::size_t k = 0; k < b.data.size(); k += 2) {
    KeywordValues v = ctx.values(b, k, s.card("card 1"));
    RVelocity r = velocity_record(b, v, "NSID");
    r.kind = r.id == 0 ? RVelocity::all : RVelocity::node_set;
    r.nsidex = int(v.integer("NSIDEX"));
    r.nsidex_ref = v.ref("NSIDEX");
    r.boxid = int(v.integer("BOXID"));
    r.boxid_ref = v.ref("BOXID");
    read_icid(v, r);
    if (k + 1 >= b.data.size()) {
      ctx.missing_card(b, "card 2 (VX VY VZ)");
      break;
    }
    KeywordValues v2 = ctx.values(b, k + 1, s.card("card 2"));
    read_velocities(v2, r, out);
    if (r.nsidex > 0) {
      if (k + 2 >= b.data.size()) {
        ctx.missing_card(b, "card 3 (VXE VYE VZE), needed with NSIDEX");
        break;
      }
      KeywordValues v3 = ctx.fields(b, k + 2, s.card("card 3"));
      r.ve = {v3["VXE"], v3["VYE"], v3["VZE"]};
      for (std::size_t f = 3; f < 6; ++f)  // the first nonzero VXRE-VZRE only
        if (v3.nth(f) != 0) {
          v3.card().error(2006, int(f), "VXRE/VYRE/VZRE", "solid nodes have no rotations");
          break;
        }
      ++k;
    } else if (r.nsidex < 0) {
      v.error(1003, "NSIDEX", "a node set id (0: none)");
    }
    out.velocities.push_back(r);
  }
}

// *INITIAL_VELOCITY_GENERATION: card 1 ID STYP OMEGA VX VY VZ IVATN ICID, card 2 XC YC ZC NX NY
// NZ PHASE IRIGID.
void read_velocity_generation(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  for (std::size_t k = 0; k < b.data.size(); k += 2) {
    KeywordValues v = ctx.values(b, k, s.card("card 1"));
    RVelocity r = velocity_record(b, v, "ID");
    const long long styp = v.integer("STYP");
    r.kind = styp == 1 ? RVelocity::part_set : styp == 2 ? RVelocity::part : RVelocity::node_set;
    r.omega = v["OMEGA"];
    r.v = {v["VX"], v["VY"], v["VZ"]};
    read_icid(v, r);
    if (k + 1 < b.data.size()) {
      KeywordValues v2 = ctx.values(b, k + 1, s.card("card 2"));
      r.xc = {v2["XC"], v2["YC"], v2["ZC"]};
      r.n = {v2["NX"], v2["NY"], v2["NZ"]};
      const double len = std::sqrt(r.n[0] * r.n[0] + r.n[1] * r.n[1] + r.n[2] * r.n[2]);
      if (r.omega != 0 && !(len > 0)) v2.error(1003, "NX", "the rotation axis NX NY NZ must not be zero when OMEGA is given");
      else if (len > 0)
        for (double& a : r.n) a /= len;
    } else if (r.omega != 0) {
      v.error(1316, "OMEGA", "OMEGA needs card 2 (the axis: XC YC ZC NX NY NZ)");
    }
    if (styp >= 1 && styp <= 3) out.velocities.push_back(r);
  }
}

// *DEFINE_CURVE: card 1 LCID SIDR SFA SFO OFFA OFFO DATTYP, then points A O (2 x 20 columns).
void read_curve(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordLoads& out) {
  std::size_t k = option_cards(b);
  if (k >= b.data.size()) {
    ctx.missing_card(b, "card 1 (LCID)");
    return;
  }
  KeywordValues v = ctx.fields(b, k, s.card("card 1"));
  const int lcid = ctx.xid(int(v.integer("LCID")), b, 'f');
  v.card().set_card(b.keyword + " " + std::to_string(lcid));
  v.rest();
  const double sfa = v["SFA"], sfo = v["SFO"], offa = v["OFFA"], offo = v["OFFO"];
  LoadCurve lc;
  lc.number = lcid;
  const std::string point = "curve " + std::to_string(lcid) + " point";
  for (++k; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues p = ctx.fields(b, k, s.card("point"), &point);
    const double t = p["A"] * sfa + offa;
    const double f = p["O"] * sfo + offo;
    if (!lc.t.empty() && !(t > lc.t.back())) p.error(1217, "A");
    lc.t.push_back(t);
    lc.f.push_back(f);
  }
  for (std::size_t j = 0; j < out.curves.size(); ++j)
    if (out.curves[j].number == lcid) v.error(1200, "LCID", "also defined at " + at(out.curve_refs[j]));
  out.curves.push_back(std::move(lc));
  out.curve_refs.push_back(v.ref("LCID"));
}

// The keywords of the family read by one function of the same arguments.
using FamilyReader = void (*)(const Block&, KeywordContext&, const KeywordSpec&, KeywordLoads&);
const std::map<std::string, FamilyReader, std::less<>>& plain_readers() {
  static const std::map<std::string, FamilyReader, std::less<>> r = {
      {"DAMPING_GLOBAL", read_damping},
      {"DEFINE_CURVE", read_curve},
      {"CONSTRAINED_GLOBAL", read_constrained_global},
      {"CONSTRAINED_SPOTWELD", read_spot_welds},
      {"CONSTRAINED_GENERALIZED_WELD_SPOT", read_generalized_welds},
      {"RIGIDWALL_PLANAR", read_planar_walls},
      {"INITIAL_VELOCITY_NODE", read_velocity_nodes},
      {"INITIAL_VELOCITY", read_initial_velocity},
      {"INITIAL_VELOCITY_GENERATION", read_velocity_generation},
  };
  return r;
}

}  // namespace

bool read_loads_bcs(const Block& b, KeywordContext& ctx, KeywordLoads& l) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || s->family != KeywordFamily::loads_bcs) return false;
  if (s->once) ctx.once(b);
  const std::string& n = b.name;
  if (auto r = plain_readers().find(n); r != plain_readers().end()) {
    r->second(b, ctx, *s, l);
  } else if (n == "LOAD_NODE_POINT" || n == "LOAD_NODE_SET" || n == "LOAD_RIGID_BODY") {
    read_load_node(b, ctx, *s, n == "LOAD_NODE_SET" ? RLoad::node_set : n == "LOAD_RIGID_BODY" ? RLoad::rigid_body : RLoad::node, l);
  } else if (n == "LOAD_SEGMENT" || n == "LOAD_SEGMENT_SET") {
    read_load_segment(b, ctx, *s, n == "LOAD_SEGMENT_SET", l);
  } else if (n == "LOAD_BODY_PARTS") {
    if (!b.data.empty()) {
      KeywordValues v = ctx.values(b, 0, s->card("card 1"));
      l.body_parts_psid = ctx.xid(int(v.integer("PSID")), b, 's');
      l.body_parts_ref = v.ref("PSID");
    }
  } else if (n.rfind("LOAD_BODY_", 0) == 0) {
    read_load_body(b, ctx, *s, n.back() == 'X' ? 0 : n.back() == 'Y' ? 1 : n.back() == 'Z' ? 2 : 3, l);
  } else if (n.rfind("BOUNDARY_SPC_", 0) == 0) {
    read_spc(b, ctx, *s, n.rfind("BOUNDARY_SPC_SET", 0) == 0, n.find("_BIRTH_DEATH") != std::string::npos, l);
  } else if (n.rfind("RIGIDWALL_GEOMETRIC_CYLINDER", 0) == 0) {
    if (n.find("_MOTION") != std::string::npos) {
      Location loc;
      loc.file = b.kw.file->name();
      loc.line = b.kw.line->number;
      loc.card = b.keyword;
      ctx.diag.add(1312, loc, "_MOTION: moving geometric walls (IMPACT-3D's cylinders are fixed)");
    } else {
      read_geometric_walls(b, ctx, *s, n.find("_DISPLAY") != std::string::npos, l);
    }
  } else if (n == "INITIAL_TEMPERATURE_NODE" || n == "INITIAL_TEMPERATURE_SET") {
    read_temperatures(b, ctx, *s, n == "INITIAL_TEMPERATURE_SET", l);
  } else {
    read_motions(b, ctx, *s, n == "BOUNDARY_PRESCRIBED_MOTION_NODE" ? RLoad::motion_node
                            : n == "BOUNDARY_PRESCRIBED_MOTION_SET" ? RLoad::motion_set : RLoad::motion_rigid, l);
  }
  return true;
}

}  // namespace impact3d::kw
