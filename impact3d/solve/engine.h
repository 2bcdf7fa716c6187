#pragma once
// The engine: the explicit cycle on a State.  run_simulation (run.h) drives it with output;
// tests drive it directly.

#include <string>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"
#include "impact3d/contact/sliding_interface.h"
#include "impact3d/contact/stonewall.h"
#include "impact3d/solve/loads.h"

namespace impact3d {

namespace parallel {
class DistributedCycle;
}

enum class StepStatus { ok, finished, negative_volume, non_finite, dt_too_small, diverged };

// Wall-clock seconds spent in each phase of the cycle since initialize() (benchmarks and the
// run's final report).
struct PhaseTimes {
  double contact = 0;   // sliding interfaces (search and penalty forces)
  double loads = 0;     // loads, prescribed motions and their work
  double nodes = 0;     // node pass: forces, accelerations, velocities, positions, kinetic energy
  double walls = 0;     // stonewalls and rigid bodies
  double elements = 0;  // element pass and its reductions
};

// The energy ratio (total / (initial + external work)) above which a run stops as diverged
// (message 4007, docs/command-line.md "Run checks").
inline constexpr double kDivergedEnergyRatio = 10.0;
bool energy_diverged(const State& s);

class Engine {
 public:
  explicit Engine(const Model& m);
  // Initialization and the element pass at t = 0 (first time step).
  StepStatus initialize();
  // One cycle: nodal forces -> accelerations -> velocities (rigid bodies, constraints, walls)
  // -> positions -> element processing at the new time -> next step.
  StepStatus step();
  // Runs until the termination time or an error.
  StepStatus run_to_end();

  const State& state() const { return s_; }
  State& state() { return s_; }
  const Model& model() const { return m_; }
  // at the termination time, or past the termination cycle when the deck sets one (ENDCYC)
  // The next steps end no later than time t ("exact_output_time" of DYNA3D decks: states at
  // the output times themselves); a t already reached is ignored.
  void land_on(double t) { land_time_ = t; }
  bool finished() const {
    return s_.time >= m_.control.end_time * (1 - 1e-12) ||
           (m_.control.end_cycle > 0 && s_.cycle >= m_.control.end_cycle) || added_mass_limit_reached_;
  }
  // Whether the run ends because the added mass reached ENDMAS (mass scaling).
  bool added_mass_limit_reached() const { return added_mass_limit_reached_; }
  // Element (0-based) behind the last error, and a description.
  int error_element() const { return error_elem_; }

  SlidingInterfaces& contact() { return contact_; }
  // Resultant force on each sliding interface (slave side; the master side carries the opposite) at the last cycle.
  const std::vector<std::array<double, 3>>& interface_forces() const { return contact_.interface_forces(); }

  // Energy diagnostics
  double kinetic_energy_of_material(int mat) const;

  const PhaseTimes& phase_times() const { return times_; }

  // A distributed run (impact3d/parallel/distributed_cycle.h): set before initialize() on
  // every rank.  Rank 0's initialize() and step() tell the other ranks to do the same.
  void distribute(parallel::DistributedCycle* d) { dist_ = d; }
  parallel::DistributedCycle* distribution() const { return dist_; }
  // Before an output: rank 0 gathers every rank's part of the State (nothing in one process).
  void gather_for_output();
  // Before the run checks' time-centred ratio: rank 0 gathers every node's v^{n-1/2} and
  // v^{n+1/2} (nothing in one process).
  void gather_velocities();
  // Rank 0 at the end of a distributed run: the other ranks stop with this exit code.
  void release_followers(int code);

 private:
  double land_time_ = -1;
  StepStatus process_elements();
  void calc_kinetic_energy();

  const Model& m_;
  State s_;
  SlidingInterfaces contact_;
  int error_elem_ = -1;
  bool added_mass_limit_reached_ = false;
  PhaseTimes times_;
  LoadSet loads_;
  std::vector<FixedWall> fixed_walls_;  // walls the node pass applies itself (see NodePass)
  parallel::DistributedCycle* dist_ = nullptr;
};

}  // namespace impact3d
