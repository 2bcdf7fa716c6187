#pragma once
// The Belytschko-Tsay shell (shell_bt.h) in block form: calc_shell_bt_forces written for a
// block of kLanes shells at once, one SIMD lane per shell (struct-of-arrays [..][lane]).  Every
// lane does exactly the scalar kernel's operations in the same order, so a block gives the same
// bits as calc_shell_bt_forces shell by shell (tests/element/test_shell_block.cpp checks this),
// as the solids' HexBlock does for the hexahedron.  Requires IEEE arithmetic without contraction
// (-ffp-contract=off, set in CMakeLists.txt).
//
// Materials: elastic (type 1) in lanes; the plastic ones through the material's solid block
// kernel (MaterialType::solid.update_block on a MaterialPointBlock of 3-D points, the code the
// solids run): LS-DYNA's iterative plane stress (plane_stress.h: secant iterations on the
// thickness strain rate until sigma_zz = 0) runs lane by lane in step, each lane iterating as
// long as its scalar twin would and keeping its own last trial.  The element pass (solve/shell_processing.cpp) gathers a
// block, calls calc_shell_bt_forces_block, and stores the results unless a lane is bad (a
// non-positive area): such a block, a block with a deleted shell, and a group's last shells
// short of a block go through the scalar kernel shell by shell (the same bits either way).

#include "impact3d/element/shell_bt.h"
#include "impact3d/material/material_point_block.h"

namespace impact3d {

// The material's 3-D block update (MaterialType::solid.update_block).
using MaterialBlockUpdate = void (*)(const MaterialConstants&, MaterialPointBlock&, double dt);

// The frame of ShellFrame in lanes, and a lane's failure (1: zero or negative area).
struct alignas(64) ShellFrameLanes {
  Lanes e[3][3];
  Lanes xl[4], yl[4];
  Lanes area;
  Lanes b1[4], b2[4];
  Lanes bad;
};

// A block's working set: gathered data, point state, results.  Reused block after block.
struct alignas(64) ShellBlock {
  // in: x^n, v and omega at t^{n-1/2} [node][component][lane], thickness
  Lanes x[4][3], v[4][3], w[4][3];
  Lanes h;
  // in and out: the points' state through the thickness (what the material carries), the
  // hourglass resultants (stiffness forms) and the corner drilling moments
  Lanes sig[kMaxShellIntegrationPoints][5];
  Lanes back[kMaxShellIntegrationPoints][6];
  Lanes eps_p[kMaxShellIntegrationPoints], yielded[kMaxShellIntegrationPoints];
  Lanes hgq[5], drill[4];
  // out
  Lanes f[4][3], m[4][3];    // corner forces and moments (global)
  Lanes area, de_ie, de_hg, dt_e;
  Lanes bad;                 // 1: a frame with a non-positive area (the results are not valid)
  // work
  ShellFrameLanes fm, fr;    // frames at x^{n-1/2} and x^n
  Lanes xm[4][3];
  Lanes vl[4][3], wl[4][2], drate[4];
  Lanes dxx, dyy, gxy, kxx, kyy, kxy, gxz, gyz;      // mid-surface rates (ShellRates)
  Lanes Nxx, Nyy, Nxy, Mxx, Myy, Mxy, Qxz, Qyz, work;  // resultants (ShellResultants)
  Lanes fl[4][3], ml[4][2], mz[4];
  MaterialPointBlock point;  // the plastic materials' 3-D trial points
};

// What a group's block kernel needs besides ShellGroupConstants: the material, its kind (elastic,
// plastic_kinematic or piecewise_linear), its block update (plastic kinds), whether the points
// carry a back stress and the shells hourglass resultants.
struct ShellBlockMaterial {
  const MaterialConstants* mc = nullptr;
  ShellMaterialKind kind = ShellMaterialKind::elastic;
  MaterialBlockUpdate update_block = nullptr;
  bool has_back = false;
  bool has_hgq = false;
};

// Whether the block kernel covers this material (the group then runs in blocks): elastic,
// plastic-kinematic without rate effects, piecewise-linear.
bool shell_block_covers(ShellMaterialKind kind, const MaterialConstants& mc);

// calc_shell_bt_forces on the block's kLanes shells (dt uniform).
void calc_shell_bt_forces_block(const ShellGroupConstants& g, const ShellBlockMaterial& mat, double dt,
                                ShellBlock& b);

}  // namespace impact3d
