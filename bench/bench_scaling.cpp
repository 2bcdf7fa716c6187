// Scaling benchmark: the cost of a cycle per hexahedron, phase by phase, from 10^3 to 10^6
// hexahedra on 1 and 2 threads; memory per hexahedron; the input phase's rate.
//
//   build/bench/impact3d_bench_scaling [--hex N[,N...]] [--threads T[,T...]] [--contact]
//                                      [--seconds S] [--no-input] [--shuffle]
//                                      [--reorder auto|on|off] [--ranks R[,R...]]
//
// Model: a copper bar (the Taylor bar's material: elastic-plastic, isotropic hardening,
// hourglass type 1, q1 1.2) of n x n x 4n hexahedra, 1 mm cells, at 227 m/s onto a stonewall;
// with --contact, two such bars of half the size meeting head on through a symmetric sliding
// interface (no wall).  Each size runs a few warm-up cycles, then as many cycles as fill about
// S seconds (default 2) of one thread.  --shuffle numbers the nodes and solids in a random
// order (a fixed seed), as a deck with scattered numbering would; --reorder is impact3d's
// reorder= (init/mesh_order.h, default auto), applied after it.  Printed per size and thread count:
//   elements, nodes, walls, contact: ns per hexahedron-cycle of each phase (Engine::phase_times)
//   cycle: the whole cycle, ns per hexahedron-cycle (wall clock)
//   cpu: CPU time of all threads over the same cycles, ns per hexahedron-cycle
//   output: ns per hexahedron for one plot state (d3plot, 4-byte words, to /tmp)
//   mem: resident memory per hexahedron after initialization (model + state), bytes
//   input: reading and checking the same model written as a keyword and as a fixed-format deck
//          (impact3d's input phase), seconds and MB/s
//   ranks (--ranks, a build with MPI, the bar only): the same model as a keyword deck run whole
//          by impact3d (beside this program) for the 1-thread row's cycles, as one process and
//          under `mpirun -np R` (one thread a rank): the run's elapsed time per hexahedron-cycle
//          (input, initialization and the two plot states included) and rank 0's time in the
//          cycle's messages (docs/cluster.md)
// Numbers go in README.md ("Performance") with the machine and the command.

#include <omp.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/init/mesh_order.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/parallel/comm.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/thread_policy.h"
#include "tests/support/box_mesh.h"
#include "tests/support/shuffle_mesh.h"

using namespace impact3d;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
// CPU time of the whole process (all threads), seconds: on a busy machine the single-thread
// figure is the one to trust.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Resident set (VmRSS) or its peak (VmHWM) in bytes, from /proc/self/status.
double proc_status_bytes(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return 1024.0 * std::atof(line.c_str() + std::strlen(key));
  return 0;
}

MaterialData copper() {
  MaterialData m;
  m.number = 1;
  m.type = 3;
  m.rho = 8930;
  m.E = 1.17e11;
  m.nu = 0.35;
  m.sigma_y = 4.0e8;
  m.E_tan = 1.0e8;
  m.beta = 1.0;
  m.hourglass_type = 1;
  m.hourglass_coef = 0.02;
  m.q1 = 1.2;
  m.q2 = 0.06;
  m.title = "copper";
  return m;
}

// n x n x 4n bar(s); about `hex` hexahedra in all.
Model make_model(int hex, bool contact) {
  Model m;
  m.title = contact ? "scaling benchmark: two bars head on" : "scaling benchmark: bar on a wall";
  m.materials.push_back(copper());
  const double cell = 1e-3;
  const int bars = contact ? 2 : 1;
  const int n = std::max(2, int(std::lround(std::cbrt(hex / (4.0 * bars)))));
  test_support::Box b;
  b.nx = b.ny = n;
  b.nz = 4 * n;
  b.lx = b.ly = n * cell;
  b.lz = 4 * n * cell;
  b.z0 = contact ? -b.lz - 0.5 * cell : 0.5 * cell;
  test_support::Box b1 = test_support::add_box(m, b, 0);
  InitialVelocity iv;
  iv.first = b1.first_node + 1;
  iv.last = b1.first_node + b1.num_nodes();
  iv.v = {0, 0, contact ? 227.0 : -227.0};
  m.init_velocities.push_back(iv);
  if (contact) {
    b.z0 = 0.5 * cell;
    test_support::Box b2 = test_support::add_box(m, b, 0);
    iv.first = b2.first_node + 1;
    iv.last = b2.first_node + b2.num_nodes();
    iv.v = {0, 0, -227.0};
    m.init_velocities.push_back(iv);
    SlidingInterface si;
    si.slave = b1.top();
    si.master = b2.bottom();
    si.slave_line.assign(si.slave.size(), 0);
    si.master_line.assign(si.master.size(), 0);
    m.interfaces.push_back(si);
  } else {
    StoneWall w;
    w.tail = {0, 0, 0};
    w.head = {0, 0, 1};
    m.walls.push_back(w);
  }
  m.control.nmmat = 1;
  m.control.num_walls = int(m.walls.size());
  m.control.num_interfaces = int(m.interfaces.size());
  m.control.num_init_velocity_cards = int(m.init_velocities.size());
  m.control.end_time = 1.0;  // never reached: the benchmark steps a set number of cycles
  m.control.tssf = 0.9;
  return m;
}

struct Row {
  int hex = 0, threads = 0, cycles = 0;
  PhaseTimes t;
  double cycle_s = 0, cpu_s = 0, output_s = 0, mem_per_hex = 0;
};

Row run_cycles(const Model& m, int threads, double seconds, bool first, double rss_before_model) {
  omp_set_num_threads(threads);
  Row r;
  r.hex = m.num_hexes();
  r.threads = threads;
  Engine eng(m);
  if (eng.initialize() != StepStatus::ok) throw std::runtime_error("initialization failed");
  if (first) r.mem_per_hex = (proc_status_bytes("VmRSS:") - rss_before_model) / r.hex;
  for (int c = 0; c < 5; ++c) eng.step();  // warm-up
  const PhaseTimes t0 = eng.phase_times();
  // cycles for about `seconds` at 150 ns per hex-cycle, at least 10
  const int cycles = std::max(10, int(seconds / (150e-9 * r.hex)));
  const auto start = Clock::now();
  const double cpu0 = process_cpu_seconds();
  for (int c = 0; c < cycles; ++c)
    if (eng.step() != StepStatus::ok) throw std::runtime_error("cycle failed");
  r.cycle_s = since(start);
  r.cpu_s = process_cpu_seconds() - cpu0;
  r.cycles = cycles;
  const PhaseTimes& t1 = eng.phase_times();
  r.t.elements = t1.elements - t0.elements;
  r.t.nodes = t1.nodes - t0.nodes;
  r.t.walls = t1.walls - t0.walls;
  r.t.contact = t1.contact - t0.contact;
  // one plot state (median of 3)
  const std::string dir = "/tmp/impact3d_bench_scaling";
  std::filesystem::create_directories(dir);
  PlotOutput out;
  out.open(m, dir + "/d3plot");
  std::vector<double> w;
  for (int k = 0; k < 3; ++k) {
    const auto t = Clock::now();
    out.write(m, eng.state(), eng.interface_forces());
    w.push_back(since(t));
  }
  std::sort(w.begin(), w.end());
  r.output_s = w[1];
  std::filesystem::remove_all(dir);
  return r;
}

void print_row(const Row& r) {
  const double per = 1e9 / (double(r.hex) * r.cycles);
  std::printf("%9d %3d %7d %9.1f %7.1f %7.1f %8.1f %8.1f %8.1f %9.1f %8.0f\n", r.hex, r.threads, r.cycles,
              r.t.elements * per, r.t.nodes * per, r.t.walls * per, r.t.contact * per, r.cycle_s * per,
              r.cpu_s * per, 1e9 * r.output_s / r.hex, r.mem_per_hex);
  std::fflush(stdout);
}

void time_input(const Model& m) {
  for (bool keyword : {true, false}) {
    const std::string path = std::string("/tmp/impact3d_bench_scaling_deck") + (keyword ? ".k" : ".dyn");
    {
      std::ofstream os(path);
      if (keyword) write_keyword_deck(os, m); else write_fixed_deck(os, m);
    }
    const double mb = double(std::filesystem::file_size(path)) / 1e6;
    const auto t = Clock::now();
    Model back;
    Diagnostics diag;
    const bool ok = read_and_check_deck(path, back, diag);
    const double s = since(t);
    std::printf("    input %-7s %9d hex: %6.1f MB read and checked in %6.3f s (%5.0f MB/s, %5.2f M hex/s)%s\n",
                keyword ? "keyword" : "fixed", m.num_hexes(), mb, s, mb / s, m.num_hexes() / s / 1e6,
                ok ? "" : "  [REFUSED]");
    std::filesystem::remove(path);
  }
}

// The first line of `path` that contains `key`, or "".
std::string line_with(const std::filesystem::path& path, const std::string& key) {
  std::ifstream is(path);
  std::string line;
  while (std::getline(is, line))
    if (line.find(key) != std::string::npos) return line;
  return "";
}

// The model as a keyword deck run whole by impact3d, as one process and on R ranks.
void time_ranks(const Model& m, int cycles, const std::vector<int>& ranks) {
  namespace fs = std::filesystem;
  const fs::path impact3d = fs::canonical("/proc/self/exe").parent_path().parent_path() / "impact3d";
  const fs::path dir = fs::temp_directory_path() / "impact3d_bench_ranks";
  fs::create_directories(dir);
  Model run = m;
  run.control.end_cycle = cycles;
  run.control.plot_interval = run.control.end_time;  // the first and the last state only
  {
    std::ofstream os(dir / "bar.k");
    write_keyword_deck(os, run);
  }
  std::vector<int> all = {1};
  for (int r : ranks)
    if (r > 1) all.push_back(r);
  const std::string root = getuid() == 0 ? " --allow-run-as-root" : "";
  for (int r : all) {
    const fs::path wd = dir / ("np" + std::to_string(r));
    fs::create_directories(wd);
    const std::string launch = r == 1 ? "" : "OMPI_MCA_mpi_yield_when_idle=1 mpirun --oversubscribe" + root + " -np " + std::to_string(r) + " ";
    const std::string cmd = "cd '" + wd.string() + "' && SOURCE_DATE_EPOCH=0 " + launch + "'" + impact3d.string() +
                            "' i=../bar.k ncpu=1 > log 2>&1";
    const int rc = std::system(cmd.c_str());
    const std::string elapsed = line_with(wd / "log", "us per element-cycle");
    const std::string comm = line_with(wd / "d3hsp", "communication on rank 0");
    double us = 0;
    const std::size_t at = elapsed.find('(');
    if (at != std::string::npos) us = std::atof(elapsed.c_str() + at + 1);
    std::printf("    ranks %2d: %s%8.1f ns per hex-cycle, whole run%s%s\n", r, rc == 0 ? "" : "[FAILED] ", 1e3 * us,
                comm.empty() ? "" : ";", comm.c_str());
    std::fflush(stdout);
  }
  fs::remove_all(dir);
}

std::vector<int> parse_list(const char* s) {
  std::vector<int> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(int(std::atof(item.c_str())));
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  ensure_passive_openmp_wait(argv);  // as impact3d does (thread_policy.h)
  std::vector<int> sizes = {1000, 10000, 100000, 1000000};
  std::vector<int> threads = {1, 2};
  bool contact = false, input = true, shuffle = false;
  MeshOrderMode reorder = MeshOrderMode::automatic;
  double seconds = 2.0;
  std::vector<int> ranks;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--hex" && a + 1 < argc) sizes = parse_list(argv[++a]);
    else if (arg == "--threads" && a + 1 < argc) threads = parse_list(argv[++a]);
    else if (arg == "--seconds" && a + 1 < argc) seconds = std::atof(argv[++a]);
    else if (arg == "--contact") contact = true;
    else if (arg == "--no-input") input = false;
    else if (arg == "--shuffle") shuffle = true;
    else if (arg == "--reorder" && a + 1 < argc && parse_mesh_order_mode(argv[a + 1], reorder)) ++a;
    else if (arg == "--ranks" && a + 1 < argc) ranks = parse_list(argv[++a]);
    else {
      std::fprintf(stderr, "usage: %s [--hex N,...] [--threads T,...] [--contact] [--seconds S] [--no-input] [--shuffle] [--reorder auto|on|off] [--ranks R,...]\n", argv[0]);
      return 3;
    }
  }
  if (!ranks.empty() && (contact || !parallel::built_with_mpi())) {
    std::fprintf(stderr, "--ranks: %s\n", contact ? "the two bars' sliding interface does not run distributed yet (docs/cluster.md)"
                                                   : "this build has no MPI (CMake option IMPACT3D_MPI)");
    return 3;
  }
  std::printf("IMPACT-3D scaling benchmark: %s, ns per hexahedron-cycle by phase\n",
              contact ? "two bars head on (sliding interface)" : "bar on a stonewall");
  std::printf("%9s %3s %7s %9s %7s %7s %8s %8s %8s %9s %8s\n", "hex", "thr", "cycles", "elements", "nodes",
              "walls", "contact", "cycle", "cpu", "output/st", "mem B/hex");
  for (int hex : sizes) {
    const double rss0 = proc_status_bytes("VmRSS:");
    Model m = make_model(hex, contact);
    if (shuffle) test_support::shuffle_mesh_numbering(m, 20261125);
    {
      const auto t = Clock::now();
      const MeshOrderReport r = order_mesh_for_locality(m, reorder);
      std::printf("   %s%s  (%.3f s)\n", shuffle ? "shuffled;" : "", mesh_order_line(r).c_str(), since(t));
    }
    bool first = true;
    int cycles = 0;
    for (int t : threads) {
      const Row r = run_cycles(m, t, seconds, first, rss0);
      print_row(r);
      if (first) cycles = r.cycles + 5;  // (its warm-up cycles too)
      first = false;
    }
    if (!ranks.empty()) time_ranks(m.renumbered() ? model_in_deck_order(m) : m, cycles, ranks);
    if (input) time_input(m.renumbered() ? model_in_deck_order(m) : m);
  }
  std::printf("peak resident memory of this process: %.0f MB\n", proc_status_bytes("VmHWM:") / 1e6);
  return 0;
}
