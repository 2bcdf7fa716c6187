// Johnson-Cook plasticity (types 15 and 98) through single-point strain paths against closed
// forms: flow stress against plastic strain, strain rate and temperature; with n = 1, C = 0
// and no heating it is bilinear hardening (type 24 with a two-point table); adiabatic heating
// books the plastic work; Johnson-Cook damage, with and without erosion (EROD); the pressure
// cutoff and the spall types; the rate forms (RATEOP 0-3); the viscoplastic form (VP = 1);
// SIGMAX.

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

// Pressure cutoff (SPALL 1): hydrostatic tension stops at mean stress -PC.
TEST(MatJohnsonCook, PressureCutoff) {
  Point p(jc_material(15, {{"A", 0.4}, {"PC", -0.2}, {"SPALL", 1}}));
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

// Uniaxial strain in tension, elastic (A large): sigma_xx = (K + 4G/3) eps is the largest
// principal stress, K eps the mean stress.  PC = -0.201, eps 1e-5 a step: SPALL 1 bounds the
// mean stress at 0.201 and keeps the deviator (2G (eps - eps/3); 1e-13); SPALL 2 (and 0,
// LS-DYNA's default) spalls in the first step with sigma_xx >= 0.201 (step 75: 269.2 * 7.5e-4 =
// 0.2019; step 74 0.1992), SPALL 3 in the first with K eps >= 0.201 (step 121: 166.7 * 1.21e-3
// = 0.2017; step 120 0.2000); spalled, the stress is zero in tension and a pure pressure K
// tr(eps) in compression afterwards (no deviator).  PC = 0: no limit, no spall.
TEST(MatJohnsonCook, SpallTypesAtTheirThresholds) {
  const double de = 1e-5;
  for (double spall : {0.0, 1.0, 2.0, 3.0}) {
    for (double pc : {-0.201, 0.0}) {
      Point p(jc_material(15, {{"A", 100}, {"PC", pc}, {"SPALL", spall}}));
      const double K = p.m.K, G = p.m.G, M = K + 4 * G / 3;
      const int mode = pc == 0 ? 0 : spall == 0 ? 2 : int(spall);
      int spalled_at = 0, expect_at = 0;
      double sx = 0, sm = 0;  // the kernel's own sums of the elastic path
      for (int k = 1; k <= 200; ++k) {
        const double d[6] = {de, 0, 0, 0, 0, 0};
        p.step(d, 1.0);
        sx += M * de, sm += K * de;
        if (expect_at == 0 && ((mode == 2 && sx >= 0.201) || (mode == 3 && sm >= 0.201))) expect_at = k;
        if (spalled_at == 0 && p.s.hist[2] != 0) spalled_at = k;
        const double e = k * de;
        if (mode == 1) {  // the mean stress bounded, the deviator kept
          const double m = std::min(K * e, 0.201);
          EXPECT_NEAR(p.s.sig[0], m + 4 * G * e / 3, 1e-13) << k;
          EXPECT_NEAR(p.s.sig[1], m - 2 * G * e / 3, 1e-13) << k;
        } else if (expect_at == 0) {  // elastic
          EXPECT_NEAR(p.s.sig[0], M * e, 1e-13) << spall << " " << k;
          EXPECT_NEAR(p.s.sig[1], (K - 2 * G / 3) * e, 1e-13) << spall << " " << k;
        } else {  // spalled: no tension
          for (int c = 0; c < 6; ++c) EXPECT_EQ(p.s.sig[c], 0.0) << spall << " " << k;
        }
      }
      EXPECT_EQ(spalled_at, expect_at) << spall << " " << pc;
      if (mode == 2) {
        EXPECT_EQ(spalled_at, 75);
      } else if (mode == 3) {
        EXPECT_EQ(spalled_at, 121);
      }
      if (mode < 2) continue;
      for (int k = 1; k <= 20; ++k) {  // compressed again: a pressure, no deviator
        const double d[6] = {-de, 0, 0, 0, 0, 0};
        p.step(d, 1.0);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.s.sig[c], -K * de * k, 1e-15) << k;
        for (int c = 3; c < 6; ++c) EXPECT_EQ(p.s.sig[c], 0.0);
      }
    }
  }
}

// The rate forms at constant rate (VP = 0) in uniaxial strain at rate r: x = 2r/3 / EPSO, the
// flow stress R(x) (A + B ep^n) with R = 1 + C ln x + C2 ln^2 x (RATEOP 1, Huh-Kang), x^C (2,
// Allen-Rule-Jones), 1 + (2r/3 / C)^(1/P) (3, Cowper-Symonds, the rate itself), R = 1 for x <= 1
// in forms 1 and 2.  Tolerances as for RATEOP 0 above (1e-12 in plastic strain, 1e-11 in stress).
TEST(MatJohnsonCook, RateFormsAgainstTheirFormulas) {
  const double A = 0.4, B = 0.6, n = 0.3;
  for (int form : {1, 2, 3}) {
    for (double r : {0.3, 30.0, 3000.0}) {
      const double C = form == 3 ? 40.0 : form == 2 ? 0.03 : 0.05, C2 = form == 3 ? 5.0 : 0.004;
      Point p(jc_material(15, {{"A", A}, {"B", B}, {"N", n}, {"C", C}, {"EPSO", 2.0}, {"RATEOP", form}, {"C2/P", C2}}));
      const double dt = 1e-3 / r;
      for (int k = 0; k < 300; ++k) {
        const double d[6] = {r, 0, 0, 0, 0, 0};
        p.step(d, dt);
      }
      const double x = 2 * r / 3 / 2.0, lx = std::log(x);
      const double R = form == 3 ? 1 + std::pow(2 * r / 3 / C, 1 / C2)
                       : x <= 1  ? 1.0
                       : form == 1 ? 1 + C * lx + C2 * lx * lx
                                   : std::pow(x, C);
      const double ep = plastic_strain_for(p.m.G, 300 * 1e-3, R, A, B, n);
      EXPECT_GT(ep, 0.05);
      EXPECT_NEAR(p.s.eps_p, ep, 1e-12) << form << " rate " << r;
      EXPECT_NEAR(p.q(), R * (A + B * std::pow(ep, n)), 1e-11) << form << " rate " << r;
    }
  }
}

// VP = 1: the rate in R is the plastic strain rate of the step.  (a) No hardening (B = 0), uniaxial
// strain at rate r: in steady flow the stress stops changing, so the plastic strain rate is the
// effective strain rate 2r/3 and q = A R(2r/3), for each rate form (the fixed point is reached
// geometrically; after 400 steps to 1e-12).  (b) With hardening the point's equation holds each
// step, q = R(d eps_p / dt) (A + B eps_p^n) (1e-12), and the flow stress lies below VP = 0's (the
// plastic strain rate is below the total one) by more than 1e-5 at the end (Allen-Rule-Jones,
// C = 0.03, the least: 6e-5).  Type 98 (VP = 1,
// RATEOP 0) as type 15.
TEST(MatJohnsonCook, ViscoplasticRateIsThePlasticStrainRate) {
  const double A = 0.4, B = 0.6, n = 0.3, r = 30.0, dt = 1e-3 / r;
  auto R_of = [](int form, double rate) {
    const double x = rate / 2.0, lx = std::log(x);
    return form == 3 ? 1 + std::pow(rate / 40.0, 1 / 5.0) : x <= 1 ? 1.0 : form == 2 ? std::pow(x, 0.03) : 1 + 0.05 * lx + (form == 1 ? 0.004 * lx * lx : 0.0);
  };
  for (int type : {15, 98}) {
    for (int form : {0, 1, 2, 3}) {
      if (type == 98 && form != 0) continue;
      const double C = form == 3 ? 40.0 : form == 2 ? 0.03 : 0.05, C2 = form == 3 ? 5.0 : form == 1 ? 0.004 : 0.0;
      std::map<std::string, double> v = {{"A", A}, {"B", 0.0}, {"N", n}, {"C", C}, {"EPSO", 2.0}, {"VP", 1}};
      if (type == 15) v["RATEOP"] = form, v["C2/P"] = C2;
      Point p(jc_material(type, v));
      double ep_old = 0;
      for (int k = 0; k < 400; ++k) {
        const double d[6] = {r, 0, 0, 0, 0, 0};
        ep_old = p.s.eps_p;
        p.step(d, dt);
      }
      EXPECT_NEAR((p.s.eps_p - ep_old) / dt, 2 * r / 3, 1e-9 * r) << type << " " << form;
      EXPECT_NEAR(p.q(), A * R_of(form, 2 * r / 3), 1e-12) << type << " " << form;
      // (b) hardening
      v["B"] = B;
      Point h(jc_material(type, v));
      v["VP"] = 0;
      Point h0(jc_material(type, v));
      for (int k = 0; k < 300; ++k) {
        const double d[6] = {r, 0, 0, 0, 0, 0};
        const double e0 = h.s.eps_p;
        h.step(d, dt);
        h0.step(d, dt);
        const double de = h.s.eps_p - e0;
        if (de > 0) {
          EXPECT_NEAR(h.q(), R_of(form, de / dt) * (A + B * std::pow(h.s.eps_p, n)), 1e-12) << type << " " << form << " " << k;
        }
      }
      EXPECT_GT(h.s.eps_p, 0.1);
      EXPECT_LT(h.q(), h0.q() - 1e-5) << type << " " << form;
    }
  }
}

// EROD = 1: the damaged point is not deleted (no failure history for the element pass); at D >= 1
// its deviatoric stress is zero and stays zero, while it still carries a pressure (K tr eps).
TEST(MatJohnsonCook, NoErosionZeroesTheDeviatoricStress) {
  const double D1 = 0.05, D2 = 0.25;
  Point p(jc_material(15, {{"A", 0.4}, {"B", 0.6}, {"N", 0.3}, {"EPSO", 1e6}, {"D1", D1}, {"D2", D2}, {"D3", -3}, {"EROD", 1}}));
  EXPECT_EQ(p.m.fail_history, -1);
  int failed_at = 0;
  for (int k = 1; k <= 4000 && failed_at == 0; ++k) {
    const double d[6] = {0, 0, 0, 2e-4, 0, 0};
    p.step(d, 1.0);
    EXPECT_NEAR(p.s.hist[1], p.s.eps_p / (D1 + D2), 1e-12);
    if (p.s.hist[1] >= 1) {
      failed_at = k;
    } else if (p.s.eps_p > 0) {
      EXPECT_GT(p.s.sig[3], 0.2);  // yielded: the shear flow stress, at least A / sqrt(3)
    }
  }
  ASSERT_GT(failed_at, 0);
  EXPECT_NEAR(p.s.eps_p, D1 + D2, 3e-4);  // fails within a step's plastic strain (2.3e-4) of D1 + D2
  for (int k = 1; k <= 10; ++k) {
    const double d[6] = {-1e-4, -1e-4, -1e-4, 2e-4, 0, 0};
    const double m0 = p.s.sig[0];
    p.step(d, 1.0);
    for (int c = 3; c < 6; ++c) EXPECT_EQ(p.s.sig[c], 0.0);
    EXPECT_NEAR(p.s.sig[0], m0 - 3 * p.m.K * 1e-4, 1e-14);
    EXPECT_EQ(p.s.sig[0], p.s.sig[1]);
    EXPECT_EQ(p.s.sig[0], p.s.sig[2]);
  }
}
