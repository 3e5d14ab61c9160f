#include "implicit/box_bvh.hpp"

#include <algorithm>
#include <numeric>

#include "core/box.hpp"

namespace convray::implicit {

namespace {

constexpr uint32_t kLeafSize = 4;
constexpr int kMaxDepth = 64;

bool holds(const Box3& box, const Vec3& p) {
  return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y &&
         p.z >= box.lo.z && p.z <= box.hi.z;
}

}  // namespace

BoxBvh::BoxBvh(std::vector<Box3> boxes) : boxes_(std::move(boxes)) {
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (boxes_.empty()) return;
  nodes_.reserve(2 * boxes_.size() / kLeafSize + 2);
  nodes_.push_back({});
  build(0, 0, uint32_t(boxes_.size()));
}

size_t BoxBvh::memory_bytes() const {
  return boxes_.capacity() * sizeof(Box3) + order_.capacity() * sizeof(uint32_t) +
         nodes_.capacity() * sizeof(Node);
}

// Fills node `node` for order_[begin, end); the children of an inner node are allocated as a
// pair, so it only stores where the left one is.
void BoxBvh::build(uint32_t node, uint32_t begin, uint32_t end) {
  Box3 box, centers;
  for (uint32_t i = begin; i < end; ++i) {
    const Box3& b = boxes_[order_[i]];
    box.extend(b.lo);
    box.extend(b.hi);
    centers.extend(0.5 * (b.lo + b.hi));
  }
  nodes_[node].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  const Vec3 extent = centers.hi - centers.lo;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) {
                     return boxes_[a].lo[axis] + boxes_[a].hi[axis] <
                            boxes_[b].lo[axis] + boxes_[b].hi[axis];
                   });
  const uint32_t left = uint32_t(nodes_.size());
  nodes_[node].first = left;
  nodes_[node].count = 0;
  nodes_.push_back({});
  nodes_.push_back({});
  build(left, begin, middle);
  build(left + 1, middle, end);
}

void BoxBvh::contain(const Vec3& p, std::vector<uint32_t>& out) const {
  if (nodes_.empty()) return;
  uint32_t stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!holds(node.box, p)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (holds(boxes_[order_[i]], p)) out.push_back(order_[i]);
      }
    } else {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }
}

void BoxBvh::crossed(const Ray& ray, double tmin, double tmax, std::vector<Span>& out) const {
  if (nodes_.empty()) return;
  uint32_t stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    double t0 = tmin, t1 = tmax;
    if (!clip_to_box(ray, node.box, t0, t1)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        double b0 = tmin, b1 = tmax;
        if (clip_to_box(ray, boxes_[order_[i]], b0, b1)) out.push_back({order_[i], b0, b1});
      }
    } else {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }
}

}  // namespace convray::implicit
