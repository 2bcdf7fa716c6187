// run_simulation: drives the Engine with the run log (stdout and the printed file), output
// triggers and the termination messages.

#include "impact3d/solve/run.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "common/messages.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/solve/engine.h"

namespace impact3d {

namespace {

class RunLog {
 public:
  RunLog(std::ostream& printed, bool quiet) : printed_(printed), quiet_(quiet) {}
  void line(const std::string& s) {
    if (!quiet_) std::cout << s << '\n' << std::flush;
    printed_ << s << '\n';
  }

 private:
  std::ostream& printed_;
  bool quiet_;
};

std::string format_cycle_line(const State& s, double elapsed, double end_time) {
  char buf[200];
  double remaining = s.time > 0 ? elapsed * (end_time - s.time) / s.time : 0;
  std::snprintf(buf, sizeof buf, " %8d %12.5e %11.4e %8d %9.5f %9.2f %9.2f", s.cycle, s.time,
                s.dt_next, s.dt_elem + 1, s.energy_ratio(), elapsed, remaining);
  return buf;
}

std::string energy_report(const State& s) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "     kinetic energy ....................... %14.6e\n"
                "     internal energy ...................... %14.6e\n"
                "     hourglass energy ..................... %14.6e\n"
                "     bulk viscosity energy ................ %14.6e\n"
                "     rigid-wall energy (taken by walls) ... %14.6e\n"
                "     contact energy ....................... %14.6e\n"
                "     external work ........................ %14.6e\n"
                "     total energy ......................... %14.6e\n"
                "     initial total energy ................. %14.6e\n"
                "     energy ratio (total/(initial+ext)) ... %14.6f",
                s.kinetic, s.internal, s.hourglass, s.bulk_viscous, s.wall_work, s.contact,
                s.external_work, s.total_energy(), s.initial_total, s.energy_ratio());
  return buf;
}

}  // namespace

int run_simulation(const Model& model, const RunOptions& opt, std::ostream& printed) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  RunLog log(printed, opt.quiet);
  if (!model.interfaces.empty()) {
    Diagnostic d{1102, Severity::error, Location{model.deck_file, model.interfaces[0].line, "sliding interface 1", {}, 0, 0, {}, false},
                 "sliding interfaces are read and checked, but the contact engine is not in this version"};
    log.line(render(d));
    log.line("\n E r r o r   t e r m i n a t i o n   (unsupported feature)");
    return exit_code::input_error;
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  Engine engine(model);
  StepStatus st = engine.initialize();
  const State& s = engine.state();
  {
    char buf[200];
    std::snprintf(buf, sizeof buf, "\n threads: %d\n first time step %.5e (element %d)\n",
                  omp_get_max_threads(), s.dt_next, s.dt_elem + 1);
    log.line(buf);
    log.line("    cycle         time          dt  element  e-ratio   elapsed  remaining(s)");
  }
  // plot states: t = 0, every plot interval, the end (and the last state of an error)
  PlotOutput plot;
  const double plot_dt = model.control.plot_interval;
  double next_plot = 0;
  auto write_plot = [&]() -> bool {
    try {
      plot.write(model, s);
    } catch (const std::exception& ex) {
      Diagnostic d{4004, Severity::error, Location{opt.plot, 0, {}, {}, 0, 0, {}, false}, ex.what()};
      log.line(render(d));
      std::cerr << "impact3d: " << render(d) << "\n";
      return false;
    }
    next_plot = (std::floor(s.time / plot_dt + 1e-9) + 1) * plot_dt;
    return true;
  };
  try {
    plot.open(model, opt.plot);
  } catch (const std::exception& ex) {
    Diagnostic d{3004, Severity::error, Location{opt.plot, 0, {}, {}, 0, 0, {}, false}, ex.what()};
    log.line(render(d));
    std::cerr << "impact3d: " << render(d) << "\n";
    return exit_code::file_error;
  }
  bool plot_ok = st != StepStatus::ok || write_plot();
  const int report = std::max(1, model.control.report_interval);
  while (st == StepStatus::ok && plot_ok) {
    st = engine.step();
    if (s.cycle % report == 0 || st != StepStatus::ok)
      log.line(format_cycle_line(s, elapsed(), model.control.end_time));
    if (st == StepStatus::ok && s.time >= next_plot * (1 - 1e-9)) plot_ok = write_plot();
  }
  // the final state (normal end) or the last state reached (error termination)
  if (plot_ok && plot.last_time() != s.time) plot_ok = write_plot();
  {
    char buf[200];
    std::snprintf(buf, sizeof buf, "\n plot database %s: %d state(s) written", opt.plot.c_str(), plot.states_written());
    log.line(buf);
  }
  if (!plot_ok) {
    log.line("\n E r r o r   t e r m i n a t i o n   (plot database write failed)");
    return exit_code::file_error;
  }
  const double cpu = elapsed();
  log.line("\n energies at the end (time " + std::to_string(s.time) + "):\n" + energy_report(s));
  {
    // summary of the final shape: extents and the largest plastic strain
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int i = 0; i < s.nn; ++i) {
      const double p[3] = {s.x[std::size_t(i)], s.y[std::size_t(i)], s.z[std::size_t(i)]};
      for (int a = 0; a < 3; ++a) { lo[a] = std::min(lo[a], p[a]); hi[a] = std::max(hi[a], p[a]); }
    }
    int emax = 0;
    for (int e = 1; e < s.ne; ++e)
      if (s.eps_p[std::size_t(e)] > s.eps_p[std::size_t(emax)]) emax = e;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "\n final extents: x [%.6e, %.6e]  y [%.6e, %.6e]  z [%.6e, %.6e]\n"
                  " maximum effective plastic strain %.5f in element %d\n"
                  " cycles %d, elapsed %.3f s (%.3f us per element-cycle)",
                  lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], s.ne ? s.eps_p[std::size_t(emax)] : 0.0,
                  emax + 1, s.cycle, cpu, s.cycle && s.ne ? 1e6 * cpu / (double(s.cycle) * s.ne) : 0.0);
    log.line(buf);
  }
  if (st == StepStatus::finished) {
    log.line("\n N o r m a l   t e r m i n a t i o n");
    return exit_code::ok;
  }
  std::string why;
  int msg = 4001;
  char buf[300];
  switch (st) {
    case StepStatus::negative_volume:
      msg = 4001;
      std::snprintf(buf, sizeof buf, "solid element %d at cycle %d, time %.6e", engine.error_element() + 1, s.cycle, s.time);
      why = buf;
      break;
    case StepStatus::non_finite:
      msg = 4002;
      std::snprintf(buf, sizeof buf, "%s%d at cycle %d, time %.6e",
                    engine.error_element() >= 0 ? "solid element " : "kinetic energy; element ",
                    engine.error_element() + 1, s.cycle, s.time);
      why = buf;
      break;
    default:
      msg = 4003;
      std::snprintf(buf, sizeof buf, "dt %.4e below %.4g x first step, element %d, cycle %d, time %.6e",
                    s.dt_next, model.control.min_step_factor, s.dt_elem + 1, s.cycle, s.time);
      why = buf;
      break;
  }
  Diagnostic d{msg, Severity::error, Location{}, why};
  log.line(render(d));
  std::cerr << "impact3d: " << render(d) << "\n";
  log.line("\n E r r o r   t e r m i n a t i o n   (" + std::string(message_def(msg).text) + ")");
  return exit_code::error_termination;
}

}  // namespace impact3d
