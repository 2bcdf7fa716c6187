// Taylor-bar convergence runs for docs/validation.md "OFHC copper with Johnson-Cook": the model of
// tests/solve/test_taylor_ofhc.cpp (the seed Taylor mesh scaled to the test's size, type 15, all
// nodes at the impact speed onto the stonewall) on any taylor_bar deck, e.g. a refined one from
// the deck generator:
//
//   impact3d_deckgen --deck taylor_bar --refine 2 > /tmp/tb2.dyn
//   build/bench/impact3d_bench_taylor_ofhc /tmp/tb2.dyn [--friction F] [--vp 0|1] [--threads T]
//                                          [--dynela]
//
// Default: OFHC copper, Johnson & Cook's constants, L0 25.4 mm, D0 7.62 mm, 190 m/s, 100 us,
// compared with the measured Lf 16.21 mm, Dm 13.56 mm.  --dynela: the code-to-code case of
// Pantale's DynELA documentation (Samples-Impacts.tex, "3D Taylor impact", DynELA against
// Abaqus/Explicit): 42CrMo4 steel, Johnson-Cook E 206.9 GPa, nu 0.3, A 806 MPa, B 614 MPa, n
// 0.168, C 0.0089, m 1.1, rho 7830, CP 460 with a Taylor-Quinney factor 0.9 (CP / 0.9 here), EPSO
// 1/s, T0 20, Tm 1540 C; L0 32.4 mm, D0 6.4 mm, 287 m/s, frictionless, 80 us; Abaqus Lf 26.55 mm,
// Df 11.22 mm, max eps_p 1.84, T 597 C.  Printed: final length, largest diameter, max plastic
// strain, the largest temperature rise, cycles and wall time.

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

int main(int argc, char** argv) {
  std::string deck;
  double friction = 0, vp = 0;
  int threads = 1;
  bool dynela = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--friction") && i + 1 < argc) {
      friction = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--vp") && i + 1 < argc) {
      vp = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--dynela")) {
      dynela = true;
    } else if (argv[i][0] != '-' && deck.empty()) {
      deck = argv[i];
    } else {
      std::fprintf(stderr, "usage: impact3d_bench_taylor_ofhc DECK [--friction F] [--vp 0|1] [--threads T] [--dynela]\n");
      return 2;
    }
  }
  if (deck.empty()) deck = std::string(IMPACT3D_SOURCE_DIR) + "/decks/taylor_bar.dyn";
  const double L0 = dynela ? 32.4e-3 : 25.4e-3, D0 = dynela ? 6.4e-3 : 7.62e-3, V = dynela ? 287.0 : 190.0;
  const double Lref = dynela ? 26.55e-3 : 0.638 * L0, Dref = dynela ? 11.22e-3 : 1.78 * D0;
  Model m;
  Diagnostics diag;
  if (!read_and_check_deck(deck, m, diag)) {
    std::fprintf(stderr, "%s: not read\n", deck.c_str());
    return 1;
  }
  omp_set_num_threads(threads);
  const double r0 = *std::max_element(m.x.begin(), m.x.end()), l0 = *std::max_element(m.z.begin(), m.z.end());
  for (std::size_t n = 0; n < m.x.size(); ++n) {
    m.x[n] *= 0.5 * D0 / r0;
    m.y[n] *= 0.5 * D0 / r0;
    m.z[n] *= L0 / l0;
  }
  for (InitialVelocity& v : m.init_velocities) v.v = {0.0, 0.0, -V};
  for (StoneWall& w : m.walls) w.friction = friction;
  MaterialData& md = m.materials[0];
  const MaterialType& t = material_type(15);
  md.type = 15;
  set_param_defaults(md, t);
  auto set = [&](const char* k, double v) { param_value(md, *find_param(t, k)) = v; };
  if (dynela) {
    md.rho = 7830, md.E = 206.9e9, md.nu = 0.3;
    set("A", 806e6), set("B", 614e6), set("N", 0.168), set("C", 0.0089), set("M", 1.1);
    set("TM", 1540), set("TR", 20), set("CP", 460 / 0.9);
  } else {
    md.rho = 8960, md.E = 124e9, md.nu = 0.34;
    set("A", 90e6), set("B", 292e6), set("N", 0.31), set("C", 0.025), set("M", 1.09);
    set("TM", 1356), set("TR", 294), set("CP", 383);
  }
  set("G", md.E / (2 * (1 + md.nu)));
  set("EPSO", 1.0);
  set("VP", vp);
  m.control.end_time = dynela ? 80e-6 : 100e-6;
  const auto t0 = std::chrono::steady_clock::now();
  Engine eng(m);
  if (eng.initialize() != StepStatus::ok) return 1;
  StepStatus st;
  while ((st = eng.step()) == StepStatus::ok) {
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const State& s = eng.state();
  const auto [zmin, zmax] = std::minmax_element(s.z.begin(), s.z.end());
  const double L = *zmax - *zmin;
  double rmax = 0, trise = 0;
  for (std::size_t n = 0; n < s.x.size(); ++n) rmax = std::max(rmax, std::hypot(s.x[n], s.y[n]));
  for (std::size_t e = 0; e < s.eps_p.size(); ++e) trise = std::max(trise, s.hist[std::size_t(s.hist_stride) * e]);
  std::printf("%s: %zu solids, friction %.2f, VP %.0f: Lf %.3f mm (%+.2f%%), Dm %.3f mm (%+.2f%%) against %s; max eps_p "
              "%.3f, max temperature rise %.1f; %d cycles, %.1f s on %d thread(s), status %d\n",
              deck.c_str(), m.hex_nodes.size(), friction, vp, L * 1e3, 100 * (L / Lref - 1), 2 * rmax * 1e3,
              100 * (2 * rmax / Dref - 1), dynela ? "Abaqus" : "the test", *std::max_element(s.eps_p.begin(), s.eps_p.end()),
              trise, s.cycle, secs, threads, int(st));
  return st == StepStatus::finished ? 0 : 1;
}
