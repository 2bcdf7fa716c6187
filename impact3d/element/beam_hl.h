#pragma once
// Beams (the third element family): the Hughes-Liu beam (LS-DYNA ELFORM 1, DYNA3D beam type 1)
// and the truss (ELFORM 3).  Scalar kernels on the caller's arrays (no heap, no solver state).
//
// Hughes-Liu beam as built here: two nodes with translations and rotations, linear
// interpolation along the axis with one integration point at the middle (a Timoshenko beam
// with transverse shear, reduced integration: no locking, no spurious modes), integrated over
// the cross section at the section's points (y along s, z along t).  Co-rotational: the local
// frame r (node 1 -> node 2), s (the section axis, carried by the mean nodal spin and kept
// normal to r), t = r x s follows the element, so the stresses kept in it need no objective
// rotation.  Strain rates at a section point (y, z), with the rates at the midpoint geometry
// x^{n+1/2} = x^{n+1} - dt/2 v and omega the nodal angular velocities:
//   d_rr = dv.r / L - y (w2 - w1).t / L + z (w2 - w1).s / L
//   2 d_rs = SHRF (dv.s / L - (w1 + w2).t / 2 - z (w2 - w1).r / L)
//   2 d_rt = SHRF (dv.t / L + (w1 + w2).s / 2 + y (w2 - w1).r / L)
// (dv = v2 - v1).  The stress of each point is uniaxial with transverse shear
// (material/beam_stress.h).  The nodal forces and moments are the rates' work conjugates
// (virtual power) at x^{n+1}, built from the resultants N = int s_rr, M_s = int z s_rr,
// M_t = -int y s_rr, Q_s = SHRF int s_rs, Q_t = SHRF int s_rt, T = SHRF int (y s_rt - z s_rs):
// they balance (no net force or moment) and the element books exactly the work they do.
//
// Rotary inertia (IMPACT-3D's choice, as LS-DYNA scales beam rotary inertia): each node gets
// J = (m/2) (L0^2 / 4 + (I_s + I_t) / A) about every axis, so that no bending, shear or torsion
// mode of the element is faster than its axial mode: the beam's step is the bar's, L / c with
// c = sqrt(E / rho).

#include <array>
#include <vector>

#include "impact3d/material/beam_stress.h"
#include "impact3d/model/model.h"

namespace impact3d {

// A point of a section's integration rule in normalized coordinates: rectangular: (a, b) in
// [-1, 1]^2 along s and t, weight w (the weights sum to 4); tubular: a in [-1, 1] across the
// wall (inner to outer), b the angle around the axis (radians), w the weight of the point's
// share (the weights sum to 2 x 2 pi: Gauss weights across the wall times the arc 2 pi / n).
struct BeamRulePoint {
  double a = 0, b = 0, w = 0;
};

// The section's integration rule (LS-DYNA QR; BeamSectionData documents the rules).
// Returns false for an unknown rule number (the input checks refuse it first).
bool beam_integration_rule(const BeamSectionData& sec, std::vector<BeamRulePoint>& rule);

// Section sizes of one beam (the means of the node 1 and node 2 values): rectangular: ts, tt
// the widths along s and t; tubular: ts the outer and tt the inner diameter.
struct BeamSectionSize {
  BeamCrossSection cst = BeamCrossSection::rectangular;
  double ts = 0, tt = 0;
};
// Exact section properties: area, second moments about s and t (I_s = int z^2, I_t = int y^2).
struct BeamSectionProperties {
  double area = 0, i_s = 0, i_t = 0;
};
BeamSectionProperties beam_section_properties(const BeamSectionSize& sz);
// The physical place (y along s, z along t) and area share dA of a rule point.
void beam_point_place(const BeamSectionSize& sz, const BeamRulePoint& p, double& y, double& z, double& da);

// One beam's data for the kernel: x at t^{n+1}, v and w (angular velocities) at t^{n+1/2}.
struct BeamKernelIO {
  double x[2][3], v[2][3], w[2][3];
  double dt = 0;            // dt^{n+1/2}
  double e2[3] = {};        // in: the s axis at t^n; out: at t^{n+1}
  // out
  double f[2][3], m[2][3];  // internal end forces and moments (global frame)
  double res[6] = {};       // resultants N, Q_s, Q_t, T, M_s, M_t (local frame)
  double length = 0;        // at t^{n+1}
  double de_ie = 0;         // work of the stresses this step (trapezoid in stress)
  bool bad = false;         // zero length or not finite
};

// Per-point state: 3 stresses (rr, rs, rt; tensor shears) per point, plastic history.
struct BeamPointState {
  double* sig;             // 3 per point
  double* eps_rr;          // 1 per point: axial strain (d_rr dt summed)
  double* back;            // 6 per point (plastic-kinematic), else null
  double* eps_p;           // 1 per point (plastic kinds), else null
  unsigned char* yielded;  // 1 per point (plastic kinds), else null
};

// The section's s axis from the beam's axis r (unit) and a direction g: g projected normal to
// r, normalized.  Returns false when g is (nearly) along r.
bool beam_s_axis(const double r[3], const double g[3], double s[3]);

// The Hughes-Liu beam: frame update, rates, stress update at each rule point, resultants,
// forces and moments, energy.
void calc_beam_hl_forces(const BeamSectionSize& sz, const std::vector<BeamRulePoint>& rule, double shrf,
                         const MaterialConstants& mc, BeamMaterialKind kind, BeamKernelIO& io,
                         const BeamPointState& st);

// The Belytschko-Schwer resultant beam (ELFORM 2), elastic: co-rotational as the Hughes-Liu
// beam, Euler-Bernoulli bending from the end rotations relative to the chord (no shear strain):
// the rates of the end moments (EI/L) (4 th_1 + 2 th_2), (EI/L) (2 th_1 + 4 th_2) with th_i
// the node's spin less the chord's (about s and t), N' = EA dv.r / L, T' = GJ dw.r / L; the
// shear forces balance the end moments (Q = (M_1 + M_2) / L).  A single element is exact for a
// cantilever's end load.  state: N, T, M_s1, M_s2, M_t1, M_t2.
struct BeamResultantSection {
  double area = 0, iss = 0, itt = 0, jt = 0;
};
void calc_beam_bs_forces(const BeamResultantSection& sec, const MaterialConstants& mc, BeamKernelIO& io, double state[6]);

// The truss (ELFORM 3): axial stress only (one point, area A), forces along the axis, no
// moments.  sig/eps_p... as one point of BeamPointState.
void calc_truss_forces(double area, const MaterialConstants& mc, BeamMaterialKind kind, BeamKernelIO& io,
                       const BeamPointState& st);

}  // namespace impact3d
