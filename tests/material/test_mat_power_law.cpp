// Type 18 (*MAT_POWER_LAW_PLASTICITY) through single-point strain paths against closed forms:
// sigma_y = R k (eps_yp + eps_p)^n in uniaxial strain, with and without Cowper-Symonds rate
// scaling and SIGY.

#include <gtest/gtest.h>

#include <cmath>

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
