#pragma once
// Plane-stress constitutive updates for shells (sigma_zz = 0 in the shell's local frame).
// Local Voigt order of a shell integration point: xx yy xy yz zx (tensor shears); the strain
// rates d are in the same order.  The transverse shear rates d[3], d[4] arrive already scaled
// by the section's shear factor (the shear stress is SHRF times the elastic one, as LS-DYNA).
// Small functions on the caller's arrays (no heap): the per-material table of shells points
// at these.

#include <cmath>

#include "impact3d/material/material.h"

namespace impact3d {

// Plane-stress history of the elastic-plastic material at one integration point.
struct PlaneStressPlastic {
  double* back;            // back stress alpha[6] (3-D Voigt xx yy zz xy yz zx; alpha_zz != 0)
  double* eps_p;           // effective plastic strain
  unsigned char* yielded;  // 1 once the point has yielded
};

// Type 1: sigma += dt C d with the plane-stress stiffness E/(1-nu^2) [1 nu; nu 1], 2G for the
// shears.  Returns the thickness strain rate d_zz = -nu/(1-nu) (d_xx + d_yy).
double update_plane_stress_elastic(const MaterialConstants& m, const double d[5], double dt,
                                   double sig[5]);

// Type 3 (plastic-kinematic, *MAT_003): the 3-D radial return (update_stress_elastic_plastic)
// with the thickness strain rate d_zz found by secant iterations so that sigma_zz = 0
// (LS-DYNA's iterative plane-stress plasticity; iterated to |sigma_zz| <= 1e-10 (sigma_y + |sigma|),
// at most kPlaneStressIterations).  Returns d_zz.
constexpr int kPlaneStressIterations = 30;

// A trial of type 3's 3-D radial return in the plane-stress (shells) and uniaxial-stress (beams)
// iterations: the caller loads s3, run() takes the back stress, plastic strain and yield flag
// from the point's saved state h (PlaneStressPlastic, BeamPointPlastic) and updates; save()
// stores the last trial's into h.
struct KinematicTrial {
  double s3[6], back[6], eps_p = 0;
  unsigned char yielded = 0;
  template <class Saved>
  void run(const MaterialConstants& m, const double d3[6], double dt, const Saved& h) {
    for (int k = 0; k < 6; ++k) back[k] = h.back[k];
    eps_p = *h.eps_p;
    yielded = *h.yielded;
    update_stress_elastic_plastic(m, d3, dt, s3, back, eps_p, yielded);
  }
  template <class Saved>
  void save(const Saved& h) const {
    for (int k = 0; k < 6; ++k) h.back[k] = back[k];
    *h.eps_p = eps_p;
    *h.yielded = yielded;
  }
};

// The secant steps of the iterative plane stress (shells) and uniaxial stress (beams): from the
// strain rate z0 whose trial stress is f0 (trial(z) runs the update and returns the stress that
// should vanish) and a second guess z1, until |f| <= tol, the secant stalls, or after
// kPlaneStressIterations; the last trial is the result.  Returns z0 when |f0| <= tol already.
template <class Trial>
double secant_zero_stress(double z0, double f0, double z1, double tol, double dt, Trial&& trial) {
  if (std::fabs(f0) > tol) {
    if (z1 == z0) z1 = z0 + 1e-6 * (std::fabs(z0) + 1e-30 / (dt > 0 ? dt : 1.0));
    double f1 = trial(z1);
    for (int it = 0; it < kPlaneStressIterations && std::fabs(f1) > tol && f1 != f0; ++it) {
      const double z2 = z1 - f1 * (z1 - z0) / (f1 - f0);
      z0 = z1;
      f0 = f1;
      z1 = z2;
      f1 = trial(z1);
    }
    z0 = z1;
  }
  return z0;
}
double update_plane_stress_plastic_kinematic(const MaterialConstants& m, const double d[5],
                                             double dt, double sig[5],
                                             const PlaneStressPlastic& h);

// Type 24 (piecewise-linear plasticity, *MAT_024): the same iterative plane stress as type 3
// around type 24's own 3-D update (update_stress_piecewise_linear: its flow curve, EPS/ES table
// or LCSS, extended beyond the last point; its rate factor, Cowper-Symonds C/P or LCSR, of the
// 3-D rate norm sqrt(D:D) with the iterated d_zz (VP = 0: the yield stress scaled) or of the
// plastic strain rate (VP = 1, viscoplastic)).  h.back is not used (may be null).  Returns d_zz.
double update_plane_stress_piecewise_linear(const MaterialConstants& m, const double d[5],
                                            double dt, double sig[5],
                                            const PlaneStressPlastic& h);

// Type 18 (power-law plasticity, *MAT_018): the same iterative plane stress around type 18's own
// 3-D update (update_stress_power_law: k (eps_yp + eps_p)^n, Cowper-Symonds of the 3-D rate norm
// with the iterated d_zz (VP = 0) or of the plastic strain rate (VP = 1)).  h.back is not used.
double update_plane_stress_power_law(const MaterialConstants& m, const double d[5], double dt, double sig[5],
                                     const PlaneStressPlastic& h);

// Type 27 (Mooney-Rivlin rubber, *MAT_027; types/mat_mooney_rivlin.cpp): incompressible plane
// stress.  b holds the point's in-plane left Cauchy-Green tensor less I (xx yy xy) in the
// shell's co-rotational frame, updated with the in-plane rate (b <- dF b dF^T, dF = (I - dt/2
// D)^-1 (I + dt/2 D)); the thickness stretch squared is b_zz = 1 / det(b) (incompressible); the
// pressure makes sigma_zz = 0: sigma = 2 (A + B I1) b - 2 B b^2 - p I.  The shells keep their
// initial thickness, so the stress returned is this Cauchy stress times the thickness stretch
// sqrt(b_zz) (the force per unit initial thickness: resultants and the stress power per initial
// volume are those of the thinned shell).  The transverse shears are elastic with G = 2 (A + B).
// Returns d_zz = -(d_xx + d_yy).
double update_plane_stress_mooney_rivlin(const MaterialConstants& m, const double d[5], double dt, double sig[5],
                                         double b[3]);

}  // namespace impact3d
