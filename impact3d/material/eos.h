#pragma once
// Equations of state: the pressure of a material's solids when its part (keyword decks: *PART
// EOSID) or its material set (fixed format: card 1 columns 21-25) names one.  The material's
// kernel gives the deviatoric stress; the EOS replaces the mean stress.  Forms (DYNA3D's
// numbers):
//   1 *EOS_LINEAR_POLYNOMIAL: p = C0 + C1 mu + C2 mu^2 + C3 mu^3 + (C4 + C5 mu + C6 mu^2) E
//     (C2 mu^2 and C6 mu^2 are dropped in tension, mu < 0, as LS-DYNA does);
//   2 *EOS_JWL: p = A (1 - OMEG/(R1 V)) exp(-R1 V) + B (1 - OMEG/(R2 V)) exp(-R2 V) + OMEG E / V;
//   3 *EOS_SACK_TUESDAY: p = A1 V^-A2 exp(-A3 V) (1 - B1/V) + B2 E / V;
//   4 *EOS_GRUNEISEN: in compression (mu > 0)
//       p = rho0 C^2 mu [1 + (1 - GAMMA0/2) mu - A/2 mu^2] /
//           [1 - (S1 - 1) mu - S2 mu^2/(mu + 1) - S3 mu^3/(mu + 1)^2]^2 + (GAMMA0 + A mu) E,
//     in tension p = rho0 C^2 mu + (GAMMA0 + A mu) E;
//   5 *EOS_RATIO_OF_POLYNOMIALS: p = (F1 + F2 E + F3 E^2 + F4 E^3) / (F5 + F6 E + F7 E^2)
//     (1 + ALPHA mu), F_i = sum_j A_ij mu^j (j to 4 for F1, F2, to 3 for F3-F7), F1 + BETA mu^2
//     in tension (mu < 0); not linear in E: the energy update below is solved by Newton
//     iterations (A10 = 1, LS-DYNA's switch to its delta-phase model, is refused);
//   6 *EOS_LINEAR_POLYNOMIAL_WITH_ENERGY_LEAK: form 1's pressure; E also grows by the energy
//     deposition rate of the load curve LCID: over a step [t - dt, t] by the curve's exact
//     integral (piecewise linear, its end segments extended as for loads), booked as internal
//     energy and as external work (the energy ratio stays 1);
//   8 *EOS_TABULATED_COMPACTION: form 9's table with a bulk-modulus column K: on the virgin
//     (loading) curve, eps_v at its smallest so far, p = C(eps_v) + GAMMA T(eps_v) E; after
//     unloading from the most compacted state eps_min (initially ln V0; the history value holds
//     eps_min - ln V0, the smallest ln(volume / initial volume), so that it starts at 0),
//     p = C(eps_min) + K(eps_min) (eps_min - eps_v) + GAMMA T(eps_v) E, and reloading goes back up
//     that line to the virgin curve (K held at its end values beyond the table; the energy term
//     follows T(eps_v) on both branches, an IMPACT-3D choice: LS-DYNA's manual states only the
//     loading form);
//   9 *EOS_TABULATED: p = C(eps_v) + GAMMA T(eps_v) E, eps_v = ln V, C and T piecewise linear in
//     eps_v through the points (EV_i, C_i), (EV_i, T_i) (EV decreasing from EV1; up to 10 points,
//     those after the first that does not decrease must be blank), beyond the first and last
//     points the end segments extended (an IMPACT-3D choice);
// with V the relative volume, mu = 1/V - 1 and E the internal energy per reference volume, a
// history value of the element (initially E0).  V = V0 x (volume / initial volume): V0 (the
// EOS's initial relative volume, 1 by default) starts the solid precompressed (V0 < 1) or
// expanded; its mass stays RO x its initial volume, its reference volume is the initial volume
// / V0.  Forms other than 5 are p = a(mu) + b(mu) E.  The energy update
// is DYNA3D's: over a step with relative volume change dv (= trD V_mid dt / V0, the increment
// the stress-work book uses, times V0),
//   E* = E^n + (deviatoric work) - (p^n + q^{n-1} + q^n) dv / 2 (+ the deposit, form 6),
//   p^{n+1} = (a + b E*) / (1 + b dv / 2),  E^{n+1} = E* - p^{n+1} dv / 2,
// so that p^{n+1} = a + b E^{n+1} exactly (the EOS holds at the end of the step) and E times
// the reference volume grows by exactly the element's stress and bulk-viscosity work.  (Form 5:
// a and b are p and dp/dE linearised at the last iterate, E^{n+1} = E* - p^{n+1} dv / 2 iterated
// to a fixed point: p^{n+1} = p(mu, E^{n+1}) to round-off.)  A pressure cutoff (the
// material's PC < 0) bounds p from below.  The element's sound speed for its time step is the
// isentropic one, c^2 = (K_s + 4G/3) / rho with K_s = (1 + mu) (a' + b' E) + p b / (1 + mu)
// (never below a tenth of the reference speed, so that an element at the cutoff keeps a
// finite step: an IMPACT-3D choice; form 8 takes the stiffer of the virgin slope and K).
//
// Fixed format (an IMPACT-3D choice: DYNA3D's EOS card layout is not public): a material set
// whose card 1 columns 21-25 give an EOS form has the form's cards after card 8, LS-DYNA's
// keyword cards without EOSID: form 1: C0 C1 C2 C3 C4 C5 C6 / E0 V0; form 2: A B R1 R2 OMEG E0
// V0 (one card); form 3: A1 A2 A3 B1 B2 E0 V0 (one card); form 4: C S1 S2 S3 GAMMA0
// A E0 / V0 (8 E10 fields each); form 5: A10-A13 / A20-A23 / ... / A70-A73 / A14 A24 / ALPHA
// BETA E0 V0 (9 cards, 4 E20 fields each: LS-DYNA's cards 2-10); form 6: form 1's cards, LCID
// (a load curve number) in card 2 columns 21-30; form 8: GAMMA E0 V0 (E10), then EV1-5 / EV6-10
// / C1-5 / C6-10 / T1-5 / T6-10 / K1-5 / K6-10 (5 E16 fields each); form 9: GAMMA E0 V0 (E10),
// then EV1-5 / EV6-10 / C1-5 / C6-10 / T1-5 / T6-10 (5 E16 fields each).

#include <algorithm>
#include <cmath>
#include <functional>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/material/material.h"
#include "impact3d/model/model.h"

namespace impact3d {

// Where an EosParam's value goes: EosData::c[slot] for slot < kEosConstants, else e0 or v0.
constexpr int kEosSlotE0 = kEosConstants, kEosSlotV0 = kEosConstants + 1;

// One parameter of an EOS form: keyword card (0, 1, ...) and field (EOSID is field 0 of card 0),
// fixed-format EOS card and field; slot: EosData::c index, kEosSlotE0, kEosSlotV0, or -1: a
// field read and refused when nonzero (unsupported).
struct EosParam {
  const char* key;
  int kcard, kfield;
  int fcard, ffield;
  int slot;
  const char* unsupported = nullptr;  // slot -1: the feature, for message 1102
};

struct EosForm {
  int form = 0;             // DYNA3D's EOS form number
  const char* name = "";    // printed name
  const char* keyword = "";  // LS-DYNA keyword without '*'
  std::vector<EosParam> params{};
  std::vector<int> widths = {10, 10};  // per card (both formats): the field width; its size: the cards
  std::vector<int> fixed_widths = {};  // the fixed format's, when its cards differ (empty: widths)
  int history = 1;                     // history values (the energy E; form 8 also eps_min)
};
// Fields per card of a form (80 columns).
inline int eos_card_fields(const EosForm& f, int card) { return 80 / f.widths[std::size_t(card)]; }
// The fixed format's cards (their field widths).
inline const std::vector<int>& eos_fixed_widths(const EosForm& f) { return f.fixed_widths.empty() ? f.widths : f.fixed_widths; }

// Layout of EosData::c (and MaterialConstants::eos) for the forms with many constants.
// Forms 8, 9: EV1-10, C1-10, T1-10, GAMMA, (form 8) K1-10; the number of points goes to
// MaterialConstants::eos[kEosConstants].
constexpr int kEosTabEv = 0, kEosTabC = 10, kEosTabT = 20, kEosTabGamma = 30, kEosTabK = 31;
// Form 5: F1, F2 (A_i0-A_i4, 5 each), F3-F7 (A_i0-A_i3, 4 each), ALPHA, BETA.
constexpr int kEosRpF3 = 10, kEosRpAlpha = 30, kEosRpBeta = 31;
// Form 6: C0-C6, LCID (a load-curve number; 0 none).
constexpr int kEosLeakCurve = 7;

// The EOS forms IMPACT-3D has.
std::span<const EosForm* const> eos_forms();
const EosForm* find_eos_form(int form);
const EosForm* find_eos_form_by_keyword(std::string_view keyword);
// "1 linear polynomial, 4 Gruneisen" for messages; "*EOS_LINEAR_POLYNOMIAL, ..." likewise.
std::string supported_eos_forms();
std::string supported_eos_keywords();
// The value a parameter names.
double& eos_value(EosData& e, const EosParam& p);
double eos_value(const EosData& e, const EosParam& p);
// The number of points of a tabulated EOS's table (forms 8, 9).
int eos_table_points(const EosData& e);
// History values an EOS form adds to its material's (0 for form 0).
int eos_history_count(int form);
// The load curve an EOS names (form 6 LCID; 0: none).
int eos_curve(const EosData& e);
// Checks after reading (V0 blank/0 -> 1); problems go to report (message, detail).
void check_eos(EosData& e, double rho0, const std::function<void(const EosParam& p, int msg, const std::string& detail)>& report);
// The kernel constants: eos_form, eos[], K (the isentropic bulk modulus at the initial state),
// lambda, c; E and nu made consistent with K and G.  eos_pc and eos_hist are the caller's.
void derive_eos_constants(const EosData& e, MaterialConstants& c);
// Form 6: the deposition curve (the model's load curve LCID) into c.eos_curve_*.
void derive_eos_curve(const EosData& e, const Model& m, MaterialConstants& c);
// The pressure at the initial state (V = V0, E = E0).
double calc_eos_initial_pressure(const MaterialConstants& c, double e0);
// The printed echo of a material's EOS (nothing for form 0).
void echo_eos(std::ostream& os, const EosData& e);

// The segment i (0 .. n-2) of a table with decreasing abscissae x[0] > x[1] > ... that holds v,
// the end segments extended beyond the table.
inline int find_eos_table_segment(const double* x, int n, double v) {
  int i = 0;
  while (i + 2 < n && v < x[i + 1]) ++i;
  return i;
}

// The integral of the form-6 deposition curve from its first point to t (its end segments
// extended; exact for the piecewise-linear curve).
inline double calc_eos_deposit_integral(const MaterialConstants& m, double t) {
  const std::size_t n = m.eos_curve_t.size();
  if (n < 2) return 0;
  std::size_t j = 0;
  while (j + 2 < n && t >= m.eos_curve_t[j + 1]) ++j;
  const double h = t - m.eos_curve_t[j];
  const double slope = (m.eos_curve_f[j + 1] - m.eos_curve_f[j]) / (m.eos_curve_t[j + 1] - m.eos_curve_t[j]);
  return m.eos_curve_F[j] + h * (m.eos_curve_f[j] + 0.5 * slope * h);
}

// Form 5: p and its derivatives in mu and E at (mu, E).
inline void calc_eos_ratio_of_polynomials(const double* k, double mu, double E, double& p, double& dpdmu, double& dpde) {
  double F[7], dF[7];
  for (int i = 0; i < 7; ++i) {
    const int base = i < 2 ? 5 * i : kEosRpF3 + 4 * (i - 2), deg = i < 2 ? 4 : 3;
    double f = k[base + deg], df = 0;
    for (int j = deg - 1; j >= 0; --j) {
      df = df * mu + f;
      f = f * mu + k[base + j];
    }
    F[i] = f, dF[i] = df;
  }
  if (mu < 0) F[0] += k[kEosRpBeta] * mu * mu, dF[0] += 2.0 * k[kEosRpBeta] * mu;
  const double num = F[0] + E * (F[1] + E * (F[2] + E * F[3]));
  const double den = F[4] + E * (F[5] + E * F[6]);
  const double dnum = dF[0] + E * (dF[1] + E * (dF[2] + E * dF[3]));
  const double dden = dF[4] + E * (dF[5] + E * dF[6]);
  const double nume = F[1] + E * (2.0 * F[2] + 3.0 * E * F[3]);
  const double dene = F[5] + 2.0 * E * F[6];
  const double g = 1.0 + k[kEosRpAlpha] * mu, r = num / den;
  p = r * g;
  dpdmu = (dnum - r * dden) / den * g + r * k[kEosRpAlpha];
  dpde = (nume - r * dene) / den * g;
}

// p = a + b E and the derivatives a', b' in mu.  e: the energy (form 5 linearises there: a, b
// are p - b e and dp/dE at e, a' + b' e = dp/dmu); ev_min: form 8's most compacted ln V so far
// (+inf: on the virgin curve).
inline void calc_eos_coefficients(const MaterialConstants& m, double mu, double e, double ev_min, double& a, double& b,
                                  double& da, double& db) {
  const double* k = m.eos.data();
  if (m.eos_form == 9 || m.eos_form == 8) {
    // tabulated: the segment i that holds eps_v (the end segments extended)
    const int n = int(k[kEosConstants]);
    const double ev = -std::log(1.0 + mu);
    const int i = find_eos_table_segment(k + kEosTabEv, n, ev);
    const double h = k[i + 1] - k[i];
    const double st = (k[kEosTabT + i + 1] - k[kEosTabT + i]) / h;
    b = k[kEosTabGamma] * (k[kEosTabT + i] + st * (ev - k[i]));
    db = -k[kEosTabGamma] * st / (1.0 + mu);  // d eps_v / d mu = -1 / (1 + mu)
    const double em = m.eos_form == 8 && ev_min < ev ? ev_min : ev;  // form 8: unloaded from em
    const int j = em == ev ? i : find_eos_table_segment(k + kEosTabEv, n, em);
    const double hj = k[j + 1] - k[j];
    const double sc = (k[kEosTabC + j + 1] - k[kEosTabC + j]) / hj;
    a = k[kEosTabC + j] + sc * (em - k[j]);
    da = -sc / (1.0 + mu);
    if (m.eos_form == 8) {
      // the unloading modulus at em (held at its end values), the line back from em; the sound
      // speed takes the stiffer of the two branches
      const double w = std::clamp((em - k[j]) / hj, 0.0, 1.0);
      const double K = k[kEosTabK + j] + w * (k[kEosTabK + j + 1] - k[kEosTabK + j]);
      a += K * (em - ev);
      da = std::max(da, K / (1.0 + mu));
    }
    return;
  }
  if (m.eos_form == 5) {
    double p, dpdmu, dpde;
    calc_eos_ratio_of_polynomials(k, mu, e, p, dpdmu, dpde);
    b = dpde;
    a = p - b * e;
    da = dpdmu;
    db = 0.0;
    return;
  }
  if (m.eos_form == 2 || m.eos_form == 3) {
    // JWL: k = A, B, R1, R2, OMEG; Sack Tuesday: k = A1, A2, A3, B1, B2; both functions of
    // V = 1 / (1 + mu), dV/dmu = -V^2
    const double V = 1.0 / (1.0 + mu);
    double dadv;
    if (m.eos_form == 2) {
      const double x1 = k[0] * std::exp(-k[2] * V), x2 = k[1] * std::exp(-k[3] * V);
      const double w = k[4];
      a = x1 * (1.0 - w / (k[2] * V)) + x2 * (1.0 - w / (k[3] * V));
      dadv = x1 * (w / (k[2] * V * V) - k[2] + w / V) + x2 * (w / (k[3] * V * V) - k[3] + w / V);
      b = w / V;
    } else {
      const double g = k[0] * std::pow(V, -k[1]) * std::exp(-k[2] * V);
      const double h = 1.0 - k[3] / V;
      a = g * h;
      dadv = g * (-k[1] / V - k[2]) * h + g * k[3] / (V * V);
      b = k[4] / V;
    }
    da = -V * V * dadv;
    db = k[4];  // b = k4 / V = k4 (1 + mu)
    return;
  }
  if (m.eos_form == 1 || m.eos_form == 6) {
    const double c2 = mu < 0.0 ? 0.0 : k[2], c6 = mu < 0.0 ? 0.0 : k[6];
    a = k[0] + mu * (k[1] + mu * (c2 + mu * k[3]));
    b = k[4] + mu * (k[5] + mu * c6);
    da = k[1] + mu * (2.0 * c2 + 3.0 * mu * k[3]);
    db = k[5] + 2.0 * c6 * mu;
    return;
  }
  // Gruneisen: k = rho0 C^2, S1, S2, S3, GAMMA0, A
  b = k[4] + k[5] * mu;
  db = k[5];
  if (mu <= 0.0) {
    a = k[0] * mu;
    da = k[0];
    return;
  }
  const double m1 = mu + 1.0;
  const double num = k[0] * mu * (1.0 + (1.0 - 0.5 * k[4]) * mu - 0.5 * k[5] * mu * mu);
  const double dnum = k[0] * (1.0 + 2.0 * (1.0 - 0.5 * k[4]) * mu - 1.5 * k[5] * mu * mu);
  const double den = 1.0 - (k[1] - 1.0) * mu - k[2] * mu * mu / m1 - k[3] * mu * mu * mu / (m1 * m1);
  const double dden = -(k[1] - 1.0) - k[2] * mu * (mu + 2.0) / (m1 * m1) - k[3] * mu * mu * (mu + 3.0) / (m1 * m1 * m1);
  a = num / (den * den);
  da = dnum / (den * den) - 2.0 * num * dden / (den * den * den);
}

// The forms linear in E at E = 0 (form 5 linearised at E = 0; form 8 on its virgin curve).
inline void calc_eos_coefficients(const MaterialConstants& m, double mu, double& a, double& b, double& da, double& db) {
  calc_eos_coefficients(m, mu, 0.0, HUGE_VAL, a, b, da, db);
}

// The EOS step of one solid after its material's update (sig holds the material's new stress,
// old the stress at the start of the step, both tension positive): replaces the mean stress by
// -p^{n+1}, updates the history values (h[0] = E, the internal energy per reference volume,
// initially E0; form 8 h[1] = eps_min - ln V0, the smallest ln(volume / initial volume) so far,
// initially 0) and returns the sound speed.  v: volume at the end of the step, vm:
// midpoint volume, vol0: initial volume, q_old, q_new: the bulk viscosity of the last step and
// this one, t: the time at the end of the step; src gets the energy the EOS deposited (form 6:
// E's increment from the curve times the reference volume; else 0).  Same operations for the
// scalar and block callers (the block calls it lane by lane).
inline double update_stress_eos_point(const MaterialConstants& m, const double old[6], const double d[6], double v,
                                      double vm, double vol0, double dt, double q_old, double q_new, double sig[6],
                                      double* h, double t, double& src, bool no_tension = false) {
  const double pt = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  const double s0 = sig[0] - pt, s1 = sig[1] - pt, s2 = sig[2] - pt;
  const double po = -(old[0] + old[1] + old[2]) * (1.0 / 3.0);
  const double o0 = old[0] + po, o1 = old[1] + po, o2 = old[2] + po;
  const double w = 0.5 * ((o0 + s0) * d[0] + (o1 + s1) * d[1] + (o2 + s2) * d[2]) +
                   ((old[3] + sig[3]) * d[3] + (old[4] + sig[4]) * d[4] + (old[5] + sig[5]) * d[5]);
  const double scale = vm * dt / vol0 * m.eos_v0;
  const double dv = (d[0] + d[1] + d[2]) * scale;
  double es = h[0] + w * scale - 0.5 * (po + q_old + q_new) * dv;
  src = 0.0;
  if (m.eos_form == 6 && !m.eos_curve_t.empty()) {  // the deposit over [t - dt, t]
    const double de = calc_eos_deposit_integral(m, t) - calc_eos_deposit_integral(m, t - dt);
    es += de;
    src = de * vol0 / m.eos_v0;
  }
  const double mu = vol0 / (m.eos_v0 * v) - 1.0;
  double ev_min = HUGE_VAL;
  if (m.eos_form == 8) {  // the most compacted state so far
    const double rel = -std::log(1.0 + mu) - m.eos_ln_v0;
    h[1] = rel < h[1] ? rel : h[1];
    ev_min = h[1] + m.eos_ln_v0;
  }
  double a, b, da, db, p, e = es;
  calc_eos_coefficients(m, mu, e, ev_min, a, b, da, db);
  p = (a + b * es) / (1.0 + 0.5 * b * dv);
  if (m.eos_form == 5) {  // not linear in E: Newton on E = E* - p(mu, E) dv / 2 to its fixed point
    for (int it = 0; it < 20; ++it) {
      const double en = es - 0.5 * p * dv;
      if (en == e) break;
      e = en;
      calc_eos_coefficients(m, mu, e, ev_min, a, b, da, db);
      p = (a + b * es) / (1.0 + 0.5 * b * dv);
    }
  }
  const double pc = no_tension ? 0.0 : m.eos_pc;  // a rubble carries no tension
  p = p < pc ? pc : p;
  e = es - 0.5 * p * dv;
  h[0] = e;
  sig[0] = s0 - p;
  sig[1] = s1 - p;
  sig[2] = s2 - p;
  const double m1 = 1.0 + mu;
  const double ks = m1 * (da + db * e) + p * b / m1;
  const double c2 = (ks + (4.0 / 3.0) * m.G) / (m.rho * m1 * m.eos_v0);  // rho V0 / V
  const double floor2 = 0.01 * m.c * m.c;
  return std::sqrt(c2 > floor2 ? c2 : floor2);
}

// The step of the forms with one history value and no deposit (the energy e).
inline double update_stress_eos_point(const MaterialConstants& m, const double old[6], const double d[6], double v,
                                      double vm, double vol0, double dt, double q_old, double q_new, double sig[6],
                                      double& e) {
  double h[2] = {e, HUGE_VAL}, src;
  const double c = update_stress_eos_point(m, old, d, v, vm, vol0, dt, q_old, q_new, sig, h, 0.0, src);
  e = h[0];
  return c;
}

}  // namespace impact3d
