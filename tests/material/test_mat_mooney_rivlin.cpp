// Type 27 (*MAT_MOONEY-RIVLIN_RUBBER) at one point through the table's kernels:
//  - small strains: shear modulus 2 (A + B) and the bulk modulus of PR (LS-DYNA's D), 1e-5;
//  - uniaxial stress driven to stretch 2.5 (lateral rate found so that sigma_yy = 0): nominal
//    stress within 1e-9 of the compressible W's and within 0.1 % (PR 0.4995) of the
//    incompressible 2 (A + B / s) (s - 1 / s^2);
//  - a stretched point spun through a full turn by the spin w: the stress rotates with it (its
//    invariants unchanged to 1e-9) and returns to its value (objectivity of the b update);
//  - a closed strain path (strains up to about 0.5) returns b and the stress to zero
//    (hyperelastic, no drift), 1e-13 in b;
//  - the plane-stress shell form in uniaxial stress: the incompressible closed form, 1e-9.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "impact3d/material/material_types.h"
#include "impact3d/material/plane_stress.h"

using namespace impact3d;

namespace {

constexpr double kA = 4e5, kB = 1e5;

MaterialData rubber(double nu) {
  const MaterialType& t = material_type(27);
  MaterialData md;
  md.type = 27;
  set_param_defaults(md, t);
  md.rho = 1100, md.nu = nu;
  param_value(md, *find_param(t, "A")) = kA;
  param_value(md, *find_param(t, "B")) = kB;
  return md;
}

void step(const MaterialConstants& m, SolidPointState& s, double d0, double d1, double d2, double dt,
          const double w[3] = nullptr) {
  const double d[6] = {d0, d1, d2, 0, 0, 0};
  for (int c = 0; c < 3; ++c) s.w[c] = w ? w[c] : 0.0;
  material_type(27).solid.update_point(m, d, dt, s);
}

// The Cayley rate that takes stretch a to b in one step of dt: (1 + h d) / (1 - h d) = b / a.
double rate_between(double a, double b, double dt) { return 2 * (b / a - 1) / ((b / a + 1) * dt); }

}  // namespace

TEST(MatMooneyRivlin, SmallStrainModuliAreTwoAPlusBAndThoseOfPR) {
  const double nu = 0.49;
  const MaterialConstants m = derive_constants(rubber(nu), Model{});
  const double G = 2 * (kA + kB), K = 2 * G * (1 + nu) / (3 * (1 - 2 * nu));
  EXPECT_NEAR(m.G, G, 1e-9 * G);
  EXPECT_NEAR(m.K, K, 1e-9 * K);
  const double e = 1e-6, dt = 1e-3;
  {  // simple shear rate: d_xy = e / dt (tensor shear)
    SolidPointState s;
    const double d[6] = {0, 0, 0, e / dt, 0, 0};
    material_type(27).solid.update_point(m, d, dt, s);
    EXPECT_NEAR(s.sig[3] / (2 * e), G, 1e-5 * G);
  }
  {  // dilatation: volumetric strain 3 e
    SolidPointState s;
    const double r = rate_between(1, 1 + e, dt);
    step(m, s, r, r, r, dt);
    const double ev = std::log(std::pow(1 + e, 3));
    EXPECT_NEAR(s.sig[0] / ev, K, 1e-5 * K);
    EXPECT_NEAR(s.sig[3], 0, 1e-9);
  }
}

TEST(MatMooneyRivlin, UniaxialStressFollowsTheIncompressibleClosedForm) {
  const double nu = 0.4995;
  const MaterialConstants m = derive_constants(rubber(nu), Model{});
  SolidPointState s;
  const double dt = 1e-3;
  double sx = 1, t = 1, worst = 0;
  for (int i = 1; i <= 300; ++i) {
    const double sx1 = 1 + 1.5 * i / 300.0;
    // the lateral stretch t1 with sigma_yy = 0 (bisection on the kernel's answer from the same state)
    double lo = 0.5 * t, hi = t;
    SolidPointState trial;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      trial = s;
      const double rt = rate_between(t, mid, dt);
      step(m, trial, rate_between(sx, sx1, dt), rt, rt, dt);
      (trial.sig[1] > 0 ? hi : lo) = mid;
    }
    s = trial;
    sx = sx1, t = 0.5 * (lo + hi);
    const double nominal = s.sig[0] * t * t;
    const double closed = 2 * (kA + kB / sx) * (sx - 1 / (sx * sx));
    worst = std::max(worst, std::fabs(nominal / closed - 1));
    EXPECT_NEAR(1 + s.hist[0], sx * sx, 1e-9 * sx * sx);  // b_xx = s^2 exactly along the path
  }
  EXPECT_LT(worst, 1e-3);
  RecordProperty("worst_vs_incompressible", std::to_string(worst));
}

TEST(MatMooneyRivlin, SpinRotatesTheStressWithoutChangingIt) {
  const MaterialConstants m = derive_constants(rubber(0.49), Model{});
  SolidPointState s;
  const double dt = 1e-3;
  step(m, s, rate_between(1, 1.5, dt), rate_between(1, 0.9, dt), 0, dt);
  const double sig0[6] = {s.sig[0], s.sig[1], s.sig[2], s.sig[3], s.sig[4], s.sig[5]};
  auto inv = [](const double* g) {
    return std::array<double, 2>{g[0] + g[1] + g[2], g[0] * g[1] + g[1] * g[2] + g[2] * g[0] - g[3] * g[3] - g[4] * g[4] - g[5] * g[5]};
  };
  const auto i0 = inv(sig0);
  const int n = 1000;
  const double w[3] = {2 * M_PI / (n * dt), 0, 0};  // W_xy: about z, one turn
  for (int k = 0; k < n; ++k) {
    step(m, s, 0, 0, 0, dt, w);
    const auto i = inv(s.sig);
    EXPECT_NEAR(i[0], i0[0], 1e-9 * std::fabs(i0[0]));
    EXPECT_NEAR(i[1], i0[1], 1e-9 * std::fabs(i0[1]));
  }
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(s.sig[c], sig0[c], 1e-6 * std::fabs(sig0[0])) << c;
}

TEST(MatMooneyRivlin, ClosedStrainPathLeavesNoStress) {
  const MaterialConstants m = derive_constants(rubber(0.49), Model{});
  SolidPointState s;
  const double dt = 1e-3;
  for (int k = 0; k < 200; ++k) {
    const double d[6] = {std::sin(k * 0.1) * 5, -2.0 * std::cos(k * 0.07), 1, 3, -1.5, 0.5};
    material_type(27).solid.update_point(m, d, dt, s);
  }
  for (int k = 199; k >= 0; --k) {
    const double d[6] = {-std::sin(k * 0.1) * 5, 2.0 * std::cos(k * 0.07), -1, -3, 1.5, -0.5};
    material_type(27).solid.update_point(m, d, dt, s);
  }
  for (int c = 0; c < 6; ++c) {
    EXPECT_NEAR(s.hist[c], 0, 1e-13) << c;
    EXPECT_NEAR(s.sig[c], 0, 1e-11 * kA) << c;
  }
}

TEST(MatMooneyRivlin, PlaneStressUniaxialIsTheIncompressibleClosedForm) {
  const MaterialConstants m = derive_constants(rubber(0.49), Model{});
  double sig[5] = {}, b[3] = {};
  const double dt = 1e-3;
  double sx = 1;
  for (int i = 1; i <= 100; ++i) {
    const double sx1 = 1 + 1.5 * i / 100.0;
    // incompressible uniaxial: lateral in-plane stretch sx^-1/2
    const double d[5] = {rate_between(sx, sx1, dt), rate_between(1 / std::sqrt(sx), 1 / std::sqrt(sx1), dt), 0, 0, 0};
    update_plane_stress_mooney_rivlin(m, d, dt, sig, b);
    sx = sx1;
    // the stress per initial thickness times the width stretch is the nominal stress
    const double nominal = sig[0] / std::sqrt(sx);
    EXPECT_NEAR(nominal, 2 * (kA + kB / sx) * (sx - 1 / (sx * sx)), 1e-9 * kA) << sx;
    EXPECT_NEAR(sig[1], 0, 1e-9 * kA) << sx;
  }
}

TEST(MatMooneyRivlin, Checks) {
  const MaterialType& t = material_type(27);
  auto keys = [&](double A, double B, double lcid, double ref) {
    MaterialData md = rubber(0.49);
    param_value(md, *find_param(t, "A")) = A;
    param_value(md, *find_param(t, "B")) = B;
    param_value(md, *find_param(t, "LCID")) = lcid;
    param_value(md, *find_param(t, "REF")) = ref;
    std::string out;
    check_material_params(md, t, [&](const MaterialParam& p, int msg, const std::string&) {
      out += std::string(p.key) + ":" + std::to_string(msg) + " ";
    });
    return out;
  };
  EXPECT_EQ(keys(kA, kB, 0, 0), "");
  EXPECT_EQ(keys(kA, kB, 5, 0), "");  // LS-DYNA ignores card 2 when A or B is given
  EXPECT_EQ(keys(0, 0, 5, 0), "LCID:1102 ");
  EXPECT_EQ(keys(0, 0, 0, 0), "A:1003 ");
  EXPECT_EQ(keys(kA, kB, 0, 1), "REF:1102 ");
  EXPECT_EQ(keys(-kA, kB, 0, 0), "B:1003 ");
}
