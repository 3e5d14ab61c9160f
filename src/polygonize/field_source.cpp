#include "polygonize/field_source.hpp"

#include <optional>

#include "accel/support_shapes.hpp"
#include "implicit/repeated_triangles.hpp"

namespace convray::polygonize {

namespace {

Box3 ball_box(const Vec3& center, double radius) {
  return {center - Vec3(radius), center + Vec3(radius)};
}

}  // namespace

std::vector<Box3> support_boxes(const implicit::ConvolutionObject& object) {
  std::vector<Box3> boxes;
  for (const implicit::MeshComponent& mesh : object.meshes) {
    // One box per distinct triangle: copies share their support, and a soup of one triangle
    // 10^7 times would otherwise hand the lattice 10^7 equal boxes to bin (issue 17).
    const std::optional<implicit::DistinctTriangles> merged = implicit::merge_repeated(mesh.triangles);
    for (const field::Triangle& triangle : merged ? merged->triangles : mesh.triangles) {
      boxes.push_back(accel::triangle_support_box(triangle, mesh.weight.radius));
    }
  }
  for (const implicit::SegmentComponent& s : object.segments) {
    boxes.push_back(accel::segment_support_box(s.segment, s.weight.radius));
  }
  for (const implicit::ArcComponent& a : object.arcs) {
    boxes.push_back(accel::arc_support_box(a.arc, a.weight.radius));
  }
  for (const implicit::PointComponent& p : object.points) {
    boxes.push_back(ball_box(p.center, p.weight.radius));
  }
  for (const implicit::BlobSphereComponent& b : object.blob_spheres) {
    boxes.push_back(ball_box(b.center, b.weight.radius));
  }
  for (const implicit::BlobCylinderComponent& c : object.blob_cylinders) {
    // A capsule of distance kernels: within r of the axis segment.
    boxes.push_back(accel::segment_support_box({c.base, c.apex}, c.weight.radius));
  }
  return boxes;
}

Box3 transform_box(const Mat4& m, const Box3& box) {
  Box3 out;
  if (box.empty()) return out;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                 (corner & 4) ? box.hi.z : box.lo.z);
    out.extend(transform_point(m, p));
  }
  return out;
}

}  // namespace convray::polygonize
