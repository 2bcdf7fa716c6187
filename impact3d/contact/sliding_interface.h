#pragma once
// Sliding interfaces (DYNA3D type 3): penalty contact between master and slave surfaces of
// hexahedron faces, the seed's method (shared/spec/physics.md section 5).

#include <array>
#include <memory>
#include <vector>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

class SlidingInterfaces {
 public:
  SlidingInterfaces();
  ~SlidingInterfaces();
  SlidingInterfaces(SlidingInterfaces&&) noexcept;
  SlidingInterfaces& operator=(SlidingInterfaces&&) noexcept;

  // Builds segments, node lists and search structures from the model (after initialize_state).
  void initialize(const Model& m, const State& s);
  // Adds the penalty forces at the current positions x^n to s.fext_x/y/z (which the engine
  // zeroes before).  dt is the step about to be taken (dt^{n+1/2}).  The result must not
  // depend on the thread count.
  void apply(const Model& m, State& s, double dt);
  // Books the contact energy of the last apply()'s forces in s.contact: their work on the mean
  // velocity (s.vx_old... + s.vx...) / 2 over dt_n.  The engine calls it once the cycle's
  // velocities v^{n+1/2} are final (after rigid bodies, walls, prescribed motions).
  void book_energy(State& s, double dt_n) const;
  bool empty() const;
  // Whether apply() needs the solids' elastic step (an interface with the maximum stable
  // stiffness): the engine then has the element pass compute it (State::elastic_dt_wanted).
  bool uses_elastic_step() const;

  // Resultant force on the slave side of each interface in the last apply() (the master side
  // takes the opposite): normal and friction parts of both passes.  For the interface-force
  // file.
  // Then one entry per force transducer (*CONTACT_FORCE_TRANSDUCER_PENALTY, Model::
  // force_transducers, after the interfaces): the contact force the interfaces put on the nodes
  // of its side A (only the forces between A and B when it has a side B).  Transducers apply
  // nothing; their sums are taken in the fixed scatter order (same bits for any thread count).
  const std::vector<std::array<double, 3>>& interface_forces() const;
  // The interface-force database (intfor): the sorted nodes of side `side` (0 slave, 1 master) of
  // interface i, and the contact force on each of them in the last apply() (3 per node, both
  // passes).  Recorded only for the sides the model writes (SlidingInterface::intfor_slave /
  // intfor_master with Model::control.intfor_interval >= 0); empty otherwise.
  const std::vector<int>& surface_nodes(std::size_t i, int side) const;
  const std::vector<double>& surface_node_forces(std::size_t i, int side) const;
  // Largest penetration (over all interfaces and both passes) found in the last apply().
  double max_penetration() const;
  // Search statistics of the last apply(): nodes searched, (node, segment) closest-point
  // evaluations, nodes in contact.  The evaluations grow linearly with the nodes.
  struct SearchStats {
    long nodes = 0, evaluations = 0, contacts = 0;
    long refused = 0;  // nodes whose penetration jumped beyond their approach (offset grew)
    // largest omega dt of a node's spring in contact: dt sqrt(k (1/m_node + sum N_A^2 / m_A))
    // (the 5-node spring's eigenvalue, seed eq. 13, with the step about to be taken); the
    // central difference is stable for omega dt < 2
    double max_omega_dt = 0;
  };
  SearchStats search_stats() const;

  // A restart dump carries the last cycle's contact forces (3 doubles per node, and a flag;
  // book_energy() needs them) and, for each node of each pass (interfaces and passes in
  // order), its last geometric penetration and its offset (the part no approach explained).
  // (The dump's second array once held a predicted v^{n+1/2}.)
  struct RestartData {
    std::vector<double> forces;    // 3 per node
    std::vector<double> admitted;  // 2 per pass node; empty in a dump without contact
    double dtn = 0;                // the soft constraint's step (SOFT 1's dt_c)
    bool has = false;
  };
  RestartData restart_data() const;
  void restore(const RestartData& d);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace impact3d
