#pragma once
// Lines of the run log that describe the model's state (run.cpp prints them): the deletion of
// a solid (message 5004, naming what deleted it), the energies, mass scaling, and the final
// shape (extents and the largest plastic strain of the live solids, shells and beams).

#include <string>
#include <vector>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Message 5004's detail for solid e (0-based) deleted in the last cycle by `cause`.
std::string describe_solid_failure(const Model& m, const State& s, int e, FailCause cause);
// Message 5005's detail for beam b deleted in the last cycle (*MAT_SPOTWELD's rule).
std::string describe_beam_failure(const Model& m, const State& s, int b);
// Message 5006's detail for the spot weld of rigid body r released in the last cycle.
std::string describe_weld_release(const Model& m, const State& s, int r);

// The energies (kinetic ... total, initial total, energy ratio), one per line.
std::string energy_report(const State& s);
// Mass scaling: the target step, the mass added so far and its share of the model's mass.
std::string mass_scaling_report(const ControlData& k, const State& s);

// The final shape of the live elements: solids, shells, beams (failed solids and shells, and
// nodes only they held, are left out, as in postimpact summary).
struct FinalShape {
  int failed_solids = 0, failed_shells = 0;
  bool any_live = false;             // a live solid or shell exists (else no extents)
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  int max_eps_solid = -1;            // 0-based live solid of the largest plastic strain, or -1
  int max_eps_shell = -1;            // 0-based live plastic shell of the largest point value, or -1
  int max_eps_beam = -1;             // 0-based plastic beam of the largest point value, or -1
  double solid_eps = 0, shell_eps = 0, beam_eps = 0;
};
FinalShape measure_final_shape(const State& s);

// The run log's lines for it (failed counts, extents, largest plastic strains).
std::vector<std::string> final_shape_lines(const Model& m, const State& s, const FinalShape& f);

}  // namespace impact3d
