#pragma once
#include "impact3d/model/state.h"
#include "impact3d/model/model.h"

namespace impact3d {

struct ElementLoopResult {
  int bad_volume_elem = -1;   // lowest element index with a non-positive volume, or -1
  int non_finite_elem = -1;   // lowest element index with a non-finite stress or force
  double dt_min = 0;          // smallest element time step (before the scale factor)
  int dt_elem = -1;           // its element (lowest index on ties)
  double die = 0, dhg = 0, dbv = 0;  // energy increments of this pass (block sums in block order)
  double dsrc = 0;                   // energy deposited by equations of state (in die too: external work)
  int failed_now = 0;         // solids that failed in this pass (s.failed == 2)
};

// Element processing at t^n, group by group and block by block (element_groups.h): midpoint
// kinematics with v^{n-1/2}, stress update over dt^{n-1/2}, bulk viscosity, stress-divergence
// and hourglass corner forces at x^n, element time steps, and the element energy books.
// Blocks write only their own slots; the reductions combine per-block results in block order,
// so the result has the same bits for any thread count.
//
// A distributed run (impact3d/parallel) passes hooks: only the solid blocks marked in
// owns_block and the shell and beam chunks marked in owns_shell_chunk and owns_beam_chunk
// (shell_processing.h, beam_processing.h) are computed, then after_blocks runs (it brings
// every block's BlockResult, every shell's and beam's results, forces and moments, and the corner forces this rank's nodes need) before the reductions, which are
// then the same on every rank.
struct ElementPassHooks {
  const std::vector<std::uint8_t>* owns_block = nullptr;  // per block; null: all blocks
  const std::vector<std::uint8_t>* owns_shell_chunk = nullptr;  // per shell chunk; null: all
  const std::vector<std::uint8_t>* owns_beam_chunk = nullptr;   // per beam chunk (beam_processing.h)
  void (*after_blocks)(void* ctx, State& s) = nullptr;
  void* ctx = nullptr;
};
ElementLoopResult calc_forces_for_elems(const Model& m, State& s, const ElementPassHooks& hooks = {});

}  // namespace impact3d
