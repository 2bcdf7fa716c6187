// The table of material types (material_types.h) and what every type shares: parameter
// defaults, the per-parameter checks, the kernel constants, the printed echo.

#include "impact3d/material/material_types.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>

#include "impact3d/material/eos.h"

namespace impact3d {

// One line per type (each defined in impact3d/material/types/mat_*.cpp).
const MaterialType& mat_elastic_type();
const MaterialType& mat_plastic_kinematic_type();
const MaterialType& mat_johnson_cook_type();
const MaterialType& mat_null_type();
const MaterialType& mat_elastic_plastic_hydro_type();
const MaterialType& mat_power_law_type();
const MaterialType& mat_simplified_johnson_cook_type();
const MaterialType& mat_piecewise_linear_type();
const MaterialType& mat_rigid_type();
const MaterialType& mat_mooney_rivlin_type();
const MaterialType& mat_modified_johnson_cook_type();
const MaterialType& mat_spotweld_type();

std::span<const MaterialType* const> material_types() {
  static const MaterialType* const table[] = {  // in increasing number
      &mat_elastic_type(),
      &mat_plastic_kinematic_type(),
      &mat_null_type(),
      &mat_elastic_plastic_hydro_type(),
      &mat_johnson_cook_type(),
      &mat_power_law_type(),
      &mat_rigid_type(),
      &mat_piecewise_linear_type(),
      &mat_mooney_rivlin_type(),
      &mat_simplified_johnson_cook_type(),
      &mat_spotweld_type(),
      &mat_modified_johnson_cook_type(),
  };
  return table;
}

const MaterialType* find_material_type(int number) {
  for (const MaterialType* t : material_types())
    if (t->number == number) return t;
  return nullptr;
}

const MaterialType* find_material_type_by_keyword(std::string_view keyword) {
  for (const MaterialType* t : material_types())
    for (const char* k : t->keywords)
      if (keyword == k) return t;
  return nullptr;
}

const MaterialParam* find_param(const MaterialType& t, std::string_view key) {
  for (const MaterialParam& p : t.params)
    if (key == p.key) return &p;
  return nullptr;
}

void check_flow_table(const MaterialData& md, const MaterialType& t, const ParamReport& report, int n, int eps1, int es1,
                      const char* const eps_names[], const char* const es_names[]) {
  for (int i = 0; i < n; ++i) {
    const double e = par(md, eps1 + i), s = par(md, es1 + i);
    if (e < 0 || (i > 0 && !(e > par(md, eps1 + i - 1))))
      report(*find_param(t, eps_names[i]), 1003, "plastic strains of the table must start at 0 or more and increase");
    if (s < 0 || (i > 0 && s < par(md, es1 + i - 1)))
      report(*find_param(t, es_names[i]), 1003, "yield stresses of the table must not be negative nor decrease (no softening)");
  }
}

const MaterialType& material_type(int number) {
  const MaterialType* t = find_material_type(number);
  if (!t) throw std::logic_error("no material type " + std::to_string(number));
  return *t;
}

std::string supported_material_types() {
  std::string s;
  for (const MaterialType* t : material_types())
    s += (s.empty() ? "" : ", ") + std::to_string(t->number) + " " + t->name;
  return s;
}

std::string supported_material_keywords() {
  std::string s;
  for (const MaterialType* t : material_types()) s += (s.empty() ? "*" : ", *") + std::string(t->keywords.front());
  return s;
}

std::string keywords_of_types(const std::vector<int>& types) {
  std::string out;
  for (int type : types) {
    if (!out.empty()) out += ", ";
    out += std::string("*") + material_type(type).keywords[0];
  }
  return out;
}

std::string numbers_of_types(const std::vector<int>& types) {
  std::string out;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (i > 0) out += i + 1 == types.size() ? " and " : ", ";
    out += std::to_string(types[i]);
  }
  return out;
}

std::string eos_material_types() {
  std::string s;
  for (const MaterialType* t : material_types())
    if (t->accepts_eos) s += (s.empty() ? "" : ", ") + std::to_string(t->number) + " " + t->name;
  return s;
}

double& param_value(MaterialData& md, const MaterialParam& p) {
  if (p.field) return md.*(p.field);
  if (md.par.size() <= std::size_t(p.index)) md.par.resize(std::size_t(p.index) + 1, 0.0);
  return md.par[std::size_t(p.index)];
}

double param_value(const MaterialData& md, const MaterialParam& p) {
  if (p.field) return md.*(p.field);
  return std::size_t(p.index) < md.par.size() ? md.par[std::size_t(p.index)] : 0.0;
}

void set_param_defaults(MaterialData& md, const MaterialType& t) {
  md.par.assign(std::size_t(t.num_par), 0.0);
  for (const MaterialParam& p : t.params) param_value(md, p) = p.def;
}

void check_material_params(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  for (const MaterialParam& p : t.params) {
    const double v = param_value(md, p);
    bool ok = true;
    switch (p.check) {
      case ParamCheck::none: break;
      case ParamCheck::positive: ok = v > 0; break;
      case ParamCheck::non_negative: ok = v >= 0; break;
      case ParamCheck::fraction: ok = v >= 0 && v <= 1; break;
      case ParamCheck::poisson: ok = v >= 0 && v < 0.5; break;
      case ParamCheck::below_E: ok = v >= 0 && v < md.E; break;
      case ParamCheck::flag01: ok = v == 0 || v == 1; break;
      case ParamCheck::integer:
      case ParamCheck::curve: ok = v >= 0 && v == std::floor(v) && v < 1e9; break;
      case ParamCheck::unsupported:
        if (v != 0) report(p, 1102, p.detail);
        continue;
      case ParamCheck::ignored:
        if (v != 0) report(p, 2006, p.detail);
        continue;
    }
    if (!ok) report(p, p.msg, p.detail);
  }
  if (t.check) t.check(md, t, report);
}

MaterialConstants derive_constants(const MaterialData& md, const Model& m) {
  MaterialConstants c;
  c.type = md.type;
  c.rho = md.rho;
  c.E = md.E;
  c.nu = md.nu;
  const MaterialType* t = find_material_type(md.type);
  if (t && t->derive) t->derive(md, m, c);
  derive_material_constants(c);
  if (md.eos.form != 0 && t && t->accepts_eos) {  // the pressure from the equation of state
    derive_eos_constants(md.eos, c);
    derive_eos_curve(md.eos, m, c);
    c.eos_hist = int(t->history.size());
  }
  derive_erosion_constants(md.erosion, c);
  return c;
}

void echo_line(std::ostream& os, const std::string& label, const std::string& value) {
  // "     label ...... value": the label and its dots fill 38 columns
  std::string l = label + " ";
  if (l.size() < 38) l += std::string(38 - l.size(), '.');
  os << "     " << l << " " << value << "\n";
}

std::string echo_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6e", v);
  return b;
}

void echo_material_params(std::ostream& os, const MaterialData& md, const MaterialType& t) {
  for (const MaterialParam& p : t.params) {
    if (!p.label) continue;
    const double v = param_value(md, p);
    char buf[64];
    if (p.check == ParamCheck::integer || p.check == ParamCheck::flag01 || p.check == ParamCheck::curve)
      std::snprintf(buf, sizeof buf, "%.0f", v);
    else
      std::snprintf(buf, sizeof buf, "%.6e", v);
    echo_line(os, p.label, std::string(buf) + (*p.unit ? std::string(" (") + p.unit + ")" : std::string()));
  }
  if (t.echo) t.echo(os, md);
  echo_eos(os, md.eos);
  if (md.erosion.active) {  // *MAT_ADD_EROSION: the criteria in use
    const ErosionData& e = md.erosion;
    auto used = [&](double v) { return v != e.excl && v != 0; };
    char buf[64];
    auto line = [&](const char* label, double v) {
      if (!used(v)) return;
      std::snprintf(buf, sizeof buf, "%.6e", v);
      echo_line(os, label, buf);
    };
    line("erosion: pressure above MXPRES", e.mxpres);
    line("erosion: pressure below MNPRES", e.mnpres);
    line("erosion: principal stress SIGP1", e.sigp1);
    line("erosion: von Mises stress SIGVM", e.sigvm);
    line("erosion: volumetric strain VOLEPS", e.voleps);
    line("erosion: failure time FAILTM", e.failtm);
    line("erosion: smallest principal strain MNEPS", e.mneps);
    line("erosion: effective strain EFFEPS", e.effeps);
    line("erosion: largest principal strain MXEPS", e.mxeps);
    line("erosion: shear strain EPSSH", e.epssh);
    echo_line(os, "erosion: criteria needed at once NCS", std::to_string(e.ncs));
  }
}

bool material_uses_curve(const MaterialData& md, int curve) {
  const MaterialType* t = find_material_type(md.type);
  if (!t || curve == 0) return false;
  if (eos_curve(md.eos) == curve) return true;  // an EOS energy deposition (form 6)
  for (const MaterialParam& p : t->params)
    if (p.check == ParamCheck::curve && param_value(md, p) == double(curve)) return true;
  return false;
}

int material_history_count(int type) {
  const MaterialType* t = find_material_type(type);
  return t ? int(t->history.size()) : 0;
}

int material_history_count(const MaterialData& md) {
  return material_history_count(md.type) + eos_history_count(md.eos.form);
}

}  // namespace impact3d
