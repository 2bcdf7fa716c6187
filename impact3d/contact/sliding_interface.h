#pragma once
// Sliding interfaces (DYNA3D type 3): penalty contact between master and slave surfaces of
// hexahedron faces, the seed's method (shared/spec/physics.md section 5).

#include <array>
#include <memory>
#include <vector>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

class SlidingInterfaces {
 public:
  SlidingInterfaces();
  ~SlidingInterfaces();
  SlidingInterfaces(SlidingInterfaces&&) noexcept;
  SlidingInterfaces& operator=(SlidingInterfaces&&) noexcept;

  // Builds segments, node lists and search structures from the model (after initialize_state).
  void initialize(const Model& m, const State& s);
  // Adds the penalty forces at the current positions x^n to s.fext_x/y/z (which the engine
  // zeroes before) and books the contact energy in s.contact.  dt is the step about to be
  // taken (dt^{n+1/2}).  The result must not depend on the thread count.
  void apply(const Model& m, State& s, double dt);
  bool empty() const;
  // Resultant force on the master side of each interface at the last apply() (for rcforc).
  const std::vector<std::array<double, 3>>& interface_forces() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace impact3d
