// run_simulation: the run driver. It reads as the run's phases, each a unit of its own:
//   start or resume   run_start.h     initialize, or read a restart dump; the log's heading
//   the outputs       run_outputs.h   plot, interface-force and time-history databases, dumps,
//                                     written when output_schedule.h says
//   the cycle         run_cycle.h     one engine step and its log lines and run checks
//   sense switches    sense_switches.h  signals answered once per cycle
//   the end           run_end.h       final report, termination line and exit code
// docs/developer-guide.md "The run driver" describes them.

#include "impact3d/solve/run.h"

#include <omp.h>

#include <memory>

#include "common/messages.h"
#include "impact3d/parallel/comm.h"
#include "impact3d/parallel/distributed_cycle.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run_cycle.h"
#include "impact3d/solve/run_end.h"
#include "impact3d/solve/run_log.h"
#include "impact3d/solve/run_outputs.h"
#include "impact3d/solve/run_start.h"
#include "impact3d/solve/sense_switches.h"

namespace impact3d {

namespace {

// The sense switches sw4 (a plot state now) and sw2 (the status), answered after a cycle.
void answer_plot_and_status_requests(SenseSwitches& switches, RunOutputs& outputs, const RunCycle& cycle,
                                     RunLog& log) {
  if (switches.take_plot_request(outputs.plot_state_at_this_time())) {
    outputs.write_extra_plot();
    log.line(" plot state written on request (SIGUSR2, sense switch sw4)");
  }
  if (switches.take_status()) {
    const std::string line = cycle.cycle_line();
    log.line(" status (SIGUSR1, sense switch sw2):");
    log.line(kCycleHeading);
    log.line(line);
  }
}

// The sense switch sw1: a restart dump and a plot state, then the run stops.
void stop_on_request(const State& s, RunOutputs& outputs, RunLog& log) {
  log.line(render(Diagnostic{5001, Severity::info, Location{}, "at cycle " + std::to_string(s.cycle)}));
  outputs.write_numbered_dump();
  outputs.write_extra_plot();
}

}  // namespace

int run_simulation(const Model& model, const RunOptions& opt, std::ostream& printed) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  Engine engine(model);
  // under mpirun with several ranks (docs/cluster.md): rank 0 runs this driver, the other
  // ranks follow its commands
  std::unique_ptr<parallel::DistributedCycle> distributed;
  if (parallel::size() > 1) {
    distributed = std::make_unique<parallel::DistributedCycle>();
    engine.distribute(distributed.get());
    distributed->restart_from(opt.restart);
    if (!distributed->leads()) return distributed->follow(engine);
  }
  auto finish = [&engine](int code) {
    engine.release_followers(code);
    return code;
  };
  RunLog log(printed, opt.quiet);
  const RunClock clock;

  const RunStart start = start_or_resume(engine, opt, log);
  if (!start.ok) return finish(exit_code::file_error);
  RunOutputs outputs(engine, opt, log, clock, start.cursor, start.restarting);
  if (!outputs.open()) return finish(exit_code::file_error);
  StepStatus st = start.status;
  if (!start.restarting && st == StepStatus::ok) outputs.write_first();

  SenseSwitches switches;
  RunCycle cycle(engine, log, clock, start.time);
  bool stopped = false;
  while (st == StepStatus::ok && outputs.ok()) {
    if (model.exact_output_times) engine.land_on(outputs.schedule().landing_time());
    st = cycle.step();
    if (st != StepStatus::ok) break;
    outputs.write_scheduled();
    answer_plot_and_status_requests(switches, outputs, cycle, log);
    outputs.write_cycle_dumps();
    if (switches.take_stop()) {
      stopped = true;
      stop_on_request(engine.state(), outputs, log);
      break;
    }
  }
  // the final state (normal end) or the last state reached (error termination)
  if (!stopped) outputs.write_last(st);
  outputs.flush();
  outputs.sync();

  engine.gather_for_output();  // (the final report reads the whole State)
  write_final_report(engine, outputs, cycle, clock.elapsed(), opt, log);
  return finish(terminate_run(engine, st, stopped, outputs, cycle, opt, log));
}

}  // namespace impact3d
