// Type 20, *MAT_RIGID: the solids move as one rigid body (E and nu only size the contact
// stiffness).

#include "impact3d/material/material_types.h"

namespace impact3d {

const MaterialType& mat_rigid_type() {
  static const MaterialType t = [] {
    MaterialType t;
    t.number = 20;
    t.name = "rigid";
    t.keywords = {"MAT_RIGID", "MAT_020"};
    t.params = {
        young_modulus_param(3, 1),
        poisson_param(4, 1),
        {.key = "N", .kcard = 0, .kfield = 4, .index = 0, .keyword_write = false},
        {.key = "COUPLE", .kcard = 0, .kfield = 5, .index = 1, .keyword_write = false},
        {.key = "M", .kcard = 0, .kfield = 6, .index = 2, .keyword_write = false},
        {.key = "CMO", .kcard = 1, .kfield = 0, .index = 3, .check = ParamCheck::unsupported, .detail = "rigid-body constraints"},
        {.key = "CON1", .kcard = 1, .kfield = 1, .index = 4, .check = ParamCheck::unsupported, .detail = "rigid-body constraints"},
        {.key = "CON2", .kcard = 1, .kfield = 2, .index = 5, .check = ParamCheck::unsupported, .detail = "rigid-body constraints"},
    };
    t.num_par = 6;
    t.keyword_cards = 3;  // card 3 (LCO or A1) is written blank and not read
    t.keyword_heads = {nullptr, nullptr, "$#lco or a1"};
    t.one_per_card = true;
    t.rigid = true;
    t.solid = {HexKernel::rigid, nullptr, nullptr, false};
    return t;
  }();
  return t;
}

}  // namespace impact3d
