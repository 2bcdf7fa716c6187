#pragma once
// The engine: initialization, the explicit cycle loop and output, for a checked Model.

#include <functional>
#include <ostream>
#include <string>

#include "impact3d/model/model.h"

namespace impact3d {

struct RunOptions {
  std::string deck;
  std::string printed = "d3hsp";
  std::string plot = "d3plot";
  std::string dump = "d3dump";
  std::string intfor;       // s=: the interface-force database root (empty: intfor beside the plot database)
  std::string restart;
  int threads = 0;          // 0 = OpenMP default
  int plot_word_size = 4;   // 4 or 8 byte words in the plot and time-history databases
  int member_size_factor = 7;  // x=: family member size limit, in units of 512 x 512 words
  // sync=: seconds of wall clock between fsyncs of the plot, time-history and interface-force
  // databases (PlotWriter::set_sync_interval; also before each restart dump and at the end);
  // 0: after every state
  double sync_seconds = 1;
  std::string deck_text;    // the deck's content, kept in restart dumps
  // When deck_text is empty: makes it, once, when the first restart dump is written (a run
  // that writes no dump never holds a second copy of a large deck)
  std::function<std::string()> deck_text_source;
  bool quiet = false;       // no run log on stdout (tests)
  bool strict = false;      // --strict: a suspect run (run_checks.h) ends with exit code 7
};

// Runs the model to its termination time.  Returns an exit code (common/messages.h).
int run_simulation(const Model& model, const RunOptions& opt, std::ostream& printed);

}  // namespace impact3d
