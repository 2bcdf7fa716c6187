// Keyword decks, the parts' resolve steps: each *PART with its section, material, equation of
// state, erosion and hourglass into a MaterialData (solid, shell and beam parts), and its
// elements' material index.  The records are read by keyword_parts_sections.cpp and
// keyword_materials.cpp; KeywordReader::resolve (keyword_reader.cpp) runs the steps once the
// elements are resolved (ResolveContext, keyword_resolve.h).

#include "impact3d/input/keyword_resolve.h"

#include "impact3d/init/beam_init.h"
#include "impact3d/init/shell_init.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

namespace impact3d::kw {

// the family's own steps
static void resolve_part_eos(ResolveContext& rc, MaterialData& md, const RPart& p, const std::string& card, const MaterialType* t);
static void resolve_material_curves(ResolveContext& rc, MaterialData& md, const RMat& r, int mid);
static void resolve_rigid_constraints(ResolveContext& rc, MaterialData& md, const RMat& r, int mid);

// A solid part's equation of state (*PART EOSID) into its material: refused for a material
// that takes none, required by one that needs one (*MAT_NULL).
void resolve_part_eos(ResolveContext& rc, MaterialData& md, const RPart& p, const std::string& card, const MaterialType* t) {
  if (p.eosid == 0) {
    if (t && t->needs_eos)
      rc.err(1204, p.eos_ref.line ? p.eos_ref : p.mid_ref, card, "EOSID",
          std::string("*") + t->keywords.front() + " needs an equation of state (" + supported_eos_keywords() + ")");
    return;
  }
  auto it = rc.mt.eos.find(p.eosid);
  if (it == rc.mt.eos.end()) {
    auto u = rc.refused.eosids.find(p.eosid);
    if (u != rc.refused.eosids.end())
      rc.err(1102, p.eos_ref, card, "EOSID", "equation of state " + std::to_string(p.eosid) + " is " + u->second + "; supported: " + supported_eos_keywords());
    else
      rc.err(1310, p.eos_ref, card, "EOSID", "*EOS " + std::to_string(p.eosid) + " is not defined");
    return;
  }
  if (t && !t->accepts_eos) {
    rc.err(1102, p.eos_ref, card, "EOSID", std::string("an equation of state with *") + t->keywords.front() + " (materials that take one: " + eos_material_types() + ")");
    return;
  }
  md.eos = it->second.eos;
  if (const int lc = eos_curve(md.eos); lc > 0) {  // *DEFINE_CURVE id -> the curve's number 1..NUMLC
    std::size_t k = 0;
    while (k < rc.ld.curves.size() && rc.ld.curves[k].number != lc) ++k;
    if (k < rc.ld.curves.size()) md.eos.c[kEosLeakCurve] = double(k + 1);
    else rc.err(1310, it->second.lcid_ref, "*EOS " + std::to_string(p.eosid), "LCID", "*DEFINE_CURVE " + std::to_string(lc) + " is not defined");
  }
}

void resolve_materials(ResolveContext& rc) {
  for (const auto& [mid, e] : rc.mt.erosion)
    if (!rc.mt.mats.count(mid) && !rc.refused.mids.count(mid))
      rc.err(1310, e.second, "*MAT_ADD_EROSION material " + std::to_string(mid), "MID", "material " + std::to_string(mid) + " is not defined by a *MAT keyword");
  rc.part_material.assign(rc.ps.parts.size(), -1);
  for (std::size_t k = 0; k < rc.ps.parts.size(); ++k) {
    const RPart& p = rc.ps.parts[k];
    if (rc.part_index[p.pid] != int(k)) continue;  // duplicate
    std::string card = "*PART " + std::to_string(p.pid);
    bool used = !rc.part_elems[k].empty() || !rc.part_shells[k].empty() || !rc.part_beams[k].empty();
    if (!rc.part_shells[k].empty()) {  // a shell part: resolve_shell_materials
      if (!rc.part_elems[k].empty()) rc.err(1102, p.sec_ref, card, "SECID", "a part of both solids and shells");
      if (!rc.part_beams[k].empty()) rc.err(1102, p.sec_ref, card, "SECID", "a part of both shells and beams");
      continue;
    }
    if (!rc.part_beams[k].empty()) {  // a beam part: resolve_beam_materials
      if (!rc.part_elems[k].empty()) rc.err(1102, p.sec_ref, card, "SECID", "a part of both solids and beams");
      continue;
    }
    auto sit = rc.ps.sections.find(p.secid);
    auto mit = rc.mt.mats.find(p.mid);
    if (!used && (sit == rc.ps.sections.end() || mit == rc.mt.mats.end())) {
      Location loc = loc_of(p.ref, card, "PID");
      rc.diag.add(2011, loc, "no *ELEMENT_SOLID uses it and its section or material is not a supported solid one");
      continue;
    }
    MaterialData md;
    md.number = int(rc.m.materials.size()) + 1;
    md.title = p.title;
    md.line = p.line;
    if (sit == rc.ps.sections.end()) {
      auto u = rc.refused.secids.find(p.secid);
      if (u != rc.refused.secids.end()) rc.err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is " + u->second + "; solids need *SECTION_SOLID");
      else rc.err(1310, p.sec_ref, card, "SECID", "*SECTION_SOLID " + std::to_string(p.secid) + " is not defined");
    } else if (sit->second.elform != 0 && sit->second.elform != 1 && sit->second.elform != 2) {
      rc.err(1102, sit->second.ref, "*SECTION_SOLID " + std::to_string(p.secid), "ELFORM", "only ELFORM 1 (one-point constant-stress hexahedron) and 2 (fully integrated selective-reduced)");
    }
    if (mit == rc.mt.mats.end()) {
      auto u = rc.refused.mids.find(p.mid);
      if (u != rc.refused.mids.end()) rc.err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is " + u->second + "; supported: " + supported_material_keywords());
      else rc.err(1310, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is not defined by a *MAT keyword");
    } else {
      const RMat& r = mit->second;
      const MaterialData keep = md;
      md = r.md;
      md.number = keep.number;
      md.title = keep.title;
      md.line = keep.line;
      // the IMPACT-3D comment line INITIALLY_ELASTIC PART sets the type's switch, if it has one
      if (const MaterialParam* ie = find_param(*r.type, "IE")) {
        md.initially_elastic = rc.ctl.initially_elastic.count(p.pid) > 0;
        param_value(md, *ie) = md.initially_elastic ? 1.0 : 0.0;
      }
      resolve_material_curves(rc, md, r, p.mid);
      resolve_rigid_constraints(rc, md, r, p.mid);
      if (auto eit = rc.mt.erosion.find(p.mid); eit != rc.mt.erosion.end()) {
        if (r.type->rigid) rc.err(1102, eit->second.second, "*MAT_ADD_EROSION material " + std::to_string(p.mid), "MID", "erosion of a rigid body");
        else md.erosion = eit->second.first;
      }
    }
    resolve_part_eos(rc, md, p, card, mit != rc.mt.mats.end() ? mit->second.type : nullptr);
    // hourglass and bulk viscosity
    int ihq = rc.ctl.ihq;
    double qm = rc.ctl.qh;
    md.q1 = rc.ctl.q1;
    md.q2 = rc.ctl.q2;
    if (p.hgid != 0) {
      auto hit = rc.ps.hourglasses.find(p.hgid);
      if (hit == rc.ps.hourglasses.end()) {
        rc.err(1310, p.hg_ref, card, "HGID", "*HOURGLASS " + std::to_string(p.hgid) + " is not defined");
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
    md.bulk_type = rc.ctl.btype;
    if (sit != rc.ps.sections.end() && sit->second.elform == 2) {  // no zero-energy modes: LS-DYNA ignores IHQ
      md.solid_elform = 2;
      md.hourglass_coef = 0;
    }
    rc.part_material[k] = int(rc.m.materials.size());
    rc.m.materials.push_back(md);
  }
  for (int& hm : rc.m.hex_material) {
    if (hm <= -2) {
      int mat = rc.part_material[std::size_t(-2 - hm)];
      hm = mat;
      if (mat < 0) {
        // the part was refused above
      }
    }
  }
  // elements of a refused part keep -1: mark them undefined so the checks skip them
  for (std::size_t e = 0; e < rc.m.hex_material.size(); ++e)
    if (rc.m.hex_material[e] < 0) rc.m.hex_nodes[e].fill(-1);
}

// What a part of shells or beams needs: its section keyword, its material forms.
struct PartKind {
  const char* section;     // the section keyword
  const char* elements;    // in messages: "shells need *SECTION_SHELL"
  const char* form;        // the material form: "has no shell form"
  const char* eos_detail;  // error 1102 when the part names an EOSID
  bool (*has_kernel)(int type);
  std::string (*materials)();  // the material keywords the form has
};
const PartKind kShellParts = {"*SECTION_SHELL", "shells", "shell", "equations of state", has_shell_kernel, shell_material_keywords};
const PartKind kBeamParts = {"*SECTION_BEAM", "beams", "beam", "equations of state of beams", has_beam_kernel, beam_material_keywords};

// A shell or beam part's section and material: the part's material (md: its data, numbered
// next, with the part's title and line), or null when the section is not found (`other`: a
// section of another kind, "is not a ...") or the MID names no material of the kind (errors
// 1102, 1103, 1310 naming the refused keyword that defines the id, if one does).
static const RMat* part_material_of_kind(ResolveContext& rc, const RPart& p, const std::string& card, const PartKind& kind,
                                         bool section_found, const char* other, MaterialData& md) {
  const std::string need = std::string("; ") + kind.elements + " need " + kind.section;
  if (!section_found) {
    if (other) rc.err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " " + other + need);
    else if (auto u = rc.refused.secids.find(p.secid); u != rc.refused.secids.end())
      rc.err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is " + u->second + need);
    else rc.err(1310, p.sec_ref, card, "SECID", std::string(kind.section) + " " + std::to_string(p.secid) + " is not defined");
    return nullptr;
  }
  auto mit = rc.mt.mats.find(p.mid);
  if (mit == rc.mt.mats.end()) {
    auto u = rc.refused.mids.find(p.mid);
    if (u != rc.refused.mids.end())
      rc.err(1103, p.mid_ref, card, "MID",
             "material " + std::to_string(p.mid) + " is " + u->second + "; supported for " + kind.elements + ": " + kind.materials());
    else rc.err(1310, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is not defined by a *MAT keyword");
    return nullptr;
  }
  if (p.eosid != 0) rc.err(1102, p.eos_ref, card, "EOSID", kind.eos_detail);
  const RMat& r = mit->second;
  md = r.md;
  md.number = int(rc.m.materials.size()) + 1;
  md.title = p.title;
  md.line = p.line;
  if (!kind.has_kernel(md.type)) {
    rc.err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " (type " + std::to_string(md.type) + ") has no " +
                                             kind.form + " form; supported for " + kind.form + "s: " + kind.materials());
    return nullptr;
  }
  return &r;
}

// Elements of refused parts (material < 0): material -1 and no nodes (the checks skip them).
template <std::size_t N>
void undefine_refused(std::vector<int>& material, std::vector<std::array<int, N>>& nodes) {
  for (std::size_t e = 0; e < material.size(); ++e)
    if (material[e] < 0) {
      material[e] = -1;
      nodes[e].fill(-1);
    }
}

// Beam parts: *SECTION_BEAM and material -> MaterialData (beam = true, its beam_section),
// the beams' material indices.
void resolve_beam_materials(ResolveContext& rc) {
  for (std::size_t k = 0; k < rc.ps.parts.size(); ++k) {
    const RPart& p = rc.ps.parts[k];
    if (rc.part_index[p.pid] != int(k) || rc.part_beams[k].empty() || !rc.part_elems[k].empty() || !rc.part_shells[k].empty()) continue;
    const std::string card = "*PART " + std::to_string(p.pid);
    auto sit = rc.ps.beam_sections.find(p.secid);
    const bool other = rc.ps.sections.count(p.secid) || rc.ps.shell_sections.count(p.secid);
    MaterialData md;
    const RMat* rm = part_material_of_kind(rc, p, card, kBeamParts, sit != rc.ps.beam_sections.end(), other ? "is not a *SECTION_BEAM" : nullptr, md);
    if (!rm) continue;
    const RMat& r = *rm;
    resolve_rigid_constraints(rc, md, r, p.mid);
    if (auto eit = rc.mt.erosion.find(p.mid); eit != rc.mt.erosion.end())
      rc.err(1102, eit->second.second, "*MAT_ADD_EROSION material " + std::to_string(p.mid), "MID", "erosion (element deletion) of beams");
    md.beam = true;
    md.beam_section = sit->second.sec;
    md.bulk_type = rc.ctl.btype;
    const int mat = int(rc.m.materials.size());
    rc.m.materials.push_back(md);
    for (int e : rc.part_beams[k]) {
      rc.m.beam_material[std::size_t(e)] = mat;
      const auto& t = rc.m.beam_thickness[std::size_t(e)];
      if (md.beam_section.elform == 3 && (t[0] != 0 || t[1] != 0 || t[2] != 0 || t[3] != 0)) {
        Location loc;
        loc.file = rc.m.file_of(rc.m.beam_file, std::size_t(e));
        loc.line = rc.m.beam_line[std::size_t(e)];
        loc.card = "*ELEMENT_BEAM_THICKNESS element " + std::to_string(rc.m.beam_id(e));
        rc.diag.add(1102, loc, "per-element truss areas (the section's A applies)");
      }
    }
  }
  undefine_refused(rc.m.beam_material, rc.m.beam_nodes);
}

// Shell parts: *SECTION_SHELL and material -> MaterialData (shell = true), the shells'
// material indices and the section's thicknesses where the element card gives none.
void resolve_shell_materials(ResolveContext& rc) {
  for (std::size_t k = 0; k < rc.ps.parts.size(); ++k) {
    const RPart& p = rc.ps.parts[k];
    if (rc.part_index[p.pid] != int(k) || rc.part_shells[k].empty() || !rc.part_elems[k].empty()) continue;
    const std::string card = "*PART " + std::to_string(p.pid);
    auto sit = rc.ps.shell_sections.find(p.secid);
    MaterialData md;
    const RMat* rm = part_material_of_kind(rc, p, card, kShellParts, sit != rc.ps.shell_sections.end(),
                                           rc.ps.sections.count(p.secid) ? "is a *SECTION_SOLID" : nullptr, md);
    if (!rm) continue;
    const RMat& r = *rm;
    if (const char* feature = nullptr; const MaterialParam* q = refused_shell_param(md, &feature)) {
      const std::size_t qi = std::size_t(q - r.type->params.data());
      rc.err(1102, qi < r.refs.size() && r.refs[qi].line ? r.refs[qi] : p.mid_ref, "*MAT material " + std::to_string(p.mid), q->key,
          std::string(feature) + " (part " + std::to_string(p.pid) + " is of shells)");
      continue;
    }
    resolve_material_curves(rc, md, r, p.mid);
    resolve_rigid_constraints(rc, md, r, p.mid);
    if (auto eit = rc.mt.erosion.find(p.mid); eit != rc.mt.erosion.end())
      rc.err(1102, eit->second.second, "*MAT_ADD_EROSION material " + std::to_string(p.mid), "MID", "erosion (element deletion) of shells");
    md.shell = true;
    md.shell_section.elform = sit->second.elform;
    md.shell_section.nip = sit->second.nip;
    md.shell_section.shrf = sit->second.shrf;
    md.shell_section.t = sit->second.t;
    int ihq = rc.ctl.ihq;
    double qm = rc.ctl.qh;
    if (p.hgid != 0) {
      auto hit = rc.ps.hourglasses.find(p.hgid);
      if (hit == rc.ps.hourglasses.end()) {
        rc.err(1310, p.hg_ref, card, "HGID", "*HOURGLASS " + std::to_string(p.hgid) + " is not defined");
      } else {
        if (hit->second.ihq != 0) ihq = hit->second.ihq;
        if (hit->second.qm > 0) qm = hit->second.qm;
      }
    }
    md.hourglass_type = ihq == 0 ? 1 : ihq;
    md.hourglass_coef = qm > 0 ? qm : 0.10;
    if (md.shell_section.elform == 16) {  // no hourglass modes: LS-DYNA ignores the part's settings
      md.hourglass_type = 1;
      md.hourglass_coef = 0;
    } else if (md.hourglass_type > 5) {
      rc.err(1102, p.hg_ref.line ? p.hg_ref : p.ref, card, "HGID", "shell hourglass type " + std::to_string(md.hourglass_type) + " (IHQ 1-3 viscous, 4-5 stiffness)");
    }
    md.bulk_type = rc.ctl.btype;
    const int mat = int(rc.m.materials.size());
    rc.m.materials.push_back(md);
    for (int e : rc.part_shells[k]) {
      rc.m.shell_material[std::size_t(e)] = mat;
      auto& t = rc.m.shell_thickness[std::size_t(e)];
      if (t[0] == 0 && t[1] == 0 && t[2] == 0 && t[3] == 0) t = sit->second.t;
      if (!(t[0] > 0)) {
        Location loc;
        loc.file = rc.m.file_of(rc.m.shell_file, std::size_t(e));
        loc.line = rc.m.shell_line[std::size_t(e)];
        loc.card = "*ELEMENT_SHELL element " + std::to_string(rc.m.shell_id(e));
        rc.diag.add(1241, loc, "neither the element card nor *SECTION_SHELL " + std::to_string(p.secid) + " (T1) gives a thickness");
      }
    }
  }
  undefine_refused(rc.m.shell_material, rc.m.shell_nodes);
}

// *MAT_RIGID CMO = -1: CON1 names a local system, CON2 six digits (x y z translations, x y z
// rotations in it).  As for *BOUNDARY_SPC: a system whose axes are the global ones (any order
// and sign) becomes the global codes (CMO = 1, CON1, CON2 0-7); skew axes are not supported
// unless all or none of the translations (and of the rotations) are fixed.
// A material's curve references (ParamCheck::curve): *DEFINE_CURVE ids -> the curves'
// numbers 1..NUMLC, for solid and shell parts alike (an undefined id: 1310).
void resolve_material_curves(ResolveContext& rc, MaterialData& md, const RMat& r, int mid) {
  for (std::size_t i = 0; i < r.type->params.size(); ++i) {
    const MaterialParam& q = r.type->params[i];
    if (q.check != ParamCheck::curve || param_value(md, q) == 0) continue;
    const int id = int(param_value(md, q));
    std::size_t k = 0;
    while (k < rc.ld.curves.size() && rc.ld.curves[k].number != id) ++k;
    if (k < rc.ld.curves.size()) param_value(md, q) = double(k + 1);
    else rc.err(1310, r.refs[i], "*MAT material " + std::to_string(mid), q.key, "*DEFINE_CURVE " + std::to_string(id) + " is not defined");
  }
}

void resolve_rigid_constraints(ResolveContext& rc, MaterialData& md, const RMat& r, int mid) {
  if (md.type != 20 || md.par.size() < 6 || md.par[3] != -1) return;
  const MaterialParam* con1 = find_param(*r.type, "CON1");
  const Ref& ref = r.refs[std::size_t(con1 - r.type->params.data())];
  const std::string card = "*MAT_RIGID " + std::to_string(mid);
  const int cid = int(md.par[4]);
  const CoordinateSystem* cs = rc.coords.system(cid);
  if (!cs) {
    rc.err(1310, ref, card, "CON1", "coordinate system " + std::to_string(cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
    return;
  }
  long long digits = (long long)md.par[5];
  unsigned local_t = 0, local_r = 0;
  for (int i = 5; i >= 0; --i, digits /= 10)
    if (digits % 10) (i < 3 ? local_t : local_r) |= 1u << (i % 3);
  std::array<int, 3> axis{{0, 1, 2}}, sign{{1, 1, 1}};
  const bool aligned = cs->axis_aligned(axis, sign);
  auto global_bits = [&](unsigned local) -> unsigned {
    if (local == 0 || local == 7) return local;
    unsigned g = 0;
    for (int i = 0; i < 3; ++i)
      if (local & (1u << i)) g |= 1u << axis[std::size_t(i)];
    return g;
  };
  if (!aligned && ((local_t != 0 && local_t != 7) || (local_r != 0 && local_r != 7))) {
    rc.err(1102, ref, card, "CON1", "rigid-body constraints along skew local axes (the axes of system " + std::to_string(cid) + " are not the global ones)");
    return;
  }
  auto code = [](unsigned b) {  // bits -> the 0-7 code (1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all)
    static const int c[8] = {0, 1, 2, 4, 3, 6, 5, 7};
    return c[b & 7u];
  };
  md.par[3] = 1;
  md.par[4] = code(global_bits(local_t));
  md.par[5] = code(global_bits(local_r));
}

}  // namespace impact3d::kw
