#pragma once
// Private to src/accel: the Embree plumbing SupportIndex and TriangleSupports share. One
// process-wide device (instances must live on the device of the scene that places them), our
// user geometry over supports (float boxes grown by a margin, exact double spans in the
// callbacks), and the two queries. Embree's handles are only forward-declared here; Embree
// itself is included by the .cpp files alone.
#include <cstdint>
#include <mutex>
#include <vector>

#include "accel/support_index.hpp"
#include "accel/support_shapes.hpp"
#include "accel/triangle_line.hpp"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace convray::accel::detail {

// One Embree user geometry per kind (and per triangle group): its primitives and where their
// ids start in the global numbering.
struct GeometrySource {
  enum class Kind { sphere, capsule, arc, triangle } kind;
  uint32_t first_id = 0;
  uint32_t count = 0;
  const Vec3* centers = nullptr;
  const field::Segment* capsules = nullptr;
  const field::Arc* arcs = nullptr;
  const field::Triangle* triangles = nullptr;
  const field::TriangleFrame* frames = nullptr;  // one per triangle (the exact spans read them)
  // Triangles: their supports' bounding balls, which the line callback tests. SupportIndex
  // makes them for its own table, the one the callbacks read (inside instances too).
  const BoundingBall* balls = nullptr;
  const double* radii = nullptr;  // per primitive, or null with `shared_radius`
  double shared_radius = 0.0;
  double margin = 0.0;  // absolute slack on the float boxes (see support_margin)
  // Distinct for every source made in this process (and kept by its copies): thread-local
  // caches key on it, as a freed source's address may be reused.
  uint64_t serial = next_serial();

  static uint64_t next_serial();

  double radius(uint32_t i) const { return radii ? radii[i] : shared_radius; }
  Box3 support_box(uint32_t i) const;
  Span span(uint32_t i, const Vec3& origin, const Vec3& direction) const;
  bool contains(uint32_t i, const Vec3& p) const;
};

// A line query: origin + t direction (unit direction), t in [tmin, tmax].
struct Line {
  Vec3 origin, direction;
  double tmin, tmax;
};

// A triangle that may cross a line (its support's bounding ball and slab said so:
// may_cross), its exact span still to be computed.
struct TriangleCandidate {
  const GeometrySource* source;
  uint32_t primitive;
};

// Appends the candidates whose exact span meets [line.tmin, line.tmax] to `out` (the whole
// span), with their terms along the line in `terms` if asked. Reorders `candidates` by source.
void span_candidates(const Line& line, std::vector<TriangleCandidate>& candidates,
                     std::vector<SupportInterval>& out, TriangleLineTable* terms);

// The float slack Embree's boxes need around supports spanning `bounds` (see the .cpp).
double support_margin(const Box3& bounds);

// Embree's device, created on first use (thread-safe) and kept for the process.
RTCDeviceTy* shared_device();

// Builds one scene on the shared device and measures what Embree allocated for it. Builds
// (and releases, see release_scene) take turns, so that the device's allocation counter,
// read before and after, counts this scene's bytes alone.
class SceneBuild {
 public:
  SceneBuild();  // a new empty scene: robust traversal, Embree's default builders (the .cpp)
  ~SceneBuild();
  SceneBuild(const SceneBuild&) = delete;
  SceneBuild& operator=(const SceneBuild&) = delete;

  RTCSceneTy* scene() const { return scene_; }
  // Adds a user geometry over `source` (which must outlive the scene); its geomID is the
  // number of geometries attached before it.
  void add_user_geometry(GeometrySource& source);
  // Commits and checks for errors (`step` names it in the message); hands the scene over.
  RTCSceneTy* commit(const char* step);
  long long bytes() const { return bytes_; }

 private:
  std::unique_lock<std::recursive_mutex> lock_;
  RTCSceneTy* scene_ = nullptr;
  long long start_ = 0;
  long long bytes_ = 0;
};

// Releases a scene built by SceneBuild (null is fine).
void release_scene(RTCSceneTy* scene);

// The queries. `sources` is the table of the scene's geometries by geomID: a geometry met
// inside an instance is looked up there by the instance's id, and its exact spans and
// distances are computed on that entry's primitives (in this scene's space), with that
// entry's first id.
void intersect_line(RTCSceneTy* scene, const std::vector<GeometrySource>& sources,
                    const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                    std::vector<SupportInterval>& out, TriangleLineTable* terms);
void contain_point(RTCSceneTy* scene, const std::vector<GeometrySource>& sources, const Vec3& p,
                   std::vector<uint32_t>& out);

}  // namespace convray::accel::detail
