// Stress updates of beam integration points; see beam_stress.h.

#include "impact3d/material/beam_stress.h"

#include <cmath>

#include "impact3d/material/material_types.h"
#include "impact3d/material/plane_stress.h"  // kPlaneStressIterations

namespace impact3d {

void update_beam_point_elastic(const MaterialConstants& m, const double d[3], double dt, double sig[3]) {
  sig[0] += dt * m.E * d[0];
  sig[1] += dt * 2.0 * m.G * d[1];
  sig[2] += dt * 2.0 * m.G * d[2];
}

namespace {

// The lateral strain rate z (d_yy = d_zz = z) for which the 3-D update gives sigma_yy = 0.
// trial(z) runs the update from the saved state into the caller's trial state s3 and returns
// sigma_yy; the last trial is the result.  The elastic guess first (exact while elastic), then
// the incompressible rate and secant steps.
template <class Trial3D>
double solve_lateral_rate(const MaterialConstants& m, const double d[3], double dt, const double* s3, Trial3D&& trial) {
  double z0 = -m.nu * d[0];
  double f0 = trial(z0);
  const double scale = m.sigma_y + std::fabs(s3[0]) + std::fabs(s3[3]) + std::fabs(s3[5]);
  const double tol = 1e-10 * scale;
  if (std::fabs(f0) > tol) {
    double z1 = -0.5 * d[0];
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

void load_stress_3d(const double sig[3], double s3[6]) {
  s3[0] = sig[0];
  s3[1] = s3[2] = 0.0;
  s3[3] = sig[1];
  s3[4] = 0.0;
  s3[5] = sig[2];
}

}  // namespace

double update_beam_point_plastic(BeamMaterialKind kind, const MaterialConstants& m, const double d[3], double dt,
                                 double sig[3], const BeamPointPlastic& h) {
  if (kind == BeamMaterialKind::plastic_kinematic) {
    double s3[6], back[6], eps_p = 0;
    unsigned char yielded = 0;
    const double z = solve_lateral_rate(m, d, dt, s3, [&](double dl) {
      const double d3[6] = {d[0], dl, dl, d[1], 0.0, d[2]};
      load_stress_3d(sig, s3);
      for (int k = 0; k < 6; ++k) back[k] = h.back[k];
      eps_p = *h.eps_p;
      yielded = *h.yielded;
      update_stress_elastic_plastic(m, d3, dt, s3, back, eps_p, yielded);
      return s3[1];
    });
    sig[0] = s3[0];
    sig[1] = s3[3];
    sig[2] = s3[5];
    for (int k = 0; k < 6; ++k) h.back[k] = back[k];
    *h.eps_p = eps_p;
    *h.yielded = yielded;
    return z;
  }
  SolidPointState t;
  const double z = solve_lateral_rate(m, d, dt, t.sig, [&](double dl) {
    const double d3[6] = {d[0], dl, dl, d[1], 0.0, d[2]};
    load_stress_3d(sig, t.sig);
    t.eps_p = *h.eps_p;
    t.yielded = *h.yielded;
    update_stress_piecewise_linear(m, d3, dt, t);
    return t.sig[1];
  });
  sig[0] = t.sig[0];
  sig[1] = t.sig[3];
  sig[2] = t.sig[5];
  *h.eps_p = t.eps_p;
  *h.yielded = t.yielded != 0.0;
  return z;
}

}  // namespace impact3d
