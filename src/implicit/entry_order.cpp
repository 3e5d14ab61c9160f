#include "implicit/entry_order.hpp"

#include "util/bucket_sort.hpp"

namespace convray::implicit {
namespace {

// A function object, not a function: passed by pointer, each comparison was a call (2 % of
// the render at R = 5).
// Equal entries (triangles sharing the corner whose ball they enter by) in primitive order:
// the order, and so every sum over the cluster, does not depend on the order the line query
// found them in (Embree's walk or a fan's list: accel/line_fans.hpp).
constexpr auto earlier = [](const accel::SupportInterval& a, const accel::SupportInterval& b) {
  return a.enter < b.enter || (a.enter == b.enter && a.primitive < b.primitive);
};

}  // namespace

// The entries of a ray spread along it: a bucket sort (util/bucket_sort.hpp) costs O(n).
void sort_by_entry(std::span<accel::SupportInterval> supports) {
  bucket_sort(
      supports, [](const accel::SupportInterval& s) { return s.enter; }, earlier);
}

}  // namespace convray::implicit
