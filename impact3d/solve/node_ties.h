#pragma once
// Tied contacts in the cycle (*CONTACT_SPOTWELD, *CONTACT_TIED_NODES_TO_SURFACE; Model::node_ties,
// State::ties): a tied slave node moves with the point of its master segment where it was
// projected, x_s = sum_a w_a x_a.  Its mass and net force go to the segment's nodes by the
// weights (m_a + w_a m_s, f_a + w_a f_s), the masters' velocities follow from those sums, and the
// slave's velocity is the weights' mix of theirs: momentum is kept exactly (sum_a w_a = 1).  Where
// the slave and all four master nodes have rotational degrees of freedom (a weld beam's end on
// shells), the rotations are tied the same way (rotary inertias and moments shared by the
// weights, omega_s = sum_a w_a omega_a), except, for a spot weld, about the segment's normal n:
// *CONTACT_SPOTWELD leaves that component the slave's own (the weld's torsion is not passed to
// the sheet: its moment about n stays with it), *CONTACT_SPOTWELD_WITH_TORSION ties it to the
// segment's in-plane spin, omega_s . n = sum_a g_a . v_a, and passes the moment T about n to the
// segment's nodes as the couple f_a = T g_a (sum_a g_a = 0: momentum kept; a rigid turn of a
// flat segment about n has spin its rate).

// _OFFSET ties (*CONTACT_TIED_NODES_TO_SURFACE_OFFSET, _SURFACE_TO_SURFACE_OFFSET) are penalty
// springs instead, external forces: the slave is not moved, and with p = sum_a w_a x_a and n the
// segment's unit normal (its diagonals' cross product c = d1 x d2 normalised) the spring holds
// r = x_s - p - g n - e = 0 (g the slave's initial offset along n, e the rest of it, zero on a
// flat segment) with the energy U = k |r|^2 / 2; the forces are U's gradient: -k r on the slave,
// k w_a r on the segment's nodes, and the normal's turning, G = k g (I - n n) r / |c| as
// d2 x G on x2 (minus on x0) and G x d1 on x3 (minus on x1).  U depends on relative positions
// only and turns with the pair: momentum and (e = 0) angular momentum are kept, and the offset
// turns with the segment.  k = 0.25 / (dt0^2 (1 / m_s + sum_a w_a^2 / m_a)), dt0 the first step:
// the spring between the slave and its point alone at omega dt = 0.5, inside the margin the
// elements' 1.8 (TSSFAC 0.9) leaves.  Translations only.  _CONSTRAINED_OFFSET ties are the constraint ties above with
// the slave left where it is: x_s - p stays its initial vector.

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// State::ties from Model::node_ties (after the masses, rotary inertias and initial velocities
// are set): each slave starts with the weights' mix of its masters' velocities.
void init_node_ties(const Model& m, State& s);

// After the node pass (net forces in s.fx...; v_old kept) at t^n: the masters' velocities from
// their and their slaves' forces and masses (constrained components left as the pass set
// them), then the slaves' velocities.
void tie_translations(State& s, double dt_n);

// The slaves' velocities from their masters' (after prescribed motions set some masters').
void tie_slave_velocities(State& s);

// Around the rotational update (update_rotational_velocities_for_nodes): keep the masters'
// angular velocities before it; after it, the masters' from their and their slaves' moments and
// rotary inertias, the slaves' the weights' mix, and the rotational kinetic energy again.
void save_tied_rotations(State& s);
void tie_rotations(State& s, double dt_n);

// _OFFSET ties: the springs' stiffnesses once the first step dt0 is known (Engine::initialize);
// their forces at x^n into the external forces (s.fext_*); their work once the cycle's
// velocities are known (s.contact -= dt_n sum f . (v^{n-1/2} + v^{n+1/2}) / 2).
constexpr double kOffsetTieStepShare = 0.5;  // the spring's omega dt0
void init_offset_tie_stiffness(State& s);
void apply_offset_ties(State& s);
void book_offset_tie_energy(State& s, double dt_n);

}  // namespace impact3d
