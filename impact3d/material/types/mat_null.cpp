// Type 9, *MAT_NULL: a fluid-like material.  Its pressure comes from its equation of state
// (required: material/eos.h), its deviatoric stress is viscous only, s = 2 MU D' (MU the dynamic
// viscosity; 0: none), recomputed every step (no elastic shear).  PC < 0 is a pressure cutoff
// (p >= PC); 0: none (an IMPACT-3D choice, as type 15's PC).  TEROD / CEROD (> 0): the solid is
// deleted (as by type 3's failure strain) in the cycle its volume ratio V/V0 (current over
// initial volume) exceeds TEROD or falls below CEROD; 0: off.  YM and PR (LS-DYNA: null shells
// and beams) are read and ignored.
//
// Fixed format (an IMPACT-3D choice: no DYNA3D manual fixes it): card 3 PC, MU, TEROD, CEROD,
// YM, PR (E10 each), the EOS type in card 1 columns 21-25 and the EOS cards after card 8.

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

enum P { pPc, pMu, pTerod, pCerod, pYm, pPr, kNumPar };
enum K { kMu };

void update_point(const MaterialConstants& m, const double d[6], double, SolidPointState& st) {
  double* sig = st.sig;
  const double p = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  const double dm = (d[0] + d[1] + d[2]) * (1.0 / 3.0);
  const double g2 = 2.0 * m.k[kMu];
  sig[0] = p + g2 * (d[0] - dm);
  sig[1] = p + g2 * (d[1] - dm);
  sig[2] = p + g2 * (d[2] - dm);
  sig[3] = g2 * d[3];
  sig[4] = g2 * d[4];
  sig[5] = g2 * d[5];
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double) {
  const double g2 = 2.0 * m.k[kMu];
  IMPACT3D_FOR_LANES {
    const double p = (k.sig[0][l] + k.sig[1][l] + k.sig[2][l]) * (1.0 / 3.0);
    const double dm = (k.d[0][l] + k.d[1][l] + k.d[2][l]) * (1.0 / 3.0);
    k.sig[0][l] = p + g2 * (k.d[0][l] - dm);
    k.sig[1][l] = p + g2 * (k.d[1][l] - dm);
    k.sig[2][l] = p + g2 * (k.d[2][l] - dm);
    k.sig[3][l] = g2 * k.d[3][l];
    k.sig[4][l] = g2 * k.d[4][l];
    k.sig[5][l] = g2 * k.d[5][l];
  }
}

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  if (par(md, pPc) > 0) report(*find_param(t, "PC"), 1003, "the pressure cutoff must not be positive (< 0: p >= PC; 0: none)");
  if (par(md, pTerod) != 0 && !(par(md, pTerod) > 1))
    report(*find_param(t, "TEROD"), 1003, "the relative volume for erosion in tension must exceed 1 (0: off)");
  if (par(md, pCerod) != 0 && !(par(md, pCerod) > 0 && par(md, pCerod) < 1))
    report(*find_param(t, "CEROD"), 1003, "the relative volume for erosion in compression must lie between 0 and 1 (0: off)");
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  c.E = 0, c.nu = 0;  // no shear stiffness; K and the wave speed come from the EOS
  c.k[kMu] = par(d, pMu);
  c.eos_pc = par(d, pPc) < 0 ? par(d, pPc) : -HUGE_VAL;
  c.vol_erode_hi = par(d, pTerod);
  c.vol_erode_lo = par(d, pCerod);
}

void echo(std::ostream& os, const MaterialData& md) {
  echo_line(os, "deviatoric stress", "2 MU D' (viscous; no shear stiffness)");
  if (par(md, pPc) < 0) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6e", par(md, pPc));
    echo_line(os, "pressure cutoff (tension)", std::string(b) + " (stress)");
  }
}

MaterialParam p(const char* key, int kfield, int index, ParamCheck check, const char* detail, const char* label,
                const char* unit = "") {
  return {.key = key, .label = label, .kcard = 0, .kfield = kfield, .fcard = 3, .fcol = 1 + 10 * (kfield - 2),
          .index = index, .check = check, .detail = detail, .unit = unit};
}

}  // namespace

const MaterialType& mat_null_type() {
  static const MaterialType t{.number = 9, .name = "null (fluid, with an equation of state)", .keywords = {"MAT_NULL", "MAT_009"},
      .params = {
          p("PC", 2, pPc, ParamCheck::none, "", "pressure cutoff PC (< 0; 0 none)", "stress"),
          p("MU", 3, pMu, ParamCheck::non_negative, "the viscosity must not be negative", "dynamic viscosity MU", "stress x time"),
          p("TEROD", 4, pTerod, ParamCheck::none, "", "erosion above relative volume TEROD (0 off)"),
          p("CEROD", 5, pCerod, ParamCheck::none, "", "erosion below relative volume CEROD (0 off)"),
          p("YM", 6, pYm, ParamCheck::ignored, "YM (LS-DYNA uses it for null shells and beams only)", nullptr),
          p("PR", 7, pPr, ParamCheck::ignored, "PR (LS-DYNA uses it for null shells and beams only)", nullptr),
      },
      .num_par = kNumPar, .keyword_cards = 1,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, false},
      .accepts_eos = true, .needs_eos = true,
  };
  return t;
}

}  // namespace impact3d
