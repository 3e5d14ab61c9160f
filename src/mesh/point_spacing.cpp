#include "mesh/point_spacing.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace convray::mesh {
namespace {

constexpr size_t kLeafSize = 8;

// A static k-d tree over the points, stored implicitly: the range [lo, hi) splits at its
// middle element, along the axis of the range's largest extent. Robust whatever the cloud's
// shape (a surface, a curve, clusters far apart), O(n log n) to build.
class KdTree {
 public:
  explicit KdTree(std::vector<Vec3> points) : points_(std::move(points)), axis_(points_.size(), 0) {
    build(0, points_.size());
  }

  // Distance from q to the nearest point at another position; infinity if there is none.
  double nearest_other(const Vec3& q) const {
    double best2 = std::numeric_limits<double>::infinity();
    search(q, 0, points_.size(), best2);
    return std::sqrt(best2);
  }

  const std::vector<Vec3>& points() const { return points_; }

 private:
  void build(size_t lo, size_t hi) {
    if (hi - lo <= kLeafSize) return;
    Box3 box;
    for (size_t i = lo; i < hi; ++i) box.extend(points_[i]);
    const Vec3 e = box.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const size_t mid = lo + (hi - lo) / 2;
    std::nth_element(points_.begin() + static_cast<std::ptrdiff_t>(lo), points_.begin() + static_cast<std::ptrdiff_t>(mid),
                     points_.begin() + static_cast<std::ptrdiff_t>(hi),
                     [axis](const Vec3& a, const Vec3& b) { return a[axis] < b[axis]; });
    axis_[mid] = static_cast<uint8_t>(axis);
    build(lo, mid);
    build(mid + 1, hi);
  }

  void consider(const Vec3& q, const Vec3& p, double& best2) const {
    const Vec3 d = p - q;
    const double d2 = glm::dot(d, d);
    if (d2 > 0.0 && d2 < best2) best2 = d2;
  }

  void search(const Vec3& q, size_t lo, size_t hi, double& best2) const {
    if (hi - lo <= kLeafSize) {
      for (size_t i = lo; i < hi; ++i) consider(q, points_[i], best2);
      return;
    }
    const size_t mid = lo + (hi - lo) / 2;
    const int axis = axis_[mid];
    const double gap = q[axis] - points_[mid][axis];
    consider(q, points_[mid], best2);
    if (gap < 0.0) {
      search(q, lo, mid, best2);
      if (gap * gap < best2) search(q, mid + 1, hi, best2);
    } else {
      search(q, mid + 1, hi, best2);
      if (gap * gap < best2) search(q, lo, mid, best2);
    }
  }

  std::vector<Vec3> points_;
  std::vector<uint8_t> axis_;  // the split axis of the range whose middle element this is
};

}  // namespace

double mean_point_spacing(const std::vector<Vec3>& points) {
  if (points.size() < 2) return 0.0;
  const KdTree tree(points);
  struct Sum {
    double total = 0.0;
    size_t count = 0;
  };
  const std::vector<Vec3>& p = tree.points();
  const Sum sum = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, p.size()), Sum{},
      [&](const tbb::blocked_range<size_t>& range, Sum s) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          const double d = tree.nearest_other(p[i]);
          if (std::isfinite(d)) s.total += d, ++s.count;
        }
        return s;
      },
      [](Sum a, const Sum& b) {
        a.total += b.total;
        a.count += b.count;
        return a;
      });
  return sum.count ? sum.total / static_cast<double>(sum.count) : 0.0;
}

}  // namespace convray::mesh
