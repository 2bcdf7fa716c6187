// Fully integrated shell kernel (LS-DYNA ELFORM 16); see shell_fi.h.

#include "impact3d/element/shell_fi.h"

#include "impact3d/element/shell_parts.h"

namespace impact3d {

namespace {

using namespace shell_parts;

constexpr double kGauss = 0.57735026918962576451;  // 1 / sqrt(3)
constexpr double kNodeR[4] = {-1, 1, 1, -1}, kNodeS[4] = {-1, -1, 1, 1};
constexpr double kPointR[4] = {-kGauss, kGauss, kGauss, -kGauss}, kPointS[4] = {-kGauss, -kGauss, kGauss, kGauss};
// The tying points of the assumed transverse shear: the edges (first node, second node) whose
// midpoints they are, A (s = -1) and C (s = 1) for g_r, B (r = -1) and D (r = 1) for g_s.
constexpr int kTieEdge[4][2] = {{0, 1}, {3, 2}, {0, 3}, {1, 2}};

// One in-plane Gauss point's geometry in the frame: the Jacobian [x_r y_r; x_s y_s], its
// determinant, and the shape-function derivatives N_x, N_y.
struct FiPoint {
  double j11, j12, j21, j22, det;
  double nx[4], ny[4];
};

bool calc_fi_point(const ShellFrame& fr, int q, FiPoint& p) {
  const double r = kPointR[q], s = kPointS[q];
  double nr[4], ns[4];
  p.j11 = p.j12 = p.j21 = p.j22 = 0;
  for (int i = 0; i < 4; ++i) {
    nr[i] = 0.25 * kNodeR[i] * (1 + kNodeS[i] * s);
    ns[i] = 0.25 * kNodeS[i] * (1 + kNodeR[i] * r);
    p.j11 += nr[i] * fr.xl[i];
    p.j12 += nr[i] * fr.yl[i];
    p.j21 += ns[i] * fr.xl[i];
    p.j22 += ns[i] * fr.yl[i];
  }
  p.det = p.j11 * p.j22 - p.j12 * p.j21;
  if (!(p.det > 0)) return false;
  const double rd = 1.0 / p.det;
  for (int i = 0; i < 4; ++i) {
    p.nx[i] = (p.j22 * nr[i] - p.j12 * ns[i]) * rd;
    p.ny[i] = (p.j11 * ns[i] - p.j21 * nr[i]) * rd;
  }
  return true;
}

bool calc_fi_points(const ShellFrame& fr, FiPoint p[4]) {
  for (int q = 0; q < 4; ++q)
    if (!calc_fi_point(fr, q, p[q])) return false;
  return true;
}

// The covariant transverse shear rates at the four tying points.
void calc_tied_shears(const ShellFrame& fr, const double vl[4][3], const double wl[4][2], double tie[4]) {
  for (int t = 0; t < 4; ++t) {
    const int i = kTieEdge[t][0], j = kTieEdge[t][1];
    const double xr = 0.5 * (fr.xl[j] - fr.xl[i]), yr = 0.5 * (fr.yl[j] - fr.yl[i]);
    tie[t] = 0.5 * (vl[j][2] - vl[i][2]) + xr * 0.5 * (wl[i][1] + wl[j][1]) - yr * 0.5 * (wl[i][0] + wl[j][0]);
  }
}

// The rates at Gauss point q: membrane and curvature from N_x, N_y, the transverse shears from
// the tied ones.
ShellRates calc_fi_rates(const FiPoint& p, int q, const double vl[4][3], const double wl[4][2], const double tie[4]) {
  ShellRates r{0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    const double bx = p.nx[i], by = p.ny[i];
    r.dxx += bx * vl[i][0];
    r.dyy += by * vl[i][1];
    r.gxy += by * vl[i][0] + bx * vl[i][1];
    r.kxx += bx * wl[i][1];
    r.kyy -= by * wl[i][0];
    r.kxy += by * wl[i][1] - bx * wl[i][0];
  }
  const double s = kPointS[q], t = kPointR[q];
  const double gr = 0.5 * (1 - s) * tie[0] + 0.5 * (1 + s) * tie[1];
  const double gs = 0.5 * (1 - t) * tie[2] + 0.5 * (1 + t) * tie[3];
  const double rd = 1.0 / p.det;
  r.gxz = (p.j22 * gr - p.j12 * gs) * rd;
  r.gyz = (p.j11 * gs - p.j21 * gr) * rd;
  return r;
}

// The point state of Gauss point q's layer (set q + 1 of st).
ShellPointState fi_point_state(const ShellPointState& st, int nip, int q) {
  const std::size_t o = std::size_t(nip) * std::size_t(q + 1);
  return {st.sig + 5 * o, st.back ? st.back + 6 * o : nullptr, st.eps_p ? st.eps_p + o : nullptr,
          st.yielded ? st.yielded + o : nullptr, nullptr, nullptr};
}

// Set 0 of st: the mean of the four Gauss points (stresses, back stresses, plastic strains; a
// layer has yielded when one of its points has).
void store_fi_point_means(const ShellPointState& st, int nip) {
  for (int p = 0; p < nip; ++p) {
    for (int c = 0; c < 5; ++c) {
      double sum = 0;
      for (int q = 1; q <= 4; ++q) sum += st.sig[5 * (nip * q + p) + c];
      st.sig[5 * p + c] = 0.25 * sum;
    }
    if (st.back)
      for (int c = 0; c < 6; ++c) {
        double sum = 0;
        for (int q = 1; q <= 4; ++q) sum += st.back[6 * (nip * q + p) + c];
        st.back[6 * p + c] = 0.25 * sum;
      }
    if (st.eps_p) {
      double sum = 0;
      unsigned char y = 0;
      for (int q = 1; q <= 4; ++q) {
        sum += st.eps_p[nip * q + p];
        y = y | st.yielded[nip * q + p];
      }
      st.eps_p[p] = 0.25 * sum;
      st.yielded[p] = y;
    }
  }
}

// Adds Gauss point p's resultants n (weighted by det J) to the local corner forces and moments;
// the transverse shears go to the tying points' conjugates ctie.
void add_fi_point_forces(const FiPoint& p, int q, const ShellResultants& n, double fl[4][3], double ml[4][2],
                         double ctie[4]) {
  const double w = p.det;
  for (int i = 0; i < 4; ++i) {
    const double bx = p.nx[i], by = p.ny[i];
    fl[i][0] += w * (bx * n.Nxx + by * n.Nxy);
    fl[i][1] += w * (by * n.Nyy + bx * n.Nxy);
    ml[i][0] += w * (-by * n.Myy - bx * n.Mxy);
    ml[i][1] += w * (bx * n.Mxx + by * n.Mxy);
  }
  // det J (Qx 2d_xz + Qy 2d_yz) = g_r (J22 Qx - J21 Qy) + g_s (J11 Qy - J12 Qx)
  const double cr = p.j22 * n.Qxz - p.j21 * n.Qyz, cs = p.j11 * n.Qyz - p.j12 * n.Qxz;
  const double s = kPointS[q], t = kPointR[q];
  ctie[0] += 0.5 * (1 - s) * cr;
  ctie[1] += 0.5 * (1 + s) * cr;
  ctie[2] += 0.5 * (1 - t) * cs;
  ctie[3] += 0.5 * (1 + t) * cs;
}

// The tying points' conjugates ctie to corner forces (z) and moments (x, y): the transpose of
// calc_tied_shears at the geometry fr.
void add_tied_shear_forces(const ShellFrame& fr, const double ctie[4], double fl[4][3], double ml[4][2]) {
  for (int t = 0; t < 4; ++t) {
    const int i = kTieEdge[t][0], j = kTieEdge[t][1];
    const double xr = 0.5 * (fr.xl[j] - fr.xl[i]), yr = 0.5 * (fr.yl[j] - fr.yl[i]);
    const double c = ctie[t];
    fl[i][2] -= 0.5 * c;
    fl[j][2] += 0.5 * c;
    ml[i][1] += 0.5 * xr * c;
    ml[j][1] += 0.5 * xr * c;
    ml[i][0] -= 0.5 * yr * c;
    ml[j][0] -= 0.5 * yr * c;
  }
}

void mark_fi_shell_bad(const ShellFrame& fr, ShellKernelIO& io) {
  io.bad = true;
  io.area = fr.area;
  io.dt_e = 0;
}

// The four Gauss points' stress updates at the midpoint geometry fm (points pm); their
// resultants n[4] and the stress work of the step.
double update_fi_points(const ShellGroupConstants& g, const MaterialConstants& mc, ShellMaterialKind kind,
                        const ShellFrame& fm, const FiPoint pm[4], ShellKernelIO& io, const ShellPointState& st,
                        ShellResultants n[4]) {
  double vl[4][3], wl[4][2], tie[4];
  calc_shell_local_velocities(fm, io, vl, wl);
  calc_tied_shears(fm, vl, wl, tie);
  io.strain_rate_membrane[0] = io.strain_rate_membrane[1] = io.strain_rate_membrane[2] = 0;
  double work = 0;
  for (int q = 0; q < 4; ++q) {
    const ShellRates r = calc_fi_rates(pm[q], q, vl, wl, tie);
    n[q] = calc_shell_point_stresses(g, mc, kind, r, io.h, io.dt, fi_point_state(st, g.nip, q));
    work += n[q].work * pm[q].det;
    io.strain_rate_membrane[0] += 0.25 * r.dxx;
    io.strain_rate_membrane[1] += 0.25 * r.dyy;
    io.strain_rate_membrane[2] += 0.125 * r.gxy;
  }
  store_fi_point_means(st, g.nip);
  return work * io.dt;
}

}  // namespace

void calc_shell_fi_forces(const ShellGroupConstants& g, const MaterialConstants& mc, ShellMaterialKind kind,
                          ShellKernelIO& io, const ShellPointState& st) {
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) io.f[i][a] = io.m[i][a] = 0;
  io.de_ie = io.de_hg = 0;
  io.bad = false;

  // kinematics at the midpoint geometry; the Gauss points' stresses and work
  double xm[4][3];
  calc_shell_midpoint_coordinates(io, xm);
  ShellFrame fm;
  FiPoint pm[4];
  if (!calc_shell_frame(xm, fm) || !calc_fi_points(fm, pm)) return mark_fi_shell_bad(fm, io);
  ShellResultants n[4];
  io.de_ie = update_fi_points(g, mc, kind, fm, pm, io, st, n);
  double drate[4] = {0, 0, 0, 0};
  if (st.drill) {
    double vl[4][3], wl[4][2];
    calc_shell_local_velocities(fm, io, vl, wl);
    calc_shell_drilling_rates(fm, io, vl, drate);
  }

  // forces and moments at x^n (local frame), drilling, to the global frame
  ShellFrame fr;
  FiPoint pr[4];
  if (!calc_shell_frame(io.x, fr) || !calc_fi_points(fr, pr)) return mark_fi_shell_bad(fr, io);
  io.area = fr.area;
  double fl[4][3] = {}, ml[4][2] = {}, ctie[4] = {0, 0, 0, 0};
  for (int q = 0; q < 4; ++q) add_fi_point_forces(pr[q], q, n[q], fl, ml, ctie);
  add_tied_shear_forces(fr, ctie, fl, ml);
  double mz[4] = {0, 0, 0, 0};
  if (st.drill && g.drill_coef > 0) io.de_ie += calc_shell_drilling_forces(g, fr, io.h, io.dt, drate, st.drill, fl, mz);
  rotate_shell_forces_to_global(fr, fl, ml, mz, io);
  const bool tri = io.x[2][0] == io.x[3][0] && io.x[2][1] == io.x[3][1] && io.x[2][2] == io.x[3][2];
  io.dt_e = calc_shell_step_length(io.x, fr.area, tri) / g.c_plate;
}

}  // namespace impact3d
