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
  // a block's corner nodes in block order: the block order[i .. i + kLanes) of a group in blocks
  // has corner j of lane l at block_nodes[4 i + kLanes j + l] (4 per shell; others' unused)
  std::vector<int> block_nodes;
  std::vector<int> nip;                       // integration points of each shell
  // the points' state, in the layout of the table below (shell_sig_at etc.; never index it by hand)
  std::vector<int> pt_base;                   // per shell: the first point of its run of points
  std::vector<std::uint8_t> pt_lane, pt_width;  // per shell: its lane in the run, the run's width
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
  // sum 1/2 I w^{n-1/2} . w^{n+1/2} over the last rotational update: the run checks' time-centred
  // book (run_cycle.h); recomputed every cycle, not in restart dumps
  double rot_kinetic_centred = 0;
};

// The layout of the points' state (sig, back, eps_p, yielded), the one table.  Shell k owns
// points [pt_base, pt_base + width * points) of a run of width shells (points: nip, ELFORM 16
// 5 nip, shell_points_per_shell); in its run it is lane pt_lane.  Its point p, component c is
//   sig[5 pt_base + (5 p + c) width + lane], back[6 pt_base + (6 p + c) width + lane],
//   eps_p[pt_base + p width + lane], yielded[pt_base + p width + lane].
// A group that runs in blocks (ShellGroup::blocks at initialization) keeps each whole block of
// kLanes shells (order[first + kLanes q ..], the block kernel's blocks) as one run of width
// kLanes: block order, what ShellBlock holds, so that the block pass loads and stores them with
// plain vector moves.  Every other shell (a group's last count mod kLanes, the groups shell by
// shell) is a run of width 1: its points together, component after component.  Runs follow the
// groups' order (init/shell_init.cpp, lay_out_shell_points).  Output, histories and exchanges read through these functions, shell by shell
// and point by point, so they see the same values in the same order for any layout.
inline std::size_t shell_point_at(const ShellState& sh, int k, int p) {
  const std::size_t K = std::size_t(k);
  return std::size_t(sh.pt_base[K]) + std::size_t(p) * sh.pt_width[K] + sh.pt_lane[K];
}
inline std::size_t shell_sig_at(const ShellState& sh, int k, int p, int c) {
  const std::size_t K = std::size_t(k);
  return 5 * std::size_t(sh.pt_base[K]) + std::size_t(5 * p + c) * sh.pt_width[K] + sh.pt_lane[K];
}
inline std::size_t shell_back_at(const ShellState& sh, int k, int p, int c) {
  const std::size_t K = std::size_t(k);
  return 6 * std::size_t(sh.pt_base[K]) + std::size_t(6 * p + c) * sh.pt_width[K] + sh.pt_lane[K];
}

}  // namespace impact3d
