// Plane-stress updates of the shell materials; see plane_stress.h.

#include "impact3d/material/plane_stress.h"

#include <cmath>

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

// One 3-D radial return from the saved state with thickness rate dzz: the resulting 3-D stress
// (s3), back stress and plastic strain; returns sigma_zz.
struct Trial {
  double s3[6], back[6], eps_p;
  unsigned char yielded;
};

double radial_return_with_dzz(const MaterialConstants& m, const double d[5], double dzz, double dt,
                              const double sig0[5], const PlaneStressPlastic& h, Trial& t) {
  const double d3[6] = {d[0], d[1], dzz, d[2], d[3], d[4]};
  t.s3[0] = sig0[0];
  t.s3[1] = sig0[1];
  t.s3[2] = 0.0;
  t.s3[3] = sig0[2];
  t.s3[4] = sig0[3];
  t.s3[5] = sig0[4];
  for (int k = 0; k < 6; ++k) t.back[k] = h.back[k];
  t.eps_p = *h.eps_p;
  t.yielded = *h.yielded;
  update_stress_elastic_plastic(m, d3, dt, t.s3, t.back, t.eps_p, t.yielded);
  return t.s3[2];
}

}  // namespace

double update_plane_stress_plastic_kinematic(const MaterialConstants& m, const double d[5],
                                             double dt, double sig[5],
                                             const PlaneStressPlastic& h) {
  const double sig0[5] = {sig[0], sig[1], sig[2], sig[3], sig[4]};
  Trial t;
  // elastic guess: exact when the point stays elastic
  double z0 = -m.nu / (1.0 - m.nu) * (d[0] + d[1]);
  double f0 = radial_return_with_dzz(m, d, z0, dt, sig0, h, t);
  const double scale = m.sigma_y + std::fabs(t.s3[0]) + std::fabs(t.s3[1]) + std::fabs(t.s3[3]);
  const double tol = 1e-10 * scale;
  if (std::fabs(f0) > tol) {
    // second point: the incompressible (fully plastic) rate; then secant steps
    double z1 = -(d[0] + d[1]);
    if (z1 == z0) z1 = z0 + 1e-6 * (std::fabs(z0) + 1e-30 / (dt > 0 ? dt : 1.0));
    double f1 = radial_return_with_dzz(m, d, z1, dt, sig0, h, t);
    for (int it = 0; it < kPlaneStressIterations && std::fabs(f1) > tol && f1 != f0; ++it) {
      const double z2 = z1 - f1 * (z1 - z0) / (f1 - f0);
      z0 = z1;
      f0 = f1;
      z1 = z2;
      f1 = radial_return_with_dzz(m, d, z1, dt, sig0, h, t);
    }
    z0 = z1;
  }
  sig[0] = t.s3[0];
  sig[1] = t.s3[1];
  sig[2] = t.s3[3];
  sig[3] = t.s3[4];
  sig[4] = t.s3[5];
  for (int k = 0; k < 6; ++k) h.back[k] = t.back[k];
  *h.eps_p = t.eps_p;
  *h.yielded = t.yielded;
  return z0;
}

}  // namespace impact3d
