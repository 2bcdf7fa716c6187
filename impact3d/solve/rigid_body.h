#pragma once
// Rigid bodies (material type 20): every node of the body moves with the body's translation
// and rotation; mass and inertia come from the lumped masses of its nodes.

#include "impact3d/model/state.h"

namespace impact3d {

// After the velocity update: integrate each body's momentum and angular momentum from the net
// nodal forces (s.fx/fy/fz) over dt_n, then set its nodes' velocities to the rigid field.
void update_rigid_body_velocities(State& s, double dt_n, double dt_next);
// Sets the velocities of a body's nodes to its rigid field vcom + omega x (x - com).
void set_rigid_body_node_velocities(State& s, const RigidBody& rb);
// The body's centre-of-mass velocity v^{n-1/2} from its nodes' s.vx_old... (during a cycle).
std::array<double, 3> rigid_body_old_velocity(const State& s, const RigidBody& rb);
// After the position update: place the body's nodes from its centre and rotation (no drift).
void update_rigid_body_positions(State& s, double dt_next);
// I w with the body's current inertia R I0 R^T about its centre of mass.
std::array<double, 3> rigid_body_inertia_times(const RigidBody& rb, const std::array<double, 3>& w);
// Sets the body's angular velocity to w (a prescribed rotation): its angular momentum becomes
// I w, and its nodes' velocities the rigid field.
void set_rigid_body_angular_velocity(State& s, RigidBody& rb, const std::array<double, 3>& w);

}  // namespace impact3d
