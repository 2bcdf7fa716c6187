// Type 107, *MAT_MODIFIED_JOHNSON_COOK: the viscoplastic modified Johnson-Cook model
// (Borvik, Hopperstad, Berstad and Langseth 2001) as LS-DYNA's keyword reads it,
//   FLAG1 = 0: sigma_y = (A + B p^N) (1 + pdot / E0DOT)^C (1 - T*^M),
//   T* = (T - TR) / (TM - TR) (T* <= 0: 1; T* >= 1: 0; M = 0 or TM <= TR: no softening),
//   FLAG1 = 1 (Zerilli-Armstrong in its general form, card 3 SIGA, B, BETA0, BETA1, card 4 A, N,
//   ALPHA0, ALPHA1; M/NA unused): sigma_y = SIGA + B exp(-beta T) + A p^N exp(-alpha T),
//   beta = BETA0 - BETA1 ln pdot*, alpha = ALPHA0 - ALPHA1 ln pdot*, pdot* = max(pdot / E0DOT, 1)
//   (the floor at the reference rate is an IMPACT-3D choice, as type 15's ln term),
// with p the effective plastic strain and pdot its rate over the step (viscoplastic: found
// with the plastic strain increment, q - 3 G dp = sigma_y(p + dp, dp / dt), by Newton's method
// safeguarded by bisection); T the absolute temperature of the solid (history value 0): its
// initial value is the mean of its nodes' *INITIAL_TEMPERATURE_NODE / _SET temperatures (T0
// for a node none names; T0 blank or 0: TR, an IMPACT-3D choice), raised by adiabatic heating
// dT = XSI sigma_y dp / (RO CP) (CP = 0: isothermal); the temperature in the flow stress is
// that of the start of the step.  Erosion: the solid is deleted when T reaches TC or the
// largest shear stress (sigma_1 - sigma_3) / 2 reaches TAUC (0: none; history value 1 is the
// flag).
//
// Refused by field (message 1102): BETA != 0 (damage coupling), ALPHA != 0 (thermal
// expansion), Q1, C1, Q2, C2 != 0 with FLAG1 = 0 (extended Voce hardening), the fracture
// models (FLAG2 = 0: DC, PD, D1-D5 != 0; FLAG2 = 1: WC != 0).
//
// Fixed format (an IMPACT-3D choice): LS-DYNA's fields in order, 8 E10 fields per card: card 3
// E, PR, BETA, XSI, CP, ALPHA; card 4 E0DOT, TR, TM, T0, FLAG1, FLAG2; card 5 A, B, N, C, M;
// card 6 Q1, C1, Q2, C2; card 7 DC, PD/WC, D1-D5; card 8 TC, TAUC.
//
// The block form runs the scalar kernel lane by lane (pow inside a Newton loop).

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_types.h"
#include "impact3d/material/radial_return.h"

namespace impact3d {

namespace {

enum Par { pBeta, pXsi, pCp, pAlpha, pE0dot, pTr, pTm, pT0, pFlag1, pFlag2, pA, pB, pN, pC, pM, pQ1, pC1, pQ2, pC2,
           pDc, pPd, pD1, pD2, pD3, pD4, pD5, pTc, pTauc, kNumPar };
enum K { kA, kB, kN, kC, kM, kTr, kTm, kE0dot, kHeat, kTc, kTauc, kThermal,
         kZa, kZaA, kZaN, kAlpha0, kAlpha1, kBeta0, kBeta1 };  // kZa: FLAG1 = 1 (kA: SIGA, kB: B)
enum H { hTemperature, hEroded };

// The temperature factor 1 - T*^M.
double thermal_factor(const MaterialConstants& m, double T) {
  if (m.k[kThermal] == 0.0) return 1.0;
  const double ts = (T - m.k[kTr]) / (m.k[kTm] - m.k[kTr]);
  return ts <= 0.0 ? 1.0 : ts >= 1.0 ? 0.0 : 1.0 - std::pow(ts, m.k[kM]);
}

// Largest shear stress (sigma_1 - sigma_3) / 2 from the deviator's principal values.
double max_shear_stress(const double sig[6]) {
  const double pm = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  const double a = sig[0] - pm, b = sig[1] - pm, c = sig[2] - pm;
  const double j2 = 0.5 * (a * a + b * b + c * c) + sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5];
  if (!(j2 > 0.0)) return 0.0;
  const double j3 = a * b * c + 2.0 * sig[3] * sig[4] * sig[5] - a * sig[4] * sig[4] - b * sig[5] * sig[5] - c * sig[3] * sig[3];
  double x = 1.5 * std::sqrt(3.0) * j3 / (j2 * std::sqrt(j2));
  x = x > 1.0 ? 1.0 : x < -1.0 ? -1.0 : x;
  const double th = std::acos(x) / 3.0, r = 2.0 * std::sqrt(j2 / 3.0);
  // principal deviators r cos(th), r cos(th - 2 pi / 3), r cos(th + 2 pi / 3): s1 - s3
  return 0.5 * r * (std::cos(th) - std::cos(th + 2.0943951023931957));
}

// The Zerilli-Armstrong flow stress at plastic strain e (>= e0, the step's start) and its slope
// d sigma_y / d e, the rate pdot = (e - e0) / dt: rate_scale = 1 / (dt E0DOT).
void za_flow(const MaterialConstants& m, double T, double e0, double rate_scale, double e, double& s, double& ds) {
  const double A = m.k[kZaA], N = m.k[kZaN];
  const double x = (e - e0 > 0.0 ? e - e0 : 0.0) * rate_scale;  // pdot*
  const double L = x > 1.0 ? std::log(x) : 0.0, dL = x > 1.0 ? 1.0 / (e - e0) : 0.0;
  const double thermal = m.k[kB] * std::exp(-(m.k[kBeta0] - m.k[kBeta1] * L) * T);
  const double ea = std::exp(-(m.k[kAlpha0] - m.k[kAlpha1] * L) * T);
  const double en = e > 0.0 ? std::pow(e, N) : (N == 0.0 ? 1.0 : 0.0);
  const double den = e > 0.0 ? N * std::pow(e, N - 1.0) : (A == 0.0 || N == 0.0 ? 0.0 : HUGE_VAL);
  s = m.k[kA] + thermal + A * en * ea;
  ds = den == HUGE_VAL ? HUGE_VAL : A * den * ea + (thermal * m.k[kBeta1] + A * en * ea * m.k[kAlpha1]) * T * dL;
}

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& st) {
  update_stress_elastic(m, d, dt, st.sig);  // elastic trial
  double* sig = st.sig;
  const TrialDeviator t = calc_trial_deviator(sig);
  const double p = t.p, s0 = t.s0, s1 = t.s1, s2 = t.s2, q = t.q;
  const double e0 = st.eps_p, A = m.k[kA], B = m.k[kB], N = m.k[kN], C = m.k[kC];
  const double rate_scale = dt > 0.0 ? 1.0 / (dt * m.k[kE0dot]) : 0.0;
  double de;
  if (m.k[kZa] != 0.0) {
    const double T = st.hist[hTemperature];
    de = solve_radial_return(q, 3.0 * m.G, e0, [&](double e, double& s, double& ds) { za_flow(m, T, e0, rate_scale, e, s, ds); });
  } else {
    const double theta = thermal_factor(m, st.hist[hTemperature]);
    de = solve_radial_return(q, 3.0 * m.G, e0, [&](double e, double& s, double& ds) {
      const double en = e > 0.0 ? std::pow(e, N) : (N == 0.0 ? 1.0 : 0.0);
      const double h = A + B * en;
      const double dh = e > 0.0 ? N * B * std::pow(e, N - 1.0) : (B == 0.0 || N == 0.0 ? 0.0 : HUGE_VAL);
      const double x = 1.0 + (e - e0 > 0.0 ? e - e0 : 0.0) * rate_scale;  // 1 + pdot / E0DOT
      const double R = C != 0.0 ? std::pow(x, C) : 1.0;
      const double dR = C != 0.0 ? C * std::pow(x, C - 1.0) * rate_scale : 0.0;
      s = theta * h * R;
      ds = dh == HUGE_VAL ? HUGE_VAL : theta * (dh * R + h * dR);
    });
  }
  if (de > 0.0) {
    const double scale = 1.0 - 3.0 * m.G * de / q;
    set_scaled_deviator(p, scale, s0, s1, s2, sig);
    st.eps_p += de;
    st.yielded = 1.0;
    st.hist[hTemperature] += m.k[kHeat] * (q - 3.0 * m.G * de) * de;  // XSI sigma_y dp / (rho CP)
  }
  if (st.hist[hTemperature] >= m.k[kTc] || max_shear_stress(sig) >= m.k[kTauc]) st.hist[hEroded] = 1.0;
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_block_lane_by_lane(m, k, dt, 2, update_point);
}

double initial_temperature(const MaterialData& md) { return par(md, pT0) != 0 ? par(md, pT0) : par(md, pTr); }

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  const double f1 = par(md, pFlag1), f2 = par(md, pFlag2);
  if (f1 != 0 && f1 != 1) report(*find_param(t, "FLAG1"), 1003, "must be 0 (Johnson-Cook) or 1 (Zerilli-Armstrong)");
  if (f2 != 0 && f2 != 1) report(*find_param(t, "FLAG2"), 1003, "must be 0 (Johnson-Cook fracture) or 1 (Cockcroft-Latham)");
  if (f1 == 0)
    for (const char* k : {"Q1/A", "C1/N", "Q2/ALPHA0", "C2/ALPHA1"})
      if (param_value(md, *find_param(t, k)) != 0)
        report(*find_param(t, k), 1102, "the extended Voce hardening terms Q1, C1, Q2, C2 of FLAG1 = 0");
  if (f1 == 1)
    for (const char* k : {"Q1/A", "C1/N"})
      if (param_value(md, *find_param(t, k)) < 0)
        report(*find_param(t, k), 1003, "the Zerilli-Armstrong A and N (FLAG1 = 1) must not be negative");
  if (f2 == 0) {
    for (const char* k : {"DC", "PD/WC", "D1", "D2", "D3", "D4", "D5"})
      if (param_value(md, *find_param(t, k)) != 0)
        report(*find_param(t, k), 1102, "the Johnson-Cook fracture model (FLAG2 = 0: DC, PD, D1-D5)");
  } else if (f2 == 1) {
    if (par(md, pPd) != 0) report(*find_param(t, "PD/WC"), 1102, "the Cockcroft-Latham fracture model (FLAG2 = 1: WC)");
  }
  if (par(md, pE0dot) == 0) param_value(md, *find_param(t, "E0DOT")) = 1.0;
  if (f1 == 0 && par(md, pM) != 0 && !(par(md, pTm) > par(md, pTr)))
    report(*find_param(t, "TM"), 1003, "the melt temperature must exceed the room temperature TR when M is given");
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  c.beta = 1;
  c.k[kA] = par(d, pA), c.k[kB] = par(d, pB), c.k[kN] = par(d, pN), c.k[kC] = par(d, pC), c.k[kM] = par(d, pM);
  c.k[kTr] = par(d, pTr), c.k[kTm] = par(d, pTm);
  c.k[kE0dot] = par(d, pE0dot) > 0 ? par(d, pE0dot) : 1.0;
  c.k[kThermal] = par(d, pFlag1) == 0 && par(d, pM) > 0 && par(d, pTm) > par(d, pTr) ? 1.0 : 0.0;
  c.k[kZa] = par(d, pFlag1) == 1 ? 1.0 : 0.0;
  c.k[kZaA] = par(d, pQ1), c.k[kZaN] = par(d, pC1), c.k[kAlpha0] = par(d, pQ2), c.k[kAlpha1] = par(d, pC2);
  c.k[kBeta0] = par(d, pN), c.k[kBeta1] = par(d, pC);
  c.k[kHeat] = par(d, pCp) > 0 && d.rho > 0 ? par(d, pXsi) / (d.rho * par(d, pCp)) : 0.0;
  c.k[kTc] = par(d, pTc) > 0 ? par(d, pTc) : HUGE_VAL;
  c.k[kTauc] = par(d, pTauc) > 0 ? par(d, pTauc) : HUGE_VAL;
  if (par(d, pTc) > 0 || par(d, pTauc) > 0) c.fail_history = hEroded;
  // the initial yield stress at the reference rate and the initial temperature T0 (or TR)
  c.sigma_y = c.k[kZa] != 0.0 ? c.k[kA] + c.k[kB] * std::exp(-c.k[kBeta0] * initial_temperature(d)) : c.k[kA];
}

void echo(std::ostream& os, const MaterialData& md) {
  char b[96];
  if (par(md, pFlag1) == 1) {
    echo_line(os, "flow stress (Zerilli-Armstrong)", "SIGA + B exp(-beta T) + A p^N exp(-alpha T)");
    echo_line(os, "  beta, alpha", "BETA0 - BETA1 ln pdot*, ALPHA0 - ALPHA1 ln pdot*");
    echo_line(os, "  pdot*", "max(pdot/E0DOT, 1), pdot the plastic strain rate");
    char z[160];
    std::snprintf(z, sizeof z, "%.6e %.6e %.6e %.6e", par(md, pQ1), par(md, pC1), par(md, pQ2), par(md, pC2));
    echo_line(os, "  A, N, ALPHA0, ALPHA1", z);
  } else {
    echo_line(os, "flow stress", "(A + B p^N) (1 + pdot/E0DOT)^C (1 - T*^M), pdot the plastic strain rate");
  }
  std::snprintf(b, sizeof b, "%.6e", initial_temperature(md));
  echo_line(os, "initial temperature (nodes not in *INITIAL_TEMPERATURE)", b);
  echo_line(os, "heating", par(md, pCp) > 0 ? "adiabatic, XSI sigma_y dp / (RO CP)" : "none (CP = 0)");
  if (par(md, pTc) > 0 || par(md, pTauc) > 0) echo_line(os, "erosion", "at T >= TC or (s1 - s3)/2 >= TAUC");
}

MaterialParam p(const char* key, int kcard, int kfield, int index, ParamCheck check = ParamCheck::none,
                const char* detail = "", const char* label = nullptr, const char* unit = "") {
  return {.key = key, .label = label, .kcard = kcard, .kfield = kfield, .fcard = kcard + 3,
          .fcol = 1 + 10 * (kfield - (kcard == 0 ? 2 : 0)), .index = index, .check = check, .detail = detail, .unit = unit};
}

}  // namespace

const MaterialType& mat_modified_johnson_cook_type() {
  static const MaterialType t{.number = 107, .name = "modified Johnson-Cook", .keywords = {"MAT_MODIFIED_JOHNSON_COOK", "MAT_107"},
      .params = {
          young_modulus_param(3, 1), poisson_param(3, 11),
          p("BETA", 0, 4, pBeta, ParamCheck::unsupported, "BETA != 0 (damage coupling)"),
          p("XSI", 0, 5, pXsi, ParamCheck::fraction, "the Taylor-Quinney coefficient must lie in [0, 1]", "Taylor-Quinney XSI"),
          p("CP", 0, 6, pCp, ParamCheck::non_negative, "must not be negative (0: no heating)", "specific heat CP"),
          p("ALPHA", 0, 7, pAlpha, ParamCheck::unsupported, "ALPHA != 0 (thermal expansion)"),
          p("E0DOT", 1, 0, pE0dot, ParamCheck::non_negative, "must not be negative (0: 1)", "reference strain rate E0DOT", "1/time"),
          p("TR", 1, 1, pTr, ParamCheck::none, "", "room temperature TR", "temperature"),
          p("TM", 1, 2, pTm, ParamCheck::none, "", "melt temperature TM", "temperature"),
          p("T0", 1, 3, pT0, ParamCheck::non_negative, "must not be negative (0: TR)", "initial temperature T0", "temperature"),
          p("FLAG1", 1, 4, pFlag1),
          p("FLAG2", 1, 5, pFlag2),
          p("A/SIGA", 2, 0, pA, ParamCheck::non_negative, "must not be negative", "A (yield stress; FLAG1 1: SIGA)", "stress"),
          p("B/B", 2, 1, pB, ParamCheck::non_negative, "must not be negative", "B (hardening; FLAG1 1: B)", "stress"),
          p("N/BETA0", 2, 2, pN, ParamCheck::non_negative, "must not be negative", "N (hardening exponent; FLAG1 1: BETA0)"),
          p("C/BETA1", 2, 3, pC, ParamCheck::non_negative, "must not be negative", "C (rate exponent; FLAG1 1: BETA1)"),
          p("M/NA", 2, 4, pM, ParamCheck::non_negative, "must not be negative", "M (thermal softening exponent; FLAG1 0 only)"),
          p("Q1/A", 3, 0, pQ1),
          p("C1/N", 3, 1, pC1),
          p("Q2/ALPHA0", 3, 2, pQ2),
          p("C2/ALPHA1", 3, 3, pC2),
          p("DC", 4, 0, pDc),
          p("PD/WC", 4, 1, pPd),
          p("D1", 4, 2, pD1),
          p("D2", 4, 3, pD2),
          p("D3", 4, 4, pD3),
          p("D4", 4, 5, pD4),
          p("D5", 4, 6, pD5),
          p("TC", 5, 0, pTc, ParamCheck::non_negative, "must not be negative (0: no erosion by temperature)", "erosion temperature TC", "temperature"),
          p("TAUC", 5, 1, pTauc, ParamCheck::non_negative, "must not be negative (0: no erosion by shear stress)", "erosion shear stress TAUC", "stress"),
      },
      .num_par = kNumPar, .keyword_cards = 6,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, true},
      .history = {"temperature", "eroded"}, .temperature_history = hTemperature,
      .initial_temperature = initial_temperature,
  };
  return t;
}

}  // namespace impact3d
