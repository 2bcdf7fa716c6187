#include "impact3d/contact/sliding_interface.h"

namespace impact3d {

// Placeholder until the contact engine lands (issue 5): run.cpp refuses decks with sliding
// interfaces, so apply() is never reached with interfaces present.
struct SlidingInterfaces::Impl {
  int count = 0;
  std::vector<std::array<double, 3>> forces;
};

SlidingInterfaces::SlidingInterfaces() : impl_(std::make_unique<Impl>()) {}
SlidingInterfaces::~SlidingInterfaces() = default;
SlidingInterfaces::SlidingInterfaces(SlidingInterfaces&&) noexcept = default;
SlidingInterfaces& SlidingInterfaces::operator=(SlidingInterfaces&&) noexcept = default;

void SlidingInterfaces::initialize(const Model& m, const State&) {
  impl_->count = int(m.interfaces.size());
}

void SlidingInterfaces::apply(const Model&, State&, double) {}

const std::vector<std::array<double, 3>>& SlidingInterfaces::interface_forces() const {
  return impl_->forces;
}

bool SlidingInterfaces::empty() const { return impl_->count == 0; }

}  // namespace impact3d
