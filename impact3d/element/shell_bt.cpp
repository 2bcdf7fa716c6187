// Belytschko-Tsay shell kernels; see shell_bt.h.

#include "impact3d/element/shell_bt.h"

#include <cmath>

#include "impact3d/element/shell_parts.h"
#include "impact3d/material/plane_stress.h"

namespace impact3d {

void gauss_legendre_rule(int n, double* z, double* w) {
  // Newton iterations on the Legendre polynomial P_n from the Chebyshev guesses (converged to
  // machine precision for n <= 10 in a few steps)
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) { p1 = x; p0 = 1; }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    // recompute the derivative at the root for the weight
    double p0 = 1, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - p0) / (x * x - 1);
    // points from the bottom (-1) to the top (+1)
    z[n - 1 - i] = x;
    w[n - 1 - i] = 2.0 / ((1 - x * x) * dp * dp);
  }
  if (n == 1) {
    z[0] = 0;
    w[0] = 2;
  }
  if (n % 2 == 1) z[n / 2] = 0;  // exact middle point
}

namespace {

void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

constexpr double kHgVector[4] = {1, -1, 1, -1};

}  // namespace

bool calc_shell_frame(const double x[4][3], ShellFrame& fr) {
  double r31[3], r42[3], r21[3], s3[3];
  for (int a = 0; a < 3; ++a) {
    r31[a] = x[2][a] - x[0][a];
    r42[a] = x[3][a] - x[1][a];
    r21[a] = x[1][a] - x[0][a];
  }
  cross(r31, r42, s3);
  const double ls3 = std::sqrt(dot(s3, s3));
  if (!(ls3 > 0)) {
    fr.area = 0;
    return false;
  }
  double* e1 = fr.e[0];
  double* e2 = fr.e[1];
  double* e3 = fr.e[2];
  const double r3 = 1.0 / ls3;
  for (int a = 0; a < 3; ++a) e3[a] = s3[a] * r3;
  const double p = dot(r21, e3);
  for (int a = 0; a < 3; ++a) e1[a] = r21[a] - p * e3[a];
  const double l1 = std::sqrt(dot(e1, e1));
  if (!(l1 > 0)) {
    fr.area = 0;
    return false;
  }
  const double r1 = 1.0 / l1;
  for (int a = 0; a < 3; ++a) e1[a] *= r1;
  cross(e3, e1, e2);
  // node 1 is the origin; node 2 lies on e1 (r21 . e1 = l1, r21 . e2 = 0 up to round-off)
  fr.xl[0] = fr.yl[0] = 0;
  for (int i = 1; i < 4; ++i) {
    const double r[3] = {x[i][0] - x[0][0], x[i][1] - x[0][1], x[i][2] - x[0][2]};
    fr.xl[i] = dot(r, e1);
    fr.yl[i] = dot(r, e2);
  }
  const double* X = fr.xl;
  const double* Y = fr.yl;
  const double A = 0.5 * ((X[2] - X[0]) * (Y[3] - Y[1]) + (X[1] - X[3]) * (Y[2] - Y[0]));
  fr.area = A;
  if (!(A > 0)) return false;
  const double r2a = 1.0 / (2.0 * A);
  fr.b1[0] = (Y[1] - Y[3]) * r2a;
  fr.b1[1] = (Y[2] - Y[0]) * r2a;
  fr.b1[2] = (Y[3] - Y[1]) * r2a;
  fr.b1[3] = (Y[0] - Y[2]) * r2a;
  fr.b2[0] = (X[3] - X[1]) * r2a;
  fr.b2[1] = (X[0] - X[2]) * r2a;
  fr.b2[2] = (X[1] - X[3]) * r2a;
  fr.b2[3] = (X[2] - X[0]) * r2a;
  return true;
}

double calc_shell_step_length(const double x[4][3], double area, bool triangle) {
  double lmax = 0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
    lmax = std::fmax(lmax, dx * dx + dy * dy + dz * dz);
  }
  return (triangle ? 2.0 : 1.0) * area / std::sqrt(lmax);
}

namespace shell_parts {

// x^{n-1/2} = x^n - dt/2 v: the geometry of the step's rates (zero strain for a rigid motion).
void calc_shell_midpoint_coordinates(const ShellKernelIO& io, double xm[4][3]) {
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) xm[i][a] = io.x[i][a] - 0.5 * io.dt * io.v[i][a];
}

// The corner velocities in the frame (v: x y z, omega: x y).
void calc_shell_local_velocities(const ShellFrame& fr, const ShellKernelIO& io, double vl[4][3], double wl[4][2]) {
  for (int i = 0; i < 4; ++i) {
    for (int a = 0; a < 3; ++a) vl[i][a] = dot(fr.e[a], io.v[i]);
    wl[i][0] = dot(fr.e[0], io.w[i]);
    wl[i][1] = dot(fr.e[1], io.w[i]);
  }
}

ShellRates calc_shell_strain_rates(const ShellFrame& fm, const double vl[4][3], const double wl[4][2]) {
  double dxx = 0, dyy = 0, gxy = 0, kxx = 0, kyy = 0, kxy = 0, gxz = 0, gyz = 0, swx = 0, swy = 0;
  for (int i = 0; i < 4; ++i) {
    const double b1 = fm.b1[i], b2 = fm.b2[i];
    dxx += b1 * vl[i][0];
    dyy += b2 * vl[i][1];
    gxy += b2 * vl[i][0] + b1 * vl[i][1];
    kxx += b1 * wl[i][1];
    kyy -= b2 * wl[i][0];
    kxy += b2 * wl[i][1] - b1 * wl[i][0];
    gxz += b1 * vl[i][2];
    gyz += b2 * vl[i][2];
    swx += wl[i][0];
    swy += wl[i][1];
  }
  gxz += 0.25 * swy;  // 2 d_xz
  gyz -= 0.25 * swx;  // 2 d_yz
  return {dxx, dyy, gxy, kxx, kyy, kxy, gxz, gyz};
}

// The drilling rates: the corners' rotation rates about e3 less the in-plane spin.
void calc_shell_drilling_rates(const ShellFrame& fm, const ShellKernelIO& io, const double vl[4][3],
                               double drate[4]) {
  double spin = 0;
  for (int i = 0; i < 4; ++i) spin += fm.b1[i] * vl[i][1] - fm.b2[i] * vl[i][0];
  spin *= 0.5;
  for (int i = 0; i < 4; ++i) drate[i] = dot(fm.e[2], io.w[i]) - spin;
}

// The material's plane-stress update of point p (sigma at s, strain rates d).
void update_shell_point_stress(const MaterialConstants& mc, ShellMaterialKind kind, const double d[5], double dt,
                               double* s, const ShellPointState& st, int p) {
  if (kind == ShellMaterialKind::elastic) {
    update_plane_stress_elastic(mc, d, dt, s);
  } else if (kind == ShellMaterialKind::power_law) {
    PlaneStressPlastic hp{nullptr, st.eps_p + p, st.yielded + p};
    update_plane_stress_power_law(mc, d, dt, s, hp);
  } else if (kind == ShellMaterialKind::mooney_rivlin) {
    update_plane_stress_mooney_rivlin(mc, d, dt, s, st.back + 6 * p);
  } else if (kind == ShellMaterialKind::plastic_kinematic) {
    PlaneStressPlastic hp{st.back + 6 * p, st.eps_p + p, st.yielded + p};
    update_plane_stress_plastic_kinematic(mc, d, dt, s, hp);
  } else {
    PlaneStressPlastic hp{nullptr, st.eps_p + p, st.yielded + p};
    update_plane_stress_piecewise_linear(mc, d, dt, s, hp);
  }
}

// Stresses at the Gauss points through the thickness h (updated when dt > 0), their resultants
// and the stress power.
ShellResultants calc_shell_point_stresses(const ShellGroupConstants& g, const MaterialConstants& mc,
                                          ShellMaterialKind kind, const ShellRates& r, double h, double dt,
                                          const ShellPointState& st) {
  ShellResultants n;
  const double hh = 0.5 * h;
  for (int p = 0; p < g.nip; ++p) {
    const double z = g.zeta[p] * hh;
    const double wz = g.weight[p] * hh;
    double* s = st.sig + 5 * p;
    const double d[5] = {r.dxx + z * r.kxx, r.dyy + z * r.kyy, 0.5 * (r.gxy + z * r.kxy), 0.5 * g.shrf * r.gyz,
                         0.5 * g.shrf * r.gxz};
    const double old[5] = {s[0], s[1], s[2], s[3], s[4]};
    if (dt > 0) {
      update_shell_point_stress(mc, kind, d, dt, s, st, p);
      // work on the true rates (the shear stress is SHRF times the elastic one)
      const double pw = 0.5 * ((old[0] + s[0]) * d[0] + (old[1] + s[1]) * d[1]) +
                        (old[2] + s[2]) * d[2] + 0.5 * (old[3] + s[3]) * r.gyz +
                        0.5 * (old[4] + s[4]) * r.gxz;
      n.work += pw * wz;
    }
    n.Nxx += wz * s[0];
    n.Nyy += wz * s[1];
    n.Nxy += wz * s[2];
    n.Mxx += wz * z * s[0];
    n.Myy += wz * z * s[1];
    n.Mxy += wz * z * s[2];
    n.Qyz += wz * s[3];
    n.Qxz += wz * s[4];
  }
  return n;
}

// The drilling constraint: corner moments about e3 mz (integrated over the step, kept in the
// co-rotational frame as the hourglass resultants) and their reaction on the in-plane spin
// (added to fl); returns their work of the step.
double calc_shell_drilling_forces(const ShellGroupConstants& g, const ShellFrame& fr, double h, double dt,
                                  const double drate[4], double* drill, double fl[4][3], double mz[4]) {
  const double kd = g.drill_coef * g.G * h * fr.area / 4.0;
  double msum = 0, dwork = 0;
  for (int i = 0; i < 4; ++i) {
    const double m0 = drill[i];
    const double m1 = m0 + kd * drate[i] * dt;
    drill[i] = m1;
    mz[i] = m1;
    msum += m1;
    dwork += 0.5 * (m0 + m1) * drate[i] * dt;
  }
  for (int i = 0; i < 4; ++i) {
    fl[i][0] += 0.5 * msum * fr.b2[i];
    fl[i][1] -= 0.5 * msum * fr.b1[i];
  }
  return dwork;
}

void rotate_shell_forces_to_global(const ShellFrame& fr, const double fl[4][3], const double ml[4][2],
                                   const double mz[4], ShellKernelIO& io) {
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) {
      io.f[i][a] = fl[i][0] * fr.e[0][a] + fl[i][1] * fr.e[1][a] + fl[i][2] * fr.e[2][a];
      io.m[i][a] = ml[i][0] * fr.e[0][a] + ml[i][1] * fr.e[1][a] + mz[i] * fr.e[2][a];
    }
}

}  // namespace shell_parts

namespace {

using namespace shell_parts;

// Corner forces and moments in the frame at x^n: the work conjugates of the rates.
void calc_shell_local_forces(const ShellFrame& fr, const ShellResultants& n, double fl[4][3], double ml[4][2]) {
  const double A = fr.area;
  for (int i = 0; i < 4; ++i) {
    const double b1 = fr.b1[i], b2 = fr.b2[i];
    fl[i][0] = A * (b1 * n.Nxx + b2 * n.Nxy);
    fl[i][1] = A * (b2 * n.Nyy + b1 * n.Nxy);
    fl[i][2] = A * (b1 * n.Qxz + b2 * n.Qyz);
    ml[i][0] = A * (-b2 * n.Myy - b1 * n.Mxy - 0.25 * n.Qyz);
    ml[i][1] = A * (b1 * n.Mxx + b2 * n.Mxy + 0.25 * n.Qxz);
  }
}

// Belytschko-Tsay hourglass control, gamma = h - (h.x) B1 - (h.y) B2: adds the hourglass
// forces and moments to fl, ml; returns the hourglass energy of the step.
double calc_shell_hourglass_forces(const ShellGroupConstants& g, const ShellFrame& fr, const ShellKernelIO& io,
                                   const ShellPointState& st, double fl[4][3], double ml[4][2]) {
  const double A = fr.area, h = io.h, dt = io.dt;
  double hx = 0, hy = 0;
  for (int i = 0; i < 4; ++i) {
    hx += kHgVector[i] * fr.xl[i];
    hy += kHgVector[i] * fr.yl[i];
  }
  double gam[4];
  double bb = 0;
  for (int i = 0; i < 4; ++i) {
    gam[i] = kHgVector[i] - hx * fr.b1[i] - hy * fr.b2[i];
    bb += fr.b1[i] * fr.b1[i] + fr.b2[i] * fr.b2[i];
  }
  // hourglass rates in the frame at x^n: membrane x, y, transverse, rotations x, y
  double q[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    q[0] += gam[i] * dot(fr.e[0], io.v[i]);
    q[1] += gam[i] * dot(fr.e[1], io.v[i]);
    q[2] += gam[i] * dot(fr.e[2], io.v[i]);
    q[3] += gam[i] * dot(fr.e[0], io.w[i]);
    q[4] += gam[i] * dot(fr.e[1], io.w[i]);
  }
  double Q[5];
  double de_hg = 0;
  const double qm = g.hourglass_coef;
  if (g.hourglass_type >= 4 && st.hgq) {
    // stiffness form (Belytschko-Tsay): membrane QM E h A BB / 8, transverse
    // QM SHRF G h^3 BB / 12, bending QM E h^3 A BB / 192, integrated over the step
    const double km = qm * g.E * h * A * bb / 8.0;
    const double kw = qm * g.shrf * g.G * h * h * h * bb / 12.0;
    const double kb = qm * g.E * h * h * h * A * bb / 192.0;
    const double k[5] = {km, km, kw, kb, kb};
    for (int j = 0; j < 5; ++j) {
      const double q0 = st.hgq[j];
      const double q1 = q0 + k[j] * q[j] * dt;
      st.hgq[j] = q1;
      Q[j] = q1;
      de_hg += 0.5 * (q0 + q1) * q[j] * dt;
    }
  } else {
    // viscous form (IMPACT-3D's scale, as the solids' QM rho c V^(2/3) / 4 with the edge
    // face h sqrt(A) for V^(2/3); the rotations with h^3/12 for h)
    const double cm = qm * g.rho * g.c_plate * h * std::sqrt(A) / 4.0;
    const double cb = cm * h * h / 12.0;
    const double c[5] = {cm, cm, cm, cb, cb};
    for (int j = 0; j < 5; ++j) {
      Q[j] = c[j] * q[j];
      const double q0 = st.hgq ? st.hgq[j] : Q[j];
      de_hg += 0.5 * (q0 + Q[j]) * q[j] * dt;
      if (st.hgq) st.hgq[j] = Q[j];
    }
  }
  for (int i = 0; i < 4; ++i) {
    fl[i][0] += gam[i] * Q[0];
    fl[i][1] += gam[i] * Q[1];
    fl[i][2] += gam[i] * Q[2];
    ml[i][0] += gam[i] * Q[3];
    ml[i][1] += gam[i] * Q[4];
  }
  return de_hg;
}

void mark_shell_bad(const ShellFrame& fr, ShellKernelIO& io) {
  io.bad = true;
  io.area = fr.area;
  io.dt_e = 0;
}

}  // namespace

void calc_shell_bt_forces(const ShellGroupConstants& g, const MaterialConstants& mc,
                          ShellMaterialKind kind, ShellKernelIO& io, const ShellPointState& st) {
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) io.f[i][a] = io.m[i][a] = 0;
  io.de_ie = io.de_hg = 0;
  io.bad = false;
  const double dt = io.dt;

  // kinematics at the midpoint geometry
  double xm[4][3];
  calc_shell_midpoint_coordinates(io, xm);
  ShellFrame fm;
  if (!calc_shell_frame(xm, fm)) return mark_shell_bad(fm, io);
  double vl[4][3], wl[4][2];
  calc_shell_local_velocities(fm, io, vl, wl);
  const ShellRates r = calc_shell_strain_rates(fm, vl, wl);
  double drate[4] = {0, 0, 0, 0};
  if (st.drill) calc_shell_drilling_rates(fm, io, vl, drate);
  io.strain_rate_membrane[0] = r.dxx;
  io.strain_rate_membrane[1] = r.dyy;
  io.strain_rate_membrane[2] = 0.5 * r.gxy;

  // stresses at the Gauss points, resultants, stress work
  const ShellResultants n = calc_shell_point_stresses(g, mc, kind, r, io.h, dt, st);
  io.de_ie = n.work * fm.area * dt;

  // forces and moments at x^n (local frame), hourglass, drilling, to the global frame
  ShellFrame fr;
  if (!calc_shell_frame(io.x, fr)) return mark_shell_bad(fr, io);
  io.area = fr.area;
  double fl[4][3], ml[4][2];
  calc_shell_local_forces(fr, n, fl, ml);
  if (g.hourglass_coef > 0) io.de_hg = calc_shell_hourglass_forces(g, fr, io, st, fl, ml);
  double mz[4] = {0, 0, 0, 0};
  if (st.drill && g.drill_coef > 0) io.de_ie += calc_shell_drilling_forces(g, fr, io.h, dt, drate, st.drill, fl, mz);
  rotate_shell_forces_to_global(fr, fl, ml, mz, io);
  const bool tri = io.x[2][0] == io.x[3][0] && io.x[2][1] == io.x[3][1] && io.x[2][2] == io.x[3][2];
  io.dt_e = calc_shell_step_length(io.x, fr.area, tri) / g.c_plate;
}

}  // namespace impact3d
