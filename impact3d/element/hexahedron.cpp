// The 8-node hexahedron with one-point integration (Flanagan & Belytschko, IJNME 17 (1981)
// 679-706, "uniform strain hexahedron"); see hexahedron.h for the contract.
//
// Everything here is straight-line code on the caller's small arrays: no heap, no globals, no
// exceptions, so the functions can be called from inside an OpenMP element loop.

#include "impact3d/element/hexahedron.h"

#include "impact3d/element/cbrt_positive.h"
#include "impact3d/element/hex_volume_derivative.h"

#include <cfloat>
#include <cmath>

namespace impact3d {

namespace {

// Scalar triple product a . (b x c).
inline double triple(double ax, double ay, double az, double bx, double by, double bz, double cx,
                     double cy, double cz) {
  return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
}

// Area of a (possibly warped) quadrilateral face: half the norm of the cross product of its
// diagonals (the exact area of a planar quad, the projected "vector area" of a warped one;
// right for faces degenerated to triangles too).
inline double quad_area(const double x[8], const double y[8], const double z[8], int a, int b,
                        int c, int d) {
  const double d1x = x[c] - x[a], d1y = y[c] - y[a], d1z = z[c] - z[a];
  const double d2x = x[d] - x[b], d2y = y[d] - y[b], d2z = z[d] - z[b];
  const double nx = d1y * d2z - d1z * d2y;
  const double ny = d1z * d2x - d1x * d2z;
  const double nz = d1x * d2y - d1y * d2x;
  return 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
}

// The four hourglass base vectors Gamma_a (Flanagan-Belytschko / DYNA3D), in the DYNA3D node
// order with natural coordinates node 1 (-1,-1,-1), 2 (1,-1,-1), 3 (1,1,-1), 4 (-1,1,-1),
// 5..8 the same at zeta = +1: Gamma_1 = eta zeta, Gamma_2 = zeta xi, Gamma_3 = xi eta,
// Gamma_4 = xi eta zeta evaluated at the nodes.
constexpr double kGamma[4][8] = {
    {1., 1., -1., -1., -1., -1., 1., 1.},
    {1., -1., -1., 1., -1., 1., 1., -1.},
    {1., -1., 1., -1., 1., -1., 1., -1.},
    {-1., 1., -1., 1., 1., -1., 1., -1.},
};

// sum_I w_I (x_I, y_I, z_I) over the 8 nodes, summed in node order: the contraction of a
// node vector (a hourglass base vector, a shape vector) with the coordinates or velocities.
inline void node_contraction(const double w[8], const double x[8], const double y[8], const double z[8], double& sx,
                             double& sy, double& sz) {
  double ax = 0.0, ay = 0.0, az = 0.0;
  for (int n = 0; n < 8; ++n) {
    ax += w[n] * x[n];
    ay += w[n] * y[n];
    az += w[n] * z[n];
  }
  sx = ax;
  sy = ay;
  sz = az;
}

// Flanagan-Belytschko hourglass shape vectors gamma_a = Gamma_a - (Gamma_a . x_i) b_i, with
// b = dV/dx / V.  They are orthogonal to every linear field (constant and linear in x).
inline void fb_gamma(const double x[8], const double y[8], const double z[8],
                     const double dvdx[8], const double dvdy[8], const double dvdz[8],
                     double volume, double g[4][8]) {
  const double rv = 1.0 / volume;
  for (int a = 0; a < 4; ++a) {
    double gx, gy, gz;
    node_contraction(kGamma[a], x, y, z, gx, gy, gz);
    gx *= rv;
    gy *= rv;
    gz *= rv;
    for (int n = 0; n < 8; ++n) {
      g[a][n] = kGamma[a][n] - (gx * dvdx[n] + gy * dvdy[n] + gz * dvdz[n]);
    }
  }
}

// Hourglass velocities h_ia = sum_I v_iI g_aI, stored h[3a + i].
inline void hourglass_rates(const double g[4][8], const double vx[8], const double vy[8],
                            const double vz[8], double h[12]) {
  for (int a = 0; a < 4; ++a) node_contraction(g[a], vx, vy, vz, h[3 * a], h[3 * a + 1], h[3 * a + 2]);
}

// f_iI += sum_a Q_ia g_aI; returns sum of (added force) . v.
inline double add_hourglass_forces(const double g[4][8], const double q[12], const double vx[8],
                                   const double vy[8], const double vz[8], double fx[8],
                                   double fy[8], double fz[8]) {
  double power = 0.0;
  for (int n = 0; n < 8; ++n) {
    double ax = 0.0, ay = 0.0, az = 0.0;
    for (int a = 0; a < 4; ++a) {
      ax += q[3 * a] * g[a][n];
      ay += q[3 * a + 1] * g[a][n];
      az += q[3 * a + 2] * g[a][n];
    }
    fx[n] += ax;
    fy[n] += ay;
    fz[n] += az;
    power += ax * vx[n] + ay * vy[n] + az * vz[n];
  }
  return power;
}

// The stable step of the viscous hourglass forms, 2 / lambda_max (hexahedron.h).  lambda_max
// <= a_h mu / (M / 8): mu bounds the largest eigenvalue of the Gram matrix g_a . g_b of the four
// shape vectors (Gershgorin: the largest row sum of its magnitudes; 8 for the base vectors
// Gamma, which are orthogonal), M / 8 bounds every corner's nodal mass from below (each node
// carries at least this solid's eighth).  So dt = 2 M / (8 a_h mu) = M / (4 a_h mu).
inline double viscous_hourglass_step(const double g[4][8], double ah, double mass) {
  double gram[4][4];
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      double s = 0.0;
      for (int n = 0; n < 8; ++n) s += g[a][n] * g[b][n];
      gram[a][b] = gram[b][a] = s;
    }
  double mu = 0.0;
  for (int a = 0; a < 4; ++a) {
    const double row = std::fabs(gram[a][0]) + std::fabs(gram[a][1]) + std::fabs(gram[a][2]) + std::fabs(gram[a][3]);
    mu = row > mu ? row : mu;
  }
  const double den = 4.0 * ah * mu;
  return den > 0.0 ? mass / den : DBL_MAX;
}

}  // namespace

double calc_hex_volume(const double x[8], const double y[8], const double z[8]) {
  // Exact volume of the trilinear hexahedron as three triple products (LULESH CalcElemVolume).
  const double dx61 = x[6] - x[1], dy61 = y[6] - y[1], dz61 = z[6] - z[1];
  const double dx70 = x[7] - x[0], dy70 = y[7] - y[0], dz70 = z[7] - z[0];
  const double dx63 = x[6] - x[3], dy63 = y[6] - y[3], dz63 = z[6] - z[3];
  const double dx20 = x[2] - x[0], dy20 = y[2] - y[0], dz20 = z[2] - z[0];
  const double dx50 = x[5] - x[0], dy50 = y[5] - y[0], dz50 = z[5] - z[0];
  const double dx64 = x[6] - x[4], dy64 = y[6] - y[4], dz64 = z[6] - z[4];
  const double dx31 = x[3] - x[1], dy31 = y[3] - y[1], dz31 = z[3] - z[1];
  const double dx72 = x[7] - x[2], dy72 = y[7] - y[2], dz72 = z[7] - z[2];
  const double dx43 = x[4] - x[3], dy43 = y[4] - y[3], dz43 = z[4] - z[3];
  const double dx57 = x[5] - x[7], dy57 = y[5] - y[7], dz57 = z[5] - z[7];
  const double dx14 = x[1] - x[4], dy14 = y[1] - y[4], dz14 = z[1] - z[4];
  const double dx25 = x[2] - x[5], dy25 = y[2] - y[5], dz25 = z[2] - z[5];
  const double v = triple(dx31 + dx72, dy31 + dy72, dz31 + dz72, dx63, dy63, dz63, dx20, dy20,
                          dz20) +
                   triple(dx43 + dx57, dy43 + dy57, dz43 + dz57, dx64, dy64, dz64, dx70, dy70,
                          dz70) +
                   triple(dx14 + dx25, dy14 + dy25, dz14 + dz25, dx61, dy61, dz61, dx50, dy50,
                          dz50);
  return v * (1.0 / 12.0);
}

double calc_hex_volume_derivatives(const double x[8], const double y[8], const double z[8],
                                   double dvdx[8], double dvdy[8], double dvdz[8]) {
#pragma GCC unroll 8
  for (const auto& c : kVolumeDerivativeNeighbours)
    volume_derivative([x](int n) { return x[n]; }, [y](int n) { return y[n]; }, [z](int n) { return z[n]; }, c + 1,
                      dvdx[c[0]], dvdy[c[0]], dvdz[c[0]]);
  // V is homogeneous of degree one in the x coordinates alone (a stretch in x scales it), so
  // V = sum_I x_I dV/dx_I exactly; this costs 8 multiply-adds and uses the same numbers.
  double v = 0.0;
  for (int n = 0; n < 8; ++n) v += x[n] * dvdx[n];
  return v;
}

double calc_hex_max_face_area(const double x[8], const double y[8], const double z[8]) {
  double a = quad_area(x, y, z, 0, 1, 2, 3);
  double b = quad_area(x, y, z, 4, 5, 6, 7);
  if (b > a) a = b;
  b = quad_area(x, y, z, 0, 1, 5, 4);
  if (b > a) a = b;
  b = quad_area(x, y, z, 1, 2, 6, 5);
  if (b > a) a = b;
  b = quad_area(x, y, z, 2, 3, 7, 6);
  if (b > a) a = b;
  b = quad_area(x, y, z, 3, 0, 4, 7);
  if (b > a) a = b;
  return a;
}

void calc_hex_strain_rate(const double bx[8], const double by[8], const double bz[8],
                          const double vx[8], const double vy[8], const double vz[8],
                          double d[6], double w[3]) {
  // L_ij = sum_I v_iI b_jI
  double lxx = 0, lxy = 0, lxz = 0, lyx = 0, lyy = 0, lyz = 0, lzx = 0, lzy = 0, lzz = 0;
  for (int n = 0; n < 8; ++n) {
    lxx += vx[n] * bx[n];
    lxy += vx[n] * by[n];
    lxz += vx[n] * bz[n];
    lyx += vy[n] * bx[n];
    lyy += vy[n] * by[n];
    lyz += vy[n] * bz[n];
    lzx += vz[n] * bx[n];
    lzy += vz[n] * by[n];
    lzz += vz[n] * bz[n];
  }
  d[0] = lxx;
  d[1] = lyy;
  d[2] = lzz;
  d[3] = 0.5 * (lxy + lyx);
  d[4] = 0.5 * (lyz + lzy);
  d[5] = 0.5 * (lzx + lxz);
  w[0] = 0.5 * (lxy - lyx);
  w[1] = 0.5 * (lyz - lzy);
  w[2] = 0.5 * (lzx - lxz);
}

void calc_hex_stress_force(const double sig[6], const double dvdx[8], const double dvdy[8],
                           const double dvdz[8], double fx[8], double fy[8], double fz[8]) {
  const double sxx = sig[0], syy = sig[1], szz = sig[2];
  const double sxy = sig[3], syz = sig[4], szx = sig[5];
  for (int n = 0; n < 8; ++n) {
    fx[n] = sxx * dvdx[n] + sxy * dvdy[n] + szx * dvdz[n];
    fy[n] = sxy * dvdx[n] + syy * dvdy[n] + syz * dvdz[n];
    fz[n] = szx * dvdx[n] + syz * dvdy[n] + szz * dvdz[n];
  }
}

// Hourglass control.
//
// Types 1-3 (viscous): f_iI = a_h sum_a h_ia g_aI with h_ia = sum_J v_iJ g_aJ and
//   a_h = qhg rho c V^(2/3) / 4; g = Gamma for type 1, the FB vectors gamma for types 2 and 3
//   (type 3 is the same as type 2 here: the volume derivatives are already exact).
//
// Types 4 and 5 (FB stiffness): hgs[3a + i] (a = mode 0..3, i = x, y, z) holds the hourglass
//   resultant Q_ia; each step Q_ia += kappa dt h_ia and f_iI = sum_a Q_ia gamma_aI, with
//       kappa = qhg * G * V^(1/3) / 4.
//   Scaling: for a cube of side L moved in the mode u_xI = delta Gamma_1I (displacement
//   delta eta zeta), the mode stiffness here is 8 kappa = 2 qhg G L, whereas a fully integrated
//   trilinear element stores the strain energy (4/3) G L delta^2 in that mode, i.e. a stiffness
//   G L / 3 per unit Gamma.  So qhg = 1/6 reproduces the fully integrated bending stiffness,
//   and the usual qhg = 0.1 (LS-DYNA's default) gives 60 % of it; the kappa V^(1/3)-scaling
//   with a modulus is the LS-DYNA form.  The resultants are kept in global axes (not rotated
//   with the element spin), as in DYNA3D.
double calc_hex_hourglass_force(const HourglassInput& in, const double x[8], const double y[8],
                                const double z[8], const double dvdx[8], const double dvdy[8],
                                const double dvdz[8], const double vx[8], const double vy[8],
                                const double vz[8], double hgs[12], double fx[8], double fy[8],
                                double fz[8], HourglassExtras* out) {
  if (out) *out = HourglassExtras{};
  if (in.qhg == 0.0 || in.volume <= 0.0) return 0.0;
  double g[4][8];
  if (in.type <= 1) {
    for (int a = 0; a < 4; ++a)
      for (int n = 0; n < 8; ++n) g[a][n] = kGamma[a][n];
  } else {
    fb_gamma(x, y, z, dvdx, dvdy, dvdz, in.volume, g);
  }
  double h[12];
  hourglass_rates(g, vx, vy, vz, h);
  if (in.type <= 3) {
    const double v23 = cbrt_positive(in.volume * in.volume);
    const double ah = 0.25 * in.qhg * in.rho * in.c * v23;
    double old_power = 0.0;
    for (int k = 0; k < 12; ++k) old_power += hgs[k] * h[k];
    for (int k = 0; k < 12; ++k) hgs[k] = ah * h[k];
    if (out) {
      out->old_power = old_power;
      out->dt = viscous_hourglass_step(g, ah, in.rho * in.volume);
    }
    return add_hourglass_forces(g, hgs, vx, vy, vz, fx, fy, fz);
  }
  const double kappa = 0.25 * in.qhg * in.shear_modulus * cbrt_positive(in.volume);
  const double kdt = kappa * in.dt;
  for (int k = 0; k < 12; ++k) hgs[k] += kdt * h[k];
  double hh = 0.0;
  for (int k = 0; k < 12; ++k) hh += h[k] * h[k];
  // the mean resultant's power (Q^n + Q^{n+1}) / 2 . h (hexahedron.h)
  return add_hourglass_forces(g, hgs, vx, vy, vz, fx, fy, fz) - 0.5 * kdt * hh;
}

double calc_bulk_viscosity(double rho, double c, double l, double trace_d, double q1,
                           double q2) {
  if (trace_d >= 0.0) return 0.0;
  return rho * l * (q1 * l * trace_d * trace_d - q2 * c * trace_d);
}

double calc_hex_time_step(double volume, double max_face_area, double c, double trace_d,
                          double q1, double q2) {
  if (max_face_area <= 0.0) return DBL_MAX;
  const double l = volume / max_face_area;
  const double q = trace_d < 0.0 ? q2 * c + q1 * l * (-trace_d) : 0.0;
  const double den = q + std::sqrt(q * q + c * c);
  if (den <= 0.0) return DBL_MAX;
  return l / den;
}

}  // namespace impact3d
