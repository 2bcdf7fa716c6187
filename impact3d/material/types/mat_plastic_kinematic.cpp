// Type 3, *MAT_PLASTIC_KINEMATIC: von Mises plasticity with linear isotropic / kinematic
// hardening (beta), Cowper-Symonds rate scaling of the yield stress, failure plastic strain.
// The kernels are material.cpp's update_stress_elastic_plastic and its block form.

#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

enum Par { kInitiallyElastic, kVP, kNumPar };

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s) {
  unsigned char y = s.yielded != 0.0;
  update_stress_elastic_plastic(m, d, dt, s.sig, s.back, s.eps_p, y);
  s.yielded = y;
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  // the back stress is carried only with a kinematic part (group_carries_back_stress)
  if ((1.0 - m.beta) * m.E_p != 0.0)
    update_stress_elastic_plastic_block<true>(m, k, dt);
  else
    update_stress_elastic_plastic_block<false>(m, k, dt);
}

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (md.rate_c > 0 && !(md.rate_p > 0)) report(*find_param(t, "SRP"), 1003, "must be positive when SRC (C) is given");
  if (md.fail_strain >= 1e19) md.fail_strain = 0;  // LS-DYNA's default 1e20: never
  md.initially_elastic = md.par[kInitiallyElastic] != 0;
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  c.sigma_y = d.sigma_y;
  c.E_tan = d.E_tan;
  c.beta = d.beta;
  c.initially_elastic = d.initially_elastic;
  if (d.rate_c > 0 && d.rate_p > 0) {
    c.rate_c = d.rate_c;
    c.rate_inv_p = 1.0 / d.rate_p;
  }
  if (d.fail_strain > 0) c.fail_strain = d.fail_strain;
}

void echo(std::ostream& os, const MaterialData& md) {
  const double Ep = md.E * md.E_tan / (md.E - md.E_tan);
  char beta[32], p[32];
  std::snprintf(beta, sizeof beta, "%.3f", md.beta);
  std::snprintf(p, sizeof p, "%.4g", md.rate_p);
  echo_line(os, "yield stress", echo_number(md.sigma_y) + " (stress)");
  echo_line(os, "tangent modulus", echo_number(md.E_tan) + " (stress)");
  echo_line(os, "plastic hardening modulus (derived)", echo_number(Ep) + " (stress)");
  echo_line(os, "hardening beta", std::string(beta) + (md.beta == 1 ? " (isotropic)" : md.beta == 0 ? " (kinematic)" : " (mixed)"));
  echo_line(os, "initially elastic fast path", md.initially_elastic ? "yes" : "no");
  if (md.rate_c > 0)
    echo_line(os, "strain-rate factor (Cowper-Symonds)", "1 + (rate/C)^(1/P), C " + echo_number(md.rate_c) + " (1/time), P " + p);
  if (md.fail_strain > 0) echo_line(os, "failure plastic strain (deletion)", echo_number(md.fail_strain));
}

}  // namespace

const MaterialType& mat_plastic_kinematic_type() {
  static const MaterialType t{.number = 3, .name = "elastic-plastic (linear hardening)", .keywords = {"MAT_PLASTIC_KINEMATIC", "MAT_003"},
      .params = {
          young_modulus_param(3, 1), poisson_param(4, 1),
          {.key = "SIGY", .fname = "yield stress", .kcard = 0, .kfield = 4, .fcard = 5, .fcol = 1,
           .field = &MaterialData::sigma_y, .check = ParamCheck::non_negative, .msg = 1211},
          {.key = "ETAN", .fname = "tangent modulus", .kcard = 0, .kfield = 5, .fcard = 6, .fcol = 1,
           .field = &MaterialData::E_tan, .check = ParamCheck::below_E, .msg = 1210},
          {.key = "BETA", .fname = "beta", .kcard = 0, .kfield = 6, .fcard = 7, .fcol = 1,
           .field = &MaterialData::beta, .check = ParamCheck::fraction, .msg = 1212},
          // the seed's "initially elastic" switch: fixed card 8 column 1-10; keyword decks set it
          // with the IMPACT-3D comment line INITIALLY_ELASTIC PART
          {.key = "IE", .fname = "initially elastic flag", .kcard = -1, .fcard = 8, .fcol = 1, .index = kInitiallyElastic,
           .check = ParamCheck::flag01, .msg = 1006, .detail = "0 or 1"},
          // card 2 (fixed: card 8 columns 11-40, an IMPACT-3D choice in the order of LS-DYNA's card 2)
          {.key = "SRC", .fname = "strain-rate parameter C", .kcard = 1, .kfield = 0, .fcard = 8, .fcol = 11,
           .field = &MaterialData::rate_c, .check = ParamCheck::non_negative,
           .detail = "must not be negative (0: no strain-rate effect)", .optional_write = true},
          {.key = "SRP", .fname = "strain-rate parameter P", .kcard = 1, .kfield = 1, .fcard = 8, .fcol = 21,
           .field = &MaterialData::rate_p, .optional_write = true},
          {.key = "FS", .fname = "failure plastic strain", .kcard = 1, .kfield = 2, .fcard = 8, .fcol = 31,
           .field = &MaterialData::fail_strain, .check = ParamCheck::non_negative,
           .detail = "must not be negative (0 or >= 1e19: no failure)", .optional_write = true},
          {.key = "VP", .kcard = 1, .kfield = 3, .index = kVP, .check = ParamCheck::unsupported,
           .detail = "the viscoplastic rate formulation (VP = 1); VP = 0 scales the yield stress"},
      },
      .num_par = kNumPar, .keyword_cards = 2, .one_per_card = true,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, true},
  };
  return t;
}

}  // namespace impact3d
