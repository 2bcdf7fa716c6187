#pragma once
// The 8-node hexahedron with one-point integration (Flanagan-Belytschko uniform gradient).
// Per-element kernels over gathered locals: the solver loops over elements, gathers the 8 nodal
// values into small arrays, calls these, and writes per-element corner forces.
//
// Node numbering as DYNA3D/LS-DYNA: 1-2-3-4 one face, 5-6-7-8 the opposite face, node i+4 across
// from node i; right-hand normal of 1-2-3-4 points toward 5-6-7-8 (positive volume). Arrays here
// are 0-based (index 0 = node 1).
//
// Symmetric tensors in Voigt order xx, yy, zz, xy, yz, zx with TENSOR (not engineering) shear
// components. Spin w = (W_xy, W_yz, W_zx), W = skew(L) = (L - L^T)/2.

#include <cfloat>

namespace impact3d {

// Exact volume of the trilinear hexahedron (also right for degenerate wedges/tetrahedra).
double calc_hex_volume(const double x[8], const double y[8], const double z[8]);

// Derivatives of the exact volume with respect to the nodal coordinates, dV/dx_I etc.
// The uniform gradient operator is b_iI = dV/dx_iI / V.  Returns the volume.
double calc_hex_volume_derivatives(const double x[8], const double y[8], const double z[8],
                                   double dvdx[8], double dvdy[8], double dvdz[8]);

// Largest face area of the six faces (for the characteristic length V / A_max).
double calc_hex_max_face_area(const double x[8], const double y[8], const double z[8]);

// Strain rate d (Voigt, tensor shear) and spin w from nodal velocities and b = dV/dx / V.
void calc_hex_strain_rate(const double bx[8], const double by[8], const double bz[8],
                          const double vx[8], const double vy[8], const double vz[8],
                          double d[6], double w[3]);

// Internal (stress-divergence) nodal forces f_iI = V sigma_ij b_jI, written (not added).
// sig includes the bulk viscosity -q on the diagonal.  Pass dvdx (= V b) directly.
void calc_hex_stress_force(const double sig[6], const double dvdx[8], const double dvdy[8],
                           const double dvdz[8], double fx[8], double fy[8], double fz[8]);

// Hourglass control.  Forces are ADDED to fx/fy/fz with the sign of internal forces (they are
// subtracted from external forces in the momentum equation, like the stress forces).
//   type 1     : DYNA3D viscous, base vectors Gamma, a_h = qhg * rho * c * V^(2/3) / 4
//   type 2, 3  : Flanagan-Belytschko viscous, gamma = Gamma - (Gamma . x) b  (orthogonal to
//                linear fields, so it vanishes for any linear velocity field)
//   type 4, 5  : Flanagan-Belytschko stiffness: hourglass resultants hgs[12] accumulate
//                qhg * G-scaled stiffness * dt * hourglass velocity (type 5 adds 0 viscous part)
// hgs[12] is the element's hourglass state: resultants (zero initially), see below.
// Returns the hourglass power for the energy books: force . velocity (>= 0) for the viscous
// forms (see below for how they are booked); for the stiffness forms the mean resultant's, (Q^n + Q^{n+1}) / 2 . h = the updated
// force's power less kappa dt |h|^2 / 2, which books the springs' stored energy |Q|^2 / 2 kappa
// exactly (the updated resultant's power overbooked it by (Q^{n+1} - Q^n) . h / 2 every step,
// as the internal energy would with the new stress instead of the mean).
struct HourglassInput {
  int type;          // 1..5
  double qhg;        // coefficient
  double rho;        // current density
  double c;          // sound speed
  double shear_modulus;  // G, for the stiffness forms
  double volume;
  double dt;         // time step used for the stiffness forms
};
//
// Viscous forms (1-3): hgs[12] holds the resultants Q_ia = a_h h_ia of the previous pass on entry
// (zero initially) and this pass's on return; the return value is their power Q . h.  The
// energy books (solve/element_processing.cpp) take each pass's resultants' work over the
// velocity step they act in, Q^n . (v^{n-1/2} + v^{n+1/2}) / 2 dt^n: the kinetic energy's own
// change under that force, whatever the damping per step.  So the next pass needs the old
// resultants' power at the new velocities, out->old_power = Q^{n-1} . h^n (the new shape vectors
// stand for the old ones: exact for type 1, whose vectors are constant).
//   Booking Q^n . h^n dt instead (as before, at the velocity the force was computed from) is over
//   by the factor 1 / (1 - lambda dt / 2): a mode u with u' = -lambda u advances as
//   u^{n+1/2} = (1 - lambda dt) u^{n-1/2}, so the kinetic energy falls by lambda dt (2 - lambda dt)
//   KE per step while Q . h dt = 2 lambda dt KE.
// out->dt: the viscous forms' stable step.  The update u^{n+1/2} = (1 - lambda dt) u^{n-1/2} of a
//   free hourglass mode is stable only for lambda dt <= 2 (and alternates in sign, period 2,
//   beyond 1), lambda = a_h |g|^2 / m the mode's damping rate.  For a cube of side L with its own
//   mass on its nodes (m = rho L^3 / 8, |Gamma|^2 = 8) lambda = 16 qhg c / L: the wave step L / c
//   times TSSF gives lambda dt = 16 qhg TSSF, past 2 for qhg > 0.139 at TSSF 0.9 (the manuals'
//   "values of QM above 0.15 may cause instabilities"); on a distorted solid the FB vectors
//   gamma grow with the distortion (|gamma|^2 >> 8) and the bound falls far below the wave step.
//   out->dt = 2 / lambda_max with lambda_max <= a_h mu / (M / 8), mu the Gershgorin bound of the
//   largest eigenvalue of the Gram matrix g_a . g_b (8 for Gamma) and M = rho V the solid's mass
//   (each node carries at least M / 8); the element step is the smaller of it and the wave step.
//   For the cube at qhg 0.1 it is 1.25 L / c: the wave step still rules.
//   Stiffness forms: old_power 0, dt DBL_MAX.
struct HourglassExtras {
  double old_power = 0.0;
  double dt = DBL_MAX;
};
double calc_hex_hourglass_force(const HourglassInput& in, const double x[8], const double y[8],
                                const double z[8], const double dvdx[8], const double dvdy[8],
                                const double dvdz[8], const double vx[8], const double vy[8],
                                const double vz[8], double hgs[12], double fx[8], double fy[8],
                                double fz[8], HourglassExtras* out = nullptr);

// Bulk (artificial) viscosity, compression only:
// q = rho * l * (q1 * l * trD^2 - q2 * c * trD) when trD < 0, else 0.
// l is the element's characteristic length, the same V / A_max as the time step uses: the step
// formula below is the stable step of a viscous element of that length, so the two must agree.
// (V^(1/3), as in the DYNA3D manuals, is several times V / A_max on a crushed element, and the
// damping it gives then outruns the step: the flattened elements at the axis of a refined
// Taylor bar went unstable with it.  For a cube the two are equal.)
double calc_bulk_viscosity(double rho, double c, double l, double trace_d, double q1, double q2);

// Element critical time step l / (Q + sqrt(Q^2 + c^2)), l = V / A_max,
// Q = q2 c + q1 l |trD| in compression, else 0.
double calc_hex_time_step(double volume, double max_face_area, double c, double trace_d,
                          double q1, double q2);

}  // namespace impact3d
