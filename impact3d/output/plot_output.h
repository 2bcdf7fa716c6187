#pragma once
// Plot states of a run into the d3plot family (common/plot_database): geometry from the Model,
// states from the State (current coordinates, velocities, accelerations, stresses, plastic
// strain, global and per-material energies).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "impact3d/contact/sliding_interface.h"
#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Resultant force on the slave side of each sliding interface (x y z), as the contact phase
// leaves it; may be empty (before the first contact pass: written as zeros).
using InterfaceForces = std::vector<std::array<double, 3>>;

PlotGeometry make_plot_geometry(const Model& m);
// One shell's kShellPlotVars words (plot_database.h) from the State: mid-surface, inner and
// outer stresses in global axes (xx yy zz xy yz zx) each with a plastic strain, the resultants,
// thickness and internal energy.  Shared by the plot and time-history databases and elout.
void fill_shell_plot_vars(const State& s, int k, double* out);
// Beam records (NV1D = 6 + 5 points words): the integration points a beam record holds (the most
// any beam section of the model has; fewer: zeros after), and one beam's words: the resultants
// N, Q_s, Q_t, M_s, M_t, T (local axes), then per point tau_rs, tau_tr, sigma_rr, eps_p, eps_rr.
int beam_plot_points(const Model& m);
void fill_beam_plot_vars(const State& s, int b, int points, double* out);
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
  // Durability against a machine crash (PlotWriter::set_sync_interval, sync).
  void set_sync_interval(double seconds) { writer_.set_sync_interval(seconds); }
  void sync() { writer_.sync(); }
  int syncs() const { return writer_.num_syncs(); }

 private:
  PlotWriter writer_;
  PlotState ps_;
  double last_time_ = -1;
};

// The interface-force database (*DATABASE_BINARY_INTFOR; file s=, default `intfor` beside the
// plot database): the d3plot family layout, written with the same PlotWriter (crash-safe states,
// members), holding the contact segments of the interface sides that ask for it (*CONTACT card 1
// SAPR / SBPR = 1) as 4-node shells, one part per side.  IMPACT-3D choices (LS-DYNA's own state
// layout is not public): the nodes are the sides' nodes (deck ids), each state holds their
// current coordinates, velocities and, in the acceleration words, the contact force on the node
// (x y z, the sum over the written sides); each segment's shell record holds, in all three
// layers, sxx = syy = szz = -p (p the contact pressure, so a reader's "pressure" is p) and
// sxy = the shear traction magnitude; the other words are zero.  Nodal pressure = the normal part
// of the node's force / its tributary area (a quarter of each of its segments), a segment's the
// mean of its four corners', so the area-weighted sum over a side is its normal force.  The
// globals hold the time and the interface (and transducer) forces as the d3plot ones.
class IntforOutput {
 public:
  // Whether the model writes the database: *DATABASE_BINARY_INTFOR and at least one side.
  static bool wanted(const Model& m);
  void open(const Model& m, const std::string& root, int word_size, std::int64_t member_words);
  void resume(const Model& m, const std::string& root, int word_size, std::int64_t member_words,
              int keep_states);
  void write(const Model& m, const State& s, const SlidingInterfaces& contact, const InterfaceForces& iface);
  int states_written() const { return writer_.num_states_written(); }
  double last_time() const { return last_time_; }
  void set_sync_interval(double seconds) { writer_.set_sync_interval(seconds); }
  void sync() { writer_.sync(); }
  int syncs() const { return writer_.num_syncs(); }
  // The geometry written (nodes: the sides' nodes; shells: their segments, numbered 1..n side
  // after side in interface order, slave side first).
  static PlotGeometry make_geometry(const Model& m);

 private:
  void prepare(const Model& m);
  struct Side {
    std::size_t iface = 0;
    int side = 0;                         // 0 slave, 1 master
    std::vector<std::array<int, 4>> seg;  // intfor node indices (0-based)
    std::vector<int> surf_node;           // the contact surface's node k -> intfor node
    int first_shell = 0;                  // its first segment's shell index
  };
  std::vector<Side> sides_;
  std::vector<int> nodes_;                // intfor node -> model node
  std::vector<double> area_, normal_, force_;  // per intfor node: tributary area, 3 normal, 3 force (per side)
  PlotWriter writer_;
  PlotState ps_;
  double last_time_ = -1;
};

}  // namespace impact3d
