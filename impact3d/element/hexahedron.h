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
// hgs[12] is the element's hourglass state (used by types 4/5 only, zero initially).
// Returns the hourglass power for the energy books: force . velocity (>= 0) for the viscous
// forms; for the stiffness forms the mean resultant's, (Q^n + Q^{n+1}) / 2 . h = the updated
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
double calc_hex_hourglass_force(const HourglassInput& in, const double x[8], const double y[8],
                                const double z[8], const double dvdx[8], const double dvdy[8],
                                const double dvdz[8], const double vx[8], const double vy[8],
                                const double vz[8], double hgs[12], double fx[8], double fy[8],
                                double fz[8]);

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
