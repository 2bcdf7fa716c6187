// Micro-benchmarks of the element kernels and the whole cycle on the seed's Taylor bar.
//   build/bench/impact3d_bench [--benchmark_filter=REGEX]
// Numbers go in README.md ("Performance") with the machine and the command.

#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "common/messages.h"
#include "impact3d/element/hex_block.h"
#include "impact3d/element/hexahedron.h"
#include "impact3d/material/material_block.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/element_processing.h"
#include "impact3d/solve/engine.h"
#include "impact3d/element/shell_bt.h"
#include "tests/solve/beam_models.h"
#include "tests/solve/shell_models.h"

using namespace impact3d;

namespace {

const Model& taylor_model() {
  static Model m;
  static bool loaded = false;
  if (!loaded) {
    Diagnostics d;
    if (!read_and_check_deck(IMPACT3D_SOURCE_DIR "/decks/taylor_bar.dyn", m, d))
      throw std::runtime_error("cannot read the Taylor bar deck");
    loaded = true;
  }
  return m;
}

void distorted_hex(double x[8], double y[8], double z[8]) {
  const double X[8] = {0, 1, 1, 0, 0, 1, 1, 0}, Y[8] = {0, 0, 1, 1, 0, 0, 1, 1},
               Z[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  for (int j = 0; j < 8; ++j) {
    x[j] = X[j] + 0.05 * Y[j] * Z[j];
    y[j] = Y[j] + 0.03 * X[j];
    z[j] = Z[j] * (1 + 0.02 * X[j]);
  }
}

void BM_CalcHexVolumeDerivatives(benchmark::State& st) {
  double x[8], y[8], z[8], dx[8], dy[8], dz[8];
  distorted_hex(x, y, z);
  for (auto _ : st) {
    benchmark::DoNotOptimize(calc_hex_volume_derivatives(x, y, z, dx, dy, dz));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CalcHexVolumeDerivatives);

void BM_CalcHexHourglassForce(benchmark::State& st) {
  double x[8], y[8], z[8], dx[8], dy[8], dz[8], vx[8], vy[8], vz[8], fx[8] = {}, fy[8] = {},
      fz[8] = {}, hgs[12] = {};
  distorted_hex(x, y, z);
  double v = calc_hex_volume_derivatives(x, y, z, dx, dy, dz);
  for (int j = 0; j < 8; ++j) { vx[j] = 0.1 * j; vy[j] = 0.01 * j * j; vz[j] = -0.2 * (j % 3); }
  HourglassInput in{int(st.range(0)), 0.1, 8930, 4500, 4.3e10, v, 1e-8};
  for (auto _ : st) {
    benchmark::DoNotOptimize(
        calc_hex_hourglass_force(in, x, y, z, dx, dy, dz, vx, vy, vz, hgs, fx, fy, fz));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CalcHexHourglassForce)->Arg(1)->Arg(3)->Arg(5);

void BM_UpdateStressElasticPlastic(benchmark::State& st) {
  MaterialConstants m;
  m.type = 3; m.rho = 8930; m.E = 117e9; m.nu = 0.35; m.sigma_y = 4e8; m.E_tan = 1e8; m.beta = 1;
  derive_material_constants(m);
  double d[6] = {-1e3, 4e2, 5e2, 1e2, 0, -3e1}, w[3] = {10, 0, 5};
  double sig[6] = {}, back[6] = {}, eps = 0;
  unsigned char y = 0;
  for (auto _ : st) {
    rotate_stress_jaumann(sig, w, 1e-8);
    benchmark::DoNotOptimize(update_stress_elastic_plastic(m, d, 1e-8, sig, back, eps, y));
  }
}
BENCHMARK(BM_UpdateStressElasticPlastic);

// The block kernels on one block of 8 distorted elements held in L1 (no gather, no store):
// the element pass's arithmetic alone.  Items = elements.
void BM_HexBlockKernels(benchmark::State& st) {
  HexBlock k;
  double x[8], y[8], z[8];
  distorted_hex(x, y, z);
  for (int l = 0; l < kLanes; ++l)
    for (int j = 0; j < 8; ++j) {
      k.x[j][l] = 1e-3 * x[j] * (1 + 0.01 * l); k.y[j][l] = 1e-3 * y[j]; k.z[j][l] = 1e-3 * z[j];
      k.vx[j][l] = 0.1 * j; k.vy[j][l] = 0.01 * j * j; k.vz[j][l] = -0.2 * (j % 3) - 200;
    }
  MaterialConstants m;
  m.type = 3; m.rho = 8930; m.E = 117e9; m.nu = 0.35; m.sigma_y = 4e8; m.E_tan = 1e8; m.beta = 1;
  derive_material_constants(m);
  for (int l = 0; l < kLanes; ++l) {
    for (int c = 0; c < 6; ++c) k.sig[c][l] = 1e8 * (c + 1);
    k.eps_p[l] = 0.1; k.yielded[l] = 0; k.q_old[l] = 0; k.rho[l] = 1e-9;
  }
  const int hg = int(st.range(0));
  for (auto _ : st) {
    calc_hex_kinematics_block(k, 1e-8);
    rotate_stress_jaumann_block(k.sig, k.w, 1e-8);
    update_stress_elastic_plastic_block<false>(m, k, 1e-8);
    IMPACT3D_FOR_LANES k.rho[l] = m.rho * 1e-9 / k.v[l];
    calc_hex_bulk_viscosity_block(k, m.c, 1.5, 0.06);
    calc_hex_stress_force_block(k);
    calc_hex_hourglass_force_block(k, hg, 0.1, m.c, m.G, 1e-8);
    calc_hex_time_step_block(k, m.c, 1.5, 0.06);
    benchmark::DoNotOptimize(k);
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(st.iterations() * kLanes);
}
BENCHMARK(BM_HexBlockKernels)->Arg(1)->Arg(3)->Arg(5);

// The whole element pass (kinematics, stress, forces, hourglass, time step) over the Taylor bar
// after 2000 cycles (plastic, deformed).  Items = elements.
void BM_CalcForcesForElems_TaylorBar(benchmark::State& st) {
  omp_set_num_threads(int(st.range(0)));
  Engine eng(taylor_model());
  eng.initialize();
  for (int c = 0; c < 2000; ++c) eng.step();
  State saved = eng.state();
  for (auto _ : st) {
    st.PauseTiming();
    eng.state() = saved;
    st.ResumeTiming();
    benchmark::DoNotOptimize(calc_forces_for_elems(eng.model(), eng.state()));
  }
  st.SetItemsProcessed(st.iterations() * eng.state().ne);
}
BENCHMARK(BM_CalcForcesForElems_TaylorBar)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// A full cycle (nodal update, wall, element pass).  Items = element-cycles.
void BM_Cycle_TaylorBar(benchmark::State& st) {
  omp_set_num_threads(int(st.range(0)));
  Engine eng(taylor_model());
  eng.initialize();
  const State initial = eng.state();
  for (auto _ : st) {
    if (eng.step() != StepStatus::ok) {
      st.PauseTiming();
      eng.state() = initial;
      st.ResumeTiming();
    }
  }
  st.SetItemsProcessed(st.iterations() * eng.state().ne);
}
BENCHMARK(BM_Cycle_TaylorBar)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// The whole Taylor bar run to 80 us (no output files).
void BM_TaylorBarWholeRun(benchmark::State& st) {
  omp_set_num_threads(int(st.range(0)));
  for (auto _ : st) {
    Engine eng(taylor_model());
    benchmark::DoNotOptimize(eng.run_to_end());
    st.counters["cycles"] = eng.state().cycle;
  }
}
BENCHMARK(BM_TaylorBarWholeRun)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1);

// Plastic shells, NIP 5, yielding every cycle (the yield stress 1 kPa): type 3 plastic-kinematic
// (beta 0.5), 24 piecewise-linear (a 4-point table from 1 kPa).
MaterialData plastic_plate_material(int type) {
  MaterialData md = shell_test::steel_shell(type, 5);
  if (type == 24) {
    const MaterialType& t = material_type(24);
    set_param_defaults(md, t);  // (blanks E, nu, rho: set again below)
    const MaterialData steel = shell_test::steel_shell(type, 5);
    md.rho = steel.rho;
    md.E = steel.E;
    md.nu = steel.nu;
    const double eps[4] = {0, 0.01, 0.05, 0.2}, es[4] = {1e3, 3e8, 3.8e8, 4.2e8};
    for (int i = 0; i < 4; ++i) {
      param_value(md, *find_param(t, "EPS" + std::to_string(i + 1))) = eps[i];
      param_value(md, *find_param(t, "ES" + std::to_string(i + 1))) = es[i];
    }
  }
  md.sigma_y = 1e3;
  md.beta = 0.5;
  return md;
}

// Belytschko-Tsay shells: one shell through the scalar kernel (elastic NIP 2; plastic NIP 5,
// yielding: type 3, and type 24 with a 4-point table), and a whole cycle of a 100 x 100 plate
// (clamped edge, transverse velocity).
void BM_ShellBTKernel(benchmark::State& st) {
  const bool table = st.range(0) == 24;
  const bool plastic = st.range(0) == 3 || table;
  MaterialData md = shell_test::steel_shell(plastic ? 3 : 1, plastic ? 5 : 2);
  MaterialConstants mc;
  mc.type = md.type;
  mc.rho = md.rho;
  mc.E = md.E;
  mc.nu = md.nu;
  mc.sigma_y = plastic ? 1e3 : md.sigma_y;  // yields every cycle
  mc.E_tan = md.E_tan;
  mc.beta = 0.5;
  derive_material_constants(mc);
  if (table) mc = derive_constants(plastic_plate_material(24), Model{});  // the table starts at 1 kPa
  ShellGroupConstants g;
  g.nip = md.shell_section.nip;
  gauss_legendre_rule(g.nip, g.zeta, g.weight);
  g.shrf = 5.0 / 6.0;
  g.rho = mc.rho;
  g.E = mc.E;
  g.nu = mc.nu;
  g.G = mc.G;
  g.c_plate = 5400;
  double sig[50] = {}, back[60] = {}, eps[10] = {};
  unsigned char yielded[10] = {};
  ShellPointState ps{sig, plastic && !table ? back : nullptr, plastic ? eps : nullptr, plastic ? yielded : nullptr, nullptr, nullptr};
  ShellKernelIO io;
  const double X[4][3] = {{0, 0, 0}, {0.01, 0.001, 0}, {0.011, 0.01, 0.0005}, {0, 0.009, 0}};
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) {
      io.x[i][a] = X[i][a];
      io.v[i][a] = 0.1 * (i + 1) * (a == 2 ? 1 : 0.3 * (i % 2 ? 1 : -1));
      io.w[i][a] = 0.5 * (a == 1 ? i : -i);
    }
  io.h = 0.001;
  io.dt = 1e-7;
  const ShellMaterialKind kind = table ? ShellMaterialKind::piecewise_linear
                                 : plastic ? ShellMaterialKind::plastic_kinematic
                                           : ShellMaterialKind::elastic;
  for (auto _ : st) {
    calc_shell_bt_forces(g, mc, kind, io, ps);
    benchmark::DoNotOptimize(io.f[0][0]);
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_ShellBTKernel)->Arg(1)->Arg(3)->Arg(24);

void BM_Cycle_ShellPlate(benchmark::State& st) {
  omp_set_num_threads(1);
  const int n = 100;
  static Model m = [] {
    Model p = shell_test::make_plate(n, n, 1.0, 1.0, 0.01, shell_test::steel_shell(1, 2), 1.0);
    for (int j = 0; j <= n; ++j) {
      p.bc[std::size_t(shell_test::plate_node(n, 0, j))] = 7;
    }
    p.init_velocities.push_back({0, 0, 1, {0, 0, 1.0}});
    return p;
  }();
  Engine eng(m);
  eng.initialize();
  for (auto _ : st) benchmark::DoNotOptimize(eng.step());
  st.SetItemsProcessed(st.iterations() * eng.state().shells.ns);
}
BENCHMARK(BM_Cycle_ShellPlate)->Unit(benchmark::kMicrosecond);

// The plate above, plastic (plastic_plate_material: Arg 3 or 24), NIP 5, the nodes starting
// with a stretching, bending and twisting velocity field: every point yields every cycle.
// Items: shell-cycles.
void BM_Cycle_ShellPlatePlastic(benchmark::State& st) {
  omp_set_num_threads(1);
  const int n = 100;
  Model m = shell_test::make_plate(n, n, 1.0, 1.0, 0.01, plastic_plate_material(int(st.range(0))), 1.0);
  for (int j = 0; j <= n; ++j) m.bc[std::size_t(shell_test::plate_node(n, 0, j))] = 7;
  for (int i = 0; i < m.num_nodes(); ++i) {  // stretching, bending and twisting everywhere
    const std::size_t I = std::size_t(i);
    m.init_velocities.push_back({i + 1, i + 1, 1, {100 * (m.x[I] - 0.5), 100 * (m.y[I] - 0.5), 10 * m.x[I] * m.y[I]}});
  }
  Engine eng(m);
  eng.initialize();
  for (auto _ : st) benchmark::DoNotOptimize(eng.step());
  st.SetItemsProcessed(st.iterations() * eng.state().shells.ns);
  const auto& e = eng.state().shells.eps_p;
  st.counters["yielded"] = double(std::count_if(e.begin(), e.end(), [](double v) { return v > 0; })) / double(e.size());
}
BENCHMARK(BM_Cycle_ShellPlatePlastic)->Arg(3)->Arg(24)->Unit(benchmark::kMicrosecond);

// Beams: one whole cycle of a clamped line of 10,000 Hughes-Liu beams (50 mm square steel,
// swinging), one thread; Arg: the quadrature rule QR (2: 2x2 Gauss, 3: 3x3) x 10 + material type
// (1 elastic, 3 plastic-kinematic, yielding).  Items: beam-cycles.
void BM_Cycle_BeamLine(benchmark::State& st) {
  omp_set_num_threads(1);
  const int qr = int(st.range(0)) / 10, type = int(st.range(0)) % 10;
  const int n = 10000;
  Model m = beam_test::make_beam_line(n, 100.0, beam_test::steel_beam(type, 0.05, 0.05, qr), 1.0);
  beam_test::clamp_node(m, 0);
  for (int i = 0; i <= n; ++i) {
    InitialVelocity iv;
    iv.first = iv.last = i + 1;
    iv.v = {0, 0, 100.0 * std::sin(0.05 * i)};
    m.init_velocities.push_back(iv);
  }
  Engine eng(m);
  eng.initialize();
  for (int c = 0; c < 20; ++c) eng.step();  // (the plastic line yields from the first cycles)
  for (auto _ : st) benchmark::DoNotOptimize(eng.step());
  st.SetItemsProcessed(st.iterations() * eng.state().beams.nb);
}
BENCHMARK(BM_Cycle_BeamLine)->Arg(21)->Arg(31)->Arg(23)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
