#pragma once
// Test and benchmark support: a model's node and solid numbers shuffled (a deterministic
// seed), as a deck with scattered numbering would have them.  The result is a new deck in its
// own right: its numbers are 1..N in the shuffled order (no user ids, no order maps), its
// initial-velocity ranges and time-history blocks name the same nodes and solids as before.

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "impact3d/init/mesh_order.h"
#include "impact3d/model/model.h"

namespace test_support {

// A permutation of 0..n-1 (Fisher-Yates with std::mt19937: the same on every platform).
inline std::vector<int> random_permutation(int n, unsigned seed) {
  std::vector<int> p(static_cast<std::size_t>(n));
  std::iota(p.begin(), p.end(), 0);
  std::mt19937 gen(seed);
  for (int i = n - 1; i > 0; --i) {
    const int j = int(gen() % std::uint32_t(i + 1));
    std::swap(p[std::size_t(i)], p[std::size_t(j)]);
  }
  return p;
}

// Number ranges [first, last] (1-based) of a list of 0-based indices, consecutive runs merged.
inline std::vector<std::array<int, 2>> ranges_of(const std::vector<int>& idx) {
  std::vector<std::array<int, 2>> r;
  for (int i : idx) {
    if (!r.empty() && r.back()[1] == i) r.back()[1] = i + 1;
    else r.push_back({i + 1, i + 1});
  }
  return r;
}

inline void shuffle_mesh_numbering(impact3d::Model& m, unsigned seed) {
  using namespace impact3d;
  const std::vector<int> node_new = random_permutation(m.num_nodes(), seed);
  const std::vector<int> hex_new = random_permutation(m.num_hexes(), seed + 1);
  // deck-number lists in the old numbering, resolved before the model moves
  std::vector<std::pair<InitialVelocity, std::vector<int>>> ivs;
  for (const auto& iv : m.init_velocities) {
    std::vector<int> nodes;
    if (iv.first != 0)
      for (int n = iv.first; n <= iv.last; n += iv.increment) nodes.push_back(node_new[std::size_t(m.node_of_deck_number(n))]);
    std::sort(nodes.begin(), nodes.end());  // one velocity: the order of its nodes does not matter
    ivs.push_back({iv, nodes});
  }
  auto blocks = [&](const std::vector<std::array<int, 2>>& bl, bool nodes) {
    std::vector<int> idx;
    for (const auto& b : bl)
      for (int k = b[0]; k <= b[1]; ++k)
        idx.push_back(nodes ? node_new[std::size_t(m.node_of_deck_number(k))] : hex_new[std::size_t(m.hex_of_deck_number(k))]);
    return ranges_of(idx);
  };
  const auto node_blocks = blocks(m.node_th_blocks, true);
  const auto solid_blocks = blocks(m.solid_th_blocks, false);
  permute_model(m, node_new, hex_new);
  m.node_order.clear();
  m.hex_order.clear();
  m.node_user_id.clear();
  m.hex_user_id.clear();
  m.init_velocities.clear();
  for (const auto& [iv, nodes] : ivs) {
    if (iv.first == 0) {
      m.init_velocities.push_back(iv);
      continue;
    }
    for (const auto& r : ranges_of(nodes)) {
      InitialVelocity one = iv;
      one.first = r[0];
      one.last = r[1];
      one.increment = 1;
      m.init_velocities.push_back(one);
    }
  }
  m.control.num_init_velocity_cards = int(m.init_velocities.size());
  m.node_th_blocks = node_blocks;
  m.solid_th_blocks = solid_blocks;
  m.control.node_th_blocks = int(m.node_th_blocks.size());
  m.control.solid_th_blocks = int(m.solid_th_blocks.size());
}

}  // namespace test_support
