#include "accel/support_geometry.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "accel/triangle_span_batch.hpp"

namespace convray::accel::detail {

uint64_t GeometrySource::next_serial() {
  static std::atomic<uint64_t> made{0};
  return ++made;
}

Box3 GeometrySource::support_box(uint32_t i) const {
  const double r = radius(i);
  switch (kind) {
    case Kind::sphere:
      return {centers[i] - Vec3(r), centers[i] + Vec3(r)};
    case Kind::capsule:
      return segment_support_box(capsules[i], r);
    case Kind::arc:
      return arc_support_box(arcs[i], r);
    case Kind::triangle:
      return triangle_support_box(triangles[i], r);
  }
  return {};
}

Span GeometrySource::span(uint32_t i, const Vec3& origin, const Vec3& direction) const {
  const double r = radius(i);
  switch (kind) {
    case Kind::sphere:
      return sphere_span(origin, direction, centers[i], r);
    case Kind::capsule:
      return capsule_span(origin, direction, capsules[i], r);
    case Kind::arc:
      return arc_span(origin, direction, arcs[i], r);
    case Kind::triangle:
      return frames ? triangle_span(origin, direction, triangles[i], frames[i], r)
                    : triangle_span(origin, direction, triangles[i], r);
  }
  return {};
}

bool GeometrySource::contains(uint32_t i, const Vec3& p) const {
  const double r = radius(i);
  double d2 = 0.0;
  switch (kind) {
    case Kind::sphere:
      d2 = glm::dot(p - centers[i], p - centers[i]);
      break;
    case Kind::capsule:
      d2 = distance2_to_segment(p, capsules[i]);
      break;
    case Kind::arc:
      d2 = distance2_to_arc(p, arcs[i]);
      break;
    case Kind::triangle:
      d2 = distance2_to_triangle(p, triangles[i]);
      break;
  }
  return d2 < r * r;
}

// Embree traverses with a float copy of the ray, which strays from the exact line by about
// 1e-7 of (|origin| + t); a slack of 1e-5 of the scene's size keeps every crossed support
// for cameras up to tens of scene sizes away. Exact spans are computed in the callbacks.
double support_margin(const Box3& bounds) {
  if (bounds.empty()) return 0.0;
  const double size = glm::length(bounds.extent()) +
                      glm::length(glm::max(glm::abs(bounds.lo), glm::abs(bounds.hi)));
  return 1e-5 * size;
}

namespace {

// What the shared device has allocated, in all (Embree reports frees as negative sizes).
std::atomic<long long> device_bytes{0};
// Builds and releases take turns so that each build's share of device_bytes is its own.
// Recursive: a build may, in principle, run inside another's TBB tasks on the same thread.
std::recursive_mutex build_mutex;

bool memory_callback(void* /*user*/, ssize_t bytes, bool /*post*/) {
  device_bytes.fetch_add(bytes, std::memory_order_relaxed);
  return true;
}

void check(const char* step) {
  const RTCError error = rtcGetDeviceError(shared_device());
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("Embree failed while ") + step + " (error " +
                             std::to_string(int(error)) + ")");
  }
}

// Extends RTCIntersectContext (it must come first) with the exact double-precision ray.
struct LineContext {
  RTCIntersectContext embree;
  Line line;
  const std::vector<GeometrySource>* sources;
  std::vector<SupportInterval>* out;
  std::vector<TriangleCandidate>* triangles;  // spans computed after the traversal, batched
  TriangleLineTable* terms;  // null: spans only
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
// Inside an instance the float ray Embree hands over is in the instanced scene's space; we
// ignore it and take the instance's entry of the index's own table, whose primitives are in
// the index's space: the exact ray meets them there, as in an index built without instances.
void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  auto* context = reinterpret_cast<LineContext*>(args->context);
  const Line& line = context->line;
  const unsigned instance = args->context->instID[0];
  const GeometrySource* source = instance == RTC_INVALID_GEOMETRY_ID
                                     ? static_cast<const GeometrySource*>(args->geometryUserPtr)
                                     : &(*context->sources)[instance];
  if (source->kind == GeometrySource::Kind::triangle) {
    if (may_cross_chunk(line.origin, line.direction, line.tmin, line.tmax,
                        source->balls[args->primID])) {
      context->triangles->push_back({source, args->primID});
    }
    return;
  }
  const Span s = source->span(args->primID, line.origin, line.direction);
  if (s.empty() || s.exit < line.tmin || s.enter > line.tmax) return;
  context->out->push_back({source->first_id + args->primID, s.enter, s.exit});
}

// The candidates of each source together, sources in address order, each one's in the order
// found: what std::stable_sort by source gives, without its buffer (an allocation per line,
// 1 % of the dragon at R = 5, whose repeated triangles make a second source). Lines meet few
// sources (a mesh's groups of repeated triangles, a union's meshes): each is gathered in one
// pass; past kFewSources, the stable sort.
template <class BySource>
void group_by_source(std::vector<TriangleCandidate>& candidates, BySource by_source) {
  constexpr size_t kFewSources = 8;
  thread_local std::vector<const GeometrySource*> sources;
  thread_local std::vector<TriangleCandidate> grouped;
  sources.clear();
  for (const TriangleCandidate& c : candidates) {
    if (std::find(sources.begin(), sources.end(), c.source) != sources.end()) continue;
    if (sources.size() == kFewSources) {
      std::stable_sort(candidates.begin(), candidates.end(), by_source);
      return;
    }
    sources.push_back(c.source);
  }
  std::sort(sources.begin(), sources.end(), std::less<const GeometrySource*>());
  grouped.clear();
  for (const GeometrySource* source : sources) {
    for (const TriangleCandidate& c : candidates) {
      if (c.source == source) grouped.push_back(c);
    }
  }
  std::copy(grouped.begin(), grouped.end(), candidates.begin());
}

}  // namespace

// The exact spans of the triangle candidates, a run of one source at a time through the SIMD
// batch (the same answers as GeometrySource::span, which tests compare it with).
// Neighbouring lines (a tile's camera rays, the shadow rays of their hits) often have the very
// same candidates: the last two gathers are kept, and a run of candidates that matches one is
// computed on it without gathering again (the soup: half of the runs).
void span_candidates(const Line& line, std::vector<TriangleCandidate>& candidates,
                     std::vector<SupportInterval>& out, TriangleLineTable* terms) {
  struct Gathered {
    TriangleSpanBatch batch;
    uint64_t serial = 0;  // the source's (0: none yet)
    std::vector<uint32_t> ids;
  };
  thread_local Gathered kept[2];
  thread_local unsigned older = 0;  // the one to gather into next
  thread_local std::vector<uint32_t> ids;
  const auto by_source = [](const TriangleCandidate& a, const TriangleCandidate& b) {
    return std::less<const GeometrySource*>()(a.source, b.source);
  };
  // Most lines meet one mesh only: then the candidates are in order already, and a stable
  // sort would still allocate its buffer and merge (3 % of a render of the soup).
  if (!std::is_sorted(candidates.begin(), candidates.end(), by_source)) {
    group_by_source(candidates, by_source);
  }
  for (size_t begin = 0; begin < candidates.size();) {
    const GeometrySource& source = *candidates[begin].source;
    size_t end = begin;
    ids.clear();
    while (end < candidates.size() && candidates[end].source == &source) {
      ids.push_back(candidates[end++].primitive);
    }
    const auto holds = [&](const Gathered& g) { return g.serial == source.serial && g.ids == ids; };
    const int held = holds(kept[0]) ? 0 : holds(kept[1]) ? 1 : -1;
    const unsigned slot = held >= 0 ? unsigned(held) : older;
    TriangleSpanBatch& batch = kept[slot].batch;
    if (held < 0) {
      batch.gather({source.triangles, source.count}, {source.frames, source.count}, ids);
      kept[slot].serial = source.serial;
      kept[slot].ids = ids;
    }
    older = slot ^ 1u;
    uint32_t row = SupportInterval::kNoTerms;
    if (terms) {
      row = uint32_t(batch.compute(line.origin, line.direction, source.shared_radius, *terms));
    } else {
      batch.compute(line.origin, line.direction, source.shared_radius);
    }
    for (size_t k = 0; k < ids.size(); ++k) {
      const Span s = batch.span(k);
      if (s.empty() || s.exit < line.tmin || s.enter > line.tmax) continue;
      out.push_back({source.first_id + ids[k], s.enter, s.exit,
                     terms ? row + uint32_t(k) : SupportInterval::kNoTerms});
    }
    begin = end;
  }
}

namespace {

// args->query is the world-space query; inside an instance the geometry is found by the
// instance's id (see intersect_callback).
bool point_callback(RTCPointQueryFunctionArguments* args) {
  auto* query = static_cast<PointContext*>(args->userPtr);
  const RTCPointQueryContext* context = args->context;
  const unsigned geometry = context->instStackSize > 0 ? context->instID[0] : args->geomID;
  const GeometrySource& source = (*query->sources)[geometry];
  if (source.contains(args->primID, query->p))
    query->out->push_back(source.first_id + args->primID);
  return false;  // the query radius is unchanged
}

RTCDevice make_device() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) throw std::runtime_error("Embree: could not create a device");
  rtcSetDeviceMemoryMonitorFunction(device, memory_callback, nullptr);
  return device;
}

}  // namespace

RTCDeviceTy* shared_device() {
  static RTCDevice device = make_device();  // never released: it lives as long as the process
  return device;
}

SceneBuild::SceneBuild() : lock_(build_mutex) {
  start_ = device_bytes.load();
  scene_ = rtcNewScene(shared_device());
  // The Morton builder for the level above the geometries. Embree builds each user geometry's
  // own hierarchy with the geometry's build quality, left at its default (the SAH builder):
  // the Morton build of the dragon's supports took half the time but held 13 MB more, a loss
  // where the pages are first touched (docs/benchmarks.md, twentieth step). The spans are
  // exact either way, only traversal changes.
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
}

SceneBuild::~SceneBuild() {
  if (scene_) rtcReleaseScene(scene_);
}

void SceneBuild::add_user_geometry(GeometrySource& source) {
  RTCGeometry geometry = rtcNewGeometry(shared_device(), RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, source.count);
  rtcSetGeometryUserData(geometry, &source);
  rtcSetGeometryBoundsFunction(geometry, bounds_callback, nullptr);
  rtcSetGeometryIntersectFunction(geometry, intersect_callback);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);  // ids from 0 in order
  rtcReleaseGeometry(geometry);
}

RTCSceneTy* SceneBuild::commit(const char* step) {
  rtcCommitScene(scene_);
  check(step);
  bytes_ = std::max(0LL, device_bytes.load() - start_);
  RTCScene built = scene_;
  scene_ = nullptr;
  return built;
}

void release_scene(RTCSceneTy* scene) {
  if (!scene) return;
  std::lock_guard lock(build_mutex);
  rtcReleaseScene(scene);
}

void intersect_line(RTCSceneTy* scene, const std::vector<GeometrySource>& sources,
                    const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                    std::vector<SupportInterval>& out, TriangleLineTable* terms) {
  LineContext line;
  rtcInitIntersectContext(&line.embree);
  line.line = {origin, direction, tmin, tmax};
  line.sources = &sources;
  line.out = &out;
  line.terms = terms;
  thread_local std::vector<TriangleCandidate> candidates;
  candidates.clear();
  line.triangles = &candidates;
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
  rayhit.ray.tfar =
      std::isfinite(tmax) ? float(tmax + slack - start) : std::numeric_limits<float>::infinity();
  rayhit.ray.mask = ~0u;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &line.embree, &rayhit);
  span_candidates(line.line, candidates, out, terms);
}

void contain_point(RTCSceneTy* scene, const std::vector<GeometrySource>& sources, const Vec3& p,
                   std::vector<uint32_t>& out) {
  RTCPointQuery query;
  query.x = float(p.x);
  query.y = float(p.y);
  query.z = float(p.z);
  query.radius = 0.0f;
  query.time = 0.0f;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  PointContext user{&sources, p, &out};
  rtcPointQuery(scene, &query, &context, point_callback, &user);
}

}  // namespace convray::accel::detail
