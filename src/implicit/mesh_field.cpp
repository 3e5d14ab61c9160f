#include "implicit/mesh_field.hpp"

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

MeshField::MeshField(std::vector<field::Triangle> triangles, double radius, double strength)
    : triangles_(std::move(triangles)),
      batch_(triangles_),
      grid_(support_boxes(triangles_, radius), radius),
      radius_(radius),
      strength_(strength) {}

double MeshField::value(const Vec3& p) const {
  return strength_ * batch_.value(p, radius_, grid_.candidates(p));
}

field::FieldSample MeshField::field(const Vec3& p) const {
  return batch_.field(p, radius_, grid_.candidates(p)) * strength_;
}

field::FieldSample MeshField::field_exact(const Vec3& p) const {
  field::FieldSample sum;
  for (uint32_t i : grid_.candidates(p)) sum += field::triangle_field(p, triangles_[i], radius_);
  return sum * strength_;
}

}  // namespace convray::implicit
