// A mesh file's skeleton as convolution components (scene/mesh_skeleton.hpp), and the
// thresholds that put the surface at an offset from a line or a point (threshold.hpp), each
// against the independent quadratures of tests/reference/.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "implicit/convolution_surface.hpp"
#include "scene/mesh_skeleton.hpp"
#include "field/threshold.hpp"
#include "reference/reference_fields.hpp"

namespace convray::implicit {
namespace {

TEST(SkeletonThreshold, LineOffsetIsTheFieldOfALongSegmentAtThatDistance) {
  // Far from its ends (at least R), a segment's field is the infinite line's.
  for (double radius : {0.5, 1.0, 3.0}) {
    for (double offset : {0.0, 0.25 * radius, 0.5 * radius, 0.9 * radius}) {
      const auto reference =
          reference::reference_segment(Vec3(0, offset, 0), Vec3(-2 * radius, 0, 0), Vec3(2 * radius, 0, 0), radius);
      EXPECT_NEAR(field::threshold_for_line_offset(2.0, radius, offset), 2.0 * reference.value, 1e-12 * radius)
          << "R " << radius << " d " << offset;
    }
  }
}

TEST(SkeletonThreshold, PointOffsetIsTheKernelAtThatDistance) {
  for (double offset : {0.0, 0.3, 0.5, 0.99}) {
    EXPECT_NEAR(field::threshold_for_point_offset(1.5, 1.0, offset),
                1.5 * reference::reference_point(Vec3(offset, 0, 0), Vec3(0.0), 1.0).value, 1e-15);
  }
  EXPECT_EQ(field::threshold_for_point_offset(1.0, 2.0, 1.0), 0.5625);  // (1 - 1/4)^2, by hand
}

TEST(SkeletonThreshold, OffsetFromTheMostExtendedKind) {
  EXPECT_EQ(field::resolve_threshold(1.0, 2.0, std::nullopt, std::nullopt, field::OffsetFrom::point), 0.5625);
  EXPECT_EQ(field::resolve_threshold(1.0, 2.0, 0.5, std::nullopt, field::OffsetFrom::line), field::threshold_for_line_offset(1.0, 2.0, 0.5));
  EXPECT_EQ(field::resolve_threshold(1.0, 2.0, 0.5, std::nullopt), field::threshold_for_offset(1.0, 2.0, 0.5));
  EXPECT_EQ(field::resolve_threshold(1.0, 2.0, 0.5, 0.125, field::OffsetFrom::point), 0.125);
  EXPECT_THROW(field::resolve_threshold(1.0, 2.0, 2.0, std::nullopt, field::OffsetFrom::point), std::invalid_argument);
}

// A file with all three kinds, by hand: a triangle, a polyline of two segments, two points.
mesh::LoadedMesh mixed_file() {
  mesh::LoadedMesh file;
  file.soup.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {3, 1, 0}, {4, 1, 0}, {0, 0, 3}, {0.5, 0, 3}};
  file.soup.triangles = {{0, 1, 2}};
  file.segments = {{3, 4}, {4, 5}};
  file.points = {6, 7};
  return file;
}

TEST(MeshSkeleton, PositionsOfEveryKind) {
  const scene::MeshSkeleton skeleton = scene::skeleton_of(mixed_file());
  ASSERT_EQ(skeleton.triangles.size(), 1u);
  EXPECT_EQ(skeleton.triangles[0].c, Vec3(0, 1, 0));
  ASSERT_EQ(skeleton.segments.size(), 2u);
  EXPECT_EQ(skeleton.segments[1].a, Vec3(3, 1, 0));
  EXPECT_EQ(skeleton.segments[1].b, Vec3(4, 1, 0));
  ASSERT_EQ(skeleton.points.size(), 2u);
  EXPECT_EQ(skeleton.points[1], Vec3(0.5, 0, 3));
  EXPECT_EQ(skeleton.offset_from(), field::OffsetFrom::plane);
}

// The triangles come in a spatial order (core/spatial_order.hpp), not the file's: the same
// triangles, each once, corners in the file's order.
TEST(MeshSkeleton, TrianglesAreTheFilesInAnotherOrder) {
  mesh::LoadedMesh file;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 300; ++i) file.soup.vertices.push_back({u(rng), u(rng), u(rng)});
  std::uniform_int_distribution<uint32_t> pick(0, 299);
  for (int i = 0; i < 500; ++i) file.soup.triangles.push_back({pick(rng), pick(rng), pick(rng)});
  const scene::MeshSkeleton skeleton = scene::skeleton_of(file);
  auto key = [](const field::Triangle& t) {
    return std::array<double, 9>{t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
  };
  std::vector<std::array<double, 9>> expected, got;
  for (const auto& t : file.soup.triangles) {
    const auto& v = file.soup.vertices;
    expected.push_back(key({v[t[0]], v[t[1]], v[t[2]]}));
  }
  for (const field::Triangle& t : skeleton.triangles) got.push_back(key(t));
  EXPECT_NE(got, expected);  // reordered (500 random triangles are not in Z-order)
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
}

TEST(MeshSkeleton, FieldIsTheSumOfTheReferenceFieldsOfEveryItem) {
  scene::ConvolutionObject object;
  const scene::Weight weight{1.5, 0.8};
  scene::add_skeleton(scene::skeleton_of(mixed_file()), weight, object);
  EXPECT_EQ(object.meshes.size(), 1u);
  EXPECT_EQ(object.segments.size(), 2u);
  EXPECT_EQ(object.points.size(), 2u);
  const ConvolutionSurface surface(object);
  for (const Vec3& p : {Vec3(0.2, 0.2, 0.3), Vec3(3.1, 0.9, 0.2), Vec3(0.25, 0.1, 3.0), Vec3(9, 9, 9)}) {
    double expected = reference::reference_triangle(p, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.8).value;
    expected += reference::reference_segment(p, {3, 0, 0}, {3, 1, 0}, 0.8).value;
    expected += reference::reference_segment(p, {3, 1, 0}, {4, 1, 0}, 0.8).value;
    expected += reference::reference_point(p, {0, 0, 3}, 0.8).value;
    expected += reference::reference_point(p, {0.5, 0, 3}, 0.8).value;
    EXPECT_NEAR(surface.field(p).value, 1.5 * expected, 1e-12) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(MeshSkeleton, PointCloudOffsetIsFromPoints) {
  mesh::LoadedMesh cloud;
  cloud.soup.vertices = {{0, 0, 0}, {5, 0, 0}};
  cloud.points = {0, 1};
  EXPECT_EQ(scene::skeleton_of(cloud).offset_from(), field::OffsetFrom::point);
  mesh::LoadedMesh lines;
  lines.soup.vertices = {{0, 0, 0}, {5, 0, 0}};
  lines.segments = {{0, 1}};
  EXPECT_EQ(scene::skeleton_of(lines).offset_from(), field::OffsetFrom::line);
}

}  // namespace
}  // namespace convray::implicit
