// Type 10, *MAT_ELASTIC_PLASTIC_HYDRO: von Mises plasticity with isotropic hardening for the
// deviatoric stress (shear modulus G), the pressure from the equation of state (required:
// material/eos.h) with the pressure cutoff PC (p >= PC; 0: none, LS-DYNA's -infinity).  The
// yield stress is sigma_y(eps_p) from the EPS/ES table (up to 16 points) when one is given,
// else SIGY + EH eps_p (EH the plastic hardening modulus, as LS-DYNA defines it); beyond the
// table's last point its last slope is extended (an IMPACT-3D choice, as type 24).  FS > 0:
// the solid is deleted when its effective plastic strain reaches FS (type 3's failure); FS < 0
// and CHARL (failure by element thickness) are refused.
//
// The radial return is exact for the piecewise-linear curve (as type 24 without rate effects):
// with the trial von Mises stress q and the segment i of the curve (sigma_y = s_i + H_i (eps -
// e_i), the first and last segments extended), de = (q - h_i(eps0)) / (3 G + H_i) in the
// segment that contains eps0 + de.
//
// Fixed format (an IMPACT-3D choice: no DYNA3D manual at hand fixes it; LS-DYNA's cards in
// order, 8 E10 fields each): card 3 G, SIGY, EH, PC, FS, CHARL; card 4 EPS1-8; card 5 EPS9-16;
// card 6 ES1-8; card 7 ES9-16; the EOS type in card 1 columns 21-25 and the EOS cards after
// card 8.

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"
#include "impact3d/material/radial_return.h"

namespace impact3d {

namespace {

constexpr int kPoints = 16;
enum Par { pG, pEh, pPc, pCharl, pEps1, pEs1 = pEps1 + kPoints, kNumPar = pEs1 + kPoints };

// The table's points (EPS1.., ES1..): up to the first pair after the first that is all zero.
int table_points(const MaterialData& md) {
  bool any = false;
  for (int i = 0; i < kPoints; ++i) any = any || par(md, pEs1 + i) != 0;
  if (!any) return 0;
  int n = 1;
  while (n < kPoints && (par(md, pEps1 + n) != 0 || par(md, pEs1 + n) != 0)) ++n;
  return n;
}

const char* const kEpsNames[kPoints] = {"EPS1", "EPS2", "EPS3", "EPS4", "EPS5", "EPS6", "EPS7", "EPS8",
                                        "EPS9", "EPS10", "EPS11", "EPS12", "EPS13", "EPS14", "EPS15", "EPS16"};
const char* const kEsNames[kPoints] = {"ES1", "ES2", "ES3", "ES4", "ES5", "ES6", "ES7", "ES8",
                                       "ES9", "ES10", "ES11", "ES12", "ES13", "ES14", "ES15", "ES16"};

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (par(md, pPc) > 0) report(*find_param(t, "PC"), 1003, "the pressure cutoff must not be positive (< 0: p >= PC; 0: none)");
  if (md.fail_strain < 0)
    report(*find_param(t, "FS"), 1102, "FS < 0 (failure by element thickness with CHARL); FS > 0 is the failure plastic strain");
  const int n = table_points(md);
  if (n == 1) report(*find_param(t, "ES2"), 1003, "a table needs at least two points (or none: SIGY and EH)");
  check_flow_table(md, t, report, n, pEps1, pEs1, kEpsNames, kEsNames);
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  // G exactly (derive_material_constants: G = E / (2 (1 + nu))); K, lambda, E, nu and the wave
  // speed then come from the equation of state
  c.E = 2.0 * par(d, pG), c.nu = 0.0;
  c.beta = 1;
  if (d.fail_strain > 0) c.fail_strain = d.fail_strain;
  c.eos_pc = par(d, pPc) < 0 ? par(d, pPc) : -HUGE_VAL;
  const int n = table_points(d);
  c.curve_eps.clear();
  c.curve_sig.clear();
  if (n > 1) {
    for (int i = 0; i < n; ++i) {
      c.curve_eps.push_back(par(d, pEps1 + i));
      c.curve_sig.push_back(par(d, pEs1 + i));
    }
  } else {
    c.curve_eps = {0.0, 1.0};
    c.curve_sig = {d.sigma_y, d.sigma_y + par(d, pEh)};
  }
  const std::size_t np = c.curve_eps.size();
  c.curve_slope.assign(np - 1, 0.0);
  for (std::size_t i = 0; i + 1 < np; ++i)
    c.curve_slope[i] = (c.curve_sig[i + 1] - c.curve_sig[i]) / (c.curve_eps[i + 1] - c.curve_eps[i]);
  c.sigma_y = c.curve_sig[0];
}

void echo(std::ostream& os, const MaterialData& md) {
  const int n = table_points(md);
  if (n > 1) {
    for (int i = 0; i < n; ++i)
      echo_line(os, "flow stress point " + std::to_string(i + 1),
                "plastic strain " + echo_number(par(md, pEps1 + i)) + ", stress " + echo_number(par(md, pEs1 + i)));
  } else {
    echo_line(os, "yield stress", echo_number(md.sigma_y) + " (stress)");
    echo_line(os, "plastic hardening modulus EH", echo_number(par(md, pEh)) + " (stress)");
  }
  if (par(md, pPc) < 0) echo_line(os, "pressure cutoff (tension)", echo_number(par(md, pPc)) + " (stress)");
  if (md.fail_strain > 0) echo_line(os, "failure plastic strain (deletion)", echo_number(md.fail_strain));
}

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s) {
  update_stress_elastic(m, d, dt, s.sig);  // elastic trial (the mean stress: the EOS's, after)
  const TrialDeviator t = calc_trial_deviator(s.sig);
  const double de = calc_piecewise_linear_increment(m, t.q, s.eps_p, 1.0);
  if (!(de > 0.0)) return;
  apply_radial_return(3.0 * m.G, de, t, s.sig);
  s.eps_p += de;
  s.yielded = 1.0;
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_stress_elastic_block(m, k.d, dt, k.sig);  // elastic trial
  alignas(64) Lanes q, de, R;
  calc_von_mises_block(k, q);
  IMPACT3D_FOR_LANES R[l] = 1.0;
  calc_piecewise_linear_increment_block(m, k, q, R, de);
  apply_radial_return_block(3.0 * m.G, q, de, k);
}

// EPSi / ESi: keyword cards 2-5 (EPS1-8, EPS9-16, ES1-8, ES9-16), fixed cards 4-7.
MaterialParam table_param(const char* key, int index) {
  const int i = index < pEs1 ? index - pEps1 : index - pEs1;
  const int card = (index < pEs1 ? 1 : 3) + i / 8;
  return {.key = key, .kcard = card, .kfield = i % 8, .fcard = card + 3, .fcol = 1 + 10 * (i % 8), .index = index,
          .optional_write = true};
}

// The card 1 rows followed by the EPS and ES tables.
std::vector<MaterialParam> with_tables(std::vector<MaterialParam> rows) {
  for (int i = 0; i < kPoints; ++i) rows.push_back(table_param(kEpsNames[i], pEps1 + i));
  for (int i = 0; i < kPoints; ++i) rows.push_back(table_param(kEsNames[i], pEs1 + i));
  return rows;
}

}  // namespace

const MaterialType& mat_elastic_plastic_hydro_type() {
  static const MaterialType t{.number = 10, .name = "elastic-plastic hydrodynamic (with an equation of state)",
      .keywords = {"MAT_ELASTIC_PLASTIC_HYDRO", "MAT_010"},
      .params = with_tables({
          {.key = "G", .label = "shear modulus G", .kcard = 0, .kfield = 2, .fcard = 3, .fcol = 1, .index = pG,
           .check = ParamCheck::positive, .detail = "the shear modulus must be positive", .unit = "stress"},
          {.key = "SIGY", .label = "yield stress SIGY (without a table)", .kcard = 0, .kfield = 3, .fcard = 3, .fcol = 11,
           .field = &MaterialData::sigma_y, .check = ParamCheck::non_negative, .msg = 1211, .unit = "stress"},
          {.key = "EH", .kcard = 0, .kfield = 4, .fcard = 3, .fcol = 21, .index = pEh, .check = ParamCheck::non_negative,
           .detail = "the plastic hardening modulus must not be negative"},
          {.key = "PC", .kcard = 0, .kfield = 5, .fcard = 3, .fcol = 31, .index = pPc},
          {.key = "FS", .kcard = 0, .kfield = 6, .fcard = 3, .fcol = 41, .field = &MaterialData::fail_strain,
           .optional_write = true},
          {.key = "CHARL", .kcard = 0, .kfield = 7, .fcard = 3, .fcol = 51, .index = pCharl, .check = ParamCheck::unsupported,
           .detail = "failure by element thickness (CHARL)", .optional_write = true},
      }),
      .num_par = kNumPar, .keyword_cards = 5,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, true},
      .accepts_eos = true, .needs_eos = true,
  };
  return t;
}

}  // namespace impact3d
