#pragma once
// The node pass of the cycle: corner forces gathered to the nodes in a fixed order, net force,
// acceleration, constraints, velocity, and (when nothing needs the new velocities first)
// position and kinetic energy in the same loop.  Threads work on fixed chunks of nodes; the
// kinetic energy is summed per chunk and the chunks in order (same bits for any thread count).

#include <vector>

#include "impact3d/contact/stonewall.h"
#include "impact3d/model/state.h"

namespace impact3d {

// At most this many walls are applied inside the node pass (more: the engine applies them
// after it).
constexpr std::size_t kMaxFusedWalls = 8;

struct NodePass {
  double dt_n = 0;      // dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2: velocity update
  double dt_next = 0;   // dt^{n+1/2}: position update
  bool has_fext = false;      // s.fext_x/y/z hold this cycle's external (contact) forces
  bool store_force = false;   // keep the net force in s.fx/fy/fz (rigid bodies use it)
  bool update_positions = false;  // also move the nodes and book the kinetic energy
  // fixed walls applied node by node between the velocity and the position update (with
  // update_positions); their forces (s.wall_force) and work (s.wall_work) are booked
  const std::vector<FixedWall>* walls = nullptr;
};

// a^n from the gathered corner forces and external forces, v^{n+1/2} = v^{n-1/2} + dt^n a^n
// (v^{n-1/2} kept in s.vx_old...), constrained components held; with update_positions also
// x^{n+1} = x^n + dt^{n+1/2} v^{n+1/2} and s.kinetic.
void update_velocities_for_nodes(State& s, const NodePass& p);

// A distributed run (impact3d/parallel): the same pass on the listed nodes only (a rank's own),
// each node's books kept apart in `records`, one record of `stride` doubles per listed node,
// node_record_size(p) of them used here: its kinetic energy (0 without p.update_positions),
// then per fused wall whether it acted and its impulse x y z and energy change (the rest of a
// record is the caller's).  update_positions_for_listed_nodes moves the listed nodes afterwards
// (a pass without update_positions: prescribed motions set velocities in between) and writes
// their kinetic energies into the records.  book_node_records takes the records of every node
// (node order) and makes the chunk sums, s.kinetic and the walls' books exactly as
// update_velocities_for_nodes and update_positions_for_nodes do.
// A pass without update_positions leaves its fixed walls p.walls to apply_walls_to_listed_nodes
// (the engine's apply_stonewalls_to_nodes in one process), which applies them to the listed
// nodes after the velocities, each node wall after wall, their books in the records as above;
// book_node_records then sums each wall's over all nodes in node order, as that function does.
int node_record_size(const NodePass& p);
void apply_walls_to_listed_nodes(State& s, const NodePass& p, const std::vector<int>& nodes, double* records,
                                 std::size_t stride);
void update_velocities_for_listed_nodes(State& s, const NodePass& p, const std::vector<int>& nodes, double* records,
                                        std::size_t stride);
void update_positions_for_listed_nodes(State& s, double dt_next, const std::vector<int>& nodes, double* records,
                                       std::size_t stride);
void book_node_records(State& s, const NodePass& p, const double* records, std::size_t stride);

// x^{n+1} = x^n + dt v^{n+1/2} and s.kinetic, after walls and rigid bodies set the velocities.
void update_positions_for_nodes(State& s, double dt_next);

// s.kinetic from the current velocities (same chunked sum as the passes above).
void calc_kinetic_energy_for_nodes(State& s);

// The time-centred energy book's product of a velocity's v^{n-1/2} (x0, y0, z0) and v^{n+1/2}
// (x1, y1, z1): v^{n-1/2} . (v^{n-1/2} + r (v^{n+1/2} - v^{n-1/2})), r = dt^{n-1/2} / dt^n, the
// increment as a step equal to the last would have made it (r = 1 but where the step changes; the
// run checks' time-centred ratio, run_cycle.h, for nodes and rotational degrees of freedom).
inline double time_centred_product(double x0, double y0, double z0, double x1, double y1, double z1, double r) {
  return x0 * (x0 + r * (x1 - x0)) + y0 * (y0 + r * (y1 - y0)) + z0 * (z0 + r * (z1 - z0));
}

}  // namespace impact3d
