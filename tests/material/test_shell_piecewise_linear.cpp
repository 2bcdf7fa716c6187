// The plane-stress form of type 24 (*MAT_PIECEWISE_LINEAR_PLASTICITY, shells:
// update_plane_stress_piecewise_linear) at one integration point against closed forms:
// uniaxial plane stress (sigma_yy = 0 by iterating d_yy here, sigma_zz = 0 by the kernel's
// d_zz iterations) follows the flow table through and past its last point, with the thickness
// strain of plastic incompressibility; a two-point table is the bilinear type 3 (beta = 1);
// Cowper-Symonds scaling with VP = 0 and VP = 1; elastic unloading.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "impact3d/material/material_types.h"
#include "impact3d/material/plane_stress.h"

using namespace impact3d;

namespace {

// Non-dimensional metal-like constants: E = 200, nu = 0.3, a 4-point flow table (yield 0.4)
// extended beyond 0.2 with its last slope.
const std::vector<std::pair<double, double>> kTable = {{0.0, 0.4}, {0.01, 0.6}, {0.05, 0.8}, {0.2, 0.9}};

MaterialData table_material(const std::vector<std::pair<double, double>>& pts, double C = 0, double P = 0, double vp = 0) {
  const MaterialType& t = material_type(24);
  MaterialData md;
  md.type = 24;
  md.number = 1;
  set_param_defaults(md, t);
  md.rho = 7.8;
  md.E = 200;
  md.nu = 0.3;
  md.rate_c = C;
  md.rate_p = P;
  param_value(md, *find_param(t, "VP")) = vp;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    param_value(md, *find_param(t, "EPS" + std::to_string(i + 1))) = pts[i].first;
    param_value(md, *find_param(t, "ES" + std::to_string(i + 1))) = pts[i].second;
  }
  return md;
}

std::string fmt_e(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3e", v);
  return b;
}

double flow(const std::vector<std::pair<double, double>>& pts, double ep) {
  std::size_t i = 0;
  while (i + 2 < pts.size() && ep > pts[i + 1].first) ++i;
  const double H = (pts[i + 1].second - pts[i].second) / (pts[i + 1].first - pts[i].first);
  return pts[i].second + H * (ep - pts[i].first);
}

// One integration point of a shell: stress, plastic strain, back stress (type 3 only), and
// the strains integrated from the rates.
struct Point {
  double sig[5] = {0, 0, 0, 0, 0};
  double back[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0;
  unsigned char yielded = 0;
  double exx = 0, eyy = 0, ezz = 0;
  double last_rate[3] = {0, 0, 0};  // the last step's d_xx, d_yy, d_zz
};

using Update = std::function<double(const double d[5], double dt, Point& p)>;

Update type24(const MaterialConstants& m) {
  return [&m](const double d[5], double dt, Point& p) {
    return update_plane_stress_piecewise_linear(m, d, dt, p.sig, PlaneStressPlastic{nullptr, &p.eps_p, &p.yielded});
  };
}
Update type3(const MaterialConstants& m) {
  return [&m](const double d[5], double dt, Point& p) {
    return update_plane_stress_plastic_kinematic(m, d, dt, p.sig, PlaneStressPlastic{p.back, &p.eps_p, &p.yielded});
  };
}

// One step of uniaxial plane stress along x at d_xx: d_yy by secant iterations (on copies of
// the point) so that sigma_yy = 0 to 1e-13 of sigma_xx.
void step_uniaxial(const Update& u, double dxx, double dt, Point& p) {
  auto trial = [&](double dyy, Point& q) {
    q = p;
    const double d[5] = {dxx, dyy, 0, 0, 0};
    const double dzz = u(d, dt, q);
    q.last_rate[0] = dxx;
    q.last_rate[1] = dyy;
    q.last_rate[2] = dzz;
    q.exx += dxx * dt;
    q.eyy += dyy * dt;
    q.ezz += dzz * dt;
    return q.sig[1];
  };
  Point a, b;
  double y0 = -0.3 * dxx, y1 = -0.5 * dxx;
  double f0 = trial(y0, a), f1 = trial(y1, b);
  for (int it = 0; it < 60 && std::fabs(f1) > 1e-13 * (std::fabs(b.sig[0]) + 1e-30) && f1 != f0; ++it) {
    const double y2 = y1 - f1 * (y1 - y0) / (f1 - f0);
    y0 = y1;
    f0 = f1;
    y1 = y2;
    f1 = trial(y1, b);
  }
  p = b;
}

}  // namespace

// Uniaxial plane-stress tension at constant strain rate to 30 % (the table ends at 20 %):
// sigma_xx = flow(eps_p) at every step (the return on the table is exact: tolerance 1e-9 of the
// stress, the plane-stress iterations' 1e-10), sigma_yy = 0, the stress point has sigma_zz = 0
// (the 3-D update with the returned d_zz), and the strains are those of an elastic-plastically
// incompressible bar: e_yy = e_zz = -nu s/E - eps_p/2, e_xx = s/E + eps_p (1e-9 absolute).
TEST(ShellPiecewiseLinear, UniaxialPlaneStressFollowsTheTableAndIncompressibility) {
  const MaterialConstants m = derive_constants(table_material(kTable), Model{});
  const Update u = type24(m);
  Point p;
  const double rate = 1.0, dt = 1e-4;  // 3000 steps to 0.3
  int checked = 0;
  double ep_prev = 0, worst_flow = 0, worst_strain = 0;
  for (int k = 0; k < 3000; ++k) {
    step_uniaxial(u, rate, dt, p);
    EXPECT_GE(p.eps_p, ep_prev);
    ep_prev = p.eps_p;
    EXPECT_NEAR(p.sig[1], 0.0, 1e-12);
    if (p.eps_p > 0) {
      ASSERT_NEAR(p.sig[0], flow(kTable, p.eps_p), 1e-9 * p.sig[0]) << "step " << k << " eps_p " << p.eps_p;
      worst_flow = std::max(worst_flow, std::fabs(p.sig[0] / flow(kTable, p.eps_p) - 1));
      ++checked;
    } else {
      EXPECT_NEAR(p.sig[0], m.E * p.exx, 1e-12);
    }
    const double s = p.sig[0];
    ASSERT_NEAR(p.exx, s / m.E + p.eps_p, 1e-9) << "step " << k;
    ASSERT_NEAR(p.ezz, -m.nu * s / m.E - 0.5 * p.eps_p, 1e-9) << "step " << k;
    ASSERT_NEAR(p.eyy, p.ezz, 1e-9) << "step " << k;
    worst_strain = std::max(worst_strain, std::fabs(p.ezz + m.nu * s / m.E + 0.5 * p.eps_p));
  }
  RecordProperty("worst_relative_flow_error", fmt_e(worst_flow));
  RecordProperty("worst_thickness_strain_error", fmt_e(worst_strain));
  EXPECT_GT(checked, 2900);
  // past the last point: its slope extended (0.9 + (0.1 / 0.15) (eps_p - 0.2))
  EXPECT_GT(p.eps_p, 0.29);
  EXPECT_NEAR(p.sig[0], 0.9 + (0.1 / 0.15) * (p.eps_p - 0.2), 1e-9);
  // the stress point is plane: the 3-D update from the step before with the returned d_zz
  // (re-run from a copy) has sigma_zz = 0 to the iterations' 1e-10 (sigma_y + |sigma|)
  Point q = p;
  SolidPointState st;
  st.sig[0] = q.sig[0];
  st.sig[1] = q.sig[1];
  st.eps_p = q.eps_p;
  st.yielded = 1;
  const double d[5] = {rate, -0.5 * rate, 0, 0, 0};
  const double dzz = update_plane_stress_piecewise_linear(m, d, dt, q.sig, PlaneStressPlastic{nullptr, &q.eps_p, &q.yielded});
  const double d3[6] = {rate, -0.5 * rate, dzz, 0, 0, 0};
  update_stress_piecewise_linear(m, d3, dt, st);
  EXPECT_NEAR(st.sig[2], 0.0, 1e-10 * (m.sigma_y + 2 * std::fabs(st.sig[0])) + 1e-15);
  EXPECT_NEAR(dzz, -0.5 * rate, 1e-3);  // (1/2 of d_yy's excess is elastic: close to incompressible)
}

// A two-point table (0, SIGY), (1, SIGY + E_p) with E_p = E ETAN / (E - ETAN) is type 3 with
// beta = 1: a non-proportional plane-stress path (biaxial, shear, transverse shear, reversal)
// gives the same stresses and plastic strains to 1e-9 of the yield stress (the two returns are
// the same algebra in different operation orders; the secant iterations stop at 1e-10).
TEST(ShellPiecewiseLinear, TwoPointTableIsBilinearType3) {
  const double sy = 0.4, et = 2.0, E = 200;
  const double Ep = E * et / (E - et);
  const MaterialConstants m24 = derive_constants(table_material({{0.0, sy}, {1.0, sy + Ep}}), Model{});
  MaterialData md3;
  md3.type = 3;
  md3.number = 1;
  set_param_defaults(md3, material_type(3));
  md3.rho = 7.8;
  md3.E = E;
  md3.nu = 0.3;
  md3.sigma_y = sy;
  md3.E_tan = et;
  md3.beta = 1;
  const MaterialConstants m3 = derive_constants(md3, Model{});
  ASSERT_EQ(m3.beta, 1.0);
  ASSERT_NEAR(m3.E_p, Ep, 1e-12 * Ep);
  const Update u24 = type24(m24), u3 = type3(m3);
  Point a, b;
  const double dt = 1e-4;
  double largest = 0;
  for (int k = 0; k < 1500; ++k) {
    const double t = k * dt;
    double d[5];
    if (k < 500) {
      d[0] = 1.0, d[1] = 0.4, d[2] = 0.2, d[3] = 0.05, d[4] = -0.03;
    } else if (k < 1000) {
      d[0] = -0.5, d[1] = 0.8, d[2] = -0.6 * std::cos(20 * t), d[3] = 0.0, d[4] = 0.1;
    } else {
      d[0] = -1.0, d[1] = -1.0, d[2] = 0.3, d[3] = -0.05, d[4] = 0.0;
    }
    u24(d, dt, a);
    u3(d, dt, b);
    for (int c = 0; c < 5; ++c) {
      ASSERT_NEAR(a.sig[c], b.sig[c], 1e-9 * sy) << "step " << k << " component " << c;
      largest = std::max(largest, std::fabs(a.sig[c] - b.sig[c]));
    }
    ASSERT_NEAR(a.eps_p, b.eps_p, 1e-11) << "step " << k;
    ASSERT_EQ(a.yielded, b.yielded);
  }
  EXPECT_GT(a.eps_p, 0.05);
  RecordProperty("largest_stress_difference", fmt_e(largest));
}

// Cowper-Symonds, VP = 0: the yield stress scaled by R = 1 + (rate/C)^(1/P) with rate the norm
// sqrt(D:D) of the step's 3-D rate (d_xx, d_yy, d_zz); VP = 1: by R of the plastic strain rate
// (the step's increment over dt).  Uniaxial plane stress at d_xx = 200 (C = 40, P = 5: R about 2.4):
// sigma_xx = R flow(eps_p) to 1e-9, from the last step's rates.
TEST(ShellPiecewiseLinear, CowperSymondsScalesTheYieldStress) {
  const double C = 40, P = 5, rate = 200, dt = 1e-6;
  for (int vp = 0; vp <= 1; ++vp) {
    const MaterialConstants m = derive_constants(table_material(kTable, C, P, vp), Model{});
    const Update u = type24(m);
    Point p;
    double ep_before = 0;
    for (int k = 0; k < 500; ++k) {  // to 10 %
      ep_before = p.eps_p;
      step_uniaxial(u, rate, dt, p);
    }
    ASSERT_GT(p.eps_p, 0.05) << "VP " << vp;
    double r;
    if (vp == 0) {
      r = std::sqrt(p.last_rate[0] * p.last_rate[0] + p.last_rate[1] * p.last_rate[1] + p.last_rate[2] * p.last_rate[2]);
      EXPECT_NEAR(r, rate * std::sqrt(1.5), 0.02 * rate);  // near the incompressible sqrt(3/2) rate
    } else {
      r = (p.eps_p - ep_before) / dt;
      EXPECT_NEAR(r, rate, 0.02 * rate);  // the plastic rate near the total one
    }
    const double R = 1 + std::pow(r / C, 1 / P);
    EXPECT_GT(R, 2.3);
    EXPECT_NEAR(p.sig[0], R * flow(kTable, p.eps_p), 1e-9 * p.sig[0]) << "VP " << vp;
    RecordProperty("R_vp" + std::to_string(vp), std::to_string(R));
    RecordProperty("relative_error_vp" + std::to_string(vp), fmt_e(p.sig[0] / (R * flow(kTable, p.eps_p)) - 1));
    EXPECT_NEAR(p.sig[1], 0.0, 1e-12);
  }
}

// Unloading is elastic: after 5 % plastic strain, a reversed strain increment of half the
// elastic range changes sigma_xx by E (uniaxial plane stress) times it, the plastic strain not
// at all (1e-12); the reloading yields again at the hardened flow stress.
TEST(ShellPiecewiseLinear, UnloadingIsElastic) {
  const MaterialConstants m = derive_constants(table_material(kTable), Model{});
  const Update u = type24(m);
  Point p;
  const double dt = 1e-4;
  while (p.eps_p < 0.05) step_uniaxial(u, 1.0, dt, p);
  const double s0 = p.sig[0], ep = p.eps_p, e0 = p.exx;
  const int n = int(std::ceil(0.5 * s0 / m.E / dt));  // reversed strain 0.5 s0 / E
  for (int k = 0; k < n; ++k) step_uniaxial(u, -1.0, dt, p);
  EXPECT_EQ(p.eps_p, ep);
  EXPECT_NEAR(p.sig[0], s0 - m.E * (e0 - p.exx), 1e-12);
  EXPECT_LT(p.sig[0], 0.55 * s0);
  for (int k = 0; k < 2 * n; ++k) step_uniaxial(u, 1.0, dt, p);
  EXPECT_GT(p.eps_p, ep);
  EXPECT_NEAR(p.sig[0], flow(kTable, p.eps_p), 1e-9 * p.sig[0]);
}
