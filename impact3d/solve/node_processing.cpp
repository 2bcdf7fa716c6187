#include "impact3d/solve/node_processing.h"

#include <algorithm>
#include <stdexcept>

namespace impact3d {

namespace {

constexpr int kNodeChunk = 2048;           // nodes per chunk (a thread's unit of work)
constexpr int kMinChunksForThreads = 8;    // below this the pass runs on one thread

// Walls applied inside the pass: only when it also moves the nodes.
int fused_wall_count(const NodePass& p) {
  return p.update_positions && p.walls ? int(p.walls->size()) : 0;
}

int num_node_chunks(const State& s) { return (s.nn + kNodeChunk - 1) / kNodeChunk; }

double kinetic_energy_of_node(const State& s, std::size_t k) {
  return 0.5 * s.mass[k] * (s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k] + s.vz[k] * s.vz[k]);
}

void sum_chunk_kinetic_energies(State& s) {
  double ke = 0;
  for (double c : s.chunk_kinetic) ke += c;
  s.kinetic = ke;
}

// One node of the pass (update_velocities_for_nodes): its corner forces summed in corner-list
// order, acceleration, velocity and, with p.update_positions, the fused walls (their books
// added to wall_books, 4 per wall; acted[w] says whether wall w touched the node, when given)
// and the position.  Returns the node's kinetic energy (0 without update_positions).
template <bool kRecordWalls>
inline double advance_node(State& s, const NodePass& p, int i, int nw, double* wall_books, std::uint8_t* acted) {
  const std::size_t k = std::size_t(i);
  const int* cstart = s.corner_start.data();
  const int* clist = s.corner_list.data();
  const double* cfx = s.cfx.data();
  const double* cfy = s.cfy.data();
  const double* cfz = s.cfz.data();
  double sx = 0, sy = 0, sz = 0;
  for (int c = cstart[k]; c < cstart[k + 1]; ++c) {
    const std::size_t cc = std::size_t(clist[c]);
    sx += cfx[cc];
    sy += cfy[cc];
    sz += cfz[cc];
  }
  const double fx = (p.has_fext ? s.fext_x[k] : 0.0) - sx;
  const double fy = (p.has_fext ? s.fext_y[k] : 0.0) - sy;
  const double fz = (p.has_fext ? s.fext_z[k] : 0.0) - sz;
  if (p.store_force) {
    s.fx[k] = fx;
    s.fy[k] = fy;
    s.fz[k] = fz;
  }
  const double inv_m = s.mass[k] > 0 ? 1.0 / s.mass[k] : 0.0;
  const uint8_t f = s.fix[k];
  const double ax = (f & 1) ? 0.0 : fx * inv_m;
  const double ay = (f & 2) ? 0.0 : fy * inv_m;
  const double az = (f & 4) ? 0.0 : fz * inv_m;
  s.ax[k] = ax;
  s.ay[k] = ay;
  s.az[k] = az;
  const double vx0 = s.vx[k], vy0 = s.vy[k], vz0 = s.vz[k];
  s.vx_old[k] = vx0;
  s.vy_old[k] = vy0;
  s.vz_old[k] = vz0;
  const double vx = vx0 + p.dt_n * ax, vy = vy0 + p.dt_n * ay, vz = vz0 + p.dt_n * az;
  s.vx[k] = vx;
  s.vy[k] = vy;
  s.vz[k] = vz;
  if (!p.update_positions) return 0.0;
  for (int w = 0; w < nw; ++w) {
    const FixedWall& fw = (*p.walls)[std::size_t(w)];
    const bool hit = apply_wall_to_node(s, i, fw.p, fw.n, 0.0, fw.friction, p.dt_next, &wall_books[4 * w],
                                        wall_books[4 * w + 3]);
    if constexpr (kRecordWalls) acted[w] = hit;
  }
  s.x[k] += p.dt_next * s.vx[k];
  s.y[k] += p.dt_next * s.vy[k];
  s.z[k] += p.dt_next * s.vz[k];
  return kinetic_energy_of_node(s, k);
}

// The walls' books, chunk by chunk in order (as apply_stonewalls_to_nodes books them).
void book_chunk_walls(State& s, const NodePass& p) {
  const int nc = num_node_chunks(s);
  const std::size_t nw = std::size_t(fused_wall_count(p));
  for (std::size_t w = 0; w < nw; ++w) {
    double imp[3] = {0, 0, 0}, dke = 0;
    for (int c = 0; c < nc; ++c) {
      const double* b = &s.chunk_walls[(std::size_t(c) * nw + w) * 4];
      for (int a = 0; a < 3; ++a) imp[a] += b[a];
      dke += b[3];
    }
    s.wall_work += dke;
    for (int a = 0; a < 3; ++a) s.wall_force[w][std::size_t(a)] = -imp[a] / p.dt_n;
  }
}

void update_velocities_for_chunk(State& s, const NodePass& p, int chunk) {
  const int i0 = chunk * kNodeChunk, i1 = std::min(s.nn, i0 + kNodeChunk);
  double ke = 0;
  const int nw = fused_wall_count(p);
  double wall_books[4 * 8] = {};  // per wall: impulse x y z, kinetic energy change
  for (int i = i0; i < i1; ++i) {
    const double ke_node = advance_node<false>(s, p, i, nw, wall_books, nullptr);
    if (p.update_positions) ke += ke_node;
  }
  if (p.update_positions) s.chunk_kinetic[std::size_t(chunk)] = ke;
  for (int m = 0; m < 4 * nw; ++m) s.chunk_walls[std::size_t(chunk) * 4 * std::size_t(nw) + std::size_t(m)] = wall_books[m];
}

void update_positions_for_chunk(State& s, double dt, int chunk) {
  const int i0 = chunk * kNodeChunk, i1 = std::min(s.nn, i0 + kNodeChunk);
  double ke = 0;
  for (int i = i0; i < i1; ++i) {
    const std::size_t k = std::size_t(i);
    s.x[k] += dt * s.vx[k];
    s.y[k] += dt * s.vy[k];
    s.z[k] += dt * s.vz[k];
    ke += kinetic_energy_of_node(s, k);
  }
  s.chunk_kinetic[std::size_t(chunk)] = ke;
}

}  // namespace

void update_velocities_for_nodes(State& s, const NodePass& p) {
  const int nc = num_node_chunks(s);
  const std::size_t nw = std::size_t(fused_wall_count(p));
  if (nw > kMaxFusedWalls) throw std::logic_error("update_velocities_for_nodes: too many fused walls");
  s.chunk_kinetic.resize(std::size_t(nc));  // sized once (no-op after the first cycle)
  s.chunk_walls.resize(std::size_t(nc) * 4 * nw);
#pragma omp parallel for schedule(dynamic, 1) if (nc >= kMinChunksForThreads)
  for (int c = 0; c < nc; ++c) update_velocities_for_chunk(s, p, c);
  if (p.update_positions) sum_chunk_kinetic_energies(s);
  book_chunk_walls(s, p);
}

// Walls in a distributed pass's records: the fused ones, or after a pass without
// update_positions the fixed walls apply_walls_to_listed_nodes applies.
int recorded_wall_count(const NodePass& p) { return p.walls ? int(p.walls->size()) : 0; }

int node_record_size(const NodePass& p) { return 1 + 5 * recorded_wall_count(p); }

void apply_walls_to_listed_nodes(State& s, const NodePass& p, const std::vector<int>& nodes, double* records,
                                 std::size_t stride) {
  const int nw = recorded_wall_count(p);
  if (p.update_positions) throw std::logic_error("apply_walls_to_listed_nodes: the pass applied its walls");
  if (std::size_t(nw) > kMaxFusedWalls) throw std::logic_error("apply_walls_to_listed_nodes: too many walls");
  const int n = int(nodes.size());
#pragma omp parallel for schedule(dynamic, kNodeChunk) if (n >= kMinChunksForThreads * kNodeChunk)
  for (int a = 0; a < n; ++a) {  // each node wall after wall, as apply_stonewalls_to_nodes
    double* r = records + stride * std::size_t(a);
    for (int w = 0; w < nw; ++w) {
      const FixedWall& fw = (*p.walls)[std::size_t(w)];
      double books[4] = {};
      r[1 + 5 * w] = apply_wall_to_node(s, nodes[std::size_t(a)], fw.p, fw.n, 0.0, fw.friction, p.dt_next, books,
                                        books[3]);
      for (int m = 0; m < 4; ++m) r[2 + 5 * w + m] = books[m];
    }
  }
}

void update_velocities_for_listed_nodes(State& s, const NodePass& p, const std::vector<int>& nodes, double* records,
                                        std::size_t stride) {
  const int nw = fused_wall_count(p);
  if (std::size_t(nw) > kMaxFusedWalls) throw std::logic_error("update_velocities_for_listed_nodes: too many fused walls");
  if (stride < std::size_t(node_record_size(p))) throw std::logic_error("update_velocities_for_listed_nodes: records too short");
  const int n = int(nodes.size());
#pragma omp parallel for schedule(dynamic, kNodeChunk) if (n >= kMinChunksForThreads * kNodeChunk)
  for (int a = 0; a < n; ++a) {
    double books[4 * 8] = {};
    std::uint8_t acted[8] = {};
    double* r = records + stride * std::size_t(a);
    r[0] = advance_node<true>(s, p, nodes[std::size_t(a)], nw, books, acted);
    for (int w = 0; w < nw; ++w) {
      r[1 + 5 * w] = acted[w];
      for (int m = 0; m < 4; ++m) r[2 + 5 * w + m] = books[4 * w + m];
    }
  }
}

void update_positions_for_listed_nodes(State& s, double dt_next, const std::vector<int>& nodes, double* records,
                                       std::size_t stride) {
  const int n = int(nodes.size());
#pragma omp parallel for schedule(dynamic, kNodeChunk) if (n >= kMinChunksForThreads * kNodeChunk)
  for (int a = 0; a < n; ++a) {  // as update_positions_for_chunk, node by node
    const std::size_t k = std::size_t(nodes[std::size_t(a)]);
    s.x[k] += dt_next * s.vx[k];
    s.y[k] += dt_next * s.vy[k];
    s.z[k] += dt_next * s.vz[k];
    records[stride * std::size_t(a)] = kinetic_energy_of_node(s, k);
  }
}

void book_node_records(State& s, const NodePass& p, const double* records, std::size_t stride) {
  const int nc = num_node_chunks(s);
  const int nw = fused_wall_count(p);
  s.chunk_kinetic.resize(std::size_t(nc));
  s.chunk_walls.resize(std::size_t(nc) * 4 * std::size_t(nw));
  for (int c = 0; c < nc; ++c) {  // each chunk's sums, node by node as update_velocities_for_chunk
    const int i0 = c * kNodeChunk, i1 = std::min(s.nn, i0 + kNodeChunk);
    double ke = 0, books[4 * 8] = {};
    for (int i = i0; i < i1; ++i) {
      const double* r = records + stride * std::size_t(i);
      ke += r[0];
      for (int w = 0; w < nw; ++w) {
        if (r[1 + 5 * w] == 0.0) continue;  // the wall did not touch the node: nothing added
        for (int a = 0; a < 3; ++a) books[4 * w + a] += r[2 + 5 * w + a];
        books[4 * w + 3] -= -r[5 + 5 * w];  // the node's own book is 0 - work: the same subtraction
      }
    }
    s.chunk_kinetic[std::size_t(c)] = ke;
    for (int m = 0; m < 4 * nw; ++m) s.chunk_walls[std::size_t(c) * 4 * std::size_t(nw) + std::size_t(m)] = books[m];
  }
  sum_chunk_kinetic_energies(s);
  book_chunk_walls(s, p);
  if (p.update_positions) return;
  // the walls of apply_walls_to_listed_nodes: each wall's sums over all nodes in node order
  // (as apply_stonewalls_to_nodes books them)
  for (int w = 0; w < recorded_wall_count(p); ++w) {
    double imp[3] = {0, 0, 0}, dke = 0;
    for (int i = 0; i < s.nn; ++i) {
      const double* r = records + stride * std::size_t(i);
      if (r[1 + 5 * w] == 0.0) continue;
      for (int a = 0; a < 3; ++a) imp[a] += r[2 + 5 * w + a];
      dke -= -r[5 + 5 * w];
    }
    s.wall_work += dke;
    for (int a = 0; a < 3; ++a) s.wall_force[std::size_t(w)][std::size_t(a)] = -imp[a] / p.dt_n;
  }
}

void update_positions_for_nodes(State& s, double dt_next) {
  const int nc = num_node_chunks(s);
  s.chunk_kinetic.resize(std::size_t(nc));
#pragma omp parallel for schedule(dynamic, 1) if (nc >= kMinChunksForThreads)
  for (int c = 0; c < nc; ++c) update_positions_for_chunk(s, dt_next, c);
  sum_chunk_kinetic_energies(s);
}

void calc_kinetic_energy_for_nodes(State& s) {
  const int nc = num_node_chunks(s);
  s.chunk_kinetic.resize(std::size_t(nc));
  for (int c = 0; c < nc; ++c) {
    const int i0 = c * kNodeChunk, i1 = std::min(s.nn, i0 + kNodeChunk);
    double ke = 0;
    for (int i = i0; i < i1; ++i) ke += kinetic_energy_of_node(s, std::size_t(i));
    s.chunk_kinetic[std::size_t(c)] = ke;
  }
  sum_chunk_kinetic_energies(s);
}

}  // namespace impact3d
