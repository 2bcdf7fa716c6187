// Type 1, *MAT_ELASTIC: isotropic linear elasticity (hypoelastic, Jaumann rate).

#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s) {
  update_stress_elastic(m, d, dt, s.sig);
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) { update_stress_elastic_block(m, k.d, dt, k.sig); }

}  // namespace

const MaterialType& mat_elastic_type() {
  static const MaterialType t{.number = 1, .name = "elastic", .keywords = {"MAT_ELASTIC", "MAT_001"},
      .params = {
          young_modulus_param(3, 1), poisson_param(4, 1),
          {.key = "DA", .kcard = 0, .kfield = 4, .index = 0, .check = ParamCheck::ignored, .detail = "axial damping (beams)", .keyword_write = false},
          {.key = "DB", .kcard = 0, .kfield = 5, .index = 1, .check = ParamCheck::ignored, .detail = "bending damping (beams)", .keyword_write = false},
      },
      .num_par = 2, .keyword_cards = 1, .extra_card_feature = "the fluid option card (VC, CP) of *MAT_ELASTIC",
      .one_per_card = true,
      .solid = {HexKernel::deformable, update_point, update_block, false},
  };
  return t;
}

}  // namespace impact3d
