// run_simulation: drives the Engine with the run log (stdout and the printed file), the output
// schedule (plot states, time histories, restart dumps), the sense switches (signals) and the
// termination messages.

#include "impact3d/solve/run.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "common/messages.h"
#include "impact3d/output/history_output.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/mass_scaling.h"
#include "impact3d/solve/run_checks.h"
#include "impact3d/solve/run_report.h"

namespace impact3d {

namespace {

// Sense switches (DYNA3D sw1, sw2, sw4): set by signal handlers, polled once per cycle.
volatile std::sig_atomic_t g_stop = 0;        // SIGINT, SIGTERM: dump + plot state, stop
volatile std::sig_atomic_t g_status = 0;      // SIGUSR1: print time, cycle, step, remaining
volatile std::sig_atomic_t g_plot_now = 0;    // SIGUSR2: write a plot state now
extern "C" void on_stop_signal(int) { g_stop = 1; }
extern "C" void on_status_signal(int) { g_status = 1; }
extern "C" void on_plot_signal(int) { g_plot_now = 1; }

class SenseSwitches {
 public:
  SenseSwitches() {
    g_stop = 0;
    g_status = 0;
    g_plot_now = 0;
    struct sigaction sa {};
    sigemptyset(&sa.sa_mask);
    sa.sa_handler = on_stop_signal;
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
    sa.sa_handler = on_status_signal;
    sigaction(SIGUSR1, &sa, &old_usr1_);
    sa.sa_handler = on_plot_signal;
    sigaction(SIGUSR2, &sa, &old_usr2_);
  }
  ~SenseSwitches() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
    sigaction(SIGUSR1, &old_usr1_, nullptr);
    sigaction(SIGUSR2, &old_usr2_, nullptr);
  }

 private:
  struct sigaction old_int_ {}, old_term_ {}, old_usr1_ {}, old_usr2_ {};
};

class RunLog {
 public:
  RunLog(std::ostream& printed, bool quiet) : printed_(printed), quiet_(quiet) {}
  void line(const std::string& s) {
    if (!quiet_) std::cout << s << '\n' << std::flush;
    printed_ << s << '\n' << std::flush;
  }

 private:
  std::ostream& printed_;
  bool quiet_;
};

std::string format_cycle_line(const Model& m, const State& s, double elapsed, double start_time,
                              double end_time) {
  char buf[200];
  const double done = s.time - start_time;
  double remaining = done > 0 ? elapsed * (end_time - s.time) / done : 0;
  std::snprintf(buf, sizeof buf, " %8d %12.5e %11.4e %8d %9.5f %9.2f %9.2f", s.cycle, s.time,
                s.dt_next, s.dt_elem >= 0 ? m.hex_id(s.dt_elem) : 0, s.energy_ratio(), elapsed, remaining);
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

// Mass scaling: the target step, the mass added so far and its share of the model's mass.
std::string mass_scaling_report(const ControlData& k, const State& s) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                " mass scaling (DT2MS %.5e%s): element steps held at >= %.5e, run step >= %.5e\n"
                "     added mass ........................... %14.6e\n"
                "     model mass without it ................ %14.6e\n"
                "     percentage increase .................. %14.6f",
                k.mass_scaling_dt, k.mass_scaling_first_only ? ", first cycle only" : "",
                std::fabs(k.mass_scaling_dt), k.tssf * std::fabs(k.mass_scaling_dt), s.added_mass, s.physical_mass,
                added_mass_percent(s));
  return buf;
}

std::string parent_or_dot(const std::string& path) {
  std::string p = std::filesystem::path(path).parent_path().string();
  return p.empty() ? "." : p;
}

std::string numbered(const std::string& root, int k) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", k);
  return root + buf;
}

}  // namespace

int run_simulation(const Model& model, const RunOptions& opt, std::ostream& printed) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  RunLog log(printed, opt.quiet);
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  auto file_error = [&](int id, const std::string& file, const std::string& what) {
    Diagnostic d{id, Severity::error, Location{file, 0, {}, {}, 0, 0, {}, false}, what};
    log.line(render(d));
    std::cerr << "impact3d: " << render(d) << "\n";
  };

  Engine engine(model);
  StepStatus st = engine.initialize();
  State& s = engine.state();
  const bool restarting = !opt.restart.empty();
  DumpHeader dump;
  if (restarting) {
    try {
      dump = read_restart_dump_header(opt.restart);
      SlidingInterfaces::RestartData cd;
      read_restart_dump_state(opt.restart, s, cd);
      engine.contact().restore(cd);
    } catch (const std::exception& ex) {
      file_error(4005, opt.restart, ex.what());
      log.line("\n E r r o r   t e r m i n a t i o n   (restart dump is invalid)");
      return exit_code::file_error;
    }
    st = engine.finished() ? StepStatus::finished : StepStatus::ok;
  }
  OutputCursor cur = restarting ? dump.cursor : OutputCursor{};
  const double start_time = s.time;
  {
    char buf[300];
    if (restarting)
      std::snprintf(buf, sizeof buf, "\n restart from %s at cycle %d, time %.6e\n threads: %d\n",
                    opt.restart.c_str(), s.cycle, s.time, omp_get_max_threads());
    else
      std::snprintf(buf, sizeof buf, "\n threads: %d\n first time step %.5e (element %d)\n",
                    omp_get_max_threads(), s.dt_next, s.dt_elem >= 0 ? model.hex_id(s.dt_elem) : 0);
    log.line(buf);
    if (model.control.mass_scaling_dt != 0) log.line(mass_scaling_report(model.control, s));
    log.line("    cycle         time          dt  element  e-ratio   elapsed  remaining(s)");
  }

  // ---- outputs
  const double plot_dt = model.control.plot_interval;
  const double th_dt = model.control.th_interval;
  const int word_size = opt.plot_word_size;
  PlotOutput plot;
  HistoryOutput history;
  const std::string out_dir = parent_or_dot(opt.printed);
  try {
    const std::int64_t member_words = std::int64_t(opt.member_size_factor) * 512 * 512;
    if (restarting) plot.resume(model, opt.plot, word_size, member_words, cur.plot_states);
    else plot.open(model, opt.plot, word_size, member_words);
  } catch (const std::exception& ex) {
    // on a restart the family must be there to continue: a missing or short one is a restart
    // problem (4006), not a write failure
    file_error(restarting ? 4006 : 3004, opt.plot, ex.what());
    log.line(restarting ? "\n E r r o r   t e r m i n a t i o n   (the plot database does not match the restart dump)"
                        : "\n E r r o r   t e r m i n a t i o n   (cannot write the output files)");
    return exit_code::file_error;
  }
  // the interface-force database (*DATABASE_BINARY_INTFOR with SAPR/SBPR sides): s=, default
  // intfor beside the plot database; its interval DT, else the plot interval
  IntforOutput intfor;
  const bool want_intfor = IntforOutput::wanted(model);
  const double intfor_dt = model.control.intfor_interval > 0 ? model.control.intfor_interval : plot_dt;
  const std::string intfor_root = !opt.intfor.empty() ? opt.intfor : parent_or_dot(opt.plot) + "/intfor";
  if (want_intfor) {
    try {
      const std::int64_t member_words = std::int64_t(opt.member_size_factor) * 512 * 512;
      if (restarting) intfor.resume(model, intfor_root, word_size, member_words, cur.intfor_states);
      else intfor.open(model, intfor_root, word_size, member_words);
    } catch (const std::exception& ex) {
      file_error(restarting ? 4006 : 3004, intfor_root, ex.what());
      log.line("\n E r r o r   t e r m i n a t i o n   (cannot write the output files)");
      return exit_code::file_error;
    }
  }
  try {
    history.open(model, out_dir, out_dir + "/d3thdt", word_size, restarting, cur.ascii_bytes,
                 cur.history_states);
  } catch (const std::exception& ex) {
    file_error(restarting ? 4006 : 3004, out_dir, ex.what());
    log.line("\n E r r o r   t e r m i n a t i o n   (cannot write the output files)");
    return exit_code::file_error;
  }
  bool out_ok = true;
  int scheduled_plot_states = cur.plot_states;  // states a restart keeps (not sense-switch extras)
  double output_seconds = 0;  // time spent writing plot states and time histories
  // adds the wall-clock time of a scope (one output, however it returns) to a total
  struct OutputTimer {
    double& total;
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    explicit OutputTimer(double& t) : total(t) {}
    ~OutputTimer() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
  };
  auto write_plot = [&](bool scheduled) {
    if (!scheduled && plot.last_time() == s.time) return;  // a state at this time exists
    const OutputTimer timer(output_seconds);
    try {
      plot.write(model, s, engine.interface_forces());
    } catch (const std::exception& ex) {
      file_error(4004, opt.plot, ex.what());
      out_ok = false;
      return;
    }
    if (scheduled) {
      cur.next_plot = (std::floor(s.time / plot_dt + 1e-9) + 1) * plot_dt;
      scheduled_plot_states = plot.states_written();
    }
  };
  auto write_intfor = [&] {
    if (!want_intfor || intfor.last_time() == s.time) return;
    const OutputTimer timer(output_seconds);
    try {
      intfor.write(model, s, engine.contact(), engine.interface_forces());
    } catch (const std::exception& ex) {
      file_error(4004, intfor_root, ex.what());
      out_ok = false;
      return;
    }
    cur.next_intfor = (std::floor(s.time / intfor_dt + 1e-9) + 1) * intfor_dt;
  };
  double last_history_time = -1;
  auto write_history = [&] {
    last_history_time = s.time;
    const OutputTimer timer(output_seconds);
    try {
      const double ns = s.cycle > 0 ? 1e9 * elapsed() / (double(s.cycle) * std::max(1, s.ne)) : 0;
      history.write(model, s, engine.interface_forces(), ns);
      history.flush();
    } catch (const std::exception& ex) {
      file_error(4004, out_dir, ex.what());
      out_ok = false;
      return;
    }
    cur.next_history = (std::floor(s.time / th_dt + 1e-9) + 1) * th_dt;
  };
  std::string deck_text = opt.deck_text;
  auto write_dump = [&](const std::string& path) -> bool {
    if (deck_text.empty() && opt.deck_text_source) deck_text = opt.deck_text_source();
    DumpHeader h;
    h.deck_name = model.deck_file;
    h.deck_text = deck_text;
    h.mesh_renumbered = model.renumbered() ? 1 : 0;
    h.plot_root = opt.plot;
    h.dump_root = opt.dump;
    h.printed = opt.printed;
    h.plot_word_size = word_size;
    h.member_size_factor = opt.member_size_factor;
    h.cursor = cur;
    h.cursor.plot_states = scheduled_plot_states;
    h.cursor.history_states = history.thdt_states();
    h.cursor.intfor_states = intfor.states_written();
    h.intfor_root = want_intfor ? intfor_root : std::string();
    history.current_sizes(h.cursor.ascii_bytes);
    try {
      write_restart_dump(path, h, s, engine.contact().restart_data());
    } catch (const std::exception& ex) {
      file_error(3004, path, ex.what());
      return false;
    }
    char buf[300];
    std::snprintf(buf, sizeof buf, " restart dump %s written at cycle %d, time %.6e", path.c_str(), s.cycle, s.time);
    log.line(buf);
    return true;
  };

  if (!restarting && st == StepStatus::ok) {
    write_plot(true);
    write_history();
    write_intfor();
  }

  SenseSwitches switches;
  long long refused_contacts = 0;  // node-cycles the penetration-growth rule did not catch
  RunChecks checks(s);             // the run checks at every report and at the end (run_checks.h)
  const int report = std::max(1, model.control.report_interval);
  const int dump_every = model.control.restart_dump_cycles;
  const int running_every = model.control.running_restart_cycles;
  bool stopped = false;
  while (st == StepStatus::ok && out_ok) {
    if (model.exact_output_times) engine.land_on(std::min(cur.next_plot, cur.next_history));
    st = engine.step();
    if (!engine.contact().empty()) refused_contacts += engine.contact().search_stats().refused;
    for (std::size_t k = 0; k < s.newly_failed.size(); ++k)
      log.line(render(Diagnostic{5004, Severity::info, Location{},
                                 describe_solid_failure(model, s, s.newly_failed[k], s.newly_failed_cause[k])}));
    for (int b : s.beams.newly_failed)
      log.line(render(Diagnostic{5005, Severity::info, Location{}, describe_beam_failure(model, s, b)}));
    for (int r : s.newly_released)
      log.line(render(Diagnostic{5006, Severity::info, Location{}, describe_weld_release(model, s, r)}));
    if (s.cycle % report == 0 || st != StepStatus::ok) {
      log.line(format_cycle_line(model, s, elapsed(), start_time, model.control.end_time));
      for (const std::string& l : checks.check_state({model, s, refused_contacts})) log.line(l);
    }
    if (st != StepStatus::ok) break;
    if (s.time >= cur.next_plot * (1 - 1e-9)) write_plot(true);
    if (s.time >= cur.next_history * (1 - 1e-9)) write_history();
    if (want_intfor && s.time >= cur.next_intfor * (1 - 1e-9)) write_intfor();
    // (a request that lands on a cycle that has just written a state waits one cycle, so the
    // extra state never repeats a time)
    if (g_plot_now && plot.last_time() != s.time) {
      g_plot_now = 0;
      write_plot(false);
      log.line(" plot state written on request (SIGUSR2, sense switch sw4)");
    }
    if (g_status) {
      g_status = 0;
      std::string l = format_cycle_line(model, s, elapsed(), start_time, model.control.end_time);
      log.line(" status (SIGUSR1, sense switch sw2):");
      log.line("    cycle         time          dt  element  e-ratio   elapsed  remaining(s)");
      log.line(l);
    }
    if (dump_every > 0 && s.cycle % dump_every == 0)
      out_ok = write_dump(numbered(opt.dump, ++cur.dumps_written)) && out_ok;
    if (running_every > 0 && s.cycle % running_every == 0)
      out_ok = write_dump(parent_or_dot(opt.dump) + "/runrsf") && out_ok;
    if (g_stop) {
      g_stop = 0;
      stopped = true;
      log.line(render(Diagnostic{5001, Severity::info, Location{}, "at cycle " + std::to_string(s.cycle)}));
      out_ok = write_dump(numbered(opt.dump, ++cur.dumps_written)) && out_ok;
      write_plot(false);
      break;
    }
  }
  // the final state (normal end) or the last state reached (error termination)
  if (out_ok && !stopped && plot.last_time() != s.time) write_plot(true);
  if (out_ok && !stopped && st == StepStatus::finished && last_history_time != s.time) write_history();
  if (out_ok && !stopped && st == StepStatus::finished) write_intfor();
  history.flush();
  const double cpu = elapsed();
  {
    char buf[200];
    std::snprintf(buf, sizeof buf, "\n plot database %s: %d state(s) written", opt.plot.c_str(), plot.states_written());
    log.line(buf);
    if (want_intfor) {
      std::snprintf(buf, sizeof buf, " interface-force database %s: %d state(s) written", intfor_root.c_str(), intfor.states_written());
      log.line(buf);
    }
  }
  log.line("\n energies at the end (time " + std::to_string(s.time) + "):\n" + energy_report(s));
  if (model.control.mass_scaling_dt != 0) log.line(mass_scaling_report(model.control, s));
  if (engine.added_mass_limit_reached()) {
    char buf[200];
    std::snprintf(buf, sizeof buf, " the added mass reached ENDMAS (%.4g %%): the run ends here", model.control.end_mass_percent);
    log.line(buf);
  }
  {
    if (refused_contacts > 0) {
      char rb[200];
      std::snprintf(rb, sizeof rb,
                    "\n contact: %lld node-cycle(s) found deeper than penetration growth allows were not caught "
                    "(README, Contact)", refused_contacts);
      log.line(rb);
    }
    for (const std::string& l : final_shape_lines(model, s, measure_final_shape(s))) log.line(l);
    char buf[400];
    std::snprintf(buf, sizeof buf, " cycles %d, elapsed %.3f s (%.3f us per element-cycle)", s.cycle, cpu,
                  s.cycle && s.ne + s.shells.ns ? 1e6 * cpu / (double(s.cycle) * (s.ne + s.shells.ns)) : 0.0);
    log.line(buf);
    const PhaseTimes& pt = engine.phase_times();
    std::snprintf(buf, sizeof buf,
                  " phase times (s): elements %.3f  nodes %.3f  walls %.3f  contact %.3f  output %.3f",
                  pt.elements, pt.nodes, pt.walls, pt.contact, output_seconds);
    log.line(buf);
  }
  for (const std::string& l : checks.check_state({model, s, refused_contacts})) log.line(l);
  log.line("\n " + checks.verdict_line());
  if (!out_ok) {
    log.line("\n E r r o r   t e r m i n a t i o n   (output write failed)");
    return exit_code::file_error;
  }
  if (stopped) {
    log.line("\n E r r o r   t e r m i n a t i o n   (stopped by signal: restart with r=" +
             numbered(opt.dump, cur.dumps_written) + ")");
    return exit_code::stopped_by_signal;
  }
  if (st == StepStatus::finished) {
    log.line("\n N o r m a l   t e r m i n a t i o n");
    return opt.strict && checks.suspect() ? exit_code::suspect_run : exit_code::ok;
  }
  std::string why;
  int msg = 4001;
  char buf[300];
  switch (st) {
    case StepStatus::negative_volume:
      msg = 4001;
      // (an index past the solids is a shell: non-positive area)
      std::snprintf(buf, sizeof buf, "%s element %d at cycle %d, time %.6e",
                    engine.error_element() >= model.num_hexes() + model.num_shells() ? "beam (zero length)"
                    : engine.error_element() >= model.num_hexes()                    ? "shell (non-positive area)"
                                                                                     : "solid",
                    model.hex_id(engine.error_element()), s.cycle, s.time);
      why = buf;
      break;
    case StepStatus::non_finite:
      msg = 4002;
      std::snprintf(buf, sizeof buf, "%s%d at cycle %d, time %.6e",
                    engine.error_element() >= model.num_hexes() + model.num_shells() ? "beam element "
                    : engine.error_element() >= model.num_hexes() ? "shell element "
                    : engine.error_element() >= 0               ? "solid element "
                                                                : "kinetic energy; element ",
                    engine.error_element() >= 0 ? model.hex_id(engine.error_element()) : 0, s.cycle, s.time);
      why = buf;
      break;
    default:
      msg = 4003;
      std::snprintf(buf, sizeof buf, "dt %.4e below %.4g x first step, element %d, cycle %d, time %.6e",
                    s.dt_next, model.control.min_step_factor, s.dt_elem >= 0 ? model.hex_id(s.dt_elem) : 0, s.cycle, s.time);
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
