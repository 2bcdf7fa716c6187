#pragma once
// Local coordinate systems, vectors, boxes and transformations of a keyword deck
// (*DEFINE_COORDINATE_SYSTEM, _NODES, _VECTOR, *DEFINE_VECTOR, *DEFINE_BOX,
// *DEFINE_TRANSFORMATION): the geometry only, no deck reading.  The keyword reader builds one
// CoordinateTable per deck and turns every CID / ICID / VID field through it; code that reads a
// keyword with such a field (loads, prescribed motions) uses the same table.

#include <array>
#include <map>
#include <string>

namespace impact3d {

using Vec3 = std::array<double, 3>;

// A right-handed orthonormal system: origin and the global components of its unit axes.
struct CoordinateSystem {
  Vec3 origin{};
  std::array<Vec3, 3> axis{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // local x, y, z in global

  // Global components of a direction given in local components.
  Vec3 to_global_direction(const Vec3& local) const;
  // Global coordinates of a point given in local coordinates.
  Vec3 to_global_point(const Vec3& local) const;
  // True if every local axis is a global axis up to sign (within 1e-9 of a unit component):
  // global_axis[i] is the global axis (0 x, 1 y, 2 z) of local axis i, sign[i] its sign.
  bool axis_aligned(std::array<int, 3>& global_axis, std::array<int, 3>& sign) const;
};

// Builds the system of *DEFINE_COORDINATE_SYSTEM (and _NODES): origin o, a point px on the
// local x axis, a point pxy in the local x-y plane (local y on its side).  Returns false (cs
// untouched) when the points are collinear or coincide.
bool coordinate_system_from_points(const Vec3& o, const Vec3& px, const Vec3& pxy, CoordinateSystem& cs);
// Builds the system of *DEFINE_COORDINATE_SYSTEM_VECTOR: local x along x, a vector xy in the
// local x-y plane; origin at the global origin.  False when x is zero or xy is along x.
bool coordinate_system_from_vectors(const Vec3& x, const Vec3& xy, CoordinateSystem& cs);

// The systems and vectors of a deck, by id.  Id 0 is the global system.
class CoordinateTable {
 public:
  void add_system(int id, const CoordinateSystem& cs) { systems_[id] = cs; }
  void add_vector(int id, const Vec3& global_unit) { vectors_[id] = global_unit; }
  bool has_system(int id) const { return id == 0 || systems_.count(id) > 0; }
  bool has_vector(int id) const { return vectors_.count(id) > 0; }
  // The system of an id (0: the global one), or nullptr if the deck defines none.
  const CoordinateSystem* system(int id) const;
  // A direction in the system's components turned into global ones; false if id is undefined.
  bool to_global_direction(int id, const Vec3& local, Vec3& global) const;
  // The global unit vector of a *DEFINE_VECTOR; false if undefined.
  bool vector(int id, Vec3& global_unit) const;

 private:
  std::map<int, CoordinateSystem> systems_;
  std::map<int, Vec3> vectors_;
};

// *DEFINE_BOX: an axis-aligned box, bounds included.
struct Box {
  Vec3 lo{}, hi{};
  bool contains(double x, double y, double z) const {
    return x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && z >= lo[2] && z <= hi[2];
  }
};

// An affine map x -> A x + t (*DEFINE_TRANSFORMATION, *INCLUDE_TRANSFORM).
struct AffineMap {
  std::array<Vec3, 3> a{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // rows
  Vec3 t{};

  Vec3 apply(const Vec3& x) const;
  // this map followed by m (the result applies this first, then m)
  AffineMap then(const AffineMap& m) const;
  static AffineMap translation(const Vec3& d);
  static AffineMap scaling(const Vec3& s);
  // Rotation by angle_deg (right hand) about the axis through point p along direction n
  // (need not be unit; must not be zero).
  static AffineMap rotation(const Vec3& n, const Vec3& p, double angle_deg);
};

}  // namespace impact3d
