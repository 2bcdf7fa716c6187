#pragma once
// The corners of elements whose nodes turn (shells, beams; internal to shell_processing.cpp and
// beam_processing.cpp): a kernel's N corners read their nodes' position, velocity and
// rotational velocity (zero for a node without rotations), and write their forces into
// State::cfx.. from corner0 and their moments into ShellState::cmx.. from moment0.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "impact3d/model/state.h"

namespace impact3d {

// Chunks of `lanes` consecutive elements of each group's order (the block kernels' blocks, the
// units a distributed run partitions), numbered group after group: how many there are, and the
// chunk of each element (order: the groups' elements, n elements in all).
template <class Groups>
int count_group_chunks(const Groups& groups, int lanes) {
  int n = 0;
  for (const auto& g : groups) n += (g.count + lanes - 1) / lanes;
  return n;
}

template <class Groups>
std::vector<int> chunk_of_group_elements(const Groups& groups, const std::vector<int>& order, int n, int lanes) {
  std::vector<int> chunk(std::size_t(n), -1);
  int c0 = 0;
  for (const auto& g : groups) {
    for (int q = 0; q < g.count; ++q) chunk[std::size_t(order[std::size_t(g.first + q)])] = c0 + q / lanes;
    c0 += (g.count + lanes - 1) / lanes;
  }
  return chunk;
}

// Each group in turn: f(g, ord, own) with its elements ord[0..g.count) (order from g.first) and
// its chunks' flags own[0..) (owns_chunk's from the group's first chunk; nullptr: every chunk).
template <class Groups, class F>
void for_each_group_with_chunks(const Groups& groups, const std::vector<int>& order, int lanes,
                                const std::vector<std::uint8_t>* owns_chunk, F&& f) {
  int c0 = 0;  // the group's first chunk
  for (const auto& g : groups) {
    const std::uint8_t* own = owns_chunk ? owns_chunk->data() + c0 : nullptr;
    c0 += (g.count + lanes - 1) / lanes;
    f(g, &order[std::size_t(g.first)], own);
  }
}

// Nodes conn[0..N) of an element into a kernel's corner arrays.
template <std::size_t N, class Conn>
inline void gather_rotational_corners(const State& s, const Conn& conn, double (&x)[N][3], double (&v)[N][3], double (&w)[N][3]) {
  const ShellState& sh = s.shells;
  for (std::size_t j = 0; j < N; ++j) {
    const std::size_t n = std::size_t(conn[j]);
    x[j][0] = s.x[n];
    x[j][1] = s.y[n];
    x[j][2] = s.z[n];
    v[j][0] = s.vx[n];
    v[j][1] = s.vy[n];
    v[j][2] = s.vz[n];
    const int r = sh.node_rot.empty() ? -1 : sh.node_rot[n];
    w[j][0] = r >= 0 ? sh.wx[std::size_t(r)] : 0.0;
    w[j][1] = r >= 0 ? sh.wy[std::size_t(r)] : 0.0;
    w[j][2] = r >= 0 ? sh.wz[std::size_t(r)] : 0.0;
  }
}

// A kernel's corner forces and moments into the state.
template <std::size_t N>
inline void store_rotational_corners(State& s, std::size_t corner0, std::size_t moment0, const double (&f)[N][3], const double (&m)[N][3]) {
  ShellState& sh = s.shells;
  for (std::size_t j = 0; j < N; ++j) {
    const std::size_t c = corner0 + j;
    s.cfx[c] = f[j][0];
    s.cfy[c] = f[j][1];
    s.cfz[c] = f[j][2];
    const std::size_t q = moment0 + j;
    sh.cmx[q] = m[j][0];
    sh.cmy[q] = m[j][1];
    sh.cmz[q] = m[j][2];
  }
}

// No forces and moments at the n corners (a deleted, rigid or bad element).
inline void zero_rotational_corners(State& s, std::size_t corner0, std::size_t moment0, std::size_t n) {
  ShellState& sh = s.shells;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t c = corner0 + j;
    s.cfx[c] = s.cfy[c] = s.cfz[c] = 0;
    const std::size_t q = moment0 + j;
    sh.cmx[q] = sh.cmy[q] = sh.cmz[q] = 0;
  }
}

// True if the n corners' forces and moments are all finite.
inline bool rotational_corners_finite(const State& s, std::size_t corner0, std::size_t moment0, std::size_t n) {
  const ShellState& sh = s.shells;
  double c = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t q = corner0 + j;
    const std::size_t r = moment0 + j;
    c += s.cfx[q] + s.cfy[q] + s.cfz[q] + sh.cmx[r] + sh.cmy[r] + sh.cmz[r];
  }
  return std::isfinite(c);
}

}  // namespace impact3d
