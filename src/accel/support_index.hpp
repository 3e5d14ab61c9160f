#pragma once
// The acceleration structure over the supports of skeleton primitives (Embree 3 user
// geometry, bounds = each primitive's support). Two queries:
//  - along a line: every primitive whose support it crosses, with the exact entry and exit;
//  - at a point: every primitive whose skeleton lies within its radius of the point.
// The primitives are not copied: the index keeps the spans it was given, which must outlive it.
// A triangle group may come with a prebuilt hierarchy (TriangleSupports, shared between
// indexes: animation frames that keep a mesh) placed by a rigid motion: it is attached as an
// Embree instance instead of being rebuilt; answers are the same as without it.
// This header does not include Embree; only accel/*.cpp do.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "accel/support_shapes.hpp"
#include "accel/triangle_line.hpp"
#include "accel/triangle_supports.hpp"
#include "field/arc.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
#include "util/math.hpp"

namespace convray::accel {

// Primitive ids run over the spheres first, then capsules, arcs, and the triangle groups in
// order; each span pairs with a radius per primitive (a triangle group shares one radius).
struct SupportSources {
  struct TriangleGroup {
    // In the index's space: exact spans and distances are always computed on these.
    std::span<const field::Triangle> triangles;
    double radius = 1.0;
    // Optional: their frames (field::triangle_frame, one per triangle, kept alive as the
    // triangles are), which the exact spans read; without them the index makes its own.
    std::span<const field::TriangleFrame> frames = {};
    // Optional: a hierarchy over the same triangles in its own space (same order, same radius)
    // and the rigid motion that places it, triangles[i] = placement(prebuilt triangles[i]) up
    // to rounding. Used as an instance when its margin suffices (required_instance_margin);
    // otherwise the index builds the group itself. A non-rigid placement is an error.
    std::shared_ptr<const TriangleSupports> prebuilt = nullptr;
    Mat4 placement{1.0};
  };
  std::span<const Vec3> sphere_centers;
  std::span<const double> sphere_radii;
  std::span<const field::Segment> capsules;
  std::span<const double> capsule_radii;
  std::span<const field::Arc> arcs;
  std::span<const double> arc_radii;
  std::vector<TriangleGroup> triangle_groups;
};

struct SupportInterval {
  static constexpr uint32_t kNoTerms = UINT32_MAX;
  uint32_t primitive = 0;
  double enter = 0.0;
  double exit = 0.0;
  // A triangle's row in the TriangleLineTable the query filled, if it was asked to.
  uint32_t terms = kNoTerms;
};

class SupportIndex {
 public:
  explicit SupportIndex(const SupportSources& sources);
  ~SupportIndex();
  SupportIndex(SupportIndex&&) noexcept;
  SupportIndex& operator=(SupportIndex&&) noexcept;

  size_t size() const;
  Box3 bounds() const;  // union of the supports
  // What Embree allocated for the structure, the prebuilt hierarchies it places included.
  size_t memory_bytes() const;
  // How many triangle groups are placed instances of prebuilt hierarchies.
  size_t instance_count() const;
  // The bounding balls of each non-empty triangle group's supports (triangle_bounding_ball),
  // in the groups' order: made once here, for the callbacks and for callers that want them.
  const std::vector<std::vector<BoundingBall>>& triangle_balls() const;

  // Appends every primitive whose support the line origin + t direction (unit direction)
  // crosses with some t in [tmin, tmax]; the interval is the whole crossing, not clipped.
  // tmin must be finite (an infinite one is read as 0). With `terms`, each triangle's terms
  // along the line (accel/triangle_line.hpp) go there too, in the row its interval names.
  void intersect(const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                 std::vector<SupportInterval>& out, TriangleLineTable* terms = nullptr) const;
  // Appends every primitive within its radius of p (strictly: the field is zero at distance R).
  void contain(const Vec3& p, std::vector<uint32_t>& out) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// The union of the supports of `sources`: what SupportIndex(sources).bounds() will be.
Box3 support_bounds(const SupportSources& sources);

// The margin a prebuilt TriangleSupports whose supports span `local_bounds` (in its own space)
// needs to be placed in an index whose supports span `index_bounds`: the index's own slack
// for its float rays, plus the rounding of Embree's float transform into the instance's space.
double required_instance_margin(const Box3& index_bounds, const Box3& local_bounds);

}  // namespace convray::accel
