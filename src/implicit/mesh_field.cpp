#include "implicit/mesh_field.hpp"

#include <algorithm>
#include <cmath>

namespace convray::implicit {

namespace {
std::vector<Box3> support_boxes(std::span<const field::Triangle> triangles, double radius) {
  std::vector<Box3> boxes(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    Box3& b = boxes[i];
    b.extend(triangles[i].a);
    b.extend(triangles[i].b);
    b.extend(triangles[i].c);
    b.lo -= Vec3(radius);
    b.hi += Vec3(radius);
  }
  return boxes;
}
}  // namespace

// Exactly repeated triangles are kept once, weighted by how often they occur (issue 17).
MeshField::Distinct MeshField::distinct(std::vector<field::Triangle> triangles) {
  std::optional<DistinctTriangles> merged = merge_repeated(triangles);
  if (!merged) {
    const size_t n = triangles.size();
    return {std::move(triangles), std::vector<double>(n, 1.0), n};
  }
  std::vector<field::Triangle> distinct;
  distinct.reserve(merged->size());
  for (const uint32_t i : merged->first) distinct.push_back(triangles[i]);
  return {std::move(distinct),
          std::vector<double>(merged->multiplicity.begin(), merged->multiplicity.end()),
          triangles.size()};
}

MeshField::MeshField(std::vector<field::Triangle> triangles, double radius, double strength)
    : MeshField(distinct(std::move(triangles)), radius, strength) {}

MeshField::MeshField(Distinct distinct, double radius, double strength)
    : triangles_(std::move(distinct.triangles)),
      weights_(std::move(distinct.weights)),
      total_(distinct.total),
      batch_(triangles_, weights_),
      grid_(support_boxes(triangles_, radius), radius),
      radius_(radius),
      strength_(strength) {
  for (const field::Triangle& t : triangles_) {
    // Centre of the bounding box: not the smallest sphere, but a tight enough bound.
    const Vec3 c = 0.5 * (glm::min(glm::min(t.a, t.b), t.c) + glm::max(glm::max(t.a, t.b), t.c));
    const double bound = std::sqrt(std::max({glm::dot(t.a - c, t.a - c), glm::dot(t.b - c, t.b - c),
                                             glm::dot(t.c - c, t.c - c)}));
    const double reach = bound + radius;
    sphere_x_.push_back(c.x), sphere_y_.push_back(c.y), sphere_z_.push_back(c.z);
    sphere_reach2_.push_back(reach * reach * (1.0 + 1e-12));  // never cull by a rounding
  }
}

void MeshField::contributors(const Vec3& p, std::vector<uint32_t>& out) const {
  out.clear();
  for (const uint32_t i : grid_.candidates(p)) {
    const double dx = p.x - sphere_x_[i], dy = p.y - sphere_y_[i], dz = p.z - sphere_z_[i];
    if (dx * dx + dy * dy + dz * dz <= sphere_reach2_[i]) out.push_back(i);
  }
}

namespace {
// One scratch list per thread: evaluation is called from TBB workers, millions of times.
std::vector<uint32_t>& scratch() {
  thread_local std::vector<uint32_t> list;
  return list;
}
}  // namespace

double MeshField::value(const Vec3& p) const {
  std::vector<uint32_t>& list = scratch();
  contributors(p, list);
  return strength_ * batch_.value(p, radius_, list);
}

field::FieldSample MeshField::field(const Vec3& p) const {
  std::vector<uint32_t>& list = scratch();
  contributors(p, list);
  return batch_.field(p, radius_, list) * strength_;
}

field::FieldSample MeshField::field_exact(const Vec3& p) const {
  field::FieldSample sum;
  for (uint32_t i : grid_.candidates(p)) {
    sum += field::triangle_field(p, triangles_[i], radius_) * weights_[i];
  }
  return sum * strength_;
}

}  // namespace convray::implicit
