// Type 18, *MAT_POWER_LAW_PLASTICITY: von Mises plasticity with isotropic power-law hardening
// sigma_y = k (eps_yp + eps_p)^n, eps_yp = (E / k)^(1 / (n - 1)) (the strain where the power
// law meets the elastic line) or, with SIGY > 0, (SIGY / k)^(1 / n); Cowper-Symonds scaling
// 1 + (rate / SRC)^(1 / SRP), VP = 0: rate = sqrt(D:D) as types 3 and 24 (the yield stress
// scaled); VP = 1 (viscoplastic): rate = d eps_p / dt, the plastic strain rate of the step,
// found with the increment; deletion at the plastic strain EPSF.  The return is
// solve_radial_return (Newton with bisection); the block form runs the scalar kernel lane by
// lane.  Shells: the plane-stress iterations of plane_stress.h around this 3-D update.
//
// Fixed format (an IMPACT-3D choice; no DYNA3D manual fixes type 18): card 3 E, PR, K, N, SRC,
// SRP; card 4 SIGY, VP, EPSF (8 E10 fields per card, LS-DYNA's order).

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"
#include "impact3d/material/radial_return.h"

namespace impact3d {

namespace {

enum Par { pK, pN, pSigy, pVp, kNumPar };
enum K { kK, kN, kEyp, kVp };

double yield_strain(const MaterialData& d) {
  const double k = par(d, pK), n = par(d, pN), sigy = par(d, pSigy);
  if (sigy > 0) return std::pow(sigy / k, 1.0 / n);
  return n < 1.0 ? std::pow(d.E / k, 1.0 / (n - 1.0)) : 0.0;
}

}  // namespace

void update_stress_power_law(const MaterialConstants& m, const double d[6], double dt, SolidPointState& st) {
  update_stress_elastic(m, d, dt, st.sig);  // elastic trial
  double* sig = st.sig;
  const bool vp = m.k[kVp] != 0.0 && m.rate_c > 0.0 && dt > 0.0;
  const double R = m.rate_c > 0.0 && !vp
                       ? 1.0 + std::pow(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] +
                                                  2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5])) / m.rate_c,
                                        m.rate_inv_p)
                       : 1.0;
  const TrialDeviator t = calc_trial_deviator(sig);
  const double q = t.q;
  const double k = m.k[kK], n = m.k[kN], eyp = m.k[kEyp];
  const double e0 = st.eps_p, rate_scale = vp ? 1.0 / (dt * m.rate_c) : 0.0;
  const double de = solve_radial_return(q, 3.0 * m.G, e0, [&](double e, double& s, double& ds) {
    const double x = eyp + e;
    if (!vp) {  // (the expressions of the VP = 0 kernel as they were: the same bits)
      s = R * k * std::pow(x, n);
      ds = x > 0.0 ? R * k * n * std::pow(x, n - 1.0) : HUGE_VAL;
      return;
    }
    const double h = k * std::pow(x, n), dh = x > 0.0 ? k * n * std::pow(x, n - 1.0) : HUGE_VAL;
    const double r = (e - e0 > 0.0 ? e - e0 : 0.0) * rate_scale;  // plastic strain rate / SRC
    const double Rv = r > 0.0 ? 1.0 + std::pow(r, m.rate_inv_p) : 1.0;
    const double dRv = r > 0.0 ? m.rate_inv_p * std::pow(r, m.rate_inv_p - 1.0) * rate_scale : HUGE_VAL;
    s = Rv * h;
    ds = dh == HUGE_VAL || dRv == HUGE_VAL ? HUGE_VAL : Rv * dh + h * dRv;
  });
  if (!(de > 0.0)) return;
  apply_radial_return(3.0 * m.G, de, t, sig);
  st.eps_p += de;
  st.yielded = 1.0;
}

namespace {

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_block_lane_by_lane(m, k, dt, 0, update_stress_power_law);
}

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (!(par(md, pK) > 0)) report(*find_param(t, "K"), 1003, "the strength coefficient must be positive");
  if (!(par(md, pN) > 0)) report(*find_param(t, "N"), 1003, "the hardening exponent must be positive");
  else if (par(md, pSigy) <= 0 && !(par(md, pN) < 1))
    report(*find_param(t, "N"), 1003, "must be below 1 when SIGY is not given (the yield strain is (E/K)^(1/(N-1)))");
  if (md.rate_c > 0 && !(md.rate_p > 0)) report(*find_param(t, "SRP"), 1003, "must be positive when SRC is given");
  if (par(md, pVp) != 0 && md.rate_c == 0) report(*find_param(t, "VP"), 2006, "VP = 1 without SRC (no rate effect)");
  if (md.fail_strain >= 1e19) md.fail_strain = 0;
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  c.beta = 1;
  c.k[kK] = par(d, pK);
  c.k[kN] = par(d, pN);
  c.k[kEyp] = c.k[kK] > 0 && c.k[kN] > 0 ? yield_strain(d) : 0.0;
  if (d.rate_c > 0 && d.rate_p > 0) {
    c.rate_c = d.rate_c;
    c.rate_inv_p = 1.0 / d.rate_p;
  }
  if (d.fail_strain > 0) c.fail_strain = d.fail_strain;
  c.sigma_y = c.k[kK] * std::pow(c.k[kEyp], c.k[kN]);
  c.k[kVp] = par(d, pVp);
}

void echo(std::ostream& os, const MaterialData& md) {
  char b[96];
  std::snprintf(b, sizeof b, "%.6e, initial yield stress %.6e", yield_strain(md),
                par(md, pK) * std::pow(yield_strain(md), par(md, pN)));
  echo_line(os, "yield strain eps_yp (derived)", b);
  if (md.rate_c > 0) {
    std::snprintf(b, sizeof b, "1 + (rate/C)^(1/P), C %.6e (1/time), P %.4g", md.rate_c, md.rate_p);
    echo_line(os, "strain-rate factor (Cowper-Symonds)", b);
    echo_line(os, "rate in the factor", par(md, pVp) != 0 ? "the plastic strain rate (VP = 1, viscoplastic)"
                                                         : "sqrt(D:D), the yield stress scaled (VP = 0)");
  }
  if (md.fail_strain > 0) {
    std::snprintf(b, sizeof b, "%.6e", md.fail_strain);
    echo_line(os, "failure plastic strain (deletion)", b);
  }
}

}  // namespace

const MaterialType& mat_power_law_type() {
  static const MaterialType t{.number = 18, .name = "power-law plasticity", .keywords = {"MAT_POWER_LAW_PLASTICITY", "MAT_018"},
      .params = {
          young_modulus_param(3, 1), poisson_param(3, 11),
          {.key = "K", .label = "strength coefficient K", .kcard = 0, .kfield = 4, .fcard = 3, .fcol = 21, .index = pK, .unit = "stress"},
          {.key = "N", .label = "hardening exponent N", .kcard = 0, .kfield = 5, .fcard = 3, .fcol = 31, .index = pN},
          {.key = "SRC", .kcard = 0, .kfield = 6, .fcard = 3, .fcol = 41, .field = &MaterialData::rate_c,
           .check = ParamCheck::non_negative, .detail = "must not be negative (0: no strain-rate effect)"},
          {.key = "SRP", .kcard = 0, .kfield = 7, .fcard = 3, .fcol = 51, .field = &MaterialData::rate_p},
          {.key = "SIGY", .label = "initial yield stress SIGY (0: from E)", .kcard = 1, .kfield = 0, .fcard = 4, .fcol = 1,
           .index = pSigy, .check = ParamCheck::non_negative, .msg = 1211, .unit = "stress"},
          {.key = "VP", .kcard = 1, .kfield = 1, .fcard = 4, .fcol = 11, .index = pVp, .check = ParamCheck::flag01,
           .detail = "must be 0 (scale the yield stress) or 1 (viscoplastic)"},
          {.key = "EPSF", .kcard = 1, .kfield = 2, .fcard = 4, .fcol = 21, .field = &MaterialData::fail_strain,
           .check = ParamCheck::non_negative, .detail = "must not be negative (0: no failure)"},
      },
      .num_par = kNumPar, .keyword_cards = 2,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_stress_power_law, update_block, true},
  };
  return t;
}

}  // namespace impact3d
