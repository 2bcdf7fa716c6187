#pragma once
// Element groups: at initialization the solids are sorted into groups of one family, one
// material and one formulation; the element pass dispatches per group (one kernel for the
// whole group, kLanes elements at a time), never per element.  A new material or family adds
// a kernel and a row in the table of element_groups.cpp, not a branch in the element loop.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// What the element pass does with solids of a material type (the table of material_types.h).
// Throws std::logic_error for a type no kernel handles (the input phase refuses
// such decks first).
HexKernel hex_kernel_for_material_type(int type);

// Whether a group's solids carry a back stress (type 3 with a kinematic part) and hourglass
// resultants (any hourglass control: the stiffness forms' springs, the viscous forms'
// resultants of the last pass for the energy books): the element pass reads and writes s.back / s.hgs only
// for such groups, and they are allocated only when some group needs them.
bool group_carries_back_stress(const SolidKernel& kernel, const MaterialConstants& mc);
bool group_carries_hourglass_state(const MaterialData& md);

// Fills s.groups, s.slot_elem, s.elem_slot and s.block_results from s.conn and s.mat: one
// group per material (in material order), its elements in increasing order, its formulation
// the material's MaterialData::solid_elform.  With one material, slot = element.
void build_element_groups(State& s, const Model& m);

// Allocates the fully integrated solids' point state (State::pt_*) and starts each point from
// its solid's state (stress, plastic strain, history: initial temperatures and the like).
// After s.hist_stride, s.back and the initial element state are set.
void init_point_state(State& s);

}  // namespace impact3d
