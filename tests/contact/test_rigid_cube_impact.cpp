// A rigid 4 mm cube (*MAT_RIGID, 4 x 4 x 4 solids) strikes a plastic-kinematic steel block
// (*MAT_PLASTIC_KINEMATIC, 20 x 20 x 10 mm, bottom held) at 300-600 m/s through
// *CONTACT_SURFACE_TO_SURFACE (solid faces both sides, DYNA3D stiffness SFSA 1 x SLSFAC 0.1).
// The energy balance: initial kinetic energy = kinetic + internal + hourglass + bulk viscosity +
// contact ("sliding interface") energy, at every cycle.
//
// The defect this guards: the contact energy is the work of the contact forces on the mean
// velocity (v^{n-1/2} + v^{n+1/2}) / 2 over dt_n.  It was booked before the node pass with
// v^{n+1/2} predicted from each node's own force and mass, and the error of that prediction for
// a rigid body's nodes (which move with the body's resultant, not their own force: here a
// prediction hundreds of m/s off) was booked one cycle late.  During the contact the booked
// energy was then wrong by about dt^2 f^2 / 2 m per contact node: the energy ratio fell to 0.548
// on the coarse block (0.968 on the 1 mm block) and came back only when the contact ended.  The
// work is now booked after the rigid bodies, walls and prescribed motions have set the velocities
// (SlidingInterfaces::book_energy): each cycle's booked contact energy is the forces' work to
// round-off.  docs/contact.md "Contact" ("Rigid bodies in contact: the energy balance").
//
// What is left in the ratio is the central-difference time levels: the kinetic energy is at
// t^{n+1/2}, the internal energy at t^{n+1}, so the ratio leads by half a cycle's internal-energy
// increment while the block deforms fast (up to +6 % on the coarse block, whose impact lasts 8
// cycles; +2 % on the 1 mm block) and settles as the deformation rate falls.
// Steel, SI units.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;

namespace {

constexpr double kRho = 7850, kE = 210e9, kNu = 0.3;
constexpr double kCube = 4e-3;     // the cube's side (4 x 4 x 4 solids)
constexpr double kGap = 0.1e-3;    // initial gap above the block
constexpr double kBlockSide = 20e-3, kBlockDepth = 10e-3;

// The deck: block of solids of size h (bottom held), cube above its centre at speed v; SOFT.
std::string deck(double h, double v, double end_time, int soft, int ihq) {
  const int nb = int(std::lround(kBlockSide / h)), nz = int(std::lround(kBlockDepth / h));
  const int nc = 4;
  const double c = kCube / nc;
  std::ostringstream d;
  d.precision(10);
  d << "*KEYWORD\n*TITLE\nrigid 4 mm cube into a plastic-kinematic block\n";
  d << "*CONTROL_TERMINATION\n" << end_time << "\n";
  d << "*NODE\n";
  int id = 0;
  auto bnode = [&](int i, int j, int k) { return 1 + i + (nb + 1) * (j + (nb + 1) * k); };
  const int cube0 = (nb + 1) * (nb + 1) * (nz + 1);
  auto cnode = [&](int i, int j, int k) { return cube0 + 1 + i + (nc + 1) * (j + (nc + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= nb; ++j)
      for (int i = 0; i <= nb; ++i)
        d << ++id << "," << (i - nb / 2.0) * h << "," << (j - nb / 2.0) * h << "," << (k - nz) * h << "\n";
  for (int k = 0; k <= nc; ++k)
    for (int j = 0; j <= nc; ++j)
      for (int i = 0; i <= nc; ++i)
        d << ++id << "," << (i - nc / 2.0) * c << "," << (j - nc / 2.0) * c << "," << kGap + k * c << "\n";
  d << "*PART\nblock\n1,1,1,0," << (ihq > 0 ? 1 : 0) << "\n*SECTION_SOLID\n1,1\n";
  if (ihq > 0) d << "*HOURGLASS\n1," << ihq << ",0.1\n";
  d << "*MAT_PLASTIC_KINEMATIC\n1," << kRho << "," << kE << "," << kNu << ",250e6,1e9,1\n";
  d << "*PART\ncube\n2,2,2\n*SECTION_SOLID\n2,1\n";
  d << "*MAT_RIGID\n2," << kRho << "," << kE << "," << kNu << "\n";
  d << "*ELEMENT_SOLID\n";
  int e = 0;
  auto hex = [&](auto node, int i, int j, int k, int pid) {
    d << ++e << "," << pid << "," << node(i, j, k) << "," << node(i + 1, j, k) << "," << node(i + 1, j + 1, k) << ","
      << node(i, j + 1, k) << "," << node(i, j, k + 1) << "," << node(i + 1, j, k + 1) << ","
      << node(i + 1, j + 1, k + 1) << "," << node(i, j + 1, k + 1) << "\n";
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < nb; ++i) hex(bnode, i, j, k, 1);
  for (int k = 0; k < nc; ++k)
    for (int j = 0; j < nc; ++j)
      for (int i = 0; i < nc; ++i) hex(cnode, i, j, k, 2);
  d << "*SET_NODE_LIST\n1\n";
  for (int j = 0; j <= nb; ++j)
    for (int i = 0; i <= nb; ++i) d << bnode(i, j, 0) << "\n";
  d << "*BOUNDARY_SPC_SET\n1,0,1,1,1,0,0,0\n";
  d << "*SET_NODE_LIST\n2\n";
  for (int n = cube0 + 1; n <= id; ++n) d << n << "\n";
  d << "*INITIAL_VELOCITY\n2\n0,0," << -v << "\n";
  d << "*CONTACT_SURFACE_TO_SURFACE\n2,1,3,3\n0,0\n1,1\n" << soft << "\n*END\n";
  return d.str();
}

bool read_text(const std::string& text, Model& m, std::string& messages) {
  Diagnostics diag;
  DeckFile deck_file;
  deck_file.load_from_string("rigid_cube.k", text);
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

struct CubeRun {
  double e0 = 0, ratio_min = 1e30, ratio_max = 0, ratio_end = 0;
  double centred_min = 1e30, centred_max = 0;  // the ratio with the element energies at t^{n+1/2}
  double worst_booking = 0;   // largest |booked contact energy increment + contact work| / e0, per cycle
  double worst_rigid = 0;     // largest |cube's kinetic energy change - contact work on its nodes| / e0
  double contact_end = 0;     // the last time with a contact force
  double ke = 0, ie = 0, hg = 0, bv = 0, contact = 0;
  double vz_end = 0;          // the cube's velocity at the end
  double max_pen = 0;         // largest penetration
  long cycles = 0;
};

CubeRun run(double h, double v, double end_time, int soft = 0, int ihq = 0) {
  Model m;
  std::string msg;
  EXPECT_TRUE(read_text(deck(h, v, end_time, soft, ihq), m, msg)) << msg;
  CubeRun r;
  Engine eng(m);
  EXPECT_EQ(eng.initialize(), StepStatus::ok);
  const State& s = eng.state();
  EXPECT_EQ(s.rigid.size(), 1u);
  const RigidBody& rb = s.rigid[0];
  r.e0 = s.initial_total;
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    const double contact0 = s.contact;
    // at t^n: internal and bulk viscosity energies, and the stiffness hourglass forms' (IHQ 4, 5)
    // springs; the viscous forms' hourglass energy is booked at the kinetic energy's level
    // t^{n+1/2} (each force's work on v^{n-1/2} -> v^{n+1/2}: hexahedron.h)
    const bool hg_at_elements = ihq >= 4;
    const double elems0 = s.internal + s.bulk_viscous + (hg_at_elements ? s.hourglass : 0.0);
    double ke_cube0 = 0;
    for (int n : rb.nodes) {
      const std::size_t k = std::size_t(n);
      ke_cube0 += 0.5 * s.mass[k] * (s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k] + s.vz[k] * s.vz[k]);
    }
    const double dt_next = std::min(s.dt_next, m.control.end_time - s.time);  // the last step lands on the end
    const double dt_n = s.cycle == 0 ? 0.5 * dt_next : 0.5 * (s.dt_half + dt_next);
    st = eng.step();
    if (st != StepStatus::ok && st != StepStatus::finished) break;
    // the contact forces of this cycle (fext: no loads in the deck) on the mean velocities
    double w = 0, w_cube = 0, fsum = 0;
    for (int i = 0; i < s.nn; ++i) {
      const std::size_t k = std::size_t(i);
      const double wk = dt_n * (s.fext_x[k] * 0.5 * (s.vx_old[k] + s.vx[k]) + s.fext_y[k] * 0.5 * (s.vy_old[k] + s.vy[k]) +
                                s.fext_z[k] * 0.5 * (s.vz_old[k] + s.vz[k]));
      w += wk;
      fsum += std::abs(s.fext_z[k]);
    }
    double ke_cube = 0;
    for (int n : rb.nodes) {
      const std::size_t k = std::size_t(n);
      w_cube += dt_n * (s.fext_x[k] * 0.5 * (s.vx_old[k] + s.vx[k]) + s.fext_y[k] * 0.5 * (s.vy_old[k] + s.vy[k]) +
                        s.fext_z[k] * 0.5 * (s.vz_old[k] + s.vz[k]));
      ke_cube += 0.5 * s.mass[k] * (s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k] + s.vz[k] * s.vz[k]);
    }
    if (fsum > 0) r.contact_end = s.time;
    r.max_pen = std::max(r.max_pen, eng.contact().max_penetration());
    r.worst_booking = std::max(r.worst_booking, std::abs((s.contact - contact0) + w) / r.e0);
    r.worst_rigid = std::max(r.worst_rigid, std::abs((ke_cube - ke_cube0) - w_cube) / r.e0);
    // the element energies at t^{n+1/2} (the mean of t^n and t^{n+1}), the kinetic energy's level
    const double elems1 = s.internal + s.bulk_viscous + (hg_at_elements ? s.hourglass : 0.0);
    const double kinetic_level = s.kinetic + (hg_at_elements ? 0.0 : s.hourglass);
    const double centred = (kinetic_level + 0.5 * (elems0 + elems1) + s.contact) / r.e0;
    r.centred_min = std::min(r.centred_min, centred);
    r.centred_max = std::max(r.centred_max, centred);
    r.ratio_min = std::min(r.ratio_min, s.energy_ratio());
    r.ratio_max = std::max(r.ratio_max, s.energy_ratio());
  }
  EXPECT_EQ(st, StepStatus::finished);
  r.ratio_end = s.energy_ratio();
  r.ke = s.kinetic;
  r.ie = s.internal;
  r.hg = s.hourglass;
  r.bv = s.bulk_viscous;
  r.contact = s.contact;
  r.vz_end = rb.vcom[2];
  r.cycles = s.cycle;
  return r;
}

void print(const char* what, double v, const CubeRun& r) {
  std::printf("  %s, %.0f m/s: %ld cycles, contact until %.2f us, largest penetration %.3f mm, cube %.1f m/s at the end; energy ratio "
              "%.5f..%.5f (centred %.5f..%.5f), end %.5f (KE0 %.3f J = KE %.3f + IE %.3f + HG %.3f + BV %.3f + contact %.3f); "
              "booked - work %.1e, rigid KE change - work %.1e (x KE0)\n",
              what, v, r.cycles, r.contact_end * 1e6, r.max_pen * 1e3, r.vz_end, r.ratio_min, r.ratio_max, r.centred_min, r.centred_max, r.ratio_end, r.e0, r.ke, r.ie,
              r.hg, r.bv, r.contact, r.worst_booking, r.worst_rigid);
}

}  // namespace

// The coarse block (2 mm solids, half the cube's size: 25 cube nodes on 4 block faces, the
// stiff DYNA3D springs bounce the cube back in 8 cycles at +104 m/s): the case where the
// mis-booking was largest (energy ratio 0.548 in the 5th cycle of contact).  Every cycle:
//   booked contact energy increment = - the contact forces' work (to 1e-12 x KE0);
//   the rigid cube's kinetic-energy change = the contact forces' work on its nodes (a rigid
//   body in translation: M dv . v_mean = F . v_mean dt; the impact is central, the cube turns
//   only by round-off, and the rotation's kinetic energy follows the moment's work to second
//   order: measured 1.6e-7 x KE0, limit 1e-6);
//   the energy ratio >= 0.995 (was 0.548) and <= 1.07 (the internal energy's half-cycle lead,
//   measured 1.063); with the element energies taken at t^{n+1/2} (the mean of t^n and
//   t^{n+1}, the kinetic energy's level) 1.000..1.027, limit 1.03.
// Since the viscous hourglass forms book each force's work on v^{n-1/2} -> v^{n+1/2} (issue 25
// defect 4) their energy is at the kinetic energy's level and the ratio is tighter: 1.0000..1.0183,
// centred 1.0000..1.0034, end 1.0045 (before: ..1.0514, ..1.0171, 1.0136).
TEST(RigidCubeImpact, ContactEnergyIsTheContactWorkEveryCycle) {
  const double v = 600;
  const CubeRun r = run(2e-3, v, 4e-6);
  print("2 mm block", v, r);
  EXPECT_LT(r.worst_booking, 1e-12);
  EXPECT_LT(r.worst_rigid, 1e-6);
  EXPECT_GT(r.ratio_min, 0.995);
  EXPECT_LT(r.ratio_max, 1.07);
  EXPECT_GT(r.centred_min, 0.995);
  EXPECT_LT(r.centred_max, 1.03);
  EXPECT_GT(r.contact_end, 1e-6);  // the impact happened (about 2.7 us)
  EXPECT_LT(r.contact_end, 4e-6);  // and ended
  EXPECT_GT(r.vz_end, 0.0);        // the cube rebounds
}

// The 1 mm block at 300 and 600 m/s, run 20 us (the cube stops in the block and is pushed
// back out, or still in it at 20 us): KE0 = KE + IE + HG + BV + contact at every cycle within
// -0.5 % / +3.5 % (measured 1.0000..1.0302 at 300 m/s, 1.0000..1.0211 at 600 m/s; before the fix
// the ratio fell to 0.966 and 0.968), with the element energies at t^{n+1/2} within -0.5 % / +1 %
// (1.0000..1.0069, 1.0000..1.0066), and within 1 % at the end (1.0022, 1.0029).
TEST(RigidCubeImpact, EnergyBalanceAt300And600MetresPerSecond) {
  for (double v : {300.0, 600.0}) {
    const CubeRun r = run(1e-3, v, 20e-6);
    print("1 mm block", v, r);
    EXPECT_LT(r.worst_booking, 1e-12) << v;
    EXPECT_LT(r.worst_rigid, 1e-6) << v;
    EXPECT_GT(r.ratio_min, 0.995) << v;
    EXPECT_LT(r.ratio_max, 1.035) << v;
    EXPECT_GT(r.centred_min, 0.995) << v;
    EXPECT_LT(r.centred_max, 1.01) << v;
    EXPECT_NEAR(r.ratio_end, 1.0, 0.01) << v;
    EXPECT_NEAR((r.ke + r.ie + r.hg + r.bv + r.contact) / r.e0, 1.0, 0.01) << v;
  }
}

// A block coarser than the cube (5 mm solids under the 4 mm cube of 1 mm solids): the DYNA3D
// stiffness k = mu K A^2 / V is a master segment's, whatever the nodes that land on it; 25 of
// the cube's nodes on the 4 faces around the block's centre node make a spring of 25 k on the
// cube's 0.5 g and on that node, beyond the step's stability (omega dt ~ 1.6 for the cube
// alone), and the first cycle of contact throws the cube back with energy no motion gave it
// (SOFT 0 with PENOPT 2, the segment's stiffness: energy ratio 2.19 at the end at 600 m/s, 1.23
// at 50 m/s).  SOFT = -1 (the IMPACT-3D maximum stable stiffness of each node pair's masses,
// docs/contact.md "Contact"; SOFT = 1 before issue 25) keeps it stable: measured
// 1.0000..1.0298, end 1.0031 at 600 m/s; limits -0.5 % / +4 %, end 1 %.  docs/contact.md "Contact" advises
// SOFT -1 for an impactor whose mesh is finer than the target's.
TEST(RigidCubeImpact, CoarseTargetKeepsTheBalanceWithSoft1) {
  const double v = 600;
  const CubeRun r0 = run(5e-3, v, 20e-6, 0);
  print("5 mm block, SOFT 0", v, r0);
  const CubeRun r = run(5e-3, v, 20e-6, -1);
  print("5 mm block, SOFT -1", v, r);
  EXPECT_LT(r.worst_booking, 1e-12);
  EXPECT_GT(r.ratio_min, 0.995);
  EXPECT_LT(r.ratio_max, 1.04);
  EXPECT_NEAR(r.ratio_end, 1.0, 0.01);
}

// The stiffness hourglass form (IHQ 4) on the block, 50 and 600 m/s, 40 us: its energy was
// booked as the updated resultant's power and climbed past the springs' stored energy every
// step (energy ratio 1.106 and 1.049 at the end); with the mean resultant
// (tests/solve/test_hourglass_energy.cpp) measured end 1.0020 and 1.0010; limits: end within
// 1 %, every cycle within -1 % / +4 %.
TEST(RigidCubeImpact, StiffnessHourglassKeepsTheBalance) {
  for (double v : {50.0, 600.0}) {
    const CubeRun r = run(1e-3, v, 40e-6, 0, 4);
    print("1 mm block, IHQ 4", v, r);
    EXPECT_LT(r.worst_booking, 1e-12) << v;
    EXPECT_GT(r.ratio_min, 0.99) << v;
    EXPECT_LT(r.ratio_max, 1.04) << v;
    EXPECT_NEAR(r.ratio_end, 1.0, 0.01) << v;
  }
}
