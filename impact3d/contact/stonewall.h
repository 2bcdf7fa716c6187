#pragma once
// Rigid walls (DYNA3D stonewalls): infinite planes, and fixed cylinders
// (*RIGIDWALL_GEOMETRIC_CYLINDER: the plane tangent at the point nearest to each node); a node
// that would cross its wall in this step has its normal velocity reduced so it ends on the wall
// (no rebound: the momentum goes into the wall), with optional stick or Coulomb friction.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

#include <algorithm>
#include <cmath>

namespace impact3d {

// One node against one wall moving at vw along its normal n (0: fixed), p a point of the wall
// at time n.  Adds the impulse the node received to imp and the kinetic energy change it
// caused to dke (negative: taken out).  Returns whether the wall acted on the node.
inline bool apply_wall_to_node(State& s, int i, const double p[3], const double n[3], double vw,
                               double fric, double dt, double imp[3], double& dke) {
  const std::size_t k = std::size_t(i);
  const double mass = s.mass[k];
  if (mass <= 0 || s.rigid_of_node[k] >= 0) return false;  // rigid bodies: warning 2012 at input
  const double d = (s.x[k] - p[0]) * n[0] + (s.y[k] - p[1]) * n[1] + (s.z[k] - p[2]) * n[2];
  const double vn = s.vx[k] * n[0] + s.vy[k] * n[1] + s.vz[k] * n[2];
  if (d + dt * (vn - vw) >= 0) return false;  // stays on the body's side
  const double vn_new = std::max(vn, vw - std::max(d, 0.0) / dt);
  const double dvn = vn_new - vn;  // >= 0
  double dv[3] = {dvn * n[0], dvn * n[1], dvn * n[2]};
  if (fric > 0) {
    double vt[3] = {s.vx[k] - vn * n[0], s.vy[k] - vn * n[1], s.vz[k] - vn * n[2]};
    double vt_mag = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
    if (vt_mag > 0) {
      // stick removes the tangential velocity; Coulomb limits its change to fric * dvn
      double dvt = fric >= 1 ? vt_mag : std::min(vt_mag, fric * dvn);
      for (int a = 0; a < 3; ++a) dv[a] -= dvt * vt[a] / vt_mag;
    }
  }
  s.vx[k] += dv[0];
  s.vy[k] += dv[1];
  s.vz[k] += dv[2];
  // Work of the wall impulse on the mean velocity (v^{n-1/2} + v^{n+1/2}) / 2: the form that
  // balances the central-difference kinetic energy.  A node resting on the wall takes none.
  const double vmx = 0.5 * (s.vx_old[k] + s.vx[k]), vmy = 0.5 * (s.vy_old[k] + s.vy[k]),
               vmz = 0.5 * (s.vz_old[k] + s.vz[k]);
  dke -= mass * (dv[0] * vmx + dv[1] * vmy + dv[2] * vmz);
  for (int a = 0; a < 3; ++a) imp[a] += mass * dv[a];
  return true;
}

// A fixed wall that acts on every node (no node list, no mass): the node pass applies it node
// by node in its own loop (node_processing.h), with the impulses and energy summed per chunk.
struct FixedWall {
  double p[3], n[3];  // a point of the plane and its unit normal (toward the body)
  double friction;
};
// The model's walls as FixedWalls, when every wall is one (else empty: the walls then run in
// apply_stonewalls_to_nodes between the velocity and position updates).
std::vector<FixedWall> fixed_walls_for_node_pass(const Model& m);

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
