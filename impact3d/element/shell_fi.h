#pragma once
// Fully integrated 4-node shell (LS-DYNA ELFORM 16): the Belytschko-Tsay kernel's co-rotational
// frame, midpoint kinematics, through-thickness Gauss points and drilling constraint
// (shell_bt.h), with 2 x 2 in-plane Gauss points instead of one, each with the section's NIP
// points through the thickness, and the transverse shear by assumed natural strains (Bathe and
// Dvorkin 1985, MITC4) so that thin shells do not lock.  No hourglass modes: no hourglass
// control (the part's hourglass settings are ignored, as LS-DYNA ignores them for ELFORM 16).
//
// In the frame, with the bilinear map x(r, s), y(r, s) of the local node coordinates
// (nodes 1-4 at (r, s) = (-1,-1), (1,-1), (1,1), (-1,1)) and at each Gauss point
// (r, s) = (+-1/sqrt3, +-1/sqrt3), Jacobian J = [x_r y_r; x_s y_s], N_x, N_y = J^-1 [N_r; N_s]:
//   d_xx = N_x.vx + z N_x.wy,  d_yy = N_y.vy - z N_y.wx,  2 d_xy = N_y.vx + N_x.vy + z (N_y.wy - N_x.wx)
// and the transverse shears from the covariant ones tied at the edge midpoints
//   g_r = dvz/dr + x_r wy - y_r wx  at A (0,-1), C (0,1),   g_s likewise at B (-1,0), D (1,0)
//   g_r(r, s) = (1 - s)/2 g_r^A + (1 + s)/2 g_r^C,   g_s(r, s) = (1 - r)/2 g_s^B + (1 + r)/2 g_s^D
//   [2 d_xz, 2 d_yz] = J^-1 [g_r, g_s]
// (on an edge, dvz/dr is the difference of its nodes' vz over 2, the rotations their mean).  The
// corner forces and moments are the work conjugates at x^n, each point weighted by det J.
//
// Integration points per shell: 5 sets of NIP (ShellState::pt_base; a run of width 1), set 0 the mean of the four
// Gauss points' stresses, plastic strains, back stresses (what the plot database, the histories
// and the failure check read: a shell fails when the mean plastic strain of every layer has
// reached FS), sets 1-4 the Gauss points in the order of the nodes.

#include "impact3d/element/shell_bt.h"

namespace impact3d {

// Integration-point sets per through-thickness point of an ELFORM 16 shell: the mean and the four
// in-plane Gauss points.
constexpr int kShellFiPointSets = 5;

// The points (through-thickness count nip) that a shell of formulation elform keeps.
inline int shell_points_per_shell(int elform, int nip) { return elform == 16 ? kShellFiPointSets * nip : nip; }

// The whole ELFORM 16 element: as calc_shell_bt_forces, with st holding kShellFiPointSets x
// g.nip points (st.hgq unused).
void calc_shell_fi_forces(const ShellGroupConstants& g, const MaterialConstants& mc, ShellMaterialKind kind,
                          ShellKernelIO& io, const ShellPointState& st);

}  // namespace impact3d
