// A plate struck by a rigid body (issue 14, "Verification"): a heavy rigid block (*MAT_RIGID,
// 100 kg) strikes the centre of a clamped square steel plate of 16 x 16 Belytschko-Tsay shells
// (a = 0.2 m, t = 5 mm) at 0.1 m/s through *CONTACT_AUTOMATIC_NODES_TO_SURFACE (the block's
// nodes on the plate's shell segments, thickness offset t/2).  The block is 64 times the plate's
// mass and the contact lasts about 11 of the plate's first periods: the quasi-static regime, in
// which the plate acts as the spring of its static centre stiffness k = P / w and the impact is
// a mass on a spring:
//   contact duration T = pi sqrt(M / k), largest force F = v sqrt(k M), largest travel v sqrt(M / k),
//   rebound at -v (elastic), impulse 2 M v.
// Corrections used in the closed form (each stated, each small here):
//   * the contact springs in series with the plate: 4 springs (the block's 4 lower corners, one
//     in each of the 4 central shells) of k_c = SFSA 0.1 K A / d (LS-DYNA's shell form),
//     k_s = 1 / (1/k + 1/(4 k_c)) (k_s = 0.983 k here);
//   * the plate's effective mass at the load, m_e = sum m_i w_i^2 / w^2 (Rayleigh, over the
//     static shape): T = pi sqrt((M + m_e) / k_s), F = v M sqrt(k_s / (M + m_e)) (m_e = 0.19 %
//     of M here).
// The plate's own vibration (its first period 0.89 ms) rides on the half sine of the force: the
// raw largest force is 11.6 % above F; the force averaged over one plate period is compared with
// the half sine's same mean, F sin(x) / x, x = pi tau / (2 T).
// k is measured first on the same mesh by dynamic relaxation (*DAMPING_GLOBAL) under the load
// pattern the contact puts on the plate (the block is a quarter shell wide: 77 % of the force on
// the centre node, the rest on its 8 neighbours, `pattern` below);
// w is the displacement conjugate to it (sum p_i w_i, the block's travel).  Timoshenko's clamped
// plate under a central point load (Timoshenko and Woinowsky-Krieger, Theory of plates and
// shells, 1959, table 35, nu = 0.3): w = 0.00560 P a^2 / D, D = E t^3 / (12 (1 - nu^2)); the
// mesh is checked against it under a point load at the centre node.  docs/contact.md "Shells in contact".
// Steel, SI units.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"
#include "../support/box_mesh.h"
#include "contact_test_util.h"

using namespace impact3d;

namespace {

constexpr double kE = 210e9, kNu = 0.3, kRho = 7850;
constexpr double kA = 0.2, kT = 0.005;  // plate side and thickness
constexpr int kN = 16;                   // shells per side
constexpr double kH = kA / kN;           // shell size
constexpr double kW = kH / 4;            // the block's side: its lower corners 1/8 of a shell from the centre node
constexpr double kM = 100, kV = 0.1;     // block mass and speed
constexpr double kGap = 1e-5;            // initial gap between the block and the plate's offset surface
constexpr double kSfsa = 1.0;            // penalty scale (x 0.1: LS-DYNA's SLSFAC default)
constexpr double kEnd = 0.012;           // the impact run's end (contact ends at about 9.75 ms)
const double kBulk = kE / (3 * (1 - 2 * kNu));
const double kD = kE * kT * kT * kT / (12 * (1 - kNu * kNu));
const double kTimoshenko = kD / (0.00560 * kA * kA);  // k of a central point load

using contact_test::fld;
using contact_test::ifld;

int plate_node(int i, int j) { return 1 + i + (kN + 1) * j; }  // deck id; (i, j) in 0..kN
constexpr int kPlateNodes = (kN + 1) * (kN + 1);
constexpr int kCentre = kN / 2;

// The plate's load pattern under the block: weight of plate node (i, j) (sums to 1).  Each of
// the block's 4 lower corners lies in one central shell at (f, f) of its side from the centre
// node (f = kW / 2 / kH) and puts a quarter of the force on that shell's nodes by the bilinear
// shape functions: the centre node (1 - f)^2, each edge neighbour 2 x f (1 - f) / 4, each
// diagonal one f^2 / 4.
double pattern(int i, int j, bool point) {
  const int di = std::abs(i - kCentre), dj = std::abs(j - kCentre);
  if (point) return di == 0 && dj == 0 ? 1.0 : 0.0;
  if (di > 1 || dj > 1) return 0.0;
  const double f = kW / 2 / kH;
  return (di == 0 ? 1 - f : f / 2) * (dj == 0 ? 1 - f : f / 2);
}

// The deck: the clamped plate (part 1, elastic, SHRF 5/6, NIP 2, IHQ 4 QM 0.1), then either a
// static load P on the pattern ramped over `ramp` and held, with *DAMPING_GLOBAL D, or the block
// (part 2, rigid, one hexahedron over the 4 central shells) falling at kV with the contact.
std::string deck(double end_time, bool impact, bool point = false, double P = 0, double ramp = 0, double damping = 0) {
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nrigid block striking a clamped plate of shells\n*CONTROL_TERMINATION\n" << fld(end_time, 10) << "\n";
  // PENOPT 2: the plate's segments' stiffness (the contact springs k_c below)
  d << "*CONTROL_CONTACT\n" << fld(0.1, 10) << ifld(0, 10) << ifld(0, 10) << ifld(0, 10) << ifld(2, 10) << "\n";
  d << "*PART\nplate\n" << ifld(1, 10) << ifld(1, 10) << ifld(1, 10) << ifld(0, 10) << ifld(1, 10) << "\n";
  d << "*SECTION_SHELL\n" << ifld(1, 10) << ifld(2, 10) << fld(5.0 / 6.0, 10) << ifld(2, 10) << "\n" << fld(kT, 10) << "\n";
  d << "*MAT_ELASTIC\n" << ifld(1, 10) << fld(kRho, 10) << fld(kE, 10) << fld(kNu, 10) << "\n";
  d << "*HOURGLASS\n" << ifld(1, 10) << ifld(4, 10) << fld(0.1, 10) << "\n";
  d << "*NODE\n";
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i)
      d << ifld(plate_node(i, j), 8) << fld(-kA / 2 + kH * i, 16) << fld(-kA / 2 + kH * j, 16) << fld(0.0, 16) << "\n";
  const double z0 = kT / 2 + kGap;
  if (impact)
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          d << ifld(kPlateNodes + 1 + i + 2 * j + 4 * k, 8) << fld(-kW / 2 + kW * i, 16) << fld(-kW / 2 + kW * j, 16)
            << fld(z0 + kH * k, 16) << "\n";
  d << "*ELEMENT_SHELL\n";
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i)
      d << ifld(1 + i + kN * j, 8) << ifld(1, 8) << ifld(plate_node(i, j), 8) << ifld(plate_node(i + 1, j), 8)
        << ifld(plate_node(i + 1, j + 1), 8) << ifld(plate_node(i, j + 1), 8) << "\n";
  // clamped edges: every boundary node fixed in translation and rotation
  d << "*SET_NODE_LIST\n" << ifld(1, 10) << "\n";
  int c = 0;
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i)
      if (i == 0 || j == 0 || i == kN || j == kN) {
        d << ifld(plate_node(i, j), 10);
        if (++c % 8 == 0) d << "\n";
      }
  if (c % 8) d << "\n";
  d << "*BOUNDARY_SPC_SET\n" << ifld(1, 10) << ifld(0, 10);
  for (int k = 0; k < 6; ++k) d << ifld(1, 10);
  d << "\n";
  if (impact) {
    const double volume = kW * kW * kH;
    d << "*PART\nblock\n" << ifld(2, 10) << ifld(2, 10) << ifld(2, 10) << "\n";
    d << "*SECTION_SOLID\n" << ifld(2, 10) << ifld(1, 10) << "\n";
    d << "*MAT_RIGID\n" << ifld(2, 10) << fld(kM / volume, 10) << fld(kE, 10) << fld(kNu, 10) << "\n";
    d << "*ELEMENT_SOLID\n" << ifld(kN * kN + 1, 8) << ifld(2, 8);
    for (int v : {1, 2, 4, 3, 5, 6, 8, 7}) d << ifld(kPlateNodes + v, 8);
    d << "\n*SET_NODE_LIST\n" << ifld(2, 10) << "\n";
    for (int v = 1; v <= 8; ++v) d << ifld(kPlateNodes + v, 10);
    d << "\n*INITIAL_VELOCITY\n" << ifld(2, 10) << "\n" << fld(0, 10) << fld(0, 10) << fld(-kV, 10) << "\n";
    // the block's nodes (SURFA part 2) on the plate's shell segments (SURFB part 1)
    d << "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n" << ifld(2, 10) << ifld(1, 10) << ifld(3, 10) << ifld(3, 10) << "\n"
      << fld(0, 10) << "\n" << fld(kSfsa, 10) << fld(kSfsa, 10) << "\n";
  } else {
    d << "*DEFINE_CURVE\n" << ifld(1, 10) << "\n" << fld(0, 20) << fld(0, 20) << "\n" << fld(ramp, 20) << fld(1, 20) << "\n"
      << fld(10 * end_time, 20) << fld(1, 20) << "\n";
    d << "*LOAD_NODE_POINT\n";
    for (int j = 0; j <= kN; ++j)
      for (int i = 0; i <= kN; ++i)
        if (pattern(i, j, point) > 0)
          d << ifld(plate_node(i, j), 10) << ifld(3, 10) << ifld(1, 10) << fld(-P * pattern(i, j, point), 10) << "\n";
    d << "*DAMPING_GLOBAL\n" << ifld(0, 10) << fld(damping, 10) << "\n";
  }
  d << "*END\n";
  return d.str();
}

bool read_text(const std::string& text, Model& m, std::string& messages) {
  Diagnostics diag;
  DeckFile deck_file;
  deck_file.load_from_string("struck_plate.k", text);
  bool ok = read_deck(deck_file, m, diag, InputOptions{});
  if (ok) {
    orient_interface_segments(m, diag);
    ok = check_model(m, diag);
  }
  std::ostringstream os;
  diag.print(os);
  messages = os.str();
  return ok;
}

// Static answer under P on the pattern, by dynamic relaxation: w (conjugate to the pattern),
// the Rayleigh effective mass of the static shape, and how static the end state is.
struct StaticResult {
  double w = 0, w90 = 0, m_eff = 0, plate_mass = 0, kinetic = 0, internal = 0, ratio = 0;
  long cycles = 0;
};

StaticResult relax(bool point, double P) {
  StaticResult r;
  // the plate's first circular frequency (clamped square: 35.99 / a^2 sqrt(D / rho t)); damping
  // 2 w1 (critical for the first mode), load ramped over 2 periods, held for 8 more
  const double w1 = 35.99 / (kA * kA) * std::sqrt(kD / (kRho * kT)), period = 2 * M_PI / w1;
  const double end = 10 * period;
  Model m;
  std::string msg;
  EXPECT_TRUE(read_text(deck(end, false, point, P, 2 * period, 2 * w1), m, msg)) << msg;
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  auto conj = [&] {
    double w = 0;
    for (int j = 0; j <= kN; ++j)
      for (int i = 0; i <= kN; ++i) w += pattern(i, j, point) * -s.z[std::size_t(plate_node(i, j) - 1)];
    return w;
  };
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = e.step();
    ++r.cycles;
    if (r.w90 == 0 && s.time >= 0.9 * end) r.w90 = conj();
  }
  EXPECT_EQ(st, StepStatus::finished);
  r.w = conj();
  for (int k = 0; k < kPlateNodes; ++k) {
    r.plate_mass += s.mass[std::size_t(k)];
    r.m_eff += s.mass[std::size_t(k)] * s.z[std::size_t(k)] * s.z[std::size_t(k)];
  }
  r.m_eff /= r.w * r.w;
  r.kinetic = s.kinetic;
  r.internal = s.internal + s.hourglass;
  r.ratio = s.energy_ratio();
  return r;
}

// One impact run, cycle by cycle.
struct ImpactResult {
  double first = -1, last = -1, contact_time = 0;  // first / last cycle with a force, sum of its steps
  double f_max = 0, travel_max = 0, impulse = 0;   // on the block (+z), its largest travel past first contact
  std::vector<double> t_hist, f_hist, dt_hist;      // the force on the block per cycle, its time and step
  double p0 = 0, p1 = 0, m_block = 0;
  double ratio_min = 1, ratio_max = 1, dt = 0;
  long cycles = 0, separations = 0;  // separations: force -> 0 transitions before the last contact
  std::vector<double> bits;
};

// The largest mean of the force over a window tau (sum F dt over the cycles in it / tau).
double largest_window_mean(const ImpactResult& r, double tau) {
  double best = 0, sum = 0, span = 0;
  std::size_t a = 0;
  for (std::size_t b = 0; b < r.f_hist.size(); ++b) {
    sum += r.f_hist[b] * r.dt_hist[b];
    span += r.dt_hist[b];
    while (span > tau) sum -= r.f_hist[a] * r.dt_hist[a], span -= r.dt_hist[a], ++a;
    best = std::max(best, sum / tau);
  }
  return best;
}

ImpactResult impact(double end) {
  ImpactResult r;
  Model m;
  std::string msg;
  EXPECT_TRUE(read_text(deck(end, true), m, msg)) << msg;
  EXPECT_EQ(m.interfaces.size(), 1u);
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  State& s = e.state();
  const std::size_t low = std::size_t(kPlateNodes);  // a lower corner of the block
  for (int k = kPlateNodes; k < kPlateNodes + 8; ++k) {
    r.m_block += s.mass[std::size_t(k)];
    r.p0 += s.mass[std::size_t(k)] * s.vz[std::size_t(k)];
  }
  bool in_contact = false;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double dt_before = s.dt_half, time = s.time;
    const int cycle = s.cycle;
    st = e.step();
    const double dt_n = cycle == 0 ? 0.5 * s.dt_half : 0.5 * (dt_before + s.dt_half);
    const double fz = e.interface_forces()[0][2];
    r.impulse += fz * dt_n;
    if (fz != 0) {
      if (r.first < 0) r.first = time, r.dt = s.dt_half;
      r.last = time;
      r.contact_time += dt_n;
      r.f_max = std::max(r.f_max, std::abs(fz));
    } else if (in_contact) {
      ++r.separations;
    }
    in_contact = fz != 0;
    r.travel_max = std::max(r.travel_max, kT / 2 - s.z[low]);  // past the plate's offset surface at rest
    r.t_hist.push_back(time);
    r.f_hist.push_back(fz);
    r.dt_hist.push_back(dt_n);
    r.ratio_min = std::min(r.ratio_min, s.energy_ratio());
    r.ratio_max = std::max(r.ratio_max, s.energy_ratio());
    ++r.cycles;
  }
  EXPECT_EQ(st, StepStatus::finished);
  if (r.separations > 0 && !in_contact) --r.separations;  // the final one
  for (int k = kPlateNodes; k < kPlateNodes + 8; ++k) r.p1 += s.mass[std::size_t(k)] * s.vz[std::size_t(k)];
  r.bits = s.z;
  r.bits.insert(r.bits.end(), s.vz.begin(), s.vz.end());
  r.bits.push_back(s.internal);
  r.bits.push_back(s.contact);
  return r;
}

}  // namespace

// The plate's static centre stiffness on this mesh, by dynamic relaxation: under a point load at
// the centre node against Timoshenko's clamped plate, and under the contact's load pattern (the
// k of the impact test below).
TEST(StruckPlate, StaticCentreStiffnessByDynamicRelaxation) {
  const double P = kV * std::sqrt(kTimoshenko * kM);  // about the impact's largest force
  const StaticResult pt = relax(true, P), pat = relax(false, P);
  const double k_point = P / pt.w, k_pattern = P / pat.w;
  std::printf("clamped plate %d x %d, a %.3g m, t %.3g mm, P %.5g N: Timoshenko k = %.6g N/m (w %.6g mm); point load "
              "k = %.6g N/m (%.4f x Timoshenko), contact pattern k = %.6g N/m (%.4f x); %ld cycles; static: w changes "
              "%.2g over the last tenth, kinetic / internal %.2g, energy ratio %.6f; plate mass %.5g kg, effective mass "
              "%.5g kg (pattern shape)\n",
              kN, kN, kA, kT * 1e3, P, kTimoshenko, P / kTimoshenko * 1e3, k_point, k_point / kTimoshenko, k_pattern,
              k_pattern / kTimoshenko, pat.cycles, pat.w / pat.w90 - 1, pat.kinetic / pat.internal, pat.ratio,
              pat.plate_mass, pat.m_eff);
  for (const StaticResult* r : {&pt, &pat}) {
    EXPECT_NEAR(r->w / r->w90, 1.0, 1e-4);       // static
    EXPECT_LT(r->kinetic, 1e-3 * r->internal);
    EXPECT_NEAR(r->ratio, 1.0, 1e-3);            // load work = strain energy + damped
    EXPECT_NEAR(r->plate_mass, kRho * kA * kA * kT, 1e-9);
  }
  // Clapeyron: P w = 2 U (linear elastic)
  EXPECT_NEAR(P * pat.w / (2 * pat.internal), 1.0, 2e-3);
  // the mesh against Timoshenko's point-load value
  EXPECT_NEAR(k_point / kTimoshenko, 1.0, 0.05);
  // the pattern spreads the load over the 4 central shells: stiffer than the point load
  EXPECT_GT(k_pattern, k_point);
  EXPECT_LT(k_pattern, 1.1 * k_point);
}

// The impact: the closed form of a mass on the measured static stiffness (with the contact
// springs in series and the plate's effective mass), and on Timoshenko's.
TEST(StruckPlate, HeavyRigidBlockIsAMassOnTheStaticStiffness) {
  const double P = kV * std::sqrt(kTimoshenko * kM);
  const StaticResult st = relax(false, P);
  const double k = P / st.w;
  // 4 contact springs mu K A / d of the central shells (mu = SFSA x 0.1), in series with the plate
  const double k_c = 4 * kSfsa * 0.1 * kBulk * kH * kH / (kH * std::sqrt(2.0));
  const double k_s = 1 / (1 / k + 1 / k_c), m_e = st.m_eff;
  const double T = M_PI * std::sqrt((kM + m_e) / k_s), F = kV * kM * std::sqrt(k_s / (kM + m_e));
  const double travel = kV * kM / std::sqrt(k_s * (kM + m_e));  // block's largest travel: plate + contact springs
  const double T0 = M_PI * std::sqrt(kM / k), F0 = kV * std::sqrt(k * kM);  // no corrections
  const double T_timo = M_PI * std::sqrt(kM / kTimoshenko), F_timo = kV * std::sqrt(kTimoshenko * kM);
  const double w1 = 35.99 / (kA * kA) * std::sqrt(kD / (kRho * kT));
  const double end = kEnd;
  std::vector<double> bits1;
  for (int threads : {1, 2}) {
    test_support::ScopedThreads th(threads);
    const ImpactResult r = impact(end);
    if (threads == 2) {
      EXPECT_TRUE(r.bits == bits1) << "1 and 2 threads differ";
      break;
    }
    bits1 = r.bits;
    const double duration = r.last - r.first;
    // the force averaged over the plate's first period tau (the plate's vibration filtered out);
    // the half sine's largest mean over tau is F sin(x) / x, x = pi tau / (2 T)
    const double tau = 2 * M_PI / w1, x = M_PI * tau / (2 * T);
    const double f_mean = largest_window_mean(r, tau), F_mean = F * std::sin(x) / x;
    std::printf("struck plate: M %.4g kg (plate %.4g kg, effective %.4g kg), v %.3g m/s, k %.6g N/m measured (%.4f x "
                "Timoshenko), contact springs 4 k_c = %.4g N/m, k_s %.6g; contact %.5g ms first to last (%.5g ms summed, "
                "%ld separations), closed form %.5g ms (no corrections %.5g, Timoshenko %.5g; plate period %.4g ms); "
                "largest force %.6g N, closed form %.6g (no corrections %.6g, Timoshenko %.6g); largest mean over a plate period %.6g N, "
                "closed form %.6g; largest travel %.5g um, "
                "closed form %.5g; impulse %.6g N s, momentum change %.6g (rel. %.2g), rebound %.5f m/s (e %.5f); energy ratio %.6f..%.6f; %ld cycles, dt %.3g us\n",
                r.m_block, st.plate_mass, m_e, kV, k, k / kTimoshenko, k_c, k_s, duration * 1e3, r.contact_time * 1e3,
                r.separations, T * 1e3, T0 * 1e3, T_timo * 1e3, 2 * M_PI / w1 * 1e3, r.f_max, F, F0, F_timo, f_mean, F_mean,
                r.travel_max * 1e6, travel * 1e6, r.impulse, r.p1 - r.p0, r.impulse / (r.p1 - r.p0) - 1,
                r.p1 / r.m_block, -r.p1 / r.p0, r.ratio_min, r.ratio_max, r.cycles,
                r.dt * 1e6);
    EXPECT_NEAR(r.m_block, kM, 1e-9 * kM);
    EXPECT_GT(r.first, 0.0);
    EXPECT_LT(r.last, end - 0.1 * T);  // separated before the end
    // the mass-spring closed form on the measured k
    // (measured +0.57 %, +0.03 %, +0.31 %)
    EXPECT_NEAR(duration / T, 1.0, 0.01);
    EXPECT_NEAR(r.travel_max / travel, 1.0, 0.005);
    EXPECT_NEAR(f_mean / F_mean, 1.0, 0.01);
    EXPECT_NEAR(r.f_max / F, 1.0, 0.15);  // the plate's vibration rides on the half sine
    // on Timoshenko's k, without corrections (the mesh's point-load k is 2.2 % softer, the
    // quarter-shell block 4.3 % stiffer than a point, the contact springs 1.7 % softer): 3 %
    EXPECT_NEAR(duration / T_timo, 1.0, 0.03);
    EXPECT_NEAR(f_mean / (F_timo * std::sin(x) / x), 1.0, 0.03);
    // impulse = the block's momentum change, about 2 M v (elastic rebound)
    EXPECT_NEAR(r.impulse / (r.p1 - r.p0), 1.0, 1e-10);
    EXPECT_NEAR(-r.p1 / r.p0, 1.0, 0.005);  // rebound: measured e = 0.9988 (the rest stays in the plate)
    EXPECT_GT(r.ratio_min, 0.99);
    EXPECT_LT(r.ratio_max, 1.01);
  }
}

// The impact is also shipped as a deck for the command line (tests/contact/struck_plate.k:
// impact3d i=struck_plate.k); it is this test's text (IMPACT3D_WRITE_STRUCK_PLATE_DECK=1
// rewrites it).
TEST(StruckPlate, ShippedDeckIsTheTestsDeck) {
  const std::string path = std::string(IMPACT3D_SOURCE_DIR) + "/tests/contact/struck_plate.k";
  const std::string text = deck(kEnd, true);
  if (std::getenv("IMPACT3D_WRITE_STRUCK_PLATE_DECK")) std::ofstream(path) << text;
  std::ifstream in(path);
  ASSERT_TRUE(in.good()) << path;
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_TRUE(ss.str() == text) << path << " differs from the test's deck(kEnd, true)";
}
