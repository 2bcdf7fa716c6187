#include "impact3d/solve/run_start.h"

#include <omp.h>

#include <cstdio>

#include "impact3d/parallel/distributed_cycle.h"
#include "impact3d/solve/run_report.h"

namespace impact3d {

namespace {

// Reads the restart dump into the engine; false: refused (logged).
bool resume(Engine& engine, const std::string& path, OutputCursor& cursor, RunLog& log) {
  try {
    cursor = read_restart_dump_header(path).cursor;
    SlidingInterfaces::RestartData cd;
    read_restart_dump_state(path, engine.state(), cd);
    engine.contact().restore(cd);
    // a distributed run: every other rank reads the same dump now
    if (parallel::DistributedCycle* d = engine.distribution(); d && d->leads())
      d->announce(parallel::DistributedCycle::Op::resume);
  } catch (const std::exception& ex) {
    log.file_error(4005, path, ex.what());
    log.line("\n E r r o r   t e r m i n a t i o n   (restart dump is invalid)");
    return false;
  }
  return true;
}

// (a distributed run: its partition, distributed_cycle.h)
void log_heading(const Model& model, const State& s, const RunOptions& opt, bool restarting,
                 const parallel::DistributedCycle* distributed, RunLog& log) {
  char buf[300];
  if (restarting)
    std::snprintf(buf, sizeof buf, "\n restart from %s at cycle %d, time %.6e\n threads: %d\n",
                  opt.restart.c_str(), s.cycle, s.time, omp_get_max_threads());
  else
    std::snprintf(buf, sizeof buf, "\n threads: %d\n first time step %.5e (element %d)\n",
                  omp_get_max_threads(), s.dt_next, s.dt_elem >= 0 ? model.hex_id(s.dt_elem) : 0);
  log.line(buf);
  if (model.control.mass_scaling_dt != 0) log.line(mass_scaling_report(model.control, s));
  if (distributed) log.line(distributed->report() + "\n");
  log.line(kCycleHeading);
}

}  // namespace

RunStart start_or_resume(Engine& engine, const RunOptions& opt, RunLog& log) {
  RunStart r;
  r.status = engine.initialize();
  r.restarting = !opt.restart.empty();
  if (r.restarting) {
    if (!resume(engine, opt.restart, r.cursor, log)) {
      r.ok = false;
      return r;
    }
    r.status = engine.finished() ? StepStatus::finished : StepStatus::ok;
  }
  r.time = engine.state().time;
  log_heading(engine.model(), engine.state(), opt, r.restarting, engine.distribution(), log);
  return r;
}

}  // namespace impact3d
