// Constitutive updates: elastic, elastic-plastic radial return (isotropic, kinematic, mixed
// hardening), Jaumann rotation, von Mises; each against a closed form.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "impact3d/material/material.h"

using namespace impact3d;

namespace {

// Non-dimensional metal-like constants: E = 200, nu = 0.3, sigma_y = 0.4 (eps_y = 0.002),
// E_tan = 20 (E_p = E E_tan / (E - E_tan) = 200 * 20 / 180 = 22.2).
MaterialConstants metal(double beta) {
  MaterialConstants m;
  m.type = 3;
  m.rho = 7.8;
  m.E = 200.0;
  m.nu = 0.3;
  m.sigma_y = 0.4;
  m.E_tan = 20.0;
  m.beta = beta;
  derive_material_constants(m);
  return m;
}

struct State {
  double sig[6] = {0, 0, 0, 0, 0, 0};
  double back[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0;
  unsigned char yielded = 0;
};

double step(const MaterialConstants& m, State& s, const double d[6], double dt) {
  return update_stress_elastic_plastic(m, d, dt, s.sig, s.back, s.eps_p, s.yielded);
}

// One uniaxial-stress increment: axial strain increment de (dt = 1), lateral d_yy = d_zz = e
// chosen so that sigma_yy = sigma_zz = 0 after the update.  sigma_yy(e) is increasing and
// piecewise linear in e; it is bracketed by e = -de/2 (isochoric) and e = -nu de (elastic), and
// found by regula falsi (Illinois) to |sigma_yy| <= 1e-15 sigma_y.
double uniaxial_stress_step(const MaterialConstants& m, State& s, double de) {
  auto trial = [&](double e, State& out) {
    out = s;
    const double d[6] = {de, e, e, 0, 0, 0};
    step(m, out, d, 1.0);
    return out.sig[1];
  };
  State t;
  double a = -0.5 * de, b = -m.nu * de;
  if (a > b) std::swap(a, b);
  a -= 1e-3 * std::fabs(de);
  b += 1e-3 * std::fabs(de);
  double fa = trial(a, t), fb = trial(b, t);
  int side = 0;
  double e = b;
  for (int it = 0; it < 200; ++it) {
    e = (a * fb - b * fa) / (fb - fa);
    const double fe = trial(e, t);
    if (std::fabs(fe) <= 1e-15 * m.sigma_y) break;
    if ((fe > 0) == (fb > 0)) {
      b = e;
      fb = fe;
      if (side == 1) fa *= 0.5;
      side = 1;
    } else {
      a = e;
      fa = fe;
      if (side == -1) fb *= 0.5;
      side = -1;
    }
  }
  trial(e, t);
  const double deps = t.eps_p - s.eps_p;
  s = t;
  return deps;
}

double vm_of_xi(const State& s) {
  double xi[6];
  for (int k = 0; k < 6; ++k) xi[k] = s.sig[k] - s.back[k];
  return calc_von_mises(xi);  // alpha is deviatoric, so vm(sigma - alpha) = vm(s - alpha)
}

}  // namespace

TEST(MaterialConstants, DerivedFromENu) {
  const MaterialConstants m = metal(1.0);
  // Closed forms; relative tolerance 1e-15.
  EXPECT_NEAR(m.G, 200.0 / 2.6, 1e-15 * m.G);
  EXPECT_NEAR(m.K, 200.0 / 1.2, 1e-15 * m.K);
  EXPECT_NEAR(m.lambda, 200.0 * 0.3 / (1.3 * 0.4), 1e-14 * m.lambda);
  EXPECT_NEAR(m.E_p, 200.0 * 20.0 / 180.0, 1e-15 * m.E_p);
  EXPECT_NEAR(m.c, std::sqrt((m.K + 4.0 * m.G / 3.0) / 7.8), 1e-15 * m.c);
  // (K + 4G/3) = lambda + 2G = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
  EXPECT_NEAR(m.c * m.c * 7.8, 200.0 * 0.7 / (1.3 * 0.4), 1e-13);
}

TEST(MaterialConstants, DerivedFromGK) {
  // The oblique-rod aluminium gives G = 26.5, K = 57.5 (GPa) and no E, nu.
  MaterialConstants m;
  m.type = 3;
  m.rho = 2.7;
  m.G = 26.5;
  m.K = 57.5;
  m.sigma_y = 0.29;
  m.E_tan = 0.055;
  derive_material_constants(m);
  // E = 9KG / (3K + G), nu = (3K - 2G) / (2 (3K + G)); G and K recovered.  Relative 1e-14.
  EXPECT_NEAR(m.E, 9 * 57.5 * 26.5 / (3 * 57.5 + 26.5), 1e-14 * m.E);
  EXPECT_NEAR(m.nu, (3 * 57.5 - 2 * 26.5) / (2 * (3 * 57.5 + 26.5)), 1e-14);
  EXPECT_NEAR(m.G, 26.5, 1e-13);
  EXPECT_NEAR(m.K, 57.5, 1e-13);
}

TEST(MaterialElastic, UniaxialStrainAndShear) {
  MaterialConstants m = metal(1.0);
  m.type = 1;
  double sig[6] = {0, 0, 0, 0, 0, 0};
  const double rate = 1e-3, dt = 0.37;
  const double d[6] = {rate, 0, 0, 0, 0, 0};
  for (int i = 0; i < 10; ++i) update_stress_elastic(m, d, dt, sig);
  const double eps = 10 * rate * dt;
  // sigma_xx = (lambda + 2G) eps, sigma_yy = sigma_zz = lambda eps.  Relative tolerance 1e-14.
  EXPECT_NEAR(sig[0], (m.lambda + 2 * m.G) * eps, 1e-14 * sig[0]);
  EXPECT_NEAR(sig[1], m.lambda * eps, 1e-14 * sig[0]);
  EXPECT_NEAR(sig[2], m.lambda * eps, 1e-14 * sig[0]);
  // Pure shear: sigma_xy = 2 G eps_xy (tensor shear).
  double tau[6] = {0, 0, 0, 0, 0, 0};
  const double ds[6] = {0, 0, 0, 0, 0, 2e-3};
  update_stress_elastic(m, ds, 1.0, tau);
  EXPECT_NEAR(tau[5], 2 * m.G * 2e-3, 1e-15);
  EXPECT_EQ(tau[0], 0.0);
}

TEST(MaterialPlastic, UniaxialStrainPathClosedForm) {
  for (double beta : {0.0, 0.5, 1.0}) {
    const MaterialConstants m = metal(beta);
    State s;
    // Uniaxial strain eps (d = (rate, 0, 0)).  Elastic: sigma_xx = (lambda + 2G) eps and the
    // von Mises stress q = sigma_xx - sigma_yy = 2G eps, so yield at eps_y = sigma_y / (2G).
    // Plastic (monotonic, any beta): dq = 2G (deps - 3/2 deps_p) = E_p deps_p gives
    // deps_p = 2G deps / (3G + E_p), and with dp = K deps,
    //   d sigma_xx / d eps = K + (4/3) G E_p / (3G + E_p),
    //   sigma_xx - sigma_yy = sigma_y + E_p eps_p.
    // Radial return is exact on this proportional path: relative tolerance 1e-12.
    const double eps_y = m.sigma_y / (2 * m.G);
    const double slope = m.K + 4.0 / 3.0 * m.G * m.E_p / (3 * m.G + m.E_p);
    const double de = eps_y / 7.3;  // steps do not land on the yield point
    for (int i = 1; i <= 80; ++i) {
      const double d[6] = {de, 0, 0, 0, 0, 0};
      step(m, s, d, 1.0);
      const double eps = i * de;
      double sxx, epsp;
      if (eps <= eps_y) {
        sxx = (m.lambda + 2 * m.G) * eps;
        epsp = 0;
      } else {
        sxx = (m.lambda + 2 * m.G) * eps_y + slope * (eps - eps_y);
        epsp = 2 * m.G * (eps - eps_y) / (3 * m.G + m.E_p);
      }
      ASSERT_NEAR(s.sig[0], sxx, 1e-12 * std::fabs(sxx)) << "beta " << beta << " step " << i;
      ASSERT_NEAR(s.eps_p, epsp, 1e-12 * (epsp + eps_y));
      const double q = eps <= eps_y ? 2 * m.G * eps : m.sigma_y + m.E_p * epsp;
      ASSERT_NEAR(s.sig[0] - s.sig[1], q, 1e-12 * m.sigma_y * 10);
      EXPECT_EQ(s.yielded, eps > eps_y ? 1 : 0);
    }
  }
}

TEST(MaterialPlastic, UniaxialStressPathIsBilinear) {
  for (double beta : {0.0, 1.0}) {
    const MaterialConstants m = metal(beta);
    State s;
    const double eps_y = m.sigma_y / m.E;
    const double de = eps_y / 6.7;
    for (int i = 1; i <= 60; ++i) {
      uniaxial_stress_step(m, s, de);
      const double eps = i * de;
      // Lateral stresses vanish (solved for): |sigma_yy| <= 1e-15 sigma_y (+ round-off).
      ASSERT_NEAR(s.sig[1], 0.0, 1e-13 * m.sigma_y);
      ASSERT_NEAR(s.sig[2], 0.0, 1e-13 * m.sigma_y);
      // Bilinear: sigma = E eps to yield, then sigma_y + E_tan (eps - eps_y), with
      // eps_p = (sigma - sigma_y) / E_p.  Relative tolerance 1e-9 (stricter than 1e-6: the
      // radial return is exact on a proportional path, only the lateral solve rounds).
      const double sxx = eps <= eps_y ? m.E * eps : m.sigma_y + m.E_tan * (eps - eps_y);
      ASSERT_NEAR(s.sig[0], sxx, 1e-9 * sxx) << "beta " << beta << " step " << i;
      ASSERT_NEAR(s.eps_p, eps <= eps_y ? 0.0 : (sxx - m.sigma_y) / m.E_p, 1e-9 * eps_y);
    }
  }
}

TEST(MaterialPlastic, ReverseYieldBauschinger) {
  // Load in uniaxial tension past yield to sigma_1, unload elastically and reverse.  With the
  // current radius R = sigma_y + beta E_p eps_p and the back stress centre alpha_1 = sigma_1 - R
  // (uniaxial measure), reverse yield occurs at sigma_r = sigma_1 - 2R:
  //   kinematic (beta = 0): sigma_1 - 2 sigma_y (Bauschinger),
  //   isotropic (beta = 1): -sigma_1,  mixed (beta = 0.5): in between.
  for (double beta : {0.0, 0.5, 1.0}) {
    const MaterialConstants m = metal(beta);
    State s;
    const double eps_y = m.sigma_y / m.E;
    for (int i = 0; i < 50; ++i) uniaxial_stress_step(m, s, eps_y / 5.0);  // to eps = 10 eps_y
    const double s1 = s.sig[0];
    ASSERT_NEAR(s1, m.sigma_y + m.E_tan * 9 * eps_y, 1e-9 * s1);
    const double R = m.sigma_y + beta * m.E_p * s.eps_p;
    const double sr = s1 - 2 * R;
    if (beta == 0.0) {
      EXPECT_NEAR(sr, s1 - 2 * m.sigma_y, 1e-12);
    }
    if (beta == 1.0) {
      EXPECT_NEAR(sr, -s1, 1e-12);
    }
    // Elastic uniaxial-stress unloading d = (de, -nu de, -nu de) changes sigma_xx by E de.
    // Unload to sr + delta: still elastic (no plastic increment); a further 2 delta: yields.
    // delta = 1e-7 sigma_y, far above round-off (1e-15) and far below the step.
    const double delta = 1e-7 * m.sigma_y;
    State u = s;
    const double de1 = (sr + delta - s1) / m.E;
    const double d1[6] = {de1, -m.nu * de1, -m.nu * de1, 0, 0, 0};
    EXPECT_EQ(step(m, u, d1, 1.0), 0.0) << "beta " << beta;
    EXPECT_NEAR(u.sig[0], sr + delta, 1e-12);
    EXPECT_NEAR(u.sig[1], 0.0, 1e-13);
    const double de2 = -2 * delta / m.E;
    const double d2[6] = {de2, -m.nu * de2, -m.nu * de2, 0, 0, 0};
    EXPECT_GT(step(m, u, d2, 1.0), 0.0) << "beta " << beta;
  }
}

TEST(MaterialPlastic, ReturnLandsOnTheYieldSurface) {
  // Large general strain increments with rotation; after each plastic return
  // vm(s - alpha) = sigma_y + beta E_p eps_p (relative 1e-10), alpha stays deviatoric (1e-14),
  // and the pressure is the elastic one, K tr(eps) (return is deviatoric; 1e-12 relative).
  for (double beta : {0.0, 0.3, 1.0}) {
    const MaterialConstants m = metal(beta);
    State s;
    double vol = 0;
    int plastic_steps = 0;
    for (int i = 0; i < 40; ++i) {
      const double d[6] = {2e-3 * std::sin(0.7 * i), 1.5e-3 * std::cos(1.3 * i),
                           -1e-3 * std::sin(2.1 * i + 0.4), 1.2e-3 * std::cos(0.5 * i),
                           -0.8e-3 * std::sin(1.7 * i), 0.9e-3 * std::cos(2.9 * i)};
      const double w[3] = {0.3 * std::sin(1.1 * i), 0.2, -0.4 * std::cos(0.9 * i)};
      const double dt = 1.0;
      rotate_stress_jaumann(s.sig, w, dt * 1e-2);
      rotate_stress_jaumann(s.back, w, dt * 1e-2);
      const double deps = step(m, s, d, dt);
      vol += d[0] + d[1] + d[2];
      if (deps > 0) {
        ++plastic_steps;
        const double r = m.sigma_y + beta * m.E_p * s.eps_p;
        ASSERT_NEAR(vm_of_xi(s), r, 1e-10 * r) << "beta " << beta << " step " << i;
      } else {
        ASSERT_LE(vm_of_xi(s), m.sigma_y + beta * m.E_p * s.eps_p);
      }
      ASSERT_NEAR(s.back[0] + s.back[1] + s.back[2], 0.0, 1e-14);
    }
    EXPECT_GT(plastic_steps, 10);
    // Rotation keeps the trace (tr(W s - s W) = 0), so p = K * total volumetric strain.
    EXPECT_NEAR((s.sig[0] + s.sig[1] + s.sig[2]) / 3, m.K * vol, 1e-12 * m.K * 1e-2);
  }
}

TEST(MaterialPlastic, YieldedFlagAndElasticFastPath) {
  const MaterialConstants m = metal(1.0);
  State s;
  // Below yield: purely elastic (identical to the type 1 update), flag stays 0.
  const double d[6] = {1e-4, -2e-5, 3e-5, 4e-5, 0, -1e-5};
  double ref[6] = {0, 0, 0, 0, 0, 0};
  EXPECT_EQ(step(m, s, d, 1.0), 0.0);
  update_stress_elastic(m, d, 1.0, ref);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(s.sig[k], ref[k]);
  EXPECT_EQ(s.yielded, 0);
  const double big[6] = {5e-3, 0, 0, 0, 0, 0};
  EXPECT_GT(step(m, s, big, 1.0), 0.0);
  EXPECT_EQ(s.yielded, 1);
}

TEST(MaterialPlastic, PerfectPlasticity) {
  // E_tan = 0: E_p = 0, the von Mises stress stays at sigma_y (relative 1e-12) in pure shear.
  MaterialConstants m = metal(1.0);
  m.E_tan = 0;
  derive_material_constants(m);
  EXPECT_EQ(m.E_p, 0.0);
  State s;
  for (int i = 0; i < 20; ++i) {
    const double d[6] = {0, 0, 0, 5e-4, 0, 0};
    step(m, s, d, 1.0);
  }
  // Pure shear: vm = sqrt(3) tau = sigma_y.
  EXPECT_NEAR(s.sig[3], m.sigma_y / std::sqrt(3.0), 1e-12 * m.sigma_y);
}

TEST(MaterialVonMises, ClosedForms) {
  const double uni[6] = {-3.0, 0, 0, 0, 0, 0};
  const double shear[6] = {0, 0, 0, 0, 2.0, 0};
  const double hyd[6] = {5.0, 5.0, 5.0, 0, 0, 0};
  // |sigma|, sqrt(3) tau, 0; relative tolerance 1e-15.
  EXPECT_NEAR(calc_von_mises(uni), 3.0, 3e-15);
  EXPECT_NEAR(calc_von_mises(shear), 2.0 * std::sqrt(3.0), 4e-15);
  EXPECT_NEAR(calc_von_mises(hyd), 0.0, 1e-15);
}

namespace {

void invariants(const double s[6], double& i1, double& i2, double& i3) {
  i1 = s[0] + s[1] + s[2];
  i2 = s[0] * s[1] + s[1] * s[2] + s[2] * s[0] - s[3] * s[3] - s[4] * s[4] - s[5] * s[5];
  i3 = s[0] * (s[1] * s[2] - s[4] * s[4]) - s[3] * (s[3] * s[2] - s[4] * s[5]) +
       s[5] * (s[3] * s[4] - s[1] * s[5]);
}

}  // namespace

TEST(MaterialJaumann, SpinAboutZRotatesUniaxialStress) {
  // Counter-clockwise rotation about z at rate Omega: v = (-Omega y, Omega x, 0), so
  // W_xy = (L_xy - L_yx)/2 = -Omega.  A uniaxial sigma_xx = 1 rotated by the small angle
  // Omega dt gets sigma_xy = Omega dt (to first order: the Jaumann update is exactly
  // sigma_xy = -W_xy dt sigma_xx), sigma_xx unchanged at first order.
  double s[6] = {1, 0, 0, 0, 0, 0};
  const double omega = 2.0, dt = 1e-3;
  const double w[3] = {-omega, 0, 0};
  rotate_stress_jaumann(s, w, dt);
  EXPECT_NEAR(s[3], omega * dt, 1e-16);  // exact in the update formula; tolerance 1 ulp-ish
  EXPECT_EQ(s[0], 1.0);
  EXPECT_EQ(s[1], 0.0);
  EXPECT_EQ(s[4], 0.0);
  EXPECT_EQ(s[5], 0.0);
}

TEST(MaterialJaumann, InvariantsPreservedToSecondOrder) {
  const double s0[6] = {3.0, -1.0, 2.0, 0.7, -0.4, 1.1};
  const double w[3] = {0.9, -1.4, 0.6};
  double a1, a2, a3;
  invariants(s0, a1, a2, a3);
  double err2[2], err3[2];
  const double dts[2] = {1e-3, 5e-4};
  for (int k = 0; k < 2; ++k) {
    double s[6];
    std::copy(s0, s0 + 6, s);
    rotate_stress_jaumann(s, w, dts[k]);
    double b1, b2, b3;
    invariants(s, b1, b2, b3);
    // tr(W s - s W) = 0: the first invariant is kept to round-off (1e-14).
    EXPECT_NEAR(b1, a1, 1e-14);
    err2[k] = std::fabs(b2 - a2);
    err3[k] = std::fabs(b3 - a3);
    // sigma* = R s R^T + dt^2 W s W with R = I + dt W, det R R^T = 1 + O(dt^2): the changes are
    // O((|w| dt)^2 |s|^n); bound with constant 10 (|w| ~ 1.8, |s| ~ 3.5).
    const double h2 = dts[k] * dts[k];
    EXPECT_LE(err2[k], 10.0 * h2 * 4.0 * 12.0);
    EXPECT_LE(err3[k], 10.0 * h2 * 4.0 * 43.0);
  }
  // Second order: halving dt divides the change by 4 (ratio in [3.5, 4.5]).
  EXPECT_GT(err2[0] / err2[1], 3.5);
  EXPECT_LT(err2[0] / err2[1], 4.5);
  EXPECT_GT(err3[0] / err3[1], 3.5);
  EXPECT_LT(err3[0] / err3[1], 4.5);
}

TEST(MaterialJaumann, MatchesMatrixProducts) {
  // sigma + dt (W sigma - sigma W) with explicit 3x3 products; W_xy = w0, W_yz = w1, W_zx = w2.
  // Tolerance 1e-15 (O(1) entries, a few products).
  const double s0[6] = {3.0, -1.0, 2.0, 0.7, -0.4, 1.1};
  const double w[3] = {0.9, -1.4, 0.6};
  const double dt = 0.1;
  const double S[3][3] = {{s0[0], s0[3], s0[5]}, {s0[3], s0[1], s0[4]}, {s0[5], s0[4], s0[2]}};
  const double W[3][3] = {{0, w[0], -w[2]}, {-w[0], 0, w[1]}, {w[2], -w[1], 0}};
  double R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      R[i][j] = S[i][j];
      for (int k = 0; k < 3; ++k) R[i][j] += dt * (W[i][k] * S[k][j] - S[i][k] * W[k][j]);
    }
  double s[6];
  std::copy(s0, s0 + 6, s);
  rotate_stress_jaumann(s, w, dt);
  EXPECT_NEAR(s[0], R[0][0], 1e-15);
  EXPECT_NEAR(s[1], R[1][1], 1e-15);
  EXPECT_NEAR(s[2], R[2][2], 1e-15);
  EXPECT_NEAR(s[3], R[0][1], 1e-15);
  EXPECT_NEAR(s[4], R[1][2], 1e-15);
  EXPECT_NEAR(s[5], R[2][0], 1e-15);
  EXPECT_NEAR(R[0][1], R[1][0], 1e-15);  // the result is symmetric
}

// Cowper-Symonds strain-rate scaling (type 3, C > 0): in pure shear at a constant strain rate
// the von Mises stress of a perfectly plastic material settles on sigma_y (1 + (rate/C)^(1/P))
// with rate = sqrt(D:D) = sqrt(2) d_xy; with hardening the returned stress lies on the scaled
// surface R (sigma_y + beta E_p eps_p) (consistency of the modified return).
TEST(MaterialPlastic, CowperSymondsScalesTheYieldStress) {
  for (double rate : {10.0, 1e3, 4e4}) {
    MaterialConstants m = metal(1.0);
    m.E_tan = 0.0;
    derive_material_constants(m);
    m.rate_c = 40.4;  // the classic mild-steel constants, 1/s
    m.rate_inv_p = 1.0 / 5.0;
    const double dxy = rate / std::sqrt(2.0);
    const double d[6] = {0, 0, 0, dxy, 0, 0};
    State s;
    const double dt = 1e-7;  // shear strain increment dxy dt per step
    for (int k = 0; k < 4000; ++k) step(m, s, d, dt);
    ASSERT_GT(s.eps_p, 0.0) << rate;
    const double expected = m.sigma_y * (1.0 + std::pow(rate / 40.4, 0.2));
    EXPECT_NEAR(calc_von_mises(s.sig), expected, 1e-12 * expected) << "rate " << rate;
  }
  // hardening (mixed, beta = 0.5): on the scaled surface after every plastic step
  MaterialConstants m = metal(0.5);
  m.rate_c = 100.0;
  m.rate_inv_p = 1.0 / 4.0;
  const double d[6] = {2e3, -1e3, -1e3, 500.0, 0, 0};
  const double rate = std::sqrt(2e3 * 2e3 + 2 * 1e3 * 1e3 + 2 * 500.0 * 500.0);
  const double R = 1.0 + std::pow(rate / 100.0, 0.25);
  State s;
  int plastic = 0;
  for (int k = 0; k < 200; ++k) {
    if (step(m, s, d, 1e-6) > 0) {
      ++plastic;
      double xi[6];
      const double p = (s.sig[0] + s.sig[1] + s.sig[2]) / 3;
      for (int c = 0; c < 6; ++c) xi[c] = s.sig[c] - (c < 3 ? p : 0.0) - s.back[c];
      const double sy = R * (m.sigma_y + m.beta * m.E_p * s.eps_p);
      EXPECT_NEAR(calc_von_mises(xi), sy, 1e-12 * sy) << "step " << k;
    }
  }
  EXPECT_GT(plastic, 50);
  // C = 0: no rate effect whatever the rate (the rate-free path)
  MaterialConstants plain = metal(1.0);
  State a, b;
  MaterialConstants zero = plain;
  zero.rate_inv_p = 0.25;  // P given but C = 0: ignored
  for (int k = 0; k < 100; ++k) {
    step(plain, a, d, 1e-6);
    step(zero, b, d, 1e-6);
  }
  for (int c = 0; c < 6; ++c) EXPECT_EQ(a.sig[c], b.sig[c]);
}
