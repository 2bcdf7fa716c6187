// Johnson-Cook plasticity (types 15 and 98) through single-point strain paths against closed
// forms: flow stress against plastic strain, strain rate and temperature; with n = 1, C = 0
// and no heating it is bilinear hardening (type 24 with a two-point table); adiabatic heating
// books the plastic work; Johnson-Cook damage; the pressure cutoff; SIGMAX.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "impact3d/material/material_types.h"

using namespace impact3d;

namespace {

// Non-dimensional: E 200, nu 0.3 (G 76.92, K 166.7), rho 7.8.
MaterialData jc_material(int type, const std::map<std::string, double>& values) {
  const MaterialType& t = material_type(type);
  MaterialData md;
  md.type = type;
  set_param_defaults(md, t);
  md.rho = 7.8, md.E = 200, md.nu = 0.3;
  if (type == 15) param_value(md, *find_param(t, "G")) = 200 / 2.6;
  for (const auto& [k, v] : values) {
    const MaterialParam* p = find_param(t, k);
    EXPECT_TRUE(p) << k;
    if (p) param_value(md, *p) = v;
  }
  return md;
}

struct Point {
  MaterialConstants m;
  SolidPointState s;
  const SolidKernel* k;
  explicit Point(const MaterialData& md) : m(derive_constants(md, Model{})), k(&material_type(md.type).solid) {}
  void step(const double d[6], double dt) { k->update_point(m, d, dt, s); }
  double q() const {
    const double p = (s.sig[0] + s.sig[1] + s.sig[2]) / 3;
    const double a = s.sig[0] - p, b = s.sig[1] - p, c = s.sig[2] - p;
    return std::sqrt(1.5 * (a * a + b * b + c * c + 2 * (s.sig[3] * s.sig[3] + s.sig[4] * s.sig[4] + s.sig[5] * s.sig[5])));
  }
};

// Closed form in uniaxial strain eps: the plastic strain solving 2 G eps - 3 G ep = f h(ep),
// h = A + B ep^n (bisection to 1e-16).
double plastic_strain_for(double G, double eps, double f, double A, double B, double n) {
  auto h = [&](double ep) { return A + B * std::pow(ep, n); };
  if (2 * G * eps <= f * h(0)) return 0;
  double lo = 0, hi = 2 * eps / 3;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (2 * G * eps - 3 * G * mid > f * h(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// n = 1, C = 0, no heating: sigma_y = A + B eps_p, type 24's two-point table (0, A), (1, A + B);
// both returns are exact (Newton to 1e-15 here), so a general strain path agrees to rounding.
TEST(MatJohnsonCook, LinearHardeningWithoutRateOrHeatIsBilinear) {
  const MaterialType& t24 = material_type(24);
  MaterialData md24;
  md24.type = 24;
  set_param_defaults(md24, t24);
  md24.rho = 7.8, md24.E = 200, md24.nu = 0.3;
  param_value(md24, *find_param(t24, "ES1")) = 0.4;
  param_value(md24, *find_param(t24, "EPS2")) = 1.0;
  param_value(md24, *find_param(t24, "ES2")) = 1.0;
  for (int type : {15, 98}) {
    Point jc(jc_material(type, {{"A", 0.4}, {"B", 0.6}, {"N", 1.0}, {"C", 0.0}}));
    Point pl(md24);
    for (int n = 0; n < 600; ++n) {
      const double d[6] = {2.5e-4, -1e-4, 0.5e-4, 1e-4, 0, -0.5e-4};
      jc.step(d, 1.0);
      pl.step(d, 1.0);
    }
    EXPECT_GT(pl.s.eps_p, 0.05);
    EXPECT_NEAR(jc.s.eps_p, pl.s.eps_p, 1e-13) << type;
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(jc.s.sig[c], pl.s.sig[c], 1e-12) << type << " " << c;
  }
}

// Uniaxial strain at rate r: the effective strain rate is 2r/3, R = 1 + C ln(2r / (3 EPSO)),
// and q = R (A + B ep^n) with 2 G eps - 3 G ep = q.  Tolerances: the Newton return converges to
// 1e-15, the path is proportional (radial return exact): 1e-12 in plastic strain, 1e-11 in
// stress.  Below EPSO there is no rate effect.
TEST(MatJohnsonCook, FlowStressAgainstStrainAndRate) {
  const double A = 0.4, B = 0.6, n = 0.3, C = 0.05;
  for (int type : {98, 15}) {
    for (double r : {0.3, 30.0, 3000.0}) {
      Point p(jc_material(type, {{"A", A}, {"B", B}, {"N", n}, {"C", C}, {"EPSO", 1.0}}));
      const double dt = 1e-3 / r;  // strain 1e-3 per step
      for (int k = 0; k < 300; ++k) {
        const double d[6] = {r, 0, 0, 0, 0, 0};
        p.step(d, dt);
      }
      const double R = 2 * r / 3 > 1 ? 1 + C * std::log(2 * r / 3) : 1.0;
      const double ep = plastic_strain_for(p.m.G, 300 * 1e-3, R, A, B, n);
      EXPECT_GT(ep, 0.1);
      EXPECT_NEAR(p.s.eps_p, ep, 1e-12) << type << " rate " << r;
      EXPECT_NEAR(p.q(), R * (A + B * std::pow(ep, n)), 1e-11) << type << " rate " << r;
    }
  }
}

// Type 15 at a fixed temperature (CP 0: no heating; T* = 0.5 set in the history): the flow
// stress is scaled by 1 - T*^M.
TEST(MatJohnsonCook, ThermalSoftening) {
  const double A = 0.4, B = 0.6, n = 0.3, M = 1.5, TR = 300, TM = 1300;
  Point p(jc_material(15, {{"A", A}, {"B", B}, {"N", n}, {"M", M}, {"TM", TM}, {"TR", TR}}));
  p.s.hist[0] = 0.5 * (TM - TR);  // temperature rise: T* = 0.5
  for (int k = 0; k < 300; ++k) {
    const double d[6] = {1e-3, 0, 0, 0, 0, 0};
    p.step(d, 1.0);
  }
  const double theta = 1 - std::pow(0.5, M);
  const double ep = plastic_strain_for(p.m.G, 0.3, theta, A, B, n);
  EXPECT_EQ(p.s.hist[0], 0.5 * (TM - TR));
  EXPECT_NEAR(p.s.eps_p, ep, 1e-12);
  EXPECT_NEAR(p.q(), theta * (A + B * std::pow(ep, n)), 1e-11);
}

// Adiabatic heating: rho CP dT = sigma_y d eps_p, so rho CP (T - TR) is the plastic work =
// the stress work (trapezoid, exact for this piecewise-linear path up to the return's
// increments) minus the elastic energy sigma_m^2 / 2K + q^2 / 6G.  The heating sums the
// end-of-step flow stress times d eps_p (a rectangle rule): 2000 steps, 2e-3 relative.
TEST(MatJohnsonCook, AdiabaticHeatingBooksThePlasticWork) {
  const double rho = 7.8, cp = 0.005;
  Point p(jc_material(15, {{"A", 0.4}, {"B", 0.6}, {"N", 0.3}, {"M", 1.0}, {"TM", 10}, {"TR", 0}, {"CP", cp}}));
  double work = 0;
  for (int k = 0; k < 2000; ++k) {
    const double old = p.s.sig[0];
    const double d[6] = {1e-4, 0, 0, 0, 0, 0};
    p.step(d, 1.0);
    work += 0.5 * (old + p.s.sig[0]) * 1e-4;
  }
  const double sm = (p.s.sig[0] + p.s.sig[1] + p.s.sig[2]) / 3, q = p.q();
  const double plastic_work = work - sm * sm / (2 * p.m.K) - q * q / (6 * p.m.G);
  EXPECT_GT(p.s.hist[0], 1.0);  // heated (T* > 0.1)
  EXPECT_NEAR(q, (0.4 + 0.6 * std::pow(p.s.eps_p, 0.3)) * (1 - p.s.hist[0] / 10), 1e-3);  // and as soft as T* says
  std::printf("adiabatic heating: rho CP dT %.6e, plastic work %.6e (relative %.2e), T* %.3f\n", rho * cp * p.s.hist[0],
              plastic_work, std::fabs(rho * cp * p.s.hist[0] / plastic_work - 1), p.s.hist[0] / 10);
  EXPECT_NEAR(rho * cp * p.s.hist[0], plastic_work, 2e-3 * plastic_work);
}

// Johnson-Cook damage in simple shear (sigma* = 0, rate below EPSO, no thermal term):
// eps_f = D1 + D2, D = eps_p / eps_f; the solid fails (D >= 1) at eps_p = D1 + D2.
TEST(MatJohnsonCook, DamageInShear) {
  const double D1 = 0.05, D2 = 0.25;
  Point p(jc_material(15, {{"A", 0.4}, {"B", 0.6}, {"N", 0.3}, {"EPSO", 1e6}, {"D1", D1}, {"D2", D2}, {"D3", -3}, {"D4", 0.1}}));
  EXPECT_EQ(p.m.fail_history, 1);
  for (int k = 0; k < 4000; ++k) {
    const double d[6] = {0, 0, 0, 2e-4, 0, 0};
    p.step(d, 1.0);
    EXPECT_NEAR(p.s.hist[1], p.s.eps_p / (D1 + D2), 1e-12);
  }
  EXPECT_GT(p.s.hist[1], 1.0);  // past failure: the element pass deletes the solid
}

// Pressure cutoff: hydrostatic tension stops at mean stress -PC.
TEST(MatJohnsonCook, PressureCutoff) {
  Point p(jc_material(15, {{"A", 0.4}, {"PC", -0.2}}));
  for (int k = 0; k < 10; ++k) {
    const double d[6] = {1e-4, 1e-4, 1e-4, 0, 0, 0};
    p.step(d, 1.0);
    const double sm = std::min(3 * p.m.K * 1e-4 * (k + 1), 0.2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.s.sig[c], sm, 1e-15) << k;
  }
}

// Type 98: the flow stress never exceeds SIGMAX.
TEST(MatJohnsonCook, SimplifiedCapsAtSigmax) {
  Point p(jc_material(98, {{"A", 0.4}, {"B", 0.6}, {"N", 0.3}, {"SIGMAX", 0.7}}));
  for (int k = 0; k < 300; ++k) {
    const double d[6] = {1e-3, 0, 0, 0, 0, 0};
    p.step(d, 1.0);
  }
  EXPECT_NEAR(p.q(), 0.7, 1e-12);
}
