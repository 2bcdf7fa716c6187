#pragma once
// Belytschko-Tsay 4-node shell (LS-DYNA ELFORM 2): co-rotational local frame, one-point
// in-plane integration, Gauss points through the thickness, Mindlin transverse shear with a
// shear factor, Belytschko-Tsay hourglass control; triangles as degenerate quadrilaterals
// (n3 == n4).  Scalar kernels on the caller's arrays (no heap, no solver state).
//
// Local frame (Belytschko, Lin, Tsay 1984): e3 along (x3 - x1) x (x4 - x2), e1 along x2 - x1
// projected on the plane normal to e3, e2 = e3 x e1.  Stresses are stored in this frame; as it
// follows the element, they need no objective rotation.
//
// Strain rates at depth z (local components, omega the nodal angular velocities):
//   d_xx = B1.vx + z B1.wy,   d_yy = B2.vy - z B2.wx,   2 d_xy = B2.vx + B1.vy + z (B2.wy - B1.wx)
//   2 d_xz = B1.vz + sum(wy)/4,   2 d_yz = B2.vz - sum(wx)/4
// and the nodal forces and moments are their work conjugates (virtual power), so the element
// books exactly the work its forces do.
//
// Drilling constraint (Hughes and Brezzi 1989, as a penalty on the corners): the nodal
// rotation about the shell normal is tied to the element's in-plane spin
//   omega_z = (dvy/dx - dvx/dy) / 2 = sum(B1 vy - B2 vx) / 2,
// corner moment rate dM_i/dt = k_d (w_i.e3 - omega_z), k_d = drill_coef G h A / 4, with the
// moments' reaction on the translations (work conjugate).  A rigid rotation gives no moment.
// Without it, a node's rotation about the normal is free, and on a curved (faceted) mesh it
// projects on the neighbours' in-plane axes with opposite signs: it enters their twist as
// -theta_n / R and takes away the twisting stiffness of a curved shell (the Scordelis-Lo roof
// 1.47 x the reference; docs/shells.md "Shells").

#include "impact3d/material/material.h"

namespace impact3d {

constexpr int kMaxShellIntegrationPoints = 10;

// The drilling constraint's coefficient (ShellGroupConstants::drill_coef) of IMPACT-3D's shells:
// corner stiffness 0.001 G h A / 4.  Large enough to remove the mechanism (the Scordelis-Lo roof
// at 16 x 16: 1.020 x the reference with 1e-4, 0.993 with 1e-3, 0.990 with 1e-2), small enough
// to add little spurious in-plane bending stiffness (one-point spin: constant per shell, so a
// spin gradient costs k_d (dx grad omega)^2; the 6 x 1 MacNeal-Harder cantilever's in-plane tip
// displacement moves by -0.7 % at 1e-3, -7 % at 1e-2): docs/shells.md "Shells".
constexpr double kShellDrillingCoef = 0.001;

// Through-thickness Gauss-Legendre rule on [-1, 1] with n points (1-10): points and weights
// (sum 2).
void gauss_legendre_rule(int n, double* z, double* w);

// What stays the same over a group of shells (one material and section).
struct ShellGroupConstants {
  int nip = 2;
  double zeta[kMaxShellIntegrationPoints] = {}, weight[kMaxShellIntegrationPoints] = {};
  double shrf = 1.0;
  int hourglass_type = 1;   // 1-3 viscous, 4-5 stiffness
  double hourglass_coef = 0.1;
  double rho = 0, E = 0, nu = 0, G = 0;
  double c_plate = 0;       // sqrt(E / (rho (1 - nu^2))): membrane wave speed, the step's
  double drill_coef = 0;    // drilling constraint: corner stiffness drill_coef G h A / 4 (0: none)
  int elform = 2;           // LS-DYNA ELFORM: 2 this kernel, 16 the fully integrated one (shell_fi.h)
};

// One shell's data for the kernel.  x at t^n, v and w (angular velocities) at t^{n-1/2}.
struct ShellKernelIO {
  double x[4][3], v[4][3], w[4][3];
  double h = 0;             // thickness
  double dt = 0;            // dt^{n-1/2}
  // out
  double f[4][3], m[4][3];  // internal corner forces and moments (global frame)
  double area = 0;          // at t^n
  double de_ie = 0, de_hg = 0;
  double dt_e = 0;          // element step L_s / c
  double strain_rate_membrane[3] = {};  // mid-surface d_xx d_yy d_xy (local), for the material
  bool bad = false;         // zero or negative area
};

// Local frame and in-plane geometry of a shell with nodes x: e[3][3] (rows e1 e2 e3), the
// local node coordinates xl, yl (relative to node 1), area A, and the one-point derivatives
// B1 = dN/dx, B2 = dN/dy at the centre.  Returns false for a non-positive area.
struct ShellFrame {
  double e[3][3];
  double xl[4], yl[4];
  double area;
  double b1[4], b2[4];
};
bool calc_shell_frame(const double x[4][3], ShellFrame& fr);

// Per-integration-point stress update callback data: the material updates sigma (5 per point,
// local xx yy xy yz zx) from d (same order, transverse shears already times SHRF).
enum class ShellMaterialKind { elastic, plastic_kinematic, piecewise_linear, mooney_rivlin, power_law };
struct ShellPointState {
  double* sig;             // 5 per point
  double* back;            // 6 per point: the back stress (plastic-kinematic) or the left Cauchy-Green
                           // tensor less I, xx yy xy (Mooney-Rivlin, the first 3); else null
  double* eps_p;           // 1 per point (plastic-kinematic, piecewise-linear), else null
  unsigned char* yielded;  // 1 per point (plastic-kinematic, piecewise-linear), else null
  double* hgq;             // 5 hourglass resultants (stiffness forms), else null
  double* drill;           // 4 corner drilling moments (about e3), else null: no constraint
};

// The whole element: kinematics at the midpoint geometry x^{n-1/2} = x^n - dt/2 v, stress
// update at each Gauss point, resultants, forces and moments at x^n, hourglass forces,
// energies (trapezoid in stress), and the element step.
void calc_shell_bt_forces(const ShellGroupConstants& g, const MaterialConstants& mc,
                          ShellMaterialKind kind, ShellKernelIO& io, const ShellPointState& st);

// Element step length L_s = (1 + beta) A / max edge (beta 1 for a triangle, 0 otherwise).
double calc_shell_step_length(const double x[4][3], double area, bool triangle);

}  // namespace impact3d
