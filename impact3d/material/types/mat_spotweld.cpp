// Type 100, *MAT_SPOTWELD (LS-DYNA *MAT_100): the material of spot-weld beams.  Von Mises
// plasticity with linear isotropic hardening (plastic hardening modulus EH; the kernel is type
// 3's with beta = 1) and the weld's failure rule, which the beam pass applies
// (solve/beam_processing.cpp, spot_weld_beam_fails): with failure resultants given (NRR NRS NRT
// MRR MSS MTT, a zero one is not used) a beam fails when
//   (max(N, 0) / NRR)^2 + (Q_s / NRS)^2 + (Q_t / NRT)^2 + (T / MRR)^2 + (M_s / MSS)^2 + (M_t / MTT)^2 >= 1
// (N the axial force, tension only; Q the shear forces, T the torque, M the bending moments in
// the beam's local axes); without them when every section point's plastic strain reaches
// EFAIL; and at the time TFAIL (> 0).  A failed beam is deleted.  Solids of this type take the
// plastic update and are deleted at EFAIL.

#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

enum Par { kEH, kDT, kTFAIL, kNRR, kNRS, kNRT, kMRR, kMSS, kMTT, kNF, kNumPar };

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s) {
  unsigned char y = s.yielded != 0.0;
  update_stress_elastic_plastic(m, d, dt, s.sig, s.back, s.eps_p, y);
  s.yielded = y;
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_stress_elastic_plastic_block<false>(m, k, dt);  // isotropic: no back stress
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  const double eh = d.par[kEH];
  c.sigma_y = d.sigma_y;
  c.E_tan = eh > 0 ? d.E * eh / (d.E + eh) : 0.0;  // EH = E E_t / (E - E_t)
  c.beta = 1;
  if (d.fail_strain > 0) c.fail_strain = d.fail_strain;
  for (int i = 0; i < 6; ++i) c.k[std::size_t(kSpotWeldNRR + i)] = d.par[std::size_t(kNRR + i)];
  c.k[kSpotWeldTFAIL] = d.par[kTFAIL];
  c.k[kSpotWeldNF] = d.par[kNF];
}

// NF: at most kSpotWeldMaxNF resultant vectors are kept (LS-DYNA's limit)
void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (md.par[kNF] > kSpotWeldMaxNF)
    report(*find_param(t, "NF"), 1003, "at most " + std::to_string(kSpotWeldMaxNF) + " resultant vectors are filtered");
}

void echo(std::ostream& os, const MaterialData& md) {
  bool resultants = false;
  for (int i = 0; i < 6; ++i) resultants = resultants || md.par[std::size_t(kNRR + i)] > 0;
  echo_line(os, "beam failure rule", resultants ? "resultants (NRR NRS NRT MRR MSS MTT)" : md.fail_strain > 0 ? "plastic strain EFAIL" : "none");
  if (md.par[kTFAIL] > 0) echo_line(os, "failure time TFAIL", echo_number(md.par[kTFAIL]));
  if (md.par[kNF] > 0) echo_line(os, "failure rule on the mean of the last NF resultants", std::to_string(int(md.par[kNF])));
}

MaterialParam force(const char* key, const char* label, int kfield, int fcol, int index) {
  return {.key = key, .label = label, .kcard = 1, .kfield = kfield, .fcard = 8, .fcol = fcol, .index = index,
          .check = ParamCheck::non_negative, .msg = 1102,
          .detail = "a negative value (a curve of the failure resultant against the strain rate) is not supported; 0: not used",
          .unit = "force", .optional_write = true};
}

}  // namespace

const MaterialType& mat_spotweld_type() {
  static const MaterialType t{.number = 100, .name = "spot weld", .keywords = {"MAT_SPOTWELD", "MAT_100"},
      // keyword card 1: MID RO E PR SIGY EH DT TFAIL; card 2: EFAIL NRR NRS NRT MRR MSS MTT NF.
      // Fixed format (an IMPACT-3D choice, no DYNA3D type 100): E card 3, PR card 4, SIGY card 5,
      // EH card 6, TFAIL card 7, card 8 EFAIL NRR NRS NRT MRR MSS MTT in columns 1-70.
      .params = {
          young_modulus_param(3, 1), poisson_param(4, 1),
          {.key = "SIGY", .fname = "yield stress", .label = "yield stress", .kcard = 0, .kfield = 4, .fcard = 5, .fcol = 1,
           .field = &MaterialData::sigma_y, .check = ParamCheck::non_negative, .msg = 1211, .unit = "stress"},
          {.key = "EH", .fname = "plastic hardening modulus", .label = "plastic hardening modulus", .kcard = 0, .kfield = 5,
           .fcard = 6, .fcol = 1, .index = kEH, .check = ParamCheck::non_negative, .detail = "must not be negative",
           .unit = "stress"},
          {.key = "DT", .kcard = 0, .kfield = 6, .index = kDT, .check = ParamCheck::unsupported,
           .detail = "mass scaling of spot-weld beams (DT)"},
          {.key = "TFAIL", .fname = "failure time", .kcard = 0, .kfield = 7, .fcard = 7, .fcol = 1, .index = kTFAIL,
           .check = ParamCheck::non_negative, .detail = "must not be negative (0: no failure by time)", .optional_write = true},
          {.key = "EFAIL", .fname = "failure plastic strain", .label = "failure plastic strain", .kcard = 1, .kfield = 0,
           .fcard = 8, .fcol = 1, .field = &MaterialData::fail_strain, .check = ParamCheck::non_negative,
           .detail = "must not be negative (0: no failure by plastic strain)", .optional_write = true},
          force("NRR", "axial failure force NRR", 1, 11, kNRR),
          force("NRS", "shear failure force NRS", 2, 21, kNRS),
          force("NRT", "shear failure force NRT", 3, 31, kNRT),
          force("MRR", "torsional failure moment MRR", 4, 41, kMRR),
          force("MSS", "bending failure moment MSS", 5, 51, kMSS),
          force("MTT", "bending failure moment MTT", 6, 61, kMTT),
          {.key = "NF", .fname = "filtered resultants NF", .kcard = 1, .kfield = 7, .fcard = 8, .fcol = 71, .index = kNF,
           .check = ParamCheck::integer, .detail = "a whole number of resultant vectors, 0 to 30", .optional_write = true},
      },
      .num_par = kNumPar, .keyword_cards = 2,
      .extra_card_feature = "the damage and failure option cards of *MAT_SPOTWELD", .one_per_card = true,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, true},
  };
  return t;
}

}  // namespace impact3d
