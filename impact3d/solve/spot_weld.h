#pragma once
// Spot welds (*CONSTRAINED_SPOTWELD, *CONSTRAINED_GENERALIZED_WELD_SPOT; Model::SpotWeld): each
// is a rigid body of its nodes (solve/rigid_body.h moves it) until its failure rule holds; then
// it is released and its nodes move freely from the next cycle on.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// The constraint force on node j of a weld's body this cycle: m (v^{n+1/2} - v^{n-1/2}) / dt_n
// less the net applied force (s.fx...), from the velocities the body set.
std::array<double, 3> spot_weld_constraint_force(const State& s, const RigidBody& rb, std::size_t j, double dt_n);

// The failure measure of a weld from its constraint forces at x^n: the largest over its nodes of
// (f_n / SN)^N + (f_s / SS)^M (terms with SN or SS 0 left out; f_n the tensile component along
// the node's normal, or with CID's axis its magnitude along it; f_s the rest).
double spot_weld_failure_measure(const SpotWeld& w, const State& s, const RigidBody& rb, double dt_n);

// The effective plastic strain at node n for the ductile rule (EP, EPSF): the elements' plastic
// strains projected to the node by a lumped least-squares fit, i.e. the mean over the live
// deformable solids and shells on the node weighted by their volume or area, a shell's strain
// integrated through its thickness (its rule's weights); 0 where none is plastic.
double spot_weld_node_plastic_strain(const State& s, int n);

// After update_rigid_body_velocities at t^n: each unreleased weld whose measure reaches 1, or
// whose TFAIL has come, or (EPSF > 0) at one of whose nodes the plastic strain reached EPSF, is released (s.newly_released lists them, in weld order).
void check_spot_weld_failure(const Model& m, State& s, double dt_n);

}  // namespace impact3d
