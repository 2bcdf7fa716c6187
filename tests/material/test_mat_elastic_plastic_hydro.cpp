// Type 10 (*MAT_ELASTIC_PLASTIC_HYDRO) through single-point strain paths against closed forms:
// the deviatoric stress in uniaxial strain yields at 2 G eps = sigma_y and then follows the
// flow curve, sigma_y(eps_p) = 2 G eps - 3 G eps_p (the EPS/ES table, up to 16 points with the
// last slope extended, or SIGY + EH eps_p), elastic unloading; the table's checks.  (The
// pressure comes from the equation of state in a run: tests/solve/test_mat_hydro.cpp.)

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "impact3d/material/material_types.h"

using namespace impact3d;

namespace {

constexpr double kG = 80.0;  // non-dimensional

MaterialData hydro_material(const std::vector<std::pair<double, double>>& pts, double sigy = 0, double eh = 0) {
  const MaterialType& t = material_type(10);
  MaterialData md;
  md.type = 10;
  md.number = 1;
  set_param_defaults(md, t);
  md.rho = 7.8;
  param_value(md, *find_param(t, "G")) = kG;
  md.sigma_y = sigy;
  param_value(md, *find_param(t, "EH")) = eh;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    param_value(md, *find_param(t, "EPS" + std::to_string(i + 1))) = pts[i].first;
    param_value(md, *find_param(t, "ES" + std::to_string(i + 1))) = pts[i].second;
  }
  return md;
}

double flow(const std::vector<std::pair<double, double>>& pts, double ep) {
  std::size_t i = 0;
  while (i + 2 < pts.size() && ep > pts[i + 1].first) ++i;
  const double H = (pts[i + 1].second - pts[i].second) / (pts[i + 1].first - pts[i].first);
  return pts[i].second + H * (ep - pts[i].first);
}

// The plastic strain at which a - 3 G ep = flow(ep) (a = 2 G eps, the trial von Mises stress in
// uniaxial strain), by bisection to 1e-15.
double plastic_strain_for(const std::vector<std::pair<double, double>>& pts, double a) {
  if (a <= flow(pts, 0)) return 0;
  double lo = 0, hi = a / (3 * kG);
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (a - 3 * kG * mid > flow(pts, mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double von_mises(const double* s) {
  const double p = (s[0] + s[1] + s[2]) / 3;
  const double a = s[0] - p, b = s[1] - p, c = s[2] - p;
  return std::sqrt(1.5 * (a * a + b * b + c * c + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

// Uniaxial strain eps_zz to eps_max in n steps: worst relative errors of eps_p and of the von
// Mises stress against the closed form along the path.
void check_uniaxial_strain(const MaterialData& md, const std::vector<std::pair<double, double>>& pts, double eps_max,
                           double& worst_ep, double& worst_q, double& ep_end) {
  const MaterialConstants m = derive_constants(md, Model{});
  ASSERT_EQ(m.G, kG);
  const SolidKernel& k = material_type(10).solid;
  SolidPointState s;
  const int n = 400;
  const double dt = 1e-3, rate = -eps_max / (n * dt);  // compression
  const double d[6] = {0, 0, rate, 0, 0, 0};
  worst_ep = worst_q = 0;
  for (int i = 1; i <= n; ++i) {
    k.update_point(m, d, dt, s);
    const double eps = std::fabs(rate) * dt * i;
    const double ep = plastic_strain_for(pts, 2 * kG * eps);
    worst_ep = std::max(worst_ep, std::fabs(s.eps_p - ep) / std::max(ep, 1e-3));
    const double q = ep > 0 ? flow(pts, ep) : 2 * kG * eps;
    worst_q = std::max(worst_q, std::fabs(von_mises(s.sig) - q) / q);
    if (std::fabs(2 * kG * eps - flow(pts, 0)) > 1e-9 * flow(pts, 0)) {  // (not at the yield point itself)
      EXPECT_EQ(s.yielded != 0, ep > 0) << i;
    }
  }
  ep_end = s.eps_p;
  // elastic unloading: a strain decrement of 1e-3 lowers the von Mises stress by 2 G 1e-3
  const double q0 = von_mises(s.sig);
  const double back[6] = {0, 0, 1e-3 / dt, 0, 0, 0};
  k.update_point(m, back, dt, s);
  EXPECT_EQ(s.eps_p, ep_end);
  EXPECT_NEAR(von_mises(s.sig), q0 - 2 * kG * 1e-3, 1e-12 * q0);
}

}  // namespace

TEST(MatElasticPlasticHydro, UniaxialStrainFollowsTheTable) {
  // 16 points (every one of the table's cards), yield 0.4: the yield strain 0.4 / (2 G) = 0.0025
  std::vector<std::pair<double, double>> pts;
  for (int i = 0; i < 16; ++i) pts.push_back({0.004 * i * (1 + 0.1 * i), 0.4 + 0.5 * std::sqrt(0.01 * i)});
  double worst_ep, worst_q, ep_end;
  check_uniaxial_strain(hydro_material(pts), pts, 0.3, worst_ep, worst_q, ep_end);
  std::printf("type 10, 16-point table: eps_p at the end %.6f (last point %.4f), worst |eps_p - closed| %.2e, |q - sigma_y| %.2e\n",
              ep_end, pts.back().first, worst_ep, worst_q);
  EXPECT_GT(ep_end, pts.back().first);  // past the last point: the last slope extended
  EXPECT_LT(worst_ep, 1e-12);
  EXPECT_LT(worst_q, 1e-12);
}

TEST(MatElasticPlasticHydro, UniaxialStrainWithSigyAndEh) {
  // no table: sigma_y = SIGY + EH eps_p
  const std::vector<std::pair<double, double>> line = {{0, 0.3}, {1, 0.3 + 2.5}};
  double worst_ep, worst_q, ep_end;
  check_uniaxial_strain(hydro_material({}, 0.3, 2.5), line, 0.05, worst_ep, worst_q, ep_end);
  // closed form at the end: eps_p = (2 G eps - SIGY) / (3 G + EH)
  EXPECT_NEAR(ep_end, (2 * kG * 0.05 - 0.3) / (3 * kG + 2.5), 1e-14);
  EXPECT_LT(worst_ep, 1e-12);
  EXPECT_LT(worst_q, 1e-12);
  // perfectly plastic (EH = 0): the von Mises stress stays at SIGY
  const std::vector<std::pair<double, double>> flat = {{0, 0.3}, {1, 0.3}};
  check_uniaxial_strain(hydro_material({}, 0.3, 0), flat, 0.05, worst_ep, worst_q, ep_end);
  EXPECT_NEAR(ep_end, (2 * kG * 0.05 - 0.3) / (3 * kG), 1e-14);
  EXPECT_LT(worst_q, 1e-12);
}

TEST(MatElasticPlasticHydro, ChecksTheTableAndTheFields) {
  const MaterialType& t = material_type(10);
  EXPECT_TRUE(t.needs_eos);
  EXPECT_TRUE(t.accepts_eos);
  EXPECT_EQ(find_material_type_by_keyword("MAT_ELASTIC_PLASTIC_HYDRO"), &t);
  EXPECT_EQ(find_material_type_by_keyword("MAT_010"), &t);
  auto problems = [&](MaterialData md) {
    std::vector<std::string> keys;
    check_material_params(md, t, [&](const MaterialParam& p, int msg, const std::string&) {
      keys.push_back(std::string(p.key) + ":" + std::to_string(msg));
    });
    std::string s;
    for (const auto& k : keys) s += k + " ";
    return s;
  };
  EXPECT_EQ(problems(hydro_material({{0, 1}, {0.1, 2}})), "");
  EXPECT_EQ(problems(hydro_material({{0, 1}, {0.1, 0.5}})), "ES2:1003 ");            // softening
  EXPECT_EQ(problems(hydro_material({{0, 1}, {0.2, 2}, {0.1, 3}})), "EPS3:1003 ");   // not increasing
  MaterialData md = hydro_material({}, 1, 0);
  param_value(md, *find_param(t, "PC")) = 5;
  param_value(md, *find_param(t, "CHARL")) = 0.1;
  md.fail_strain = -1;
  EXPECT_EQ(problems(md), "CHARL:1102 PC:1003 FS:1102 ");
  param_value(md, *find_param(t, "G")) = 0;
  EXPECT_NE(problems(md).find("G:1003"), std::string::npos);
}
