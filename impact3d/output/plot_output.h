#pragma once
// Plot states of a run into the d3plot family (common/plot_database): geometry from the Model,
// states from the State (current coordinates, velocities, accelerations, stresses, plastic
// strain, global and per-material energies).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Resultant force on the slave side of each sliding interface (x y z), as the contact phase
// leaves it; may be empty (before the first contact pass: written as zeros).
using InterfaceForces = std::vector<std::array<double, 3>>;

PlotGeometry make_plot_geometry(const Model& m);
// The global block of a state: time, energies, whole-model velocity, per-material books,
// rigid-wall normal forces and interface forces.  Shared by the plot and time-history databases
// and the glstat/matsum tables.  ps is reused: no allocation after the first call.
void fill_plot_globals(const Model& m, const State& s, const InterfaceForces& iface, PlotState& ps);
// The whole state: the globals, then current coordinates, velocities, accelerations, stresses,
// plastic strain, deletion flags.
void fill_plot_state(const Model& m, const State& s, const InterfaceForces& iface, PlotState& ps);

class PlotOutput {
 public:
  // Opens the family; throws std::runtime_error on I/O errors.
  // member_words: size limit of a family member in words (LS-DYNA's x= times 512 x 512).
  void open(const Model& m, const std::string& root, int word_size = 4,
            std::int64_t member_words = PlotWriter::kDefaultMemberSizeLimitWords);
  // Restart: keeps the first keep_states states of the existing family and appends after them.
  void resume(const Model& m, const std::string& root, int word_size, std::int64_t member_words,
              int keep_states);
  void write(const Model& m, const State& s, const InterfaceForces& iface);
  int states_written() const { return writer_.num_states_written(); }
  double last_time() const { return last_time_; }

 private:
  PlotWriter writer_;
  PlotState ps_;
  double last_time_ = -1;
};

}  // namespace impact3d
