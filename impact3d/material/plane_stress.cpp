// Plane-stress updates of the shell materials; see plane_stress.h.

#include "impact3d/material/plane_stress.h"

#include <cmath>

#include "impact3d/material/material_types.h"

namespace impact3d {

double update_plane_stress_elastic(const MaterialConstants& m, const double d[5], double dt,
                                   double sig[5]) {
  const double c = m.E / (1.0 - m.nu * m.nu) * dt;
  const double g2 = 2.0 * m.G * dt;
  sig[0] += c * (d[0] + m.nu * d[1]);
  sig[1] += c * (d[1] + m.nu * d[0]);
  sig[2] += g2 * d[2];
  sig[3] += g2 * d[3];
  sig[4] += g2 * d[4];
  return -m.nu / (1.0 - m.nu) * (d[0] + d[1]);
}

namespace {

// LS-DYNA's iterative plane stress: the thickness strain rate d_zz for which the 3-D update
// from the saved state gives sigma_zz = 0.  trial(dzz) runs that update into the caller's trial
// state (its 3-D stress s3, xx yy zz xy yz zx) and returns sigma_zz; the last trial is the
// result.  The elastic guess first (exact when the point stays elastic), then the incompressible
// rate and secant steps to |sigma_zz| <= 1e-10 (sigma_y + |sigma|), at most
// kPlaneStressIterations.  Returns d_zz.
template <class Trial3D>
double solve_thickness_rate(const MaterialConstants& m, const double d[5], double dt, const double* s3,
                            Trial3D&& trial) {
  double z0 = -m.nu / (1.0 - m.nu) * (d[0] + d[1]);
  double f0 = trial(z0);
  const double scale = m.sigma_y + std::fabs(s3[0]) + std::fabs(s3[1]) + std::fabs(s3[3]);
  const double tol = 1e-10 * scale;
  return secant_zero_stress(z0, f0, -(d[0] + d[1]), tol, dt, trial);
}

// The 3-D stress of a shell point (sigma_zz = 0) and back.
void load_stress_3d(const double sig[5], double s3[6]) {
  s3[0] = sig[0];
  s3[1] = sig[1];
  s3[2] = 0.0;
  s3[3] = sig[2];
  s3[4] = sig[3];
  s3[5] = sig[4];
}
void store_stress_3d(const double s3[6], double sig[5]) {
  sig[0] = s3[0];
  sig[1] = s3[1];
  sig[2] = s3[3];
  sig[3] = s3[4];
  sig[4] = s3[5];
}

}  // namespace

double update_plane_stress_plastic_kinematic(const MaterialConstants& m, const double d[5],
                                             double dt, double sig[5],
                                             const PlaneStressPlastic& h) {
  KinematicTrial kt;
  const double z = solve_thickness_rate(m, d, dt, kt.s3, [&](double dzz) {
    const double d3[6] = {d[0], d[1], dzz, d[2], d[3], d[4]};
    load_stress_3d(sig, kt.s3);
    kt.run(m, d3, dt, h);
    return kt.s3[2];
  });
  store_stress_3d(kt.s3, sig);
  kt.save(h);
  return z;
}

namespace {

// The iterative plane stress around a table kernel's 3-D point update (isotropic hardening, a
// plastic strain per point, no back stress).
double update_plane_stress_with(const MaterialConstants& m, const double d[5], double dt, double sig[5],
                                const PlaneStressPlastic& h,
                                void (*update_point)(const MaterialConstants&, const double*, double, SolidPointState&)) {
  SolidPointState t;
  const double z = solve_thickness_rate(m, d, dt, t.sig, [&](double dzz) {
    const double d3[6] = {d[0], d[1], dzz, d[2], d[3], d[4]};
    load_stress_3d(sig, t.sig);
    t.eps_p = *h.eps_p;
    t.yielded = *h.yielded;
    update_point(m, d3, dt, t);
    return t.sig[2];
  });
  store_stress_3d(t.sig, sig);
  *h.eps_p = t.eps_p;
  *h.yielded = t.yielded != 0.0;
  return z;
}

}  // namespace

double update_plane_stress_piecewise_linear(const MaterialConstants& m, const double d[5], double dt, double sig[5],
                                            const PlaneStressPlastic& h) {
  return update_plane_stress_with(m, d, dt, sig, h, update_stress_piecewise_linear);
}

double update_plane_stress_power_law(const MaterialConstants& m, const double d[5], double dt, double sig[5],
                                     const PlaneStressPlastic& h) {
  return update_plane_stress_with(m, d, dt, sig, h, update_stress_power_law);
}

}  // namespace impact3d
