#pragma once
#include "impact3d/model/state.h"
#include "impact3d/model/model.h"

namespace impact3d {

struct ElementLoopResult {
  int bad_volume_elem = -1;   // lowest element index with a non-positive volume, or -1
  int non_finite_elem = -1;   // lowest element index with a non-finite stress or force
  double dt_min = 0;          // smallest element time step (before the scale factor)
  int dt_elem = -1;           // its element (lowest index on ties)
};

// Element processing at t^n: midpoint kinematics with v^{n-1/2}, stress update over
// dt^{n-1/2}, bulk viscosity, stress-divergence and hourglass corner forces at x^n, element
// time steps, and the element energy increments.  One pass per element; no shared writes.
ElementLoopResult calc_forces_for_elems(const Model& m, State& s);

// Sums the corner forces of every node in fixed order into s.fx/fy/fz (as -f_int) and adds
// the external forces.
void sum_forces_for_nodes(State& s);

}  // namespace impact3d
