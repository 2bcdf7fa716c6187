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
  return secant_zero_stress(z0, f0, -0.5 * d[0], tol, dt, trial);
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
    KinematicTrial kt;
    const double z = solve_lateral_rate(m, d, dt, kt.s3, [&](double dl) {
      const double d3[6] = {d[0], dl, dl, d[1], 0.0, d[2]};
      load_stress_3d(sig, kt.s3);
      kt.run(m, d3, dt, h);
      return kt.s3[1];
    });
    sig[0] = kt.s3[0];
    sig[1] = kt.s3[3];
    sig[2] = kt.s3[5];
    kt.save(h);
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
