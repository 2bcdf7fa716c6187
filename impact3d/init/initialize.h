#pragma once
// Initialization: lumped masses, initial volumes, material constants, initial velocities,
// constraints from node codes, node-to-corner maps, rigid bodies.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Builds the State from a checked Model.  All arrays are allocated here, once.
void initialize_state(const Model& m, State& s);

}  // namespace impact3d
