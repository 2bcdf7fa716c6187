// Hughes-Liu beam and truss kernels; see beam_hl.h.

#include "impact3d/element/beam_hl.h"

#include <cmath>

#include "impact3d/element/shell_bt.h"  // gauss_legendre_rule

namespace impact3d {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTubePointsAround = 8;

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// n points and weights of a rule on [-1, 1] (Gauss-Legendre; Lobatto for the 3x3 Lobatto rule).
void line_rule(int n, bool lobatto, double* p, double* w) {
  if (lobatto) {
    p[0] = -1, p[1] = 0, p[2] = 1;
    w[0] = 1.0 / 3.0, w[1] = 4.0 / 3.0, w[2] = 1.0 / 3.0;
    return;
  }
  gauss_legendre_rule(n, p, w);
}

void update_point(BeamMaterialKind kind, const MaterialConstants& mc, const double d[3], double dt,
                  const BeamPointState& st, std::size_t i) {
  double* sig = st.sig + 3 * i;
  if (st.eps_rr) st.eps_rr[i] += d[0] * dt;
  if (kind == BeamMaterialKind::elastic) {
    update_beam_point_elastic(mc, d, dt, sig);
    return;
  }
  BeamPointPlastic h{st.back ? st.back + 6 * i : nullptr, st.eps_p + i, st.yielded + i};
  update_beam_point_plastic(kind, mc, d, dt, sig, h);
}

}  // namespace

bool beam_integration_rule(const BeamSectionData& sec, std::vector<BeamRulePoint>& rule) {
  rule.clear();
  const bool tube = sec.cst == BeamCrossSection::tubular;
  if (sec.qr <= 0) {
    if (tube || sec.user_rule.empty()) return false;
    for (const auto& p : sec.user_rule) rule.push_back({p[0], p[1], p[2]});
    return true;
  }
  if (sec.qr > 5) return false;
  if (sec.qr == 1) {  // one point at the centroid (no bending stiffness)
    rule.push_back({tube ? -2.0 : 0.0, 0.0, tube ? 4 * kPi : 4.0});
    return true;
  }
  static const int kGauss[6] = {0, 1, 2, 3, 3, 4};
  const int n = kGauss[sec.qr];
  const bool lobatto = sec.qr == 4;
  double p[4], w[4];
  line_rule(n, lobatto, p, w);
  if (tube) {  // n points across the wall (Gauss) x 8 around, the first on the s axis
    if (lobatto) gauss_legendre_rule(n, p, w);
    const double arc = 2 * kPi / kTubePointsAround;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < kTubePointsAround; ++k) rule.push_back({p[i], arc * k, w[i] * arc});
    return true;
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) rule.push_back({p[i], p[j], w[i] * w[j]});
  return true;
}

BeamSectionProperties beam_section_properties(const BeamSectionSize& sz) {
  BeamSectionProperties p;
  if (sz.cst == BeamCrossSection::tubular) {
    const double ro = 0.5 * sz.ts, ri = 0.5 * sz.tt;
    p.area = kPi * (ro * ro - ri * ri);
    p.i_s = p.i_t = 0.25 * kPi * (ro * ro * ro * ro - ri * ri * ri * ri);
  } else {
    p.area = sz.ts * sz.tt;
    p.i_t = sz.tt * sz.ts * sz.ts * sz.ts / 12.0;  // int y^2 (y along s)
    p.i_s = sz.ts * sz.tt * sz.tt * sz.tt / 12.0;  // int z^2
  }
  return p;
}

void beam_point_place(const BeamSectionSize& sz, const BeamRulePoint& p, double& y, double& z, double& da) {
  if (sz.cst == BeamCrossSection::tubular) {
    const double ro = 0.5 * sz.ts, ri = 0.5 * sz.tt;
    if (p.a < -1) {  // the one-point rule: the centroid, the whole area
      y = z = 0;
      da = kPi * (ro * ro - ri * ri);
      return;
    }
    const double r = ri + (ro - ri) * 0.5 * (1 + p.a);
    y = r * std::cos(p.b);
    z = r * std::sin(p.b);
    da = p.w * 0.5 * (ro - ri) * r;
    return;
  }
  y = 0.5 * sz.ts * p.a;
  z = 0.5 * sz.tt * p.b;
  da = 0.25 * p.w * sz.ts * sz.tt;
}

bool beam_s_axis(const double r[3], const double g[3], double s[3]) {
  const double c = dot(g, r);
  for (int a = 0; a < 3; ++a) s[a] = g[a] - c * r[a];
  const double n = std::sqrt(dot(s, s));
  const double gn = std::sqrt(dot(g, g));
  if (!(n > 1e-8 * gn) || !std::isfinite(n)) return false;
  for (int a = 0; a < 3; ++a) s[a] /= n;
  return true;
}

namespace {

// The element's axes at t^{n+1} and at the midpoint geometry, its lengths there; false when a
// length is zero or not finite.
struct BeamFrames {
  double r1[3], s1[3], t1[3], L1;  // t^{n+1}
  double rm[3], sm[3], tm[3], Lm;  // t^{n+1/2}
};

bool beam_frames(BeamKernelIO& io, BeamFrames& f, bool section_axes) {
  double d1[3], dm[3];
  for (int a = 0; a < 3; ++a) {
    d1[a] = io.x[1][a] - io.x[0][a];
    dm[a] = d1[a] - 0.5 * io.dt * (io.v[1][a] - io.v[0][a]);
  }
  f.L1 = std::sqrt(dot(d1, d1));
  f.Lm = std::sqrt(dot(dm, dm));
  if (!(f.L1 > 0) || !(f.Lm > 0) || !std::isfinite(f.L1) || !std::isfinite(f.Lm)) return false;
  for (int a = 0; a < 3; ++a) {
    f.r1[a] = d1[a] / f.L1;
    f.rm[a] = dm[a] / f.Lm;
  }
  if (!section_axes) {  // a truss: its s and t axes are never used
    for (int a = 0; a < 3; ++a) f.s1[a] = f.t1[a] = f.sm[a] = f.tm[a] = 0;
    return true;
  }
  // the s axis turns with the mean nodal spin, kept normal to r
  double wa[3], ws[3], e2n[3], e2m[3];
  for (int a = 0; a < 3; ++a) wa[a] = 0.5 * (io.w[0][a] + io.w[1][a]);
  cross(wa, io.e2, ws);
  for (int a = 0; a < 3; ++a) {
    e2n[a] = io.e2[a] + io.dt * ws[a];
    e2m[a] = io.e2[a] + 0.5 * io.dt * ws[a];
  }
  if (!beam_s_axis(f.r1, e2n, f.s1) || !beam_s_axis(f.rm, e2m, f.sm)) return false;
  cross(f.r1, f.s1, f.t1);
  cross(f.rm, f.sm, f.tm);
  return true;
}

// End forces and moments of the resultants in the frame at t^{n+1} (internal: the node pass
// subtracts them), and the frame's s axis handed on.
void assemble_beam_forces(const BeamFrames& f, BeamKernelIO& io, bool section_axes) {
  const double N = io.res[0], Qs = io.res[1], Qt = io.res[2], T = io.res[3], Ms = io.res[4], Mt = io.res[5];
  const double h = 0.5 * f.L1;
  for (int a = 0; a < 3; ++a) {
    const double F = N * f.r1[a] + Qs * f.s1[a] + Qt * f.t1[a];
    const double M = Mt * f.t1[a] + Ms * f.s1[a] + T * f.r1[a];
    const double S = h * (Qt * f.s1[a] - Qs * f.t1[a]);
    io.f[0][a] = -F;
    io.f[1][a] = F;
    io.m[0][a] = S - M;
    io.m[1][a] = S + M;
  }
  if (section_axes)
    for (int a = 0; a < 3; ++a) io.e2[a] = f.s1[a];
  io.length = f.L1;
}

void zero_outputs(BeamKernelIO& io) {
  for (int j = 0; j < 2; ++j)
    for (int a = 0; a < 3; ++a) io.f[j][a] = io.m[j][a] = 0;
  for (double& r : io.res) r = 0;
  io.de_ie = 0;
}

}  // namespace

void calc_beam_hl_forces(const BeamSectionSize& sz, const std::vector<BeamRulePoint>& rule, double shrf,
                         const MaterialConstants& mc, BeamMaterialKind kind, BeamKernelIO& io,
                         const BeamPointState& st) {
  zero_outputs(io);
  BeamFrames f;
  io.bad = !beam_frames(io, f, true);
  if (io.bad) return;
  double dv[3], dw[3], ws[3];
  for (int a = 0; a < 3; ++a) {
    dv[a] = io.v[1][a] - io.v[0][a];
    dw[a] = io.w[1][a] - io.w[0][a];
    ws[a] = io.w[0][a] + io.w[1][a];
  }
  const double inv = 1.0 / f.Lm;
  const double d0 = dot(dv, f.rm) * inv;
  const double kt = dot(dw, f.tm) * inv, ks = dot(dw, f.sm) * inv, phi = dot(dw, f.rm) * inv;
  const double gs = dot(dv, f.sm) * inv - 0.5 * dot(ws, f.tm);
  const double gt = dot(dv, f.tm) * inv + 0.5 * dot(ws, f.sm);
  double N = 0, Qs = 0, Qt = 0, T = 0, Ms = 0, Mt = 0, work = 0;
  for (std::size_t i = 0; i < rule.size(); ++i) {
    double y, z, da;
    beam_point_place(sz, rule[i], y, z, da);
    const double d[3] = {d0 - y * kt + z * ks, 0.5 * shrf * (gs - z * phi), 0.5 * shrf * (gt + y * phi)};
    double* sig = st.sig + 3 * i;
    const double o0 = sig[0], o1 = sig[1], o2 = sig[2];
    update_point(kind, mc, d, io.dt, st, i);
    work += da * (0.5 * (o0 + sig[0]) * d[0] + (o1 + sig[1]) * d[1] + (o2 + sig[2]) * d[2]);
    N += da * sig[0];
    Ms += da * z * sig[0];
    Mt -= da * y * sig[0];
    Qs += da * sig[1];
    Qt += da * sig[2];
    T += da * (y * sig[2] - z * sig[1]);
  }
  io.res[0] = N;
  io.res[1] = shrf * Qs;
  io.res[2] = shrf * Qt;
  io.res[3] = shrf * T;
  io.res[4] = Ms;
  io.res[5] = Mt;
  io.de_ie = work * io.dt * f.Lm;
  assemble_beam_forces(f, io, true);
}

void calc_truss_forces(double area, const MaterialConstants& mc, BeamMaterialKind kind, BeamKernelIO& io,
                       const BeamPointState& st) {
  zero_outputs(io);
  BeamFrames f;
  io.bad = !beam_frames(io, f, false);
  if (io.bad) return;
  double dv[3];
  for (int a = 0; a < 3; ++a) dv[a] = io.v[1][a] - io.v[0][a];
  const double d[3] = {dot(dv, f.rm) / f.Lm, 0.0, 0.0};
  const double o0 = st.sig[0];
  update_point(kind, mc, d, io.dt, st, 0);
  io.de_ie = area * 0.5 * (o0 + st.sig[0]) * d[0] * io.dt * f.Lm;
  io.res[0] = area * st.sig[0];
  assemble_beam_forces(f, io, false);
}

}  // namespace impact3d

namespace impact3d {

void calc_beam_bs_forces(const BeamResultantSection& sec, const MaterialConstants& mc, BeamKernelIO& io, double state[6]) {
  zero_outputs(io);
  BeamFrames f;
  io.bad = !beam_frames(io, f, true);
  if (io.bad) return;
  double dv[3], dw[3];
  for (int a = 0; a < 3; ++a) {
    dv[a] = io.v[1][a] - io.v[0][a];
    dw[a] = io.w[1][a] - io.w[0][a];
  }
  const double L = f.Lm, dt = io.dt;
  // chord spins about t and s, and the ends' rotation rates relative to the chord
  const double chord_t = dot(dv, f.sm) / L, chord_s = -dot(dv, f.tm) / L;
  const double th_t[2] = {dot(io.w[0], f.tm) - chord_t, dot(io.w[1], f.tm) - chord_t};
  const double th_s[2] = {dot(io.w[0], f.sm) - chord_s, dot(io.w[1], f.sm) - chord_s};
  const double elong = dot(dv, f.rm), twist = dot(dw, f.rm);
  const double kt = mc.E * sec.itt / L, ks = mc.E * sec.iss / L;
  double old[6];
  for (int k = 0; k < 6; ++k) old[k] = state[k];
  state[0] += dt * mc.E * sec.area * elong / L;
  state[1] += dt * mc.G * sec.jt * twist / L;
  state[2] += dt * ks * (4 * th_s[0] + 2 * th_s[1]);
  state[3] += dt * ks * (2 * th_s[0] + 4 * th_s[1]);
  state[4] += dt * kt * (4 * th_t[0] + 2 * th_t[1]);
  state[5] += dt * kt * (2 * th_t[0] + 4 * th_t[1]);
  const double rate[6] = {elong, twist, th_s[0], th_s[1], th_t[0], th_t[1]};
  double work = 0;
  for (int k = 0; k < 6; ++k) work += 0.5 * (old[k] + state[k]) * rate[k];
  io.de_ie = work * dt;
  // end forces and moments at t^{n+1}: axial, torsion, end moments, and the shear couples
  // that balance them
  const double N = state[0], T = state[1];
  const double Qs = -(state[4] + state[5]) / f.L1;  // along s, from the moments about t
  const double Qt = (state[2] + state[3]) / f.L1;   // along t, from the moments about s
  for (int a = 0; a < 3; ++a) {
    const double F = N * f.r1[a] + Qs * f.s1[a] + Qt * f.t1[a];
    io.f[0][a] = -F;
    io.f[1][a] = F;
    io.m[0][a] = -T * f.r1[a] + state[2] * f.s1[a] + state[4] * f.t1[a];
    io.m[1][a] = T * f.r1[a] + state[3] * f.s1[a] + state[5] * f.t1[a];
    io.e2[a] = f.s1[a];
  }
  io.length = f.L1;
  io.res[0] = N;
  io.res[1] = Qs;
  io.res[2] = Qt;
  io.res[3] = T;
  io.res[4] = 0.5 * (state[3] - state[2]);  // the moments at the middle (the ends' mean, signed as the section's)
  io.res[5] = 0.5 * (state[5] - state[4]);
}

}  // namespace impact3d
