#pragma once
// The run log: lines to stdout (unless quiet) and to the printed file, the run's wall clock, and
// the cycle line (cycle, time, step, controlling element, energy ratio, elapsed, remaining).

#include <chrono>
#include <ostream>
#include <string>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Seconds since the run started.
class RunClock {
 public:
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

class RunLog {
 public:
  RunLog(std::ostream& printed, bool quiet) : printed_(printed), quiet_(quiet) {}
  void line(const std::string& s);
  // An error about a file (message `id`, the file named), in the log and on stderr.
  void file_error(int id, const std::string& file, const std::string& what);
  // An error without a place (the termination messages 4001-4003), in the log and on stderr.
  void error(int id, const std::string& what);

 private:
  std::ostream& printed_;
  bool quiet_;
};

// The heading of the cycle lines.
inline constexpr const char* kCycleHeading =
    "    cycle         time          dt  element  e-ratio   elapsed  remaining(s)";

// A cycle line; the time remaining is extrapolated from the time run since `start_time`.
std::string format_cycle_line(const Model& m, const State& s, double elapsed, double start_time,
                              double end_time);

}  // namespace impact3d
