// The EOS forms (eos.h): their card layouts, checks, constants and echo.

#include "impact3d/material/eos.h"

#include <cstdio>
#include <ostream>

#include "impact3d/material/material_types.h"  // echo_line

namespace impact3d {

namespace {

const EosForm& linear_polynomial() {
  static const EosForm f = {1, "linear polynomial", "EOS_LINEAR_POLYNOMIAL",
                            {{"C0", 0, 1, 0, 0, 0}, {"C1", 0, 2, 0, 1, 1}, {"C2", 0, 3, 0, 2, 2}, {"C3", 0, 4, 0, 3, 3},
                             {"C4", 0, 5, 0, 4, 4}, {"C5", 0, 6, 0, 5, 5}, {"C6", 0, 7, 0, 6, 6},
                             {"E0", 1, 0, 1, 0, 7}, {"V0", 1, 1, 1, 1, 8}}};
  return f;
}

const EosForm& gruneisen() {
  static const EosForm f = {4, "Gruneisen", "EOS_GRUNEISEN",
                            {{"C", 0, 1, 0, 0, 0}, {"S1", 0, 2, 0, 1, 1}, {"S2", 0, 3, 0, 2, 2}, {"S3", 0, 4, 0, 3, 3},
                             {"GAMMA0", 0, 5, 0, 4, 4}, {"A", 0, 6, 0, 5, 5}, {"E0", 0, 7, 0, 6, 7},
                             {"V0", 1, 0, 1, 0, 8}, {"LCID", 1, 1, -1, 0, -1, "LCID (GAMMA0 from a curve of the energy)"},
                             {"LCID", 1, 2, -1, 0, -1, "LCID (GAMMA0 from a curve of the energy)"}}};
  return f;
}

std::string f6(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6e", v);
  return b;
}

}  // namespace

std::span<const EosForm* const> eos_forms() {
  static const EosForm* const table[] = {&linear_polynomial(), &gruneisen()};
  return table;
}

const EosForm* find_eos_form(int form) {
  for (const EosForm* f : eos_forms())
    if (f->form == form) return f;
  return nullptr;
}

const EosForm* find_eos_form_by_keyword(std::string_view keyword) {
  for (const EosForm* f : eos_forms())
    if (keyword == f->keyword) return f;
  return nullptr;
}

std::string supported_eos_forms() {
  std::string s;
  for (const EosForm* f : eos_forms()) s += (s.empty() ? "" : ", ") + std::to_string(f->form) + " " + f->name;
  return s;
}

double& eos_value(EosData& e, const EosParam& p) {
  static thread_local double sink = 0;
  if (p.slot >= 0 && p.slot < 7) return e.c[std::size_t(p.slot)];
  if (p.slot == 7) return e.e0;
  if (p.slot == 8) return e.v0;
  sink = 0;
  return sink;
}

double eos_value(const EosData& e, const EosParam& p) {
  if (p.slot >= 0 && p.slot < 7) return e.c[std::size_t(p.slot)];
  if (p.slot == 7) return e.e0;
  if (p.slot == 8) return e.v0;
  return 0;
}

void check_eos(EosData& e, double rho0, const std::function<void(const EosParam& p, int msg, const std::string& detail)>& report) {
  const EosForm* f = find_eos_form(e.form);
  if (!f) return;
  auto param = [&](const char* key) -> const EosParam& {
    for (const EosParam& p : f->params)
      if (std::string_view(p.key) == key) return p;
    return f->params.front();
  };
  if (e.v0 == 0) e.v0 = 1;
  if (e.v0 != 1) report(param("V0"), 1102, "an initial relative volume V0 other than 1 (a precompressed or expanded start)");
  if (e.form == 4 && !(e.c[0] > 0)) report(param("C"), 1003, "the bulk sound speed C must be positive");
  if (e.form == 4 && e.c[1] < 1) report(param("S1"), 1003, "the slope S1 of the us-up line must be at least 1");
  // a sound speed at the initial state (the time step and the hourglass and bulk viscosity need one)
  MaterialConstants c;
  c.rho = rho0;
  derive_eos_constants(e, c);
  if (!(c.K > 0))
    report(param(e.form == 1 ? "C1" : "C"), 1003,
           "the equation of state gives no sound speed at its initial state (isentropic bulk modulus " + f6(c.K) + " <= 0)");
}

void derive_eos_constants(const EosData& e, MaterialConstants& c) {
  c.eos_form = e.form;
  c.eos = e.c;
  if (e.form == 4) c.eos[0] = c.rho * e.c[0] * e.c[0];
  double a, b, da, db;
  calc_eos_coefficients(c, 0.0, a, b, da, db);
  const double p0 = a + b * e.e0;
  c.K = da + db * e.e0 + p0 * b;
  const double G = c.G;
  c.lambda = c.K - 2.0 * G / 3.0;
  c.E = G > 0 ? 9.0 * c.K * G / (3.0 * c.K + G) : 0.0;
  c.nu = G > 0 ? (3.0 * c.K - 2.0 * G) / (2.0 * (3.0 * c.K + G)) : 0.5;
  c.c = c.rho > 0.0 && c.K + 4.0 * G / 3.0 > 0.0 ? std::sqrt((c.K + 4.0 * G / 3.0) / c.rho) : 0.0;
}

double calc_eos_initial_pressure(const MaterialConstants& c, double e0) {
  double a, b, da, db;
  calc_eos_coefficients(c, 0.0, a, b, da, db);
  const double p = a + b * e0;
  return p < c.eos_pc ? c.eos_pc : p;
}

void echo_eos(std::ostream& os, const EosData& e) {
  const EosForm* f = find_eos_form(e.form);
  if (!f) return;
  echo_line(os, "equation of state", std::string(f->name) + " (form " + std::to_string(f->form) + (e.id ? ", EOSID " + std::to_string(e.id) : std::string()) + ")");
  for (const EosParam& p : f->params)
    if (p.slot >= 0) echo_line(os, std::string("  EOS ") + p.key, f6(eos_value(e, p)));
  echo_line(os, "pressure from", "the equation of state (deviatoric stress from the material)");
}

}  // namespace impact3d
