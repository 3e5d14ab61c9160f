// OpenVDB 10: the field sampled into a sparse FloatGrid restricted to the supports, then
// tools::volumeToMesh; and, for the repair comparison, the soup's unsigned distance field
// (tools::meshToUnsignedDistanceField) meshed at the offset.
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <openvdb/tree/LeafManager.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <vector>

#include "polygonizer_eval.hpp"

namespace convray::bench {

namespace {

using Clock = std::chrono::steady_clock;

// volumeToMesh's quads (and, with adaptivity, triangles) as our soup. Its polygons face the
// side where the grid's values are larger: with values negative inside (the level-set
// convention we sample in), that is outward, as ours.
mesh::TriangleSoup to_soup(const std::vector<openvdb::Vec3s>& points,
                           const std::vector<openvdb::Vec3I>& triangles,
                           const std::vector<openvdb::Vec4I>& quads) {
  mesh::TriangleSoup soup;
  soup.vertices.reserve(points.size());
  for (const auto& p : points) soup.vertices.push_back({p.x(), p.y(), p.z()});
  for (const auto& t : triangles) soup.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    soup.triangles.push_back({q[0], q[1], q[2]});
    soup.triangles.push_back({q[0], q[2], q[3]});
  }
  return soup;
}

}  // namespace

PolygonizerOutput polygonize_openvdb(const Problem& problem, double adaptivity) {
  openvdb::initialize();
  const auto start = Clock::now();
  const double h = problem.cell;
  const float threshold = static_cast<float>(problem.threshold);
  // Values T - F: negative inside, as OpenVDB's level sets; the background (F = 0, outside
  // every support) is T.
  auto grid = openvdb::FloatGrid::create(threshold);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(h));
  auto& tree = grid->tree();

  // Activate whole 8^3 leaves over each triangle's box grown by R and a voxel: F can only be
  // nonzero there, and the extra voxel keeps every sign change between two sampled voxels.
  const double reach = problem.field->radius() + h;
  const auto& soup = *problem.soup;
  for (size_t t = 0; t < soup.triangles.size(); ++t) {
    Box3 box;
    for (const Vec3& p : soup.corners(t)) box.extend(p);
    const glm::ivec3 lo(glm::floor((box.lo - reach) / h)), hi(glm::floor((box.hi + reach) / h));
    for (int x = lo.x & ~7; x <= hi.x; x += 8) {
      for (int y = lo.y & ~7; y <= hi.y; y += 8) {
        for (int z = lo.z & ~7; z <= hi.z; z += 8) tree.touchLeaf(openvdb::Coord(x, y, z));
      }
    }
  }
  // Sample every voxel of those leaves, leaves in parallel (TBB).
  openvdb::tree::LeafManager<openvdb::FloatTree> leaves(tree);
  const implicit::MeshField& field = *problem.field;
  leaves.foreach ([&](openvdb::FloatTree::LeafNodeType& leaf, size_t) {
    for (auto it = leaf.beginValueAll(); it; ++it) {
      const openvdb::Coord c = it.getCoord();
      const Vec3 p(c.x() * h, c.y() * h, c.z() * h);
      leaf.setValueOn(it.pos(), threshold - static_cast<float>(field.value(p)));
    }
  });
  const double sample_seconds = std::chrono::duration<double>(Clock::now() - start).count();

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, adaptivity);
  PolygonizerOutput result;
  result.mesh = to_soup(points, triangles, quads);
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::ostringstream note;
  note << "FloatGrid voxel " << h << ", " << tree.leafCount() << " leaves, "
       << tree.activeVoxelCount() << " voxels sampled in " << sample_seconds
       << " s (TBB); volumeToMesh adaptivity " << adaptivity << " (TBB)";
  result.note = note.str();
  return result;
}

PolygonizerOutput openvdb_soup_offset(const Problem& problem, double offset) {
  openvdb::initialize();
  const auto start = Clock::now();
  const double h = problem.cell;
  const auto& soup = *problem.soup;
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  const std::vector<openvdb::Vec4I> no_quads;
  for (const Vec3& p : soup.vertices) points.emplace_back(p.x, p.y, p.z);
  for (const auto& t : soup.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  auto transform = openvdb::math::Transform::createLinearTransform(h);
  // The band (in voxels) must reach past the isovalue, with room for interpolation.
  const float band = static_cast<float>(std::ceil(offset / h) + 3.0);
  auto distance = openvdb::tools::meshToUnsignedDistanceField<openvdb::FloatGrid>(
      *transform, points, triangles, no_quads, band);
  const double distance_seconds = std::chrono::duration<double>(Clock::now() - start).count();

  std::vector<openvdb::Vec3s> out_points;
  std::vector<openvdb::Vec3I> out_triangles;
  std::vector<openvdb::Vec4I> out_quads;
  openvdb::tools::volumeToMesh(*distance, out_points, out_triangles, out_quads, offset, 0.0);
  PolygonizerOutput result;
  result.mesh = to_soup(out_points, out_triangles, out_quads);
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::ostringstream note;
  note << "meshToUnsignedDistanceField voxel " << h << ", band " << band << " voxels, "
       << distance->activeVoxelCount() << " active voxels, " << distance_seconds
       << " s (TBB); volumeToMesh isovalue " << offset << ", adaptivity 0 (TBB)";
  result.note = note.str();
  return result;
}

}  // namespace convray::bench
