#include "core/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace convray {
namespace {

constexpr int kBins = 16;
// Past this depth splits are medians (always halving), so the traversal stack stays small.
constexpr int kSahDepth = 48;
// Leaves never exceed this, whatever the heuristic says (Node::count is 16 bits).
constexpr uint32_t kMaxLeafSize = 16;

double half_area(const Box3& box) {
  if (is_empty(box)) return 0.0;
  const Vec3 e = box.hi - box.lo;
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

Vec3 centroid(const Box3& box) { return 0.5 * (box.lo + box.hi); }

}  // namespace

Bvh::Bvh(std::span<const Box3> boxes, int max_leaf_size) {
  if (boxes.empty()) return;
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::vector<Vec3> centroids(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centroids[i] = centroid(boxes[i]);
  nodes_.reserve(2 * boxes.size());
  nodes_.emplace_back();
  build(boxes, centroids, 0, 0, uint32_t(boxes.size()),
        std::clamp(max_leaf_size, 1, int(kMaxLeafSize)), 0);
}

void Bvh::build(std::span<const Box3> boxes, std::vector<Vec3>& centroids, uint32_t node,
                uint32_t begin, uint32_t end, int max_leaf_size, int depth) {
  Box3 bounds;
  for (uint32_t i = begin; i < end; ++i) bounds = hull(bounds, boxes[order_[i]]);
  nodes_[node].box = bounds;
  const uint32_t count = end - begin;
  if (count <= uint32_t(max_leaf_size)) {
    nodes_[node].offset = begin;
    nodes_[node].count = uint16_t(count);
    return;
  }
  int axis = 0;
  const uint32_t middle =
      depth < kSahDepth ? split(boxes, centroids, bounds, begin, end, axis) : end;
  uint32_t cut = middle;
  if (cut == end) {
    // A leaf, unless too big: then the median along the widest centroid axis.
    if (count <= kMaxLeafSize && depth < kSahDepth) {
      nodes_[node].offset = begin;
      nodes_[node].count = uint16_t(count);
      return;
    }
    Box3 spread;
    for (uint32_t i = begin; i < end; ++i) spread.extend(centroids[order_[i]]);
    const Vec3 e = spread.hi - spread.lo;
    axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    cut = begin + count / 2;
    std::nth_element(
        order_.begin() + begin, order_.begin() + cut, order_.begin() + end,
        [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  }
  nodes_[node].axis = uint8_t(axis);
  const auto first = uint32_t(nodes_.size());
  nodes_.emplace_back();
  build(boxes, centroids, first, begin, cut, max_leaf_size, depth + 1);
  const auto second = uint32_t(nodes_.size());
  nodes_.emplace_back();
  nodes_[node].offset = second;
  nodes_[node].count = 0;
  build(boxes, centroids, second, cut, end, max_leaf_size, depth + 1);
}

// The binned SAH split of order_[begin, end): returns the partition point, or `end` when a
// leaf costs less than any split (or the centroids coincide).
uint32_t Bvh::split(std::span<const Box3> boxes, const std::vector<Vec3>& centroids,
                    const Box3& bounds, uint32_t begin, uint32_t end, int& axis) {
  Box3 spread;
  for (uint32_t i = begin; i < end; ++i) spread.extend(centroids[order_[i]]);
  const Vec3 extent = spread.hi - spread.lo;
  axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  if (!(extent[axis] > 0.0)) return end;
  // Bin the centroids along the axis.
  const double scale = kBins / extent[axis];
  auto bin_of = [&](uint32_t primitive) {
    const int b = int((centroids[primitive][axis] - spread.lo[axis]) * scale);
    return std::clamp(b, 0, kBins - 1);
  };
  Box3 bin_box[kBins];
  uint32_t bin_count[kBins] = {};
  for (uint32_t i = begin; i < end; ++i) {
    const int b = bin_of(order_[i]);
    bin_box[b] = hull(bin_box[b], boxes[order_[i]]);
    ++bin_count[b];
  }
  // Sweep from the right, then from the left, pricing each of the kBins - 1 cuts.
  double right_cost[kBins];
  Box3 running;
  uint32_t running_count = 0;
  for (int b = kBins - 1; b > 0; --b) {
    running = hull(running, bin_box[b]);
    running_count += bin_count[b];
    right_cost[b] = half_area(running) * running_count;
  }
  double best_cost = half_area(bounds) * double(end - begin);  // the leaf's cost
  int best_cut = -1;
  running = Box3{};
  running_count = 0;
  for (int b = 0; b + 1 < kBins; ++b) {
    running = hull(running, bin_box[b]);
    running_count += bin_count[b];
    const double cost = half_area(running) * running_count + right_cost[b + 1];
    if (running_count > 0 && running_count < end - begin && cost < best_cost) {
      best_cost = cost;
      best_cut = b;
    }
  }
  if (best_cut < 0) return end;
  const auto middle = std::partition(order_.begin() + begin, order_.begin() + end,
                                     [&](uint32_t p) { return bin_of(p) <= best_cut; });
  return uint32_t(middle - order_.begin());
}

}  // namespace convray
