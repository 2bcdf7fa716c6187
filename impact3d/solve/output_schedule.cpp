#include "impact3d/solve/output_schedule.h"

#include <algorithm>
#include <cmath>

namespace impact3d {

OutputSchedule::OutputSchedule(const ControlData& control, const OutputCursor& cursor)
    : cursor_(cursor),
      plot_interval_(control.plot_interval),
      history_interval_(control.th_interval),
      intfor_interval_(control.intfor_interval > 0 ? control.intfor_interval : control.plot_interval),
      dump_cycles_(control.restart_dump_cycles),
      running_cycles_(control.running_restart_cycles) {}

double OutputSchedule::next_after(double time, double interval) {
  return (std::floor(time / interval + 1e-9) + 1) * interval;
}

bool OutputSchedule::reached(double time, double next) { return time >= next * (1 - 1e-9); }

double OutputSchedule::landing_time() const { return std::min(cursor_.next_plot, cursor_.next_history); }

}  // namespace impact3d
