#pragma once
// The beams' element pass (Hughes-Liu beams and trusses, group by group, one kernel per
// group).  Their rotations go through the shells' rotational node pass
// (update_rotational_velocities_for_nodes, shell_processing.h), their translations through the
// common corner-force gather.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

struct BeamPassResult {
  double die = 0;                // internal-energy increment (beam by beam in group order)
  double dt_min = 0;             // smallest beam step and its beam (lowest index on ties)
  int dt_beam = -1;
  int bad_beam = -1, non_finite_beam = -1;  // lowest such beam, or -1
};

// Element pass of the beams at t^{n+1} (x^{n+1}, v^{n+1/2}, omega^{n+1/2}, dt^{n+1/2}):
// stresses, end forces (s.cfx... at BeamState::corner_base) and moments (s.shells.cmx... at
// BeamState::moment_base), steps L / c, energy books (s.mat_internal too).  Every beam writes
// only its own entries and the sums run in a fixed order: the same bits for any thread count.
BeamPassResult calc_forces_for_beams(const Model& m, State& s);

// The beams' unit of work in a distributed run (impact3d/parallel), as the shells'
// (shell_processing.h): a chunk of kLanes consecutive beams of a group's order, numbered group
// after group.  The number of chunks, and each beam's chunk.
int num_beam_chunks(const BeamState& bm);
std::vector<int> beam_chunk_of_beams(const BeamState& bm);

// The two halves of calc_forces_for_beams: every beam's stresses, end forces and moments, step
// and energy increment (with owns_chunk, only the beams of the marked chunks); then the books
// over every beam in group order (energies, smallest step, bad and non-finite beams, the spot
// welds' failure rule).
void compute_beam_forces(State& s, const std::vector<std::uint8_t>* owns_chunk = nullptr);
BeamPassResult book_beam_results(State& s);

// *MAT_SPOTWELD's failure rule (types/mat_spotweld.cpp) for a beam with resultants res (N,
// Q_s, Q_t, T, M_s, M_t), its section points' plastic strains (null: none) and the time.
bool spot_weld_beam_fails(const MaterialConstants& mc, const double res[6], const double* eps_p, int points, double time);

// The resultants the failure rule of spot-weld beam b takes: with NF > 0 (BeamState::weld_res),
// this pass's vector joins the beam's ring of its last NF and their mean is written to mean
// (returned); otherwise this pass's resultants (BeamState::res).
const double* filtered_weld_resultants(BeamState& bm, int b, double mean[6]);

// The beam's step: L / c, c = sqrt(E / rho) (the rotary inertia keeps the other modes slower).
double beam_time_step(double length, const MaterialConstants& mc);

}  // namespace impact3d
