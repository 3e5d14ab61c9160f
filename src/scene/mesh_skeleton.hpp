#pragma once
// A mesh file's skeleton (mesh::LoadedMesh: triangles, segments, points over indexed
// vertices) as positions, and as the components of a convolution object: the triangles one
// mesh component, each segment and each point a component of its own, all of one weight. So
// the files' point clouds and polylines go through the same closed forms and tracers as a
// scene's `point { }` and `segment { }` (points through the exact sphere sweep).
#include <vector>

#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "scene/convolution_object.hpp"
#include "field/threshold.hpp"
#include "mesh/load.hpp"

namespace convray::scene {

struct MeshSkeleton {
  std::vector<field::Triangle> triangles;
  std::vector<field::Segment> segments;
  std::vector<Vec3> points;

  // What an offset is measured from: triangles, else segments, else points.
  field::OffsetFrom offset_from() const {
    return !triangles.empty() ? field::OffsetFrom::plane : !segments.empty() ? field::OffsetFrom::line : field::OffsetFrom::point;
  }
};

MeshSkeleton skeleton_of(const mesh::LoadedMesh& mesh);

// The triangles of a soup as field primitives, in the soup's own order (skeleton_of puts them
// in spatial order).
std::vector<field::Triangle> soup_triangles(const mesh::TriangleSoup& soup);

// Appends the skeleton's components to `object` (the triangles moved in).
void add_skeleton(MeshSkeleton skeleton, const Weight& weight, ConvolutionObject& object);

}  // namespace convray::scene
