#pragma once
// Model: what the deck says, in the deck's own numbering, after the input phase has read and
// checked it.  Nodes and solids are numbered 1..NUMNP and 1..NUMELH in the deck (each number
// once, any order); the arrays here are indexed by number - 1.  Element node references are
// 0-based node indices.

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace impact3d {

struct ControlData {
  // card 2
  int nmmat = 0, numnp = 0, numelh = 0;
  int interface_segments_out = 0;
  double interface_out_interval = 0;
  // card 3
  int node_th_blocks = 0, solid_th_blocks = 0;
  int report_interval = 100;  // cycles between run-log lines
  int reaction_print_flag = 0;
  // card 5
  int numlc = 0, num_walls = 0, num_init_velocity_cards = 0, num_interfaces = 0;
  // card 6
  double end_time = 0;
  int end_cycle = 0;         // also stop after this many cycles (0: no limit; keyword ENDCYC)
  double th_interval = 0;    // time-history output interval (0 -> end_time / 1000)
  double plot_interval = 0;  // plot-state interval (0 -> end_time / 20)
  int restart_dump_cycles = 0, running_restart_cycles = 0;
  double initial_dt = 0;     // 0 = computed
  double penalty_scale = 0.10;
  int viscosity_flag = 0;
  double tssf = 0.90;
  // card 8
  double min_step_factor = 0;  // error termination when dt < factor * dt0 (0 = no check)
};

// *SECTION_SHELL of a shell part (Belytschko-Tsay, LS-DYNA ELFORM 2).
struct ShellSectionData {
  int nip = 2;                       // Gauss points through the thickness, 1-10
  double shrf = 1.0;                 // transverse shear factor (LS-DYNA: blank/0 -> 1; 5/6 advised)
  std::array<double, 4> t{};         // default nodal thicknesses T1-T4
  int line = 0;
};

struct MaterialData {
  int number = 0;
  int type = 0;          // 1 elastic, 3 elastic-plastic, 20 rigid
  double rho = 0;
  int hourglass_type = 1;
  double hourglass_coef = 0.10;
  int bulk_type = 1;
  double q1 = 1.5;       // quadratic bulk viscosity
  double q2 = 0.06;      // linear bulk viscosity
  std::string title;
  double E = 0, nu = 0, sigma_y = 0, E_tan = 0, beta = 0;
  // type 3: Cowper-Symonds strain-rate scaling of the yield stress, 1 + (rate / C)^(1/P)
  // (C = 0: none), and the effective plastic strain at which a solid fails and is deleted
  // (0: never)
  double rate_c = 0, rate_p = 0, fail_strain = 0;
  bool initially_elastic = false;
  bool packed = false;   // parameters were read 8 per card
  int line = 0;          // line of card 1, for messages
  bool shell = false;    // the part is a shell part (its elements are in Model::shell_nodes)
  ShellSectionData shell_section;
};

struct StoneWall {
  std::array<double, 3> tail{}, head{};
  double friction = 0;   // 0 frictionless, 1 stick, between Coulomb
  // moving wall (mass > 0): a rigid plate of this mass that translates along its normal, with
  // initial velocity v0 along the normal (tail -> head); the nodes' impulses act on it
  double mass = 0, v0 = 0;
  std::vector<int> nodes;  // 0-based; empty = all nodes
  int line = 0;
};

struct InitialVelocity {
  int first = 0, last = 0, increment = 1;  // deck node numbers; first = 0 means all nodes
  std::array<double, 3> v{};
};

struct SlidingInterface {
  int type = 3;
  double fs = 0, fd = 0, decay = 0;
  double penalty_scale = 0;   // 0 -> control penalty_scale
  int stiffness_method = 0;   // 0 DYNA3D mu K A^2 / V, 1 IMPACT-3D maximum stable
  bool symmetric = true;
  std::vector<std::array<int, 4>> slave, master;  // 0-based nodes
  std::vector<int> slave_line, master_line;       // deck line of each segment card (messages)
  std::vector<int> slave_file, master_file;       // Model::source_files index of that line (empty: the deck)
  int line = 0;
};

struct LoadCurve {
  int number = 0;
  std::vector<double> t, f;
};

struct Model {
  std::string title;
  std::string deck_file;
  bool large_format = true;
  bool keyword_deck = false;  // read from an LS-DYNA keyword deck
  ControlData control;
  std::vector<MaterialData> materials;  // indexed by material number - 1

  // nodes (index = node number - 1)
  std::vector<double> x, y, z;
  std::vector<int> bc;       // 0-7 displacement code
  // solids (index = element number - 1)
  std::vector<std::array<int, 8>> hex_nodes;  // 0-based node indices
  std::vector<int> hex_material;              // 0-based material index
  std::vector<int> hex_line;                  // deck line of each solid card, 0 = not read
  std::vector<int> hex_file;                  // source_files index of that line (empty: the deck)
  std::vector<std::string> source_files;      // include files that lines refer to (keyword decks)
  // the file a line recorded with index `idx` of `files` is in (messages)
  const std::string& file_of(const std::vector<int>& files, std::size_t idx) const {
    if (idx < files.size() && files[idx] >= 0 && std::size_t(files[idx]) < source_files.size())
      return source_files[std::size_t(files[idx])];
    return deck_file;
  }
  // Ids in the deck when they are not 1..N (keyword decks have arbitrary sparse ids and are
  // renumbered 1..N in increasing id order); empty = identity.
  std::vector<int> node_user_id, hex_user_id;

  // Shells (Belytschko-Tsay, index = shell number - 1): nodes n1-n4 (0-based, n3 == n4 for a
  // triangle), material, nodal thicknesses, and where each card is.
  std::vector<std::array<int, 4>> shell_nodes;
  std::vector<int> shell_material;
  std::vector<std::array<double, 4>> shell_thickness;
  std::vector<int> shell_line, shell_file;
  std::vector<int> shell_user_id;            // deck ids when not 1..N (empty: identity)
  // Rotational constraints per node (bit 0 rx, 1 ry, 2 rz; empty: none) and initial
  // rotational velocities (empty: none); they act on nodes that shells use.
  std::vector<std::uint8_t> rot_bc;
  std::vector<std::array<double, 3>> init_omega;
  double shell_rotary_scale = 1.0;           // *CONTROL_SHELL ROTASCL: scales the rotary inertia
  int num_shells() const { return static_cast<int>(shell_nodes.size()); }
  int shell_id(int k) const { return shell_user_id.empty() ? k + 1 : shell_user_id[std::size_t(k)]; }

  std::vector<std::array<int, 2>> node_th_blocks, solid_th_blocks;  // deck numbers, inclusive
  std::vector<LoadCurve> load_curves;
  std::vector<StoneWall> walls;
  std::vector<InitialVelocity> init_velocities;
  std::vector<SlidingInterface> interfaces;

  int num_nodes() const { return static_cast<int>(x.size()); }
  // The deck's number of node i / solid e (0-based indices): what every message and output shows.
  int node_id(int i) const { return node_user_id.empty() ? i + 1 : node_user_id[std::size_t(i)]; }
  // (an index past the solids is a shell: num_hexes() + shell index, as the element pass
  // reports the element controlling the step)
  int hex_id(int e) const {
    if (e >= num_hexes()) return shell_id(e - num_hexes());
    return hex_user_id.empty() ? e + 1 : hex_user_id[std::size_t(e)];
  }
  int num_hexes() const { return static_cast<int>(hex_nodes.size()); }
};

// Which translational components a boundary-condition code 0-7 fixes.
inline bool bc_fixes_x(int code) { return code == 1 || code == 4 || code == 6 || code == 7; }
inline bool bc_fixes_y(int code) { return code == 2 || code == 4 || code == 5 || code == 7; }
inline bool bc_fixes_z(int code) { return code == 3 || code == 5 || code == 6 || code == 7; }

// A node list as a set: later repeats of a node removed, the order of first appearance kept (a
// wall's nodes are a set: a repeated node must not count twice).
inline void remove_repeated_nodes(std::vector<int>& nodes) {
  std::vector<int> out;
  out.reserve(nodes.size());
  std::vector<int> sorted = nodes;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return;  // none
  std::vector<char> seen(sorted.empty() ? 0 : std::size_t(sorted.back()) + 1, 0);
  for (int n : nodes)
    if (n >= 0 && !seen[std::size_t(n)]) seen[std::size_t(n)] = 1, out.push_back(n);
  nodes.swap(out);
}

}  // namespace impact3d
