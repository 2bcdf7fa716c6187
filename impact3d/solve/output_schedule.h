#pragma once
// The output schedule of a run: when it writes a plot state, a time-history state, an
// interface-force state and a restart dump. Pure arithmetic on times and cycles (no files):
// run_outputs.h writes what this says is due.
//
// A state is due once the time reaches its next output time to a relative 1e-9 (so a step that
// lands a rounding short of it still writes); after a write, the next time is the first multiple
// of the interval past the time written (again to 1e-9, so a time a rounding short of a multiple
// does not write that multiple twice). With exact output times (*CONTROL_OUTPUT / the deck's
// choice) the engine shortens the step to land on the nearer of the next plot and history times.

#include "impact3d/model/model.h"
#include "impact3d/output/restart_dump.h"

namespace impact3d {

class OutputSchedule {
 public:
  // The intervals from the model's control data; `cursor`: where a run starts (zero) or the
  // restart dump's cursor on a restart.
  OutputSchedule(const ControlData& control, const OutputCursor& cursor);

  // The first multiple of `interval` after `time` (a time within 1e-9 of a multiple counts as it).
  static double next_after(double time, double interval);
  // Whether `time` has reached `next` (to a relative 1e-9).
  static bool reached(double time, double next);

  bool plot_due(double time) const { return reached(time, cursor_.next_plot); }
  bool history_due(double time) const { return reached(time, cursor_.next_history); }
  bool intfor_due(double time) const { return reached(time, cursor_.next_intfor); }
  // After a scheduled state written at `time`: the next one.
  void plot_written(double time) { cursor_.next_plot = next_after(time, plot_interval_); }
  void history_written(double time) { cursor_.next_history = next_after(time, history_interval_); }
  void intfor_written(double time) { cursor_.next_intfor = next_after(time, intfor_interval_); }
  // The time the engine lands on with exact output times: the next plot or history time.
  double landing_time() const;

  // Restart dumps after cycle `cycle`: a numbered one every restart_dump_cycles (d3dump01, 02,
  // ...), the running one (runrsf, overwritten) every running_restart_cycles; 0: none.
  bool numbered_dump_due(int cycle) const { return dump_cycles_ > 0 && cycle % dump_cycles_ == 0; }
  bool running_dump_due(int cycle) const { return running_cycles_ > 0 && cycle % running_cycles_ == 0; }
  // The number of the next numbered dump (counts it as written).
  int next_dump_number() { return ++cursor_.dumps_written; }
  int dumps_written() const { return cursor_.dumps_written; }

  double plot_interval() const { return plot_interval_; }
  double history_interval() const { return history_interval_; }
  double intfor_interval() const { return intfor_interval_; }
  // The cursor a restart dump keeps (the state counts are filled in by the writer).
  const OutputCursor& cursor() const { return cursor_; }

 private:
  OutputCursor cursor_;
  double plot_interval_, history_interval_;
  double intfor_interval_;  // *DATABASE_BINARY_INTFOR's DT, else the plot interval
  int dump_cycles_, running_cycles_;
};

}  // namespace impact3d
