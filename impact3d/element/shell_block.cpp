// The Belytschko-Tsay shell in block form; see shell_block.h.  Each function is the lane form of
// the scalar one of the same name in shell_bt.cpp (without _block), operation for operation.

#include "impact3d/element/shell_block.h"

#include <cmath>

#include "impact3d/material/material_block.h"
#include "impact3d/material/plane_stress.h"

namespace impact3d {

namespace {

constexpr double kHgVector[4] = {1, -1, 1, -1};

bool any_lane(const Lanes& a) {
  bool any = false;
  for (int l = 0; l < kLanes; ++l) any = any || a[l] != 0.0;
  return any;
}

// calc_shell_frame of each lane (bad: 1 where the scalar one returns false).
void calc_shell_frame_block(const Lanes x[4][3], ShellFrameLanes& fr) {
  IMPACT3D_FOR_LANES {
    const double r31x = x[2][0][l] - x[0][0][l], r31y = x[2][1][l] - x[0][1][l], r31z = x[2][2][l] - x[0][2][l];
    const double r42x = x[3][0][l] - x[1][0][l], r42y = x[3][1][l] - x[1][1][l], r42z = x[3][2][l] - x[1][2][l];
    const double r21x = x[1][0][l] - x[0][0][l], r21y = x[1][1][l] - x[0][1][l], r21z = x[1][2][l] - x[0][2][l];
    const double s3x = r31y * r42z - r31z * r42y;
    const double s3y = r31z * r42x - r31x * r42z;
    const double s3z = r31x * r42y - r31y * r42x;
    const double ls3 = std::sqrt(s3x * s3x + s3y * s3y + s3z * s3z);
    const double r3 = 1.0 / ls3;
    const double e3x = s3x * r3, e3y = s3y * r3, e3z = s3z * r3;
    const double p = r21x * e3x + r21y * e3y + r21z * e3z;
    double e1x = r21x - p * e3x, e1y = r21y - p * e3y, e1z = r21z - p * e3z;
    const double l1 = std::sqrt(e1x * e1x + e1y * e1y + e1z * e1z);
    const double r1 = 1.0 / l1;
    e1x *= r1;
    e1y *= r1;
    e1z *= r1;
    const double e2x = e3y * e1z - e3z * e1y;
    const double e2y = e3z * e1x - e3x * e1z;
    const double e2z = e3x * e1y - e3y * e1x;
    fr.e[0][0][l] = e1x, fr.e[0][1][l] = e1y, fr.e[0][2][l] = e1z;
    fr.e[1][0][l] = e2x, fr.e[1][1][l] = e2y, fr.e[1][2][l] = e2z;
    fr.e[2][0][l] = e3x, fr.e[2][1][l] = e3y, fr.e[2][2][l] = e3z;
    double X[4], Y[4];
    X[0] = Y[0] = 0;
    for (int i = 1; i < 4; ++i) {
      const double rx = x[i][0][l] - x[0][0][l], ry = x[i][1][l] - x[0][1][l], rz = x[i][2][l] - x[0][2][l];
      X[i] = rx * e1x + ry * e1y + rz * e1z;
      Y[i] = rx * e2x + ry * e2y + rz * e2z;
    }
    for (int i = 0; i < 4; ++i) fr.xl[i][l] = X[i], fr.yl[i][l] = Y[i];
    const double A = 0.5 * ((X[2] - X[0]) * (Y[3] - Y[1]) + (X[1] - X[3]) * (Y[2] - Y[0]));
    fr.area[l] = A;
    fr.bad[l] = !(ls3 > 0) || !(l1 > 0) || !(A > 0) ? 1.0 : 0.0;
    const double r2a = 1.0 / (2.0 * A);
    fr.b1[0][l] = (Y[1] - Y[3]) * r2a;
    fr.b1[1][l] = (Y[2] - Y[0]) * r2a;
    fr.b1[2][l] = (Y[3] - Y[1]) * r2a;
    fr.b1[3][l] = (Y[0] - Y[2]) * r2a;
    fr.b2[0][l] = (X[3] - X[1]) * r2a;
    fr.b2[1][l] = (X[0] - X[2]) * r2a;
    fr.b2[2][l] = (X[1] - X[3]) * r2a;
    fr.b2[3][l] = (X[2] - X[0]) * r2a;
  }
}

void calc_shell_midpoint_coordinates_block(double dt, ShellBlock& b) {
  const double hdt = 0.5 * dt;
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) IMPACT3D_FOR_LANES b.xm[i][a][l] = b.x[i][a][l] - hdt * b.v[i][a][l];
}

void calc_shell_local_velocities_block(ShellBlock& b) {
  const ShellFrameLanes& f = b.fm;
  for (int i = 0; i < 4; ++i) {
    IMPACT3D_FOR_LANES {
      const double vx = b.v[i][0][l], vy = b.v[i][1][l], vz = b.v[i][2][l];
      const double wx = b.w[i][0][l], wy = b.w[i][1][l], wz = b.w[i][2][l];
      for (int a = 0; a < 3; ++a) b.vl[i][a][l] = f.e[a][0][l] * vx + f.e[a][1][l] * vy + f.e[a][2][l] * vz;
      b.wl[i][0][l] = f.e[0][0][l] * wx + f.e[0][1][l] * wy + f.e[0][2][l] * wz;
      b.wl[i][1][l] = f.e[1][0][l] * wx + f.e[1][1][l] * wy + f.e[1][2][l] * wz;
    }
  }
}

void calc_shell_strain_rates_block(ShellBlock& b) {
  IMPACT3D_FOR_LANES {
    double dxx = 0, dyy = 0, gxy = 0, kxx = 0, kyy = 0, kxy = 0, gxz = 0, gyz = 0, swx = 0, swy = 0;
    for (int i = 0; i < 4; ++i) {
      const double b1 = b.fm.b1[i][l], b2 = b.fm.b2[i][l];
      const double v0 = b.vl[i][0][l], v1 = b.vl[i][1][l], v2 = b.vl[i][2][l];
      const double w0 = b.wl[i][0][l], w1 = b.wl[i][1][l];
      dxx += b1 * v0;
      dyy += b2 * v1;
      gxy += b2 * v0 + b1 * v1;
      kxx += b1 * w1;
      kyy -= b2 * w0;
      kxy += b2 * w1 - b1 * w0;
      gxz += b1 * v2;
      gyz += b2 * v2;
      swx += w0;
      swy += w1;
    }
    gxz += 0.25 * swy;
    gyz -= 0.25 * swx;
    b.dxx[l] = dxx, b.dyy[l] = dyy, b.gxy[l] = gxy, b.kxx[l] = kxx, b.kyy[l] = kyy, b.kxy[l] = kxy;
    b.gxz[l] = gxz, b.gyz[l] = gyz;
  }
}

void calc_shell_drilling_rates_block(ShellBlock& b) {
  IMPACT3D_FOR_LANES {
    double spin = 0;
    for (int i = 0; i < 4; ++i) spin += b.fm.b1[i][l] * b.vl[i][1][l] - b.fm.b2[i][l] * b.vl[i][0][l];
    spin *= 0.5;
    for (int i = 0; i < 4; ++i)
      b.drate[i][l] = b.fm.e[2][0][l] * b.w[i][0][l] + b.fm.e[2][1][l] * b.w[i][1][l] +
                      b.fm.e[2][2][l] * b.w[i][2][l] - spin;
  }
}

// update_plane_stress_elastic of point p.
void update_plane_stress_elastic_block(const MaterialConstants& m, const Lanes d[5], double dt, Lanes s[5]) {
  const double c = m.E / (1.0 - m.nu * m.nu) * dt;
  const double g2 = 2.0 * m.G * dt;
  const double nu = m.nu;
  IMPACT3D_FOR_LANES {
    s[0][l] += c * (d[0][l] + nu * d[1][l]);
    s[1][l] += c * (d[1][l] + nu * d[0][l]);
    s[2][l] += g2 * d[2][l];
    s[3][l] += g2 * d[3][l];
    s[4][l] += g2 * d[4][l];
  }
}

// One 3-D trial of the plane-stress iteration in every lane: point p's saved state (sigma_zz = 0)
// with the thickness strain rate dzz, through the material's block update, into b.point.
void run_plane_stress_trial_block(const ShellBlockMaterial& mat, const Lanes d[5], const Lanes& dzz, double dt,
                                  ShellBlock& b, int p) {
  MaterialPointBlock& k = b.point;
  IMPACT3D_FOR_LANES {
    k.d[0][l] = d[0][l], k.d[1][l] = d[1][l], k.d[2][l] = dzz[l];
    k.d[3][l] = d[2][l], k.d[4][l] = d[3][l], k.d[5][l] = d[4][l];
    k.sig[0][l] = b.sig[p][0][l], k.sig[1][l] = b.sig[p][1][l], k.sig[2][l] = 0.0;
    k.sig[3][l] = b.sig[p][2][l], k.sig[4][l] = b.sig[p][3][l], k.sig[5][l] = b.sig[p][4][l];
    k.eps_p[l] = b.eps_p[p][l];
    k.yielded[l] = b.yielded[p][l];
  }
  if (mat.has_back)
    for (int c = 0; c < 6; ++c) IMPACT3D_FOR_LANES k.back[c][l] = b.back[p][c][l];
  mat.update_block(*mat.mc, k, dt);
}

// The iteration needs of a trial only its sigma_zz (and, of the first, the in-plane stresses
// that scale the tolerance); the state comes from one full trial at each lane's last d_zz.  A
// probe computes that sigma_zz (and those stresses) in every lane with exactly the operations
// the material's block update does for them (the same bits), reusing what does not depend on
// d_zz; the materials without a probe run full trials.
constexpr int kMaxProbeSegments = 16;  // a type 24 curve's segments a probe takes (more: full trials)

enum class ProbeKind {
  trial,           // the material's block update (type 24 with rate effects)
  kinematic,       // type 3 without back stress (update_stress_elastic_plastic_block<false>)
  kinematic_back,  // type 3 with back stress (<true>)
  table            // type 24 without rate effects (the piecewise-linear block update with R = 1)
};

ProbeKind plane_stress_probe_kind(const ShellBlockMaterial& mat) {
  const MaterialConstants& m = *mat.mc;
  if (mat.kind == ShellMaterialKind::plastic_kinematic && !(m.rate_c > 0.0))  // (mat_plastic_kinematic's choice)
    return (1.0 - m.beta) * m.E_p != 0.0 ? ProbeKind::kinematic_back : ProbeKind::kinematic;
  if (mat.kind == ShellMaterialKind::piecewise_linear && !(m.rate_c > 0.0) && m.rate_x.empty() &&
      m.curve_slope.size() <= std::size_t(kMaxProbeSegments))
    return ProbeKind::table;
  return ProbeKind::trial;
}

// The block's probe kind and, type 24, the curve's segments' plastic-strain bounds
// (calc_piecewise_linear_increment_block's lo, hi).
struct ProbeMaterial {
  ProbeKind kind;
  int ns = 0;
  double lo[kMaxProbeSegments], hi[kMaxProbeSegments];
};

ProbeMaterial probe_material(const ShellBlockMaterial& mat) {
  const MaterialConstants& m = *mat.mc;
  ProbeMaterial pm;
  pm.kind = plane_stress_probe_kind(mat);
  if (pm.kind != ProbeKind::table) return pm;
  pm.ns = int(m.curve_slope.size());
  for (int i = 0; i < pm.ns; ++i) {
    pm.lo[i] = i == 0 ? -HUGE_VAL : m.curve_eps[std::size_t(i)];
    pm.hi[i] = i == pm.ns - 1 ? HUGE_VAL : m.curve_eps[std::size_t(i + 1)];
  }
  return pm;
}

// What point p's trials share: the in-plane elastic increments less their d_zz part, the
// trial shears (3-D xy yz zx) less the back stress, twice their squares' sum, the yield stress.
struct alignas(64) PlaneStressProbe {
  Lanes d01, g0, g1, t[3], xs[3], shear, sy;
};

void setup_plane_stress_probe(const ShellBlockMaterial& mat, const ProbeMaterial& pm, const Lanes d[5], double dt,
                              const ShellBlock& b, int p, PlaneStressProbe& q) {
  const MaterialConstants& m = *mat.mc;
  const bool back = pm.kind == ProbeKind::kinematic_back;
  const double g2 = 2.0 * m.G * dt;
  const double beta_ep = m.beta * m.E_p;
  IMPACT3D_FOR_LANES {
    q.d01[l] = d[0][l] + d[1][l];
    q.g0[l] = g2 * d[0][l];
    q.g1[l] = g2 * d[1][l];
    for (int c = 0; c < 3; ++c) {
      q.t[c][l] = b.sig[p][2 + c][l] + g2 * d[2 + c][l];
      q.xs[c][l] = back ? q.t[c][l] - b.back[p][3 + c][l] : q.t[c][l];
    }
    q.shear[l] = 2.0 * (q.xs[0][l] * q.xs[0][l] + q.xs[1][l] * q.xs[1][l] + q.xs[2][l] * q.xs[2][l]);
    q.sy[l] = m.sigma_y + beta_ep * b.eps_p[p][l];
  }
}

// sigma_zz of point p's trials at dzz into szz; with First, also the trial's sigma_xx, sigma_yy
// and sigma_xy into s01 (scale: their absolute values' sum, as the scalar iteration's).
template <bool First>
void probe_plane_stress_block(const ShellBlockMaterial& mat, const ProbeMaterial& pm, const PlaneStressProbe& q,
                              const Lanes d[5], const Lanes& dzz, double dt, ShellBlock& b, int p, Lanes& szz,
                              Lanes& scale) {
  const MaterialConstants& m = *mat.mc;
  const double g2 = 2.0 * m.G * dt;
  const double ldt = m.lambda * dt;
  const double G3 = 3.0 * m.G;
  if (pm.kind == ProbeKind::trial) {
    run_plane_stress_trial_block(mat, d, dzz, dt, b, p);
    const MaterialPointBlock& k = b.point;
    IMPACT3D_FOR_LANES {
      szz[l] = k.sig[2][l];
      if (First) scale[l] = m.sigma_y + std::fabs(k.sig[0][l]) + std::fabs(k.sig[1][l]) + std::fabs(k.sig[3][l]);
    }
    return;
  }
  if (pm.kind == ProbeKind::table) {
    alignas(64) Lanes s[3], mean, vm, de, found;
    IMPACT3D_FOR_LANES {
      const double lt = ldt * (q.d01[l] + dzz[l]);
      s[0][l] = b.sig[p][0][l] + (lt + q.g0[l]);
      s[1][l] = b.sig[p][1][l] + (lt + q.g1[l]);
      s[2][l] = 0.0 + (lt + g2 * dzz[l]);
      const double pm = (s[0][l] + s[1][l] + s[2][l]) * (1.0 / 3.0);
      const double s0 = s[0][l] - pm, s1 = s[1][l] - pm, s2 = s[2][l] - pm;
      mean[l] = pm;
      vm[l] = std::sqrt(1.5 * (s0 * s0 + s1 * s1 + s2 * s2 + q.shear[l]));
      de[l] = 0.0;
      found[l] = 0.0;
    }
    // calc_piecewise_linear_increment_block with R = 1 (R h = h, G3 + R slope = G3 + slope)
    for (int i = 0; i < pm.ns; ++i) {
      const double cei = m.curve_eps[std::size_t(i)], csi = m.curve_sig[std::size_t(i)];
      const double chi = m.curve_slope[std::size_t(i)];
      const double den = G3 + chi, lo = pm.lo[i], hi = pm.hi[i];
      IMPACT3D_FOR_LANES {
        const double h = csi + chi * (b.eps_p[p][l] - cei);
        const double cand = (vm[l] - h) / den;
        const double e = b.eps_p[p][l] + cand;
        const bool take = (found[l] == 0.0) & (e >= lo) & (e <= hi);
        de[l] = take ? cand : de[l];
        found[l] = take ? 1.0 : found[l];
      }
    }
    IMPACT3D_FOR_LANES {
      const double dl = de[l] > 0.0 ? de[l] : 0.0;
      const bool yields = dl > 0.0;
      const double rs = G3 * dl / vm[l];
      const double pm = mean[l];
      szz[l] = yields ? s[2][l] - rs * (s[2][l] - pm) : s[2][l];
      if (First) {
        const double o0 = yields ? s[0][l] - rs * (s[0][l] - pm) : s[0][l];
        const double o1 = yields ? s[1][l] - rs * (s[1][l] - pm) : s[1][l];
        const double o3 = yields ? q.t[0][l] - rs * q.t[0][l] : q.t[0][l];
        scale[l] = m.sigma_y + std::fabs(o0) + std::fabs(o1) + std::fabs(o3);
      }
    }
    return;
  }
  const bool back = pm.kind == ProbeKind::kinematic_back;
  const double plain_den = 3.0 * m.G + m.E_p;
  IMPACT3D_FOR_LANES {
    const double lt = ldt * (q.d01[l] + dzz[l]);
    const double s0 = b.sig[p][0][l] + (lt + q.g0[l]);
    const double s1 = b.sig[p][1][l] + (lt + q.g1[l]);
    const double s2 = 0.0 + (lt + g2 * dzz[l]);
    const double pm = (s0 + s1 + s2) * (1.0 / 3.0);
    const double xi0 = back ? s0 - pm - b.back[p][0][l] : s0 - pm;
    const double xi1 = back ? s1 - pm - b.back[p][1][l] : s1 - pm;
    const double xi2 = back ? s2 - pm - b.back[p][2][l] : s2 - pm;
    const double xx = xi0 * xi0 + xi1 * xi1 + xi2 * xi2 + q.shear[l];
    const double vm = std::sqrt(1.5 * xx);
    const double f = vm - q.sy[l];
    const bool yields = f > 0.0;
    const double deps = f / plain_den;
    const double rs = G3 * deps / vm;
    szz[l] = yields ? s2 - rs * xi2 : s2;
    if (First) {
      const double o0 = yields ? s0 - rs * xi0 : s0;
      const double o1 = yields ? s1 - rs * xi1 : s1;
      const double o3 = yields ? q.t[0][l] - rs * q.xs[0][l] : q.t[0][l];
      scale[l] = m.sigma_y + std::fabs(o0) + std::fabs(o1) + std::fabs(o3);
    }
  }
}

// One point's plane-stress iteration: the secant's last two points, the tolerance, the lanes
// still stepping, each lane's last d_zz, what the probes share.
struct alignas(64) PlaneStressIteration {
  Lanes z0, f0, z1, f1, tol, active, zlast;
  PlaneStressProbe q;
};

// update_plane_stress_plastic_kinematic / update_plane_stress_piecewise_linear of the block's
// nip points (strain rates d[p]): plane_stress.cpp's solve_thickness_rate in every lane, each
// lane stepping while its scalar twin would (the elastic guess, the incompressible rate, secant
// steps to |sigma_zz| <= tol, at most kPlaneStressIterations) on the probes' sigma_zz, then the
// full trial at the lane's last d_zz: the state of the scalar iteration's last trial.  The
// points step together (a step of every point, then the next: their chains of square roots
// and divisions overlap); each point's own steps are those it would take alone.
void update_plane_stress_plastic_block(const ShellBlockMaterial& mat, int nip, const Lanes (*d)[5], double dt,
                                       ShellBlock& b) {
  const MaterialConstants& m = *mat.mc;
  const ProbeMaterial pm = probe_material(mat);
  alignas(64) PlaneStressIteration its[kMaxShellIntegrationPoints];
  alignas(64) Lanes z2, scale;
  const double guess = -m.nu / (1.0 - m.nu);
  const double tiny = 1e-30 / (dt > 0 ? dt : 1.0);
  bool any = false;
  for (int p = 0; p < nip; ++p) {
    PlaneStressIteration& t = its[p];
    if (pm.kind != ProbeKind::trial) setup_plane_stress_probe(mat, pm, d[p], dt, b, p, t.q);
    IMPACT3D_FOR_LANES t.z0[l] = guess * (d[p][0][l] + d[p][1][l]);
    probe_plane_stress_block<true>(mat, pm, t.q, d[p], t.z0, dt, b, p, t.f0, scale);
    IMPACT3D_FOR_LANES {
      t.tol[l] = 1e-10 * scale[l];
      t.active[l] = std::fabs(t.f0[l]) > t.tol[l] ? 1.0 : 0.0;
      t.zlast[l] = t.z0[l];
    }
    if (!any_lane(t.active)) continue;
    any = true;
    IMPACT3D_FOR_LANES {
      const double z = -(d[p][0][l] + d[p][1][l]);
      t.z1[l] = z == t.z0[l] ? t.z0[l] + 1e-6 * (std::fabs(t.z0[l]) + tiny) : z;
      t.zlast[l] = t.active[l] != 0.0 ? t.z1[l] : t.zlast[l];
    }
    probe_plane_stress_block<false>(mat, pm, t.q, d[p], t.z1, dt, b, p, t.f1, scale);
    IMPACT3D_FOR_LANES
    t.active[l] = t.active[l] != 0.0 && std::fabs(t.f1[l]) > t.tol[l] && t.f1[l] != t.f0[l] ? 1.0 : 0.0;
  }
  for (int it = 0; it < kPlaneStressIterations && any; ++it) {
    any = false;
    for (int p = 0; p < nip; ++p) {
      PlaneStressIteration& t = its[p];
      if (!any_lane(t.active)) continue;
      IMPACT3D_FOR_LANES {
        const bool a = t.active[l] != 0.0;
        const double zn = t.z1[l] - t.f1[l] * (t.z1[l] - t.z0[l]) / (t.f1[l] - t.f0[l]);
        t.z0[l] = a ? t.z1[l] : t.z0[l];
        t.f0[l] = a ? t.f1[l] : t.f0[l];
        t.z1[l] = a ? zn : t.z1[l];
        t.zlast[l] = a ? zn : t.zlast[l];
      }
      probe_plane_stress_block<false>(mat, pm, t.q, d[p], t.z1, dt, b, p, z2, scale);
      IMPACT3D_FOR_LANES {
        const bool a = t.active[l] != 0.0;
        t.f1[l] = a ? z2[l] : t.f1[l];
        t.active[l] = a && std::fabs(t.f1[l]) > t.tol[l] && t.f1[l] != t.f0[l] ? 1.0 : 0.0;
      }
      any = any || any_lane(t.active);
    }
  }
  for (int p = 0; p < nip; ++p) {
    run_plane_stress_trial_block(mat, d[p], its[p].zlast, dt, b, p);
    const MaterialPointBlock& k = b.point;
    IMPACT3D_FOR_LANES {
      b.sig[p][0][l] = k.sig[0][l], b.sig[p][1][l] = k.sig[1][l], b.sig[p][2][l] = k.sig[3][l];
      b.sig[p][3][l] = k.sig[4][l], b.sig[p][4][l] = k.sig[5][l];
      b.eps_p[p][l] = k.eps_p[l];
      b.yielded[p][l] = k.yielded[l] != 0.0 ? 1.0 : 0.0;
    }
    if (mat.has_back)
      for (int c = 0; c < 6; ++c) IMPACT3D_FOR_LANES b.back[p][c][l] = k.back[c][l];
  }
}

void calc_shell_point_stresses_block(const ShellGroupConstants& g, const ShellBlockMaterial& mat, double dt,
                                     ShellBlock& b) {
  IMPACT3D_FOR_LANES {
    b.Nxx[l] = b.Nyy[l] = b.Nxy[l] = b.Mxx[l] = b.Myy[l] = b.Mxy[l] = b.Qxz[l] = b.Qyz[l] = 0;
    b.work[l] = 0;
  }
  const double hs = 0.5 * g.shrf;
  const int nip = g.nip;
  alignas(64) Lanes z[kMaxShellIntegrationPoints], wz[kMaxShellIntegrationPoints];
  alignas(64) Lanes d[kMaxShellIntegrationPoints][5], old[kMaxShellIntegrationPoints][5];
  for (int p = 0; p < nip; ++p) {
    IMPACT3D_FOR_LANES {
      const double hh = 0.5 * b.h[l];
      z[p][l] = g.zeta[p] * hh;
      wz[p][l] = g.weight[p] * hh;
      d[p][0][l] = b.dxx[l] + z[p][l] * b.kxx[l];
      d[p][1][l] = b.dyy[l] + z[p][l] * b.kyy[l];
      d[p][2][l] = 0.5 * (b.gxy[l] + z[p][l] * b.kxy[l]);
      d[p][3][l] = hs * b.gyz[l];
      d[p][4][l] = hs * b.gxz[l];
      for (int c = 0; c < 5; ++c) old[p][c][l] = b.sig[p][c][l];
    }
  }
  if (dt > 0) {
    if (mat.kind == ShellMaterialKind::elastic)
      for (int p = 0; p < nip; ++p) update_plane_stress_elastic_block(*mat.mc, d[p], dt, b.sig[p]);
    else
      update_plane_stress_plastic_block(mat, nip, d, dt, b);
  }
  // the work and the resultants point by point (the scalar kernel's sums)
  for (int p = 0; p < nip; ++p) {
    const Lanes* s = b.sig[p];
    if (dt > 0) {
      IMPACT3D_FOR_LANES {
        const double pw = 0.5 * ((old[p][0][l] + s[0][l]) * d[p][0][l] + (old[p][1][l] + s[1][l]) * d[p][1][l]) +
                          (old[p][2][l] + s[2][l]) * d[p][2][l] + 0.5 * (old[p][3][l] + s[3][l]) * b.gyz[l] +
                          0.5 * (old[p][4][l] + s[4][l]) * b.gxz[l];
        b.work[l] += pw * wz[p][l];
      }
    }
    IMPACT3D_FOR_LANES {
      b.Nxx[l] += wz[p][l] * s[0][l];
      b.Nyy[l] += wz[p][l] * s[1][l];
      b.Nxy[l] += wz[p][l] * s[2][l];
      b.Mxx[l] += wz[p][l] * z[p][l] * s[0][l];
      b.Myy[l] += wz[p][l] * z[p][l] * s[1][l];
      b.Mxy[l] += wz[p][l] * z[p][l] * s[2][l];
      b.Qyz[l] += wz[p][l] * s[3][l];
      b.Qxz[l] += wz[p][l] * s[4][l];
    }
  }
}

void calc_shell_local_forces_block(ShellBlock& b) {
  const ShellFrameLanes& fr = b.fr;
  for (int i = 0; i < 4; ++i) {
    IMPACT3D_FOR_LANES {
      const double A = fr.area[l], b1 = fr.b1[i][l], b2 = fr.b2[i][l];
      b.fl[i][0][l] = A * (b1 * b.Nxx[l] + b2 * b.Nxy[l]);
      b.fl[i][1][l] = A * (b2 * b.Nyy[l] + b1 * b.Nxy[l]);
      b.fl[i][2][l] = A * (b1 * b.Qxz[l] + b2 * b.Qyz[l]);
      b.ml[i][0][l] = A * (-b2 * b.Myy[l] - b1 * b.Mxy[l] - 0.25 * b.Qyz[l]);
      b.ml[i][1][l] = A * (b1 * b.Mxx[l] + b2 * b.Mxy[l] + 0.25 * b.Qxz[l]);
    }
  }
}

// The hourglass resultants' update over the step, one mode j (stiffness form): Q_j = q0 + k q dt,
// and its energy.
inline double update_hourglass_resultant(double k, double q, double dt, double& Q, double& de_hg) {
  const double q0 = Q;
  const double q1 = q0 + k * q * dt;
  Q = q1;
  de_hg += 0.5 * (q0 + q1) * q * dt;
  return q1;
}

void calc_shell_hourglass_forces_block(const ShellGroupConstants& g, bool stiffness, double dt, ShellBlock& b) {
  const ShellFrameLanes& fr = b.fr;
  const double qm = g.hourglass_coef;
  const double qE = qm * g.E, qsG = qm * g.shrf * g.G, qrc = qm * g.rho * g.c_plate;
  alignas(64) Lanes gam[4], bb, q[5], Q[5];
  IMPACT3D_FOR_LANES {
    double hx = 0, hy = 0;
    for (int i = 0; i < 4; ++i) {
      hx += kHgVector[i] * fr.xl[i][l];
      hy += kHgVector[i] * fr.yl[i][l];
    }
    double s = 0;
    for (int i = 0; i < 4; ++i) {
      gam[i][l] = kHgVector[i] - hx * fr.b1[i][l] - hy * fr.b2[i][l];
      s += fr.b1[i][l] * fr.b1[i][l] + fr.b2[i][l] * fr.b2[i][l];
    }
    bb[l] = s;
  }
  // hourglass rates in the frame at x^n: membrane x, y, transverse, rotations x, y
  IMPACT3D_FOR_LANES {
    double q0 = 0, q1 = 0, q2 = 0, q3 = 0, q4 = 0;
    for (int i = 0; i < 4; ++i) {
      const double vx = b.v[i][0][l], vy = b.v[i][1][l], vz = b.v[i][2][l];
      const double wx = b.w[i][0][l], wy = b.w[i][1][l], wz = b.w[i][2][l];
      const double gi = gam[i][l];
      q0 += gi * (fr.e[0][0][l] * vx + fr.e[0][1][l] * vy + fr.e[0][2][l] * vz);
      q1 += gi * (fr.e[1][0][l] * vx + fr.e[1][1][l] * vy + fr.e[1][2][l] * vz);
      q2 += gi * (fr.e[2][0][l] * vx + fr.e[2][1][l] * vy + fr.e[2][2][l] * vz);
      q3 += gi * (fr.e[0][0][l] * wx + fr.e[0][1][l] * wy + fr.e[0][2][l] * wz);
      q4 += gi * (fr.e[1][0][l] * wx + fr.e[1][1][l] * wy + fr.e[1][2][l] * wz);
    }
    q[0][l] = q0, q[1][l] = q1, q[2][l] = q2, q[3][l] = q3, q[4][l] = q4;
  }
  if (stiffness) {
    IMPACT3D_FOR_LANES {
      const double A = fr.area[l], h = b.h[l];
      const double km = qE * h * A * bb[l] / 8.0;
      const double kw = qsG * h * h * h * bb[l] / 12.0;
      const double kb = qE * h * h * h * A * bb[l] / 192.0;
      double de_hg = 0;
      Q[0][l] = update_hourglass_resultant(km, q[0][l], dt, b.hgq[0][l], de_hg);
      Q[1][l] = update_hourglass_resultant(km, q[1][l], dt, b.hgq[1][l], de_hg);
      Q[2][l] = update_hourglass_resultant(kw, q[2][l], dt, b.hgq[2][l], de_hg);
      Q[3][l] = update_hourglass_resultant(kb, q[3][l], dt, b.hgq[3][l], de_hg);
      Q[4][l] = update_hourglass_resultant(kb, q[4][l], dt, b.hgq[4][l], de_hg);
      b.de_hg[l] = de_hg;
    }
  } else {
    IMPACT3D_FOR_LANES {
      const double h = b.h[l];
      const double cm = qrc * h * std::sqrt(fr.area[l]) / 4.0;
      const double cb = cm * h * h / 12.0;
      const double c[5] = {cm, cm, cm, cb, cb};
      double de_hg = 0;
      for (int j = 0; j < 5; ++j) {
        Q[j][l] = c[j] * q[j][l];
        de_hg += 0.5 * (b.hgq[j][l] + Q[j][l]) * q[j][l] * dt;
        b.hgq[j][l] = Q[j][l];
      }
      b.de_hg[l] = de_hg;
    }
  }
  for (int i = 0; i < 4; ++i) {
    IMPACT3D_FOR_LANES {
      const double gi = gam[i][l];
      b.fl[i][0][l] += gi * Q[0][l];
      b.fl[i][1][l] += gi * Q[1][l];
      b.fl[i][2][l] += gi * Q[2][l];
      b.ml[i][0][l] += gi * Q[3][l];
      b.ml[i][1][l] += gi * Q[4][l];
    }
  }
}

void calc_shell_drilling_forces_block(const ShellGroupConstants& g, double dt, ShellBlock& b) {
  const ShellFrameLanes& fr = b.fr;
  const double cG = g.drill_coef * g.G;
  IMPACT3D_FOR_LANES {
    const double kd = cG * b.h[l] * fr.area[l] / 4.0;
    double msum = 0, dwork = 0;
    for (int i = 0; i < 4; ++i) {
      const double m0 = b.drill[i][l];
      const double m1 = m0 + kd * b.drate[i][l] * dt;
      b.drill[i][l] = m1;
      b.mz[i][l] = m1;
      msum += m1;
      dwork += 0.5 * (m0 + m1) * b.drate[i][l] * dt;
    }
    b.de_ie[l] += dwork;
    for (int i = 0; i < 4; ++i) {
      b.fl[i][0][l] += 0.5 * msum * fr.b2[i][l];
      b.fl[i][1][l] -= 0.5 * msum * fr.b1[i][l];
    }
  }
}

void rotate_shell_forces_to_global_block(ShellBlock& b) {
  const ShellFrameLanes& fr = b.fr;
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a)
      IMPACT3D_FOR_LANES {
        b.f[i][a][l] = b.fl[i][0][l] * fr.e[0][a][l] + b.fl[i][1][l] * fr.e[1][a][l] + b.fl[i][2][l] * fr.e[2][a][l];
        b.m[i][a][l] = b.ml[i][0][l] * fr.e[0][a][l] + b.ml[i][1][l] * fr.e[1][a][l] + b.mz[i][l] * fr.e[2][a][l];
      }
}

// The element step (calc_shell_step_length / c): the longest edge, a triangle's factor 2.
void calc_shell_step_block(const ShellGroupConstants& g, ShellBlock& b) {
  IMPACT3D_FOR_LANES {
    double lmax = 0;
    for (int i = 0; i < 4; ++i) {
      const int j = (i + 1) % 4;
      const double dx = b.x[j][0][l] - b.x[i][0][l], dy = b.x[j][1][l] - b.x[i][1][l], dz = b.x[j][2][l] - b.x[i][2][l];
      const double e = dx * dx + dy * dy + dz * dz;
      lmax = e > lmax ? e : lmax;  // std::fmax for these (never NaN, never -0)
    }
    const bool tri = b.x[2][0][l] == b.x[3][0][l] && b.x[2][1][l] == b.x[3][1][l] && b.x[2][2][l] == b.x[3][2][l];
    b.dt_e[l] = (tri ? 2.0 : 1.0) * b.fr.area[l] / std::sqrt(lmax) / g.c_plate;
  }
}

}  // namespace

bool shell_block_covers(ShellMaterialKind kind, const MaterialConstants& mc) {
  // (type 3's block radial return with rate effects groups beta * E_p apart from the scalar one's
  // rate_factor * beta * E_p: not the same bits, so rate-dependent type 3 stays scalar)
  return kind == ShellMaterialKind::elastic || kind == ShellMaterialKind::piecewise_linear ||
         (kind == ShellMaterialKind::plastic_kinematic && !(mc.rate_c > 0.0));
}

void calc_shell_bt_forces_block(const ShellGroupConstants& g, const ShellBlockMaterial& mat, double dt,
                                ShellBlock& b) {
  IMPACT3D_FOR_LANES b.de_ie[l] = b.de_hg[l] = 0;
  calc_shell_midpoint_coordinates_block(dt, b);
  calc_shell_frame_block(b.xm, b.fm);
  calc_shell_local_velocities_block(b);
  calc_shell_strain_rates_block(b);
  calc_shell_drilling_rates_block(b);
  calc_shell_point_stresses_block(g, mat, dt, b);
  IMPACT3D_FOR_LANES b.de_ie[l] = b.work[l] * b.fm.area[l] * dt;
  calc_shell_frame_block(b.x, b.fr);
  IMPACT3D_FOR_LANES {
    b.area[l] = b.fr.area[l];
    b.bad[l] = b.fm.bad[l] != 0.0 || b.fr.bad[l] != 0.0 ? 1.0 : 0.0;
  }
  calc_shell_local_forces_block(b);
  if (g.hourglass_coef > 0) calc_shell_hourglass_forces_block(g, g.hourglass_type >= 4 && mat.has_hgq, dt, b);
  for (int i = 0; i < 4; ++i) IMPACT3D_FOR_LANES b.mz[i][l] = 0;
  if (g.drill_coef > 0) calc_shell_drilling_forces_block(g, dt, b);
  rotate_shell_forces_to_global_block(b);
  calc_shell_step_block(g, b);
}

}  // namespace impact3d
