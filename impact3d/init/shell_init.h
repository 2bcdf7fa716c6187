#pragma once
// Initialization of the shells (State::shells): groups, integration points, masses and rotary
// inertias, the shells' corners in the node -> corner map, the rotational degrees of freedom.

#include <string>

#include "impact3d/material/material_types.h"
#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// The kernel that processes shells of a material type (the one table of material type ->
// shell kernel).  Throws std::logic_error for a type no shell kernel handles (the input phase
// refuses such decks first).
ShellKernel shell_kernel_for_material_type(int type);
// Whether shells of a material type have a kernel (the input phase refuses the others).
bool has_shell_kernel(int type);
// The materials shells take, for the readers' messages: "*MAT_ELASTIC, *MAT_PLASTIC_KINEMATIC,
// ..." (their first keywords) and "1, 3, 20 and 24".
std::string shell_material_keywords();
std::string shell_material_numbers();
// A parameter of md that shells refuse when nonzero (message 1102; *feature names what it
// asks for), or nullptr.
const MaterialParam* refused_shell_param(const MaterialData& md, const char** feature);

// Rotary inertia that a shell corner of mass m gives its node: m max(h^2 / 12, A / 8) (the scaled
// rotary inertia of Hughes, Cohen and Haroun 1978 and Kennedy, Belytschko and Lin 1986): the
// thickness-shear mode (every node turning alike) then allows 1.095 L / c for any nu >= 0, so the
// rotations never set the step (docs/shells.md, "Kinks and the rotary inertia").
double shell_rotary_inertia(double corner_mass, double h, double area);

// Share of a shell's mass at corner j: a quadrilateral 1/4 each; a triangle (n3 == n4) 1/3 per
// node (corners 3 and 4 are the same node: 1/6 each).
double corner_fraction(const std::array<int, 4>& c, int j);

// Fills s.shells from the model's shells and adds their masses to s.mass; extends the corner
// forces (s.cfx...) and the node -> corner map by the shells' 4 corners each.  Call after the
// solids are initialized (init_elements) and before the initial velocities.
void init_shells(const Model& m, State& s);

// Initial angular velocities (Model::init_omega) on the rotational degrees of freedom, the
// constrained components at rest.
void init_shell_rotational_velocities(const Model& m, State& s);

}  // namespace impact3d
