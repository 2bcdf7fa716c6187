#include "impact3d/contact/stonewall.h"

#include <algorithm>
#include <cmath>

namespace impact3d {

namespace {
// The node cannot move along n: each axis n has a component on is fixed (boundary code).
inline bool held_along(const State& s, std::size_t k, const double n[3]) {
  const double big = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
  for (int a = 0; a < 3; ++a)
    if (std::fabs(n[a]) > 1e-12 * big && !(s.fix[k] & (1u << a))) return false;
  return true;
}
}  // namespace

std::vector<FixedWall> fixed_walls_for_node_pass(const Model& m) {
  std::vector<FixedWall> out;
  for (const StoneWall& sw : m.walls) {
    if (sw.mass > 0 || !sw.nodes.empty() || sw.cylinder()) return {};
    FixedWall w;
    double n[3] = {sw.head[0] - sw.tail[0], sw.head[1] - sw.tail[1], sw.head[2] - sw.tail[2]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int a = 0; a < 3; ++a) {
      w.n[a] = n[a] / len;
      w.p[a] = sw.tail[std::size_t(a)];
    }
    w.friction = sw.friction;
    out.push_back(w);
  }
  return out;
}

// A fixed cylinder (StoneWall::cylinder): each node against the plane tangent to the cylinder at
// the point nearest to it (normal: radial, outward), so the node ends on the surface; nodes on
// the axis, and past an end of a finite cylinder, are left.
static void apply_cylinder_to_nodes(const StoneWall& sw, State& s, double dt, double imp[3], double& dke) {
  double a[3] = {sw.head[0] - sw.tail[0], sw.head[1] - sw.tail[1], sw.head[2] - sw.tail[2]};
  const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  for (double& c : a) c /= len;
  auto one = [&](int i) {
    const std::size_t k = std::size_t(i);
    const double r[3] = {s.x[k] - sw.tail[0], s.y[k] - sw.tail[1], s.z[k] - sw.tail[2]};
    const double axial = r[0] * a[0] + r[1] * a[1] + r[2] * a[2];
    if (sw.length > 0 && (axial < 0 || axial > sw.length)) return;
    double n[3] = {r[0] - axial * a[0], r[1] - axial * a[1], r[2] - axial * a[2]};
    const double rho = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(rho > 0)) return;
    for (double& c : n) c /= rho;
    const double p[3] = {sw.tail[0] + axial * a[0] + sw.radius * n[0], sw.tail[1] + axial * a[1] + sw.radius * n[1],
                         sw.tail[2] + axial * a[2] + sw.radius * n[2]};
    apply_wall_to_node(s, i, p, n, 0.0, sw.friction, dt, imp, dke);
  };
  if (sw.nodes.empty())
    for (int i = 0; i < s.nn; ++i) one(i);
  else
    for (int i : sw.nodes) one(i);
}

void apply_stonewalls_to_nodes(const Model& m, State& s, double dt, double dt_n) {
  for (std::size_t w = 0; w < m.walls.size(); ++w) {
    const StoneWall& sw = m.walls[w];
    if (sw.cylinder()) {
      double imp[3] = {0, 0, 0}, dke = 0;
      apply_cylinder_to_nodes(sw, s, dt, imp, dke);
      s.wall_work += dke;  // the energy the fixed cylinder takes out
      for (int a = 0; a < 3; ++a) s.wall_force[w][std::size_t(a)] = -imp[a] / dt_n;
      continue;
    }
    double n[3] = {sw.head[0] - sw.tail[0], sw.head[1] - sw.tail[1], sw.head[2] - sw.tail[2]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n) c /= len;
    double p[3] = {sw.tail[0], sw.tail[1], sw.tail[2]};  // a point of the wall at time n
    double imp[3] = {0, 0, 0};
    double dke = 0;
    double vw = 0;
    bool stopped = false;  // a moving wall stopped by a held node
    // the wall's nodes in order (all nodes, or the listed ones): serial, so the sums are the
    // same for any thread count
    auto visit = [&](auto&& f) {
      if (sw.nodes.empty()) for (int i = 0; i < s.nn; ++i) f(i);
      else for (int i : sw.nodes) f(i);
    };
    if (sw.mass > 0) {
      // Moving wall: the wall and the nodes it stops reach one normal velocity V (each node
      // V - gap/dt, so that it ends on the wall), with momentum kept:
      // M V + sum m (V - g) = M V_old + sum m vn over the nodes that would cross.  Which nodes
      // cross depends on V: iterate to a fixed set (serial, node order: deterministic).
      const double V0 = s.wall_vel[w];
      for (int a = 0; a < 3; ++a) p[a] += s.wall_disp[w] * n[a];
      double V = V0;
      // Nodes held along the normal by their boundary codes (and rigid-body nodes, which walls
      // skip) are supports, not mass: the wall stops short of crossing a held node (the support
      // takes the rest of its momentum).
      double v_stop = INFINITY;
      visit([&](int i) {
        const std::size_t k = std::size_t(i);
        if (s.rigid_of_node[k] >= 0 || !held_along(s, k, n)) return;
        const double d = (s.x[k] - p[0]) * n[0] + (s.y[k] - p[1]) * n[1] + (s.z[k] - p[2]) * n[2];
        v_stop = std::min(v_stop, std::max(d, 0.0) / dt);
      });
      for (int it = 0; it < 100; ++it) {
        double msum = 0, psum = 0;
        visit([&](int i) {
          const std::size_t k = std::size_t(i);
          if (s.mass[k] <= 0 || s.rigid_of_node[k] >= 0 || held_along(s, k, n)) return;
          const double d = (s.x[k] - p[0]) * n[0] + (s.y[k] - p[1]) * n[1] + (s.z[k] - p[2]) * n[2];
          const double vn = s.vx[k] * n[0] + s.vy[k] * n[1] + s.vz[k] * n[2];
          const double g = std::max(d, 0.0) / dt;
          if (vn < V - g) {
            msum += s.mass[k];
            psum += s.mass[k] * (vn + g);
          }
        });
        const double Vn = (sw.mass * V0 + psum) / (sw.mass + msum);
        if (Vn == V) break;
        V = Vn;
      }
      stopped = V > v_stop;
      vw = stopped ? v_stop : V;
    }
    // (a moving wall leaves its held nodes to their supports)
    const bool moving = sw.mass > 0;
    visit([&](int i) {
      if (moving && held_along(s, std::size_t(i), n)) return;
      apply_wall_to_node(s, i, p, n, vw, sw.friction, dt, imp, dke);
    });
    if (moving) {
      // the wall takes the opposite normal impulse; stopped by a held node, it moves at vw
      const double in = imp[0] * n[0] + imp[1] * n[1] + imp[2] * n[2];
      s.wall_vel[w] = stopped ? vw : s.wall_vel[w] - in / sw.mass;
      // a moving wall is an external body: its work on the nodes is external work
      s.external_work -= dke;
    } else {
      s.wall_work += dke;  // the energy a fixed wall takes out
    }
    // force on the wall = - impulse given to the nodes / dt
    for (int a = 0; a < 3; ++a) s.wall_force[w][std::size_t(a)] = -imp[a] / dt_n;
  }
}

void update_moving_walls(const Model& m, State& s, double dt) {
  for (std::size_t w = 0; w < m.walls.size(); ++w)
    if (m.walls[w].mass > 0) s.wall_disp[w] += dt * s.wall_vel[w];
}

}  // namespace impact3d
