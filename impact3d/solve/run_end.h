#pragma once
// The last phase of a run: the final report in the run log (states written, energies, mass
// scaling, contact misses, final shape, timings, run checks and their verdict) and the
// termination (its line and the exit code, common/messages.h).

#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/run_cycle.h"
#include "impact3d/solve/run_log.h"
#include "impact3d/solve/run_outputs.h"

namespace impact3d {

// `seconds`: the run's wall-clock time.
void write_final_report(const Engine& engine, const RunOutputs& outputs, RunCycle& cycle, double seconds,
                        const RunOptions& opt, RunLog& log);

// How the run ended: the output error, a stop by signal (naming the dump to restart from), the
// normal end (suspect with --strict: exit code 7) or an error termination (4001-4003, naming the
// element, cycle and time). Logs the termination line; returns the exit code.
int terminate_run(const Engine& engine, StepStatus st, bool stopped, const RunOutputs& outputs,
                  const RunCycle& cycle, const RunOptions& opt, RunLog& log);

}  // namespace impact3d
