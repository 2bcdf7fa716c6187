#pragma once
// Loads and prescribed motions in the cycle (docs/developer-guide.md, "Cycle phases"):
//   forces:    apply_loads_to_nodes      nodal forces, pressures on faces (on the current
//                                        geometry), body forces and global mass damping
//                                        (-D m v^{n-1/2}) into s.fext_x/y/z at t^n
//   velocities: (node pass)              a^n and v^{n+1/2} from the internal and external forces
//   motions:   apply_prescribed_motions  prescribed components of v^{n+1/2} (nodes and rigid bodies)
//   books:     book_external_work        the work of the loads and of the prescribed motions' reactions
// The external work of one cycle is F^n . (v^{n-1/2} + v^{n+1/2}) / 2 * dt^n, the form that
// balances the central-difference kinetic energy (as the contact energy is booked).

#include <vector>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Value of a load curve at time t: linear between its points; before the first and after the
// last point the first and last segments are extended (as LS-DYNA extrapolates load curves).
double value_of_curve(const LoadCurve& lc, double t);

// The loads of a model, laid out for the cycle.  Built once at initialization.
struct LoadSet {
  bool has_rotations = false;          // some prescribed motion is a rotation
  std::vector<double> rot_old;         // per prescribed motion: omega^{n-1/2} of its node (3)
  // nodal forces and pressures: the force of each this cycle, kept for the work book
  std::vector<double> nodal_force;     // 3 per Model::nodal_loads entry
  std::vector<double> pressure_force;  // 12 per Model::pressure_loads entry (4 nodes x 3)
  std::vector<double> rigid_force;     // 3 per Model::rigid_body_loads entry
  std::vector<int> rigid_body;         // its rigid body (index in State::rigid)
  // body loads: mass of each node they act on (0 for the others); empty without body loads
  std::vector<uint8_t> body_node;      // 1: the body loads act on this node
  std::array<double, 3> body_acc{};    // this cycle's body acceleration
  // prescribed motions: v^{n+1/2} before the prescription (for the reaction's work)
  std::vector<double> free_velocity;   // 1 per Model::prescribed_motions entry
  std::vector<uint8_t> active;         // 1 when the motion acted this cycle
  // the vector change a motion made this cycle beyond its own component (3 per motion): a held
  // normal plane's (DOF -4 / -8) velocity change, or a rigid rotation's whole change of omega
  std::vector<double> delta;
  std::vector<int> motion_body;        // per motion: its rigid body (index in State::rigid), -1
  double damping_d = 0;                // this cycle's global damping constant D
  std::vector<double> terms;           // the external work's terms of one cycle (load_term_nodes)
  bool has_loads = false, has_motions = false;
};

void prepare_loads(const Model& m, State& s, LoadSet& loads);

// Adds this cycle's load forces at time t (= t^n, positions x^n) to s.fext_x/y/z.
void apply_loads_to_nodes(const Model& m, State& s, LoadSet& loads, double t);

// After the velocity update (and rigid bodies and walls): sets the prescribed components of
// v^{n+1/2}.  t is t^n; dt_n and dt_next as in the node pass.  `owned` (a distributed run: 1
// for a rank's own nodes) limits the motions of nodes to those nodes; null: all.
void apply_prescribed_motions(const Model& m, State& s, LoadSet& loads, double t, double dt_n,
                              double dt_next, const std::vector<std::uint8_t>* owned = nullptr);

// Prescribed rotations (PrescribedMotion::rotation) of nodes with rotations (shells', beams'):
// capture_rotations keeps omega^{n-1/2} before the rotational update, apply_prescribed_rotations
// then sets the prescribed component of omega^{n+1/2} along the axis (from the curve: the
// angular velocity, from omega^{n-1/2} and the angular acceleration, or from the angle turned so
// far), with DOF -8 the components normal to it held at 0, and books the reaction moment's work
// I (w - w_free) / dt_n . (w_old + w) / 2 * dt_n.
void capture_rotations(const Model& m, const State& s, LoadSet& loads);
void apply_prescribed_rotations(const Model& m, State& s, LoadSet& loads, double t, double dt_n, double dt_next);

// Books the work of the loads and of the prescribed motions' reactions over this cycle in
// s.external_work (call after the velocities are final).
void book_external_work(const Model& m, State& s, LoadSet& loads, double dt_n);

// The same book from its terms, for a distributed run (impact3d/parallel): the ranks that own
// the nodes compute the terms, rank 0 sums them in the one-process order.
//  - load terms, one slot each, load_term_nodes(m) giving each slot's node: per nodal load its
//    power; per pressure load 4 (its corners' powers; a triangle's fourth 0); per prescribed
//    motion 3 (1 when it acted on its node this cycle, its reaction's power along its direction,
//    the power of its held plane's or orbit's change); a rigid body's slots (node -1) stay 0
//    (one process books rigid bodies from their state);
//  - node terms, node_power_term_count(m) per node: m (v_old + v) x y z of a node the body
//    loads act on (0 for another), then with global damping m v_old (v_old + v) x y z.
std::vector<int> load_term_nodes(const Model& m);
void compute_load_terms(const Model& m, const State& s, const LoadSet& loads, double dt_n,
                        const std::vector<std::uint8_t>* owned, double* terms);
int node_power_term_count(const Model& m);
void compute_node_power_terms(const Model& m, const State& s, const LoadSet& loads, std::size_t k, double* out);
// terms: every slot (load_term_nodes' order); node_terms: every node's, node_stride apart.
void book_external_work_from_terms(const Model& m, State& s, const LoadSet& loads, double dt_n, const double* terms,
                                   const double* node_terms, std::size_t node_stride);

}  // namespace impact3d
