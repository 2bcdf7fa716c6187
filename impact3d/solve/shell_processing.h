#pragma once
// The shells' parts of the cycle: the element pass of the Belytschko-Tsay shells (group by
// group, one kernel per group) and the node pass of the rotational degrees of freedom (kept
// apart from node_processing.cpp: the translations of shell nodes go through the common
// corner-force gather there).

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

struct ShellPassResult {
  double die = 0, dhg = 0;       // energy increments (shell by shell in group order)
  double dt_min = 0;             // smallest shell step and its shell (lowest index on ties)
  int dt_shell = -1;
  int bad_shell = -1, non_finite_shell = -1;  // lowest such shell, or -1
  int failed_now = 0;            // shells deleted in this pass (failure strain FS)
};

// Element pass of the shells at t^n (x^n, v^{n-1/2}, omega^{n-1/2}, dt^{n-1/2}): stresses,
// corner forces (s.cfx... at ShellState::corner_base) and moments, steps, energy books
// (s.mat_internal, s.mat_hourglass too).  Every shell writes only its own entries and the
// sums run in a fixed order: the same bits for any thread count.  The two halves below.
ShellPassResult calc_forces_for_shells(const Model& m, State& s);

// The shells' unit of work in a distributed run (impact3d/parallel): a chunk of kLanes
// consecutive shells of a group's order (one block of the block kernel; a group's last chunk
// may be shorter), numbered group after group.  The number of chunks, and each shell's chunk.
int num_shell_chunks(const ShellState& sh);
std::vector<int> shell_chunk_of_shells(const ShellState& sh);

// The first half: every shell's stresses, corner forces and moments, step and this pass's
// energy increments (ShellState::de_ie, de_hg, dt_e, bad, failed 2); with owns_chunk (one
// entry per chunk), only the shells of the marked chunks.
void compute_shell_forces(State& s, const std::vector<std::uint8_t>* owns_chunk = nullptr);
// The second half: the books over every shell, group by group in order (energies, the
// smallest step, bad and non-finite shells, failures), from what the first half left.
ShellPassResult book_shell_results(State& s);

// omega^{n+1/2} = omega^{n-1/2} + dt^n (-sum of the corner moments) / I on the rotational
// degrees of freedom, constrained components held (nodes of rigid bodies take the body's
// angular velocity); books the rotational kinetic energy in s.shells.rot_kinetic and adds it to
// s.kinetic (call after the translational node pass has set s.kinetic).
void update_rotational_velocities_for_nodes(State& s, double dt_n);

// Rotational kinetic energy sum I |omega|^2 / 2 (in rotational dof order).
double calc_rotational_kinetic_energy(const State& s);

}  // namespace impact3d
