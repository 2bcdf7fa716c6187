// The shells' block kernel (shell_block.h: 8 Belytschko-Tsay shells at once, one SIMD lane each)
// gives exactly the bits of the scalar kernel (shell_bt.h, calc_shell_bt_forces) shell by shell:
// distorted, warped quadrilaterals and triangles of different sizes, random velocities and
// angular velocities, over several steps (the state carried from step to step: stresses, back
// stresses, plastic strains, hourglass resultants, drilling moments), for the elastic (NIP 2, 3),
// plastic-kinematic (NIP 5; beta 0, 0.5, 0.3, 1: kinematic, mixed, isotropic) and
// piecewise-linear (NIP 5: a table; rate effects, VP 0 and 1) materials, the viscous and stiffness
// hourglass forms, with and without the drilling constraint, and a first step with dt = 0.  Every
// output compared bit for bit (memcmp: -0.0 against 0.0 and NaN would show).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "impact3d/element/shell_block.h"
#include "impact3d/element/shell_bt.h"
#include "impact3d/material/material_types.h"
#include "impact3d/model/model.h"

using namespace impact3d;

namespace {

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Case {
  int type = 1;
  int nip = 2;
  double beta = 1;
  double sigma_y = 2.5e8;
  int hourglass_type = 1;
  double hourglass_coef = 0.1;
  double drill_coef = kShellDrillingCoef;
  bool rate = false;   // type 24: Cowper-Symonds C, P
  bool vp = false;     // type 24: VP = 1
};

MaterialConstants material(const Case& c) {
  MaterialData md;
  md.number = 1;
  md.type = c.type;
  if (c.type == 24) set_param_defaults(md, material_type(24));
  md.rho = 7850;
  md.E = 2.1e11;
  md.nu = 0.3;
  md.sigma_y = c.sigma_y;
  md.E_tan = 2e9;
  md.beta = c.beta;
  if (c.type == 24) {
    const MaterialType& t = material_type(24);
    const double eps[4] = {0, 1e-4, 5e-4, 2e-3}, es[4] = {c.sigma_y, 1.5 * c.sigma_y, 1.8 * c.sigma_y, 2 * c.sigma_y};
    for (int i = 0; i < 4; ++i) {
      param_value(md, *find_param(t, "EPS" + std::to_string(i + 1))) = eps[i];
      param_value(md, *find_param(t, "ES" + std::to_string(i + 1))) = es[i];
    }
    if (c.rate) {
      md.rate_c = 40;
      md.rate_p = 5;
    }
    if (c.vp) param_value(md, *find_param(t, "VP")) = 1;
  }
  return derive_constants(md, Model{});
}

ShellGroupConstants constants(const Case& c, const MaterialConstants& mc) {
  ShellGroupConstants g;
  g.nip = c.nip;
  gauss_legendre_rule(g.nip, g.zeta, g.weight);
  g.shrf = 5.0 / 6.0;
  g.hourglass_type = c.hourglass_type;
  g.hourglass_coef = c.hourglass_coef;
  g.rho = mc.rho;
  g.E = mc.E;
  g.nu = mc.nu;
  g.G = mc.G;
  g.c_plate = std::sqrt(mc.E / (mc.rho * (1 - mc.nu * mc.nu)));
  g.drill_coef = c.drill_coef;
  return g;
}

ShellMaterialKind kind_of(int type) {
  return type == 3 ? ShellMaterialKind::plastic_kinematic
         : type == 24 ? ShellMaterialKind::piecewise_linear
                      : ShellMaterialKind::elastic;
}

// One lane's shell for the scalar kernel: its kernel data and point state.
struct Scalar {
  ShellKernelIO io;
  double sig[5 * kMaxShellIntegrationPoints] = {}, back[6 * kMaxShellIntegrationPoints] = {};
  double eps[kMaxShellIntegrationPoints] = {};
  unsigned char yielded[kMaxShellIntegrationPoints] = {};
  double hgq[5] = {}, drill[4] = {};
};

// Runs `steps` steps of the block kernel and of the scalar one on 8 random shells and compares.
void check_same_bits(const Case& c, unsigned seed, int steps = 6) {
  const MaterialConstants mc = material(c);
  const ShellGroupConstants g = constants(c, mc);
  const ShellMaterialKind kind = kind_of(c.type);
  ASSERT_TRUE(shell_block_covers(kind, mc));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  static ShellBlock b;  // (40 KB: not on the test's stack)
  b = ShellBlock{};
  Scalar sc[kLanes];
  const double X[4] = {0, 1, 1, 0}, Y[4] = {0, 0, 1, 1};
  for (int l = 0; l < kLanes; ++l) {
    const double a = 0.01 * (1 + 0.4 * l);  // sizes differ lane to lane
    const bool tri = l == 3 || l == 6;
    for (int j = 0; j < 4; ++j) {
      const int jj = tri && j == 3 ? 2 : j;
      const double xyz[3] = {a * (X[jj] + 0.25 * u(rng)), a * (Y[jj] + 0.25 * u(rng)), a * 0.1 * u(rng)};
      for (int k = 0; k < 3; ++k) sc[l].io.x[j][k] = tri && j == 3 ? sc[l].io.x[2][k] : xyz[k];
      for (int k = 0; k < 3; ++k) {
        sc[l].io.v[j][k] = 5 * u(rng);
        sc[l].io.w[j][k] = 200 * u(rng);
      }
    }
    sc[l].io.h = 1e-3 * (1 + 0.2 * l);
  }
  const ShellBlockMaterial mat{&mc, kind, material_type(c.type).solid.update_block, kind == ShellMaterialKind::plastic_kinematic,
                               true};
  for (int step = 0; step < steps; ++step) {
    const double dt = step == 0 ? 0.0 : 1e-7 * (1 + 0.1 * step);
    for (int l = 0; l < kLanes; ++l) {
      Scalar& s = sc[l];
      s.io.dt = dt;
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 3; ++k) {
          if (step > 0) s.io.x[j][k] += dt * s.io.v[j][k];
          b.x[j][k][l] = s.io.x[j][k];
          b.v[j][k][l] = s.io.v[j][k];
          b.w[j][k][l] = s.io.w[j][k];
        }
      b.h[l] = s.io.h;
      for (int p = 0; p < g.nip; ++p) {
        for (int k = 0; k < 5; ++k) b.sig[p][k][l] = s.sig[5 * p + k];
        for (int k = 0; k < 6; ++k) b.back[p][k][l] = s.back[6 * p + k];
        b.eps_p[p][l] = s.eps[p];
        b.yielded[p][l] = s.yielded[p];
      }
      for (int j = 0; j < 5; ++j) b.hgq[j][l] = s.hgq[j];
      for (int j = 0; j < 4; ++j) b.drill[j][l] = s.drill[j];
      const ShellPointState st{s.sig, kind == ShellMaterialKind::plastic_kinematic ? s.back : nullptr,
                               kind == ShellMaterialKind::elastic ? nullptr : s.eps,
                               kind == ShellMaterialKind::elastic ? nullptr : s.yielded, s.hgq, s.drill};
      calc_shell_bt_forces(g, mc, kind, s.io, st);
      ASSERT_FALSE(s.io.bad);
    }
    calc_shell_bt_forces_block(g, mat, dt, b);
    int yielded = 0;
    for (int l = 0; l < kLanes; ++l) {
      const Scalar& s = sc[l];
      SCOPED_TRACE("step " + std::to_string(step) + " lane " + std::to_string(l));
      ASSERT_EQ(b.bad[l], 0.0);
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 3; ++k) {
          ASSERT_TRUE(same(b.f[j][k][l], s.io.f[j][k])) << "f " << j << k << ": " << b.f[j][k][l] << " " << s.io.f[j][k];
          ASSERT_TRUE(same(b.m[j][k][l], s.io.m[j][k])) << "m " << j << k;
        }
      ASSERT_TRUE(same(b.area[l], s.io.area));
      ASSERT_TRUE(same(b.de_ie[l], s.io.de_ie));
      ASSERT_TRUE(same(b.de_hg[l], s.io.de_hg));
      ASSERT_TRUE(same(b.dt_e[l], s.io.dt_e));
      for (int p = 0; p < g.nip; ++p) {
        for (int k = 0; k < 5; ++k) ASSERT_TRUE(same(b.sig[p][k][l], s.sig[5 * p + k])) << "sig " << p << k;
        if (kind == ShellMaterialKind::plastic_kinematic) {
          for (int k = 0; k < 6; ++k) ASSERT_TRUE(same(b.back[p][k][l], s.back[6 * p + k])) << "back " << p << k;
        }
        if (kind != ShellMaterialKind::elastic) {
          ASSERT_TRUE(same(b.eps_p[p][l], s.eps[p])) << "eps_p " << p;
          ASSERT_EQ(b.yielded[p][l], double(s.yielded[p]));
          yielded += s.yielded[p];
        }
      }
      for (int j = 0; j < 5; ++j) ASSERT_TRUE(same(b.hgq[j][l], s.hgq[j]));
      for (int j = 0; j < 4; ++j) ASSERT_TRUE(same(b.drill[j][l], s.drill[j]));
    }
    if (kind != ShellMaterialKind::elastic && step == steps - 1) {
      EXPECT_GT(yielded, 0);  // the plastic branch ran
    }
  }
}

}  // namespace

TEST(ShellBlock, ElasticSameBits) {
  for (unsigned seed = 1; seed <= 4; ++seed) check_same_bits(Case{}, seed);
  Case c;
  c.nip = 3;
  c.hourglass_type = 4;
  check_same_bits(c, 11);
  c.hourglass_type = 5;
  c.drill_coef = 0;
  check_same_bits(c, 12);
  c.hourglass_coef = 0;
  check_same_bits(c, 13);
}

TEST(ShellBlock, PlasticKinematicSameBits) {
  for (const double beta : {0.0, 0.5, 0.3, 1.0}) {
    Case c;
    c.type = 3;
    c.nip = 5;
    c.beta = beta;
    c.sigma_y = 2e6;  // yields in the first steps
    check_same_bits(c, 21);
    c.hourglass_type = 4;
    check_same_bits(c, 22);
  }
}

TEST(ShellBlock, PiecewiseLinearSameBits) {
  Case c;
  c.type = 24;
  c.nip = 5;
  c.sigma_y = 2e6;
  check_same_bits(c, 31);
  c.rate = true;
  check_same_bits(c, 32);
  c.vp = true;
  check_same_bits(c, 33);
}

TEST(ShellBlock, CoversElasticKinematicPiecewiseOnly) {
  Case c;
  c.type = 3;
  MaterialConstants mc = material(c);
  EXPECT_TRUE(shell_block_covers(ShellMaterialKind::plastic_kinematic, mc));
  mc.rate_c = 40;  // rate-dependent type 3: the scalar kernel
  EXPECT_FALSE(shell_block_covers(ShellMaterialKind::plastic_kinematic, mc));
  EXPECT_FALSE(shell_block_covers(ShellMaterialKind::mooney_rivlin, mc));
  EXPECT_FALSE(shell_block_covers(ShellMaterialKind::power_law, mc));
}
