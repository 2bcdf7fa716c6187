#include "impact3d/solve/run_cycle.h"

#include <algorithm>

#include "common/messages.h"
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

std::vector<std::string> RunCycle::check_now() { return checks_.check_state({model_, s_, refused_contacts_}); }

}  // namespace impact3d
