#pragma once
// The fully integrated selective-reduced 8-node hexahedron (LS-DYNA *SECTION_SOLID ELFORM 2):
// 2 x 2 x 2 Gauss points for the deviatoric part, the volumetric part at one point (mean
// dilatation, "B-bar").  At each Gauss point g the strain rate is
//   dbar_g = dev(d_g) + (trD / 3) I,   trD = the element's mean volumetric strain rate
// (sum over nodes of v . dV/dx / V, the one-point element's trace), so the pressure comes from
// the mean volumetric strain rate and the element cannot lock in near-incompressible flow; the
// point's material state (stress, plastic strain, history) is updated with dbar_g.  The forces
// are the work-conjugate B-bar forces
//   f_iI = sum_g J_g [ s_g,ij B_g,jI ] + (sum_g J_g p_g / V - q) dV/dx_iI,
// s_g the point's deviatoric stress, p_g its mean stress, J_g the point's Jacobian determinant
// (weight 1: the J_g sum to the exact volume V), B_g the shape-function gradients at the point.
// A uniform stress gives the one-point element's forces sigma dV/dx.  The 2 x 2 x 2 rule has
// no zero-energy modes: no hourglass control.
//
// Node numbering and Voigt order as hexahedron.h.  Gauss point g sits at the natural coordinates
// (xi, eta, zeta) of node g times 1/sqrt(3) (point g is the one nearest node g).

namespace impact3d {

constexpr int kSriPoints = 8;

// Shape-function gradients dN_I/dx (bx, by, bz) at Gauss point g in the configuration x, y, z,
// and the Jacobian determinant there (returned; <= 0 for an inverted point).
double calc_hex_sri_point_gradients(const double x[8], const double y[8], const double z[8], int g,
                                    double bx[8], double by[8], double bz[8]);

// The point's selective-reduced strain rate dbar (Voigt, tensor shear) and spin w from the
// nodal velocities, the point's gradients and the element's mean trD.
void calc_hex_sri_strain_rate(const double bx[8], const double by[8], const double bz[8],
                              const double vx[8], const double vy[8], const double vz[8],
                              double trd_mean, double d[6], double w[3]);

// Adds the point's deviatoric stress forces J_g s_g . B_g to fx, fy, fz (s_g = sig - p I) and
// returns J_g p_g, the point's share of the pressure force (the caller adds
// (sum_g J_g p_g / V - q) dV/dx once all points are in).
double add_hex_sri_point_forces(const double sig[6], const double bx[8], const double by[8],
                                const double bz[8], double detj, double fx[8], double fy[8],
                                double fz[8]);

}  // namespace impact3d
