#include "impact3d/solve/run_outputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "impact3d/output/restart_dump.h"

namespace impact3d {

namespace {

std::string parent_or_dot(const std::string& path) {
  std::string p = std::filesystem::path(path).parent_path().string();
  return p.empty() ? "." : p;
}

std::string numbered(const std::string& root, int k) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", k);
  return root + buf;
}

constexpr const char* kCannotWrite = "cannot write the output files";

// Adds the wall-clock time of a scope (one output, however it returns) to a total.
struct OutputTimer {
  double& total;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  explicit OutputTimer(double& t) : total(t) {}
  ~OutputTimer() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
};

// A database written by write(); a failure is error 4004 naming `where`, and the run writes no
// more (ok false).  False when it failed.
template <class Write>
bool write_or_stop(RunLog& log, const std::string& where, bool& ok, Write&& write) {
  try {
    write();
  } catch (const std::exception& ex) {
    log.file_error(4004, where, ex.what());
    ok = false;
    return false;
  }
  return true;
}

}  // namespace

RunOutputs::RunOutputs(Engine& engine, const RunOptions& opt, RunLog& log, const RunClock& clock,
                       const OutputCursor& cursor, bool restarting)
    : engine_(engine),
      model_(engine.model()),
      s_(engine.state()),
      opt_(opt),
      log_(log),
      clock_(clock),
      restarting_(restarting),
      schedule_(engine.model().control, cursor),
      member_words_(std::int64_t(opt.member_size_factor) * 512 * 512),
      out_dir_(parent_or_dot(opt.printed)),
      // the interface-force database (*DATABASE_BINARY_INTFOR with SAPR/SBPR sides): s=, default
      // intfor beside the plot database
      want_intfor_(IntforOutput::wanted(engine.model())),
      intfor_root_(!opt.intfor.empty() ? opt.intfor : parent_or_dot(opt.plot) + "/intfor"),
      scheduled_plot_states_(cursor.plot_states),
      deck_text_(opt.deck_text) {}

bool RunOutputs::open_one(void (RunOutputs::*how)(), const std::string& file, const char* why) {
  try {
    (this->*how)();
  } catch (const std::exception& ex) {
    log_.file_error(restarting_ ? 4006 : 3004, file, ex.what());
    log_.line(std::string("\n E r r o r   t e r m i n a t i o n   (") + why + ")");
    return false;
  }
  return true;
}

bool RunOutputs::open() {
  // on a restart the family must be there to continue: a missing or short one is a restart
  // problem (4006), not a write failure
  const char* plot_why = restarting_ ? "the plot database does not match the restart dump" : kCannotWrite;
  const bool opened = open_one(&RunOutputs::open_plot, opt_.plot, plot_why) &&
                      (!want_intfor_ || open_one(&RunOutputs::open_intfor, intfor_root_, kCannotWrite)) &&
                      open_one(&RunOutputs::open_history, out_dir_, kCannotWrite);
  plot_.set_sync_interval(opt_.sync_seconds);
  intfor_.set_sync_interval(opt_.sync_seconds);
  history_.set_sync_interval(opt_.sync_seconds);
  return opened;
}

bool RunOutputs::sync() {
  const OutputTimer timer(seconds_);
  const std::string* file = &opt_.plot;
  try {
    plot_.sync();
    file = &intfor_root_;
    intfor_.sync();
    file = &out_dir_;
    history_.sync();
  } catch (const std::exception& ex) {
    log_.file_error(4004, *file, ex.what());
    ok_ = false;
  }
  return ok_;
}

void RunOutputs::open_plot() {
  const OutputCursor& cur = schedule_.cursor();
  if (restarting_) plot_.resume(model_, opt_.plot, opt_.plot_word_size, member_words_, cur.plot_states);
  else plot_.open(model_, opt_.plot, opt_.plot_word_size, member_words_);
}

void RunOutputs::open_intfor() {
  const OutputCursor& cur = schedule_.cursor();
  if (restarting_) intfor_.resume(model_, intfor_root_, opt_.plot_word_size, member_words_, cur.intfor_states);
  else intfor_.open(model_, intfor_root_, opt_.plot_word_size, member_words_);
}

void RunOutputs::open_history() {
  const OutputCursor& cur = schedule_.cursor();
  history_.open(model_, out_dir_, out_dir_ + "/d3thdt", opt_.plot_word_size, restarting_, cur.ascii_bytes,
                cur.history_states);
}

void RunOutputs::write_first() {
  write_plot(true);
  write_history();
  write_intfor();
}

void RunOutputs::write_scheduled() {
  if (schedule_.plot_due(s_.time)) write_plot(true);
  if (schedule_.history_due(s_.time)) write_history();
  if (want_intfor_ && schedule_.intfor_due(s_.time)) write_intfor();
}

bool RunOutputs::plot_state_at_this_time() const { return plot_.last_time() == s_.time; }

void RunOutputs::write_cycle_dumps() {
  if (schedule_.numbered_dump_due(s_.cycle)) write_numbered_dump();
  if (schedule_.running_dump_due(s_.cycle)) ok_ = write_dump(parent_or_dot(opt_.dump) + "/runrsf") && ok_;
}

void RunOutputs::write_numbered_dump() {
  ok_ = write_dump(numbered(opt_.dump, schedule_.next_dump_number())) && ok_;
}

std::string RunOutputs::last_numbered_dump() const { return numbered(opt_.dump, schedule_.dumps_written()); }

void RunOutputs::write_last(StepStatus st) {
  if (ok_ && plot_.last_time() != s_.time) write_plot(true);
  if (ok_ && st == StepStatus::finished && last_history_time_ != s_.time) write_history();
  if (ok_ && st == StepStatus::finished) write_intfor();
}

void RunOutputs::write_plot(bool scheduled) {
  if (!scheduled && plot_.last_time() == s_.time) return;  // a state at this time exists
  const OutputTimer timer(seconds_);
  engine_.gather_for_output();  // a distributed run: every rank's part to rank 0
  if (!write_or_stop(log_, opt_.plot, ok_, [&] { plot_.write(model_, s_, engine_.interface_forces()); })) return;
  if (scheduled) {
    schedule_.plot_written(s_.time);
    scheduled_plot_states_ = plot_.states_written();
  }
}

void RunOutputs::write_intfor() {
  if (!want_intfor_ || intfor_.last_time() == s_.time) return;
  const OutputTimer timer(seconds_);
  engine_.gather_for_output();
  if (!write_or_stop(log_, intfor_root_, ok_, [&] { intfor_.write(model_, s_, engine_.contact(), engine_.interface_forces()); }))
    return;
  schedule_.intfor_written(s_.time);
}

void RunOutputs::write_history() {
  last_history_time_ = s_.time;
  const OutputTimer timer(seconds_);
  engine_.gather_for_output();
  const bool written = write_or_stop(log_, out_dir_, ok_, [&] {
    const double ns = s_.cycle > 0 ? 1e9 * clock_.elapsed() / (double(s_.cycle) * std::max(1, s_.ne)) : 0;
    history_.write(model_, s_, engine_.interface_forces(), ns);
    history_.flush();
  });
  if (!written) return;
  schedule_.history_written(s_.time);
}

DumpHeader RunOutputs::dump_header() {
  if (deck_text_.empty() && opt_.deck_text_source) deck_text_ = opt_.deck_text_source();
  DumpHeader h;
  h.deck_name = model_.deck_file;
  h.deck_text = deck_text_;
  h.mesh_renumbered = model_.renumbered() ? 1 : 0;
  h.plot_root = opt_.plot;
  h.dump_root = opt_.dump;
  h.printed = opt_.printed;
  h.plot_word_size = opt_.plot_word_size;
  h.member_size_factor = opt_.member_size_factor;
  h.cursor = schedule_.cursor();
  h.cursor.plot_states = scheduled_plot_states_;
  h.cursor.history_states = history_.thdt_states();
  h.cursor.intfor_states = intfor_.states_written();
  h.intfor_root = want_intfor_ ? intfor_root_ : std::string();
  history_.current_sizes(h.cursor.ascii_bytes);
  return h;
}

bool RunOutputs::write_dump(const std::string& path) {
  // the states the dump counts durable before it (a restart after a machine crash finds them)
  if (!sync()) return false;
  const DumpHeader h = dump_header();
  engine_.gather_for_output();
  try {
    write_restart_dump(path, h, s_, engine_.contact().restart_data());
  } catch (const std::exception& ex) {
    log_.file_error(3004, path, ex.what());
    return false;
  }
  char buf[300];
  std::snprintf(buf, sizeof buf, " restart dump %s written at cycle %d, time %.6e", path.c_str(), s_.cycle, s_.time);
  log_.line(buf);
  return true;
}

}  // namespace impact3d
