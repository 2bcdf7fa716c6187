// Type 20, *MAT_RIGID: the solids move as one rigid body (E and nu only size the contact
// stiffness).

#include "impact3d/material/material_types.h"

#include <cmath>

namespace impact3d {

namespace {

// CMO, CON1 and CON2: the codes each option takes.
void check(MaterialData& md, const MaterialType& type, const ParamReport& report) {
  const double cmo = md.par[3], con1 = md.par[4], con2 = md.par[5];
  auto whole = [](double v, double lo, double hi) { return v == std::floor(v) && v >= lo && v <= hi; };
  if (cmo != 0 && cmo != 1 && cmo != -1)
    report(*find_param(type, "CMO"), 1006, "-1 (constraints in a local system), 0 (none) or 1 (global constraints)");
  if (cmo == 1) {
    if (!whole(con1, 0, 7)) report(*find_param(type, "CON1"), 1006, "a translational constraint code 0-7 (1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all)");
    if (!whole(con2, 0, 7)) report(*find_param(type, "CON2"), 1006, "a rotational constraint code 0-7 (1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all)");
  } else if (cmo == -1) {
    if (!whole(con1, 0, 1e9)) report(*find_param(type, "CON1"), 1006, "a coordinate system id (CMO = -1)");
    // six digits 0/1: x y z translations, x y z rotations of the local system
    bool ok = whole(con2, 0, 111111);
    for (double v = con2; ok && v >= 1; v = std::floor(v / 10)) ok = std::fmod(v, 10) <= 1;
    if (!ok) report(*find_param(type, "CON2"), 1006, "six digits 0 or 1 (x, y, z translations, x, y, z rotations of the local system, e.g. 100001)");
  } else if (con1 != 0 || con2 != 0) {
    report(*find_param(type, "CON1"), 2006, "CON1 and CON2 act only with CMO = 1 or -1");
  }
}

}  // namespace

const MaterialType& mat_rigid_type() {
  static const MaterialType t{.number = 20, .name = "rigid", .keywords = {"MAT_RIGID", "MAT_020"},
      .params = {
          young_modulus_param(3, 1), poisson_param(4, 1),
          {.key = "N", .kcard = 0, .kfield = 4, .index = 0, .keyword_write = false},
          {.key = "COUPLE", .kcard = 0, .kfield = 5, .index = 1, .keyword_write = false},
          {.key = "M", .kcard = 0, .kfield = 6, .index = 2, .keyword_write = false},
          // constraints of the body (IMPACT-3D choice for the fixed format: cards 5-7, columns 1-10)
          {.key = "CMO", .fname = "constraint option CMO", .label = "constraint option CMO", .kcard = 1, .kfield = 0,
           .fcard = 5, .fcol = 1, .index = 3, .optional_write = true},
          {.key = "CON1", .fname = "translational constraint CON1", .label = "constraint CON1", .kcard = 1, .kfield = 1,
           .fcard = 6, .fcol = 1, .index = 4, .optional_write = true},
          {.key = "CON2", .fname = "rotational constraint CON2", .label = "constraint CON2", .kcard = 1, .kfield = 2,
           .fcard = 7, .fcol = 1, .index = 5, .optional_write = true},
      },
      // card 3 (LCO or A1) is written blank and not read
      .num_par = 6, .keyword_cards = 3, .keyword_heads = {nullptr, nullptr, "$#lco or a1"}, .one_per_card = true,
      .rigid = true, .check = check,
      .solid = {HexKernel::rigid, nullptr, nullptr, false},
  };
  return t;
}

void rigid_body_constraints(const MaterialData& md, unsigned& fix_translation, unsigned& fix_rotation) {
  fix_translation = fix_rotation = 0;
  if (md.type != 20 || md.par.size() < 6 || md.par[3] != 1) return;
  auto bits = [](int code) {
    return unsigned((bc_fixes_x(code) ? 1 : 0) | (bc_fixes_y(code) ? 2 : 0) | (bc_fixes_z(code) ? 4 : 0));
  };
  fix_translation = bits(int(md.par[4]));
  fix_rotation = bits(int(md.par[5]));
}

}  // namespace impact3d
