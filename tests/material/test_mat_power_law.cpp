// Type 18 (*MAT_POWER_LAW_PLASTICITY) through single-point strain paths against closed forms:
// sigma_y = R k (eps_yp + eps_p)^n in uniaxial strain, with and without Cowper-Symonds rate
// scaling and SIGY.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "impact3d/material/material_types.h"

using namespace impact3d;

namespace {

MaterialData power_law(double k, double n, double sigy = 0, double C = 0, double P = 0) {
  const MaterialType& t = material_type(18);
  MaterialData md;
  md.type = 18;
  set_param_defaults(md, t);
  md.rho = 7.8, md.E = 200, md.nu = 0.3, md.rate_c = C, md.rate_p = P;
  param_value(md, *find_param(t, "K")) = k;
  param_value(md, *find_param(t, "N")) = n;
  param_value(md, *find_param(t, "SIGY")) = sigy;
  return md;
}

}  // namespace

// Uniaxial strain eps (rate r, dt): q = 2 G eps - 3 G ep = R k (eps_yp + ep)^n, eps_yp = (E/k)^(1/(n-1))
// or (SIGY/k)^(1/n), R = 1 + (r / C)^(1/P) (rate = sqrt(D:D) = r).  Radial return exact on this
// proportional path, Newton to 1e-15: 1e-12 in plastic strain, 1e-11 in stress.
TEST(MatPowerLaw, UniaxialStrainFollowsThePowerLaw) {
  struct Case { double sigy, C, P, r; };
  for (const Case c : {Case{0, 0, 0, 1}, Case{0.5, 0, 0, 1}, Case{0, 40, 5, 100}}) {
    const double k = 1.2, n = 0.25;
    const MaterialData md = power_law(k, n, c.sigy, c.C, c.P);
    const MaterialConstants m = derive_constants(md, Model{});
    const double eyp = c.sigy > 0 ? std::pow(c.sigy / k, 1 / n) : std::pow(md.E / k, 1 / (n - 1));
    EXPECT_NEAR(m.sigma_y, c.sigy > 0 ? c.sigy : md.E * eyp, 1e-12);  // where the law meets the elastic line
    const double R = c.C > 0 ? 1 + std::pow(c.r / c.C, 1 / c.P) : 1.0;
    SolidPointState s;
    const double dt = 1e-3 / c.r;
    for (int i = 0; i < 400; ++i) {
      const double d[6] = {c.r, 0, 0, 0, 0, 0};
      material_type(18).solid.update_point(m, d, dt, s);
    }
    const double eps = 0.4, G = m.G;
    double lo = 0, hi = eps;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (2 * G * eps - 3 * G * mid > R * k * std::pow(eyp + mid, n) ? lo : hi) = mid;
    }
    const double ep = 0.5 * (lo + hi);
    EXPECT_GT(ep, 0.2);
    EXPECT_NEAR(s.eps_p, ep, 1e-12) << c.sigy << " " << c.C;
    EXPECT_NEAR(s.sig[0] - s.sig[1], R * k * std::pow(eyp + ep, n), 1e-11) << c.sigy << " " << c.C;
  }
}

TEST(MatPowerLaw, Checks) {
  const MaterialType& t = material_type(18);
  int errors = 0;
  MaterialData md = power_law(1.2, 1.5);  // n >= 1 needs SIGY
  check_material_params(md, t, [&](const MaterialParam& p, int, const std::string&) { errors += std::string(p.key) == "N"; });
  EXPECT_EQ(errors, 1);
}

// VP = 1 (viscoplastic): the Cowper-Symonds factor of the plastic strain rate of the step.
// Uniaxial strain at rate r in steps dt: each step's increment dp solves, by hand (bisection),
// q_trial - 3 G dp = (1 + (dp / (dt C))^(1/P)) k (eps_yp + p + dp)^n with q_trial the elastic
// predictor from the previous step's stress: the kernel follows it to 1e-12 in p and 1e-10 in
// stress; once the flow is steady the plastic rate nears the deviatoric one, 2 r / 3, and the
// stress (1 + (2 r / (3 C))^(1/P)) k (eps_yp + p)^n within 1 %, well above the rate-free one.
TEST(MatPowerLaw, ViscoplasticRateIsThePlasticStrainRate) {
  const double k = 1.2, n = 0.25, C = 40, P = 5, r = 100;
  MaterialData md = power_law(k, n, 0, C, P);
  param_value(md, *find_param(material_type(18), "VP")) = 1;
  const MaterialConstants m = derive_constants(md, Model{});
  const double eyp = std::pow(md.E / k, 1 / (n - 1)), G = m.G;
  SolidPointState s;
  const double dt = 1e-3 / r;
  double p = 0, q = 0;  // by hand: plastic strain, von Mises stress (sigma_xx - sigma_yy)
  for (int i = 0; i < 400; ++i) {
    const double d[6] = {r, 0, 0, 0, 0, 0};
    material_type(18).solid.update_point(m, d, dt, s);
    const double trial = q + 2 * G * r * dt;
    auto flow = [&](double dp) { return (1 + std::pow(dp / (dt * C), 1 / P)) * k * std::pow(eyp + p + dp, n); };
    double dp = 0;
    if (trial > k * std::pow(eyp + p, n)) {
      double lo = 0, hi = trial / (3 * G);
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (trial - 3 * G * mid > flow(mid) ? lo : hi) = mid;
      }
      dp = 0.5 * (lo + hi);
    }
    p += dp;
    q = trial - 3 * G * dp;
    ASSERT_NEAR(s.eps_p, p, 1e-12) << i;
    ASSERT_NEAR(s.sig[0] - s.sig[1], q, 1e-10) << i;
  }
  EXPECT_GT(p, 0.2);
  const double steady = (1 + std::pow(2 * r / (3 * C), 1 / P)) * k * std::pow(eyp + p, n);
  EXPECT_NEAR(q, steady, 0.01 * steady);
  EXPECT_GT(q, 1.1 * k * std::pow(eyp + p, n));
}

TEST(MatPowerLaw, VpIsZeroOrOne) {
  const MaterialType& t = material_type(18);
  std::string said;
  MaterialData md = power_law(1.2, 0.25, 0, 40, 5);
  param_value(md, *find_param(t, "VP")) = 2;
  check_material_params(md, t, [&](const MaterialParam& p, int msg, const std::string&) { said += std::string(p.key) + ":" + std::to_string(msg) + " "; });
  EXPECT_EQ(said, "VP:1003 ");
}
