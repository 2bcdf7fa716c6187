// Type 24, *MAT_PIECEWISE_LINEAR_PLASTICITY: von Mises plasticity with isotropic hardening
// sigma_y(eps_p) from the EPS/ES table (up to 8 points), an LCSS curve, or (neither) SIGY and
// the linear plastic modulus E_p = E ETAN / (E - ETAN) (as type 3); rate effects: the yield
// stress scaled by R = 1 + (rate/C)^(1/P) (Cowper-Symonds) or R = LCSR(rate) (a load curve of
// the rate, taking precedence over C and P; piecewise linear, its end values held beyond its
// first and last points: an IMPACT-3D choice), with rate the norm sqrt(D:D) of the step's
// strain rate (VP = 0, as type 3) or the effective plastic strain rate de/dt of the step
// (VP = 1, viscoplastic); deletion at the plastic strain FAIL and below the element step TDEL.
//
// The radial return is exact for the piecewise-linear curve: with the trial von Mises stress
// q, the rate factor R and the curve's segment i (sigma_y = s_i + H_i (eps - e_i), the first
// and last segments extended), the plastic strain increment solves q - 3 G de = R sigma_y(eps0
// + de), i.e. de = (q - R h_i(eps0)) / (3 G + R H_i) in the segment that contains eps0 + de
// (the left side minus the right decreases strictly in de: one root, one segment).  With VP = 1
// the factor depends on de: q - 3 G de = R(de/dt) sigma_y(eps0 + de) is solved by Newton's
// method safeguarded by bisection (radial_return.h; yielding when q exceeds R(0) sigma_y(eps0)),
// and the block form runs the scalar kernel lane by lane.
//
// Fixed format (an IMPACT-3D choice; no DYNA3D manual fixes type 24): card 3 E, nu, SIGY,
// ETAN, FAIL, TDEL; card 4 C, P, LCSS, LCSR, VP; card 5 EPS1-8; card 6 ES1-8 (8 E10 each).

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"
#include "impact3d/material/radial_return.h"

namespace impact3d {

namespace {

enum Par { kTdel, kLcss, kLcsr, kVP, kLcf, kEps1, kEs1 = kEps1 + 8, kNumPar = kEs1 + 8 };
// MaterialConstants::k: the viscoplastic flag (VP = 1)
enum K { kViscoplastic };

// Load curve number id (1-based), or nullptr (0, or beyond the deck's curves).
const LoadCurve* load_curve(const Model& m, int id) {
  return id > 0 && std::size_t(id) <= m.load_curves.size() ? &m.load_curves[std::size_t(id - 1)] : nullptr;
}

// Whether any of EPS1-EPS8 is nonzero: LS-DYNA reads an all-zero EPS table as no table (the
// flow stress from SIGY and ETAN, or LCSS), whatever ES1-ES8 hold.
bool eps_table_given(const MaterialData& md) {
  for (int i = 0; i < 8; ++i)
    if (par(md, kEps1 + i) != 0) return true;
  return false;
}

// The table's points (EPS1.., ES1..): up to the first pair after the first that is all zero;
// none when EPS1-EPS8 are all zero.
int table_points(const MaterialData& md) {
  bool any = false;
  for (int i = 0; i < 8; ++i) any = any || par(md, kEs1 + i) != 0;
  if (!any || !eps_table_given(md)) return 0;
  int n = 1;
  while (n < 8 && (par(md, kEps1 + n) != 0 || par(md, kEs1 + n) != 0)) ++n;
  return n;
}

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (md.rate_c > 0 && !(md.rate_p > 0) && par(md, kLcsr) == 0) report(*find_param(t, "P"), 1003, "must be positive when C is given");
  if (md.rate_c > 0 && par(md, kLcsr) > 0) report(*find_param(t, "C"), 2006, "C and P (the curve LCSR scales the yield stress)");
  const double vp = par(md, kVP);
  if (vp != 0 && vp != 1)
    report(*find_param(t, "VP"), 1102, "VP other than 0 (the yield stress scaled by the strain rate) and 1 (viscoplastic)");
  if (md.fail_strain < 0) report(*find_param(t, "FAIL"), 1102, "a user failure subroutine (FAIL < 0)");
  if (md.fail_strain >= 1e19) md.fail_strain = 0;  // LS-DYNA's default 1e21: never
  const int n = table_points(md);
  static const char* const eps_names[] = {"EPS1", "EPS2", "EPS3", "EPS4", "EPS5", "EPS6", "EPS7", "EPS8"};
  static const char* const es_names[] = {"ES1", "ES2", "ES3", "ES4", "ES5", "ES6", "ES7", "ES8"};
  if (!eps_table_given(md))
    for (int i = 0; i < 8; ++i)
      if (par(md, kEs1 + i) != 0) {  // the first nonzero ES: not used
        report(*find_param(t, es_names[i]), 2006,
               "EPS1-EPS8 are all zero: LS-DYNA reads no table (the flow stress from SIGY and ETAN, or LCSS)");
        break;
      }
  check_flow_table(md, t, report, n, kEps1, kEs1, eps_names, es_names);
}

void derive(const MaterialData& d, const Model& m, MaterialConstants& c) {
  c.sigma_y = d.sigma_y;
  c.E_tan = d.E_tan;
  c.beta = 1;
  const int lcsr = int(par(d, kLcsr));
  c.rate_x.clear();
  c.rate_f.clear();
  c.rate_slope.clear();
  if (const LoadCurve* lc = load_curve(m, lcsr)) {
    c.rate_x = lc->t;
    c.rate_f = lc->f;
    for (std::size_t i = 0; i + 1 < lc->t.size(); ++i)
      c.rate_slope.push_back(lc->t[i + 1] > lc->t[i] ? (lc->f[i + 1] - lc->f[i]) / (lc->t[i + 1] - lc->t[i]) : 0.0);
  } else if (d.rate_c > 0 && d.rate_p > 0) {
    c.rate_c = d.rate_c;
    c.rate_inv_p = 1.0 / d.rate_p;
  }
  c.k[kViscoplastic] = par(d, kVP) == 1 && (c.rate_c > 0 || !c.rate_x.empty()) ? 1.0 : 0.0;
  if (d.fail_strain > 0) c.fail_strain = d.fail_strain;
  c.tdel = par(d, kTdel);
  c.shell_tdel = c.tdel;
  const int lcss = int(par(d, kLcss));
  const int n = table_points(d);
  c.curve_eps.clear();
  c.curve_sig.clear();
  if (const LoadCurve* lc = load_curve(m, lcss)) {
    c.curve_eps = lc->t;
    c.curve_sig = lc->f;
  } else if (n > 0) {
    for (int i = 0; i < n; ++i) {
      c.curve_eps.push_back(par(d, kEps1 + i));
      c.curve_sig.push_back(par(d, kEs1 + i));
    }
  } else {
    // bilinear: E_p = E ETAN / (E - ETAN), as type 3
    const double Ep = (d.E_tan > 0 && d.E_tan < d.E) ? d.E * d.E_tan / (d.E - d.E_tan) : 0.0;
    c.curve_eps = {0.0, 1.0};
    c.curve_sig = {d.sigma_y, d.sigma_y + Ep};
  }
  const std::size_t np = c.curve_eps.size();
  c.curve_slope.assign(np > 1 ? np - 1 : 1, 0.0);
  for (std::size_t i = 0; i + 1 < np; ++i)
    c.curve_slope[i] = (c.curve_sig[i + 1] - c.curve_sig[i]) / (c.curve_eps[i + 1] - c.curve_eps[i]);
  c.sigma_y = c.curve_sig.empty() ? 0.0 : c.curve_sig[0];
}

void echo(std::ostream& os, const MaterialData& md) {
  const int n = table_points(md);
  if (par(md, kLcss) > 0) {
    echo_line(os, "flow stress", "load curve " + std::to_string(int(par(md, kLcss))) + " (plastic strain -> stress)");
  } else if (n > 0) {
    for (int i = 0; i < n; ++i)
      echo_line(os, "flow stress point " + std::to_string(i + 1),
                "plastic strain " + echo_number(par(md, kEps1 + i)) + ", stress " + echo_number(par(md, kEs1 + i)));
  } else {
    const double Ep = (md.E_tan > 0 && md.E_tan < md.E) ? md.E * md.E_tan / (md.E - md.E_tan) : 0.0;
    echo_line(os, "yield stress", echo_number(md.sigma_y) + " (stress)");
    echo_line(os, "tangent modulus", echo_number(md.E_tan) + " (stress)");
    echo_line(os, "plastic hardening modulus (derived)", echo_number(Ep) + " (stress)");
  }
  const char* rate = par(md, kVP) == 1 ? "plastic strain rate (VP = 1, viscoplastic)" : "total strain rate sqrt(D:D) (VP = 0)";
  if (par(md, kLcsr) > 0) {
    echo_line(os, "strain-rate factor", "load curve " + std::to_string(int(par(md, kLcsr))) + " (rate -> factor)");
    echo_line(os, "rate of the factor", rate);
  } else if (md.rate_c > 0) {
    char p[32];
    std::snprintf(p, sizeof p, "%.4g", md.rate_p);
    echo_line(os, "strain-rate factor (Cowper-Symonds)", "1 + (rate/C)^(1/P), C " + echo_number(md.rate_c) + " (1/time), P " + p);
    echo_line(os, "rate of the factor", rate);
  }
  if (md.fail_strain > 0) echo_line(os, "failure plastic strain (deletion)", echo_number(md.fail_strain));
  if (par(md, kTdel) > 0) echo_line(os, "deletion below element step TDEL", echo_number(par(md, kTdel)) + " (time)");
}

double rate_norm(const double d[6]) {
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5]));
}

// The rate factor R at this rate and its slope dR (Cowper-Symonds or the LCSR curve; 1, 0
// without rate effects).
void calc_rate_factor(const MaterialConstants& m, double rate, double& R, double& dR) {
  const int n = int(m.rate_x.size());
  if (n > 0) {
    const double* x = m.rate_x.data();
    if (n == 1 || rate <= x[0]) {
      R = m.rate_f[0];
      dR = 0.0;
      return;
    }
    if (rate >= x[n - 1]) {
      R = m.rate_f[std::size_t(n - 1)];
      dR = 0.0;
      return;
    }
    int i = 0;
    while (i + 2 < n && rate > x[i + 1]) ++i;
    dR = m.rate_slope[std::size_t(i)];
    R = m.rate_f[std::size_t(i)] + dR * (rate - x[i]);
    return;
  }
  if (m.rate_c > 0.0) {
    const double r = rate / m.rate_c;
    R = 1.0 + std::pow(r, m.rate_inv_p);
    dR = r > 0.0 ? m.rate_inv_p * std::pow(r, m.rate_inv_p - 1.0) / m.rate_c : (m.rate_inv_p < 1.0 ? HUGE_VAL : m.rate_inv_p == 1.0 ? 1.0 / m.rate_c : 0.0);
    return;
  }
  R = 1.0;
  dR = 0.0;
}

// The flow stress of the hardening curve at plastic strain e and its slope (the end segments
// extended).
void calc_curve_flow(const MaterialConstants& m, double e, double& s, double& ds) {
  const int ns = int(m.curve_slope.size());
  int i = 0;
  while (i + 1 < ns && e > m.curve_eps[std::size_t(i + 1)]) ++i;
  ds = m.curve_slope[std::size_t(i)];
  s = m.curve_sig[std::size_t(i)] + ds * (e - m.curve_eps[std::size_t(i)]);
}

// VP = 1: the plastic strain increment of q - 3 G de = R(de/dt) sigma_y(e0 + de).
double calc_viscoplastic_strain_increment(const MaterialConstants& m, double q, double e0, double dt) {
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  return solve_radial_return(q, 3.0 * m.G, e0, [&](double e, double& s, double& ds) {
    double h, dh, R, dR;
    calc_curve_flow(m, e, h, dh);
    calc_rate_factor(m, (e - e0) * inv_dt, R, dR);
    s = R * h;
    ds = dR >= HUGE_VAL ? HUGE_VAL : R * dh + dR * inv_dt * h;
  });
}

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s) {
  update_stress_elastic(m, d, dt, s.sig);  // elastic trial
  const TrialDeviator t = calc_trial_deviator(s.sig);
  double de;
  if (m.k[kViscoplastic] != 0.0) {
    de = calc_viscoplastic_strain_increment(m, t.q, s.eps_p, dt);
  } else {
    double R = 1.0, dR;
    if (m.rate_c > 0.0 || !m.rate_x.empty()) calc_rate_factor(m, rate_norm(d), R, dR);
    de = calc_piecewise_linear_increment(m, t.q, s.eps_p, R);
  }
  if (!(de > 0.0)) return;
  apply_radial_return(3.0 * m.G, de, t, s.sig);
  s.eps_p += de;
  s.yielded = 1.0;
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  if (m.k[kViscoplastic] != 0.0) {  // Newton per lane: the scalar kernel lane by lane
    update_block_lane_by_lane(m, k, dt, 0, update_point);
    return;
  }
  update_stress_elastic_block(m, k.d, dt, k.sig);  // elastic trial
  alignas(64) Lanes R, q, de;
  if (m.rate_c > 0.0 || !m.rate_x.empty()) {
    IMPACT3D_FOR_LANES {
      R[l] = std::sqrt(k.d[0][l] * k.d[0][l] + k.d[1][l] * k.d[1][l] + k.d[2][l] * k.d[2][l] +
                       2.0 * (k.d[3][l] * k.d[3][l] + k.d[4][l] * k.d[4][l] + k.d[5][l] * k.d[5][l]));
    }
    for (int l = 0; l < kLanes; ++l) {
      double dR;
      calc_rate_factor(m, R[l], R[l], dR);
    }
  } else {
    IMPACT3D_FOR_LANES R[l] = 1.0;
  }
  calc_von_mises_block(k, q);
  calc_piecewise_linear_increment_block(m, k, q, R, de);
  apply_radial_return_block(3.0 * m.G, q, de, k);
}

MaterialParam table_param(const char* key, int card, int field, int index) {
  return {.key = key, .kcard = card - 1, .kfield = field, .fcard = card + 2, .fcol = 1 + 10 * field, .index = index,
          .optional_write = true};
}

}  // namespace

void update_stress_piecewise_linear(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s) {
  update_point(m, d, dt, s);
}

const MaterialType& mat_piecewise_linear_type() {
  static const MaterialType t{.number = 24, .name = "piecewise-linear plasticity", .keywords = {"MAT_PIECEWISE_LINEAR_PLASTICITY", "MAT_024"},
      .params = {
          young_modulus_param(3, 1), poisson_param(3, 11),
          {.key = "SIGY", .kcard = 0, .kfield = 4, .fcard = 3, .fcol = 21, .field = &MaterialData::sigma_y,
           .check = ParamCheck::non_negative, .msg = 1211},
          {.key = "ETAN", .kcard = 0, .kfield = 5, .fcard = 3, .fcol = 31, .field = &MaterialData::E_tan,
           .check = ParamCheck::below_E, .msg = 1210},
          {.key = "FAIL", .kcard = 0, .kfield = 6, .fcard = 3, .fcol = 41, .field = &MaterialData::fail_strain, .optional_write = true},
          {.key = "TDEL", .kcard = 0, .kfield = 7, .fcard = 3, .fcol = 51, .index = kTdel, .check = ParamCheck::non_negative,
           .detail = "must not be negative (0: no deletion by time step)", .optional_write = true},
          {.key = "C", .kcard = 1, .kfield = 0, .fcard = 4, .fcol = 1, .field = &MaterialData::rate_c,
           .check = ParamCheck::non_negative, .detail = "must not be negative (0: no strain-rate effect)", .optional_write = true},
          {.key = "P", .kcard = 1, .kfield = 1, .fcard = 4, .fcol = 11, .field = &MaterialData::rate_p, .optional_write = true},
          {.key = "LCSS", .kcard = 1, .kfield = 2, .fcard = 4, .fcol = 21, .index = kLcss, .check = ParamCheck::curve,
           .detail = "a load-curve number (0: none)", .optional_write = true},
          {.key = "LCSR", .kcard = 1, .kfield = 3, .fcard = 4, .fcol = 31, .index = kLcsr, .check = ParamCheck::curve,
           .detail = "a load-curve number (0: none; strain rate -> yield-stress factor)", .optional_write = true},
          {.key = "VP", .kcard = 1, .kfield = 4, .fcard = 4, .fcol = 41, .index = kVP,
           .detail = "VP: 0 the yield stress scaled by the strain rate, 1 viscoplastic", .optional_write = true},
          {.key = "LCF", .kcard = 1, .kfield = 5, .index = kLcf, .check = ParamCheck::unsupported,
           .detail = "the failure curve LCF"},
          table_param("EPS1", 3, 0, kEps1 + 0), table_param("EPS2", 3, 1, kEps1 + 1),
          table_param("EPS3", 3, 2, kEps1 + 2), table_param("EPS4", 3, 3, kEps1 + 3),
          table_param("EPS5", 3, 4, kEps1 + 4), table_param("EPS6", 3, 5, kEps1 + 5),
          table_param("EPS7", 3, 6, kEps1 + 6), table_param("EPS8", 3, 7, kEps1 + 7),
          table_param("ES1", 4, 0, kEs1 + 0), table_param("ES2", 4, 1, kEs1 + 1),
          table_param("ES3", 4, 2, kEs1 + 2), table_param("ES4", 4, 3, kEs1 + 3),
          table_param("ES5", 4, 4, kEs1 + 4), table_param("ES6", 4, 5, kEs1 + 5),
          table_param("ES7", 4, 6, kEs1 + 6), table_param("ES8", 4, 7, kEs1 + 7),
      },
      .num_par = kNumPar, .keyword_cards = 4,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, true},
  };
  return t;
}

}  // namespace impact3d
