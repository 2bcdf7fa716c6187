#pragma once
// Time histories at the deck's time-history interval: the binary time-history database
// (d3thdt family: the d3plot layout restricted to the time-history nodes, solids and shells) and the
// ASCII tables in the LS-DYNA style: glstat, matsum, rwforc, rcforc, nodout, elout.

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

class HistoryOutput {
 public:
  static constexpr int kNumAscii = 6;
  static const char* ascii_name(int k);  // glstat matsum rwforc rcforc nodout elout

  HistoryOutput() = default;
  ~HistoryOutput();
  HistoryOutput(const HistoryOutput&) = delete;
  HistoryOutput& operator=(const HistoryOutput&) = delete;

  // dir: folder for the ASCII files; thdt_root: root name of the binary family (e.g.
  // DIR/d3thdt).  With resume, the files are cut back to the sizes / state count recorded in
  // the restart dump and continued.  Throws std::runtime_error on I/O errors.
  void open(const Model& m, const std::string& dir, const std::string& thdt_root, int word_size,
            bool resume, const std::uint64_t* ascii_bytes, int thdt_states);
  // One output time.  contact_forces: resultant force on each interface (may be empty).
  void write(const Model& m, const State& s,
             const std::vector<std::array<double, 3>>& contact_forces, double cpu_per_zone_ns);
  void current_sizes(std::uint64_t out[kNumAscii]) const;
  int thdt_states() const { return thdt_ ? thdt_->num_states_written() : 0; }
  void flush();
  // d3thdt's durability against a machine crash (PlotWriter::set_sync_interval, sync); the
  // ASCII files are flushed after each write (flush), not fsync'ed.
  void set_sync_interval(double seconds) {
    if (thdt_) thdt_->set_sync_interval(seconds);
  }
  void sync() {
    if (thdt_) thdt_->sync();
  }
  int syncs() const { return thdt_ ? thdt_->num_syncs() : 0; }

 private:
  // write()'s files, in order (history_output.cpp)
  void write_glstat(FILE* f, const Model& m, const State& s);
  void write_matsum(FILE* f, const Model& m, const State& s);
  void write_rwforc(FILE* f, const Model& m, const State& s);
  void write_rcforc(FILE* f, const State& s, const std::vector<std::array<double, 3>>& contact_forces);
  void write_nodout(FILE* f, const Model& m, const State& s);
  void write_elout_solids(FILE* f, const Model& m, const State& s);
  void write_elout_shells(FILE* f, const Model& m, const State& s);
  void write_elout_beams(FILE* f, const Model& m, const State& s);
  void write_thdt_state(const State& s);

  std::string dir_;
  FILE* files_[kNumAscii] = {};
  std::unique_ptr<PlotWriter> thdt_;
  std::vector<int> th_nodes_, th_solids_, th_shells_;  // 0-based, deck order
  std::vector<int> th_beams_;   // 0-based beams of the beam time-history blocks
  int beam_points_ = 0;         // section points per beam record (the d3plot's: beam_plot_points)
  std::vector<int> thdt_node_of_;          // subset: global node -> subset index
  std::vector<int> subset_nodes_;          // subset index -> global node
  PlotState ps_;
  std::vector<double> shell_words_;  // one shell's plot words (elout)
};

}  // namespace impact3d
