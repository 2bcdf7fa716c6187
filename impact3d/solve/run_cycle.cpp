#include "impact3d/solve/run_cycle.h"

#include <algorithm>
#include <limits>

#include "common/messages.h"
#include "impact3d/solve/node_processing.h"
#include "impact3d/solve/run_report.h"

namespace impact3d {

RunCycle::RunCycle(Engine& engine, RunLog& log, const RunClock& clock, double start_time)
    : engine_(engine),
      model_(engine.model()),
      s_(engine.state()),
      log_(log),
      clock_(clock),
      start_time_(start_time),
      report_(std::max(1, engine.model().control.report_interval)),
      checks_(engine.state()) {}

StepStatus RunCycle::step() {
  before_ = {s_.internal + s_.hourglass + s_.bulk_viscous, s_.contact + s_.wall_work, s_.external_work, s_.dt_half, true};
  const StepStatus st = engine_.step();
  if (!engine_.contact().empty()) refused_contacts_ += engine_.contact().search_stats().refused;
  log_failures();
  if (s_.cycle % report_ == 0 || st != StepStatus::ok) {
    log_.line(cycle_line());
    for (const std::string& l : check_now()) log_.line(l);
  }
  return st;
}

void RunCycle::log_failures() {
  for (std::size_t k = 0; k < s_.newly_failed.size(); ++k)
    log_.line(render(Diagnostic{5004, Severity::info, Location{},
                                describe_solid_failure(model_, s_, s_.newly_failed[k], s_.newly_failed_cause[k])}));
  for (int b : s_.beams.newly_failed)
    log_.line(render(Diagnostic{5005, Severity::info, Location{}, describe_beam_failure(model_, s_, b)}));
  for (int r : s_.newly_released)
    log_.line(render(Diagnostic{5006, Severity::info, Location{}, describe_weld_release(model_, s_, r)}));
}

std::string RunCycle::cycle_line() const {
  return format_cycle_line(model_, s_, clock_.elapsed(), start_time_, model_.control.end_time);
}

// The time-centred book at t^n after a step from t^n: kinetic energy sum 1/2 m v^{n-1/2} . v^{n+1/2}
// (nodes, and rotations: ShellState::rot_kinetic_centred) with the element energies at x^n, and the
// contact, wall and external work at the mean of their books before and after the step. For
// linear forces the central-difference update holds it exactly (docs/command-line.md, "Run
// checks"). NaN before the first cycle. A distributed run gathers every node's velocities to rank
// 0 first (check_now), which makes the same sum in node order.
double RunCycle::time_centred_ratio() const {
  if (!before_.known) return std::numeric_limits<double>::quiet_NaN();
  // r: 1 but where the step changed, as on the last step, which lands on the end time (without it
  // that step's change alone moved the ratio; time_centred_product)
  const double r = before_.dt_half > 0 && s_.dt_vel > 0 ? before_.dt_half / s_.dt_vel : 1.0;
  double ke = s_.shells.rot_kinetic_centred;
  for (int i = 0; i < s_.nn; ++i) {
    const std::size_t k = std::size_t(i);
    ke += 0.5 * s_.mass[k] * time_centred_product(s_.vx_old[k], s_.vy_old[k], s_.vz_old[k], s_.vx[k], s_.vy[k], s_.vz[k], r);
  }
  const double e = ke + before_.elements + 0.5 * (before_.contact_walls + s_.contact + s_.wall_work);
  const double ref = s_.initial_total + 0.5 * (before_.external + s_.external_work);
  return ref != 0 ? e / ref : std::numeric_limits<double>::quiet_NaN();
}

std::vector<std::string> RunCycle::check_now() {
  if (before_.known) engine_.gather_velocities();  // a distributed run: every rank's nodes to rank 0
  return checks_.check_state({model_, s_, refused_contacts_, time_centred_ratio()});
}

}  // namespace impact3d
