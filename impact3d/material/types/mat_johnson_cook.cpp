// Johnson-Cook plasticity, two types:
//   15 *MAT_JOHNSON_COOK: sigma_y = (A + B eps_p^N) R(rate) (1 - T*^M), T* = (T - TR) /
//      (TM - TR), adiabatic heating dT = sigma_y d eps_p / (rho0 CP) from the plastic work,
//      Johnson-Cook damage D = sum d eps_p / eps_f, eps_f = max(EFMIN, (D1 + D2 exp(D3
//      sigma*)) (1 + D4 ln rate*) (1 + D5 T*)), deletion at D >= 1 (EROD = 0) or, EROD != 0,
//      no deletion and the deviatoric stress zero from then on; deletion at the element step
//      DTF.  G is the card's shear modulus.  Tension (PC < 0; PC = 0: none), LS-DYNA's SPALL:
//      1 the mean stress is bounded by -PC; 2 (and 0, LS-DYNA's default) the point spalls when
//      its largest principal stress reaches -PC; 3 it spalls when the pressure reaches PC.
//      Spalled (history 2 = 1): deviatoric stress zero and no tension (a tensile mean stress is
//      reset to 0) from then on, a rubble.  With an equation of state (*PART EOSID, fixed
//      format card 1 columns 21-25; material/eos.h) the pressure comes from it (the kernel's
//      trial pressure, the old EOS pressure plus K dV, serves the damage triaxiality and the
//      spall tests; PC < 0 bounds the EOS pressure, 0 that of a spalled point); without one it is
//      hypoelastic with the bulk modulus of E and PR.
//   98 *MAT_SIMPLIFIED_JOHNSON_COOK: sigma_y = min((min(A + B eps_p^N, SIGSAT)) (1 + C ln
//      rate*), SIGMAX), deletion at the plastic strain PSFAIL.
// rate* = max(rate / EPSO, 1).  The rate factor R (type 15 RATEOP; type 98 uses 0): 0 1 + C ln
// rate*; 1 (Huh-Kang) 1 + C ln rate* + C2 (ln rate*)^2; 2 (Allen-Rule-Jones) rate*^C; 3
// (Cowper-Symonds) 1 + (rate / C)^(1/P), C2/P the field P (the rate itself, in the deck's time
// unit, as *MAT_003).  VP = 0: rate = sqrt(2/3 D':D'), the effective (deviatoric) strain rate of
// the step, scales the yield stress; VP = 1 (viscoplastic): rate = d eps_p / dt, the plastic
// strain rate of the step, found with the plastic strain increment.  The return solves q - 3 G
// de = sigma_y(eps_p + de, rate) by Newton's method safeguarded by bisection (the flow stress
// is nonlinear, and with VP = 1 it grows with de through the rate); the temperature factor is
// that of the start of the step.
//
// Fixed format (an IMPACT-3D choice; no DYNA3D manual fixes these types): LS-DYNA's cards in
// order, 8 E10 fields per card from card 3 (type 15: card 3 G, E, PR, DTF, VP, RATEOP; card 4 A,
// B, N, C, M, TM, TR, EPSO; card 5 CP, PC, SPALL, IT, D1-D4; card 6 D5, C2/P, EROD, EFMIN; type
// 98: card 3 E, PR, VP; card 4 A, B, N, C, PSFAIL, SIGMAX, SIGSAT, EPSO).
//
// The block form runs the scalar kernel lane by lane (pow, log and exp inside a Newton loop do
// not vectorize); same bits by construction.

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"
#include "impact3d/material/radial_return.h"

namespace impact3d {

namespace {

// MaterialConstants::k
// (thermal terms: TM > TR; kDamage 0 none, 1 deletion at D >= 1, 2 no erosion (EROD != 0);
// kSpall 0 none (PC = 0), 1-3 LS-DYNA's SPALL; kRateop 0-3, kC2 its C2 or P)
enum K { kA, kB, kN, kC, kM, kTm, kTr, kEps0, kCp, kPc, kD1, kD2, kD3, kD4, kD5, kEfmin, kSigmax, kSigsat,
         kDamage, kHistory, kRateop, kC2, kVp, kSpall, kNumK };
static_assert(kNumK <= 24);
// MaterialData::par (type 15)
enum P15 { pG, pDtf, pVp, pRateop, pA, pB, pN, pC, pM, pTm, pTr, pEps0, pCp, pPc, pSpall, pIt,
           pD1, pD2, pD3, pD4, pD5, pC2, pErod, pEfmin, pNumint, kNumPar15 };
// MaterialData::par (type 98)
enum P98 { qVp, qA, qB, qN, qC, qSigmax, qSigsat, qEps0, kNumPar98 };
// history (type 15)
enum H { hTemperatureRise, hDamage, hSpalled };

// The rate factor R of the effective strain rate r and its slope dR/dr (rate* = max(r / EPSO, 1)).
void calc_rate_factor(const MaterialConstants& m, double r, double& R, double& dR) {
  const int form = int(m.k[kRateop]);
  if (form == 3) {  // Cowper-Symonds: 1 + (r / C)^(1/P)
    const double x = r / m.k[kC], ip = 1.0 / m.k[kC2];
    R = r > 0.0 ? 1.0 + std::pow(x, ip) : 1.0;
    dR = r > 0.0 ? ip * std::pow(x, ip - 1.0) / m.k[kC] : HUGE_VAL;
    return;
  }
  const double rs = r / m.k[kEps0];
  if (!(rs > 1.0)) {
    R = 1.0, dR = 0.0;
    return;
  }
  const double lr = std::log(rs);
  if (form == 2) {  // Allen-Rule-Jones: rate*^C
    R = std::pow(rs, m.k[kC]);
    dR = m.k[kC] * R / r;
  } else {  // 0: 1 + C ln rate*; 1 (Huh-Kang): + C2 (ln rate*)^2
    R = 1.0 + m.k[kC] * lr + m.k[kC2] * lr * lr;
    dR = (m.k[kC] + 2.0 * m.k[kC2] * lr) / r;
  }
}

// The flow stress f (A + B e^N) (capped) and its derivative in e; f = rate and thermal factor.
void calc_flow_stress(const MaterialConstants& m, double f, double e, double& s, double& ds) {
  const double en = e > 0.0 ? std::pow(e, m.k[kN]) : (m.k[kN] == 0.0 ? 1.0 : 0.0);
  const double h = m.k[kA] + m.k[kB] * en;
  const double dh = e > 0.0 ? m.k[kN] * m.k[kB] * std::pow(e, m.k[kN] - 1.0) : HUGE_VAL;
  const bool sat = h >= m.k[kSigsat];
  const double sy = f * (sat ? m.k[kSigsat] : h);
  const bool capped = sy >= m.k[kSigmax];
  s = capped ? m.k[kSigmax] : sy;
  ds = capped || sat ? 0.0 : f * dh;
}

// The plastic strain increment for trial von Mises stress q (0: elastic).  VP = 0: f is the
// rate and thermal factor; VP = 1: f is the thermal factor, the rate factor that of the plastic
// strain rate de / dt.
double calc_plastic_strain_increment(const MaterialConstants& m, double q, double e0, double f, double dt) {
  if (m.k[kVp] == 0.0 || !(dt > 0.0))
    return solve_radial_return(q, 3.0 * m.G, e0, [&](double e, double& s, double& ds) { calc_flow_stress(m, f, e, s, ds); });
  return solve_radial_return(q, 3.0 * m.G, e0, [&](double e, double& s, double& ds) {
    const double de = e - e0 > 0.0 ? e - e0 : 0.0;
    double R, dR, h, dh;
    calc_rate_factor(m, de / dt, R, dR);
    calc_flow_stress(m, f, e, h, dh);  // f h(e), capped
    const double sy = R * h;
    const bool capped = sy >= m.k[kSigmax];
    s = capped ? m.k[kSigmax] : sy;
    ds = capped ? 0.0 : R * dh + h * dR / dt;
  });
}

double effective_strain_rate(const double d[6]) {
  const double tr = (d[0] + d[1] + d[2]) * (1.0 / 3.0);
  const double a = d[0] - tr, b = d[1] - tr, c = d[2] - tr;
  return std::sqrt((2.0 / 3.0) * (a * a + b * b + c * c + 2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5])));
}

// The largest principal value of the symmetric stress (Voigt, tensor shears): the largest root
// of the deviator's characteristic equation (trigonometric form) plus the mean.
double calc_max_principal_stress(const double sig[6], double pm) {
  const double a = sig[0] - pm, b = sig[1] - pm, c = sig[2] - pm;
  const double j2 = 0.5 * (a * a + b * b + c * c) + sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5];
  if (!(j2 > 0.0)) return pm;
  const double j3 = a * b * c + 2.0 * sig[3] * sig[4] * sig[5] - a * sig[4] * sig[4] - b * sig[5] * sig[5] - c * sig[3] * sig[3];
  double x = 1.5 * std::sqrt(3.0) * j3 / (j2 * std::sqrt(j2));  // cos(3 theta)
  x = x > 1.0 ? 1.0 : x < -1.0 ? -1.0 : x;
  return pm + 2.0 * std::sqrt(j2 / 3.0) * std::cos(std::acos(x) / 3.0);
}

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& st) {
  update_stress_elastic(m, d, dt, st.sig);  // elastic trial
  double* sig = st.sig;
  const double p = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  const int spall = int(m.k[kSpall]);
  if (st.hist[hSpalled] != 0.0 || (m.k[kDamage] == 2.0 && st.hist[hDamage] >= 1.0)) {
    // spalled (no deviatoric stress, no tension) or failed without erosion (no deviatoric stress)
    const double pm = st.hist[hSpalled] != 0.0 ? (p > 0.0 ? 0.0 : p) : (spall == 1 && p > -m.k[kPc] ? -m.k[kPc] : p);
    sig[0] = sig[1] = sig[2] = pm;
    sig[3] = sig[4] = sig[5] = 0.0;
    return;
  }
  const double rate = effective_strain_rate(d);
  const double rs_ = rate / m.k[kEps0];
  const double lr = rs_ > 1.0 ? std::log(rs_) : 0.0;
  double R = 1.0, dR;
  if (m.k[kVp] == 0.0) calc_rate_factor(m, rate, R, dR);
  const bool thermal = m.k[kTm] > m.k[kTr];
  double tstar = 0.0, theta = 1.0;
  if (thermal) {
    tstar = st.hist[hTemperatureRise] / (m.k[kTm] - m.k[kTr]);
    theta = tstar <= 0.0 ? 1.0 : tstar >= 1.0 ? 0.0 : 1.0 - std::pow(tstar, m.k[kM]);
  }
  double s0 = sig[0] - p, s1 = sig[1] - p, s2 = sig[2] - p;
  const double q = std::sqrt(1.5 * (s0 * s0 + s1 * s1 + s2 * s2 + 2.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5])));
  const double de = calc_plastic_strain_increment(m, q, st.eps_p, R * theta, dt);
  double pm = p;
  if (spall == 1 && pm > -m.k[kPc]) pm = -m.k[kPc];  // pressure cutoff: mean stress <= -PC
  const double scale = de > 0.0 ? 1.0 - 3.0 * m.G * de / q : 1.0;
  set_scaled_deviator(pm, scale, s0, s1, s2, sig);
  if (spall >= 2 && (spall == 2 ? calc_max_principal_stress(sig, pm) >= -m.k[kPc] : pm >= -m.k[kPc])) {
    // spall (2: the largest principal stress of the updated stress reached -PC; 3: the
    // pressure reached PC): from now on a rubble, tension reset to 0
    st.hist[hSpalled] = 1.0;
    sig[0] = sig[1] = sig[2] = pm > 0.0 ? 0.0 : pm;
    sig[3] = sig[4] = sig[5] = 0.0;
  }
  if (!(de > 0.0)) return;
  const double qf = q - 3.0 * m.G * de;  // the flow stress reached
  st.eps_p += de;
  st.yielded = 1.0;
  if (thermal && m.k[kCp] > 0.0) st.hist[hTemperatureRise] += qf * de / (m.rho * m.k[kCp]);
  if (m.k[kDamage] != 0.0) {
    const double triax = qf > 0.0 ? pm / qf : 0.0;
    double ef = (m.k[kD1] + m.k[kD2] * std::exp(m.k[kD3] * triax)) * (1.0 + m.k[kD4] * lr) * (1.0 + m.k[kD5] * tstar);
    if (ef < m.k[kEfmin]) ef = m.k[kEfmin];
    st.hist[hDamage] += ef > 0.0 ? de / ef : HUGE_VAL;
  }
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_block_lane_by_lane(m, k, dt, int(m.k[kHistory]), update_point);
}

// ---- type 15

void check15(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (!(par(md, pG) > 0)) report(*find_param(t, "G"), 1003, "the shear modulus must be positive");
  if (par(md, pTm) <= par(md, pTr) && par(md, pM) != 0)
    report(*find_param(t, "TM"), 1003, "the melt temperature must exceed the room temperature TR");
  const double spall = par(md, pSpall), rateop = par(md, pRateop);
  if (spall != 0 && spall != 1 && spall != 2 && spall != 3)
    report(*find_param(t, "SPALL"), 1003, "the spall type must be 0 (2), 1, 2 or 3");
  if (rateop == 4 || rateop == 5)
    report(*find_param(t, "RATEOP"), 1102, "rate forms 4 (nonlinear rate coefficient) and 5 (Couque)");
  else if (rateop != 0 && rateop != 1 && rateop != 2 && rateop != 3)
    report(*find_param(t, "RATEOP"), 1003, "the rate form must be 0, 1, 2 or 3");
  if (rateop == 3 && !(par(md, pC) > 0))
    report(*find_param(t, "C"), 1003, "RATEOP = 3 (Cowper-Symonds) needs C > 0");
  if (rateop == 3 && !(par(md, pC2) > 0))
    report(*find_param(t, "C2/P"), 1003, "RATEOP = 3 (Cowper-Symonds) needs P > 0");
  if (par(md, pEps0) == 0) param_value(md, *find_param(t, "EPSO")) = 1.0;
}

void derive15(const MaterialData& d, const Model&, MaterialConstants& c) {
  // K from E and PR (no equation of state yet), G from the card; E and nu made consistent
  const double K = d.E / (3.0 * (1.0 - 2.0 * d.nu)), G = par(d, pG) > 0 ? par(d, pG) : d.E / (2.0 * (1.0 + d.nu));
  c.E = 9.0 * K * G / (3.0 * K + G);
  c.nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  c.beta = 1;
  c.k[kA] = par(d, pA), c.k[kB] = par(d, pB), c.k[kN] = par(d, pN), c.k[kC] = par(d, pC), c.k[kM] = par(d, pM);
  c.k[kTm] = par(d, pTm), c.k[kTr] = par(d, pTr), c.k[kEps0] = par(d, pEps0) > 0 ? par(d, pEps0) : 1.0;
  c.k[kCp] = par(d, pCp), c.k[kPc] = par(d, pPc);
  for (int i = 0; i < 5; ++i) c.k[std::size_t(kD1 + i)] = par(d, pD1 + i);
  c.k[kEfmin] = par(d, pEfmin);
  c.k[kSigmax] = HUGE_VAL, c.k[kSigsat] = HUGE_VAL;
  c.k[kHistory] = 3;
  const bool damage = par(d, pD1) != 0 || par(d, pD2) != 0, erode = par(d, pErod) == 0;
  c.k[kDamage] = damage ? (erode ? 1 : 2) : 0;
  if (damage && erode) c.fail_history = hDamage;
  c.k[kRateop] = par(d, pRateop), c.k[kC2] = par(d, pC2), c.k[kVp] = par(d, pVp);
  // LS-DYNA's SPALL 0 is 2; PC = 0 (blank): no tension limit and no spall
  c.k[kSpall] = par(d, pPc) < 0 ? (par(d, pSpall) == 0 ? 2 : par(d, pSpall)) : 0;
  c.tdel = par(d, pDtf);
  c.sigma_y = c.k[kA];
  c.eos_pc = par(d, pPc) < 0 ? par(d, pPc) : -HUGE_VAL;  // bounds an EOS pressure
  c.no_tension_hist = hSpalled;                           // ... and a spalled point's at 0
}

const char* rate_form_text(double rateop) {
  return rateop == 1 ? "1 + C ln rate* + C2 (ln rate*)^2 (Huh-Kang)"
         : rateop == 2 ? "rate*^C (Allen-Rule-Jones)"
         : rateop == 3 ? "1 + (rate / C)^(1/P) (Cowper-Symonds)"
                       : "1 + C ln rate*";
}

void echo15(std::ostream& os, const MaterialData& md) {
  echo_line(os, "flow stress", "(A + B eps_p^N) R (1 - T*^M)");
  echo_line(os, "rate factor R", rate_form_text(par(md, pRateop)));
  echo_line(os, "rate in R", par(md, pVp) != 0 ? "the plastic strain rate (VP = 1, viscoplastic)"
                                              : "the effective strain rate (VP = 0)");
  if (md.eos.form == 0) echo_line(os, "bulk modulus from", "E and PR (no equation of state)");
  if (par(md, pD1) != 0 || par(md, pD2) != 0)
    echo_line(os, "failure", par(md, pErod) == 0 ? "Johnson-Cook damage D >= 1 deletes the solid"
                                                 : "Johnson-Cook damage D >= 1 zeroes the deviatoric stress (EROD)");
  if (par(md, pPc) < 0) {
    const double sp = par(md, pSpall);
    echo_line(os, sp == 1 ? "pressure cutoff (tension)" : "spall stress", echo_number(par(md, pPc)) + " (stress)");
    echo_line(os, "spall", sp == 1   ? "1: mean stress bounded by -PC"
                           : sp == 3 ? "3: spall at pressure PC (then no deviatoric stress, no tension)"
                                     : "2: spall at largest principal stress -PC (then no deviatoric stress, no tension)");
  }
}

MaterialParam p(const char* key, int kcard, int kfield, int index, ParamCheck check = ParamCheck::none,
                const char* detail = "", const char* label = nullptr, const char* unit = "") {
  return {.key = key, .label = label, .kcard = kcard, .kfield = kfield, .fcard = kcard + 3, .fcol = 1 + 10 * kfield,
          .index = index, .check = check, .detail = detail, .unit = unit};
}

// ---- type 98

void check98(MaterialData& md, const MaterialType& t, const ParamReport&) {
  if (par(md, qEps0) == 0) param_value(md, *find_param(t, "EPSO")) = 1.0;
  if (par(md, qSigmax) == 0) param_value(md, *find_param(t, "SIGMAX")) = 1e28;
  if (par(md, qSigsat) == 0) param_value(md, *find_param(t, "SIGSAT")) = 1e28;
  if (md.fail_strain >= 1e16) md.fail_strain = 0;  // LS-DYNA's default 1e17: never
}

void derive98(const MaterialData& d, const Model&, MaterialConstants& c) {
  c.beta = 1;
  c.k[kA] = par(d, qA), c.k[kB] = par(d, qB), c.k[kN] = par(d, qN), c.k[kC] = par(d, qC);
  c.k[kEps0] = par(d, qEps0) > 0 ? par(d, qEps0) : 1.0;
  c.k[kSigmax] = par(d, qSigmax) > 0 ? par(d, qSigmax) : HUGE_VAL;
  c.k[kSigsat] = par(d, qSigsat) > 0 ? par(d, qSigsat) : HUGE_VAL;
  c.k[kVp] = par(d, qVp);
  if (d.fail_strain > 0) c.fail_strain = d.fail_strain;
  c.sigma_y = c.k[kA];
}

void echo98(std::ostream& os, const MaterialData& md) {
  echo_line(os, "flow stress", "min(min(A + B eps_p^N, SIGSAT) (1 + C ln rate*), SIGMAX)");
  if (par(md, qVp) != 0) echo_line(os, "rate in the flow stress", "the plastic strain rate (VP = 1, viscoplastic)");
  if (md.fail_strain > 0) echo_line(os, "failure plastic strain (deletion)", echo_number(md.fail_strain));
}

}  // namespace

const MaterialType& mat_johnson_cook_type() {
  static const MaterialType t{.number = 15, .name = "Johnson-Cook", .keywords = {"MAT_JOHNSON_COOK", "MAT_015"},
      .params = {
          {.key = "G", .label = "shear modulus G", .kcard = 0, .kfield = 2, .fcard = 3, .fcol = 1, .index = pG, .unit = "stress"},
          young_modulus_param(3, 11, 3), poisson_param(3, 21, 4),
          {.key = "DTF", .kcard = 0, .kfield = 5, .fcard = 3, .fcol = 31, .index = pDtf, .check = ParamCheck::non_negative,
           .detail = "must not be negative (0: no deletion by time step)"},
          {.key = "VP", .kcard = 0, .kfield = 6, .fcard = 3, .fcol = 41, .index = pVp, .check = ParamCheck::flag01,
           .detail = "must be 0 (scale the yield stress) or 1 (viscoplastic)"},
          {.key = "RATEOP", .kcard = 0, .kfield = 7, .fcard = 3, .fcol = 51, .index = pRateop},
          p("A", 1, 0, pA, ParamCheck::non_negative, "must not be negative", "A (yield stress)", "stress"),
          p("B", 1, 1, pB, ParamCheck::non_negative, "must not be negative", "B (hardening)", "stress"),
          p("N", 1, 2, pN, ParamCheck::non_negative, "must not be negative", "N (hardening exponent)"),
          p("C", 1, 3, pC, ParamCheck::non_negative, "must not be negative", "C (rate)"),
          p("M", 1, 4, pM, ParamCheck::non_negative, "must not be negative", "M (thermal softening exponent)"),
          p("TM", 1, 5, pTm, ParamCheck::none, "", "melt temperature TM", "temperature"),
          p("TR", 1, 6, pTr, ParamCheck::none, "", "room temperature TR", "temperature"),
          p("EPSO", 1, 7, pEps0, ParamCheck::non_negative, "must not be negative (0: 1)", "reference strain rate EPSO", "1/time"),
          p("CP", 2, 0, pCp, ParamCheck::non_negative, "must not be negative (0: no heating)", "specific heat CP"),
          p("PC", 2, 1, pPc, ParamCheck::none, "", "pressure cutoff PC (< 0; 0 none)", "stress"),
          p("SPALL", 2, 2, pSpall),
          p("IT", 2, 3, pIt),
          p("D1", 2, 4, pD1, ParamCheck::none, "", "damage D1"),
          p("D2", 2, 5, pD2, ParamCheck::none, "", "damage D2"),
          p("D3", 2, 6, pD3, ParamCheck::none, "", "damage D3"),
          p("D4", 2, 7, pD4, ParamCheck::none, "", "damage D4"),
          p("D5", 3, 0, pD5, ParamCheck::none, "", "damage D5"),
          p("C2/P", 3, 1, pC2, ParamCheck::none, "", "rate C2 (RATEOP 1) or P (RATEOP 3)"),
          p("EROD", 3, 2, pErod),
          p("EFMIN", 3, 3, pEfmin, ParamCheck::non_negative, "must not be negative", "minimum failure strain EFMIN"),
          {.key = "NUMINT", .kcard = 3, .kfield = 4, .index = pNumint},
      },
      .num_par = kNumPar15, .keyword_cards = 4,
      .check = check15, .derive = derive15, .echo = echo15,
      .solid = {HexKernel::deformable, update_point, update_block, true},
      .accepts_eos = true, .history = {"temperature rise", "damage", "spalled"},
  };
  return t;
}

const MaterialType& mat_simplified_johnson_cook_type() {
  static const MaterialType t{.number = 98, .name = "simplified Johnson-Cook", .keywords = {"MAT_SIMPLIFIED_JOHNSON_COOK", "MAT_098"},
      .params = {
          young_modulus_param(3, 1), poisson_param(3, 11),
          {.key = "VP", .kcard = 0, .kfield = 4, .fcard = 3, .fcol = 21, .index = qVp, .check = ParamCheck::flag01,
           .detail = "must be 0 (scale the yield stress) or 1 (viscoplastic)"},
          p("A", 1, 0, qA, ParamCheck::non_negative, "must not be negative", "A (yield stress)", "stress"),
          p("B", 1, 1, qB, ParamCheck::non_negative, "must not be negative", "B (hardening)", "stress"),
          p("N", 1, 2, qN, ParamCheck::non_negative, "must not be negative", "N (hardening exponent)"),
          p("C", 1, 3, qC, ParamCheck::non_negative, "must not be negative", "C (rate)"),
          {.key = "PSFAIL", .kcard = 1, .kfield = 4, .fcard = 4, .fcol = 41, .field = &MaterialData::fail_strain,
           .check = ParamCheck::non_negative, .detail = "must not be negative (0 or >= 1e16: no failure)"},
          p("SIGMAX", 1, 5, qSigmax, ParamCheck::non_negative, "must not be negative (0: none)", "maximum flow stress SIGMAX", "stress"),
          p("SIGSAT", 1, 6, qSigsat, ParamCheck::non_negative, "must not be negative (0: none)", "saturation stress SIGSAT", "stress"),
          p("EPSO", 1, 7, qEps0, ParamCheck::non_negative, "must not be negative (0: 1)", "reference strain rate EPSO", "1/time"),
      },
      .num_par = kNumPar98, .keyword_cards = 2,
      .check = check98, .derive = derive98, .echo = echo98,
      .solid = {HexKernel::deformable, update_point, update_block, true},
  };
  return t;
}

}  // namespace impact3d
