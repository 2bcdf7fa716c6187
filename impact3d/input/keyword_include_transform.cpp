// Keyword decks, *INCLUDE_TRANSFORM: once the deck is parsed, the records read from a file
// included with a transform get its id offsets and their coordinates its map (FCTLEN scaling,
// then *DEFINE_TRANSFORMATION TRANID); what cannot be transformed is error 1102.  The
// reader opens the file and gives the ids that keyed definitions define their offsets while
// parsing (KeywordReader::xid, keyword_reader.cpp).

#include "impact3d/input/keyword_resolve.h"

#include <algorithm>

namespace impact3d::kw {

static void offset(int& id, long long off) {
  if (id != 0) id = int(id + off);
}
static void offset_set_members(RIdList& s, const IncludeTransform& t, long long member_off) {
  for (int& id : s.ids) offset(id, member_off);
  for (auto& r : s.ranges) r[0] += member_off, r[1] += member_off;
  for (RSetTerm& term : s.terms) {
    const long long off = term.option == "NODE" ? t.idnoff : term.option == "ELEM" ? t.ideoff : term.option == "PART" ? t.idpoff
                          : term.option == "BOX" ? t.iddoff : term.option == "SET" || term.option.rfind("SET_", 0) == 0 ? t.idsoff : 0;
    for (int& id : term.ids) offset(id, off);
  }
}

// The records read from a file of an *INCLUDE_TRANSFORM get the id offsets (an id 0, which
// means "none" or "all", stays 0; the ids that keyed definitions define got theirs while
// parsing, xid) and their coordinates the map: nodes, the points of walls and coordinate
// systems, boxes (translation and scaling only).
void apply_include_transforms(ResolveContext& rc, IncludeTransforms& inc) {
  if (inc.list.empty()) return;
  for (IncludeTransform& t : inc.list) {
    t.map = AffineMap::scaling({t.fctlen, t.fctlen, t.fctlen});
    if (t.tranid != 0) {
      auto it = rc.sb.transformations.find(t.tranid);
      if (it == rc.sb.transformations.end()) rc.err(1310, t.tranid_ref, "*INCLUDE_TRANSFORM", "TRANID", "*DEFINE_TRANSFORMATION " + std::to_string(t.tranid) + " is not defined");
      else t.map = t.map.then(it->second.map);
    }
    const AffineMap id;
    t.moves = t.map.a != id.a || t.map.t != id.t;
  }
  // FCTLEN converts units: only coordinates are converted here, so data with other
  // length-dimensioned units (materials, curves) in such a file is not supported
  for (auto& [mid, mat] : rc.mt.mats)
    if (const IncludeTransform* t = inc.of(mat.ref.file); t && t->fctlen != 1)
      rc.err(1102, mat.ref, "*MAT " + std::to_string(mid), "MID", "a material in an *INCLUDE_TRANSFORM file with FCTLEN other than 1 (its units would have to be converted)");
  for (std::size_t k = 0; k < rc.ld.curves.size(); ++k)
    if (const IncludeTransform* t = inc.of(rc.ld.curve_refs[k].file); t && t->fctlen != 1)
      rc.err(1102, rc.ld.curve_refs[k], "*DEFINE_CURVE " + std::to_string(rc.ld.curves[k].number), "LCID", "a curve in an *INCLUDE_TRANSFORM file with FCTLEN other than 1 (its units would have to be converted)");
  for (RNode& n : rc.me.nodes)
    if (const IncludeTransform* t = inc.of(n.card.file)) {
      offset(n.id, t->idnoff);
      const Vec3 p = t->map.apply({n.x, n.y, n.z});
      n.x = p[0], n.y = p[1], n.z = p[2];
    }
  for (RElem& e : rc.me.elems)
    if (const IncludeTransform* t = inc.of(e.card.file)) {
      offset(e.id, t->ideoff);
      offset(e.pid, t->idpoff);
      for (int& v : e.n) offset(v, t->idnoff);
    }
  for (RPart& p : rc.ps.parts)
    if (const IncludeTransform* t = inc.of(p.ref.file)) {
      offset(p.pid, t->idpoff);
      offset(p.mid, t->idmoff);
      offset(p.secid, t->idroff);
      offset(p.hgid, t->idroff);
      offset(p.eosid, t->idroff);
    }
  const std::pair<std::map<int, RIdList>*, long long IncludeTransform::*> sets[] = {
      {&rc.sb.node_sets, &IncludeTransform::idnoff}, {&rc.sb.part_sets, &IncludeTransform::idpoff},
      {&rc.sb.solid_sets, &IncludeTransform::ideoff}, {&rc.sb.shell_sets, &IncludeTransform::ideoff}};
  for (auto [map, member] : sets) {
    for (auto& [sid, s] : *map)
      if (const IncludeTransform* t = inc.of(s.ref.file)) offset_set_members(s, *t, t->*member);
  }
  for (auto& [sid, s] : rc.sb.seg_sets)
    if (const IncludeTransform* t = inc.of(s.ref.file)) {
      for (auto& seg : s.segs)
        for (int& v : seg) offset(v, t->idnoff);
      for (RSetTerm& term : s.terms)
        for (int& id : term.ids) offset(id, term.option == "PART" ? t->idpoff : t->idsoff);
    }
  for (RContact& c : rc.contacts)
    if (const IncludeTransform* t = inc.of(c.ref.file))
      for (RSide* side : {&c.a, &c.b}) {
        offset(side->id, side->type == 3 ? t->idpoff : t->idsoff);
        offset(side->boxid, t->iddoff);
      }
  for (RWall& w : rc.ld.walls)
    if (const IncludeTransform* t = inc.of(w.nsid_ref.file)) {
      offset(w.nsid, t->idsoff);
      offset(w.nsidex, t->idsoff);
      offset(w.boxid, t->iddoff);
      w.w.tail = t->map.apply(w.w.tail);
      w.w.head = t->map.apply(w.w.head);
    }
  for (RVelocity& v : rc.ld.velocities)
    if (const IncludeTransform* t = inc.of(v.ref.file)) {
      offset(v.id, v.kind == RVelocity::node ? t->idnoff : v.kind == RVelocity::part ? t->idpoff : t->idsoff);
      offset(v.nsidex, t->idsoff);
      offset(v.boxid, t->iddoff);
      offset(v.icid, t->iddoff);
      if (t->moves && (v.v != Vec3{} || v.omega != 0 || v.ve != Vec3{}))
        rc.err(1102, v.ref, v.keyword, nullptr, "initial velocities in an *INCLUDE_TRANSFORM file that is scaled, turned or moved (the velocities would have to turn with it)");
    }
  for (RSpc& s : rc.ld.spcs)
    if (const IncludeTransform* t = inc.of(s.ref.file)) {
      offset(s.id, s.set ? t->idsoff : t->idnoff);
      offset(s.cid, t->iddoff);
    }
  for (RWeld& w : rc.ld.welds)
    if (const IncludeTransform* t = inc.of(w.ref.file)) {
      if (w.generalized) offset(w.nsid, t->idsoff);
      else offset(w.n1, t->idnoff), offset(w.n2, t->idnoff);
      offset(w.cid, t->iddoff);
    }
  for (RHistory& h : rc.ctl.histories)
    for (std::size_t j = 0; j < h.ids.size(); ++j)
      if (const IncludeTransform* t = inc.of(h.refs[j].file)) offset(h.ids[j], h.sets ? t->idsoff : h.solid ? t->ideoff : t->idnoff);
  for (auto& [bid, r] : rc.sb.boxes)
    if (const IncludeTransform* t = inc.of(r.ref.file)) {
      const auto& a = t->map.a;
      const bool diagonal = a[0][1] == 0 && a[0][2] == 0 && a[1][0] == 0 && a[1][2] == 0 && a[2][0] == 0 && a[2][1] == 0;
      if (!diagonal) {
        rc.err(1102, r.ref, "*DEFINE_BOX " + std::to_string(bid), "BOXID", "a box in a turned *INCLUDE_TRANSFORM file (it would no longer be aligned with the axes)");
        continue;
      }
      const Vec3 lo = t->map.apply(r.box.lo), hi = t->map.apply(r.box.hi);
      for (int q = 0; q < 3; ++q) {
        r.box.lo[std::size_t(q)] = std::min(lo[std::size_t(q)], hi[std::size_t(q)]);
        r.box.hi[std::size_t(q)] = std::max(lo[std::size_t(q)], hi[std::size_t(q)]);
      }
    }
  for (RCoordSystem& r : rc.sb.systems)
    if (const IncludeTransform* t = inc.of(r.ref.file)) {
      offset(r.cid, t->iddoff);
      for (int& v : r.n) offset(v, t->idnoff);
      if (t->moves && (r.kind == RCoordSystem::points || r.kind == RCoordSystem::vector) && r.n[0] == 0 && r.cid == 0) {
        for (int q = 0; q < 3; ++q) {  // the points move with the mesh
          const Vec3 p = t->map.apply({r.v[std::size_t(3 * q)], r.v[std::size_t(3 * q + 1)], r.v[std::size_t(3 * q + 2)]});
          for (int j = 0; j < 3; ++j) r.v[std::size_t(3 * q + j)] = p[std::size_t(j)];
        }
      } else if (t->moves && r.kind == RCoordSystem::vectors) {
        rc.err(1102, r.ref, r.keyword, nullptr, "*DEFINE_COORDINATE_VECTOR in a turned or moved *INCLUDE_TRANSFORM file");
      }
    }
}

}  // namespace impact3d::kw
