#pragma once
// One cycle of a run as the run log sees it: the engine's step, then the deletions and releases
// it made (messages 5004-5006), and every report interval (and at the last cycle) the cycle line
// and the run checks (run_checks.h). It also counts the contact misses over the run.

#include <string>
#include <vector>

#include "impact3d/solve/engine.h"
#include "impact3d/solve/run_checks.h"
#include "impact3d/solve/run_log.h"

namespace impact3d {

class RunCycle {
 public:
  // `start_time`: the time the run started from (the time remaining is extrapolated from it).
  RunCycle(Engine& engine, RunLog& log, const RunClock& clock, double start_time);

  StepStatus step();
  // The cycle line now (the status sense switch prints it outside the report interval).
  std::string cycle_line() const;
  // The run checks on the state now (their new findings' lines), and the verdict.
  std::vector<std::string> check_now();
  const RunChecks& checks() const { return checks_; }
  long long refused_contacts() const { return refused_contacts_; }

 private:
  void log_failures();
  double time_centred_ratio() const;

  // The books at t^n, taken before each step: the element energies (at x^n until the step's
  // element pass), the contact and wall work and the external work booked so far.
  struct BooksAtN {
    double elements = 0, contact_walls = 0, external = 0;
    double dt_half = 0;  // dt^{n-1/2}
    bool known = false;
  };

  Engine& engine_;
  const Model& model_;
  const State& s_;
  RunLog& log_;
  const RunClock& clock_;
  const double start_time_;
  const int report_;              // cycles between cycle lines
  RunChecks checks_;
  long long refused_contacts_ = 0;  // node-cycles the penetration-growth rule did not catch
  BooksAtN before_;
};

}  // namespace impact3d
