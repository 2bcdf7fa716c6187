#pragma once
// The output files of a run and their writing: the plot database (d3plot family), the
// interface-force database (intfor), the time histories (d3thdt and the ASCII files) and the
// restart dumps, opened new or resumed from a restart dump's cursor. When to write is the
// OutputSchedule's (output_schedule.h); this writes, logs a failed write (message 4004, 3004 for
// a dump) and keeps going, so that the run ends with the output error's termination.

#include <string>

#include "impact3d/output/history_output.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/output_schedule.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/run_log.h"

namespace impact3d {

class RunOutputs {
 public:
  RunOutputs(Engine& engine, const RunOptions& opt, RunLog& log, const RunClock& clock,
             const OutputCursor& cursor, bool restarting);

  // Opens (or, restarting, resumes) the databases; false: refused, the error and the
  // termination line logged.
  bool open();

  // The state at the start of a new run: plot, history and intfor states.
  void write_first();
  // After a cycle: the plot, history and intfor states the schedule finds due.
  void write_scheduled();
  // A plot state outside the schedule (sense switch sw4, the stop): none when one at this time
  // exists.
  void write_extra_plot() { write_plot(false); }
  bool plot_state_at_this_time() const;
  // After a cycle: the numbered and running restart dumps due.
  void write_cycle_dumps();
  // The next numbered restart dump, now (the stop).
  void write_numbered_dump();
  // At the end (normal or error termination, not a stop): the last state reached, and at a
  // normal end the final history and intfor states.
  void write_last(StepStatus st);
  void flush() { history_.flush(); }
  // Makes every state written so far durable (fsync of the binary databases; before a restart
  // dump and at the end): false, and message 4004 logged, when that fails.
  bool sync();

  bool ok() const { return ok_; }
  OutputSchedule& schedule() { return schedule_; }
  int plot_states() const { return plot_.states_written(); }
  bool intfor_wanted() const { return want_intfor_; }
  const std::string& intfor_root() const { return intfor_root_; }
  int intfor_states() const { return intfor_.states_written(); }
  std::string last_numbered_dump() const;
  double seconds() const { return seconds_; }  // wall-clock time spent writing plot states and histories

 private:
  // Runs `how`; on an exception logs 3004 (4006 restarting: a restart problem) naming `file`
  // and the termination line with `why`.
  bool open_one(void (RunOutputs::*how)(), const std::string& file, const char* why);
  void open_plot();
  void open_intfor();
  void open_history();
  void write_plot(bool scheduled);
  void write_intfor();
  void write_history();
  bool write_dump(const std::string& path);
  DumpHeader dump_header();

  Engine& engine_;
  const Model& model_;
  State& s_;
  const RunOptions& opt_;
  RunLog& log_;
  const RunClock& clock_;
  const bool restarting_;
  OutputSchedule schedule_;
  const std::int64_t member_words_;
  const std::string out_dir_;  // the printed file's folder: time histories
  PlotOutput plot_;
  HistoryOutput history_;
  IntforOutput intfor_;
  const bool want_intfor_;
  const std::string intfor_root_;
  bool ok_ = true;
  int scheduled_plot_states_;  // states a restart keeps (not sense-switch extras)
  double last_history_time_ = -1;
  double seconds_ = 0;
  std::string deck_text_;
};

}  // namespace impact3d
