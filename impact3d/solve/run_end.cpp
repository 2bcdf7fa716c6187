#include "impact3d/solve/run_end.h"

#include <cstdio>

#include "common/messages.h"
#include "impact3d/parallel/distributed_cycle.h"
#include "impact3d/solve/run_report.h"

namespace impact3d {

namespace {

void log_states_written(const RunOutputs& outputs, const RunOptions& opt, RunLog& log) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "\n plot database %s: %d state(s) written", opt.plot.c_str(), outputs.plot_states());
  log.line(buf);
  if (outputs.intfor_wanted()) {
    std::snprintf(buf, sizeof buf, " interface-force database %s: %d state(s) written", outputs.intfor_root().c_str(),
                  outputs.intfor_states());
    log.line(buf);
  }
}

void log_timings(const Engine& engine, const State& s, double seconds, double output_seconds, RunLog& log) {
  char buf[400];
  std::snprintf(buf, sizeof buf, " cycles %d, elapsed %.3f s (%.3f us per element-cycle)", s.cycle, seconds,
                s.cycle && s.ne + s.shells.ns ? 1e6 * seconds / (double(s.cycle) * (s.ne + s.shells.ns)) : 0.0);
  log.line(buf);
  const PhaseTimes& pt = engine.phase_times();
  std::snprintf(buf, sizeof buf,
                " phase times (s): elements %.3f  nodes %.3f  walls %.3f  contact %.3f  output %.3f",
                pt.elements, pt.nodes, pt.walls, pt.contact, output_seconds);
  log.line(buf);
  if (const parallel::DistributedCycle* d = engine.distribution()) {  // (in the phases above)
    std::snprintf(buf, sizeof buf,
                  " communication on rank 0 (%d ranks): %.3f s in the cycle's messages, %.1f us per cycle; "
                  "output gathers %.3f s",
                  d->domain().nranks, d->cycle_comm_seconds(), s.cycle ? 1e6 * d->cycle_comm_seconds() / s.cycle : 0.0,
                  d->output_gather_seconds());
    log.line(buf);
  }
}

// Message 4001-4003 and 4007: the detail for an error termination `st`.
std::string error_detail(const Engine& engine, StepStatus st) {
  const Model& model = engine.model();
  const State& s = engine.state();
  const int e = engine.error_element();
  char buf[300];
  switch (st) {
    case StepStatus::negative_volume:
      // (an index past the solids is a shell: non-positive area)
      std::snprintf(buf, sizeof buf, "%s element %d at cycle %d, time %.6e",
                    e >= model.num_hexes() + model.num_shells() ? "beam (zero length)"
                    : e >= model.num_hexes()                    ? "shell (non-positive area)"
                                                                : "solid",
                    model.hex_id(e), s.cycle, s.time);
      break;
    case StepStatus::non_finite:
      std::snprintf(buf, sizeof buf, "%s%d at cycle %d, time %.6e",
                    e >= model.num_hexes() + model.num_shells() ? "beam element "
                    : e >= model.num_hexes()                    ? "shell element "
                    : e >= 0                                    ? "solid element "
                                                                : "kinetic energy; element ",
                    e >= 0 ? model.hex_id(e) : 0, s.cycle, s.time);
      break;
    case StepStatus::diverged:
      std::snprintf(buf, sizeof buf,
                    "total energy %.4e is %.4g times the initial energy + external work %.4e (limit %.0f) at cycle "
                    "%d, time %.6e; the step was set by element %d",
                    s.total_energy(), s.energy_ratio(), s.initial_total + s.external_work, kDivergedEnergyRatio,
                    s.cycle, s.time, s.dt_elem >= 0 ? model.hex_id(s.dt_elem) : 0);
      break;
    default:
      std::snprintf(buf, sizeof buf, "dt %.4e below %.4g x first step, element %d, cycle %d, time %.6e",
                    s.dt_next, model.control.min_step_factor, s.dt_elem >= 0 ? model.hex_id(s.dt_elem) : 0, s.cycle,
                    s.time);
      break;
  }
  return buf;
}

int error_message_of(StepStatus st) {
  switch (st) {
    case StepStatus::negative_volume: return 4001;
    case StepStatus::non_finite: return 4002;
    case StepStatus::diverged: return 4007;
    default: return 4003;
  }
}

}  // namespace

void write_final_report(const Engine& engine, const RunOutputs& outputs, RunCycle& cycle, double seconds,
                        const RunOptions& opt, RunLog& log) {
  const Model& model = engine.model();
  const State& s = engine.state();
  log_states_written(outputs, opt, log);
  log.line("\n energies at the end (time " + std::to_string(s.time) + "):\n" + energy_report(s));
  if (model.control.mass_scaling_dt != 0) log.line(mass_scaling_report(model.control, s));
  if (engine.added_mass_limit_reached()) {
    char buf[200];
    std::snprintf(buf, sizeof buf, " the added mass reached ENDMAS (%.4g %%): the run ends here", model.control.end_mass_percent);
    log.line(buf);
  }
  if (cycle.refused_contacts() > 0) {
    char rb[200];
    std::snprintf(rb, sizeof rb,
                  "\n contact: %lld node-cycle(s) found deeper than penetration growth allows were not caught "
                  "(README, Contact)", cycle.refused_contacts());
    log.line(rb);
  }
  for (const std::string& l : final_shape_lines(model, s, measure_final_shape(s))) log.line(l);
  log_timings(engine, s, seconds, outputs.seconds(), log);
  for (const std::string& l : cycle.check_now()) log.line(l);
  log.line("\n " + cycle.checks().verdict_line());
}

int terminate_run(const Engine& engine, StepStatus st, bool stopped, const RunOutputs& outputs,
                  const RunCycle& cycle, const RunOptions& opt, RunLog& log) {
  if (!outputs.ok()) {
    log.line("\n E r r o r   t e r m i n a t i o n   (output write failed)");
    return exit_code::file_error;
  }
  if (stopped) {
    log.line("\n E r r o r   t e r m i n a t i o n   (stopped by signal: restart with r=" +
             outputs.last_numbered_dump() + ")");
    return exit_code::stopped_by_signal;
  }
  if (st == StepStatus::finished) {
    log.line("\n N o r m a l   t e r m i n a t i o n");
    return opt.strict && cycle.checks().suspect() ? exit_code::suspect_run : exit_code::ok;
  }
  const int msg = error_message_of(st);
  log.error(msg, error_detail(engine, st));
  log.line("\n E r r o r   t e r m i n a t i o n   (" + std::string(message_def(msg).text) + ")");
  return exit_code::error_termination;
}

}  // namespace impact3d
