#pragma once
// The beams' part of the State (Hughes-Liu beams and trusses, the third element family):
// element data, per-integration-point stresses and history, resultants.  The beams' end
// forces follow the shells' corners in State::cfx/cfy/cfz; their end moments follow the shells'
// corner moments in ShellState::cmx/cmy/cmz, so that the rotational degrees of freedom
// (ShellState: shared by shells and beams on common nodes) gather both.  Allocated once at
// initialization (init/beam_init.h).

#include <array>
#include <cstdint>
#include <vector>

#include "impact3d/element/beam_hl.h"

namespace impact3d {

// Beam kernels, chosen per group from the section's formulation and the material type (one
// table: kBeamMaterials in init/beam_init.cpp).
enum class BeamKernel : std::uint8_t { rigid, hughes_liu, truss, resultant };

struct BeamGroup {
  BeamKernel kernel = BeamKernel::rigid;
  BeamMaterialKind material_kind = BeamMaterialKind::elastic;
  int material = 0;                  // 0-based material index
  double shrf = 1.0;                 // transverse shear factor
  std::vector<BeamRulePoint> rule;   // the section's integration rule (Hughes-Liu)
  int first = 0, count = 0;          // its beams: order[first .. first + count)
  bool spot_weld = false;            // *MAT_SPOTWELD (type 100): its failure rule deletes beams
};

struct BeamState {
  int nb = 0;                                 // number of beams
  std::vector<std::array<int, 3>> conn;       // 0-based nodes n1 n2 n3 (n3 -1: none)
  std::vector<int> mat;                       // 0-based material index
  std::vector<BeamSectionSize> size;          // section sizes (Hughes-Liu)
  std::vector<double> area;                   // cross-section area
  std::vector<double> length0, length;        // initial and current length
  std::vector<double> e2;                     // 3 per beam: the section's s axis (global, unit)
  std::vector<BeamGroup> groups;              // one per material, in material order
  std::vector<int> order;                     // beams group after group, increasing in a group
  std::vector<int> ip_start;                  // first integration point of each beam (nb + 1)
  std::vector<double> sig;                    // 3 per point: local rr rs rt (tensor shears)
  std::vector<double> eps_rr;                 // 1 per point: axial strain (the sum of d_rr dt; output)
  std::vector<double> back;                   // 6 per point (with a plastic-kinematic group; else empty)
  std::vector<double> eps_p;                  // 1 per point (with a plastic group; else empty)
  std::vector<std::uint8_t> yielded;          // 1 per point (with a plastic group; else empty)
  std::vector<double> res;                    // 6 per beam: N, Q_s, Q_t, T, M_s, M_t
  // resultant beams (ELFORM 2): 6 per beam, N, T, M_s at ends 1 and 2, M_t at ends 1 and 2
  // (empty without such a group); their section properties and step factor
  std::vector<double> bs;
  std::vector<BeamResultantSection> rsec;     // per beam (empty without a resultant group)
  std::vector<double> step_scale;             // per beam: the step is L / (c step_scale)
  std::vector<double> dt_e;                   // element step
  std::vector<double> de_ie;                  // this pass's internal-energy increment per beam
  std::vector<double> energy;                 // accumulated internal energy per beam
  std::vector<std::uint8_t> bad;              // 1: zero length in this pass
  // 1: failed and deleted (no forces, no step; *MAT_SPOTWELD's failure rule); the beams that
  // failed in the last pass, in group order (the run log lists them)
  std::vector<std::uint8_t> failed;
  std::vector<int> newly_failed;
  // *MAT_SPOTWELD NF > 0: per such beam its last NF resultant vectors (6 each; a ring, slot
  // count % NF next) from weld_res_start[b] (nb + 1 entries; empty without such a group), and
  // weld_res_count[b] the vectors stored so far; the failure rule takes their mean
  std::vector<double> weld_res;
  std::vector<int> weld_res_start, weld_res_count;
  std::vector<std::uint8_t> rigid_elem;       // 1: beam of a rigid material
  std::size_t corner_base = 0;                // beam b's end j: cfx[corner_base + 2 b + j]
  std::size_t moment_base = 0;                // ... and shells.cmx[moment_base + 2 b + j]
};

}  // namespace impact3d
