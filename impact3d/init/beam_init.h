#pragma once
// Initialization of the beams (State::beams): groups and integration rules, section sizes,
// masses and rotary inertias, the beams' ends in the node -> corner map, and the rotational
// degrees of freedom of their nodes (shared with the shells: ShellState's rotational part).

#include <string>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Whether beams of a material type have a kernel (the input phase refuses the others), and
// the types they take for messages: "*MAT_ELASTIC, *MAT_PLASTIC_KINEMATIC, ..." / "1, 3, 20
// and 24".
bool has_beam_kernel(int type);
std::string beam_material_keywords();
std::string beam_material_numbers();

// The section sizes of beam b of the model: the element's TS1 TS2 TT1 TT2 when it gives them
// (Model::beam_thickness not all 0), else the section's; the means of the node 1 and 2 values.
BeamSectionSize beam_section_size(const Model& m, int b);
// The cross-section area of beam b (a truss: the section's A).
double beam_area(const Model& m, int b);

// Beam b's *ELEMENT_BEAM_ORIENTATION vector (VX VY VZ), or null where it gives none.
const double* beam_orientation_vector(const Model& m, int b);

// The s axis of beam b at its initial position: towards the orientation node n3 (normal to
// the axis), or, without n3, along its orientation vector (normal to the axis), or, without
// either, the global axis least aligned with the beam (x, y, z first on a tie) projected normal
// to it.  Returns false when n3 or the vector lies on the beam's axis or the beam has no length.
bool beam_initial_s_axis(const Model& m, int b, double s[3]);

// Rotary inertia of a beam node: J = (m_e / 2) (L0^2 / 4 + (I_s + I_t) / A), m_e = rho A L0
// (beam_hl.h: no mode of the element is then faster than its axial one).
double beam_rotary_inertia(double beam_mass, double length0, const BeamSectionProperties& p);

// A resultant beam's (ELFORM 2) step factor: its fastest mode (axial 4 EA / (L m), the
// Euler-Bernoulli bending modes 12 EI/L (4 / (L^2 m) + 1 / (2 J)) and 2 EI / (L J), torsion
// 2 G J_t / (L J); m the beam's mass, J a node's rotary inertia from it) over the axial one,
// at least 1: its step is L / (c factor).
double resultant_beam_step_scale(const MaterialConstants& mc, const BeamResultantSection& sec, double length0,
                                 double beam_mass, double node_inertia);

// Fills s.beams from the model's beams, adds their masses to s.mass, extends the corner forces
// and the node -> corner map by the beams' 2 ends each, and adds the nodes of deformable
// Hughes-Liu beams to the rotational degrees of freedom (renumbered in node order; a node of
// shells and beams keeps one set, its inertia the sum).  Call after init_shells.
void init_beams(const Model& m, State& s);

}  // namespace impact3d
