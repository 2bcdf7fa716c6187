#pragma once
// The shells' part of the State (Belytschko-Tsay, the second element family): element data,
// per-integration-point stresses and history, corner moments, and the rotational degrees of
// freedom of the nodes that shells use.  Allocated once at initialization (init/shell_init.h).

#include <array>
#include <cstdint>
#include <vector>

#include "impact3d/element/shell_block.h"
#include "impact3d/element/shell_bt.h"

namespace impact3d {

// Shell kernels, chosen per group from the material type (one table: kShellMaterials in
// init/shell_init.cpp).
enum class ShellKernel : std::uint8_t { rigid, elastic, plastic_kinematic, piecewise_linear, mooney_rivlin, power_law };

// Whether a kernel keeps 6 values per integration point in ShellState::back (the back stress of
// the plastic-kinematic kernel, the left Cauchy-Green tensor of the Mooney-Rivlin one).
inline bool shell_kernel_has_back(ShellKernel k) {
  return k == ShellKernel::plastic_kinematic || k == ShellKernel::mooney_rivlin;
}

// Whether a kernel keeps a plastic strain per integration point (eps_p, yielded; FAIL deletes).
inline bool shell_kernel_is_plastic(ShellKernel k) {
  return k == ShellKernel::plastic_kinematic || k == ShellKernel::piecewise_linear || k == ShellKernel::power_law;
}

// The element kernel's material kind of a shell kernel.
inline ShellMaterialKind shell_material_kind(ShellKernel k) {
  return k == ShellKernel::plastic_kinematic ? ShellMaterialKind::plastic_kinematic
         : k == ShellKernel::piecewise_linear ? ShellMaterialKind::piecewise_linear
         : k == ShellKernel::mooney_rivlin    ? ShellMaterialKind::mooney_rivlin
         : k == ShellKernel::power_law        ? ShellMaterialKind::power_law
                                              : ShellMaterialKind::elastic;
}

struct ShellGroup {
  ShellKernel kernel = ShellKernel::rigid;
  int material = 0;                 // 0-based material index
  ShellGroupConstants constants;    // section and material constants of the kernel
  int first = 0, count = 0;         // its shells: order[first .. first + count)
  // chosen at initialization: the group runs in blocks of kLanes shells (shell_block.h) when the
  // block kernel covers its material, else shell by shell through the scalar kernel
  bool blocks = false;
  MaterialBlockUpdate update_block = nullptr;  // the material's 3-D block update (plastic kinds)
};

struct ShellState {
  int ns = 0;                                 // number of shells
  std::vector<std::array<int, 4>> conn;       // 0-based nodes (n3 == n4: triangle)
  std::vector<int> mat;                       // 0-based material index
  std::vector<double> thick;                  // thickness (mean of the nodal ones)
  std::vector<double> area0, area;            // initial and current area
  std::vector<ShellGroup> groups;             // one per material, in material order
  std::vector<int> order;                     // shells group after group, increasing in a group
  std::vector<int> nip;                       // integration points of each shell
  std::vector<int> ip_start;                  // first integration point of each shell
  std::vector<double> sig;                    // 5 per point: local xx yy xy yz zx
  std::vector<double> back;                   // 6 per point (with a plastic-kinematic or Mooney-Rivlin group; else empty)
  std::vector<double> eps_p;                  // 1 per point (with a plastic group; else empty)
  std::vector<std::uint8_t> yielded;          // 1 per point (with a plastic group; else empty)
  std::vector<double> hgq;                    // 5 per shell: hourglass resultants (stiffness forms)
  std::vector<double> drill;                  // 4 per shell: corner drilling moments (about e3)
  std::vector<double> dt_e;                   // element step
  std::vector<double> ms_factor;              // mass-scaling factor (empty without mass scaling)
  std::vector<double> de_ie, de_hg;           // this pass's energy increments per shell
  std::vector<double> energy;                 // accumulated internal energy per shell (plot database)
  std::vector<std::uint8_t> bad;              // 1: non-positive area in this pass
  std::vector<std::uint8_t> rigid_elem;       // 1: shell of a rigid material
  std::vector<std::uint8_t> failed;           // 1: deleted (every point past the material's FS)
  std::size_t corner_base = 0;                // shell k's corner j is cfx[corner_base + 4 k + j]
  std::vector<double> cmx, cmy, cmz;          // 4 per shell: corner moments (global)
  // rotational degrees of freedom: only the nodes that deformable shells use
  int nr = 0;
  std::vector<int> rot_node;                  // node of each rotational dof set
  std::vector<int> node_rot;                  // per node: its rotational index or -1
  std::vector<double> wx, wy, wz;             // angular velocities omega^{n-1/2} -> omega^{n+1/2}
  std::vector<double> inertia;                // lumped rotary inertia
  std::vector<std::uint8_t> rot_fix;          // bit 0 rx, 1 ry, 2 rz
  std::vector<int> rot_corner_start, rot_corner_list;  // CSR: rotational dof -> shell corners (4 k + j)
  double rot_kinetic = 0;                     // rotational kinetic energy (in State::kinetic)
};

}  // namespace impact3d
