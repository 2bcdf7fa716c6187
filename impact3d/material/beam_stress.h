#pragma once
// Stress updates of beam integration points: uniaxial stress with transverse shear (sigma_yy =
// sigma_zz = sigma_yz = 0 in the beam's local frame r s t).  A point's stress is (xx, xy, xz)
// with tensor shears; the strain rates d arrive in the same order, the shears already times
// the section's shear factor (as the shells' transverse shear, plane_stress.h).

#include "impact3d/material/material.h"

namespace impact3d {

enum class BeamMaterialKind { elastic, plastic_kinematic, piecewise_linear };

// History of an elastic-plastic beam point.
struct BeamPointPlastic {
  double* back;            // back stress alpha[6] (3-D Voigt; plastic-kinematic only, else null)
  double* eps_p;           // effective plastic strain
  unsigned char* yielded;  // 1 once the point has yielded
};

// Type 1: sigma_xx += dt E d_xx, sigma_xy += dt 2G d_xy, sigma_xz += dt 2G d_xz.
void update_beam_point_elastic(const MaterialConstants& m, const double d[3], double dt, double sig[3]);

// Types 3 and 24: the 3-D update of the type (update_stress_elastic_plastic, or
// update_stress_piecewise_linear) with the lateral strain rates d_yy = d_zz found by secant
// iterations so that sigma_yy = 0 (then sigma_zz = 0 too: the state is symmetric in y and z),
// as the shells' iterative plane stress (plane_stress.h: to |sigma_yy| <= 1e-10 (sigma_y +
// |sigma|), at most kPlaneStressIterations).  Returns the lateral strain rate.
double update_beam_point_plastic(BeamMaterialKind kind, const MaterialConstants& m, const double d[3], double dt,
                                 double sig[3], const BeamPointPlastic& h);

}  // namespace impact3d
