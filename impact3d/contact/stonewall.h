#pragma once
// Rigid walls (DYNA3D stonewalls): infinite planes; a node that would cross its wall in this
// step has its normal velocity reduced so it ends on the wall (no rebound: the momentum goes
// into the wall), with optional stick or Coulomb friction.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Applies every wall to the velocities v^{n+1/2} (positions x^n; dt_next the step about to be
// taken, for the crossing test).  Books the force on each wall, impulse / dt_n with dt_n the
// step the velocity jump belongs to (s.wall_force), and the energy the walls take out
// (s.wall_work).
void apply_stonewalls_to_nodes(const Model& m, State& s, double dt_next, double dt_n);

// Moving walls (mass > 0) translate along their normal with their velocity over the step, like
// the nodes (x^{n+1} = x^n + dt v^{n+1/2}).  The velocity changes in apply_stonewalls_to_nodes
// by the opposite of the impulse the wall gives its nodes, so momentum is kept exactly.
void update_moving_walls(const Model& m, State& s, double dt_next);

}  // namespace impact3d
