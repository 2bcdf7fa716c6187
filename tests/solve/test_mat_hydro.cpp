// Type 10 (*MAT_ELASTIC_PLASTIC_HYDRO) with an equation of state through the whole cycle: one
// solid squeezed in uniaxial strain (bottom fixed, sides on rollers, the top moving at -V) and
// let back: at every cycle its pressure is the EOS of its own volume (linear polynomial p = C1
// mu, as for type 9), and its deviatoric stress yields at 2 G |eps| = SIGY and then follows the
// closed form of uniaxial strain, eps_p = (2 G |eps| - SIGY) / (3 G + EH) and sigma_z -
// sigma_x = -(SIGY + EH eps_p), eps = ln(V / V0) the solid's true strain; the pressure cutoff
// PC bounds the pressure in tension.  Units SI (an aluminium-like solid).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

using namespace impact3d;
using namespace solve_test;

namespace {

constexpr double kG = 26e9, kK = 70e9, kSigy = 3e8, kEh = 1.2e9, kRho = 2700;

MaterialData hydro_material(double pc) {
  const MaterialType& t = material_type(10);
  MaterialData md;
  md.number = 1;
  md.type = 10;
  set_param_defaults(md, t);
  md.rho = kRho;
  param_value(md, *find_param(t, "G")) = kG;
  md.sigma_y = kSigy;
  param_value(md, *find_param(t, "EH")) = kEh;
  param_value(md, *find_param(t, "PC")) = pc;
  md.eos.form = 1;
  md.eos.c[1] = kK;  // p = K mu
  md.title = "elastic-plastic hydro";
  return md;
}

// One 1 mm cube, bottom fixed, sides on rollers, the top face at -V until T, then at +V.
Model squeezed_cube(const MaterialData& md, double V, double T, double end) {
  Box b;
  b.lx = b.ly = b.lz = 1e-3;
  Model m = make_box_model(b, md, end, 4);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.z[std::size_t(n)] == 0) m.bc[std::size_t(n)] = 7;
  LoadCurve lc;
  lc.number = 1;
  lc.t = {0, T, T * 1.0000001, 10 * T};
  lc.f = {-V, -V, V, V};
  m.load_curves = {lc};
  m.control.numlc = 1;
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (m.z[std::size_t(n)] == 0) continue;
    PrescribedMotion pm;
    pm.node = n;
    pm.dir = {0, 0, 1};
    pm.curve = 0;
    m.prescribed_motions.push_back(pm);
  }
  m.control.tssf = 0.5;
  return m;
}

double pressure(const double* g) { return -(g[0] + g[1] + g[2]) / 3; }

}  // namespace

TEST(MatElasticPlasticHydro, UniaxialStrainYieldsAtTheClosedFormWithTheEosPressure) {
  ScopedThreads one(1);
  // compression at 10 m/s for 30 us: true strain -0.35 (mu 0.42), far past the yield strain
  // SIGY / (2 G) = 5.8e-3
  const double V = 10, T = 30e-6;
  Model m = squeezed_cube(hydro_material(0), V, T, T);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  EXPECT_EQ(s.mats[0].G, kG);
  EXPECT_NEAR(s.mats[0].K, kK, 1e-6 * kK);
  double worst_p = 0, worst_ep = 0, worst_q = 0, first_yield_eps = 0, eps_before_yield = 0, eps_prev = 0;
  int cycles = 0, plastic = 0;
  StepStatus st;
  while ((st = eng.step()) == StepStatus::ok) {
    const double* g = &s.sig[0];
    const double mu = s.vol0[0] / s.vol[0] - 1, eps = std::log(s.vol[0] / s.vol0[0]);
    worst_p = std::max(worst_p, std::fabs(pressure(g) - kK * mu) / (kK * std::fabs(mu)));
    const double ep = std::max(0.0, (2 * kG * std::fabs(eps) - kSigy) / (3 * kG + kEh));
    const double diff = g[2] - g[0];  // sigma_z - sigma_x (compression: negative)
    const double want = ep > 0 ? -(kSigy + kEh * ep) : 2 * kG * eps;
    worst_q = std::max(worst_q, std::fabs(diff - want) / kSigy);
    if (ep > 0) worst_ep = std::max(worst_ep, std::fabs(s.eps_p[0] - ep) / ep), ++plastic;
    if (s.yielded[0] && first_yield_eps == 0) first_yield_eps = eps, eps_before_yield = eps_prev;
    eps_prev = eps;
    ++cycles;
  }
  ASSERT_EQ(st, StepStatus::finished);
  const double eps_end = std::log(s.vol[0] / s.vol0[0]);
  std::printf("type 10 + linear polynomial, uniaxial strain to eps %.4f (%d cycles, %d plastic): first yield at eps %.6e "
              "(SIGY / 2G = %.6e); worst |p - K mu| / p %.2e, |eps_p - closed| / eps_p %.2e, "
              "|(s_z - s_x) - closed| / SIGY %.2e\n",
              eps_end, cycles, plastic, first_yield_eps, -kSigy / (2 * kG), worst_p, worst_ep, worst_q);
  EXPECT_LT(eps_end, -0.3);
  EXPECT_GT(plastic, cycles / 2);
  EXPECT_LT(worst_p, 1e-12);
  EXPECT_LT(worst_ep, 5e-6);  // measured 9e-7: the cycle's strain increments against ln(V / V0)
  EXPECT_LT(worst_q, 1e-6);
  // the first yielding cycle is the one that crosses the yield strain
  EXPECT_LE(first_yield_eps, -kSigy / (2 * kG));
  EXPECT_GT(eps_before_yield, -kSigy / (2 * kG));
}

TEST(MatElasticPlasticHydro, PressureCutoffBoundsTheTension) {
  ScopedThreads one(1);
  // stretched at 5 m/s: K mu reaches -0.35 GPa by 1 us; PC = -1e8 holds p there
  const double pc = -1e8;
  Model m = squeezed_cube(hydro_material(pc), -5, 10e-6, 2e-6);
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  double pmin = 0, mu_min = 0;
  StepStatus st;
  while ((st = eng.step()) == StepStatus::ok) {
    const double mu = s.vol0[0] / s.vol[0] - 1, p = pressure(&s.sig[0]);
    if (kK * mu > pc) {
      EXPECT_NEAR(p, kK * mu, 1e-12 * kSigy);
    }
    EXPECT_GE(p, pc * (1 + 1e-15));
    pmin = std::min(pmin, p), mu_min = std::min(mu_min, mu);
  }
  ASSERT_EQ(st, StepStatus::finished);
  std::printf("type 10 PC = %.1e: mu down to %.4f (K mu = %.3e), p down to %.6e\n", pc, mu_min, kK * mu_min, pmin);
  EXPECT_LT(kK * mu_min, 2 * pc);
  EXPECT_NEAR(pmin, pc, 1e-15 * -pc);
}
