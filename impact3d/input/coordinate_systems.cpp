#include "impact3d/input/coordinate_systems.h"

#include <algorithm>
#include <cmath>

namespace impact3d {

namespace {
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double max_abs(const Vec3& a) { return std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}); }
}  // namespace

Vec3 CoordinateSystem::to_global_direction(const Vec3& l) const {
  Vec3 g{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) g[std::size_t(j)] += l[std::size_t(i)] * axis[std::size_t(i)][std::size_t(j)];
  return g;
}

Vec3 CoordinateSystem::to_global_point(const Vec3& l) const {
  Vec3 g = to_global_direction(l);
  for (int j = 0; j < 3; ++j) g[std::size_t(j)] += origin[std::size_t(j)];
  return g;
}

bool CoordinateSystem::axis_aligned(std::array<int, 3>& global_axis, std::array<int, 3>& sign) const {
  constexpr double tol = 1e-9;
  for (int i = 0; i < 3; ++i) {
    global_axis[std::size_t(i)] = -1;
    for (int j = 0; j < 3; ++j) {
      const double c = axis[std::size_t(i)][std::size_t(j)];
      if (std::fabs(std::fabs(c) - 1) < tol) {
        global_axis[std::size_t(i)] = j;
        sign[std::size_t(i)] = c > 0 ? 1 : -1;
      } else if (std::fabs(c) > tol) {
        return false;
      }
    }
    if (global_axis[std::size_t(i)] < 0) return false;
  }
  return true;
}

bool coordinate_system_from_vectors(const Vec3& x, const Vec3& xy, CoordinateSystem& cs) {
  const double lx = norm(x);
  if (!(lx > 0)) return false;
  Vec3 z = cross(x, xy);
  const double lz = norm(z);
  // xy along x (relative to the sizes given): no plane
  if (!(lz > 1e-10 * lx * std::max(norm(xy), max_abs(xy)))) return false;
  CoordinateSystem c;
  for (int j = 0; j < 3; ++j) {
    c.axis[0][std::size_t(j)] = x[std::size_t(j)] / lx;
    c.axis[2][std::size_t(j)] = z[std::size_t(j)] / lz;
  }
  c.axis[1] = cross(c.axis[2], c.axis[0]);
  cs = c;
  return true;
}

bool coordinate_system_from_points(const Vec3& o, const Vec3& px, const Vec3& pxy, CoordinateSystem& cs) {
  CoordinateSystem c;
  if (!coordinate_system_from_vectors(sub(px, o), sub(pxy, o), c)) return false;
  c.origin = o;
  cs = c;
  return true;
}

const CoordinateSystem* CoordinateTable::system(int id) const {
  static const CoordinateSystem global;
  if (id == 0) return &global;
  auto it = systems_.find(id);
  return it == systems_.end() ? nullptr : &it->second;
}

bool CoordinateTable::to_global_direction(int id, const Vec3& local, Vec3& global) const {
  const CoordinateSystem* cs = system(id);
  if (!cs) return false;
  global = cs->to_global_direction(local);
  return true;
}

bool CoordinateTable::vector(int id, Vec3& global_unit) const {
  auto it = vectors_.find(id);
  if (it == vectors_.end()) return false;
  global_unit = it->second;
  return true;
}

Vec3 AffineMap::apply(const Vec3& x) const {
  Vec3 y = t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) y[std::size_t(i)] += a[std::size_t(i)][std::size_t(j)] * x[std::size_t(j)];
  return y;
}

AffineMap AffineMap::then(const AffineMap& m) const {
  // m(this(x)) = m.a (a x + t) + m.t
  AffineMap r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += m.a[std::size_t(i)][std::size_t(k)] * a[std::size_t(k)][std::size_t(j)];
      r.a[std::size_t(i)][std::size_t(j)] = s;
    }
  r.t = m.apply(t);
  return r;
}

AffineMap AffineMap::translation(const Vec3& d) {
  AffineMap m;
  m.t = d;
  return m;
}

AffineMap AffineMap::scaling(const Vec3& s) {
  AffineMap m;
  for (int i = 0; i < 3; ++i) m.a[std::size_t(i)][std::size_t(i)] = s[std::size_t(i)];
  return m;
}

AffineMap AffineMap::rotation(const Vec3& n, const Vec3& p, double angle_deg) {
  const double ln = norm(n);
  const Vec3 u = {n[0] / ln, n[1] / ln, n[2] / ln};
  const double th = angle_deg * std::acos(-1.0) / 180.0;
  const double c = std::cos(th), s = std::sin(th), C = 1 - c;
  AffineMap r;  // Rodrigues: R = c I + s [u]x + C u u^T
  r.a = {{{c + u[0] * u[0] * C, u[0] * u[1] * C - u[2] * s, u[0] * u[2] * C + u[1] * s},
          {u[1] * u[0] * C + u[2] * s, c + u[1] * u[1] * C, u[1] * u[2] * C - u[0] * s},
          {u[2] * u[0] * C - u[1] * s, u[2] * u[1] * C + u[0] * s, c + u[2] * u[2] * C}}};
  // about p: x -> R (x - p) + p
  const Vec3 rp = r.apply(p);
  r.t = sub(p, rp);
  return r;
}

}  // namespace impact3d
