#include "implicit/box_bvh.hpp"

#include "core/box.hpp"

namespace convray::implicit {

namespace {

std::vector<Box3> padded_boxes(const std::vector<Box3>& boxes) {
  std::vector<Box3> out;
  out.reserve(boxes.size());
  for (const Box3& box : boxes) out.push_back(padded(box));
  return out;
}

}  // namespace

BoxBvh::BoxBvh(std::vector<Box3> boxes)
    : boxes_(std::move(boxes)), bvh_(padded_boxes(boxes_), 4) {
  for (const Box3& box : boxes_) {
    bounds_.extend(box.lo);
    bounds_.extend(box.hi);
  }
}

size_t BoxBvh::memory_bytes() const {
  return boxes_.capacity() * sizeof(Box3) + bvh_.memory_bytes();
}

void BoxBvh::contain(const Vec3& p, std::vector<uint32_t>& out) const {
  bvh_.any_at(p, [&](uint32_t id) {
    if (contains(boxes_[id], p)) out.push_back(id);
    return false;  // every box, not just one
  });
}

void BoxBvh::crossed(const Ray& ray, double tmin, double tmax, std::vector<Span>& out) const {
  double reach = tmax;  // never narrowed: every box along [tmin, tmax]
  bvh_.traverse(ray, tmin, reach, [&](uint32_t id, double&) {
    double t0 = tmin, t1 = tmax;
    if (clip_to_box(ray, boxes_[id], t0, t1)) out.push_back({id, t0, t1});
  });
}

}  // namespace convray::implicit
