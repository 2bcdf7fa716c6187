#pragma once
// The first phase of a run: start (initialize the State from the Model) or resume (read the
// State, the sliding interfaces' data and the output cursor from a restart dump, r=), then the
// run log's heading (threads, first step or restart point, mass scaling, the cycle heading).

#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/run_log.h"

namespace impact3d {

struct RunStart {
  bool ok = true;            // false: the restart dump was refused (4005 and the termination logged)
  bool restarting = false;
  StepStatus status = StepStatus::ok;  // finished: a restart from a dump at the end time
  OutputCursor cursor;       // where the output schedule stands (zero on a new run)
  double time = 0;           // the time the run starts from
};

RunStart start_or_resume(Engine& engine, const RunOptions& opt, RunLog& log);

}  // namespace impact3d
