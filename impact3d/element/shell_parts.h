#pragma once
// The pieces that the Belytschko-Tsay kernel (shell_bt.h) and the fully integrated one
// (shell_fi.h) share: the midpoint geometry, the velocities in the co-rotational frame, the
// one-point strain rates, the through-thickness stress update and its resultants, the drilling
// constraint, and the rotation of the corner forces back to the global frame.  Internal to the
// shell kernels.

#include "impact3d/element/shell_bt.h"

namespace impact3d::shell_parts {

// The mid-surface rates in the local frame: membrane d_xx, d_yy, 2 d_xy, curvature rates,
// transverse shears 2 d_xz, 2 d_yz.
struct ShellRates {
  double dxx, dyy, gxy, kxx, kyy, kxy, gxz, gyz;
};

// Stress resultants (membrane N, moments M, shears Q, per unit length) and the stress power per
// unit area.
struct ShellResultants {
  double Nxx = 0, Nyy = 0, Nxy = 0, Mxx = 0, Myy = 0, Mxy = 0, Qxz = 0, Qyz = 0;
  double work = 0;
};

// x^{n-1/2} = x^n - dt/2 v: the geometry of the step's rates (zero strain for a rigid motion).
void calc_shell_midpoint_coordinates(const ShellKernelIO& io, double xm[4][3]);

// The corner velocities in the frame (v: x y z, omega: x y).
void calc_shell_local_velocities(const ShellFrame& fr, const ShellKernelIO& io, double vl[4][3], double wl[4][2]);

// The one-point rates (B1, B2 of the frame; the transverse shears with the mean rotations).
ShellRates calc_shell_strain_rates(const ShellFrame& fm, const double vl[4][3], const double wl[4][2]);

// The drilling rates: the corners' rotation rates about e3 less the in-plane spin.
void calc_shell_drilling_rates(const ShellFrame& fm, const ShellKernelIO& io, const double vl[4][3],
                               double drate[4]);

// Stresses at the Gauss points through the thickness h (st's first g.nip points, updated when
// dt > 0) from the rates r, their resultants and the stress power per unit area.
ShellResultants calc_shell_point_stresses(const ShellGroupConstants& g, const MaterialConstants& mc,
                                          ShellMaterialKind kind, const ShellRates& r, double h, double dt,
                                          const ShellPointState& st);

// The drilling constraint's corner moments mz (kept in drill) and their reaction on the in-plane
// spin (added to fl); returns their work of the step.
double calc_shell_drilling_forces(const ShellGroupConstants& g, const ShellFrame& fr, double h, double dt,
                                  const double drate[4], double* drill, double fl[4][3], double mz[4]);

// Local corner forces fl, moments ml (x, y) and mz (about e3) to io.f, io.m (global).
void rotate_shell_forces_to_global(const ShellFrame& fr, const double fl[4][3], const double ml[4][2],
                                   const double mz[4], ShellKernelIO& io);

}  // namespace impact3d::shell_parts
