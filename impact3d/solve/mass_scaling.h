#pragma once
// Mass scaling (LS-DYNA's *CONTROL_TIMESTEP DT2MS, MS1ST; *CONTROL_TERMINATION ENDMAS).
//
// The element pass computes each element's step dt_e with the material's own density.  An
// element whose mass is f times rho0 V0 has the step dt_e sqrt(f) (the sound speed goes as
// 1 / sqrt(rho); the bulk viscosity keeps the physical density, which only makes the scaled
// step more stable).  With a target element step T = |DT2MS|:
// - every element whose scaled step is below T gets f = (T / dt_e)^2, the mass added going to
//   its nodes as its own mass does (1/8 per solid corner; a shell's corner shares, with the
//   matching rotary inertia); f never decreases, so mass once added stays;
// - DT2MS > 0 also takes mass from the elements above T at the first cycle (f < 1), as LS-DYNA
//   does, so that every deformable element starts with the step T;
// - MS1ST = 1: only at the first cycle.
// The run's step is then TSSF x the smallest scaled step, >= TSSF x T while the scaling
// follows every cycle.  Added mass keeps the node's velocity (as in LS-DYNA): its kinetic
// energy 1/2 dm v^2 is booked as external work so the energy ratio stays meaningful.  Rigid
// solids and shells are never scaled.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Allocates the factors (all 1) and records the model's mass.  No-op without mass scaling.
void init_mass_scaling(const Model& m, State& s);

// Scales the elements whose step is below the target and returns the smallest scaled step
// with its element (solids 0..ne-1, shells ne + k; the lowest index on ties).  dt_min / dt_elem
// are the element pass's unscaled results, returned unchanged without mass scaling.
struct ScaledStep {
  double dt_min = 0;
  int dt_elem = -1;
};
// A distributed run (impact3d/parallel/distributed_cycle.h): every rank has every element's
// step, so every rank adds the same masses to every node; before_adding(ctx, s) is called once,
// on every rank at the same element, before the first mass of a call is added (it brings every
// node's velocity to rank 0, which books the kinetic energy the added mass brings).
struct MassScalingHook {
  void (*before_adding)(void* ctx, State& s) = nullptr;
  void* ctx = nullptr;
};
ScaledStep scale_masses_for_time_step(const Model& m, State& s, double dt_min, int dt_elem, bool first_cycle,
                                      const MassScalingHook& hook = {});

// Added mass as a percentage of the model's mass before scaling.
double added_mass_percent(const State& s);

}  // namespace impact3d
