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

void update_velocities_for_chunk(State& s, const NodePass& p, int chunk) {
  const int i0 = chunk * kNodeChunk, i1 = std::min(s.nn, i0 + kNodeChunk);
  const int* cstart = s.corner_start.data();
  const int* clist = s.corner_list.data();
  const double* cfx = s.cfx.data();
  const double* cfy = s.cfy.data();
  const double* cfz = s.cfz.data();
  double ke = 0;
  const int nw = fused_wall_count(p);
  double wall_books[4 * 8] = {};  // per wall: impulse x y z, kinetic energy change
  for (int i = i0; i < i1; ++i) {
    const std::size_t k = std::size_t(i);
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
    if (p.update_positions) {
      for (int w = 0; w < nw; ++w) {
        const FixedWall& fw = (*p.walls)[std::size_t(w)];
        apply_wall_to_node(s, i, fw.p, fw.n, 0.0, fw.friction, p.dt_next, &wall_books[4 * w],
                           wall_books[4 * w + 3]);
      }
      s.x[k] += p.dt_next * s.vx[k];
      s.y[k] += p.dt_next * s.vy[k];
      s.z[k] += p.dt_next * s.vz[k];
      ke += kinetic_energy_of_node(s, k);
    }
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
  // the walls' books, chunk by chunk in order (as apply_stonewalls_to_nodes books them)
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
