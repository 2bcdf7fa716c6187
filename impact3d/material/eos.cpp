// The EOS forms (eos.h): their card layouts, checks, constants and echo.

#include "impact3d/material/eos.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <ostream>
#include <utility>
#include <vector>

#include "impact3d/material/material_types.h"  // echo_line

namespace impact3d {

namespace {

// The rows of a form whose values follow EOSID in order, eight fields a card (keyword card k,
// field j: the (8 k + j)-th value, EOSID the 0-th); the fixed format has the same cards without
// EOSID, so the first card's fields move one to the left.  Then the rows `refused` (slot -1).
std::vector<EosParam> in_order(std::initializer_list<std::pair<const char*, int>> keys_slots,
                               std::initializer_list<EosParam> refused = {}) {
  std::vector<EosParam> rows;
  int i = 1;
  for (const auto& [key, slot] : keys_slots) {
    const int card = i / 8, field = i % 8;
    rows.push_back({key, card, field, card, card == 0 ? field - 1 : field, slot});
    ++i;
  }
  rows.insert(rows.end(), refused);
  return rows;
}

// LS-DYNA's EOS 1: EOSID C0-C6; card 2 E0 V0.  c: C0-C6.
const EosForm& linear_polynomial() {
  static const EosForm f = {1, "linear polynomial", "EOS_LINEAR_POLYNOMIAL",
                            in_order({{"C0", 0}, {"C1", 1}, {"C2", 2}, {"C3", 3}, {"C4", 4}, {"C5", 5}, {"C6", 6},
                                      {"E0", kEosSlotE0}, {"V0", kEosSlotV0}})};
  return f;
}

// LS-DYNA's EOS 2: EOSID A B R1 R2 OMEG E0 V0 (one card).  c: A, B, R1, R2, OMEG.
const EosForm& jwl() {
  static const EosForm f = {2, "JWL", "EOS_JWL",
                            in_order({{"A", 0}, {"B", 1}, {"R1", 2}, {"R2", 3}, {"OMEG", 4}, {"E0", kEosSlotE0}, {"V0", kEosSlotV0}}),
                            {10}};
  return f;
}

// LS-DYNA's EOS 3: EOSID A1 A2 A3 B1 B2 E0 V0 (one card).  c: A1, A2, A3, B1, B2.
const EosForm& sack_tuesday() {
  static const EosForm f = {3, "Sack Tuesday", "EOS_SACK_TUESDAY",
                            in_order({{"A1", 0}, {"A2", 1}, {"A3", 2}, {"B1", 3}, {"B2", 4}, {"E0", kEosSlotE0}, {"V0", kEosSlotV0}}),
                            {10}};
  return f;
}

// LS-DYNA's EOS 4: EOSID C S1 S2 S3 GAMMA0 A E0; card 2 V0, then LCID (refused).  c: C, S1-S3,
// GAMMA0, A.
const EosForm& gruneisen() {
  static const EosForm f = {4, "Gruneisen", "EOS_GRUNEISEN",
                            in_order({{"C", 0}, {"S1", 1}, {"S2", 2}, {"S3", 3}, {"GAMMA0", 4}, {"A", 5}, {"E0", kEosSlotE0},
                                      {"V0", kEosSlotV0}},
                                     {{"LCID", 1, 1, -1, 0, -1, "LCID (GAMMA0 from a curve of the energy)"},
                                      {"LCID", 1, 2, -1, 0, -1, "LCID (GAMMA0 from a curve of the energy)"}})};
  return f;
}

// The tables of forms 8 and 9 (cards 2 on, 5 E16 fields each, two cards a table): EV1-10,
// C1-10, T1-10 in c[0..29] and, the fourth table of form 8, K1-10 from kEosTabK.
void append_table_params(EosForm& f, int tables) {
  static const char* const names[40] = {"EV1", "EV2", "EV3", "EV4", "EV5", "EV6", "EV7", "EV8", "EV9", "EV10",
                                        "C1",  "C2",  "C3",  "C4",  "C5",  "C6",  "C7",  "C8",  "C9",  "C10",
                                        "T1",  "T2",  "T3",  "T4",  "T5",  "T6",  "T7",  "T8",  "T9",  "T10",
                                        "K1",  "K2",  "K3",  "K4",  "K5",  "K6",  "K7",  "K8",  "K9",  "K10"};
  for (int j = 0; j < 10 * tables; ++j)
    f.params.push_back({names[j], 1 + j / 5, j % 5, 1 + j / 5, j % 5, j < 30 ? j : kEosTabK + j - 30});
}

// LS-DYNA's EOS 9: card 1 EOSID GAMA E0 V0; cards 2-7 (5 E16 each) EV1-5, EV6-10, C1-5, C6-10,
// T1-5, T6-10.  c: EV1-10 (0-9), C1-10 (10-19), T1-10 (20-29), GAMMA (30).
const EosForm& tabulated() {
  static const EosForm f = [] {
    EosForm f{.form = 9, .name = "tabulated", .keyword = "EOS_TABULATED",
              .params = {{"GAMA", 0, 1, 0, 0, 30}, {"E0", 0, 2, 0, 1, kEosSlotE0}, {"V0", 0, 3, 0, 2, kEosSlotV0}},
              .widths = {10, 16, 16, 16, 16, 16, 16}};
    append_table_params(f, 3);
    return f;
  }();
  return f;
}

// LS-DYNA's EOS 5: card 1 EOSID; cards 2-8 (4 E20 each) A_i0-A_i3 for i = 1..7; card 9 A14
// A24; card 10 ALPHA BETA E0 V0.  The fixed format: cards 2-10 (9 cards).  c: F1 A10-A14 (0-4),
// F2 A20-A24 (5-9), F3-F7 A_i0-A_i3 (10-29), ALPHA (30), BETA (31).
const EosForm& ratio_of_polynomials() {
  static const EosForm f = [] {
    EosForm f{.form = 5, .name = "ratio of polynomials", .keyword = "EOS_RATIO_OF_POLYNOMIALS",
              .widths = {10, 20, 20, 20, 20, 20, 20, 20, 20, 20}, .fixed_widths = {20, 20, 20, 20, 20, 20, 20, 20, 20}};
    static const char* const names[7][5] = {{"A10", "A11", "A12", "A13", "A14"}, {"A20", "A21", "A22", "A23", "A24"},
                                            {"A30", "A31", "A32", "A33", ""},    {"A40", "A41", "A42", "A43", ""},
                                            {"A50", "A51", "A52", "A53", ""},    {"A60", "A61", "A62", "A63", ""},
                                            {"A70", "A71", "A72", "A73", ""}};
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 4; ++j) f.params.push_back({names[i][j], 1 + i, j, i, j, i < 2 ? 5 * i + j : kEosRpF3 + 4 * (i - 2) + j});
    f.params.push_back({"A14", 8, 0, 7, 0, 4});
    f.params.push_back({"A24", 8, 1, 7, 1, 9});
    f.params.push_back({"ALPHA", 9, 0, 8, 0, kEosRpAlpha});
    f.params.push_back({"BETA", 9, 1, 8, 1, kEosRpBeta});
    f.params.push_back({"E0", 9, 2, 8, 2, kEosSlotE0});
    f.params.push_back({"V0", 9, 3, 8, 3, kEosSlotV0});
    return f;
  }();
  return f;
}

// LS-DYNA's EOS 6: form 1's cards, card 2 E0 V0 LCID (the energy deposition rate's curve).
const EosForm& linear_polynomial_with_energy_leak() {
  static const EosForm f = {6, "linear polynomial with energy deposition", "EOS_LINEAR_POLYNOMIAL_WITH_ENERGY_LEAK",
                            in_order({{"C0", 0}, {"C1", 1}, {"C2", 2}, {"C3", 3}, {"C4", 4}, {"C5", 5}, {"C6", 6},
                                      {"E0", kEosSlotE0}, {"V0", kEosSlotV0}, {"LCID", kEosLeakCurve}})};
  return f;
}

// LS-DYNA's EOS 8: card 1 EOSID GAMA E0 V0 (LCC LCT LCK LCID: the tables as curves and an energy
// deposition, refused); cards 2-9 (5 E16 each) EV1-5, EV6-10, C1-5, C6-10, T1-5, T6-10, K1-5,
// K6-10.  c: form 9's layout, K1-10 at 31-40.
const EosForm& tabulated_compaction() {
  static const EosForm f = [] {
    EosForm f{.form = 8, .name = "tabulated compaction", .keyword = "EOS_TABULATED_COMPACTION",
              .params = {{"GAMA", 0, 1, 0, 0, kEosTabGamma}, {"E0", 0, 2, 0, 1, kEosSlotE0}, {"V0", 0, 3, 0, 2, kEosSlotV0},
                         {"LCC", 0, 4, -1, 0, -1, "LCC (the C table as a load curve)"},
                         {"LCT", 0, 5, -1, 0, -1, "LCT (the T table as a load curve)"},
                         {"LCK", 0, 6, -1, 0, -1, "LCK (the K table as a load curve)"},
                         {"LCID", 0, 7, -1, 0, -1, "LCID (an energy deposition curve)"}},
              .widths = {10, 16, 16, 16, 16, 16, 16, 16, 16}, .history = 2};
    append_table_params(f, 4);
    return f;
  }();
  return f;
}

}  // namespace

std::span<const EosForm* const> eos_forms() {
  static const EosForm* const table[] = {&linear_polynomial(),  &jwl(), &sack_tuesday(), &gruneisen(), &ratio_of_polynomials(),
                                         &linear_polynomial_with_energy_leak(), &tabulated_compaction(), &tabulated()};
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

std::string supported_eos_keywords() {
  std::string s;
  for (const EosForm* f : eos_forms()) s += (s.empty() ? "*" : ", *") + std::string(f->keyword);
  return s;
}

int eos_history_count(int form) {
  const EosForm* f = form != 0 ? find_eos_form(form) : nullptr;
  return f ? f->history : 0;
}

int eos_curve(const EosData& e) { return e.form == 6 ? int(e.c[kEosLeakCurve]) : 0; }

double& eos_value(EosData& e, const EosParam& p) {
  static thread_local double sink = 0;
  if (p.slot >= 0 && p.slot < kEosConstants) return e.c[std::size_t(p.slot)];
  if (p.slot == kEosSlotE0) return e.e0;
  if (p.slot == kEosSlotV0) return e.v0;
  sink = 0;
  return sink;
}

double eos_value(const EosData& e, const EosParam& p) {
  if (p.slot >= 0 && p.slot < kEosConstants) return e.c[std::size_t(p.slot)];
  if (p.slot == kEosSlotE0) return e.e0;
  if (p.slot == kEosSlotV0) return e.v0;
  return 0;
}

int eos_table_points(const EosData& e) {
  if (e.form != 9 && e.form != 8) return 0;
  int n = 1;
  while (n < 10 && e.c[std::size_t(n)] < e.c[std::size_t(n - 1)]) ++n;
  return n;
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
  if (!(e.v0 > 0)) report(param("V0"), 1003, "the initial relative volume V0 must be positive (blank or 0: 1)");
  if (e.form == 9 || e.form == 8) {
    static const char* const ev[10] = {"EV1", "EV2", "EV3", "EV4", "EV5", "EV6", "EV7", "EV8", "EV9", "EV10"};
    static const char* const kk[10] = {"K1", "K2", "K3", "K4", "K5", "K6", "K7", "K8", "K9", "K10"};
    const int n = eos_table_points(e);
    if (n < 2) report(param("EV2"), 1003, "the table needs at least two points with EV decreasing (EV1 > EV2: compression is negative)");
    for (int j = n; j < 10 && n >= 2; ++j)
      if (e.c[std::size_t(j)] != 0 || e.c[std::size_t(10 + j)] != 0 || e.c[std::size_t(20 + j)] != 0 ||
          (e.form == 8 && e.c[std::size_t(kEosTabK + j)] != 0)) {
        report(param(ev[j]), 1003, "the volumetric strains EV must decrease (ln V: compression negative); points after the table's last must be blank");
        break;
      }
    if (n < 2) return;
    for (int j = 0; j < n && e.form == 8; ++j)
      if (!(e.c[std::size_t(kEosTabK + j)] > 0)) {
        report(param(kk[j]), 1003, "the unloading bulk modulus K must be positive at every point of the table");
        return;
      }
  }
  if (e.form == 5 && e.c[0] == 1)
    report(param("A10"), 1102, "A10 = 1 (LS-DYNA's switch to its delta-phase pressure model)");
  if (e.form == 6) {
    const double lc = e.c[kEosLeakCurve];
    if (!(lc >= 0 && lc == std::floor(lc) && lc < 1e9))
      report(param("LCID"), 1003, "a load-curve number (the energy deposition rate against time; 0: none)");
  }
  if (e.form == 2 && !(e.c[2] > 0)) report(param("R1"), 1003, "R1 must be positive");
  if (e.form == 2 && !(e.c[3] > 0)) report(param("R2"), 1003, "R2 must be positive");
  if (e.form == 2 && (!(e.c[2] > 0) || !(e.c[3] > 0))) return;
  if (e.form == 4 && !(e.c[0] > 0)) report(param("C"), 1003, "the bulk sound speed C must be positive");
  if (e.form == 4 && e.c[1] < 1) report(param("S1"), 1003, "the slope S1 of the us-up line must be at least 1");
  // a sound speed at the initial state (the time step and the hourglass and bulk viscosity need one)
  MaterialConstants c;
  c.rho = rho0;
  derive_eos_constants(e, c);
  if (!(c.K > 0))
    report(param(e.form == 1 || e.form == 6 || e.form == 8 || e.form == 9 ? "C1" : e.form == 2 ? "A" : e.form == 3 ? "A1" : e.form == 5 ? "A11" : "C"), 1003,
           "the equation of state gives no sound speed at its initial state (isentropic bulk modulus " + echo_number(c.K) + " <= 0)");
}

void derive_eos_constants(const EosData& e, MaterialConstants& c) {
  c.eos_form = e.form;
  for (std::size_t j = 0; j < e.c.size(); ++j) c.eos[j] = e.c[j];
  if (e.form == 4) c.eos[0] = c.rho * e.c[0] * e.c[0];
  if (e.form == 9 || e.form == 8) c.eos[kEosConstants] = eos_table_points(e);
  c.eos_v0 = e.v0 > 0 ? e.v0 : 1.0;
  c.eos_ln_v0 = std::log(c.eos_v0);
  // the isentropic bulk modulus at the initial state, V = V0 (mu0 = 1/V0 - 1)
  const double m1 = 1.0 / c.eos_v0;
  double a, b, da, db;
  calc_eos_coefficients(c, m1 - 1.0, e.e0, HUGE_VAL, a, b, da, db);
  const double p0 = a + b * e.e0;
  c.K = m1 * (da + db * e.e0) + p0 * b / m1;
  const double G = c.G;
  c.lambda = c.K - 2.0 * G / 3.0;
  c.E = G > 0 ? 9.0 * c.K * G / (3.0 * c.K + G) : 0.0;
  c.nu = G > 0 ? (3.0 * c.K - 2.0 * G) / (2.0 * (3.0 * c.K + G)) : 0.5;
  c.c = c.rho > 0.0 && c.K + 4.0 * G / 3.0 > 0.0 ? std::sqrt((c.K + 4.0 * G / 3.0) / c.rho) : 0.0;
}

void derive_eos_curve(const EosData& e, const Model& m, MaterialConstants& c) {
  c.eos_curve_t.clear(), c.eos_curve_f.clear(), c.eos_curve_F.clear();
  const int lc = eos_curve(e);
  for (const LoadCurve& l : m.load_curves)
    if (lc > 0 && l.number == lc && l.t.size() >= 2) {
      c.eos_curve_t = l.t;
      c.eos_curve_f = l.f;
      c.eos_curve_F.assign(l.t.size(), 0.0);
      for (std::size_t j = 1; j < l.t.size(); ++j)
        c.eos_curve_F[j] = c.eos_curve_F[j - 1] + 0.5 * (l.f[j - 1] + l.f[j]) * (l.t[j] - l.t[j - 1]);
    }
}

double calc_eos_initial_pressure(const MaterialConstants& c, double e0) {
  double a, b, da, db;
  calc_eos_coefficients(c, 1.0 / c.eos_v0 - 1.0, e0, HUGE_VAL, a, b, da, db);
  const double p = a + b * e0;
  return p < c.eos_pc ? c.eos_pc : p;
}

void echo_eos(std::ostream& os, const EosData& e) {
  const EosForm* f = find_eos_form(e.form);
  if (!f) return;
  echo_line(os, "equation of state", std::string(f->name) + " (form " + std::to_string(f->form) + (e.id ? ", EOSID " + std::to_string(e.id) : std::string()) + ")");
  const int n = eos_table_points(e);
  for (const EosParam& p : f->params) {
    if (p.slot < 0) continue;
    const bool table = (e.form == 9 || e.form == 8) && p.slot != kEosTabGamma && p.slot < kEosConstants;
    if (table && (p.slot < kEosTabGamma ? p.slot % 10 : p.slot - kEosTabK) >= n) continue;  // past the table
    const double v = eos_value(e, p);
    echo_line(os, std::string("  EOS ") + p.key, e.form == 6 && p.slot == kEosLeakCurve ? std::to_string(int(v)) : echo_number(v));
  }
  echo_line(os, "pressure from", "the equation of state (deviatoric stress from the material)");
}

}  // namespace impact3d
