// The node -> corner map (State::corner_start / corner_list, CSR): each node's element corners,
// whose forces the node pass sums in this fixed order (the same sums for any thread count).
#pragma once

#include <cstddef>
#include <vector>

namespace impact3d {

// Appends the corners of ne elements of k nodes each to the map of nn nodes: corner j of element
// e is number base + k e + j (node_of(e, j) its node), placed at each node after the corners it
// already has, in element order.
template <class NodeOf>
void append_corners(std::vector<int>& start, std::vector<int>& list, int nn, int ne, int k, std::size_t base,
                    NodeOf node_of) {
  const std::vector<int> old_start = start, old_list = list;
  std::vector<int> count(std::size_t(nn), 0);
  for (int e = 0; e < ne; ++e)
    for (int j = 0; j < k; ++j) ++count[std::size_t(node_of(e, j))];
  start.assign(std::size_t(nn) + 1, 0);
  for (int i = 0; i < nn; ++i)
    start[std::size_t(i) + 1] =
        start[std::size_t(i)] + (old_start[std::size_t(i) + 1] - old_start[std::size_t(i)]) + count[std::size_t(i)];
  list.assign(std::size_t(start[std::size_t(nn)]), 0);
  std::vector<int> fill(static_cast<std::size_t>(nn));
  for (int i = 0; i < nn; ++i) {
    int f = start[std::size_t(i)];
    for (int c = old_start[std::size_t(i)]; c < old_start[std::size_t(i) + 1]; ++c) list[std::size_t(f++)] = old_list[std::size_t(c)];
    fill[std::size_t(i)] = f;
  }
  for (int e = 0; e < ne; ++e)
    for (int j = 0; j < k; ++j)
      list[std::size_t(fill[std::size_t(node_of(e, j))]++)] = int(base + std::size_t(k) * std::size_t(e) + std::size_t(j));
}

}  // namespace impact3d
