#include "accel/support_index.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include "accel/support_shapes.hpp"

namespace convray::accel {
namespace {

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
  const double* radii = nullptr;  // per primitive, or null with `shared_radius`
  double shared_radius = 0.0;
  double margin = 0.0;            // absolute slack on the float boxes (see build_geometry)

  double radius(uint32_t i) const { return radii ? radii[i] : shared_radius; }

  Box3 support_box(uint32_t i) const {
    const double r = radius(i);
    switch (kind) {
      case Kind::sphere: return {centers[i] - Vec3(r), centers[i] + Vec3(r)};
      case Kind::capsule: return segment_support_box(capsules[i], r);
      case Kind::arc: return arc_support_box(arcs[i], r);
      case Kind::triangle: return triangle_support_box(triangles[i], r);
    }
    return {};
  }

  Span span(uint32_t i, const Vec3& origin, const Vec3& direction) const {
    const double r = radius(i);
    switch (kind) {
      case Kind::sphere: return sphere_span(origin, direction, centers[i], r);
      case Kind::capsule: return capsule_span(origin, direction, capsules[i], r);
      case Kind::arc: return arc_span(origin, direction, arcs[i], r);
      case Kind::triangle: return triangle_span(origin, direction, triangles[i], r);
    }
    return {};
  }

  bool contains(uint32_t i, const Vec3& p) const {
    const double r = radius(i);
    double d2 = 0.0;
    switch (kind) {
      case Kind::sphere: d2 = glm::dot(p - centers[i], p - centers[i]); break;
      case Kind::capsule: d2 = distance2_to_segment(p, capsules[i]); break;
      case Kind::arc: d2 = distance2_to_arc(p, arcs[i]); break;
      case Kind::triangle: d2 = distance2_to_triangle(p, triangles[i]); break;
    }
    return d2 < r * r;
  }
};

// Extends RTCIntersectContext (it must come first) with the exact double-precision ray.
struct LineContext {
  RTCIntersectContext embree;
  Vec3 origin, direction;
  double tmin, tmax;
  std::vector<SupportInterval>* out;
};

struct PointContext {
  const std::vector<GeometrySource>* sources;
  Vec3 p;
  std::vector<uint32_t>* out;
};

void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* source = static_cast<const GeometrySource*>(args->geometryUserPtr);
  const Box3 box = source->support_box(args->primID);
  // Round outwards to float, plus the margin that covers the float ray's own rounding.
  constexpr float kInf = std::numeric_limits<float>::infinity();
  auto down = [&](double v) { return std::nextafter(float(v - source->margin), -kInf); };
  auto up = [&](double v) { return std::nextafter(float(v + source->margin), kInf); };
  *args->bounds_o = RTCBounds{down(box.lo.x), down(box.lo.y), down(box.lo.z), 0.0f,
                              up(box.hi.x),   up(box.hi.y),   up(box.hi.z),   0.0f};
}

// Never reports a hit, so Embree keeps traversing and every crossed support is recorded.
void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* source = static_cast<const GeometrySource*>(args->geometryUserPtr);
  auto* line = reinterpret_cast<LineContext*>(args->context);
  const Span s = source->span(args->primID, line->origin, line->direction);
  if (s.empty() || s.exit < line->tmin || s.enter > line->tmax) return;
  line->out->push_back({source->first_id + args->primID, s.enter, s.exit});
}

bool point_callback(RTCPointQueryFunctionArguments* args) {
  auto* query = static_cast<PointContext*>(args->userPtr);
  const GeometrySource& source = (*query->sources)[args->geomID];
  if (source.contains(args->primID, query->p)) query->out->push_back(source.first_id + args->primID);
  return false;  // the query radius is unchanged
}

bool memory_callback(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<long long>*>(user)->fetch_add(bytes, std::memory_order_relaxed);
  return true;
}

}  // namespace

struct SupportIndex::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<GeometrySource> sources;  // indexed by Embree's geomID
  std::atomic<long long> embree_bytes{0};
  Box3 bounds;
  size_t size = 0;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void check(const char* step) const {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
      throw std::runtime_error(std::string("Embree failed while ") + step + " (error " +
                               std::to_string(int(error)) + ")");
    }
  }
};

namespace {

void add_source(std::vector<GeometrySource>& sources, GeometrySource source, uint32_t& next_id) {
  if (source.count == 0) return;
  source.first_id = next_id;
  next_id += source.count;
  sources.push_back(source);
}

std::vector<GeometrySource> collect_sources(const SupportSources& in) {
  using Kind = GeometrySource::Kind;
  std::vector<GeometrySource> sources;
  uint32_t next_id = 0;
  GeometrySource spheres{Kind::sphere};
  spheres.count = uint32_t(in.sphere_centers.size());
  spheres.centers = in.sphere_centers.data();
  spheres.radii = in.sphere_radii.data();
  add_source(sources, spheres, next_id);
  GeometrySource capsules{Kind::capsule};
  capsules.count = uint32_t(in.capsules.size());
  capsules.capsules = in.capsules.data();
  capsules.radii = in.capsule_radii.data();
  add_source(sources, capsules, next_id);
  GeometrySource arcs{Kind::arc};
  arcs.count = uint32_t(in.arcs.size());
  arcs.arcs = in.arcs.data();
  arcs.radii = in.arc_radii.data();
  add_source(sources, arcs, next_id);
  for (const auto& group : in.triangle_groups) {
    GeometrySource triangles{Kind::triangle};
    triangles.count = uint32_t(group.triangles.size());
    triangles.triangles = group.triangles.data();
    triangles.shared_radius = group.radius;
    add_source(sources, triangles, next_id);
  }
  return sources;
}

}  // namespace

SupportIndex::SupportIndex(const SupportSources& in) : impl_(std::make_unique<Impl>()) {
  if (in.sphere_radii.size() != in.sphere_centers.size() ||
      in.capsule_radii.size() != in.capsules.size() || in.arc_radii.size() != in.arcs.size()) {
    throw std::invalid_argument("SupportIndex: one radius per primitive expected");
  }
  Impl& m = *impl_;
  m.sources = collect_sources(in);
  for (const GeometrySource& s : m.sources) {
    for (uint32_t i = 0; i < s.count; ++i) {
      const Box3 box = s.support_box(i);
      m.bounds.extend(box.lo);
      m.bounds.extend(box.hi);
    }
    m.size += s.count;
  }
  // Embree traverses with a float copy of the ray, which strays from the exact line by about
  // 1e-7 of (|origin| + t); a slack of 1e-5 of the scene's size keeps every crossed support
  // for cameras up to tens of scene sizes away. Exact spans are computed in the callback.
  const double scale = m.bounds.empty() ? 0.0
                                        : glm::length(m.bounds.extent()) +
                                              glm::length(glm::max(glm::abs(m.bounds.lo),
                                                                   glm::abs(m.bounds.hi)));
  for (GeometrySource& s : m.sources) s.margin = 1e-5 * scale;

  m.device = rtcNewDevice(nullptr);
  if (!m.device) throw std::runtime_error("Embree: could not create a device");
  rtcSetDeviceMemoryMonitorFunction(m.device, memory_callback, &m.embree_bytes);
  m.scene = rtcNewScene(m.device);
  // The Morton builder: a million supports in about half a second on two cores, and half the
  // memory of the SAH builder; the spans are exact either way, only traversal changes.
  rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_LOW);
  rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);
  for (GeometrySource& s : m.sources) {
    RTCGeometry geometry = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, s.count);
    rtcSetGeometryUserData(geometry, &s);
    rtcSetGeometryBoundsFunction(geometry, bounds_callback, nullptr);
    rtcSetGeometryIntersectFunction(geometry, intersect_callback);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m.scene, geometry);  // ids from 0 in order: the index into `sources`
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(m.scene);
  m.check("building the support hierarchy");
}

SupportIndex::~SupportIndex() = default;
SupportIndex::SupportIndex(SupportIndex&&) noexcept = default;
SupportIndex& SupportIndex::operator=(SupportIndex&&) noexcept = default;

size_t SupportIndex::size() const { return impl_->size; }
Box3 SupportIndex::bounds() const { return impl_->bounds; }
size_t SupportIndex::memory_bytes() const {
  return size_t(std::max(0LL, impl_->embree_bytes.load())) +
         impl_->sources.capacity() * sizeof(GeometrySource);
}

void SupportIndex::intersect(const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                             std::vector<SupportInterval>& out) const {
  if (impl_->size == 0) return;
  LineContext line;
  rtcInitIntersectContext(&line.embree);
  line.origin = origin;
  line.direction = direction;
  line.tmin = tmin;
  line.tmax = tmax;
  line.out = &out;
  // Embree starts at tnear >= 0: its float ray starts at tmin (less a slack that covers the
  // float rounding of the range), and the callbacks measure t from the exact origin.
  const double slack = 1e-5 * (std::abs(tmin) + (std::isfinite(tmax) ? std::abs(tmax) : 0.0) + 1.0);
  const double start = std::isfinite(tmin) ? tmin - slack : 0.0;
  const Vec3 shifted = origin + start * direction;
  RTCRayHit rayhit{};
  rayhit.ray.org_x = float(shifted.x);
  rayhit.ray.org_y = float(shifted.y);
  rayhit.ray.org_z = float(shifted.z);
  rayhit.ray.dir_x = float(direction.x);
  rayhit.ray.dir_y = float(direction.y);
  rayhit.ray.dir_z = float(direction.z);
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = std::isfinite(tmax) ? float(tmax + slack - start)
                                        : std::numeric_limits<float>::infinity();
  rayhit.ray.mask = ~0u;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &line.embree, &rayhit);
}

void SupportIndex::contain(const Vec3& p, std::vector<uint32_t>& out) const {
  if (impl_->size == 0) return;
  RTCPointQuery query;
  query.x = float(p.x);
  query.y = float(p.y);
  query.z = float(p.z);
  query.radius = 0.0f;
  query.time = 0.0f;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  PointContext user{&impl_->sources, p, &out};
  rtcPointQuery(impl_->scene, &query, &context, point_callback, &user);
}

}  // namespace convray::accel
