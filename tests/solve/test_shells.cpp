// Physics verification of the Belytschko-Tsay shells against closed forms: the membrane wave
// speed of a laterally constrained strip, a rigid-body rotation that must leave no strain, the
// membrane patch test on distorted quadrilaterals, and the first bending frequency of a
// clamped strip against Euler-Bernoulli.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <algorithm>

#include "impact3d/element/shell_bt.h"
#include "impact3d/material/plane_stress.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/shell_processing.h"
#include "tests/solve/shell_models.h"
#include "tests/support/threaded_run.h"

using namespace impact3d;
using namespace shell_test;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

// The Gauss rule integrates polynomials of degree 2n - 1 exactly on [-1, 1].
TEST(ShellGauss, RulesIntegrateTheirDegreeExactly) {
  for (int n = 1; n <= 10; ++n) {
    double z[10], w[10];
    gauss_legendre_rule(n, z, w);
    for (int p = 0; p <= 2 * n - 1; ++p) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += w[i] * std::pow(z[i], p);
      const double exact = p % 2 ? 0.0 : 2.0 / (p + 1);
      EXPECT_NEAR(sum, exact, 1e-14) << "n " << n << " degree " << p;
    }
    for (int i = 1; i < n; ++i) EXPECT_LT(z[i - 1], z[i]);  // bottom to top
  }
}

// Plane-stress updates: elastic closed form; plastic-kinematic equibiaxial stretch ends on the
// yield surface with sigma_zz = 0 (the secant iterations), and isotropic hardening sigma =
// sigma_y + E_p eps_p.
TEST(ShellPlaneStress, ElasticAndEquibiaxialPlastic) {
  MaterialConstants mc;
  mc.type = 3;
  mc.rho = 7850;
  mc.E = 210e9;
  mc.nu = 0.3;
  mc.sigma_y = 250e6;
  mc.E_tan = 2e9;
  mc.beta = 1;
  derive_material_constants(mc);
  double sig[5] = {0, 0, 0, 0, 0};
  const double d[5] = {1.0, 0.5, 0.2, 0.1, -0.1};
  const double dzz = update_plane_stress_elastic(mc, d, 1e-5, sig);
  const double c = mc.E / (1 - mc.nu * mc.nu) * 1e-5;
  EXPECT_NEAR(sig[0], c * (1.0 + 0.3 * 0.5), 1e-9 * std::fabs(sig[0]));
  EXPECT_NEAR(sig[1], c * (0.5 + 0.3 * 1.0), 1e-9 * std::fabs(sig[1]));
  EXPECT_NEAR(sig[2], 2 * mc.G * 0.2e-5, 1e-9 * std::fabs(sig[2]));
  EXPECT_NEAR(dzz, -0.3 / 0.7 * 1.5, 1e-14);
  // equibiaxial stretch in 200 steps to 1 % strain
  double s[5] = {0, 0, 0, 0, 0}, back[6] = {0, 0, 0, 0, 0, 0}, eps = 0;
  unsigned char y = 0;
  PlaneStressPlastic h{back, &eps, &y};
  for (int k = 0; k < 200; ++k) {
    const double de[5] = {1.0, 1.0, 0, 0, 0};
    update_plane_stress_plastic_kinematic(mc, de, 0.01 / 200, s, h);
  }
  EXPECT_TRUE(y);
  EXPECT_GT(eps, 0.005);
  // von Mises of (s, s, 0) is s: on the hardened surface (tolerance: the iteration's 1e-10)
  const double vm = calc_von_mises(std::array<double, 6>{s[0], s[1], 0, s[2], s[3], s[4]}.data());
  EXPECT_NEAR(vm, mc.sigma_y + mc.E_p * eps, 1e-8 * vm);
  EXPECT_NEAR(s[0], s[1], 1e-8 * s[0]);
}

// Membrane wave: a strip along x of 200 shells, its nodes held in y (lateral strain zero, so
// the plane-stress modulus E / (1 - nu^2) carries the wave: c = sqrt(E / (rho (1 - nu^2)))),
// all nodes at vx = 1 m/s, the end x = L held.  The compression wave's half-amplitude point
// passes two stations; their distance over the time between is the wave speed (the two-station
// difference removes the start-up; tolerance 1 %: the front's smearing over a few elements of
// 5 mm moves both stations alike).
TEST(ShellWaves, MembraneWaveSpeedAlongAStrip) {
  const int nx = 200;
  const double L = 1.0, v0 = 1.0;
  MaterialData mat = steel_shell();
  const double c = std::sqrt(mat.E / (mat.rho * (1 - mat.nu * mat.nu)));
  Model m = make_plate(nx, 1, L, 0.005, 0.001, mat, 0.8 * L / c);
  for (int i = 0; i < m.num_nodes(); ++i) m.bc[std::size_t(i)] = 2;  // y fixed
  m.bc[std::size_t(plate_node(nx, nx, 0))] = 4;  // x and y fixed at x = L
  m.bc[std::size_t(plate_node(nx, nx, 1))] = 4;
  m.init_velocities.push_back({0, 0, 1, {v0, 0, 0}});
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const int s1 = plate_node(nx, 3 * nx / 4, 0), s2 = plate_node(nx, nx / 4, 0);
  double t1 = -1, t2 = -1, p1 = v0, p2 = v0, tp = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double a = s.vx[std::size_t(s1)], b = s.vx[std::size_t(s2)];
    if (t1 < 0 && a <= 0.5 * v0) t1 = tp + (s.time - tp) * (0.5 * v0 - p1) / (a - p1);
    if (t2 < 0 && b <= 0.5 * v0) t2 = tp + (s.time - tp) * (0.5 * v0 - p2) / (b - p2);
    p1 = a;
    p2 = b;
    tp = s.time;
  }
  ASSERT_EQ(st, StepStatus::finished);
  ASSERT_GT(t1, 0);
  ASSERT_GT(t2, t1);
  const double measured = 0.5 * L / (t2 - t1);
  std::printf("membrane wave speed: measured %.2f m/s, closed form %.2f m/s (%.3f %%)\n", measured, c,
              100 * (measured / c - 1));
  EXPECT_NEAR(measured, c, 0.01 * c);
  // stress behind the front: rho c v0 (plane-stress sigma_xx, middle shell, after the wave passed)
  const State& s = eng.state();
  const ShellState& sh = s.shells;
  const int k = nx / 2;
  const double sxx = sh.sig[shell_sig_at(sh, k, 0, 0)];
  EXPECT_NEAR(-sxx, mat.rho * c * v0, 0.03 * mat.rho * c * v0);
  // energy: kinetic + internal + hourglass conserved (the held end does no work)
  EXPECT_NEAR(s.energy_ratio(), 1.0, 0.01);
}

// Rigid-body rotation: a 1 m plate (4 x 4 shells, 10 mm) spinning at 10 rad/s about the y axis
// through its centre (an out-of-plane rotation: the frame, the rotations and the transverse
// shear all take part) turns by 90 degrees.  The strain must stay at the level of the real
// centrifugal stress rho omega^2 R^2 ~ 2e5 Pa, not of the rotation (a frame error of 90 degrees
// would give stresses of order E); energy is conserved; the plate ends standing vertical.
TEST(ShellRigidMotion, RotationByNinetyDegreesLeavesNoStrain) {
  const int n = 4;
  const double L = 1.0, w = 10.0;
  MaterialData mat = steel_shell();
  const double t_end = 0.5 * kPi / w;
  Model m = make_plate(n, n, L, L, 0.01, mat, t_end);
  m.init_omega.assign(std::size_t(m.num_nodes()), {0, w, 0});
  for (int i = 0; i < m.num_nodes(); ++i) {
    InitialVelocity iv;
    iv.first = iv.last = i + 1;
    const double rx = m.x[std::size_t(i)] - 0.5 * L;
    iv.v = {0, 0, -w * rx};  // omega e_y x r = -w rx e_z
    m.init_velocities.push_back(iv);
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  double smax = 0;
  for (double v : s.shells.sig) smax = std::max(smax, std::fabs(v));
  std::printf("rigid rotation by 90 degrees: largest stress %.3e Pa (E = %.3e), energy ratio %.6f\n", smax,
              mat.E, s.energy_ratio());
  EXPECT_LT(smax, 2e6);  // strain < 1e-5
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-3);
  // the node at (L, y) is now at x = L/2, z = -L/2 (rotation about +y takes +x to -z)
  const std::size_t corner = std::size_t(plate_node(n, n, 0));
  EXPECT_NEAR(s.x[corner], 0.5 * L, 2e-3 * L);
  EXPECT_NEAR(s.z[corner], -0.5 * L, 2e-3 * L);
}

// Membrane patch test: a patch of 4 distorted quadrilaterals (inner node off centre) under the
// velocity field of a uniform strain rate must give every shell the same, exact stress, and
// the inner node no net force (to round-off).
TEST(ShellPatch, UniformStrainRateOnDistortedMesh) {
  MaterialData mat = steel_shell();
  mat.hourglass_coef = 0.1;
  Model m = make_plate(2, 2, 1.0, 1.0, 0.01, mat, 1.0);
  const std::size_t inner = std::size_t(plate_node(2, 1, 1));
  m.x[inner] = 0.62;
  m.y[inner] = 0.41;
  m.x[std::size_t(plate_node(2, 1, 0))] = 0.45;
  m.y[std::size_t(plate_node(2, 2, 1))] = 0.57;
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  State& s = eng.state();
  const double dxx = 2.0, dyy = -0.7, gxy = 1.3;  // engineering shear rate 2 d_xy
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    // v = D x with the shear split symmetrically: no spin
    s.vx[k] = dxx * s.x[k] + 0.5 * gxy * s.y[k];
    s.vy[k] = 0.5 * gxy * s.x[k] + dyy * s.y[k];
    s.vz[k] = 0;
  }
  const double dt = 1e-7;
  s.dt_half = dt;
  // positions at t^n = x^{n-1/2} + dt/2 v: the midpoint geometry is the mesh above
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    s.x[k] += 0.5 * dt * s.vx[k];
    s.y[k] += 0.5 * dt * s.vy[k];
  }
  std::fill(s.shells.sig.begin(), s.shells.sig.end(), 0.0);
  calc_forces_for_shells(m, s);
  MaterialConstants mc = s.mats[0];
  const double c = mc.E / (1 - mc.nu * mc.nu) * dt;
  const double sxx = c * (dxx + mc.nu * dyy), syy = c * (dyy + mc.nu * dxx), sxy = mc.G * gxy * dt;
  for (int k = 0; k < s.shells.ns; ++k)
    for (int p = 0; p < s.shells.nip[std::size_t(k)]; ++p) {
      double q[5];
      for (int c = 0; c < 5; ++c) q[c] = s.shells.sig[shell_sig_at(s.shells, k, p, c)];
      // the local frame of each shell is along its edge 1-2: compare invariants
      const double tr = q[0] + q[1], det = q[0] * q[1] - q[2] * q[2];
      EXPECT_NEAR(tr, sxx + syy, 1e-6 * std::fabs(sxx));
      EXPECT_NEAR(det, sxx * syy - sxy * sxy, 1e-6 * sxx * sxx);
      EXPECT_NEAR(q[3], 0.0, 1e-9 * std::fabs(sxx));
      EXPECT_NEAR(q[4], 0.0, 1e-9 * std::fabs(sxx));
    }
  double f[3] = {0, 0, 0}, fmax = 0;
  for (int c2 = s.corner_start[inner]; c2 < s.corner_start[inner + 1]; ++c2) {
    const std::size_t q = std::size_t(s.corner_list[std::size_t(c2)]);
    f[0] += s.cfx[q];
    f[1] += s.cfy[q];
    f[2] += s.cfz[q];
    fmax = std::max({fmax, std::fabs(s.cfx[q]), std::fabs(s.cfy[q])});
  }
  EXPECT_GT(fmax, 0);
  EXPECT_LT(std::fabs(f[0]) + std::fabs(f[1]) + std::fabs(f[2]), 1e-6 * fmax);
}

// Clamped strip (cantilever) L = 0.5 m, 20 mm wide, 10 mm thick, 40 x 1 shells, steel: first
// bending frequency against Euler-Bernoulli f1 = (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)),
// I = b h^3 / 12 (free edges: beam, not plate, stiffness).  Started with the first mode's
// velocity shape; the period from the zero crossings of the tip deflection.  Tolerance 3 %:
// the one-point shell with 40 elements along, the scaled rotary inertia and the transverse
// shear (L/h = 50) each shift f1 by well under 1 %.
TEST(ShellBending, CantileverFirstFrequencyMatchesEulerBernoulli) {
  const int nx = 40;
  const double L = 0.5, b = 0.02, h = 0.01, v0 = 0.01;
  MaterialData mat = steel_shell(1, 3);
  const double bl = 1.87510407;
  const double f_eb = bl * bl / (2 * kPi) * std::sqrt(mat.E * h * h / (12 * mat.rho)) / (L * L);
  Model m = make_plate(nx, 1, L, b, h, mat, 2.3 / f_eb);
  const double sg = (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl));
  auto phi = [&](double x) {
    const double u = bl * x / L;
    return std::cosh(u) - std::cos(u) - sg * (std::sinh(u) - std::sin(u));
  };
  auto dphi = [&](double x) {
    const double u = bl * x / L;
    return bl / L * (std::sinh(u) + std::sin(u) - sg * (std::cosh(u) - std::cos(u)));
  };
  const double tip_shape = phi(L);
  m.init_omega.assign(std::size_t(m.num_nodes()), {0, 0, 0});
  m.rot_bc.assign(std::size_t(m.num_nodes()), 0);
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double x = m.x[std::size_t(i)];
    InitialVelocity iv;
    iv.first = iv.last = i + 1;
    iv.v = {0, 0, v0 * phi(x) / tip_shape};
    m.init_velocities.push_back(iv);
    m.init_omega[std::size_t(i)] = {0, -v0 * dphi(x) / tip_shape, 0};  // theta_y = -dw/dx
    if (x == 0) {
      m.bc[std::size_t(i)] = 7;
      m.rot_bc[std::size_t(i)] = 7;
    }
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  const std::size_t tip = std::size_t(plate_node(nx, nx, 0));
  std::vector<double> crossings;
  double zp = 0, tp = 0;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = eng.step();
    const State& s = eng.state();
    const double z = s.z[tip];
    if (s.cycle > 1 && ((zp > 0 && z <= 0) || (zp < 0 && z >= 0)))
      crossings.push_back(tp + (s.time - tp) * zp / (zp - z));
    zp = z;
    tp = s.time;
  }
  ASSERT_EQ(st, StepStatus::finished);
  ASSERT_GE(crossings.size(), 4u);
  const double period = 2 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  const double f = 1 / period;
  std::printf("cantilever strip: first frequency %.3f Hz, Euler-Bernoulli %.3f Hz (%.3f %%)\n", f, f_eb,
              100 * (f / f_eb - 1));
  EXPECT_NEAR(f, f_eb, 0.03 * f_eb);
  EXPECT_NEAR(eng.state().energy_ratio(), 1.0, 0.01);
}

// Threads: a 70 x 70 plate (4900 shells, past the threshold where the shell pass runs on
// several threads) gives the same bits on one and on two threads.
TEST(ShellThreads, SameBitsForAnyThreadCount) {
  const int n = 70;
  MaterialData mat = steel_shell(3, 3);
  mat.sigma_y = 20e6;  // yields: the plane-stress iterations run too
  Model m = make_plate(n, n, 1.0, 1.0, 0.002, mat, 1.0);
  for (int j = 0; j <= n; ++j) m.bc[std::size_t(plate_node(n, 0, j))] = 7;
  for (int i = 0; i < m.num_nodes(); ++i) {
    InitialVelocity iv;
    iv.first = iv.last = i + 1;
    iv.v = {5.0 * m.x[std::size_t(i)], 0, 5.0 * m.x[std::size_t(i)] * (1 + m.y[std::size_t(i)])};
    m.init_velocities.push_back(iv);
  }
  const State a = test_support::run_cycles_on_threads(m, 1, 60), b = test_support::run_cycles_on_threads(m, 2, 60);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.shells.sig, b.shells.sig);
  EXPECT_EQ(a.shells.wy, b.shells.wy);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_EQ(a.kinetic, b.kinetic);
  EXPECT_GT(*std::max_element(a.shells.eps_p.begin(), a.shells.eps_p.end()), 0.0);
}

// Triangles (n3 == n4): a patch of 8 triangles under a uniform strain rate gives every triangle
// the exact plane-stress stress, and the inner node no net force; mass 1/3 per node.
TEST(ShellPatch, TrianglesUnderUniformStrainRate) {
  MaterialData mat = steel_shell();
  Model m = make_plate(2, 2, 1.0, 1.0, 0.01, mat, 1.0);
  m.x[std::size_t(plate_node(2, 1, 1))] = 0.58;
  m.y[std::size_t(plate_node(2, 1, 1))] = 0.44;
  std::vector<std::array<int, 4>> tri;
  for (const auto& q : m.shell_nodes) {
    tri.push_back({q[0], q[1], q[2], q[2]});
    tri.push_back({q[0], q[2], q[3], q[3]});
  }
  m.shell_nodes = tri;
  m.shell_material.assign(tri.size(), 0);
  m.shell_thickness.assign(tri.size(), {0.01, 0.01, 0.01, 0.01});
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  State& s = eng.state();
  double mass = 0;
  for (double v : s.mass) mass += v;
  EXPECT_NEAR(mass, mat.rho * 0.01 * 1.0, 1e-12 * mass);
  const double dxx = -1.0, dyy = 0.4, gxy = 0.9, dt = 1e-7;
  for (int i = 0; i < s.nn; ++i) {
    const std::size_t k = std::size_t(i);
    s.vx[k] = dxx * s.x[k] + 0.5 * gxy * s.y[k];
    s.vy[k] = 0.5 * gxy * s.x[k] + dyy * s.y[k];
    s.x[k] += 0.5 * dt * s.vx[k];
    s.y[k] += 0.5 * dt * s.vy[k];
  }
  s.dt_half = dt;
  calc_forces_for_shells(m, s);
  const MaterialConstants& mc = s.mats[0];
  const double c = mc.E / (1 - mc.nu * mc.nu) * dt;
  const double sxx = c * (dxx + mc.nu * dyy), syy = c * (dyy + mc.nu * dxx), sxy = mc.G * gxy * dt;
  for (int k = 0; k < s.shells.ns; ++k) {
    double q[3];
    for (int c = 0; c < 3; ++c) q[c] = s.shells.sig[shell_sig_at(s.shells, k, 0, c)];
    EXPECT_NEAR(q[0] + q[1], sxx + syy, 1e-6 * std::fabs(sxx));
    EXPECT_NEAR(q[0] * q[1] - q[2] * q[2], sxx * syy - sxy * sxy, 1e-6 * sxx * sxx);
  }
  const std::size_t inner = std::size_t(plate_node(2, 1, 1));
  double f[3] = {0, 0, 0}, fmax = 0;
  for (int c2 = s.corner_start[inner]; c2 < s.corner_start[inner + 1]; ++c2) {
    const std::size_t q = std::size_t(s.corner_list[std::size_t(c2)]);
    f[0] += s.cfx[q];
    f[1] += s.cfy[q];
    f[2] += s.cfz[q];
    fmax = std::max({fmax, std::fabs(s.cfx[q]), std::fabs(s.cfy[q])});
  }
  EXPECT_LT(std::fabs(f[0]) + std::fabs(f[1]) + std::fabs(f[2]), 1e-6 * fmax);
}

// Hourglass control: a free plate started in the out-of-plane hourglass pattern vz = +-v
// (checkerboard of nodes, a zero-energy mode of one-point shells) keeps its kinetic energy
// without control (QM = 0: the mode is free), loses it to the viscous form (IHQ 1), and
// stores it in the stiffness form (IHQ 4: bounded, the energy balance holds).
TEST(ShellHourglass, OutOfPlaneModeIsResisted) {
  auto run = [](int ihq, double qm) {
    MaterialData mat = steel_shell();
    mat.hourglass_type = ihq;
    mat.hourglass_coef = qm;
    const int n = 8;
    Model m = make_plate(n, n, 0.4, 0.4, 0.01, mat, 2e-4);
    for (int i = 0; i < m.num_nodes(); ++i) {
      const int a = i % (n + 1), b = i / (n + 1);
      InitialVelocity iv;
      iv.first = iv.last = i + 1;
      iv.v = {0, 0, (a + b) % 2 ? 1.0 : -1.0};
      m.init_velocities.push_back(iv);
    }
    Engine eng(m);
    EXPECT_EQ(eng.initialize(), StepStatus::ok);
    const double ke0 = eng.state().kinetic;
    StepStatus st = StepStatus::ok;
    while (st == StepStatus::ok) st = eng.step();
    EXPECT_EQ(st, StepStatus::finished);
    const State& s = eng.state();
    return std::array<double, 3>{s.kinetic / ke0, s.hourglass / ke0, s.energy_ratio()};
  };
  const auto free = run(1, 0.0), viscous = run(1, 0.1), stiff = run(4, 0.1);
  std::printf("hourglass mode: KE/KE0 free %.4f, viscous %.4f, stiffness %.4f (hourglass energy %.4f)\n", free[0],
              viscous[0], stiff[0], stiff[1]);
  EXPECT_GT(free[0], 0.99);     // nothing resists the mode
  EXPECT_LT(viscous[0], 0.5);   // damped
  EXPECT_GT(viscous[1], 0.5);   // into hourglass energy
  EXPECT_LT(stiff[0], 0.9);     // the stiffness form takes energy out of the motion...
  EXPECT_NEAR(stiff[2], 1.0, 0.02);  // ...and the books balance
}

// Rigid shells (type 20) form a rigid body: a spinning rigid plate keeps its shape and its
// energy.
TEST(ShellRigidMotion, RigidShellPlateStaysRigid) {
  MaterialData mat = steel_shell(20);
  Model m = make_plate(3, 3, 0.3, 0.3, 0.01, mat, 0.05);
  for (int i = 0; i < m.num_nodes(); ++i) {
    InitialVelocity iv;
    iv.first = iv.last = i + 1;
    const double rx = m.x[std::size_t(i)] - 0.15, ry = m.y[std::size_t(i)] - 0.15;
    iv.v = {1.0 - 20.0 * ry, 20.0 * rx, 0.5};  // translation + 20 rad/s about z
    m.init_velocities.push_back(iv);
  }
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) st = eng.step();
  ASSERT_EQ(st, StepStatus::finished);
  const State& s = eng.state();
  ASSERT_EQ(s.rigid.size(), 1u);
  const std::size_t a = std::size_t(plate_node(3, 0, 0)), b = std::size_t(plate_node(3, 3, 3));
  const double d = std::hypot(s.x[a] - s.x[b], s.y[a] - s.y[b], s.z[a] - s.z[b]);
  EXPECT_NEAR(d, 0.3 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s.energy_ratio(), 1.0, 1e-6);
  EXPECT_NEAR(s.z[a], 0.5 * 0.05, 1e-9);
}
