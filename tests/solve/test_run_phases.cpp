// The run driver's phases on their own (impact3d/solve/run.cpp, docs/developer-guide.md "The run
// driver"): the output schedule (which times write a state, given the intervals; exact output
// times), the sense switches (signals answered once, the plot request that waits), and the
// schedule as a whole run follows it (the plot database's state times).

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/solve/output_schedule.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/sense_switches.h"
#include "test_models.h"
#include "../support/history_runs.h"

using namespace impact3d;

namespace {

ControlData intervals(double plot, double history, double intfor = -1, int dumps = 0, int running = 0) {
  ControlData c;
  c.plot_interval = plot;
  c.th_interval = history;
  c.intfor_interval = intfor;
  c.restart_dump_cycles = dumps;
  c.running_restart_cycles = running;
  return c;
}

// The cycles (1-based) after which a plot state is written, the driver's way: the state at time
// 0, then each cycle whose time the schedule finds due.
std::vector<int> plot_cycles(OutputSchedule& sched, const std::vector<double>& times) {
  std::vector<int> cycles;
  sched.plot_written(0);
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!sched.plot_due(times[k])) continue;
    cycles.push_back(int(k) + 1);
    sched.plot_written(times[k]);
  }
  return cycles;
}

}  // namespace

TEST(OutputSchedule, NextTimeIsTheFirstMultipleAfterTheTimeWritten) {
  EXPECT_EQ(OutputSchedule::next_after(0.0, 0.25), 0.25);
  EXPECT_EQ(OutputSchedule::next_after(0.3, 0.25), 0.5);
  EXPECT_EQ(OutputSchedule::next_after(0.5, 0.25), 0.75);  // a time on a multiple: the next one
  // a time a rounding short of a multiple counts as it: 0.3 is not written twice
  EXPECT_EQ(OutputSchedule::next_after(0.3 * (1 - 1e-12), 0.1), 4 * 0.1);
  // ... but a time clearly short of it does not
  EXPECT_EQ(OutputSchedule::next_after(0.3 * (1 - 1e-6), 0.1), 3 * 0.1);
}

TEST(OutputSchedule, DueWithinARelativeBillionth) {
  EXPECT_TRUE(OutputSchedule::reached(1.0, 1.0));
  EXPECT_TRUE(OutputSchedule::reached(1.0 - 0.5e-9, 1.0));
  EXPECT_FALSE(OutputSchedule::reached(1.0 - 2e-9, 1.0));
  EXPECT_TRUE(OutputSchedule::reached(1.5, 1.0));
}

// Steps of 0.3 ms, plot interval 1 ms, end time 2 ms (the last step clipped to it): states at
// 0, after cycle 4 (1.2 ms: the first time past 1 ms) and after cycle 7 (2 ms).
TEST(OutputSchedule, PlotStatesAtTheFirstCyclePastEachInterval) {
  OutputSchedule sched(intervals(1e-3, 1e-4), OutputCursor{});
  const std::vector<double> t = {0.3e-3, 0.6e-3, 0.9e-3, 1.2e-3, 1.5e-3, 1.8e-3, 2.0e-3};
  EXPECT_EQ(plot_cycles(sched, t), (std::vector<int>{4, 7}));
  EXPECT_DOUBLE_EQ(sched.cursor().next_plot, 3e-3);
}

// A step longer than the interval writes one state per cycle, never two at one time, and the
// next time skips the multiples passed.
TEST(OutputSchedule, StepLongerThanTheIntervalWritesOncePerCycle) {
  OutputSchedule sched(intervals(1.0, 1.0), OutputCursor{});
  EXPECT_EQ(plot_cycles(sched, {2.5, 5.0, 5.2, 6.1}), (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(sched.cursor().next_plot, 7.0);
}

// Exact output times: the engine lands on the nearer of the next plot and history times.
TEST(OutputSchedule, LandingTimeIsTheNearerOfPlotAndHistory) {
  OutputSchedule sched(intervals(1e-3, 0.4e-3), OutputCursor{});
  sched.plot_written(0);
  sched.history_written(0);
  EXPECT_DOUBLE_EQ(sched.landing_time(), 0.4e-3);
  sched.history_written(0.8e-3);
  EXPECT_DOUBLE_EQ(sched.landing_time(), 1e-3);
  sched.plot_written(1e-3);
  EXPECT_DOUBLE_EQ(sched.landing_time(), 1.2e-3);
}

// The interface-force database takes its own interval, else the plot interval.
TEST(OutputSchedule, IntforIntervalDefaultsToThePlotInterval) {
  EXPECT_EQ(OutputSchedule(intervals(2.0, 1.0, 0), OutputCursor{}).intfor_interval(), 2.0);
  EXPECT_EQ(OutputSchedule(intervals(2.0, 1.0, 0.5), OutputCursor{}).intfor_interval(), 0.5);
  OutputSchedule sched(intervals(2.0, 1.0, 0.5), OutputCursor{});
  sched.intfor_written(0.6);
  EXPECT_EQ(sched.cursor().next_intfor, 1.0);
  EXPECT_FALSE(sched.intfor_due(0.9));
  EXPECT_TRUE(sched.intfor_due(1.0));
}

// A restart resumes the schedule where the dump left it.
TEST(OutputSchedule, RestartResumesTheCursor) {
  OutputCursor cur;
  cur.next_plot = 5.0;
  cur.next_history = 4.5;
  cur.dumps_written = 2;
  OutputSchedule sched(intervals(1.0, 0.5), cur);
  EXPECT_FALSE(sched.plot_due(4.9));
  EXPECT_TRUE(sched.plot_due(5.0));
  EXPECT_TRUE(sched.history_due(4.5));
  EXPECT_EQ(sched.next_dump_number(), 3);
  EXPECT_EQ(sched.dumps_written(), 3);
}

TEST(OutputSchedule, RestartDumpsEveryNCycles) {
  OutputSchedule sched(intervals(1.0, 1.0, -1, 3, 5), OutputCursor{});
  std::vector<int> numbered, running;
  for (int c = 1; c <= 15; ++c) {
    if (sched.numbered_dump_due(c)) numbered.push_back(c);
    if (sched.running_dump_due(c)) running.push_back(c);
  }
  EXPECT_EQ(numbered, (std::vector<int>{3, 6, 9, 12, 15}));
  EXPECT_EQ(running, (std::vector<int>{5, 10, 15}));
  OutputSchedule none(intervals(1.0, 1.0), OutputCursor{});
  EXPECT_FALSE(none.numbered_dump_due(10));
  EXPECT_FALSE(none.running_dump_due(10));
}

// Each signal is answered once; SIGINT and SIGTERM are both the stop.
TEST(SenseSwitches, EachSignalAnsweredOnce) {
  SenseSwitches sw;
  EXPECT_FALSE(sw.take_stop());
  EXPECT_FALSE(sw.take_status());
  EXPECT_FALSE(sw.take_plot_request(false));
  std::raise(SIGUSR1);
  EXPECT_TRUE(sw.take_status());
  EXPECT_FALSE(sw.take_status());
  EXPECT_FALSE(sw.take_stop());
  std::raise(SIGTERM);
  EXPECT_TRUE(sw.take_stop());
  EXPECT_FALSE(sw.take_stop());
  std::raise(SIGINT);
  EXPECT_TRUE(sw.take_stop());
}

// A plot request on a cycle that has just written a state waits for the next cycle.
TEST(SenseSwitches, PlotRequestWaitsWhileAStateAtThisTimeExists) {
  SenseSwitches sw;
  std::raise(SIGUSR2);
  EXPECT_FALSE(sw.take_plot_request(true));
  EXPECT_FALSE(sw.take_plot_request(true));
  EXPECT_TRUE(sw.take_plot_request(false));
  EXPECT_FALSE(sw.take_plot_request(false));
}

namespace {
volatile std::sig_atomic_t g_test_usr1 = 0;
extern "C" void test_usr1_handler(int) { g_test_usr1 = 1; }
}  // namespace

// The switches clear what an earlier run left and give the handlers back when they go.
TEST(SenseSwitches, RestoreThePreviousHandlers) {
  struct sigaction mine {}, old {};
  sigemptyset(&mine.sa_mask);
  mine.sa_handler = test_usr1_handler;
  sigaction(SIGUSR1, &mine, &old);
  {
    SenseSwitches first;
    std::raise(SIGUSR1);  // left unanswered
  }
  {
    SenseSwitches second;
    EXPECT_FALSE(second.take_status());
    EXPECT_EQ(g_test_usr1, 0);
  }
  std::raise(SIGUSR1);
  EXPECT_EQ(g_test_usr1, 1);
  sigaction(SIGUSR1, &old, nullptr);
}

namespace {

// A 2x2x2 copper cube translating at 10 m/s for `end` seconds, plot states every `plot_dt`, run
// as impact3d runs it (to a normal end, 8-byte words); returns the plot database's state times.
std::vector<double> plot_times(const std::string& name, double end, double plot_dt, bool exact) {
  solve_test::Box b;
  b.nx = b.ny = b.nz = 2;
  b.lx = b.ly = b.lz = 2e-3;
  Model m = solve_test::make_box_model(b, solve_test::copper_elastic(), end);
  solve_test::set_uniform_velocity(m, 10, 0, 0);
  m.control.plot_interval = plot_dt;
  m.control.th_interval = end;
  m.exact_output_times = exact;
  const std::filesystem::path dir = test_support::run_model_in(m, "run_phases", name, 8);
  PlotReader r;
  r.open((dir / "d3plot").string());
  std::vector<double> t;
  for (int i = 0; i < r.num_states(); ++i) t.push_back(r.time(i));
  return t;
}

}  // namespace

// The schedule through a whole run: with exact output times every state lands on a multiple of
// the interval (to 1e-12 relative; the end time too); without, each state is the first cycle at
// or past the multiple, less than one step after it. The step of this cube is about 0.18 us,
// the interval 1.05 us (not a multiple of it).
TEST(RunOutputSchedule, PlotStateTimesWithAndWithoutExactOutputTimes) {
  const double end = 10e-6, dt = 1.05e-6;
  const std::vector<double> exact = plot_times("exact", end, dt, true);
  // 0, 1.05, ..., 9.45 us (10 states), then the end, 10 us
  ASSERT_EQ(exact.size(), 11u);
  for (int k = 0; k < 10; ++k) EXPECT_NEAR(exact[std::size_t(k)], k * dt, 1e-12 * dt) << "state " << k;
  EXPECT_NEAR(exact.back(), end, 1e-12 * end);

  const std::vector<double> loose = plot_times("loose", end, dt, false);
  ASSERT_EQ(loose.size(), 11u);
  EXPECT_EQ(loose[0], 0.0);
  for (int k = 1; k < 10; ++k) {
    EXPECT_GE(loose[std::size_t(k)], k * dt * (1 - 1e-9)) << "state " << k;
    EXPECT_LT(loose[std::size_t(k)], k * dt + 0.2e-6) << "state " << k;
  }
  EXPECT_NEAR(loose.back(), end, 1e-12 * end);
  int off_multiple = 0;
  for (int k = 1; k < 10; ++k) off_multiple += std::fabs(loose[std::size_t(k)] - k * dt) > 1e-12 * dt;
  EXPECT_GT(off_multiple, 0);  // the exact-time landing is what put them on the multiples
}
