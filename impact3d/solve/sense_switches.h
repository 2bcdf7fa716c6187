#pragma once
// DYNA3D's sense switches as signals, set by signal handlers and answered once per cycle by the
// run driver (docs/output-files.md):
//   SIGINT, SIGTERM  sw1: write a restart dump and a plot state, then stop (exit code 5);
//   SIGUSR1          sw2: print the time, cycle, step and the time remaining;
//   SIGUSR2          sw4: write a plot state now.
// One SenseSwitches object at a time: it installs the handlers (clearing requests left from an
// earlier run) and restores the previous ones when it goes.

#include <csignal>

namespace impact3d {

class SenseSwitches {
 public:
  SenseSwitches();
  ~SenseSwitches();
  SenseSwitches(const SenseSwitches&) = delete;
  SenseSwitches& operator=(const SenseSwitches&) = delete;

  // Each answers whether its switch was set since it was last answered, and clears it.
  bool take_stop();
  bool take_status();
  // A plot-state request waits while a state at this time exists (`state_at_this_time`: the
  // cycle has just written one), so the extra state never repeats a time; it is answered (true,
  // cleared) on the first cycle without one.
  bool take_plot_request(bool state_at_this_time);

 private:
  struct sigaction old_int_ {}, old_term_ {}, old_usr1_ {}, old_usr2_ {};
};

}  // namespace impact3d
