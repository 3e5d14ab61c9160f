#pragma once
// The solids a ray is inside, innermost last, each with its index of refraction, so that a
// ray leaving a glass inside water goes back to water's ior, not to air's. A ray entering a
// surface pushes it; leaving pops it (wherever it is in the stack: overlapping solids need not
// nest), or pops the innermost solid when that surface is not on the stack (the faces of a CSG
// solid carry surface records of their own: a ray may enter by one, leave by another).
// Outside everything the ior is 1. Small and fixed-size: a ray is copied at every bounce, and
// nesting deeper than kMaxDepth forgets the outermost solids.
#include <array>
#include <cstddef>

#include "geometry/shape.hpp"

namespace convray::render {

class MediumStack {
 public:
  static constexpr size_t kMaxDepth = 8;

  double ior() const { return size_ == 0 ? 1.0 : entries_[size_ - 1].ior; }
  size_t depth() const { return size_; }
  // The innermost solid's surface (its interior), or null outside everything.
  const geometry::SurfaceInfo* innermost() const {
    return size_ == 0 ? nullptr : entries_[size_ - 1].surface;
  }

  // The stack after entering `surface`'s solid.
  MediumStack entered(const geometry::SurfaceInfo* surface, double ior) const {
    MediumStack next = *this;
    if (next.size_ == kMaxDepth) next.drop(0);
    next.entries_[next.size_++] = {surface, ior};
    return next;
  }

  // The stack after leaving `surface`'s solid.
  MediumStack left(const geometry::SurfaceInfo* surface) const {
    MediumStack next = *this;
    if (next.size_ == 0) return next;
    for (size_t k = next.size_; k-- > 0;) {
      if (next.entries_[k].surface == surface) {
        next.drop(k);
        return next;
      }
    }
    next.drop(next.size_ - 1);
    return next;
  }

 private:
  struct Entry {
    const geometry::SurfaceInfo* surface = nullptr;
    double ior = 1.0;
  };

  void drop(size_t k) {
    for (size_t m = k + 1; m < size_; ++m) entries_[m - 1] = entries_[m];
    --size_;
  }

  std::array<Entry, kMaxDepth> entries_{};
  size_t size_ = 0;
};

}  // namespace convray::render
