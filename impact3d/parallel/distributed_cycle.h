#pragma once
// The distributed cycle (docs/cluster.md): the Engine's cycle on a rank's domain (partition.h),
// with the same bits as one process for any rank count.
//
// Every rank reads the deck and builds the whole State (memory is not yet divided: a first
// step); each computes only its own blocks of solids and its own nodes:
//  - element pass: this rank's blocks of solids and chunks of shells; then every block's
//    BlockResult and every shell's and beam's record (its books' inputs, corner forces and moments) to
//    every rank (allgather), so the reductions over blocks and shells in the one-process order
//    are the same numbers on every rank (the step, its element, the energies), and the corner
//    forces of this rank's solids at other ranks' nodes to their owners (neighbour exchange);
//  - node pass: this rank's nodes, each summing its corner list in the one-process order (the
//    corners of other ranks' solids are the received values, the same numbers), so each
//    node's force has the same bits; each node's kinetic energy and wall books to rank 0
//    (gather), which sums them in the one-process chunk order; the new positions and
//    velocities of this rank's nodes to the ranks that have them as ghosts;
//  - the rotational update (shells' rotational degrees of freedom): every rank makes it for
//    all of them from the shells' moments that every rank has, so the angular velocities are
//    the same bits everywhere without an exchange;
//  - mass scaling: every solid's step goes to every rank with the block results, so every rank
//    adds the same masses to every node; a cycle that adds mass first brings every node's
//    velocity to rank 0, which books the kinetic energy it brings (solve/mass_scaling.h);
//  - loads and prescribed motions: every rank adds every load's forces (their values at the
//    rank's own nodes are those of one process: a pressure face's corners are ghosts of the
//    owners of its other corners), the owner of a node sets its prescribed motions between the
//    velocity and the position update (a node pass in two parts), and the external work's
//    terms (solve/loads.h) go to rank 0 with the node books, which sums them in the
//    one-process order.
// Rank 0 leads: it runs the run driver (outputs, schedule, run checks, messages) and tells the
// other ranks what to do next (initialize, step, gather for output, finish); before an output
// it gathers every rank's nodes, solids and corner forces, so that it writes the same files
// as one process (a restart dump too: every point of every shell, the motions' angles); before
// the run checks, every node's velocities (the time-centred ratio).  A restart: every rank
// reads the dump once rank 0 has (Op::resume).

#include <string>
#include <vector>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"
#include "impact3d/parallel/comm.h"
#include "impact3d/parallel/partition.h"
#include "impact3d/solve/element_processing.h"
#include "impact3d/solve/loads.h"
#include "impact3d/solve/mass_scaling.h"
#include "impact3d/solve/node_processing.h"

namespace impact3d {
class Engine;
}

namespace impact3d::parallel {

// What the distributed cycle cannot carry yet in this model, on nranks ranks, as a list for
// message 3007 (empty: it can run distributed).
std::string distributed_refusal(const Model& m, int nranks);

class DistributedCycle {
 public:
  DistributedCycle();
  bool leads() const { return rank_ == 0; }

  // After initialize_state and prepare_loads: the partition (rank 0, sent to all), this rank's
  // domain, buffers; the model and its loads are kept (the external work's terms).
  void setup(const State& s, const Model& m, const LoadSet& loads);
  const Domain& domain() const { return dom_; }
  // d3hsp's lines on the partition (rank 0).
  const std::string& report() const { return report_; }

  ElementPassHooks element_hooks();
  // Mass scaling: every node's velocity to rank 0 before masses are added (mass_scaling.h).
  MassScalingHook mass_scaling_hook() { return {&DistributedCycle::before_adding_mass, this}; }
  // The node pass on this rank's nodes, the books to rank 0, the ghosts' kinematics.  A pass
  // without p.update_positions stops after the velocities; finish_node_pass then moves this
  // rank's nodes (after the prescribed motions) and sends the books and the ghosts.
  void node_pass(State& s, const NodePass& p);
  void finish_node_pass(State& s, const NodePass& p);
  // Between the two parts: the fixed walls p.walls on this rank's nodes, booked by rank 0 with
  // the node books.
  void apply_walls(State& s, const NodePass& p);
  // Per node: 1 for this rank's own nodes (prescribed motions act there).
  const std::vector<std::uint8_t>& owned_node_mask() const { return dom_.owns_node; }
  // Rank 0: the cycle's external work from the terms that came with the node books (the
  // other ranks: nothing).
  void book_external_work(State& s, double dt_n);
  // Rank 0 receives every rank's nodes, solids and corner forces (collective).
  void gather_state(State& s);
  // Rank 0 receives every rank's nodes' v^{n-1/2} and v^{n+1/2} (s.vx_old..., s.vx...), the
  // run checks' time-centred ratio (collective; solve/run_cycle.h).
  void gather_velocities(State& s);

  // The leader's commands (rank 0), and the other ranks' loop that follows them until finish;
  // follow returns the exit code rank 0 finished with.
  // Wall-clock seconds this rank spent in the cycle's messages (exchanges, block results, node
  // books, commands) and in the output gathers; each includes the wait for the other ranks.
  double cycle_comm_seconds() const { return comm_s_; }
  double output_gather_seconds() const { return gather_s_; }

  enum class Op : int { initialize = 1, step, gather, finish, gather_velocities, resume };
  void announce(Op op, double land_time = -1, int code = 0);
  int follow(Engine& engine);
  // A restart (r=): the dump every rank reads when rank 0 has read it (Op::resume; the same
  // dump on every rank, as one process restores it).
  void restart_from(const std::string& path) { restart_path_ = path; }

 private:
  static void after_blocks(void* self, State& s);
  static void before_adding_mass(void* self, State& s);
  void share_solid_steps(State& s);
  void resume(Engine& engine);
  void share_block_results(State& s);
  void share_shell_results(State& s);
  void send_corner_forces(State& s);
  void send_ghost_kinematics(State& s);
  void size_node_records(const State& s, const NodePass& p);
  void share_node_books(State& s, const NodePass& p);
  void setup_exchanges();                               // setup's neighbour exchange buffers
  void setup_gathers(const State& s, const Model& m);  // setup's output and velocity gathers
  void unpack_rank_state(State& s, int q, const double* from);

  int rank_ = 0, nranks_ = 1;
  Domain dom_;
  std::string report_;
  std::vector<std::vector<int>> rank_blocks_;  // every rank's solids' blocks, increasing
  std::vector<std::vector<int>> rank_shells_;  // every rank's shells, chunk after chunk
  std::vector<std::vector<int>> rank_beams_;   // every rank's beams, chunk after chunk
  std::vector<std::vector<int>> rank_nodes_;   // every rank's nodes, increasing (rank 0 only)
  std::vector<std::vector<int>> rank_motions_; // every rank's prescribed motions of nodes, increasing
  std::vector<int> shell_points_;              // per shell: its integration points (shell_fi.h)
  std::string restart_path_;
  // buffers, sized once
  std::vector<BlockResult> block_buf_;
  std::vector<int> block_bytes_, block_displs_;
  std::vector<double> step_buf_;               // mass scaling: every block's solids' steps (kLanes each)
  std::vector<int> step_bytes_, step_displs_;
  std::vector<double> shell_buf_;              // every shell's and beam's record (distributed_cycle.cpp)
  std::vector<int> shell_bytes_, shell_displs_;
  std::vector<double> send_buf_, recv_buf_;    // neighbour exchanges: per peer, one after another
  std::vector<Exchange> corner_ex_, node_ex_;
  // the node books: per own node a record of stride_ doubles (node_processing.h's, then the
  // external work's node terms from terms_offset_), then this rank's load terms
  std::vector<double> records_, all_records_, gathered_records_;
  std::vector<int> record_counts_, record_displs_;
  std::size_t stride_ = 0, terms_offset_ = 0;
  const Model* model_ = nullptr;
  const LoadSet* loads_ = nullptr;
  bool load_terms_ = false;                   // loads or prescribed motions: terms go to rank 0
  std::vector<std::vector<int>> rank_slots_;  // every rank's load-term slots (loads.h), increasing
  std::vector<double> terms_, all_terms_;     // this rank's terms; every slot's (rank 0)
  std::vector<double> state_buf_, state_all_;
  std::vector<int> state_bytes_, state_displs_;
  std::vector<double> vel_buf_, vel_all_;       // the velocities' gather: 6 per own node
  std::vector<int> vel_bytes_, vel_displs_;
  double comm_s_ = 0, gather_s_ = 0;
};

}  // namespace impact3d::parallel
