// Mass scaling (*CONTROL_TIMESTEP DT2MS, MS1ST; *CONTROL_TERMINATION ENDMAS; fixed format
// control card 9 columns 46-70): the mass added against its closed form from the unscaled
// element steps, the run's step held at TSSF |DT2MS| while a block is crushed, the wave speed of
// a uniformly scaled bar (DT2MS > 0), the energy balance, ENDMAS, restart dumps, and the readers.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/mass_scaling.h"
#include "tests/solve/test_models.h"
#include "../support/deck_text.h"

using namespace impact3d;
using namespace solve_test;

namespace {

// A 1 x 1 x 6 column of 10 mm copper cubes whose top layer is squeezed to 1 mm: the top solid's
// step is about a tenth of the others'.
Model column_with_thin_top(double end_time) {
  Model m = make_box_model({1, 1, 6, 0.01, 0.01, 0.06, 0, 0, 0}, copper_elastic(), end_time);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.z[std::size_t(n)] > 0.055) m.z[std::size_t(n)] = 0.051;
  return m;
}

// A 6 x 6 x 6 block of plastic copper (10 mm) whose upper and lower halves collide at 2 x 400 m/s
// on its mid-plane: the middle solids flatten.
Model crushed_block() {
  Model m = make_box_model({6, 6, 6, 0.01, 0.01, 0.01, 0, 0, 0}, copper_plastic(), 1e-5);
  set_velocity_field(m, [](double, double, double z) {
    const double d = z - 0.005;
    return std::array<double, 3>{0, 0, d > 1e-9 ? -400.0 : d < -1e-9 ? 400.0 : 0.0};
  });
  return m;
}

std::vector<double> unscaled_steps(const Model& m) {
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  return e.state().dt_e;
}

// One cycle: ok, or the last one (finished).
bool stepped(Engine& e) {
  const StepStatus st = e.step();
  return st == StepStatus::ok || st == StepStatus::finished;
}

double sum(const std::vector<double>& v) {
  double t = 0;
  for (double x : v) t += x;
  return t;
}

}  // namespace

// DT2MS < 0: only the solids whose step is below |DT2MS| get mass, (|DT2MS| / dt_e)^2 - 1 times
// their own; the first step is TSSF |DT2MS|; the nodes carry exactly the added mass; the kinetic
// energy of a moving body counts the added mass from the start (not as external work).
TEST(MassScaling, AddsMassOnlyToSolidsBelowTheTarget) {
  Model m = column_with_thin_top(1e-5);
  const std::vector<double> dt = unscaled_steps(m);
  const double dt_thin = dt[5], dt_cube = *std::min_element(dt.begin(), dt.begin() + 5);
  ASSERT_LT(dt_thin, 0.2 * dt_cube);
  const double target = 0.5 * dt_cube;  // between the two
  m.control.mass_scaling_dt = -target;
  set_uniform_velocity(m, 0, 0, -10.0);
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  const State& s = e.state();
  const double f = (target / dt_thin) * (target / dt_thin);
  const double expected = (f - 1) * s.mass_e[5];
  EXPECT_NEAR(s.added_mass, expected, 1e-12 * expected);
  EXPECT_EQ(s.ms_factor[0], 1.0);
  EXPECT_NEAR(s.ms_factor[5], f, 1e-12 * f);
  EXPECT_NEAR(sum(s.mass), s.physical_mass + expected, 1e-12 * s.physical_mass);
  EXPECT_NEAR(added_mass_percent(s), 100 * expected / s.physical_mass, 1e-9);
  EXPECT_NEAR(s.dt_next, m.control.tssf * target, 1e-12 * target);
  EXPECT_EQ(s.dt_elem, 5);
  // kinetic energy 1/2 (m + dm) v^2, no external work: the ratio starts at 1
  EXPECT_NEAR(s.kinetic, 0.5 * sum(s.mass) * 100.0, 1e-9 * s.kinetic);
  EXPECT_EQ(s.external_work, 0.0);
  // without DT2MS nothing is added and the thin solid sets the step
  Model plain = column_with_thin_top(1e-5);
  Engine p(plain);
  ASSERT_EQ(p.initialize(), StepStatus::ok);
  EXPECT_EQ(p.state().added_mass, 0.0);
  EXPECT_TRUE(p.state().ms_factor.empty());
  EXPECT_NEAR(p.state().dt_next, plain.control.tssf * dt_thin, 1e-12 * dt_thin);
}

// A block crushed on its mid-plane: its solids' steps fall as they flatten, mass is added as
// they do (never taken back), the run's step never drops below TSSF |DT2MS|, and the energy
// ratio stays 1 (the added mass's kinetic energy is booked as external work).  MS1ST = 1 adds
// mass at the first cycle only, so the step then falls below the target.
TEST(MassScaling, HoldsTheStepWhileABlockIsCrushed) {
  Model m = crushed_block();
  const std::vector<double> dt = unscaled_steps(m);
  const double target = 0.98 * *std::min_element(dt.begin(), dt.end());  // nothing added at t = 0
  m.control.mass_scaling_dt = -target;
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  EXPECT_EQ(e.state().added_mass, 0.0);
  double added = 0, min_dt = 1e30;
  int grew = 0;
  while (!e.finished()) {
    ASSERT_TRUE(stepped(e));
    const State& s = e.state();
    if (s.time < m.control.end_time * (1 - 1e-9)) min_dt = std::min(min_dt, s.dt_next);
    EXPECT_GE(s.added_mass, added);
    grew += s.added_mass > added;
    added = s.added_mass;
  }
  const State& s = e.state();
  EXPECT_GT(grew, 10);
  EXPECT_GT(added_mass_percent(s), 1.0);                         // the crush did need mass
  EXPECT_GE(min_dt, m.control.tssf * target * (1 - 1e-12));      // and the step held
  EXPECT_GT(s.external_work, 0.0);
  // the same crush without mass scaling takes steps well below the target
  Model plain = m;
  plain.control.mass_scaling_dt = 0;
  Engine p(plain);
  ASSERT_EQ(p.initialize(), StepStatus::ok);
  double min_plain = 1e30;
  while (!p.finished()) {
    ASSERT_TRUE(stepped(p));
    if (p.state().time < plain.control.end_time * (1 - 1e-9)) min_plain = std::min(min_plain, p.state().dt_next);
  }
  EXPECT_LT(min_plain, 0.9 * m.control.tssf * target);
  // the energy balance of the scaled run is as good as the plain run's (a violent crush: both
  // within 2 %)
  const double err_scaled = std::fabs(s.energy_ratio() - 1), err_plain = std::fabs(p.state().energy_ratio() - 1);
  EXPECT_LT(err_plain, 0.02);
  EXPECT_LT(err_scaled, err_plain + 0.005) << s.energy_ratio() << " vs " << p.state().energy_ratio();
  // MS1ST: scaling only at the first cycle (where none is needed): nothing is ever added
  Model first = m;
  first.control.mass_scaling_first_only = true;
  Engine f(first);
  ASSERT_EQ(f.initialize(), StepStatus::ok);
  while (!f.finished()) ASSERT_TRUE(stepped(f));
  EXPECT_EQ(f.state().added_mass, 0.0);
}

// DT2MS > 0 sets every solid's step to DT2MS at the first cycle (mass added or taken): a
// uniform bar with DT2MS = 2 dt_e carries 4 times its mass, so a velocity step at one end
// reaches the far end at 2 L / c instead of L / c.
TEST(MassScaling, PositiveDt2msScalesEverySolidAndSlowsTheWave) {
  MaterialData mat = copper_elastic();
  mat.nu = 0;  // one solid across: the bar speed sqrt(E / rho)
  mat.q1 = mat.q2 = 0;  // no bulk viscosity: every solid's step is the same, moving or not
  const double L = 0.2, c = std::sqrt(mat.E / mat.rho);
  auto wave_arrival = [&](double dt2ms, double* mass_ratio) {
    Model m = make_box_model({1, 1, 40, 0.005, 0.005, L, 0, 0, 0}, mat, 2.5 * L / c);
    // the bottom end's nodes start at 1 m/s: a pulse runs up the bar
    for (int n = 0; n < m.num_nodes(); ++n)
      if (m.z[std::size_t(n)] < 1e-12) {
        InitialVelocity iv;
        iv.first = iv.last = n + 1;
        iv.v = {0, 0, 1.0};
        m.init_velocities.push_back(iv);
      }
    m.control.num_init_velocity_cards = int(m.init_velocities.size());
    if (dt2ms != 0) {
      const std::vector<double> dt = unscaled_steps(m);
      m.control.mass_scaling_dt = dt2ms * dt.back();  // the top solid: no strain rate at t = 0
    }
    Engine e(m);
    EXPECT_EQ(e.initialize(), StepStatus::ok);
    *mass_ratio = sum(e.state().mass) / sum(e.state().mass_e);
    double t_arrive = -1;
    while (!e.finished()) {
      EXPECT_TRUE(stepped(e));
      const State& s = e.state();
      const int top = m.num_nodes() - 1;
      if (t_arrive < 0 && s.vz[std::size_t(top)] > 0.05) t_arrive = s.time;
    }
    return t_arrive;
  };
  double r_plain = 0, r_scaled = 0;
  const double t_plain = wave_arrival(0, &r_plain);
  const double t_scaled = wave_arrival(2.0, &r_scaled);
  EXPECT_DOUBLE_EQ(r_plain, 1.0);
  EXPECT_NEAR(r_scaled, 4.0, 1e-9);
  // the (dispersed) front passes 5 % of the step a little before L / c: compare the two runs
  EXPECT_NEAR(t_plain, L / c, 0.1 * L / c);
  EXPECT_NEAR(t_scaled / t_plain, 2.0, 0.05);
}

// ENDMAS: the run ends (normally) once the added mass reaches that percentage.
TEST(MassScaling, EndmasEndsTheRun) {
  Model m = crushed_block();
  const std::vector<double> dt = unscaled_steps(m);
  m.control.mass_scaling_dt = -0.98 * *std::min_element(dt.begin(), dt.end());
  m.control.end_mass_percent = 0.5;
  Engine e(m);
  ASSERT_EQ(e.initialize(), StepStatus::ok);
  while (!e.finished()) ASSERT_TRUE(stepped(e));
  EXPECT_TRUE(e.added_mass_limit_reached());
  EXPECT_GE(added_mass_percent(e.state()), 0.5);
  EXPECT_LT(e.state().time, 0.99 * m.control.end_time);
}

// A restart dump of a mass-scaled run keeps the added mass (nodal masses, factors, books): the
// continued run is the same bits.
TEST(MassScaling, RestartDumpContinuesBitForBit) {
  Model m = crushed_block();
  const std::vector<double> dt = unscaled_steps(m);
  m.control.mass_scaling_dt = -0.98 * *std::min_element(dt.begin(), dt.end());
  Engine a(m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  for (int c = 0; c < 20; ++c) ASSERT_EQ(a.step(), StepStatus::ok);
  ASSERT_GT(a.state().added_mass, 0.0);
  DumpHeader h;
  h.deck_name = "crush.k";
  h.deck_text = "*KEYWORD\n*END\n";
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/mass_scaling_restart_dump";
  write_restart_dump(path, h, a.state(), a.contact().restart_data());
  Engine b(m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  for (int c = 0; c < 20; ++c) {
    ASSERT_TRUE(stepped(a));
    ASSERT_TRUE(stepped(b));
  }
  EXPECT_EQ(a.state().z, b.state().z);
  EXPECT_EQ(a.state().mass, b.state().mass);
  EXPECT_EQ(a.state().added_mass, b.state().added_mass);
  EXPECT_EQ(a.state().external_work, b.state().external_work);
}

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& name, const std::string& text) { return test_support::read_deck_text(text, name); }

std::string one_hex_deck(const std::string& controls) {
  return "*KEYWORD\n*TITLE\nmass scaling\n" + controls + "*DATABASE_BINARY_D3PLOT\n   5.0E-07\n" +
         "*PART\nblock\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
         "*MAT_ELASTIC\n         1    7800.0   2.0e11       0.3\n*NODE\n"
         "       1             0.0             0.0             0.0\n       2            0.01             0.0             0.0\n"
         "       3            0.01            0.01             0.0\n       4             0.0            0.01             0.0\n"
         "       5             0.0             0.0            0.01\n       6            0.01             0.0            0.01\n"
         "       7            0.01            0.01            0.01\n       8             0.0            0.01            0.01\n"
         "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7       8\n*END\n";
}

}  // namespace

// The keyword fields (DT2MS, MS1ST, ENDMAS with LS-DYNA's 1e8 "never"), the refusals, and the
// converter: keyword -> fixed (control card 9 columns 46-70) -> keyword gives the same model.
TEST(MassScalingInput, ReadsDt2msMs1stEndmasAndConverts) {
  Read r = read_text("ms.k", one_hex_deck("*CONTROL_TERMINATION\n   1.0E-05         0       0.0       0.0       5.0\n"
                                          "*CONTROL_TIMESTEP\n       0.0       0.8         0       0.0  -2.5E-07         0         0         1\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  EXPECT_DOUBLE_EQ(r.m.control.mass_scaling_dt, -2.5e-7);
  EXPECT_TRUE(r.m.control.mass_scaling_first_only);
  EXPECT_DOUBLE_EQ(r.m.control.end_mass_percent, 5.0);
  EXPECT_DOUBLE_EQ(r.m.control.tssf, 0.8);
  Read never = read_text("ms.k", one_hex_deck("*CONTROL_TERMINATION\n   1.0E-05         0       0.0       0.0     1.0E8\n"));
  ASSERT_TRUE(never.ok) << never.messages();
  EXPECT_EQ(never.m.control.end_mass_percent, 0.0);
  EXPECT_EQ(never.m.control.mass_scaling_dt, 0.0);
  // refusals name the field
  Read bad = read_text("ms.k", one_hex_deck("*CONTROL_TERMINATION\n   1.0E-05         0       0.0       0.0      -1.0\n"
                                            "*CONTROL_TIMESTEP\n       0.0       0.8         0       0.0  -2.5E-07         0         0         2\n"));
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.messages().find("ENDMAS"), std::string::npos) << bad.messages();
  EXPECT_NE(bad.messages().find("MS1ST"), std::string::npos) << bad.messages();
  // converter round trip through the fixed format
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/mass_scaling.dyn";
  const std::string kw = std::string(IMPACT3D_BINARY_DIR) + "/mass_scaling.k";
  std::ostringstream log;
  ASSERT_EQ(write_converted_decks(r.m, kw, fixed, log), exit_code::ok) << log.str();
  Read f;
  {
    DeckFile deck;
    ASSERT_TRUE(deck.load(fixed, f.d));
    InputOptions o;
    f.ok = read_deck(deck, f.m, f.d, o) && check_model(f.m, f.d);
  }
  ASSERT_TRUE(f.ok) << f.messages();
  Read k;
  {
    DeckFile deck;
    ASSERT_TRUE(deck.load(kw, k.d));
    InputOptions o;
    k.ok = read_deck(deck, k.m, k.d, o) && check_model(k.m, k.d);
  }
  ASSERT_TRUE(k.ok) << k.messages();
  std::string diff;
  for (const auto& l : model_differences(r.m, f.m)) diff += l + "\n";
  for (const auto& l : model_differences(r.m, k.m)) diff += l + "\n";
  EXPECT_EQ(diff, "");
  EXPECT_DOUBLE_EQ(f.m.control.mass_scaling_dt, -2.5e-7);
  EXPECT_TRUE(f.m.control.mass_scaling_first_only);
  EXPECT_DOUBLE_EQ(f.m.control.end_mass_percent, 5.0);
}
