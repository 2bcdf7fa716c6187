// Type 24 (*MAT_PIECEWISE_LINEAR_PLASTICITY) through single-point strain paths against closed
// forms: the flow stress against plastic strain in uniaxial strain and in shear, with and
// without Cowper-Symonds rate scaling, with an LCSR curve, the viscoplastic form (VP = 1),
// elastic unloading; the table of material types.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "impact3d/material/material_types.h"

using namespace impact3d;

namespace {

// Non-dimensional metal-like constants: E = 200, nu = 0.3 (G = 76.9, K = 166.7), a flow curve
// of 4 points (yield 0.4), extended beyond 0.2 with its last slope.
const std::vector<std::pair<double, double>> kTable = {{0.0, 0.4}, {0.01, 0.6}, {0.05, 0.8}, {0.2, 0.9}};

MaterialData table_material(const std::vector<std::pair<double, double>>& pts, double C = 0, double P = 0) {
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
  for (std::size_t i = 0; i < pts.size(); ++i) {
    param_value(md, *find_param(t, "EPS" + std::to_string(i + 1))) = pts[i].first;
    param_value(md, *find_param(t, "ES" + std::to_string(i + 1))) = pts[i].second;
  }
  return md;
}

// The flow stress of the table (last slope extended).
double flow(const std::vector<std::pair<double, double>>& pts, double ep) {
  std::size_t i = 0;
  while (i + 2 < pts.size() && ep > pts[i + 1].first) ++i;
  const double H = (pts[i + 1].second - pts[i].second) / (pts[i + 1].first - pts[i].first);
  return pts[i].second + H * (ep - pts[i].first);
}

// Closed form: the plastic strain at which a * - 3 G ep = R flow(ep) (a = the trial von Mises
// stress 2 G eps in uniaxial strain, sqrt(3) G gamma in shear), by bisection to 1e-15.
double plastic_strain_for(const std::vector<std::pair<double, double>>& pts, double G, double a, double R) {
  if (a <= R * flow(pts, 0)) return 0;
  double lo = 0, hi = a / (3 * G);
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (a - 3 * G * mid > R * flow(pts, mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Path {
  MaterialConstants m;
  SolidPointState s;
  const SolidKernel* k;
  explicit Path(const MaterialData& md, const Model& model = Model{})
      : m(derive_constants(md, model)), k(&material_type(24).solid) {}
  void step(const double d[6], double dt) { k->update_point(m, d, dt, s); }
};

}  // namespace

TEST(MaterialTable, EveryTypeIsCompleteAndFoundByNumberAndKeyword) {
  int previous = 0;
  for (const MaterialType* t : material_types()) {
    EXPECT_GT(t->number, previous) << "the table is in increasing number";
    previous = t->number;
    EXPECT_EQ(find_material_type(t->number), t);
    for (const char* k : t->keywords) EXPECT_EQ(find_material_type_by_keyword(k), t) << k;
    EXPECT_LE(int(t->history.size()), kMaxHistory);
    if (!t->rigid) {
      EXPECT_TRUE(t->solid.update_point && t->solid.update_block) << t->number;
    }
    for (const MaterialParam& p : t->params) {
      if (!p.field) {
        EXPECT_LT(p.index, t->num_par) << t->number << " " << p.key;
      }
      EXPECT_TRUE(p.kcard < 0 || p.kcard < t->keyword_cards) << t->number << " " << p.key;
      EXPECT_TRUE(p.fcard == 0 || (p.fcard >= 3 && p.fcard <= 8 && (p.fcol - 1) % 10 == 0 && p.fcol <= 71))
          << t->number << " " << p.key;
    }
  }
  EXPECT_EQ(find_material_type(2), nullptr);  // unknown: refused when the deck is read
  EXPECT_EQ(find_material_type_by_keyword("MAT_ORTHOTROPIC_ELASTIC"), nullptr);
  EXPECT_EQ(find_material_type_by_keyword("MAT_PIECEWISE_LINEAR_PLASTICITY")->number, 24);
}

// Uniaxial strain, monotonic: sigma_xx = K eps + 2/3 q, q = 2 G eps - 3 G ep = flow(ep).  The
// radial return is exact for this proportional path, so the increments change only rounding:
// tolerance 1e-12 of the stress scale.
TEST(MatPiecewiseLinear, UniaxialStrainFollowsTheFlowCurve) {
  Path p(table_material(kTable));
  const double G = p.m.G, K = p.m.K;
  const double de = 2.5e-4;
  int checked = 0;
  for (int n = 1; n <= 2000; ++n) {
    const double d[6] = {de, 0, 0, 0, 0, 0};
    p.step(d, 1.0);
    const double eps = n * de;
    const double ep = plastic_strain_for(kTable, G, 2 * G * eps, 1.0);
    const double q = 2 * G * eps - 3 * G * ep;
    if (n % 100 == 0) {
      EXPECT_NEAR(p.s.eps_p, ep, 1e-12) << "eps " << eps;
      EXPECT_NEAR(p.s.sig[0], K * eps + 2.0 / 3.0 * q, 1e-12 * 100) << "eps " << eps;
      EXPECT_NEAR(p.s.sig[1], K * eps - q / 3.0, 1e-12 * 100) << "eps " << eps;
      if (ep > 0) {
        EXPECT_NEAR(p.s.sig[0] - p.s.sig[1], flow(kTable, ep), 1e-11);
      }
      ++checked;
    }
  }
  EXPECT_GT(p.s.eps_p, 0.2);  // beyond the last point: the extended slope was used
  EXPECT_EQ(checked, 20);
  // Unloading by 0.004 is elastic (q drops by 2 G 0.004 = 0.62 < 2 sigma_y): the stress moves
  // by the constrained modulus K + 4G/3, the plastic strain stays.
  const double ep0 = p.s.eps_p, sx0 = p.s.sig[0];
  for (int n = 0; n < 16; ++n) {
    const double d[6] = {-2.5e-4, 0, 0, 0, 0, 0};
    p.step(d, 1.0);
  }
  EXPECT_EQ(p.s.eps_p, ep0);
  EXPECT_NEAR(p.s.sig[0] - sx0, -(K + 4 * G / 3) * 0.004, 1e-12 * 100);
}

// Simple shear: tau = G gamma - sqrt(3) G ep and sqrt(3) tau = flow(ep).
TEST(MatPiecewiseLinear, ShearFollowsTheFlowCurve) {
  Path p(table_material(kTable));
  const double G = p.m.G;
  const double dg = 2e-4;  // engineering shear strain per step (d_xy = dg / 2)
  for (int n = 1; n <= 1500; ++n) {
    const double d[6] = {0, 0, 0, dg / 2, 0, 0};
    p.step(d, 1.0);
  }
  const double gamma = 1500 * dg;
  const double ep = plastic_strain_for(kTable, G, std::sqrt(3.0) * G * gamma, 1.0);
  EXPECT_NEAR(p.s.eps_p, ep, 1e-12);
  EXPECT_NEAR(std::sqrt(3.0) * p.s.sig[3], flow(kTable, ep), 1e-11);
  EXPECT_NEAR(p.s.sig[0], 0.0, 1e-14);
}

// Cowper-Symonds (VP = 0): the flow stress is scaled by R = 1 + (rate / C)^(1/P) with rate =
// sqrt(D:D) = |d_xx|; uniaxial strain at rate 0.25 with C 10, P 2 gives R = 1.158.
TEST(MatPiecewiseLinear, RateScalesTheFlowStress) {
  const double C = 10, P = 2;
  Path p(table_material(kTable, C, P));
  const double G = p.m.G, K = p.m.K;
  const double dt = 1e-3, rate = 0.25;
  const double R = 1 + std::pow(rate / C, 1 / P);
  for (int n = 1; n <= 800; ++n) {
    const double d[6] = {rate, 0, 0, 0, 0, 0};
    p.step(d, dt);
  }
  const double eps = 800 * rate * dt;
  const double ep = plastic_strain_for(kTable, G, 2 * G * eps, R);
  EXPECT_GT(ep, 0.05);
  EXPECT_NEAR(p.s.eps_p, ep, 1e-12);
  EXPECT_NEAR(p.s.sig[0] - p.s.sig[1], R * flow(kTable, ep), 1e-11);
  EXPECT_NEAR(p.s.sig[0], K * eps + 2.0 / 3.0 * R * flow(kTable, ep), 1e-10);
}

namespace {

// A model holding one load curve: the LCSR curve rate -> factor (1 at rates up to 0.1, 1.2 at
// 0.1, 1.5 at 1 and beyond: the end values held).
Model rate_curve_model() {
  Model model;
  LoadCurve lc;
  lc.number = 1;
  lc.t = {0.0, 0.1, 1.0};
  lc.f = {1.0, 1.2, 1.5};
  model.load_curves = {lc};
  return model;
}
double rate_curve(double r) { return r <= 0.1 ? 1.0 + 2.0 * r : r >= 1.0 ? 1.5 : 1.2 + (r - 0.1) / 3.0; }

MaterialData rate_material(double C, double P, double lcsr, double vp) {
  MaterialData md = table_material(kTable, C, P);
  param_value(md, *find_param(material_type(24), "LCSR")) = lcsr;
  param_value(md, *find_param(material_type(24), "VP")) = vp;
  return md;
}

}  // namespace

// LCSR (VP = 0): the flow stress is scaled by R = LCSR(rate), rate = sqrt(D:D) = |d_xx| in
// uniaxial strain; C and P beside it are not used.  Rate 0.25 and 2 (beyond the last point).
TEST(MatPiecewiseLinear, RateCurveScalesTheFlowStress) {
  const Model model = rate_curve_model();
  for (double rate : {0.25, 2.0}) {
    Path p(rate_material(10, 2, 1, 0), model);
    const double G = p.m.G;
    const double dt = 0.2 / rate / 800;  // to eps 0.2
    const double R = rate_curve(rate);
    for (int n = 1; n <= 800; ++n) {
      const double d[6] = {rate, 0, 0, 0, 0, 0};
      p.step(d, dt);
    }
    const double eps = 800 * rate * dt;
    const double ep = plastic_strain_for(kTable, G, 2 * G * eps, R);
    EXPECT_GT(ep, 0.05);
    EXPECT_NEAR(p.s.eps_p, ep, 1e-12) << rate;
    EXPECT_NEAR(p.s.sig[0] - p.s.sig[1], R * flow(kTable, ep), 1e-11) << rate;
  }
  EXPECT_NEAR(rate_curve(0.25), 1.25, 1e-15);
}

// VP = 1 (viscoplastic): the factor is that of the plastic strain rate.  Perfect plasticity
// (flow stress 0.4) in uniaxial strain at the constant rate r: at the steady state the stress no
// longer changes, the deviatoric strain rate is all plastic and the effective plastic strain
// rate is sqrt(2/3 d':d') = 2 r / 3, so q = 0.4 R(2 r / 3) (Cowper-Symonds and LCSR), against
// R(r) with VP = 0 (the total strain rate sqrt(D:D) = r).  With hardening, every step meets
// q = R(d eps_p / dt) flow(eps_p).  Tolerances: 1e-12 of the stress (the return is solved to
// 1e-15 relative).
TEST(MatPiecewiseLinear, ViscoplasticRateIsThePlasticStrainRate) {
  const Model model = rate_curve_model();
  const std::vector<std::pair<double, double>> perfect = {{0.0, 0.4}, {1.0, 0.4}};
  const double C = 10, P = 2;
  for (double lcsr : {0.0, 1.0}) {
    for (double rate : {0.25, 0.9}) {
      auto R = [&](double r) { return lcsr > 0 ? rate_curve(r) : 1 + std::pow(r / C, 1 / P); };
      for (double vp : {0.0, 1.0}) {
        MaterialData md = table_material(perfect, C, P);
        param_value(md, *find_param(material_type(24), "LCSR")) = lcsr;
        param_value(md, *find_param(material_type(24), "VP")) = vp;
        Path p(md, model);
        const double dt = 1e-4;
        for (int n = 1; n <= 4000; ++n) {  // eps to 0.1 (0.36) at rate 0.25 (0.9)
          const double d[6] = {rate, 0, 0, 0, 0, 0};
          p.step(d, dt);
        }
        const double q = p.s.sig[0] - p.s.sig[1];
        const double want = 0.4 * R(vp == 1 ? 2 * rate / 3 : rate);
        EXPECT_NEAR(q, want, 1e-12) << "LCSR " << lcsr << " rate " << rate << " VP " << vp;
        std::printf("LCSR %g rate %g VP %g: q %.15f, closed form 0.4 R(%s) = %.15f\n", lcsr, rate, vp, q,
                    vp == 1 ? "2r/3" : "r", want);
      }
    }
  }
  // hardening table, VP = 1, Cowper-Symonds: each step's stress is R(d eps_p / dt) flow(eps_p)
  Path h(rate_material(C, P, 0, 1));
  const double dt = 1e-3, rate = 0.25;
  int plastic_steps = 0;
  for (int n = 1; n <= 800; ++n) {
    const double e0 = h.s.eps_p;
    const double d[6] = {rate, 0, 0, 0, 0, 0};
    h.step(d, dt);
    const double dep = h.s.eps_p - e0;
    if (dep > 0) {
      ++plastic_steps;
      const double want = (1 + std::pow(dep / dt / C, 1 / P)) * flow(kTable, h.s.eps_p);
      ASSERT_NEAR(h.s.sig[0] - h.s.sig[1], want, 1e-12 * want) << n;
    }
  }
  EXPECT_GT(h.s.eps_p, 0.05);
  EXPECT_GT(plastic_steps, 700);
}

// Neither table nor curve: SIGY and the linear modulus E_p = E ETAN / (E - ETAN), as type 3:
// the same path gives type 3's stress to rounding.
TEST(MatPiecewiseLinear, BilinearWithoutTableIsTypeThree) {
  const MaterialType& t = material_type(24);
  MaterialData md;
  md.type = 24;
  set_param_defaults(md, t);
  md.rho = 7.8, md.E = 200, md.nu = 0.3, md.sigma_y = 0.4, md.E_tan = 20;
  Path p(md);
  MaterialData m3 = md;
  m3.type = 3;
  m3.beta = 1;
  m3.par.assign(2, 0.0);
  const MaterialConstants c3 = derive_constants(m3, Model{});
  SolidPointState s3;
  for (int n = 1; n <= 400; ++n) {
    const double d[6] = {2.5e-4, -1e-4, 0.5e-4, 1e-4, 0, -0.5e-4};
    p.step(d, 1.0);
    material_type(3).solid.update_point(c3, d, 1.0, s3);
  }
  EXPECT_GT(s3.eps_p, 0.01);
  EXPECT_NEAR(p.s.eps_p, s3.eps_p, 1e-13);
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(p.s.sig[c], s3.sig[c], 1e-12) << c;
}

// The table's checks: strains increase, stresses do not decrease; FAIL >= 1e19 means never.
TEST(MatPiecewiseLinear, TableChecks) {
  const MaterialType& t = material_type(24);
  std::vector<std::string> bad;
  auto report = [&](const MaterialParam& p, int msg, const std::string&) { bad.push_back(std::string(p.key) + ":" + std::to_string(msg)); };
  MaterialData ok = table_material(kTable);
  ok.fail_strain = 1e21;
  check_material_params(ok, t, report);
  EXPECT_TRUE(bad.empty());
  EXPECT_EQ(ok.fail_strain, 0.0);
  MaterialData md = table_material({{0.0, 0.4}, {0.02, 0.6}, {0.01, 0.7}, {0.05, 0.5}});
  check_material_params(md, t, report);
  ASSERT_EQ(bad.size(), 2u);
  EXPECT_EQ(bad[0], "EPS3:1003");
  EXPECT_EQ(bad[1], "ES4:1003");
}

// An EPS table that is all zero is no table, as LS-DYNA reads it: ES1-ES8 (here a flat 0.7 and a
// rising tail that, read as a table, would be refused for its strains) are not used, warning 2006
// names the first nonzero ES, and the flow stress is SIGY and ETAN's: the path of the bilinear
// material without a table, to the bit.
TEST(MatPiecewiseLinear, AllZeroEpsTableIsNoTable) {
  const MaterialType& t = material_type(24);
  MaterialData md = table_material({{0.0, 0.0}, {0.0, 0.7}, {0.0, 0.8}});
  md.sigma_y = 0.4, md.E_tan = 20;
  std::vector<std::string> said;
  check_material_params(md, t, [&](const MaterialParam& p, int msg, const std::string&) {
    said.push_back(std::string(p.key) + ":" + std::to_string(msg));
  });
  ASSERT_EQ(said.size(), 1u);
  EXPECT_EQ(said[0], "ES2:2006");
  const MaterialConstants m = derive_constants(md, Model{});
  const double Ep = 200 * 20 / (200 - 20.0);
  ASSERT_EQ(m.curve_eps.size(), 2u);
  EXPECT_EQ(m.curve_sig[0], 0.4);
  EXPECT_EQ(m.curve_sig[1], 0.4 + Ep);
  MaterialData plain = md;
  for (int i = 1; i <= 8; ++i) param_value(plain, *find_param(t, "ES" + std::to_string(i))) = 0;
  Path a(md), b(plain);
  for (int n = 1; n <= 300; ++n) {
    const double d[6] = {2.5e-4, -1e-4, 0.5e-4, 1e-4, 0, -0.5e-4};
    a.step(d, 1.0);
    b.step(d, 1.0);
  }
  EXPECT_GT(a.s.eps_p, 0.01);
  EXPECT_EQ(a.s.eps_p, b.s.eps_p);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(a.s.sig[c], b.s.sig[c]) << c;
}
