// Keyword and fixed-format deck writers, and the model comparison used by the round-trip
// tests and the converter.

#include "impact3d/input/deck_writer.h"
#include "impact3d/input/fixed_cards.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/cards.h"
#include "impact3d/init/beam_init.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

// Shortest text that reads back as exactly v (Fortran style: exponent without '+' and leading
// zeros, always a decimal point).
std::string shortest(double v) {
  if (v == 0) return std::signbit(v) ? "-0.0" : "0.0";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  std::string mant = s, exp;
  std::size_t e = s.find('e');
  if (e != std::string::npos) {
    mant = s.substr(0, e);
    std::string ex = s.substr(e + 1);
    bool neg = !ex.empty() && ex[0] == '-';
    if (!ex.empty() && (ex[0] == '+' || ex[0] == '-')) ex.erase(0, 1);
    while (ex.size() > 1 && ex[0] == '0') ex.erase(0, 1);
    exp = std::string("e") + (neg ? "-" : "") + ex;
  }
  if (mant.find('.') == std::string::npos) mant += ".0";
  return mant + exp;
}

bool reads_back(const std::string& s, double v) {
  double r = 0;
  return parse_fortran_real(s, r) == FieldStatus::ok && r == v;
}

// The most exact text of v in at most w characters; exact tells whether it reads back as v.
std::string fit(double v, int w, bool& exact) {
  std::string s = shortest(v);
  if (int(s.size()) <= w) {
    exact = true;
    return s;
  }
  for (int p = 16; p >= 0; --p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", p, v);
    std::string t = shortest(std::strtod(buf, nullptr));
    if (int(t.size()) <= w) {
      exact = reads_back(t, v);
      return t;
    }
  }
  exact = false;
  return std::string(std::size_t(w), '*');
}

// ------------------------------------------------------------------ keyword cards
struct KField {
  std::string text;
  int width;
};

// One keyword card: fixed columns (right-justified) when every value fits, else comma free
// format (always exact).
std::string kcard(const std::vector<KField>& f) {
  bool fits = true;
  for (const auto& x : f) fits = fits && int(x.text.size()) <= x.width;
  std::string out;
  if (fits) {
    for (const auto& x : f) out += std::string(std::size_t(x.width) - x.text.size(), ' ') + x.text;
  } else {
    for (std::size_t k = 0; k < f.size(); ++k) out += (k ? "," : "") + f[k].text;
    if (f.size() == 1) out += ",";  // a comma marks the line as free format
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}
KField I(long long v, int w = 10) { return {std::to_string(v), w}; }
KField R(double v, int w = 10) { return {shortest(v), w}; }
KField B(int w = 10) { return {"", w}; }

// 1-3 when d is the x, y or z axis, else 0.
int axis_number(const std::array<double, 3>& d) {
  for (int a = 0; a < 3; ++a)
    if (d[std::size_t(a)] == 1 && d[std::size_t((a + 1) % 3)] == 0 && d[std::size_t((a + 2) % 3)] == 0) return a + 1;
  return 0;
}

class KeywordWriter {
 public:
  KeywordWriter(std::ostream& os, const Model& m, std::vector<std::string>* notes) : os_(os), m_(m), notes_(notes) {}

  void write() {
    const ControlData& k = m_.control;
    os_ << "*KEYWORD\n";
    os_ << "$ written by IMPACT-3D (impact3d --write-keyword); layout: README.md \"Keyword decks\"\n";
    os_ << "*TITLE\n" << m_.title << "\n";
    if (k.end_mass_percent > 0)
      os_ << "*CONTROL_TERMINATION\n$#  endtim    endcyc     dtmin    endeng    endmas\n"
          << kcard({R(k.end_time), I(k.end_cycle), R(k.min_step_factor), B(), R(k.end_mass_percent)}) << "\n";
    else
      os_ << "*CONTROL_TERMINATION\n$#  endtim    endcyc     dtmin\n"
          << kcard({R(k.end_time), I(k.end_cycle), R(k.min_step_factor)}) << "\n";
    if (k.mass_scaling_dt != 0 || k.erode_small_steps)
      os_ << "*CONTROL_TIMESTEP\n$#  dtinit    tssfac      isdo    tslimt     dt2ms      lctm     erode     ms1st\n"
          << kcard({R(k.initial_dt), R(k.tssf), B(), B(), R(k.mass_scaling_dt), B(), I(k.erode_small_steps ? 1 : 0),
                    I(k.mass_scaling_first_only ? 1 : 0)}) << "\n";
    else
      os_ << "*CONTROL_TIMESTEP\n$#  dtinit    tssfac\n" << kcard({R(k.initial_dt), R(k.tssf)}) << "\n";
    if (m_.interfaces.empty()) {
      os_ << "*CONTROL_CONTACT\n$#  slsfac\n" << kcard({R(k.penalty_scale)}) << "\n";
    } else {
      // PENOPT: one per deck in LS-DYNA (the first interface's; the others noted if they differ)
      const int penopt = m_.interfaces[0].penopt;
      for (const SlidingInterface& si : m_.interfaces)
        if (si.penopt != penopt) note("sliding interfaces with different PENOPT: written as " + std::to_string(penopt));
      os_ << "*CONTROL_CONTACT\n$#  slsfac    rwpnal    islchk    shlthk    penopt\n"
          << kcard({R(k.penalty_scale), B(), B(), B(), I(penopt)}) << "\n";
    }
    os_ << "*CONTROL_OUTPUT\n$#   npopt    neecho    nrefup    iaccop     opifs    ipnint    ikedit\n"
        << kcard({B(), B(), B(), B(), B(), B(), I(k.report_interval)}) << "\n";
    os_ << "*DATABASE_BINARY_D3PLOT\n$#      dt\n" << kcard({R(k.plot_interval)}) << "\n";
    for (const char* n : {"NODOUT", "ELOUT", "GLSTAT"})
      os_ << "*DATABASE_" << n << "\n$#      dt\n" << kcard({R(k.th_interval)}) << "\n";
    if (k.interface_out_interval > 0)
      os_ << "*DATABASE_NCFORC\n$#      dt\n" << kcard({R(k.interface_out_interval)}) << "\n";
    if (k.reaction_print_flag != 0) {
      os_ << "*DATABASE_SPCFORC\n$#      dt\n" << kcard({R(k.th_interval)}) << "\n";
    }
    if (k.restart_dump_cycles > 0) os_ << "*DATABASE_BINARY_D3DUMP\n$#    cycl\n" << kcard({I(k.restart_dump_cycles)}) << "\n";
    if (k.running_restart_cycles > 0) os_ << "*DATABASE_BINARY_RUNRSF\n$#    cycl\n" << kcard({I(k.running_restart_cycles)}) << "\n";
    if (k.intfor_interval >= 0) os_ << "*DATABASE_BINARY_INTFOR\n$#      dt\n" << kcard({R(k.intfor_interval)}) << "\n";
    // IMPACT-3D fields with no LS-DYNA equivalent travel in *COMMENT, which LS-DYNA ignores
    std::string extra;
    if (k.interface_segments_out != 0) extra += "IMPACT-3D INTERFACE_SEGMENTS " + std::to_string(k.interface_segments_out) + "\n";
    if (k.viscosity_flag != 0) extra += "IMPACT-3D VISCOSITY_FLAG " + std::to_string(k.viscosity_flag) + "\n";
    if (k.reaction_print_flag > 1) extra += "IMPACT-3D REACTION_PRINT_FLAG " + std::to_string(k.reaction_print_flag) + "\n";
    for (std::size_t j = 0; j < m_.materials.size(); ++j)
      if (m_.materials[j].initially_elastic) extra += "IMPACT-3D INITIALLY_ELASTIC PART " + std::to_string(j + 1) + "\n";
    if (!extra.empty()) os_ << "*COMMENT\n" << extra;
    for (const auto& b : m_.node_th_blocks) history(b, false);
    for (const auto& b : m_.solid_th_blocks) history(b, true);
    for (const auto& b : m_.shell_th_blocks) history(b, true, true);
    for (const auto& b : m_.beam_th_blocks) history(b, true, false, true);
    materials();
    nodes();
    elements();
    shell_elements();
    beam_elements();
    curves();
    walls();
    velocities();
    temperatures();
    shell_conditions();
    interfaces();
    loads();
    spot_welds();
    tied_contacts();
    os_ << "*END\n";
  }

 private:
  std::ostream& os_;
  const Model& m_;
  std::vector<std::string>* notes_;
  int next_node_set_ = 1, next_segment_set_ = 1;

  void note(const std::string& s) {
    if (notes_) notes_->push_back(s);
  }
  int nid(int idx) const { return m_.node_user_id.empty() ? idx + 1 : m_.node_user_id[std::size_t(idx)]; }
  int eid(int idx) const { return m_.hex_user_id.empty() ? idx + 1 : m_.hex_user_id[std::size_t(idx)]; }

  void history(const std::array<int, 2>& b, bool solid, bool shell = false, bool beam = false) {
    os_ << (beam    ? "*DATABASE_HISTORY_BEAM\n$#     eid\n"
            : shell ? "*DATABASE_HISTORY_SHELL\n$#     eid\n"
            : solid ? "*DATABASE_HISTORY_SOLID\n$#     eid\n"
                    : "*DATABASE_HISTORY_NODE\n$#     nid\n");
    std::vector<KField> f;
    for (int n = b[0]; n <= b[1]; ++n) {
      f.push_back(I(beam ? m_.beam_id(n - 1) : shell ? m_.shell_id(n - 1) : solid ? eid(n - 1) : nid(n - 1)));
      if (f.size() == 8) { os_ << kcard(f) << "\n"; f.clear(); }
    }
    if (!f.empty()) os_ << kcard(f) << "\n";
  }

  // *MAT_...: the cards of the type's table (material_types.h), a comment line of field names
  // above each.
  void write_material(const MaterialType& t, const MaterialData& md, int id) {
    os_ << "*" << t.keywords.front() << "\n";
    for (int c = 0; c < t.keyword_cards; ++c) {
      std::vector<std::string> keys(8);
      std::vector<KField> f(8, B());
      int n = 0;
      if (c == 0) {
        keys[0] = "mid", f[0] = I(id);
        keys[1] = "ro", f[1] = R(md.rho);
        n = 2;
      }
      for (const MaterialParam& p : t.params) {
        if (p.kcard != c || p.kfield < 0 || p.kfield > 7 || !p.keyword_write) continue;
        const double v = param_value(md, p);
        std::string k = p.key;
        for (char& ch : k) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        keys[std::size_t(p.kfield)] = k;
        const bool whole = p.check == ParamCheck::curve || p.check == ParamCheck::integer || p.check == ParamCheck::flag01;
        f[std::size_t(p.kfield)] = whole && v == std::floor(v) && std::fabs(v) < 1e9 ? I((long long)v) : R(v);
        n = std::max(n, p.kfield + 1);
      }
      std::string head;
      for (int k = 0; k < n; ++k) {
        const std::string& key = keys[std::size_t(k)];
        head += std::string(key.size() < 10 ? 10 - key.size() : 0, ' ') + key;
      }
      if (head.size() >= 2) head.replace(0, 2, "$#");
      if (std::size_t(c) < t.keyword_heads.size() && t.keyword_heads[std::size_t(c)]) head = t.keyword_heads[std::size_t(c)];
      f.resize(std::size_t(n));
      os_ << (head.empty() ? "$#" : head) << "\n" << kcard(f) << "\n";
    }
  }

  // *EOS_...: the form's cards (material/eos.h), EOSID = the part's id.
  void write_eos(const EosData& e, int id) {
    const EosForm* f = find_eos_form(e.form);
    if (!f) return;
    os_ << "*" << f->keyword << "\n";
    for (int c = 0; c < int(f->widths.size()); ++c) {
      const int w = f->widths[std::size_t(c)];
      std::vector<KField> fields(std::size_t(eos_card_fields(*f, c)), B(w));
      std::string head(80, ' ');
      int n = 0;
      if (c == 0) fields[0] = I(id), n = 1, head.replace(5, 5, "eosid");
      for (const EosParam& p : f->params) {
        if (p.kcard != c || p.slot < 0) continue;
        fields[std::size_t(p.kfield)] = e.form == 6 && p.slot == kEosLeakCurve ? I((long long)eos_value(e, p), w) : R(eos_value(e, p), w);
        std::string k = p.key;
        for (char& ch : k) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        head.replace(std::size_t(w * p.kfield + w) - k.size(), k.size(), k);
        n = std::max(n, p.kfield + 1);
      }
      fields.resize(std::size_t(n));
      head.resize(std::size_t(w * n));
      head.replace(0, 2, "$#");
      os_ << head << "\n" << kcard(fields) << "\n";
    }
  }

  void materials() {
    os_ << "*SECTION_SOLID\n$#   secid    elform\n" << kcard({I(1), I(1)}) << "\n";
    // the fully integrated solids' section (ELFORM 2) after the shells' and beams' (1 + pid)
    const int sri_secid = int(m_.materials.size()) + 2;
    bool any_sri = false;
    for (const MaterialData& md : m_.materials) any_sri = any_sri || (!md.shell && !md.beam && md.solid_elform == 2);
    if (any_sri) os_ << "*SECTION_SOLID\n$#   secid    elform\n" << kcard({I(sri_secid), I(2)}) << "\n";
    for (std::size_t k = 0; k < m_.materials.size(); ++k) {
      const MaterialData& md = m_.materials[k];
      int id = int(k) + 1;
      os_ << "*PART\n$# title\n" << md.title << "\n";
      // a shell part has its own *SECTION_SHELL (secid 1 + pid)
      const int secid = md.shell || md.beam ? 1 + id : md.solid_elform == 2 ? sri_secid : 1;
      os_ << "$#     pid     secid       mid     eosid      hgid\n" << kcard({I(id), I(secid), I(id), I(md.eos.form != 0 ? id : 0), I(id)}) << "\n";
      if (md.beam) {  // a beam part: its own *SECTION_BEAM (secid 1 + pid)
        const BeamSectionData& sec = md.beam_section;
        os_ << "*SECTION_BEAM\n$#   secid    elform      shrf   qr/irid       cst\n"
            << kcard({I(1 + id), I(sec.spot_weld_beam ? 9 : sec.elform), R(sec.shrf), I(sec.qr), I(int(sec.cst))}) << "\n";
        if (sec.elform == 3) os_ << "$#       a\n" << kcard({R(sec.area)}) << "\n";
        else if (sec.elform == 2)
          os_ << "$#       a       iss       itt         j        sa\n" << kcard({R(sec.area), R(sec.iss), R(sec.itt), R(sec.jt), R(sec.sa)}) << "\n";
        else os_ << "$#     ts1       ts2       tt1       tt2\n" << kcard({R(sec.ts1), R(sec.ts2), R(sec.tt1), R(sec.tt2)}) << "\n";
        if (sec.qr <= 0) note("material " + std::to_string(id) + ": a user beam integration rule cannot be written");
      }
      if (md.shell) {
        const ShellSectionData& sec = md.shell_section;
        os_ << "*SECTION_SHELL\n$#   secid    elform      shrf       nip\n" << kcard({I(1 + id), I(sec.elform), R(sec.shrf), I(sec.nip)}) << "\n"
            << "$#      t1        t2        t3        t4\n" << kcard({R(sec.t[0]), R(sec.t[1]), R(sec.t[2]), R(sec.t[3])}) << "\n";
      }
      if (const MaterialType* t = find_material_type(md.type)) {
        write_material(*t, md, id);
        if (md.eos.form != 0) write_eos(md.eos, id);
        if (md.erosion.active) {
          const ErosionData& e = md.erosion;
          os_ << "*MAT_ADD_EROSION\n$#     mid      excl    mxpres     mneps    effeps    voleps    numfip       ncs\n"
              << kcard({I(id), R(e.excl), R(e.mxpres), R(e.mneps), R(e.effeps), R(e.voleps), B(), I(e.ncs)}) << "\n"
              << "$#  mnpres     sigp1     sigvm     mxeps     epssh     sigth   impulse    failtm\n"
              << kcard({R(e.mnpres), R(e.sigp1), R(e.sigvm), R(e.mxeps), R(e.epssh), B(), B(), R(e.failtm)}) << "\n";
        }
      } else {
        note("material " + std::to_string(id) + ": type " + std::to_string(md.type) + " cannot be written");
      }
      if (md.bulk_type != 1) note("material " + std::to_string(id) + ": bulk viscosity type " + std::to_string(md.bulk_type) + " written as 1");
      os_ << "*HOURGLASS\n$#    hgid       ihq        qm       ibq        q1        q2\n"
          << kcard({I(id), I(md.hourglass_type), R(md.hourglass_coef), I(0), R(md.q1), R(md.q2)}) << "\n";
    }
  }

  void nodes() {
    os_ << "*NODE\n$#   nid               x               y               z      tc      rc\n";
    for (int n = 0; n < m_.num_nodes(); ++n)
      os_ << kcard({I(nid(n), 8), R(m_.x[std::size_t(n)], 16), R(m_.y[std::size_t(n)], 16), R(m_.z[std::size_t(n)], 16),
                    I(m_.bc[std::size_t(n)], 8), I(0, 8)})
          << "\n";
  }

  void elements() {
    os_ << "*ELEMENT_SOLID\n$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n";
    for (int e = 0; e < m_.num_hexes(); ++e) {
      std::vector<KField> f = {I(eid(e), 8), I(m_.hex_material[std::size_t(e)] + 1, 8)};
      for (int v : m_.hex_nodes[std::size_t(e)]) f.push_back(I(v >= 0 ? nid(v) : 0, 8));
      os_ << kcard(f) << "\n";
    }
  }

  // Shells, their thicknesses on every element card; rotational constraints, initial rotational
  // velocities and the rotary inertia scale (shell_conditions).
  void shell_elements() {
    if (m_.num_shells() == 0) return;
    os_ << "*ELEMENT_SHELL_THICKNESS\n$#   eid     pid      n1      n2      n3      n4\n";
    element_cards(m_.num_shells(), m_.shell_nodes, m_.shell_material, m_.shell_thickness, [&](int e) { return m_.shell_id(e); });
  }

  // Beams, with their section sizes on every element card (all 0: the section's), and their
  // orientation vectors where the model has any (_ORIENTATION: one more card each).
  void beam_elements() {
    if (m_.num_beams() == 0) return;
    const bool oriented = !m_.beam_orientation.empty();
    os_ << (oriented ? "*ELEMENT_BEAM_THICKNESS_ORIENTATION" : "*ELEMENT_BEAM_THICKNESS") << "\n$#   eid     pid      n1      n2      n3\n";
    element_cards(m_.num_beams(), m_.beam_nodes, m_.beam_material, m_.beam_thickness, [&](int e) { return m_.beam_id(e); },
                  oriented ? &m_.beam_orientation : nullptr);
  }

  // The cards of n shells or beams: EID PID N1... (a missing node 0), then the four sizes.
  template <class Nodes, class Materials, class Sizes, class Id>
  void element_cards(int n, const Nodes& nodes, const Materials& material, const Sizes& sizes, Id&& id,
                     const std::vector<std::array<double, 3>>* orientation = nullptr) {
    for (int e = 0; e < n; ++e) {
      std::vector<KField> f = {I(id(e), 8), I(material[std::size_t(e)] + 1, 8)};
      for (int v : nodes[std::size_t(e)]) f.push_back(I(v >= 0 ? nid(v) : 0, 8));
      os_ << kcard(f) << "\n";
      const auto& t = sizes[std::size_t(e)];
      os_ << kcard({R(t[0], 16), R(t[1], 16), R(t[2], 16), R(t[3], 16)}) << "\n";
      if (orientation) {
        const auto& v = (*orientation)[std::size_t(e)];
        os_ << kcard({R(v[0], 16), R(v[1], 16), R(v[2], 16)}) << "\n";
      }
    }
  }

  void shell_conditions() {
    if (m_.shell_rotary_scale != 1.0)
      os_ << "*CONTROL_SHELL\n$#  wrpang     esort     irnxx    istupd    theory\n" << kcard({B(), B(), B(), B(), I(2)}) << "\n"
          << "$# rotascl\n" << kcard({R(m_.shell_rotary_scale)}) << "\n";
    for (int n = 0; n < int(m_.rot_bc.size()); ++n) {
      const int b = m_.rot_bc[std::size_t(n)];
      if (b == 0) continue;
      os_ << "*BOUNDARY_SPC_NODE\n$#     nid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz\n"
          << kcard({I(nid(n)), I(0), I(0), I(0), I(0), I(b & 1 ? 1 : 0), I(b & 2 ? 1 : 0), I(b & 4 ? 1 : 0)}) << "\n";
    }
    if (m_.init_omega.empty()) return;
    // a node's rotational velocity with its translational one (the velocity cards above, applied
    // in order), so that this card changes nothing else
    std::vector<std::array<double, 3>> v(std::size_t(m_.num_nodes()), {0, 0, 0});
    for (const InitialVelocity& iv : m_.init_velocities) {
      if (iv.first == 0) { std::fill(v.begin(), v.end(), iv.v); continue; }
      for (int k = iv.first; k <= iv.last && k <= m_.num_nodes(); k += std::max(1, iv.increment)) v[std::size_t(k - 1)] = iv.v;
    }
    for (int n = 0; n < m_.num_nodes(); ++n) {
      const auto& w = m_.init_omega[std::size_t(n)];
      if ((w[0] == 0 && w[1] == 0 && w[2] == 0) || (!omega_written_.empty() && omega_written_[std::size_t(n)])) continue;
      const auto& u = v[std::size_t(n)];
      os_ << "*INITIAL_VELOCITY_NODE\n$#     nid        vx        vy        vz       vxr       vyr       vzr\n"
          << kcard({I(nid(n)), R(u[0]), R(u[1]), R(u[2]), R(w[0]), R(w[1]), R(w[2])}) << "\n";
    }
  }

  // *INITIAL_TEMPERATURE_NODE: the nodes given one.
  void temperatures() {
    bool head = true;
    for (std::size_t n = 0; n < m_.node_temperature.size(); ++n) {
      if (std::isnan(m_.node_temperature[n])) continue;
      if (head) os_ << "*INITIAL_TEMPERATURE_NODE\n$#     nid      temp       loc\n";
      head = false;
      os_ << kcard({I(nid(int(n))), R(m_.node_temperature[n])}) << "\n";
    }
  }

  void curves() {
    for (const LoadCurve& lc : m_.load_curves) {
      os_ << "*DEFINE_CURVE\n$#    lcid      sidr       sfa       sfo      offa      offo\n" << kcard({I(lc.number)}) << "\n";
      os_ << "$#                a1                  o1\n";
      for (std::size_t p = 0; p < lc.t.size(); ++p) os_ << kcard({R(lc.t[p], 20), R(lc.f[p], 20)}) << "\n";
    }
  }

  int node_set(const std::vector<int>& nodes) {
    int sid = next_node_set_++;
    os_ << "*SET_NODE_LIST\n$#     sid\n" << kcard({I(sid)}) << "\n$#    nid1      nid2      nid3      nid4      nid5      nid6      nid7      nid8\n";
    std::vector<KField> f;
    for (int n : nodes) {
      f.push_back(I(nid(n)));
      if (f.size() == 8) { os_ << kcard(f) << "\n"; f.clear(); }
    }
    if (!f.empty()) os_ << kcard(f) << "\n";
    return sid;
  }

  // Spot welds: two-node welds without an axis as *CONSTRAINED_SPOTWELD, the others as
  // *CONSTRAINED_GENERALIZED_WELD_SPOT (a node set; the axis as the z axis of a coordinate
  // system of id 900001 on).
  void spot_welds() {
    int cid = 900000;
    for (const SpotWeld& w : m_.spot_welds) {
      if (!w.generalized && !w.has_axis && w.nodes.size() == 2) {
        os_ << (w.id ? "*CONSTRAINED_SPOTWELD_ID\n" + kcard({I(w.id)}) + "\n" : std::string("*CONSTRAINED_SPOTWELD\n"))
            << "$#      n1        n2        sn        ss         n         m        tf        ep\n"
            << kcard({I(nid(w.nodes[0])), I(nid(w.nodes[1])), R(w.sn), R(w.ss), R(w.n), R(w.m), R(w.tfail), R(w.epsf > 0 ? w.epsf : 1e20)}) << "\n";
        continue;
      }
      int c = 0;
      if (w.has_axis) {
        c = ++cid;
        // local x normal to the axis, y = z x x
        const auto& z = w.axis;
        std::array<double, 3> a = std::fabs(z[0]) < 0.9 ? std::array<double, 3>{1, 0, 0} : std::array<double, 3>{0, 1, 0};
        const double d = a[0] * z[0] + a[1] * z[1] + a[2] * z[2];
        std::array<double, 3> x = {a[0] - d * z[0], a[1] - d * z[1], a[2] - d * z[2]};
        const double l = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (double& v : x) v /= l;
        const std::array<double, 3> y = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]};
        os_ << "*DEFINE_COORDINATE_SYSTEM\n$#     cid        xo        yo        zo        xl        yl        zl\n"
            << kcard({I(c), R(0), R(0), R(0), R(x[0]), R(x[1]), R(x[2])}) << "\n$#      xp        yp        zp\n"
            << kcard({R(y[0]), R(y[1]), R(y[2])}) << "\n";
      }
      const int sid = node_set(w.nodes);
      os_ << (w.id ? "*CONSTRAINED_GENERALIZED_WELD_SPOT_ID\n" + kcard({I(w.id)}) + "\n" : std::string("*CONSTRAINED_GENERALIZED_WELD_SPOT\n"))
          << "$#    nsid       cid\n" << kcard({I(sid), I(c)}) << "\n"
          << "$#   tfail      epsf        sn        ss         n         m\n"
          << kcard({R(w.tfail), R(w.epsf), R(w.sn), R(w.ss), R(w.n), R(w.m)}) << "\n";
    }
  }

  // Tied contacts: the slave nodes as a node set, the master segments as a segment set (the tied
  // nodes were moved onto their segments when read: they tie again where they are).
  void tied_contacts() {
    for (const TiedContact& tc : m_.tied_contacts) {
      const int a = node_set(tc.slave_nodes), b = segment_set(tc.master);
      const std::string kw = !tc.keyword.empty() ? "*" + tc.keyword
                             : tc.torsion        ? "*CONTACT_SPOTWELD_WITH_TORSION"
                             : tc.spotweld       ? "*CONTACT_SPOTWELD"
                                                 : "*CONTACT_TIED_NODES_TO_SURFACE";
      os_ << (tc.id ? kw + "_ID\n" + kcard({I(tc.id)}) + "\n" : kw + "\n");
      os_ << "$#   surfa     surfb  surfatyp  surfbtyp\n" << kcard({I(a), I(b), I(4), I(0)}) << "\n";
      os_ << "$#      fs        fd        dc\n" << kcard({R(0), R(0), R(0)}) << "\n";
      os_ << "$#    sfsa      sfsb      sast\n" << kcard({R(1), R(1), R(tc.tolerance > 0 ? -tc.tolerance : 0.0)}) << "\n";
    }
  }

  void walls() {
    for (const StoneWall& w : m_.walls) {
      int sid = w.nodes.empty() ? 0 : node_set(w.nodes);
      if (w.cylinder()) {
        os_ << "*RIGIDWALL_GEOMETRIC_CYLINDER\n$#    nsid\n" << kcard({I(sid)}) << "\n"
            << "$#      xt        yt        zt        xh        yh        zh      fric\n"
            << kcard({R(w.tail[0]), R(w.tail[1]), R(w.tail[2]), R(w.head[0]), R(w.head[1]), R(w.head[2]), R(w.friction)}) << "\n"
            << "$#  radcyl    lencyl\n" << kcard({R(w.radius), R(w.length)}) << "\n";
        continue;
      }
      os_ << (w.mass > 0 ? "*RIGIDWALL_PLANAR_MOVING\n" : "*RIGIDWALL_PLANAR\n") << "$#    nsid\n" << kcard({I(sid)}) << "\n"
          << "$#      xt        yt        zt        xh        yh        zh      fric\n"
          << kcard({R(w.tail[0]), R(w.tail[1]), R(w.tail[2]), R(w.head[0]), R(w.head[1]), R(w.head[2]), R(w.friction)}) << "\n";
      if (w.mass > 0) os_ << "$#    mass        v0\n" << kcard({R(w.mass), R(w.v0)}) << "\n";
    }
  }

  // The rotational velocities (shell nodes) that a velocity card of these nodes can carry: the
  // nodes' common one, or none when they differ (shell_conditions writes those); marks them.
  std::array<double, 3> common_omega(const std::vector<int>& nodes) {
    std::array<double, 3> w{0, 0, 0};
    if (m_.init_omega.empty() || nodes.empty()) return w;
    w = m_.init_omega[std::size_t(nodes[0])];
    for (int n : nodes)
      if (m_.init_omega[std::size_t(n)] != w) return {0, 0, 0};
    if (omega_written_.empty()) omega_written_.assign(std::size_t(m_.num_nodes()), 0);
    for (int n : nodes) omega_written_[std::size_t(n)] = 1;
    return w;
  }
  std::vector<char> omega_written_;

  // The velocity card (with its comment line): VX VY VZ, and VXR VYR VZR only when not zero;
  // node > 0: the *INITIAL_VELOCITY_NODE form with NID first.
  std::string velocity_card(const std::array<double, 3>& v, const std::array<double, 3>& w, int node) {
    const bool rot = w[0] != 0 || w[1] != 0 || w[2] != 0;
    std::string head = node > 0 ? "$#     nid        vx        vy        vz" : "$#      vx        vy        vz";
    std::vector<KField> f;
    if (node > 0) f.push_back(I(node));
    for (double c : v) f.push_back(R(c));
    if (rot) {
      head += "       vxr       vyr       vzr";
      for (double c : w) f.push_back(R(c));
    }
    return head + "\n" + kcard(f) + "\n";
  }

  void velocities() {
    int nn = m_.num_nodes();
    for (const InitialVelocity& iv : m_.init_velocities) {
      if (iv.first == 0) {
        std::vector<int> every_node(std::size_t(nn), 0);
        for (int n = 0; n < nn; ++n) every_node[std::size_t(n)] = n;
        const auto w = common_omega(every_node);
        os_ << "*INITIAL_VELOCITY\n$#    nsid\n" << kcard({I(0)}) << "\n" << velocity_card(iv.v, w, 0);
        continue;
      }
      int inc = std::max(1, iv.increment);
      std::vector<int> nodes;
      for (int n = iv.first; n <= iv.last && n <= nn; n += inc) nodes.push_back(n - 1);
      if (nodes.empty()) continue;
      if (nodes.back() + 1 != iv.last || (nodes.size() == 1 && iv.increment != 1))
        note("initial velocity of nodes " + std::to_string(iv.first) + "-" + std::to_string(iv.last) + " by " +
             std::to_string(iv.increment) + " written as its node list (same velocities, range normalized)");
      const auto w = common_omega(nodes);
      if (nodes.size() == 1) {
        os_ << "*INITIAL_VELOCITY_NODE\n" << velocity_card(iv.v, w, nid(nodes[0]));
      } else {
        int sid = node_set(nodes);
        os_ << "*INITIAL_VELOCITY\n$#    nsid\n" << kcard({I(sid)}) << "\n" << velocity_card(iv.v, w, 0);
      }
    }
  }

  int lcid(int curve) const { return m_.load_curves[std::size_t(curve)].number; }

  // the axis 1-3 of a unit direction along x, y or z, or 0
  static int axis_of(const std::array<double, 3>& d) { return axis_number(d); }
  // A *DEFINE_VECTOR head (tail at the origin) that the reader's normalisation turns back into
  // the unit d bit for bit: d times the first whole number 1-32 that does (else d, noted).
  std::array<double, 3> vector_head(const std::array<double, 3>& d) {
    for (int k = 1; k <= 32; ++k) {
      const std::array<double, 3> h = {d[0] * k, d[1] * k, d[2] * k};
      const double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      if (h[0] / len == d[0] && h[1] / len == d[1] && h[2] / len == d[2]) return h;
    }
    note("a motion's vector (" + shortest(d[0]) + ", " + shortest(d[1]) + ", " + shortest(d[2]) + ") is read back rounded");
    return d;
  }
  int dof_of(const std::array<double, 3>& d, const std::string& what) {
    const int a = axis_of(d);
    if (a == 0) note(what + ": direction not along an axis, written as x");
    return a == 0 ? 1 : a;
  }

  void loads() {
    for (const NodalLoad& l : m_.nodal_loads)
      os_ << "*LOAD_NODE_POINT\n$#     nid       dof      lcid        sf\n"
          << kcard({I(nid(l.node)), I(dof_of(l.dir, "nodal load")), I(lcid(l.curve)), R(l.scale)}) << "\n";
    for (const RigidBodyLoad& l : m_.rigid_body_loads)
      os_ << "*LOAD_RIGID_BODY\n$#     pid       dof      lcid        sf\n"
          << kcard({I(l.material + 1), I(dof_of(l.dir, "rigid-body load")), I(lcid(l.curve)), R(l.scale)}) << "\n";
    for (const PressureLoad& l : m_.pressure_loads) {
      double f = l.factor[0];
      for (double x : l.factor)
        if (x != f) {
          note("pressure multipliers " + shortest(l.factor[0]) + " " + shortest(l.factor[1]) + " " + shortest(l.factor[2]) + " " +
               shortest(l.factor[3]) + " have no keyword field: written as their mean");
          f = 0.25 * (l.factor[0] + l.factor[1] + l.factor[2] + l.factor[3]);
          break;
        }
      if (l.death < 1e28) note("pressure death time " + shortest(l.death) + " has no *LOAD_SEGMENT field: not written");
      os_ << "*LOAD_SEGMENT\n$#    lcid        sf        at        n1        n2        n3        n4\n"
          << kcard({I(lcid(l.curve)), R(l.scale * f), R(l.birth), I(nid(l.nodes[0])), I(nid(l.nodes[1])), I(nid(l.nodes[2])),
                    I(nid(l.nodes[3]))})
          << "\n";
    }
    for (const BodyLoad& b : m_.body_loads) {
      const int a = axis_of(b.dir);
      if (a > 0) {
        os_ << "*LOAD_BODY_" << "XYZ"[a - 1] << "\n$#    lcid        sf\n" << kcard({I(lcid(b.curve)), R(b.scale)}) << "\n";
      } else {
        os_ << "*LOAD_BODY_VECTOR\n$#    lcid        sf\n" << kcard({I(lcid(b.curve)), R(b.scale)}) << "\n"
            << "$#      v1        v2        v3\n" << kcard({R(b.dir[0]), R(b.dir[1]), R(b.dir[2])}) << "\n";
      }
    }
    if (m_.damping.active) {
      const GlobalDamping& g = m_.damping;
      os_ << "*DAMPING_GLOBAL\n$#    lcid    valdmp       stx       sty       stz       srx       sry       srz\n"
          << kcard({I(g.curve >= 0 ? lcid(g.curve) : 0), R(g.d), R(g.factor[0]), R(g.factor[1]), R(g.factor[2]), R(0), R(0), R(0)})
          << "\n";
    }
    if (!m_.body_loads.empty() && !m_.body_load_materials.empty()) {
      const int sid = 1;
      os_ << "*SET_PART_LIST\n$#     sid\n" << kcard({I(sid)}) << "\n$#    pid1      pid2      pid3      pid4      pid5      pid6      pid7      pid8\n";
      std::vector<KField> f;
      for (int mt : m_.body_load_materials) {
        f.push_back(I(mt + 1));
        if (f.size() == 8) { os_ << kcard(f) << "\n"; f.clear(); }
      }
      if (!f.empty()) os_ << kcard(f) << "\n";
      os_ << "*LOAD_BODY_PARTS\n$#    psid\n" << kcard({I(sid)}) << "\n";
    }
    int next_vector = 1;
    for (const PrescribedMotion& pm : m_.prescribed_motions) {
      const bool rigid = pm.node < 0;
      int dof = axis_of(pm.dir), vid = 0;
      if (pm.orbit) {
        dof = (pm.radial_free ? -1 : 1) * (dof + 8);  // 9-11 (-11 to -9): turning about an axis along x y z
      } else if (dof == 0 || pm.hold_normal) {  // DOF 4 / 8 (-4 / -8) along or about a *DEFINE_VECTOR
        vid = next_vector++;
        const std::array<double, 3> h = vector_head(pm.dir);
        os_ << "*DEFINE_VECTOR\n$#     vid        xt        yt        zt        xh        yh        zh\n"
            << kcard({I(vid), R(0), R(0), R(0), R(h[0]), R(h[1]), R(h[2])}) << "\n";
        dof = (pm.hold_normal ? -1 : 1) * (pm.rotation ? 8 : 4);
      } else if (pm.rotation) {
        dof += 4;  // 5-7: about x y z
      }
      os_ << (rigid ? "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n$#     pid" : "*BOUNDARY_PRESCRIBED_MOTION_NODE\n$#     nid")
          << "       dof       vad      lcid        sf       vid     death     birth\n"
          << kcard({I(rigid ? pm.rigid_material + 1 : nid(pm.node)), I(dof), I(int(pm.kind)),
                    I(lcid(pm.curve)), R(pm.scale), I(vid), pm.death < 1e28 ? R(pm.death) : R(0), R(pm.birth)})
          << "\n";
      if (pm.orbit) {  // card 2: the axis's point in the plane normal to it (y z, z x, x y)
        const int a = axis_of(pm.dir) - 1;
        os_ << "$#  offset1   offset2       lrb     node1     node2\n"
            << kcard({R(pm.center[std::size_t((a + 1) % 3)]), R(pm.center[std::size_t((a + 2) % 3)]), I(0), I(0), I(0)}) << "\n";
      }
    }
  }

  int segment_set(const std::vector<std::array<int, 4>>& segs) {
    int sid = next_segment_set_++;
    os_ << "*SET_SEGMENT\n$#     sid\n" << kcard({I(sid)}) << "\n$#      n1        n2        n3        n4\n";
    for (const auto& s : segs) os_ << kcard({I(nid(s[0])), I(nid(s[1])), I(nid(s[2])), I(nid(s[3]))}) << "\n";
    return sid;
  }

  // SFSA with SFSA * SLSFAC == penalty_scale exactly.
  double scale_factor(double ps, double slsfac) {
    double s = ps / slsfac;
    for (int k = 0; k < 8 && s * slsfac != ps; ++k) s = std::nextafter(s, s * slsfac < ps ? INFINITY : -INFINITY);
    if (s * slsfac != ps) note("sliding interface penalty scale " + shortest(ps) + " written as SFSA " + shortest(s) + " (rounded)");
    return s;
  }

  // optional card A: SOFT 0 (DYNA3D), 1 (LS-DYNA soft constraint, SOFSCL), 2 (LS-DYNA segment-based),
  // -1 (IMPACT-3D maximum stable); card B of a non-automatic contact whose shells keep their thickness: THKOPT 1 with
  // its SHLTHK (*CONTROL_CONTACT SHLTHK, written blank, leaves them at their mid-surface)
  void soft_card(const SlidingInterface& si, bool automatic) {
    const int soft = si.stiffness_method == 2 ? 1 : si.stiffness_method == 3 ? 2 : si.stiffness_method == 1 ? -1 : 0;
    os_ << "$#    soft    sofscl\n" << kcard({I(soft), R(si.sofscl)}) << "\n";
    if (!automatic && si.shell_thickness != 0)
      os_ << "$#  penmax    thkopt    shlthk\n" << kcard({B(), I(1), I(si.shell_thickness)}) << "\n";
  }

  // An interface's beam nodes (contact nodes without segments) against the segment set seg_set:
  // a nodes-to-surface contact of their node set (SURFATYP 4) with the interface's constants;
  // read back, the same forces (one more interface in the model).
  void beam_node_contact(const SlidingInterface& si, const std::vector<int>& nodes, int seg_set) {
    if (nodes.empty()) return;
    note("sliding interface's " + std::to_string(nodes.size()) +
         " beam nodes written as a *CONTACT_NODES_TO_SURFACE of their node set (one more interface, the same forces)");
    const int ns = node_set(nodes);
    os_ << (si.eroding ? "*CONTACT_ERODING_NODES_TO_SURFACE\n" : "*CONTACT_NODES_TO_SURFACE\n");
    os_ << "$#   surfa     surfb  surfatyp  surfbtyp\n" << kcard({I(ns), I(seg_set), I(4), I(0)}) << "\n";
    os_ << "$#      fs        fd        dc\n" << kcard({R(si.fs), R(si.fd), R(si.decay)}) << "\n";
    double s = si.penalty_scale == 0 ? 1.0 : scale_factor(si.penalty_scale, m_.control.penalty_scale);
    os_ << "$#    sfsa      sfsb\n" << kcard({R(s), R(s)}) << "\n";
    if (si.eroding) os_ << "$#    isym    erosop      iadj\n" << kcard({I(0), I(1), I(0)}) << "\n";
    soft_card(si, si.eroding);
  }

  // The keyword an interface is written as: the one it was read from where that reads back as
  // the same interface (an automatic one only with its shells at +-t/2), else the plain form.
  static std::string contact_keyword(const SlidingInterface& si) {
    auto kept = [&](std::initializer_list<const char*> names, const char* plain) {
      for (const char* n : names)
        if (si.keyword == n) {
          const bool automatic = si.keyword.find("AUTOMATIC") != std::string::npos || si.keyword.find("FORMING") != std::string::npos;
          if (!automatic || si.shell_thickness == 2) return "*" + si.keyword + "\n";
        }
      return std::string(plain);
    };
    if (si.type == 4)
      return si.eroding ? "*CONTACT_ERODING_SINGLE_SURFACE\n" : kept({"CONTACT_SINGLE_SURFACE"}, "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n");
    if (si.eroding) return si.symmetric ? "*CONTACT_ERODING_SURFACE_TO_SURFACE\n" : "*CONTACT_ERODING_NODES_TO_SURFACE\n";
    if (si.symmetric) return kept({"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE"}, "*CONTACT_SURFACE_TO_SURFACE\n");
    return kept({"CONTACT_AUTOMATIC_NODES_TO_SURFACE", "CONTACT_ONE_WAY_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE",
                 "CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE"},
                "*CONTACT_NODES_TO_SURFACE\n");
  }
  static bool automatic_keyword(const std::string& kw) {
    return kw.find("AUTOMATIC") != std::string::npos || kw.find("FORMING") != std::string::npos || kw.find("SINGLE") != std::string::npos ||
           kw.find("ERODING") != std::string::npos;
  }

  void interfaces() {
    for (const SlidingInterface& si : m_.interfaces) {
      if (si.type == 4) {  // single surface: side A only, a segment set
        const int a = segment_set(si.slave);
        os_ << contact_keyword(si);
        os_ << "$#   surfa     surfb  surfatyp  surfbtyp   saboxid   sbboxid      sapr\n"
            << kcard({I(a), I(0), I(0), I(0), I(0), I(0), I(si.intfor_slave ? 1 : 0)}) << "\n";
        os_ << "$#      fs        fd        dc\n" << kcard({R(si.fs), R(si.fd), R(si.decay)}) << "\n";
        double s = si.penalty_scale == 0 ? 1.0 : scale_factor(si.penalty_scale, m_.control.penalty_scale);
        os_ << "$#    sfsa      sfsb\n" << kcard({R(s), R(s)}) << "\n";
        if (si.eroding) os_ << "$#    isym    erosop      iadj\n" << kcard({I(0), I(1), I(0)}) << "\n";
        soft_card(si, true);
        beam_node_contact(si, si.slave_nodes, a);
        continue;
      }
      if (si.slave.empty()) {  // a side of beams only: its nodes against the master segments (one pass)
        beam_node_contact(si, si.slave_nodes, segment_set(si.master));
        continue;
      }
      int a = segment_set(si.slave), b = segment_set(si.master);
      if (si.type != 3) note("sliding interface type " + std::to_string(si.type) + " written as type 3");
      const std::string kw = contact_keyword(si);
      os_ << kw;
      if (si.intfor_slave || si.intfor_master)
        os_ << "$#   surfa     surfb  surfatyp  surfbtyp   saboxid   sbboxid      sapr      sbpr\n"
            << kcard({I(a), I(b), I(0), I(0), I(0), I(0), I(si.intfor_slave ? 1 : 0), I(si.intfor_master ? 1 : 0)}) << "\n";
      else
        os_ << "$#   surfa     surfb  surfatyp  surfbtyp\n" << kcard({I(a), I(b), I(0), I(0)}) << "\n";
      os_ << "$#      fs        fd        dc\n" << kcard({R(si.fs), R(si.fd), R(si.decay)}) << "\n";
      double s = si.penalty_scale == 0 ? 1.0 : scale_factor(si.penalty_scale, m_.control.penalty_scale);
      if (si.penalty_scale != 0 && s == 1.0) note("sliding interface penalty scale equal to the control value: written as the default");
      os_ << "$#    sfsa      sfsb\n" << kcard({R(s), R(s)}) << "\n";
      if (si.eroding) os_ << "$#    isym    erosop      iadj\n" << kcard({I(0), I(1), I(0)}) << "\n";
      soft_card(si, automatic_keyword(kw));
      beam_node_contact(si, si.slave_nodes, b);
      if (si.symmetric) beam_node_contact(si, si.master_nodes, a);
    }
    // force transducers: their sides as node sets (SURFATYP / SURFBTYP 4)
    for (const ForceTransducer& ft : m_.force_transducers) {
      const int a = node_set(ft.a_nodes), b = ft.has_b ? node_set(ft.b_nodes) : 0;
      if (ft.id != 0) os_ << "*CONTACT_FORCE_TRANSDUCER_PENALTY_ID\n$#     cid\n" << kcard({I(ft.id)}) << "\n";
      else os_ << "*CONTACT_FORCE_TRANSDUCER_PENALTY\n";
      os_ << "$#   surfa     surfb  surfatyp  surfbtyp\n" << kcard({I(a), I(b), I(4), I(ft.has_b ? 4 : 0)}) << "\n";
    }
  }
};

// ------------------------------------------------------------------ fixed-format cards
class FixedLine {
 public:
  explicit FixedLine(std::vector<std::string>* notes, std::string what) : notes_(notes), what_(std::move(what)) {}
  FixedLine& i(int c1, int c2, long long v) {
    std::string s = std::to_string(v);
    if (int(s.size()) > c2 - c1 + 1) {
      if (notes_) notes_->push_back(what_ + ": " + s + " does not fit columns " + std::to_string(c1) + "-" + std::to_string(c2));
      s = std::string(std::size_t(c2 - c1 + 1), '*');
    }
    return put(c1, c2, s);
  }
  FixedLine& r(int c1, int c2, double v) {
    bool exact = true;
    std::string s = fit(v, c2 - c1 + 1, exact);
    if (!exact && notes_) notes_->push_back(what_ + ": " + shortest(v) + " rounded to " + s + " (columns " + std::to_string(c1) + "-" + std::to_string(c2) + ")");
    return put(c1, c2, s);
  }
  FixedLine& a(int c1, int c2, const std::string& s) {
    std::string t = s.substr(0, std::size_t(c2 - c1 + 1));
    if (t.size() < s.size() && notes_) notes_->push_back(what_ + ": text cut to " + std::to_string(c2 - c1 + 1) + " characters");
    if (int(line_.size()) < c2) line_.resize(std::size_t(c2), ' ');
    for (std::size_t k = 0; k < t.size(); ++k) line_[std::size_t(c1 - 1) + k] = t[k];
    return *this;
  }
  std::string str() const {
    std::string s = line_;
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
  }

 private:
  FixedLine& put(int /*c1*/, int c2, const std::string& s) {
    if (int(line_.size()) < c2) line_.resize(std::size_t(c2), ' ');
    int start = c2 - int(s.size()) + 1;
    for (std::size_t k = 0; k < s.size(); ++k) line_[std::size_t(start - 1) + k] = s[k];
    return *this;
  }
  std::vector<std::string>* notes_;
  std::string what_;
  std::string line_;
};

// A card written by its table (fixed_cards.h): each named field where the table puts it.
class TableLine {
 public:
  TableLine(std::vector<std::string>* notes, const char* id, std::string what = {})
      : layout_(fixed_card_layout(id, FixedVintage::dyna3d_later)), line_(notes, what.empty() ? id : what) {}
  TableLine& operator()(const std::string& name, double v) { return (*this)(name.c_str(), v); }
  TableLine& operator()(const char* name, double v) {
    const FixedField& f = layout_.field(name);
    if (is_integer(f.kind)) line_.i(f.c1, f.c2, static_cast<long long>(v));
    else line_.r(f.c1, f.c2, v);
    return *this;
  }
  // Every integer field written as 0 (a card whose fields are counts and flags).
  TableLine& zeros() {
    for (const FixedField& f : layout_.fields)
      if (is_integer(f.kind)) line_.i(f.c1, f.c2, 0);
    return *this;
  }
  TableLine& text(const char* name, const std::string& v) {
    const FixedField& f = layout_.field(name);
    line_.a(f.c1, f.c2, v);
    return *this;
  }
  std::string str() const { return line_.str(); }

 private:
  const FixedCardLayout& layout_;
  FixedLine line_;
};

// The fixed-format deck (the later vintage, large format), card by card from the tables
// (fixed_cards.h); what the format cannot hold is noted and left out.
class FixedWriter {
 public:
  FixedWriter(std::ostream& os, const Model& m, std::vector<std::string>* notes) : os_(os), m_(m), notes_(notes) {}

  void write() {
    if ((!m_.node_user_id.empty() || !m_.hex_user_id.empty())) note("node and element ids renumbered 1..N (the fixed format needs 1..N)");
    if (!m_.node_temperature.empty()) note("initial nodal temperatures (*INITIAL_TEMPERATURE) have no fixed-format card: not written");
    os_ << T("title card").text("title", m_.title).text("format digits", "88").text("format flag", "large").str() << "\n";
    os_ << "*----- written by IMPACT-3D (impact3d --write-fixed); layout: README.md \"Deck format\"\n";
    control_cards_2_to_4();
    note_unwritable();
    control_cards_5_to_9();
    materials();
    beam_rules();
    nodes();
    solids();
    beams();
    shells();
    time_history_blocks();
    curves();
    loads();
    walls();
    velocities();
    interfaces();
    base_accelerations();
    if (damping_card_) {
      os_ << "*----- MASS DAMPING: damping ratio, frequency (D = 2 ratio frequency = *DAMPING_GLOBAL VALDMP)\n";
      os_ << T("mass damping card")("damping ratio", 0.5)("frequency", m_.damping.d).str() << "\n";
    }
    os_ << "*----- END OF DECK\n";
  }

 private:
  std::ostream& os_;
  const Model& m_;
  std::vector<std::string>* notes_;
  int node_motions_ = 0;
  bool damping_card_ = false;
  std::array<int, 3> base_ = {-1, -1, -1};  // body load written as each axis's base acceleration
  std::vector<int> rule_of_;                 // per material: its user beam rule (1..), 0 none
  int rules_ = 0, rule_points_ = 0;

  TableLine T(const char* id, std::string what = {}) const { return TableLine(notes_, id, std::move(what)); }
  void note(const std::string& s) const {
    if (notes_) notes_->push_back(s);
  }

  void control_cards_2_to_4() {
    const ControlData& k = m_.control;
    os_ << "*----- CONTROL CARD #2: counts\n";
    os_ << T("control card 2")("NMMAT", int(m_.materials.size()))("NUMNP", m_.num_nodes())("NUMELH", m_.num_hexes())
               ("NUMELB", m_.num_beams())("NUMELS", m_.num_shells())("NUMELT", 0)("interface segments", k.interface_segments_out)
               ("interface output interval", k.interface_out_interval).str() << "\n";
    os_ << "*----- CONTROL CARD #3\n";
    os_ << T("control card 3")("node time-history blocks", int(m_.node_th_blocks.size()))
               ("solid time-history blocks", int(m_.solid_th_blocks.size()))("beam time-history blocks", int(m_.beam_th_blocks.size()))
               ("shell time-history blocks", int(m_.shell_th_blocks.size()))("thick shell time-history blocks", 0)
               ("report interval", k.report_interval)("reaction-force print flag", k.reaction_print_flag)
               ("discrete-element print flag", 0)("element deletion flag", 0).str() << "\n";
    os_ << "*----- CONTROL CARD #4\n";
    os_ << T("control card 4")("sliding boundary planes", 0)("sliding planes with failure", 0)
               ("density-versus-depth points", 0)("Brode function flag", 0)("rigid-body merge cards", 0)
               .text("coordinate format", "e20.0")("force cross-sections", 0).str() << "\n";
  }

  // What the fixed format can hold of the loads: prescribed motions of nodes, one base
  // acceleration per axis on every material; the rest is noted and left out.
  void note_unwritable() {
    int rigid = 0;
    for (const PrescribedMotion& pm : m_.prescribed_motions) {
      rigid += pm.node < 0 ? 1 : 0;
      if (fixed_motion(pm)) ++node_motions_;
      else if (pm.node >= 0)
        note("node " + std::to_string(pm.node + 1) + ": a node turning about an axis (LS-DYNA DOF 9-11), or a rotation given by its acceleration or angle, about a vector or with the other rotations held (DOF 8, -8), has no fixed-format card: not written");
    }
    if (rigid > 0) note("prescribed motions of rigid bodies have no fixed-format card: not written");
    if (!m_.rigid_body_loads.empty()) note("rigid-body loads have no fixed-format card: not written");
    if (!m_.spot_welds.empty())
      note("spot welds (*CONSTRAINED_SPOTWELD, *CONSTRAINED_GENERALIZED_WELD_SPOT) have no fixed-format card: not written");
    damping_card_ = m_.damping.active && m_.damping.curve < 0 && m_.damping.factor == std::array<double, 3>{1, 1, 1};
    if (m_.damping.active && !damping_card_)
      note("global mass damping with a curve or per-axis factors (*DAMPING_GLOBAL) has no fixed-format card: not written");
    if (!m_.tied_contacts.empty())
      note("tied contacts (*CONTACT_SPOTWELD, *CONTACT_TIED_...) have no fixed-format card: not written");
    if (!m_.force_transducers.empty()) note("force transducers (*CONTACT_FORCE_TRANSDUCER_PENALTY) have no fixed-format card: not written");
    if (m_.control.intfor_interval >= 0)
      note("the interface-force database (*DATABASE_BINARY_INTFOR, SAPR/SBPR) has no fixed-format card: not written");
    for (std::size_t j = 0; j < m_.body_loads.size(); ++j) {
      const auto& d = m_.body_loads[j].dir;
      int a = -1;
      for (int q = 0; q < 3; ++q)
        if (d[std::size_t(q)] == 1 && d[std::size_t((q + 1) % 3)] == 0 && d[std::size_t((q + 2) % 3)] == 0) a = q;
      if (a < 0 || base_[std::size_t(a)] >= 0 || !m_.body_load_materials.empty()) {
        note("body load " + std::to_string(j + 1) + " is not one base acceleration per axis on every material: not written");
        continue;
      }
      base_[std::size_t(a)] = int(j);
    }
    for (const PressureLoad& l : m_.pressure_loads)
      if (l.death < 1e28) { note("pressure death times have no fixed-format field: not written"); break; }
  }

  void control_cards_5_to_9() {
    const ControlData& k = m_.control;
    os_ << "*----- CONTROL CARD #5\n";
    os_ << T("control card 5").zeros()("NUMLC", int(m_.load_curves.size()))("concentrated nodal loads", int(m_.nodal_loads.size()))
               ("pressure-loaded sides", int(m_.pressure_loads.size()))("velocity/acceleration boundary cards", node_motions_)
               ("stonewalls", int(m_.walls.size()))("initial condition parameter", int(m_.init_velocities.size()))
               ("sliding interfaces", int(m_.interfaces.size()))("base acceleration x", base_[0] >= 0 ? 1 : 0)
               ("base acceleration y", base_[1] >= 0 ? 1 : 0)("base acceleration z", base_[2] >= 0 ? 1 : 0).str() << "\n";
    if (k.end_cycle > 0) note("termination cycle (ENDCYC " + std::to_string(k.end_cycle) + ") has no field in the fixed format: not written");
    os_ << "*----- CONTROL CARD #6\n";
    os_ << T("control card 6")("termination time", k.end_time)("time-history interval", k.th_interval)("plot interval", k.plot_interval)
               ("restart dump cycles", k.restart_dump_cycles)("running restart cycles", k.running_restart_cycles)
               ("initial time step", k.initial_dt)("penalty scale factor", k.penalty_scale)("thermal option", 0)
               ("default viscosity flag", k.viscosity_flag)("time-step scale factor", k.tssf).str() << "\n";
    os_ << "*----- CONTROL CARD #7\n";
    os_ << T("control card 7").zeros()("mass damping sets", damping_card_ ? 1 : 0).str() << "\n";
    // user beam integration rules: one per beam material that has one, numbered in material order
    rule_of_.assign(m_.materials.size(), 0);
    for (std::size_t j = 0; j < m_.materials.size(); ++j)
      if (m_.materials[j].beam && !m_.materials[j].beam_section.user_rule.empty()) {
        rule_of_[j] = ++rules_;
        rule_points_ = std::max(rule_points_, int(m_.materials[j].beam_section.user_rule.size()));
      }
    os_ << "*----- CONTROL CARD #8\n";
    os_ << T("control card 8").zeros()("minimum step factor", k.min_step_factor)("beam integration rules", rules_)
               ("beam integration points", rule_points_).str() << "\n";
    os_ << "*----- CONTROL CARD #9\n";
    TableLine c9 = T("control card 9");
    c9("plane-stress plasticity option", 0)("printout flag", 0)("1-D slidelines", 0)("relaxation database flag", 0);
    if (k.mass_scaling_dt != 0 || k.end_mass_percent > 0 || k.erode_small_steps)
      c9("DT2MS", k.mass_scaling_dt)("MS1ST", k.mass_scaling_first_only ? 1 : 0)("ENDMAS", k.end_mass_percent)("ERODE", k.erode_small_steps ? 1 : 0);
    os_ << c9.str() << "\n";
  }

  void materials() {
    os_ << "*----- MATERIALS\n";
    for (std::size_t j = 0; j < m_.materials.size(); ++j) {
      const MaterialData& md = m_.materials[j];
      const std::string what = "material " + std::to_string(j + 1);
      if (!md.shell && !md.beam && md.solid_elform == 2)
        note(what + ": a fully integrated solid (*SECTION_SOLID ELFORM 2) has no DYNA3D element formulation: written as the one-point hexahedron (with hourglass type 1, coefficient 0.1)");
      if (md.shell && md.shell_section.elform == 16)
        note(what + ": a fully integrated shell (*SECTION_SHELL ELFORM 16) has no DYNA3D element formulation: written as a Belytschko-Tsay shell (with hourglass type 1, coefficient 0.1)");
      os_ << T("material card 1", what + " card 1")("material number", int(j) + 1)("material type", md.type)("density", md.rho)
                 ("EOS type", md.eos.form)("hourglass type", md.hourglass_type)("hourglass coefficient", md.hourglass_coef)
                 ("bulk viscosity type", md.bulk_type)("quadratic bulk viscosity Q1", md.q1)("linear bulk viscosity Q2", md.q2)
                 ("element type", md.shell ? 2 : md.beam ? 1 : 0)("element formulation", md.beam ? 1 : 0).str() << "\n";
      os_ << T("material title card", what + " title").text("title", md.title).str() << "\n";
      property_cards(md, what);
      if (md.beam) beam_section(md, j, what);
      if (md.shell) shell_section(md, what);
      if (const EosForm* f = find_eos_form(md.eos.form)) eos_cards(md, *f, what);
    }
  }

  // Cards 3-8: each parameter where the type's table puts it (material_types.h).
  void property_cards(const MaterialData& md, const std::string& what) {
    const MaterialType* t = find_material_type(md.type);
    for (int c = 3; c <= 8; ++c) {
      FixedLine line(notes_, what + " card " + std::to_string(c));
      if (t) {
        // a card's optional fields are written together when any of them is nonzero
        bool any_optional = false;
        for (const MaterialParam& p : t->params)
          if (p.fcard == c && p.optional_write && param_value(md, p) != 0) any_optional = true;
        for (const MaterialParam& p : t->params)
          if (p.fcard == c && (!p.optional_write || any_optional)) line.r(p.fcol, p.fcol + 9, param_value(md, p));
      }
      const std::string text = line.str();
      os_ << (text.find_first_not_of(' ') == std::string::npos ? std::string() : text) << "\n";
    }
  }

  // DYNA3D's beam section: a title line, SHRF QR CST, TS1 TS2 TT1 TT2.
  void beam_section(const MaterialData& md, std::size_t j, const std::string& what) {
    const BeamSectionData& sec = md.beam_section;
    if (sec.elform != 1) note(what + ": a resultant beam or truss (ELFORM 2/3) has no DYNA3D beam card: written as a Hughes-Liu beam");
    const bool user = !sec.user_rule.empty();
    os_ << " Hughes-Liu beam section properties\n";
    os_ << T("beam section card 1", what + " beam section card 1")("shear factor", sec.shrf)
               ("quadrature rule", user ? -rule_of_[j] : sec.qr)("cross-section type", user ? 2 : int(sec.cst)).str() << "\n";
    os_ << T("beam section card 2", what + " beam section card 2")("TS1", sec.ts1)("TS2", sec.ts2)("TT1", sec.tt1)("TT2", sec.tt2).str() << "\n";
  }

  // DYNA3D's shell section: a title line, SHRF NIP QR, T1-T4.
  void shell_section(const MaterialData& md, const std::string& what) {
    const ShellSectionData& sec = md.shell_section;
    os_ << " shell section properties\n";
    os_ << T("shell section card 1", what + " shell section card 1")("shear factor SHRF", sec.shrf)("NIP", sec.nip)
               ("quadrature rule QR", 0).str() << "\n";
    os_ << T("shell section card 2", what + " shell section card 2")("T1", sec.t[0])("T2", sec.t[1])("T3", sec.t[2])("T4", sec.t[3]).str() << "\n";
  }

  // The EOS cards (material/eos.h: each form's widths and fields).
  void eos_cards(const MaterialData& md, const EosForm& f, const std::string& what) {
    const std::vector<int>& fw = eos_fixed_widths(f);
    for (int c = 0; c < int(fw.size()); ++c) {
      FixedLine line(notes_, what + " EOS card " + std::to_string(c + 1));
      const int w = fw[std::size_t(c)];
      for (const EosParam& p : f.params) {
        if (p.fcard != c || p.slot < 0) continue;
        if (md.eos.form == 6 && p.slot == kEosLeakCurve) line.i(1 + w * p.ffield, w + w * p.ffield, int(eos_value(md.eos, p)));
        else line.r(1 + w * p.ffield, w + w * p.ffield, eos_value(md.eos, p));
      }
      os_ << line.str() << "\n";
    }
  }

  void beam_rules() {
    if (rules_ > 0) os_ << "*----- USER BEAM INTEGRATION RULES: points, 1.0; s, t, weight\n";
    for (std::size_t j = 0; j < m_.materials.size(); ++j) {
      if (!rule_of_[j]) continue;
      const auto& rule = m_.materials[j].beam_section.user_rule;
      os_ << T("beam integration rule header card", "beam integration rule")("number of points", int(rule.size()))("rule area factor", 1.0).str() << "\n";
      for (const auto& p : rule)
        os_ << T("beam integration point card", "beam integration point")("s", p[0])("t", p[1])("weight", p[2]).str() << "\n";
    }
  }

  void nodes() {
    os_ << "*----- NODES\n";
    static const int rot_code[8] = {0, 1, 2, 4, 3, 6, 5, 7};  // bits (0 rx, 1 ry, 2 rz) -> code 0-7
    for (int n = 0; n < m_.num_nodes(); ++n) {
      const std::size_t i = std::size_t(n);
      const int rc = i < m_.rot_bc.size() ? rot_code[m_.rot_bc[i] & 7] : 0;
      os_ << T("node card", "node " + std::to_string(n + 1))("node number", n + 1)("boundary code", m_.bc[i])("x", m_.x[i])("y", m_.y[i])
                 ("z", m_.z[i])("rotational code", rc).str() << "\n";
    }
  }

  void solids() {
    static const char* const nf[8] = {"node n1", "node n2", "node n3", "node n4", "node n5", "node n6", "node n7", "node n8"};
    os_ << "*----- SOLID ELEMENTS\n";
    for (int e = 0; e < m_.num_hexes(); ++e) {
      TableLine c = T("solid element card", "solid " + std::to_string(e + 1));
      c("element number", e + 1)("material number", m_.hex_material[std::size_t(e)] + 1);
      for (int j = 0; j < 8; ++j) c(nf[j], m_.hex_nodes[std::size_t(e)][std::size_t(j)] + 1);
      os_ << c.str() << "\n";
    }
  }

  void beams() {
    if (m_.num_beams() > 0) os_ << "*----- BEAM ELEMENTS: id, material, n1, n2, orientation node n3, TS1 TS2 TT1 TT2\n";
    for (int e = 0; e < m_.num_beams(); ++e) {
      const auto& n = m_.beam_nodes[std::size_t(e)];
      const auto& t = m_.beam_thickness[std::size_t(e)];
      os_ << T("beam element card", "beam " + std::to_string(e + 1))("element number", e + 1)
                 ("material number", m_.beam_material[std::size_t(e)] + 1)("node n1", n[0] + 1)("node n2", n[1] + 1)
                 ("orientation node n3", n[2] + 1)("field 6", t[0])("field 7", t[1])("field 8", t[2])("field 9", t[3]).str() << "\n";
    }
  }

  void shells() {
    static const char* const nf[4] = {"node n1", "node n2", "node n3", "node n4"};
    static const char* const tf[4] = {"thickness t1", "thickness t2", "thickness t3", "thickness t4"};
    if (m_.num_shells() > 0) os_ << "*----- SHELL ELEMENTS: id, material, n1-n4; thicknesses t1-t4\n";
    for (int e = 0; e < m_.num_shells(); ++e) {
      const std::string what = "shell " + std::to_string(e + 1);
      TableLine c = T("shell element card", what);
      c("element number", e + 1)("material number", m_.shell_material[std::size_t(e)] + 1);
      for (int j = 0; j < 4; ++j) c(nf[j], m_.shell_nodes[std::size_t(e)][std::size_t(j)] + 1);
      os_ << c.str() << "\n";
      TableLine t = T("shell thickness card", what + " thicknesses");
      for (int j = 0; j < 4; ++j) t(tf[j], m_.shell_thickness[std::size_t(e)][std::size_t(j)]);
      os_ << t.str() << "\n";
    }
  }

  void time_history_blocks() {
    os_ << "*----- TIME-HISTORY BLOCKS\n";
    for (const auto* blocks : {&m_.node_th_blocks, &m_.solid_th_blocks, &m_.beam_th_blocks, &m_.shell_th_blocks})  // five blocks a card
      for (std::size_t b = 0; b < blocks->size(); b += 5) {
        TableLine c = T("time-history block card");
        for (std::size_t j = 0; j < 5 && b + j < blocks->size(); ++j)
          c("first " + std::to_string(j + 1), (*blocks)[b + j][0])("last " + std::to_string(j + 1), (*blocks)[b + j][1]);
        os_ << c.str() << "\n";
      }
  }

  void curves() {
    if (!m_.load_curves.empty()) os_ << "*----- LOAD CURVES\n";
    for (std::size_t c = 0; c < m_.load_curves.size(); ++c) {
      const LoadCurve& lc = m_.load_curves[c];
      os_ << T("load curve header card", "load curve")("curve number", int(c) + 1)("NPTS", int(lc.t.size())).str() << "\n";
      for (std::size_t p = 0; p < lc.t.size(); ++p)
        os_ << T("load curve point card", "load curve point")("time", lc.t[p])("value", lc.f[p]).str() << "\n";
    }
  }

  void loads() {
    if (!m_.nodal_loads.empty()) os_ << "*----- NODAL LOADS: node, direction, load curve, scale\n";
    for (const NodalLoad& l : m_.nodal_loads) {
      int d = 0;
      for (int q = 0; q < 3; ++q) if (l.dir[std::size_t(q)] == 1) d = q + 1;
      if (d == 0) note("nodal load direction not along an axis: written as x");
      os_ << T("nodal load card", "nodal load")("node", l.node + 1)("direction", d == 0 ? 1 : d)("load curve", l.curve + 1)
                 ("scale factor", l.scale).str() << "\n";
    }
    pressures();
    motions();
  }

  void pressures() {
    if (!m_.pressure_loads.empty()) os_ << "*----- PRESSURE LOADS: load curve, n1-n4, multipliers\n";
    for (const PressureLoad& l : m_.pressure_loads) {
      if (l.birth != 0) note("pressure arrival time " + shortest(l.birth) + " has no field in DYNA3D's pressure card: not written");
      TableLine c = T("pressure card");
      c("load curve", l.curve + 1);
      for (int q = 0; q < 4; ++q)
        c("node n" + std::to_string(q + 1), l.nodes[std::size_t(q)] + 1)("multiplier " + std::to_string(q + 1), l.factor[std::size_t(q)] * l.scale);
      os_ << c.str() << "\n";
    }
  }

  // Whether the fixed format's velocity/acceleration card holds this motion: a node's, along an
  // axis or a vector, or a rotational velocity about an axis (DOF 5-7, type 0).
  static bool fixed_motion(const PrescribedMotion& pm) {
    if (pm.node < 0 || pm.orbit) return false;
    return !pm.rotation || (pm.kind == MotionKind::velocity && !pm.hold_normal && axis_number(pm.dir) > 0);
  }

  void motions() {
    if (node_motions_ > 0) os_ << "*----- VELOCITY/ACCELERATION BOUNDARY CONDITIONS: node, curve, DOF, scale, vector, type, birth\n";
    for (const PrescribedMotion& pm : m_.prescribed_motions) {
      if (!fixed_motion(pm)) continue;
      if (pm.hold_normal)
        note("node " + std::to_string(pm.node + 1) + ": a motion along a vector with its normal plane held (LS-DYNA DOF -4) has no fixed-format field: written as DOF 4, the normal plane free");
      int d = 4;
      for (int q = 0; q < 3; ++q) if (pm.dir[std::size_t(q)] == 1 && !pm.hold_normal) d = (pm.rotation ? 5 : 1) + q;
      TableLine c = T("velocity/acceleration boundary card");
      c("node", pm.node + 1)("load curve", pm.curve + 1)("DOF", d)("scale factor", pm.scale);
      if (d == 4) c("vx", pm.dir[0])("vy", pm.dir[1])("vz", pm.dir[2]);
      c("type", int(pm.kind));
      if (pm.birth != 0) c("birth time", pm.birth);
      if (pm.death < 1e28) c("death time", pm.death);
      os_ << c.str() << "\n";
    }
  }

  void walls() {
    if (!m_.walls.empty()) os_ << "*----- STONEWALLS\n";
    const FixedCardLayout& list = fixed_card_layout("node list card", FixedVintage::dyna3d_later);
    const std::size_t per = list.fields.size();
    for (const StoneWall& w : m_.walls) {
      os_ << T("stonewall card", "stonewall")("NSN", int(w.nodes.size()))("moving flag", w.mass > 0 ? 1 : 0)("XT", w.tail[0])("YT", w.tail[1])
                 ("ZT", w.tail[2])("XH", w.head[0])("YH", w.head[1])("ZH", w.head[2])("FRIC", w.friction).str() << "\n";
      if (w.mass > 0) os_ << T("moving stonewall card", "moving stonewall")("MASS", w.mass)("V0", w.v0).str() << "\n";
      for (std::size_t j = 0; j < w.nodes.size(); j += per) {
        TableLine c = T("node list card", "stonewall nodes");
        for (std::size_t q = j; q < std::min(j + per, w.nodes.size()); ++q) c(list.fields[q - j].name, w.nodes[q] + 1);
        os_ << c.str() << "\n";
      }
    }
  }

  void velocities() {
    if (!m_.init_velocities.empty()) os_ << "*----- INITIAL VELOCITIES\n";
    for (const InitialVelocity& iv : m_.init_velocities)
      os_ << T("initial velocity range card", "initial velocity")("first node", iv.first)("vx", iv.v[0])("vy", iv.v[1])("vz", iv.v[2])
                 ("last node", iv.last)("increment", iv.increment).str() << "\n";
  }

  void interfaces() {
    if (!m_.interfaces.empty()) os_ << "*----- SLIDING INTERFACES\n";
    for (const SlidingInterface& si : m_.interfaces)
      os_ << T("sliding interface control card")("NSS", int(si.slave.size()))("NMS", int(si.master.size()))
                 ("type", si.type)("static friction", si.fs)("dynamic friction", si.fd)("decay coefficient", si.decay)
                 ("stiffness method", si.stiffness_method)("one-pass flag", si.symmetric || si.type == 4 ? 0 : 1)
                 ("penalty scale factor", si.penalty_scale).str() << "\n";
    for (const SlidingInterface& si : m_.interfaces) {
      if (si.stiffness_method == 2) note("sliding interface: LS-DYNA's soft constraint (SOFT 1) has no fixed-format value: written as stiffness method 2");
      if (si.penopt != 2) note("sliding interface: PENOPT " + std::to_string(si.penopt) + " has no fixed-format field (the fixed format takes the segment's stiffness)");
      if (si.type == 3 && si.shell_thickness != 0 && m_.num_shells() > 0)
        note("sliding interface: shell thickness offsets (SHLTHK " + std::to_string(si.shell_thickness) + ") have no fixed-format field (the fixed format's interfaces meet shells at their mid-surface)");
    }
    for (const SlidingInterface& si : m_.interfaces)
      for (const auto* segs : {&si.slave, &si.master})
        for (std::size_t s = 0; s < segs->size(); ++s) {
          TableLine c = T("segment card", "segment");
          c("segment number", int(s) + 1);
          for (int j = 0; j < 4; ++j) c("node n" + std::to_string(j + 1), (*segs)[s][std::size_t(j)] + 1);
          os_ << c.str() << "\n";
        }
  }

  void base_accelerations() {
    if (base_[0] >= 0 || base_[1] >= 0 || base_[2] >= 0) os_ << "*----- BASE ACCELERATIONS: load curve, scale\n";
    for (int a = 0; a < 3; ++a) {
      if (base_[std::size_t(a)] < 0) continue;
      const BodyLoad& b = m_.body_loads[std::size_t(base_[std::size_t(a)])];
      os_ << T("base acceleration card", "base acceleration")("load curve", b.curve + 1)("scale factor", b.scale).str() << "\n";
    }
  }
};

}  // namespace

void write_keyword_deck(std::ostream& os, const Model& m, std::vector<std::string>* notes) {
  KeywordWriter(os, m, notes).write();
}

void write_fixed_deck(std::ostream& os, const Model& m, std::vector<std::string>* notes) {
  FixedWriter(os, m, notes).write();
}

bool write_deck_file(const std::string& path, const Model& m, bool keyword, Diagnostics& diag,
                     std::vector<std::string>* notes) {
  std::ostringstream text;
  if (keyword) write_keyword_deck(text, m, notes);
  else write_fixed_deck(text, m, notes);
  std::ofstream out(path, std::ios::binary);
  out << text.str();
  out.close();
  if (!out) {
    Location loc;
    loc.file = path;
    diag.add(3004, loc, std::strerror(errno));
    return false;
  }
  return true;
}

int write_converted_decks(const Model& m, const std::string& keyword_path, const std::string& fixed_path,
                          std::ostream& log) {
  Diagnostics diag;
  for (int k = 0; k < 2; ++k) {
    const std::string& path = k == 0 ? keyword_path : fixed_path;
    if (path.empty()) continue;
    if (k == 1 && m.num_shells() > 0) {  // what the fixed-format shell cards cannot hold
      bool omega = false;
      for (const auto& w : m.init_omega) omega = omega || w[0] != 0 || w[1] != 0 || w[2] != 0;
      if (omega || m.shell_rotary_scale != 1.0) {
        log << " error: the fixed-format deck " << path << " cannot hold this model (not written): "
            << (omega ? "initial rotational velocities of shell nodes" : "a rotary inertia scale (*CONTROL_SHELL ROTASCL)")
            << " (no fixed-format field; write a keyword deck)\n";
        return exit_code::input_error;
      }
    }
    if (k == 1 && !m.beam_orientation.empty()) {  // DYNA3D's beam card holds an orientation node only
      log << " error: the fixed-format deck " << path << " cannot hold this model (not written): beam orientation "
          << "vectors (*ELEMENT_BEAM_ORIENTATION; no fixed-format field: give orientation nodes N3, or write a keyword deck)\n";
      return exit_code::input_error;
    }
    if (k == 1)
      for (std::size_t j = 0; j < m.materials.size(); ++j)
        if (m.materials[j].beam && m.materials[j].beam_section.elform != 1) {
          log << " error: the fixed-format deck " << path << " cannot hold this model (not written): material " << j + 1
              << " is a resultant beam or a truss (ELFORM 2/3: DYNA3D's beam cards hold Hughes-Liu beams; write a keyword deck)\n";
          return exit_code::input_error;
        }
    if (k == 1)  // beam contact nodes: the fixed format's interfaces hold segments only
      for (std::size_t j = 0; j < m.interfaces.size(); ++j)
        if (!m.interfaces[j].slave_nodes.empty() || !m.interfaces[j].master_nodes.empty()) {
          log << " error: the fixed-format deck " << path << " cannot hold this model (not written): sliding interface "
              << j + 1 << " has beam nodes (contact nodes without segments: no fixed-format card; write a keyword deck)\n";
          return exit_code::input_error;
        }
    if (k == 1)  // eroding contact has no fixed-format card (its sides hold interior faces)
      for (std::size_t j = 0; j < m.interfaces.size(); ++j)
        if (m.interfaces[j].eroding) {
          log << " error: the fixed-format deck " << path << " cannot hold this model (not written): sliding interface "
              << j + 1 << " is an eroding contact (*CONTACT_ERODING_*: no fixed-format card; write a keyword deck)\n";
          return exit_code::input_error;
        }
    if (k == 1)  // segment-based contact (SOFT 2) has no fixed-format stiffness method
      for (std::size_t j = 0; j < m.interfaces.size(); ++j)
        if (m.interfaces[j].stiffness_method == 3) {
          log << " error: the fixed-format deck " << path << " cannot hold this model (not written): sliding interface "
              << j + 1 << " is a segment-based contact (SOFT 2: no fixed-format stiffness method; write a keyword deck)\n";
          return exit_code::input_error;
        }
    if (k == 1)  // a cylinder wall has no fixed-format card
      for (std::size_t j = 0; j < m.walls.size(); ++j)
        if (m.walls[j].cylinder()) {
          log << " error: the fixed-format deck " << path << " cannot hold this model (not written): rigid wall " << j + 1
              << " is a cylinder (*RIGIDWALL_GEOMETRIC_CYLINDER: no fixed-format card; write a keyword deck)\n";
          return exit_code::input_error;
        }
    if (k == 1) {  // *MAT_ADD_EROSION has no fixed-format card
      for (std::size_t j = 0; j < m.materials.size(); ++j)
        if (m.materials[j].erosion.active) {
          log << " error: the fixed-format deck " << path << " cannot hold this model (not written): material "
              << j + 1 << " has *MAT_ADD_EROSION criteria (no fixed-format card; write a keyword deck)\n";
          return exit_code::input_error;
        }
    }
    std::vector<std::string> notes;
    if (!write_deck_file(path, m, k == 0, diag, &notes)) {
      diag.print(log);
      return exit_code::file_error;
    }
    // an integer (a count, an id) that does not fit its columns makes the deck unreadable: the
    // file is removed and the conversion fails
    bool unusable = false;
    for (const auto& n : notes) unusable = unusable || n.find(" does not fit columns ") != std::string::npos;
    if (unusable) {
      std::remove(path.c_str());
      log << " error: the " << (k == 0 ? "keyword" : "fixed-format") << " deck " << path
          << " cannot hold this model (not written):\n";
      for (const auto& n : notes)
        if (n.find(" does not fit columns ") != std::string::npos) log << "   " << n << "\n";
      return exit_code::input_error;
    }
    log << " wrote " << (k == 0 ? "keyword" : "fixed-format") << " deck " << path << "\n";
    for (const auto& n : notes) log << "   note: " << n << "\n";
  }
  return exit_code::ok;
}

namespace {

// The differences found so far (at most max_lines), "what: a vs b".
struct Differences {
  std::vector<std::string>& out;
  int max_lines;
  void diff(const std::string& what, const std::string& va, const std::string& vb) {
    if (int(out.size()) < max_lines) out.push_back(what + ": " + va + " vs " + vb);
  }
  void D(const std::string& what, double x, double y) {
    if (!(x == y) && !(std::isnan(x) && std::isnan(y))) diff(what, shortest(x), shortest(y));
  }
  void N(const std::string& what, long long x, long long y) {
    if (x != y) diff(what, std::to_string(x), std::to_string(y));
  }
};

// The title and the control data.
void control_differences(const Model& a, const Model& b, Differences& d) {
  if (a.title != b.title) d.diff("title", "\"" + a.title + "\"", "\"" + b.title + "\"");
  const ControlData &ka = a.control, &kb = b.control;
  d.N("NMMAT", ka.nmmat, kb.nmmat);
  d.N("NUMNP", ka.numnp, kb.numnp);
  d.N("NUMELH", ka.numelh, kb.numelh);
  d.N("interface segments out", ka.interface_segments_out, kb.interface_segments_out);
  d.D("interface output interval", ka.interface_out_interval, kb.interface_out_interval);
  d.N("node time-history blocks", ka.node_th_blocks, kb.node_th_blocks);
  d.N("solid time-history blocks", ka.solid_th_blocks, kb.solid_th_blocks);
  d.N("report interval", ka.report_interval, kb.report_interval);
  d.N("reaction print flag", ka.reaction_print_flag, kb.reaction_print_flag);
  d.N("NUMLC", ka.numlc, kb.numlc);
  d.N("stonewalls", ka.num_walls, kb.num_walls);
  d.N("initial-velocity cards", ka.num_init_velocity_cards, kb.num_init_velocity_cards);
  d.N("sliding interfaces", ka.num_interfaces, kb.num_interfaces);
  d.D("end time", ka.end_time, kb.end_time);
  d.N("end cycle", ka.end_cycle, kb.end_cycle);
  d.D("time-history interval", ka.th_interval, kb.th_interval);
  d.D("plot interval", ka.plot_interval, kb.plot_interval);
  d.N("restart dump cycles", ka.restart_dump_cycles, kb.restart_dump_cycles);
  d.N("running restart cycles", ka.running_restart_cycles, kb.running_restart_cycles);
  d.D("initial time step", ka.initial_dt, kb.initial_dt);
  d.D("penalty scale", ka.penalty_scale, kb.penalty_scale);
  d.N("viscosity flag", ka.viscosity_flag, kb.viscosity_flag);
  d.D("TSSF", ka.tssf, kb.tssf);
  d.D("mass-scaling step DT2MS", ka.mass_scaling_dt, kb.mass_scaling_dt);
  d.N("MS1ST", ka.mass_scaling_first_only ? 1 : 0, kb.mass_scaling_first_only ? 1 : 0);
  d.D("ENDMAS", ka.end_mass_percent, kb.end_mass_percent);
  d.N("ERODE", ka.erode_small_steps ? 1 : 0, kb.erode_small_steps ? 1 : 0);
  d.D("minimum step factor", ka.min_step_factor, kb.min_step_factor);
}

// The materials: number, type, density, hourglass and bulk viscosity, EOS, erosion, parameters.
void material_differences(const Model& a, const Model& b, Differences& d) {
  d.N("materials", long(a.materials.size()), long(b.materials.size()));
  for (std::size_t k = 0; k < std::min(a.materials.size(), b.materials.size()); ++k) {
    const MaterialData &x = a.materials[k], &y = b.materials[k];
    std::string w = "material " + std::to_string(k + 1) + " ";
    d.N(w + "number", x.number, y.number);
    d.N(w + "type", x.type, y.type);
    d.D(w + "rho", x.rho, y.rho);
    d.N(w + "hourglass type", x.hourglass_type, y.hourglass_type);
    d.D(w + "hourglass coefficient", x.hourglass_coef, y.hourglass_coef);
    d.N(w + "bulk type", x.bulk_type, y.bulk_type);
    d.D(w + "Q1", x.q1, y.q1);
    d.D(w + "Q2", x.q2, y.q2);
    if (x.title != y.title) d.diff(w + "title", x.title, y.title);
    d.N(w + "erosion", x.erosion.active ? 1 : 0, y.erosion.active ? 1 : 0);
    d.N(w + "EOS form", x.eos.form, y.eos.form);
    for (std::size_t j = 0; j < x.eos.c.size(); ++j) d.D(w + "EOS constant " + std::to_string(j), x.eos.c[j], y.eos.c[j]);
    d.D(w + "EOS E0", x.eos.e0, y.eos.e0);
    d.D(w + "EOS V0", x.eos.v0, y.eos.v0);
    d.D(w + "erosion EXCL", x.erosion.excl, y.erosion.excl);
    d.D(w + "erosion MXPRES", x.erosion.mxpres, y.erosion.mxpres);
    d.D(w + "erosion MNPRES", x.erosion.mnpres, y.erosion.mnpres);
    d.D(w + "erosion SIGP1", x.erosion.sigp1, y.erosion.sigp1);
    d.D(w + "erosion SIGVM", x.erosion.sigvm, y.erosion.sigvm);
    d.D(w + "erosion VOLEPS", x.erosion.voleps, y.erosion.voleps);
    d.D(w + "erosion FAILTM", x.erosion.failtm, y.erosion.failtm);
    d.D(w + "erosion MNEPS", x.erosion.mneps, y.erosion.mneps);
    d.D(w + "erosion EFFEPS", x.erosion.effeps, y.erosion.effeps);
    d.D(w + "erosion MXEPS", x.erosion.mxeps, y.erosion.mxeps);
    d.D(w + "erosion EPSSH", x.erosion.epssh, y.erosion.epssh);
    d.N(w + "erosion NCS", x.erosion.ncs, y.erosion.ncs);
    d.D(w + "E", x.E, y.E);
    d.D(w + "nu", x.nu, y.nu);
    d.D(w + "sigma_y", x.sigma_y, y.sigma_y);
    d.D(w + "E_tan", x.E_tan, y.E_tan);
    d.D(w + "beta", x.beta, y.beta);
    d.N(w + "initially elastic", x.initially_elastic, y.initially_elastic);
    d.D(w + "strain-rate C", x.rate_c, y.rate_c);
    d.D(w + "strain-rate P", x.rate_p, y.rate_p);
    d.D(w + "failure strain", x.fail_strain, y.fail_strain);
    for (std::size_t j = 0; j < std::max(x.par.size(), y.par.size()); ++j)
      d.D(w + "parameter " + std::to_string(j), j < x.par.size() ? x.par[j] : 0.0, j < y.par.size() ? y.par[j] : 0.0);
  }
}

// The nodes, solids, shells and beams (connectivity, materials, sizes, ids).
void mesh_differences(const Model& a, const Model& b, Differences& d) {
  d.N("nodes", a.num_nodes(), b.num_nodes());
  for (int n = 0; n < std::min(a.num_nodes(), b.num_nodes()); ++n) {
    std::string w = "node " + std::to_string(n + 1) + " ";
    d.D(w + "x", a.x[std::size_t(n)], b.x[std::size_t(n)]);
    d.D(w + "y", a.y[std::size_t(n)], b.y[std::size_t(n)]);
    d.D(w + "z", a.z[std::size_t(n)], b.z[std::size_t(n)]);
    d.N(w + "bc", a.bc[std::size_t(n)], b.bc[std::size_t(n)]);
  }
  if (a.node_user_id != b.node_user_id) d.diff("node ids", std::to_string(a.node_user_id.size()), std::to_string(b.node_user_id.size()));
  if (a.hex_user_id != b.hex_user_id) d.diff("element ids", std::to_string(a.hex_user_id.size()), std::to_string(b.hex_user_id.size()));
  d.N("solids", a.num_hexes(), b.num_hexes());
  for (int e = 0; e < std::min(a.num_hexes(), b.num_hexes()); ++e) {
    std::string w = "solid " + std::to_string(e + 1) + " ";
    d.N(w + "material", a.hex_material[std::size_t(e)], b.hex_material[std::size_t(e)]);
    for (int j = 0; j < 8; ++j)
      d.N(w + "node " + std::to_string(j + 1), a.hex_nodes[std::size_t(e)][std::size_t(j)], b.hex_nodes[std::size_t(e)][std::size_t(j)]);
  }
  d.N("shells", a.num_shells(), b.num_shells());
  for (int e = 0; e < std::min(a.num_shells(), b.num_shells()); ++e) {
    std::string w = "shell " + std::to_string(e + 1) + " ";
    d.N(w + "material", a.shell_material[std::size_t(e)], b.shell_material[std::size_t(e)]);
    for (int j = 0; j < 4; ++j) {
      d.N(w + "node " + std::to_string(j + 1), a.shell_nodes[std::size_t(e)][std::size_t(j)], b.shell_nodes[std::size_t(e)][std::size_t(j)]);
      d.D(w + "thickness " + std::to_string(j + 1), a.shell_thickness[std::size_t(e)][std::size_t(j)], b.shell_thickness[std::size_t(e)][std::size_t(j)]);
    }
  }
  if (a.shell_user_id != b.shell_user_id) d.diff("shell ids", std::to_string(a.shell_user_id.size()), std::to_string(b.shell_user_id.size()));
  d.N("beams", a.num_beams(), b.num_beams());
  for (int e = 0; e < std::min(a.num_beams(), b.num_beams()); ++e) {
    std::string w = "beam " + std::to_string(e + 1) + " ";
    d.N(w + "material", a.beam_material[std::size_t(e)], b.beam_material[std::size_t(e)]);
    for (int j = 0; j < 3; ++j)
      d.N(w + "node " + std::to_string(j + 1), a.beam_nodes[std::size_t(e)][std::size_t(j)], b.beam_nodes[std::size_t(e)][std::size_t(j)]);
    for (int j = 0; j < 4; ++j)
      d.D(w + "size " + std::to_string(j + 1), a.beam_thickness[std::size_t(e)][std::size_t(j)], b.beam_thickness[std::size_t(e)][std::size_t(j)]);
    const double* va = beam_orientation_vector(a, e);
    const double* vb = beam_orientation_vector(b, e);
    for (int j = 0; j < 3; ++j) d.D(w + "orientation vector " + "xyz"[j], va ? va[j] : 0.0, vb ? vb[j] : 0.0);
  }
  if (a.beam_user_id != b.beam_user_id) d.diff("beam ids", std::to_string(a.beam_user_id.size()), std::to_string(b.beam_user_id.size()));
}

// The sections of shell and beam materials, rotational constraints and velocities, time-history
// blocks, load curves, walls, initial velocities, sliding interfaces, force transducers.
void section_and_output_differences(const Model& a, const Model& b, Differences& d) {
  for (std::size_t k = 0; k < std::min(a.materials.size(), b.materials.size()); ++k) {
    const auto &x = a.materials[k], &y = b.materials[k];
    std::string w = "material " + std::to_string(k + 1) + " ";
    d.N(w + "shell", x.shell, y.shell);
    d.N(w + "shell ELFORM", x.shell_section.elform, y.shell_section.elform);
    d.N(w + "NIP", x.shell_section.nip, y.shell_section.nip);
    d.D(w + "SHRF", x.shell_section.shrf, y.shell_section.shrf);
    for (int j = 0; j < 4; ++j) d.D(w + "section T" + std::to_string(j + 1), x.shell_section.t[std::size_t(j)], y.shell_section.t[std::size_t(j)]);
    d.N(w + "beam", x.beam, y.beam);
    const BeamSectionData &bx = x.beam_section, &by = y.beam_section;
    d.N(w + "ELFORM", bx.elform, by.elform);
    d.N(w + "QR", bx.qr, by.qr);
    d.N(w + "CST", int(bx.cst), int(by.cst));
    d.D(w + "beam SHRF", bx.shrf, by.shrf);
    d.D(w + "TS1", bx.ts1, by.ts1);
    d.D(w + "TS2", bx.ts2, by.ts2);
    d.D(w + "TT1", bx.tt1, by.tt1);
    d.D(w + "TT2", bx.tt2, by.tt2);
    d.D(w + "A", bx.area, by.area);
    d.D(w + "ISS", bx.iss, by.iss);
    d.D(w + "ITT", bx.itt, by.itt);
    d.D(w + "J", bx.jt, by.jt);
    d.D(w + "SA", bx.sa, by.sa);
  }
  auto nonzero = [](const auto& v) {
    for (const auto& x : v)
      if (x != std::decay_t<decltype(x)>{}) return true;
    return false;
  };
  if ((nonzero(a.rot_bc) || nonzero(b.rot_bc)) && a.rot_bc != b.rot_bc) d.diff("rotational constraints", "", "other");
  if ((nonzero(a.init_omega) || nonzero(b.init_omega)) && a.init_omega != b.init_omega) d.diff("initial rotational velocities", "", "other");
  d.D("rotary inertia scale", a.shell_rotary_scale, b.shell_rotary_scale);
  auto blocks = [&](const char* w, const std::vector<std::array<int, 2>>& x, const std::vector<std::array<int, 2>>& y) {
    if (x != y) d.diff(w, std::to_string(x.size()) + " block(s)", std::to_string(y.size()) + " block(s), or other ranges");
  };
  blocks("node time-history blocks", a.node_th_blocks, b.node_th_blocks);
  blocks("solid time-history blocks", a.solid_th_blocks, b.solid_th_blocks);
  blocks("shell time-history blocks", a.shell_th_blocks, b.shell_th_blocks);
  blocks("beam time-history blocks", a.beam_th_blocks, b.beam_th_blocks);
  d.N("load curves", long(a.load_curves.size()), long(b.load_curves.size()));
  for (std::size_t c = 0; c < std::min(a.load_curves.size(), b.load_curves.size()); ++c) {
    const LoadCurve &x = a.load_curves[c], &y = b.load_curves[c];
    d.N("load curve " + std::to_string(c + 1) + " number", x.number, y.number);
    if (x.t != y.t || x.f != y.f) d.diff("load curve " + std::to_string(c + 1), "points", "other points");
  }
  d.N("walls", long(a.walls.size()), long(b.walls.size()));
  for (std::size_t w = 0; w < std::min(a.walls.size(), b.walls.size()); ++w) {
    const StoneWall &x = a.walls[w], &y = b.walls[w];
    std::string s = "wall " + std::to_string(w + 1) + " ";
    for (int q = 0; q < 3; ++q) {
      d.D(s + "tail", x.tail[std::size_t(q)], y.tail[std::size_t(q)]);
      d.D(s + "head", x.head[std::size_t(q)], y.head[std::size_t(q)]);
    }
    d.D(s + "friction", x.friction, y.friction);
    d.D(s + "mass", x.mass, y.mass);
    d.D(s + "V0", x.v0, y.v0);
    d.D(s + "cylinder radius", x.radius, y.radius);
    d.D(s + "cylinder length", x.length, y.length);
    if (x.nodes != y.nodes) d.diff(s + "nodes", std::to_string(x.nodes.size()), std::to_string(y.nodes.size()));
  }
  d.N("initial velocities", long(a.init_velocities.size()), long(b.init_velocities.size()));
  for (std::size_t v = 0; v < std::min(a.init_velocities.size(), b.init_velocities.size()); ++v) {
    const InitialVelocity &x = a.init_velocities[v], &y = b.init_velocities[v];
    std::string s = "initial velocity " + std::to_string(v + 1) + " ";
    d.N(s + "first", x.first, y.first);
    if (x.first != 0) {
      d.N(s + "last", x.last, y.last);
      d.N(s + "increment", x.increment, y.increment);
    }
    for (int q = 0; q < 3; ++q) d.D(s + "v", x.v[std::size_t(q)], y.v[std::size_t(q)]);
  }
  d.N("sliding interfaces", long(a.interfaces.size()), long(b.interfaces.size()));
  for (std::size_t i = 0; i < std::min(a.interfaces.size(), b.interfaces.size()); ++i) {
    const SlidingInterface &x = a.interfaces[i], &y = b.interfaces[i];
    std::string s = "interface " + std::to_string(i + 1) + " ";
    d.N(s + "type", x.type, y.type);
    d.D(s + "fs", x.fs, y.fs);
    d.D(s + "fd", x.fd, y.fd);
    d.D(s + "decay", x.decay, y.decay);
    d.D(s + "penalty scale", x.penalty_scale, y.penalty_scale);
    d.N(s + "stiffness method", x.stiffness_method, y.stiffness_method);
    d.D(s + "sofscl", x.sofscl, y.sofscl);
    d.N(s + "penopt", x.penopt, y.penopt);
    d.N(s + "symmetric", x.symmetric, y.symmetric);
    d.N(s + "shell thickness", x.shell_thickness, y.shell_thickness);
    d.N(s + "eroding", x.eroding, y.eroding);
    if (x.slave != y.slave) d.diff(s + "slave segments", std::to_string(x.slave.size()), std::to_string(y.slave.size()));
    if (x.master != y.master) d.diff(s + "master segments", std::to_string(x.master.size()), std::to_string(y.master.size()));
    if (x.slave_nodes != y.slave_nodes) d.diff(s + "slave beam nodes", std::to_string(x.slave_nodes.size()), std::to_string(y.slave_nodes.size()));
    if (x.master_nodes != y.master_nodes) d.diff(s + "master beam nodes", std::to_string(x.master_nodes.size()), std::to_string(y.master_nodes.size()));
    d.N(s + "intfor slave side", x.intfor_slave, y.intfor_slave);
    d.N(s + "intfor master side", x.intfor_master, y.intfor_master);
  }
  d.N("force transducers", long(a.force_transducers.size()), long(b.force_transducers.size()));
  for (std::size_t i = 0; i < std::min(a.force_transducers.size(), b.force_transducers.size()); ++i) {
    const ForceTransducer &x = a.force_transducers[i], &y = b.force_transducers[i];
    std::string s = "force transducer " + std::to_string(i + 1) + " ";
    if (x.a_nodes != y.a_nodes) d.diff(s + "side A nodes", std::to_string(x.a_nodes.size()), std::to_string(y.a_nodes.size()));
    if (x.b_nodes != y.b_nodes || x.has_b != y.has_b) d.diff(s + "side B nodes", std::to_string(x.b_nodes.size()), std::to_string(y.b_nodes.size()));
  }
  d.D("interface-force database interval", a.control.intfor_interval, b.control.intfor_interval);
}

// Loads and prescribed motions: what acts (curve values, directions, effective scales), damping.
void load_differences(const Model& a, const Model& b, Differences& d) {
  // loads and prescribed motions: what acts (curve values, directions, effective scales)
  auto curve_differs = [&](const std::string& w, int ca, int cb) {
    if (ca < 0 || cb < 0) {  // no curve (a constant) on one side or both
      if ((ca < 0) != (cb < 0)) d.diff(w + "load curve", ca < 0 ? "none" : "a curve", cb < 0 ? "none" : "a curve");
      return;
    }
    const LoadCurve &x = a.load_curves[std::size_t(ca)], &y = b.load_curves[std::size_t(cb)];
    if (x.t != y.t || x.f != y.f) d.diff(w + "load curve", std::to_string(x.number), std::to_string(y.number));
  };
  auto dir_differs = [&](const std::string& w, const std::array<double, 3>& x, const std::array<double, 3>& y) {
    for (int q = 0; q < 3; ++q) d.D(w + "direction " + "xyz"[q], x[std::size_t(q)], y[std::size_t(q)]);
  };
  d.N("nodal loads", long(a.nodal_loads.size()), long(b.nodal_loads.size()));
  for (std::size_t j = 0; j < std::min(a.nodal_loads.size(), b.nodal_loads.size()); ++j) {
    const NodalLoad &x = a.nodal_loads[j], &y = b.nodal_loads[j];
    const std::string w = "nodal load " + std::to_string(j + 1) + " ";
    d.N(w + "node", x.node, y.node);
    dir_differs(w, x.dir, y.dir);
    curve_differs(w, x.curve, y.curve);
    d.D(w + "scale", x.scale, y.scale);
  }
  d.N("rigid-body loads", long(a.rigid_body_loads.size()), long(b.rigid_body_loads.size()));
  d.N("pressure loads", long(a.pressure_loads.size()), long(b.pressure_loads.size()));
  for (std::size_t j = 0; j < std::min(a.pressure_loads.size(), b.pressure_loads.size()); ++j) {
    const PressureLoad &x = a.pressure_loads[j], &y = b.pressure_loads[j];
    const std::string w = "pressure load " + std::to_string(j + 1) + " ";
    if (x.nodes != y.nodes) d.diff(w + "nodes", "", "");
    curve_differs(w, x.curve, y.curve);
    for (int q = 0; q < 4; ++q) d.D(w + "scale at node " + std::to_string(q + 1), x.scale * x.factor[std::size_t(q)], y.scale * y.factor[std::size_t(q)]);
    d.D(w + "birth", x.birth, y.birth);
    d.D(w + "death", x.death, y.death);
  }
  d.N("body loads", long(a.body_loads.size()), long(b.body_loads.size()));
  for (std::size_t j = 0; j < std::min(a.body_loads.size(), b.body_loads.size()); ++j) {
    const BodyLoad &x = a.body_loads[j], &y = b.body_loads[j];
    const std::string w = "body load " + std::to_string(j + 1) + " ";
    dir_differs(w, x.dir, y.dir);
    curve_differs(w, x.curve, y.curve);
    d.D(w + "scale", x.scale, y.scale);
  }
  d.N("global damping", a.damping.active ? 1 : 0, b.damping.active ? 1 : 0);
  if (a.damping.active && b.damping.active) {
    curve_differs("global damping ", a.damping.curve, b.damping.curve);
    d.D("global damping D", a.damping.d, b.damping.d);
    for (int q = 0; q < 3; ++q) d.D("global damping factor " + std::to_string(q + 1), a.damping.factor[std::size_t(q)], b.damping.factor[std::size_t(q)]);
  }
  if (a.body_load_materials != b.body_load_materials) d.diff("body-load materials", std::to_string(a.body_load_materials.size()), std::to_string(b.body_load_materials.size()));
  d.N("prescribed motions", long(a.prescribed_motions.size()), long(b.prescribed_motions.size()));
  for (std::size_t j = 0; j < std::min(a.prescribed_motions.size(), b.prescribed_motions.size()); ++j) {
    const PrescribedMotion &x = a.prescribed_motions[j], &y = b.prescribed_motions[j];
    const std::string w = "prescribed motion " + std::to_string(j + 1) + " ";
    d.N(w + "node", x.node, y.node);
    d.N(w + "rigid body", x.rigid_material, y.rigid_material);
    dir_differs(w, x.dir, y.dir);
    d.N(w + "kind", int(x.kind), int(y.kind));
    d.N(w + "rotation", x.rotation ? 1 : 0, y.rotation ? 1 : 0);
    d.N(w + "normal held", x.hold_normal ? 1 : 0, y.hold_normal ? 1 : 0);
    d.N(w + "turning about an axis", x.orbit ? 1 : 0, y.orbit ? 1 : 0);
    d.N(w + "distance from the axis free", x.radial_free ? 1 : 0, y.radial_free ? 1 : 0);
    for (std::size_t a = 0; a < 3; ++a) d.D(w + "axis point " + "xyz"[a], x.center[a], y.center[a]);
    curve_differs(w, x.curve, y.curve);
    d.D(w + "scale", x.scale, y.scale);
    d.D(w + "birth", x.birth, y.birth);
    d.D(w + "death", x.death, y.death);
  }
}

}  // namespace

std::vector<std::string> model_differences(const Model& a, const Model& b, int max_lines) {
  std::vector<std::string> out;
  Differences d{out, max_lines};
  control_differences(a, b, d);
  material_differences(a, b, d);
  mesh_differences(a, b, d);
  section_and_output_differences(a, b, d);
  load_differences(a, b, d);
  return out;
}

}  // namespace impact3d
