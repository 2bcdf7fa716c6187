// The block kernels (hex_block.h, material_block.h: 8 solids at once, one SIMD lane each) give
// exactly the bits of the scalar kernels (hexahedron.h, material.h) element by element, on
// distorted elements with random velocities and stresses, for every hourglass type and the
// elastic and elastic-plastic updates (with and without back stress and rate effects).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "impact3d/element/cbrt_positive.h"
#include "impact3d/element/hex_block.h"
#include "impact3d/element/hexahedron.h"
#include "impact3d/material/material.h"
#include "impact3d/material/material_block.h"
#include "impact3d/material/material_types.h"

using namespace impact3d;

namespace {

// Same bits (so that -0.0 != 0.0 and NaN == NaN would show).
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Fixture {
  HexBlock k;
  double x[kLanes][8], y[kLanes][8], z[kLanes][8], vx[kLanes][8], vy[kLanes][8], vz[kLanes][8];
  double sig[kLanes][6], back[kLanes][6];
  double dt = 2e-8;

  explicit Fixture(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const double X[8] = {0, 1, 1, 0, 0, 1, 1, 0}, Y[8] = {0, 0, 1, 1, 0, 0, 1, 1}, Z[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    for (int l = 0; l < kLanes; ++l) {
      const double h = 1e-3 * (1 + 0.3 * l);  // sizes differ lane to lane
      for (int j = 0; j < 8; ++j) {
        x[l][j] = h * (X[j] + 0.2 * u(rng));
        y[l][j] = h * (Y[j] + 0.2 * u(rng));
        z[l][j] = h * (Z[j] + 0.2 * u(rng));
        vx[l][j] = 100 * u(rng);
        vy[l][j] = 100 * u(rng);
        vz[l][j] = 100 * u(rng);
        k.x[j][l] = x[l][j]; k.y[j][l] = y[l][j]; k.z[j][l] = z[l][j];
        k.vx[j][l] = vx[l][j]; k.vy[j][l] = vy[l][j]; k.vz[j][l] = vz[l][j];
      }
      for (int c = 0; c < 6; ++c) {
        sig[l][c] = 3e8 * (0.1 + 0.15 * l) * u(rng);  // small in the first lanes, large in the last
        back[l][c] = c < 3 ? 2e7 * u(rng) : 1e7 * u(rng);
        k.sig[c][l] = sig[l][c];
        k.back[c][l] = back[l][c];
      }
      k.eps_p[l] = 0.1 * (1 + u(rng));
      k.yielded[l] = 0;
    }
  }
};

MaterialConstants copper(double beta, double rate_c) {
  MaterialConstants m;
  m.type = 3;
  m.rho = 8930;
  m.E = 117e9;
  m.nu = 0.35;
  m.sigma_y = 3e8;  // some lanes yield, some do not
  m.E_tan = 1e9;
  m.beta = beta;
  if (rate_c > 0) {
    m.rate_c = rate_c;
    m.rate_inv_p = 1.0 / 5.0;
  }
  derive_material_constants(m);
  return m;
}

}  // namespace

TEST(HexBlock, KinematicsEqualTheScalarKernelsBitForBit) {
  for (unsigned seed : {1u, 2u, 3u}) {
    Fixture f(seed);
    calc_hex_kinematics_block(f.k, f.dt);
    for (int l = 0; l < kLanes; ++l) {
      double xm[8], ym[8], zm[8], bx[8], by[8], bz[8], dvdx[8], dvdy[8], dvdz[8], d[6], w[3];
      for (int j = 0; j < 8; ++j) {
        xm[j] = f.x[l][j] - 0.5 * f.dt * f.vx[l][j];
        ym[j] = f.y[l][j] - 0.5 * f.dt * f.vy[l][j];
        zm[j] = f.z[l][j] - 0.5 * f.dt * f.vz[l][j];
      }
      const double vm = calc_hex_volume_derivatives(xm, ym, zm, bx, by, bz);
      const double v = calc_hex_volume_derivatives(f.x[l], f.y[l], f.z[l], dvdx, dvdy, dvdz);
      ASSERT_GT(v, 0);
      EXPECT_TRUE(same(vm, f.k.vm[l]));
      EXPECT_TRUE(same(v, f.k.v[l]));
      const double inv_vm = 1.0 / vm;
      for (int j = 0; j < 8; ++j) {
        bx[j] *= inv_vm; by[j] *= inv_vm; bz[j] *= inv_vm;
        EXPECT_TRUE(same(bx[j], f.k.bx[j][l]) && same(by[j], f.k.by[j][l]) && same(bz[j], f.k.bz[j][l]));
        EXPECT_TRUE(same(dvdx[j], f.k.dvdx[j][l]) && same(dvdy[j], f.k.dvdy[j][l]) && same(dvdz[j], f.k.dvdz[j][l]));
      }
      calc_hex_strain_rate(bx, by, bz, f.vx[l], f.vy[l], f.vz[l], d, w);
      for (int c = 0; c < 6; ++c) EXPECT_TRUE(same(d[c], f.k.d[c][l])) << "lane " << l << " d" << c;
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(same(w[c], f.k.w[c][l]));
      EXPECT_TRUE(same(d[0] + d[1] + d[2], f.k.trd[l]));
      EXPECT_TRUE(same(calc_hex_max_face_area(f.x[l], f.y[l], f.z[l]), f.k.amax[l]));
    }
  }
}

TEST(HexBlock, ForcesHourglassViscosityAndStepEqualTheScalarKernels) {
  const double c = 3900, G = 43e9, rho0 = 8930, q1 = 1.5, q2 = 0.06, qhg = 0.1;
  for (int type = 1; type <= 5; ++type) {
    Fixture f(10u + unsigned(type));
    calc_hex_kinematics_block(f.k, f.dt);
    for (int l = 0; l < kLanes; ++l) {
      f.k.rho[l] = rho0 * (1 + 0.01 * l);
      for (int m = 0; m < 12; ++m) f.k.hgs[m][l] = 1e-3 * (m - 5) * (l + 1);
    }
    calc_hex_bulk_viscosity_block(f.k, c, q1, q2);
    calc_hex_stress_force_block(f.k);
    calc_hex_hourglass_force_block(f.k, type, qhg, c, G, f.dt);
    calc_hex_time_step_block(f.k, c, q1, q2);
    for (int l = 0; l < kLanes; ++l) {
      const double v = f.k.v[l], amax = f.k.amax[l], trd = f.k.trd[l];
      const double q = calc_bulk_viscosity(f.k.rho[l], c, v / amax, trd, q1, q2);
      EXPECT_TRUE(same(q, f.k.q[l])) << "lane " << l;
      double se[6] = {f.sig[l][0] - q, f.sig[l][1] - q, f.sig[l][2] - q, f.sig[l][3], f.sig[l][4], f.sig[l][5]};
      double dvdx[8], dvdy[8], dvdz[8], fx[8], fy[8], fz[8], hgs[12];
      calc_hex_volume_derivatives(f.x[l], f.y[l], f.z[l], dvdx, dvdy, dvdz);
      calc_hex_stress_force(se, dvdx, dvdy, dvdz, fx, fy, fz);
      for (int m = 0; m < 12; ++m) hgs[m] = 1e-3 * (m - 5) * (l + 1);
      HourglassInput in{type, qhg, f.k.rho[l], c, G, v, f.dt};
      HourglassExtras ex;
      const double power = calc_hex_hourglass_force(in, f.x[l], f.y[l], f.z[l], dvdx, dvdy, dvdz, f.vx[l],
                                                    f.vy[l], f.vz[l], hgs, fx, fy, fz, &ex);
      EXPECT_TRUE(same(power, f.k.de_hg[l])) << "type " << type << " lane " << l;
      EXPECT_TRUE(same(ex.old_power, f.k.hg_old[l])) << "type " << type << " lane " << l;
      EXPECT_TRUE(same(ex.dt, f.k.dt_hg[l])) << "type " << type << " lane " << l;
      if (type <= 3) {
        EXPECT_LT(ex.dt, DBL_MAX);
      }
      for (int j = 0; j < 8; ++j)
        EXPECT_TRUE(same(fx[j], f.k.fx[j][l]) && same(fy[j], f.k.fy[j][l]) && same(fz[j], f.k.fz[j][l]))
            << "type " << type << " lane " << l << " corner " << j;
      for (int m = 0; m < 12; ++m) EXPECT_TRUE(same(hgs[m], f.k.hgs[m][l]));
      EXPECT_TRUE(same(calc_hex_time_step(v, amax, c, trd, q1, q2), f.k.dt[l]));
    }
  }
}

TEST(HexBlock, StressUpdatesEqualTheScalarKernels) {
  struct Case { double beta, rate_c; bool with_back; };
  for (const Case cs : {Case{1.0, 0, false}, Case{0.0, 0, true}, Case{0.5, 0, true}, Case{1.0, 1e7, false},
                        Case{0.3, 1e7, true}}) {
    const MaterialConstants m = copper(cs.beta, cs.rate_c);
    Fixture f(20u);
    calc_hex_kinematics_block(f.k, f.dt);
    if (!cs.with_back)
      for (int l = 0; l < kLanes; ++l)
        for (int c = 0; c < 6; ++c) f.back[l][c] = f.k.back[c][l] = 0;
    const HexBlock before = f.k;
    rotate_stress_jaumann_block(f.k.sig, f.k.w, f.dt);
    if (cs.with_back) {
      rotate_stress_jaumann_block(f.k.back, f.k.w, f.dt);
      update_stress_elastic_plastic_block<true>(m, f.k, f.dt);
    } else {
      update_stress_elastic_plastic_block<false>(m, f.k, f.dt);
    }
    int yielded = 0;
    for (int l = 0; l < kLanes; ++l) {
      double d[6], w[3], sig[6], back[6];
      for (int c = 0; c < 6; ++c) { d[c] = before.d[c][l]; sig[c] = f.sig[l][c]; back[c] = f.back[l][c]; }
      for (int c = 0; c < 3; ++c) w[c] = before.w[c][l];
      double eps = before.eps_p[l];
      unsigned char y = 0;
      rotate_stress_jaumann(sig, w, f.dt);
      rotate_stress_jaumann(back, w, f.dt);
      update_stress_elastic_plastic(m, d, f.dt, sig, back, eps, y);
      yielded += y;
      for (int c = 0; c < 6; ++c) {
        EXPECT_TRUE(same(sig[c], f.k.sig[c][l])) << "beta " << cs.beta << " lane " << l << " c " << c;
        if (cs.with_back) {
          EXPECT_TRUE(same(back[c], f.k.back[c][l]));
        }
      }
      EXPECT_TRUE(same(eps, f.k.eps_p[l]));
      EXPECT_EQ(double(y), f.k.yielded[l]);
    }
    EXPECT_GT(yielded, 0) << "beta " << cs.beta << " rate " << cs.rate_c;  // both branches run
    EXPECT_LT(yielded, kLanes) << "beta " << cs.beta << " rate " << cs.rate_c;
  }
  // elastic (type 1)
  MaterialConstants e = copper(1, 0);
  e.type = 1;
  Fixture f(30u);
  calc_hex_kinematics_block(f.k, f.dt);
  update_stress_elastic_block(e, f.k.d, f.dt, f.k.sig);
  for (int l = 0; l < kLanes; ++l) {
    double d[6], sig[6];
    for (int c = 0; c < 6; ++c) { d[c] = f.k.d[c][l]; sig[c] = f.sig[l][c]; }
    update_stress_elastic(e, d, f.dt, sig);
    for (int c = 0; c < 6; ++c) EXPECT_TRUE(same(sig[c], f.k.sig[c][l]));
  }
}

TEST(HexBlock, CubeRootIsWithinOneUlpOfTheExactRoot) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> e(-30, 30), m(1, 10);
  double worst = 0;
  for (int i = 0; i < 1000000; ++i) {
    const double x = m(rng) * std::pow(10.0, e(rng));
    const double y = cbrt_positive(x);
    const double ref = double(cbrtl((long double)x));  // extended precision, rounded (glibc's cbrt is off by up to 3 ulp)
    const double ulp = std::nextafter(ref, INFINITY) - ref;
    worst = std::max(worst, std::fabs(y - ref) / ulp);
  }
  EXPECT_LE(worst, 1.0);
  EXPECT_EQ(cbrt_positive(8.0), 2.0);
  EXPECT_EQ(cbrt_positive(1e-9), 1e-3);
}

// Every deformable type of the table: its block kernel gives the bits of its scalar kernel, lane
// by lane (types 24 and 10 with a 4-point table spanning the lanes' plastic strains, with and without
// rate effects, types 24, 15 and 98 also viscoplastic, VP = 1; types 1 and 3 as above, through the table).
TEST(HexBlock, TableKernelsEqualTheirScalarKernels) {
  for (const MaterialType* t : material_types()) {
    if (t->rigid) continue;
    for (double rate_c : {0.0, 1e7, -1e7}) {
      const bool viscoplastic = rate_c < 0;
      if (viscoplastic && t->number != 24 && t->number != 15 && t->number != 98) continue;
      rate_c = std::fabs(rate_c);
      MaterialData md;
      md.type = t->number;
      set_param_defaults(md, *t);
      md.rho = 8930, md.E = 117e9, md.nu = 0.35, md.sigma_y = 3e8, md.E_tan = 1e9, md.beta = 1;
      md.rate_c = rate_c, md.rate_p = 5;
      // Johnson-Cook constants where the type has them (OFHC-copper-like, hot enough to soften)
      const std::pair<const char*, double> jc[] = {{"G", 43e9}, {"A", 9e7}, {"B", 2.9e8}, {"N", 0.31}, {"C", 0.025},
                                                   {"EPSO", 1}, {"M", 1.09}, {"TM", 1356}, {"TR", 293}, {"CP", 383},
                                                   {"D1", 0.54}, {"D2", 4.89}, {"D3", -3.03}, {"D4", 0.014}, {"D5", 1.12},
                                                   // type 107's names (its history 0 is the temperature: 0-700 K)
                                                   {"A/SIGA", 9e7}, {"B/B", 2.9e8}, {"N/BETA0", 0.31}, {"C/BETA1", 0.025},
                                                   {"M/NA", 1.09}, {"E0DOT", 1}, {"XSI", 0.9}};
      if (find_param(*t, "A") || find_param(*t, "A/SIGA"))
        for (const auto& [key, v] : jc)
          if (const MaterialParam* p = find_param(*t, key)) param_value(md, *p) = v;
      if (find_param(*t, "K")) {  // power law: the yield strain (E / K)^(1 / (N - 1)) = 4.1e-4
        param_value(md, *find_param(*t, "K")) = 5e8;
        param_value(md, *find_param(*t, "N")) = 0.3;
      }
      if (t->number == 10) param_value(md, *find_param(*t, "G")) = 43e9;  // K from its EOS in a run
      if (viscoplastic) param_value(md, *find_param(*t, "VP")) = 1;
      if (t->number == 24 || t->number == 10) {
        const double eps[4] = {0, 0.05, 0.12, 0.18}, es[4] = {3e8, 3.5e8, 3.6e8, 4.5e8};
        for (int i = 0; i < 4; ++i) {
          param_value(md, *find_param(*t, "EPS" + std::to_string(i + 1))) = eps[i];
          param_value(md, *find_param(*t, "ES" + std::to_string(i + 1))) = es[i];
        }
      }
      const MaterialConstants m = derive_constants(md, Model{});
      Fixture f(40u);
      calc_hex_kinematics_block(f.k, f.dt);
      for (int l = 0; l < kLanes; ++l)
        for (int c = 0; c < 6; ++c) f.back[l][c] = f.k.back[c][l] = 0;
      for (int l = 0; l < kLanes; ++l)
        for (int h = 0; h < kMaxHistory; ++h) f.k.hist[h][l] = 100.0 * l * (h == 0);  // temperature rises
      const HexBlock before = f.k;
      t->solid.update_block(m, f.k, f.dt);
      int yielded = 0;
      for (int l = 0; l < kLanes; ++l) {
        SolidPointState s;
        double d[6];
        for (int c = 0; c < 6; ++c) d[c] = before.d[c][l], s.sig[c] = before.sig[c][l];
        s.eps_p = before.eps_p[l];
        s.yielded = before.yielded[l];
        for (int h = 0; h < kMaxHistory; ++h) s.hist[h] = before.hist[h][l];
        for (int c = 0; c < 3; ++c) s.w[c] = before.w[c][l];
        t->solid.update_point(m, d, f.dt, s);
        for (int h = 0; h < int(t->history.size()); ++h) EXPECT_TRUE(same(s.hist[h], f.k.hist[h][l])) << "type " << t->number << " h " << h;
        for (int c = 0; c < 6; ++c) EXPECT_TRUE(same(s.sig[c], f.k.sig[c][l])) << "type " << t->number << " lane " << l << " c " << c << " " << s.sig[c] << " " << f.k.sig[c][l];
        if (t->solid.plastic_strain) {
          EXPECT_TRUE(same(s.eps_p, f.k.eps_p[l])) << "type " << t->number << " lane " << l;
          EXPECT_EQ(s.yielded, f.k.yielded[l]);
          for (int h = 0; h < int(t->history.size()); ++h) EXPECT_TRUE(same(s.hist[h], f.k.hist[h][l])) << "type " << t->number;
          yielded += s.yielded != 0;
        }
      }
      if (t->solid.plastic_strain) {
        EXPECT_GT(yielded, 0) << "type " << t->number;  // both branches run
        EXPECT_LT(yielded, kLanes) << "type " << t->number;
      }
    }
  }
}
