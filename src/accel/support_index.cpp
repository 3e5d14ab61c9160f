#include "accel/support_index.hpp"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "accel/line_fans.hpp"
#include "accel/support_geometry.hpp"
#include "accel/triangle_supports_impl.hpp"

namespace convray::accel {

using detail::GeometrySource;

struct SupportIndex::Impl {
  RTCScene scene = nullptr;
  std::vector<GeometrySource> sources;  // indexed by Embree's geomID, instances included
  std::vector<std::vector<BoundingBall>> balls;  // of each triangle source's supports
  // The frames of triangle groups that came without them (SupportSources::TriangleGroup).
  std::vector<std::vector<field::TriangleFrame>> own_frames;
  // The placed hierarchies, kept alive while `scene` refers to them.
  std::vector<std::shared_ptr<const TriangleSupports>> instances;
  // Lists for lines through a common point (line_fans.hpp), where every source is a mesh's
  // and there are few enough triangles.
  std::unique_ptr<LineFans> fans;
  long long embree_bytes = 0;  // this scene's own allocations
  Box3 bounds;
  size_t size = 0;

  ~Impl() { detail::release_scene(scene); }
};

namespace {

// One entry per Embree geometry to be: the source, and the group it came from (triangles).
struct Collected {
  std::vector<GeometrySource> sources;
  std::vector<const SupportSources::TriangleGroup*> groups;  // null for other kinds
};

void add_source(Collected& c, GeometrySource source, const SupportSources::TriangleGroup* group,
                uint32_t& next_id) {
  if (source.count == 0) return;
  source.first_id = next_id;
  next_id += source.count;
  c.sources.push_back(source);
  c.groups.push_back(group);
}

Collected collect_sources(const SupportSources& in) {
  using Kind = GeometrySource::Kind;
  Collected c;
  uint32_t next_id = 0;
  GeometrySource spheres{Kind::sphere};
  spheres.count = uint32_t(in.sphere_centers.size());
  spheres.centers = in.sphere_centers.data();
  spheres.radii = in.sphere_radii.data();
  add_source(c, spheres, nullptr, next_id);
  GeometrySource capsules{Kind::capsule};
  capsules.count = uint32_t(in.capsules.size());
  capsules.capsules = in.capsules.data();
  capsules.radii = in.capsule_radii.data();
  add_source(c, capsules, nullptr, next_id);
  GeometrySource arcs{Kind::arc};
  arcs.count = uint32_t(in.arcs.size());
  arcs.arcs = in.arcs.data();
  arcs.radii = in.arc_radii.data();
  add_source(c, arcs, nullptr, next_id);
  for (const auto& group : in.triangle_groups) {
    GeometrySource triangles{Kind::triangle};
    triangles.count = uint32_t(group.triangles.size());
    triangles.triangles = group.triangles.data();
    const bool framed = group.frames.size() == group.triangles.size();
    triangles.frames = framed ? group.frames.data() : nullptr;
    triangles.shared_radius = group.radius;
    add_source(c, triangles, &group, next_id);
  }
  return c;
}

Box3 bounds_of(const std::vector<GeometrySource>& sources) {
  Box3 bounds;
  for (const GeometrySource& s : sources) {
    for (uint32_t i = 0; i < s.count; ++i) {
      const Box3 box = s.support_box(i);
      bounds.extend(box.lo);
      bounds.extend(box.hi);
    }
  }
  return bounds;
}

// How far the group's triangles stray from the placed prebuilt ones (rounding, normally).
double placement_deviation(const SupportSources::TriangleGroup& group) {
  const std::vector<field::Triangle>& local = group.prebuilt->triangles();
  double deviation = 0.0;
  auto stray = [&](const Vec3& placed, const Vec3& p) {
    const Vec3 d = glm::abs(placed - transform_point(group.placement, p));
    deviation = std::max({deviation, d.x, d.y, d.z});
  };
  for (size_t i = 0; i < local.size(); ++i) {
    stray(group.triangles[i].a, local[i].a);
    stray(group.triangles[i].b, local[i].b);
    stray(group.triangles[i].c, local[i].c);
  }
  return std::isfinite(deviation) ? deviation : INFINITY;
}

// Whether the group's prebuilt hierarchy can stand in for it: every support the index's float
// rays may cross must lie within the placed boxes. Throws for what the caller got wrong.
bool can_place(const SupportSources::TriangleGroup& group, const Box3& index_bounds) {
  const TriangleSupports& prebuilt = *group.prebuilt;
  if (prebuilt.size() != group.triangles.size() || prebuilt.radius() != group.radius) {
    throw std::invalid_argument("SupportIndex: a prebuilt hierarchy of another mesh or radius");
  }
  if (!is_rigid(group.placement, 1e-9)) {
    throw std::invalid_argument("SupportIndex: a prebuilt hierarchy needs a rigid placement");
  }
  const double needed = required_instance_margin(index_bounds, prebuilt.bounds());
  return prebuilt.margin() >= needed + placement_deviation(group);
}

void attach_instance(detail::SceneBuild& build, const TriangleSupports& prebuilt,
                     const Mat4& placement) {
  RTCGeometry instance = rtcNewGeometry(detail::shared_device(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, prebuilt.impl().scene);
  float xfm[12];  // 3x4, column-major: the linear part's columns, then the translation
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 3; ++row) xfm[3 * column + row] = float(placement[column][row]);
  }
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  rtcCommitGeometry(instance);
  rtcAttachGeometry(build.scene(), instance);  // ids in order, as the user geometries
  rtcReleaseGeometry(instance);
}

}  // namespace

SupportIndex::SupportIndex(const SupportSources& in) : impl_(std::make_unique<Impl>()) {
  if (in.sphere_radii.size() != in.sphere_centers.size() ||
      in.capsule_radii.size() != in.capsules.size() || in.arc_radii.size() != in.arcs.size()) {
    throw std::invalid_argument("SupportIndex: one radius per primitive expected");
  }
  Impl& m = *impl_;
  Collected collected = collect_sources(in);
  m.sources = std::move(collected.sources);  // final: the geometries point into it
  m.bounds = bounds_of(m.sources);
  const double margin = detail::support_margin(m.bounds);
  for (GeometrySource& s : m.sources) {
    s.margin = margin;
    m.size += s.count;
    if (s.kind != GeometrySource::Kind::triangle) continue;
    std::vector<BoundingBall>& balls = m.balls.emplace_back(s.count);
    tbb::parallel_for(uint32_t(0), s.count, [&](uint32_t i) {
      balls[i] = triangle_bounding_ball(s.triangles[i], s.radius(i));
    });
    s.balls = balls.data();
    if (!s.frames) {
      std::vector<field::TriangleFrame>& frames = m.own_frames.emplace_back(s.count);
      tbb::parallel_for(uint32_t(0), s.count,
                        [&](uint32_t i) { frames[i] = field::triangle_frame(s.triangles[i]); });
      s.frames = frames.data();
    }
  }
  detail::SceneBuild build;
  for (size_t g = 0; g < m.sources.size(); ++g) {
    const SupportSources::TriangleGroup* group = collected.groups[g];
    if (group && group->prebuilt && can_place(*group, m.bounds)) {
      attach_instance(build, *group->prebuilt, group->placement);
      m.instances.push_back(group->prebuilt);
    } else {
      build.add_user_geometry(m.sources[g]);
    }
  }
  m.scene = build.commit("building the support hierarchy");
  m.embree_bytes = build.bytes();
  const bool meshes_only = std::all_of(m.sources.begin(), m.sources.end(), [](const auto& s) {
    return s.kind == GeometrySource::Kind::triangle;
  });
  if (meshes_only && LineFans::worth_making(m.sources, m.bounds)) {
    m.fans = std::make_unique<LineFans>(m.sources, m.bounds);
  }
}

SupportIndex::~SupportIndex() = default;
SupportIndex::SupportIndex(SupportIndex&&) noexcept = default;
SupportIndex& SupportIndex::operator=(SupportIndex&&) noexcept = default;

size_t SupportIndex::size() const { return impl_->size; }
Box3 SupportIndex::bounds() const { return impl_->bounds; }
size_t SupportIndex::instance_count() const { return impl_->instances.size(); }

const std::vector<std::vector<BoundingBall>>& SupportIndex::triangle_balls() const {
  return impl_->balls;
}

size_t SupportIndex::memory_bytes() const {
  size_t bytes = size_t(impl_->embree_bytes) + impl_->sources.capacity() * sizeof(GeometrySource);
  for (const auto& prebuilt : impl_->instances) bytes += prebuilt->memory_bytes();
  if (impl_->fans) bytes += impl_->fans->memory_bytes();
  for (const auto& balls : impl_->balls) bytes += balls.capacity() * sizeof(BoundingBall);
  for (const auto& frames : impl_->own_frames) {
    bytes += frames.capacity() * sizeof(field::TriangleFrame);
  }
  return bytes;
}

void SupportIndex::intersect(const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                             std::vector<SupportInterval>& out,
                             TriangleLineTable* terms) const {
  if (impl_->size == 0) return;
  if (impl_->fans) {
    thread_local std::vector<detail::TriangleCandidate> candidates;
    candidates.clear();
    const detail::Line line{origin, direction, tmin, tmax};
    if (impl_->fans->candidates(line, candidates)) {
      detail::span_candidates(line, candidates, out, terms);
      return;
    }
  }
  detail::intersect_line(impl_->scene, impl_->sources, origin, direction, tmin, tmax, out, terms);
}

void SupportIndex::contain(const Vec3& p, std::vector<uint32_t>& out) const {
  if (impl_->size == 0) return;
  detail::contain_point(impl_->scene, impl_->sources, p, out);
}

Box3 support_bounds(const SupportSources& sources) {
  return bounds_of(collect_sources(sources).sources);
}

// Embree carries the float ray into the instance's space through a float copy of the
// placement: the rounding grows with the coordinates on both sides (the translation is as big
// as both), so the instance's boxes take the index's slack plus the slack of their own space.
double required_instance_margin(const Box3& index_bounds, const Box3& local_bounds) {
  return detail::support_margin(index_bounds) + detail::support_margin(local_bounds);
}

}  // namespace convray::accel
