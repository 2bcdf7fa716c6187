#include "impact3d/solve/run_log.h"

#include <cstdio>
#include <iostream>

#include "common/messages.h"

namespace impact3d {

void RunLog::line(const std::string& s) {
  if (!quiet_) std::cout << s << '\n' << std::flush;
  printed_ << s << '\n' << std::flush;
}

void RunLog::file_error(int id, const std::string& file, const std::string& what) {
  Diagnostic d{id, Severity::error, Location{file, 0, {}, {}, 0, 0, {}, false}, what};
  line(render(d));
  std::cerr << "impact3d: " << render(d) << "\n";
}

void RunLog::error(int id, const std::string& what) {
  Diagnostic d{id, Severity::error, Location{}, what};
  line(render(d));
  std::cerr << "impact3d: " << render(d) << "\n";
}

std::string format_cycle_line(const Model& m, const State& s, double elapsed, double start_time,
                              double end_time) {
  char buf[200];
  const double done = s.time - start_time;
  double remaining = done > 0 ? elapsed * (end_time - s.time) / done : 0;
  std::snprintf(buf, sizeof buf, " %8d %12.5e %11.4e %8d %9.5f %9.2f %9.2f", s.cycle, s.time,
                s.dt_next, s.dt_elem >= 0 ? m.hex_id(s.dt_elem) : 0, s.energy_ratio(), elapsed, remaining);
  return buf;
}

}  // namespace impact3d
