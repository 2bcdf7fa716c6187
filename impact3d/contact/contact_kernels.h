#pragma once
// Per-point physics of the sliding interfaces (shared/spec/physics.md section 5, seed part II):
// the bilinear segment, the closest point of a node on a segment (Newton on the patch, with the
// edges and corners where the normal jumps), the two penalty stiffnesses, the force
// distribution of the 5-node "pyramid" spring (seed eqs. 3-4, fig. 5) and Coulomb friction.
// Small pure functions: sliding_interface.cpp calls them once per node and per candidate
// segment, the unit tests call them directly.

#include <cstdint>

namespace impact3d::contact {

// Segment nodes 0..3 at (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1): counter-clockwise seen from
// outside the body, so x_xi x x_eta is the outward normal.  A triangle repeats node 3 = node 2.
// Edge e joins node e and node (e+1) % 4.
using SegX = double[4][3];

// N_A(xi, eta) = (1 + xi_A xi)(1 + eta_A eta) / 4 (seed eq. 1).
void shape4(double xi, double eta, double N[4]);

// x(xi, eta) and its tangents x_xi, x_eta.
void segment_point(const SegX& X, double xi, double eta, double x[3], double x_xi[3],
                   double x_eta[3]);

// Unit outward normal at (xi, eta); falls back to the normal of the diagonals where the
// tangents are parallel (the collapsed corner of a triangle).
void segment_normal(const SegX& X, double xi, double eta, double n[3]);

// Area (half the cross product of the diagonals: exact for a plane quadrilateral).
double segment_area(const SegX& X);

// Newton (full, falling back to Gauss-Newton where the Hessian is not positive) on
// |x(xi, eta) - p|^2 over the extended patch, (xi, eta) kept in [-2, 2]^2.  Starts at (0, 0).
// Returns the iterations used.
int project_to_patch(const SegX& X, const double p[3], double& xi, double& eta);

// The closest point of a node on one segment and the gap along the contact normal.
struct SegmentHit {
  bool valid = false;    // false: the point is off the surface (beyond a boundary edge)
  bool on_edge = false;  // the closest point is on an edge or a corner (normal from the offset)
  double xi = 0, eta = 0;  // point of the segment used to distribute the force (in [-1, 1]^2)
  double xp[3] = {0, 0, 0};
  double n[3] = {0, 0, 0};  // contact normal, pointing out of the master body
  double gap = 0;           // (x_node - x_p) . n: negative = penetration
  double dist = 0;          // |x_node - x_p|: what the search minimises over segments
};

// boundary_edges: bit e set when edge e of this segment is on the boundary of its surface (no
// other segment of the surface shares it).  tol: how far (in xi, eta) beyond the square a
// projection still counts as interior (round-off at the rim of a surface).
//  - projection inside the square (+ tol): x_p on the patch, n the patch normal there, gap
//    along n (the Newton point, seed fig. 2);
//  - otherwise the nearest point on the four (straight) edges.  On an interior edge or corner
//    (where the normal jumps) the normal is the unit offset x_node - x_p, signed by the side of
//    the segment the node is on: a node in a concave corner is pushed straight out, a node
//    outside a convex edge gets no force.  Beyond a boundary edge (the rim of the surface: a
//    free edge, or a symmetry plane whose mirrored neighbour is not modelled) the face is
//    extended: x_p the clamped projection, n its normal, valid only for a node below the face
//    by more than it is beyond the rim (|lateral offset| <= -gap).
SegmentHit closest_point_on_segment(const SegX& X, const double p[3], std::uint8_t boundary_edges,
                                    double tol);

// The closest point of a node on a shell segment (the shell's mid-surface, both sides usable):
//  - projection inside the square (+ tol): x_p on the patch, n = +-(patch normal) on the node's
//    side, dist = |(x_node - x_p) . n_patch|;
//  - otherwise the nearest point on the four straight edges (free rim or not): the contact
//    surface is rounded about the edge (LS-DYNA's automatic contacts), n = the unit offset
//    x_node - x_p, dist = its length (a node on the edge itself: n the patch normal).
// gap = dist: the caller subtracts the thickness offsets (half the shell's thickness, plus half
// the node's own shell thickness), penetration = offset - dist.  Always valid.
SegmentHit closest_point_on_shell_segment(const SegX& X, const double p[3], double tol);

// Penalty stiffness of a shell segment, choice 0 (LS-DYNA's shell form of the DYNA3D
// stiffness): k = mu K A / (longest diagonal).
double shell_stiffness(double mu, double bulk_modulus, double area, double max_diagonal);

// Penalty stiffness, choice 0 (DYNA3D, Hallquist; seed eq. 6): k = mu K A^2 / V.
double dyna3d_stiffness(double mu, double bulk_modulus, double area, double volume);

// PENOPT (LS-DYNA *CONTROL_CONTACT): the penalty stiffness of a node on a segment from the
// segment's stiffness and the node's own (the smallest of its surface segments'): 1 the smaller
// (LS-DYNA's default: a stiff segment's k on a light node is not stable), 2 the segment's
// (DYNA3D), 3 the node's.  A node without a stiffness of its own (0) takes the segment's.
double penopt_stiffness(int penopt, double k_segment, double k_node);

// LS-DYNA's soft constraint (SOFT = 1): k = max(k0, SOFSCL 0.5 m* / dt_c^2), k0 the penalty
// stiffness of choice 0 (with PENOPT), m* the smaller of the node's mass and its segment's
// nodes' masses, dt_c the step (the first, and later the largest taken).
double soft_constraint_stiffness(double k0, double sofscl, double m_star, double dt_c);

// LS-DYNA's segment-based contact (SOFT = 2): the stiffness of a segment pair,
// k = 0.5 mu m1 m2 / (m1 + m2) / dt_c^2 (mu = SLSFAC x SFS, m1, m2 the two segments' masses,
// dt_c the step).  0 when a mass or dt_c is not positive.
double segment_pair_stiffness(double mu, double m1, double m2, double dt_c);

// The points of a segment that segment-based contact checks: its 2 x 2 Gauss points
// (xi, eta) = (+-1/sqrt(3), +-1/sqrt(3)), counter-clockwise from (-, -); each carries a quarter
// of the segment pair's stiffness.
constexpr int kSegmentPoints = 4;
void segment_point_coordinates(int i, double& xi, double& eta);

// Penalty stiffness, choice 1 (IMPACT-3D maximum stable; seed eqs. 10-17):
// alpha = 1 - F^2 (F the time-step scale factor), k = c alpha / (dt^2 (1/m1 + 1/m2)) with c = 2
// for the symmetric (two-pass) treatment, where each spring only gets half the mass alpha m
// (eq. 16-17), and c = 4 for one pass (eq. 14-15).  alpha is kept >= 0.01 (F = 1 leaves no
// margin).  Returns 0 when a mass is not positive.
double max_stable_alpha(double tssf);
double max_stable_stiffness(double tssf, double dt, double m1, double m2, bool symmetric);

// Force distribution (seed eq. 3 and fig. 5): F = k p n on the node, F_A = -F N_A on the four
// segment nodes.  The sum is zero (momentum is conserved exactly).
void distribute_force(const double f[3], const double N[4], double fa[4][3]);

// The 5-node pyramid spring in the normal direction (seed eq. 4): K = k [N N^T, -N; -N^T, 1]
// (row/column 4 is the node), so that K u gives the explicit forces for normal displacements u.
void pyramid_stiffness(double k, const double N[4], double K[5][5]);

// Its only non-zero eigenvalue of K x = lambda M x with M = diag(m_seg x 4, m_node) (seed
// eq. 13): lambda = k (1/m_node + sum N_A^2 / m_seg).
double pyramid_eigenvalue(double k, const double N[4], double m_seg, double m_node);

// Coulomb coefficient with exponential decay (DYNA3D): mu = fd + (fs - fd) exp(-decay |v_t|).
double friction_coefficient(double fs, double fd, double decay, double vt);

// Tangential (friction) force on the node, given the normal force magnitude fn, the contact
// normal, the relative velocity v_node - sum N_A v_A, and 1/m_eff = 1/m_node + sum N_A^2/m_A.
// Coulomb: |F_t| = min(mu fn, cap) against the sliding direction, the cap being half the force
// that would stop the relative tangential motion in one step dt (a stable explicit stick, no
// history: the result depends only on the state at the start of the cycle).
void friction_force(double mu, double fn, const double n[3], const double vrel[3],
                    double inv_meff, double dt, double ft[3]);

}  // namespace impact3d::contact
