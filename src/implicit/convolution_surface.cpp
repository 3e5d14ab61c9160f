#include "implicit/convolution_surface.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "accel/support_shapes.hpp"
#include "implicit/inside_balls.hpp"
#include "implicit/lent_triangles.hpp"
#include "implicit/near_hit.hpp"
#include "implicit/reference_tracer.hpp"
#include "implicit/repeated_triangles.hpp"
#include "implicit/support_cache.hpp"
#include "implicit/surface_impl.hpp"
#include "implicit/surface_roots.hpp"

namespace convray::implicit {
namespace {

// Chunked first-root searches pay off from about this many supports per line (measured on
// the vertex blob of bench/vertex_blob_render: a loss at 2.5, a gain from 10).
constexpr double kChunkedSupportsPerLine = 5.0;
// A chunk is at least this many mean support widths long: a support crossing a chunk's end is
// gathered (and its exact span computed) again in the next chunk, which costs more than the
// chunks save where they are short beside the supports (the soup of scenes/soup.pov).
// (The soup's render: 0.79 of the instructions with chunks of at least 2 widths, 0.80 with
// 4 or more, which leave it one chunk; the dragon's chunks are longer anyway.)
constexpr double kChunkWidths = 2.0;

void check_weight(const scene::Weight& w, const char* what) {
  if (!(w.radius > 0.0) || !std::isfinite(w.radius) || !std::isfinite(w.strength)) {
    throw std::invalid_argument(std::string(what) +
                                ": radius must be positive and finite, strength finite");
  }
}

// Whether the component's source describes its triangles (the same count; the support index
// checks the placement triangle by triangle and builds the group itself where it strays).
bool has_source(const scene::MeshComponent& m) {
  return m.source && m.source->local && m.source->local->size() == m.triangles.size();
}

// Mesh groups whose component has a source take their hierarchy from the cache (null: a
// group of merged repeated triangles, which builds its own).
void take_prebuilt(accel::SupportSources& sources,
                   const std::vector<const scene::MeshComponent*>& group_meshes, SupportCache& cache) {
  const Box3 index_bounds = accel::support_bounds(sources);
  for (size_t g = 0; g < group_meshes.size(); ++g) {
    if (!group_meshes[g] || !has_source(*group_meshes[g])) continue;
    const scene::MeshComponent& mesh = *group_meshes[g];
    auto& group = sources.triangle_groups[g];
    const SupportCache::Placed placed =
        cache.acquire(*mesh.source, group.triangles, group.radius, index_bounds);
    group.prebuilt = placed.supports;
    group.placement = placed.placement;
  }
}

}  // namespace

ConvolutionSurface::Impl::Impl(const scene::ConvolutionObject& object, SupportCache* cache)
    : threshold(object.threshold) {
  static std::atomic<uint64_t> surfaces_made{0};
  serial = ++surfaces_made;
  if (!(threshold > 0.0) || !std::isfinite(threshold)) {
    throw std::invalid_argument("convolution object: the threshold must be positive and finite");
  }
  min_radius = std::numeric_limits<double>::infinity();
  auto note = [&](const scene::Weight& w, const char* what) {
    check_weight(w, what);
    min_radius = std::min(min_radius, w.radius);
    nonnegative = nonnegative && w.strength >= 0.0;
  };
  for (const scene::PointComponent& c : object.points) {
    note(c.weight, "point");
    sphere_centers.push_back(c.center);
    sphere_radii.push_back(c.weight.radius);
    sphere_strengths.push_back(c.weight.strength);
  }
  for (const scene::BlobSphereComponent& c : object.blob_spheres) {
    note(c.weight, "blob sphere");
    sphere_centers.push_back(c.center);
    sphere_radii.push_back(c.weight.radius);
    sphere_strengths.push_back(c.weight.strength);
  }
  for (const scene::SegmentComponent& c : object.segments) {
    note(c.weight, "segment");
    capsules.push_back(c.segment);
    capsule_radii.push_back(c.weight.radius);
    capsule_strengths.push_back(c.weight.strength);
    capsule_is_blob.push_back(0);
  }
  for (const scene::BlobCylinderComponent& c : object.blob_cylinders) {
    note(c.weight, "blob cylinder");
    capsules.push_back({c.base, c.apex});
    capsule_radii.push_back(c.weight.radius);
    capsule_strengths.push_back(c.weight.strength);
    capsule_is_blob.push_back(1);
  }
  for (const scene::ArcComponent& c : object.arcs) {
    note(c.weight, "arc");
    arcs.push_back(c.arc);
    arc_radii.push_back(c.weight.radius);
    arc_strengths.push_back(c.weight.strength);
  }
  size_t triangle_count = 0;
  for (const scene::MeshComponent& m : object.meshes) triangle_count += m.triangles.size();
  std::vector<const scene::MeshComponent*> group_meshes;  // parallel to `groups`
  for (const scene::MeshComponent& m : object.meshes) {
    if (m.triangles.empty()) continue;
    note(m.weight, "mesh");
    const auto mesh = uint32_t(&m - object.meshes.data());
    const std::optional<DistinctTriangles> merged = merge_repeated(m.triangles);
    // A lent mesh (lent_triangles.hpp) is taken whole where it is the surface's first and
    // has no repeats, else freed once copied, before the rest of the surface is made.
    std::vector<field::Triangle>* lent = LentTriangles::take(m.triangles);
    const auto release = [&] { std::vector<field::Triangle>().swap(*lent); };
    if (!merged && lent && triangles.empty()) {
      triangles = std::move(*lent);
      release();
      groups.push_back({0, uint32_t(triangles.size()), m.weight.radius, m.weight.strength, mesh});
      group_meshes.push_back(&m);
      continue;
    }
    if (triangles.capacity() < triangle_count) triangles.reserve(triangle_count);
    if (!merged) {
      const auto first = uint32_t(triangles.size());
      triangles.insert(triangles.end(), m.triangles.begin(), m.triangles.end());
      if (lent) release();
      groups.push_back({first, uint32_t(triangles.size()), m.weight.radius, m.weight.strength,
                        mesh});
      group_meshes.push_back(&m);
      continue;
    }
    // Repeated triangles: each distinct one once, in a group per multiplicity k whose strength
    // is k times the mesh's (the same sum). Such groups no longer match the file's triangles
    // one for one, so they build their own hierarchy instead of taking the cache's.
    merged_triangles += m.triangles.size() - merged->size();
    std::vector<uint32_t> multiplicities = merged->multiplicity;
    std::sort(multiplicities.begin(), multiplicities.end());
    multiplicities.erase(std::unique(multiplicities.begin(), multiplicities.end()),
                         multiplicities.end());
    for (const uint32_t k : multiplicities) {
      const auto first = uint32_t(triangles.size());
      for (size_t i = 0; i < merged->size(); ++i) {
        if (merged->multiplicity[i] == k) triangles.push_back(m.triangles[merged->first[i]]);
      }
      groups.push_back({first, uint32_t(triangles.size()), m.weight.radius,
                        k * m.weight.strength, mesh});
      group_meshes.push_back(nullptr);
    }
    if (lent) release();
  }
  if (!std::isfinite(min_radius)) min_radius = 1.0;  // an empty object

  point_count = uint32_t(object.points.size());
  segment_count = uint32_t(object.segments.size());
  capsule_base = uint32_t(sphere_centers.size());
  arc_base = capsule_base + uint32_t(capsules.size());
  triangle_base = arc_base + uint32_t(arcs.size());
  spheres_only = capsules.empty() && arcs.empty() && triangles.empty();
  frames.resize(triangles.size());
  tbb::parallel_for(size_t(0), triangles.size(),
                    [&](size_t i) { frames[i] = field::triangle_frame(triangles[i]); });
  for (size_t i = 0; i < sphere_radii.size(); ++i) {
    const double r2 = sphere_radii[i] * sphere_radii[i];
    sphere_weights.push_back(sphere_strengths[i] / (r2 * r2));
  }

  accel::SupportSources sources;
  sources.sphere_centers = sphere_centers;
  sources.sphere_radii = sphere_radii;
  sources.capsules = capsules;
  sources.capsule_radii = capsule_radii;
  sources.arcs = arcs;
  sources.arc_radii = arc_radii;
  for (const Group& g : groups) {
    const size_t count = g.end_triangle - g.first_triangle;
    sources.triangle_groups.push_back(
        {std::span<const field::Triangle>(triangles).subspan(g.first_triangle, count), g.radius,
         std::span<const field::TriangleFrame>(frames).subspan(g.first_triangle, count)});
  }
  if (cache) take_prebuilt(sources, group_meshes, *cache);
  index = std::make_unique<accel::SupportIndex>(sources);
  gather_in_chunks = expected_supports_per_line() > kChunkedSupportsPerLine;
  min_chunk = kChunkWidths * mean_support_width();
}

// Cauchy's formula: a convex body's mean shadow is a quarter of its surface area, so a random
// line through the bounds crosses about (sum of support areas) / area(bounds) supports. A
// support is the skeleton swept by a ball of radius r, whose area Steiner's formula gives: a
// ball 4 pi r^2, a capsule 2 pi r L + 4 pi r^2, a triangle 2A + pi r P + 4 pi r^2 (perimeter
// P); an arc (not convex) is counted as the capsule of its length.
double ConvolutionSurface::Impl::expected_supports_per_line() const {
  const Vec3 e = index->bounds().extent();
  const double area = 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  double supports = 0.0;
  auto swept = [](double r, double length) { return 2.0 * kPi * r * length + 4.0 * kPi * r * r; };
  for (double r : sphere_radii) supports += swept(r, 0.0);
  for (size_t i = 0; i < capsules.size(); ++i) {
    supports += swept(capsule_radii[i], glm::length(capsules[i].b - capsules[i].a));
  }
  for (size_t i = 0; i < arcs.size(); ++i) {
    supports += swept(arc_radii[i], arcs[i].angle * arcs[i].radius);
  }
  // The triangles' edge lengths and areas from their frames (the same values: no square
  // root per triangle, 3-4 ms of the dragon's start-up).
  for (const Group& g : groups) {
    for (uint32_t i = g.first_triangle; i < g.end_triangle; ++i) {
      const field::TriangleFrame& f = frames[i];
      const double perimeter = f.length[0] + f.length[1] + f.length[2];
      const double twice_area = 2.0 * f.area;
      supports += twice_area + kPi * g.radius * perimeter + 4.0 * kPi * g.radius * g.radius;
    }
  }
  return area > 0.0 ? supports / area : 0.0;
}

// Twice the mean of the supports' half-widths: each primitive's radius plus how far its
// skeleton reaches from its middle (a point's nothing, a segment's half length, a triangle's
// smallest enclosing ball, an arc's circle radius).
double ConvolutionSurface::Impl::mean_support_width() const {
  double sum = 0.0;
  for (double r : sphere_radii) sum += r;
  for (size_t i = 0; i < capsules.size(); ++i) {
    sum += capsule_radii[i] + 0.5 * glm::length(capsules[i].b - capsules[i].a);
  }
  for (size_t i = 0; i < arcs.size(); ++i) sum += arc_radii[i] + arcs[i].radius;
  // The index's balls, made once (the smallest balls cost about 10 ms on 200,000 triangles);
  // floats rounded outwards, so the width is exact to a few parts in 10^7.
  for (const std::vector<accel::BoundingBall>& balls : index->triangle_balls()) {
    for (const accel::BoundingBall& ball : balls) sum += ball.radius;
  }
  const size_t count = sphere_radii.size() + capsules.size() + arcs.size() + triangles.size();
  return count > 0 ? 2.0 * sum / double(count) : 0.0;
}

namespace {
// This class is the quartic kernel's; `kernel cauchy` objects are CauchySurface's.
const scene::ConvolutionObject& require_quartic(const scene::ConvolutionObject& object) {
  if (object.kernel.type != field::KernelType::quartic) {
    throw std::invalid_argument("ConvolutionSurface traces the quartic kernel only; use "
                                "CauchySurface for kernel cauchy");
  }
  return object;
}
}  // namespace

ConvolutionSurface::ConvolutionSurface(const scene::ConvolutionObject& object, SupportCache* cache,
                                       Tracer tracer)
    : impl_(std::make_unique<Impl>(require_quartic(object), cache)) {
  impl_->tracer = tracer;
}
ConvolutionSurface::~ConvolutionSurface() = default;
ConvolutionSurface::ConvolutionSurface(ConvolutionSurface&&) noexcept = default;
ConvolutionSurface& ConvolutionSurface::operator=(ConvolutionSurface&&) noexcept = default;

double ConvolutionSurface::threshold() const { return impl_->threshold; }
Tracer ConvolutionSurface::tracer() const { return impl_->tracer; }
Box3 ConvolutionSurface::bounds() const { return impl_->index->bounds(); }
size_t ConvolutionSurface::primitive_count() const { return impl_->index->size(); }

size_t ConvolutionSurface::merged_triangle_count() const { return impl_->merged_triangles; }

std::vector<Box3> ConvolutionSurface::support_boxes() const {
  const Impl& m = *impl_;
  std::vector<Box3> boxes;
  boxes.reserve(m.index->size());
  for (size_t i = 0; i < m.sphere_centers.size(); ++i) {
    const Vec3 reach(m.sphere_radii[i]);
    boxes.push_back({m.sphere_centers[i] - reach, m.sphere_centers[i] + reach});
  }
  for (size_t i = 0; i < m.capsules.size(); ++i) {
    // Blob cylinders too: a capsule of distance kernels lies within r of its axis segment.
    boxes.push_back(accel::segment_support_box(m.capsules[i], m.capsule_radii[i]));
  }
  for (size_t i = 0; i < m.arcs.size(); ++i) {
    boxes.push_back(accel::arc_support_box(m.arcs[i], m.arc_radii[i]));
  }
  for (const Impl::Group& g : m.groups) {
    for (uint32_t i = g.first_triangle; i < g.end_triangle; ++i) {
      boxes.push_back(accel::triangle_support_box(m.triangles[i], g.radius));
    }
  }
  return boxes;
}

size_t ConvolutionSurface::memory_bytes() const {
  const Impl& m = *impl_;
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return sizeof(Impl) + bytes(m.sphere_centers) + bytes(m.sphere_radii) +
         bytes(m.sphere_strengths) + bytes(m.sphere_weights) + bytes(m.capsules) +
         bytes(m.capsule_radii) + bytes(m.capsule_strengths) + bytes(m.capsule_is_blob) +
         bytes(m.arcs) + bytes(m.arc_radii) + bytes(m.arc_strengths) + bytes(m.triangles) +
         bytes(m.frames) + bytes(m.groups) + m.index->memory_bytes();
}

field::FieldSample ConvolutionSurface::field(const Vec3& p) const {
  thread_local std::vector<uint32_t> ids;
  ids.clear();
  impl_->index->contain(p, ids);
  field::FieldSample sum;
  for (uint32_t id : ids) sum += impl_->sample(id, p);
  return sum;
}

void ConvolutionSurface::component_values(const Vec3& p,
                                          std::vector<ComponentValue>& out) const {
  thread_local std::vector<uint32_t> ids;
  ids.clear();
  impl_->index->contain(p, ids);
  for (uint32_t id : ids) out.push_back({impl_->component(id), impl_->value(id, p)});
}

void ConvolutionSurface::roots(const Ray& ray, double tmin, double tmax, std::vector<double>& out,
                               TraceStats& stats) const {
  if (impl_->tracer == Tracer::reference) return reference_roots(*this, ray, tmin, tmax, out, stats);
  find_roots(*impl_, ray, tmin, tmax, RootMode::all, out, stats);
}

std::optional<SurfaceHit> ConvolutionSurface::first_hit(const Ray& ray, double tmin, double tmax,
                                                        TraceStats& stats) const {
  if (impl_->tracer == Tracer::reference) return reference_first_hit(*this, ray, tmin, tmax, stats);
  thread_local std::vector<double> found;
  found.clear();
  std::optional<Vec3> gradient;
  NearHit near;
  find_roots(*impl_, ray, tmin, tmax, RootMode::first, found, stats, &gradient, nullptr, &near,
             NearHits::find(*impl_));
  if (found.empty()) return std::nullopt;
  if (near.bend >= 0.0) NearHits::remember(*impl_, near);
  if (!gradient) return make_surface_hit(*this, ray, found.front());
  return surface_hit_from_gradient(ray, found.front(), *gradient);
}

void ConvolutionSurface::hits(const Ray& ray, double tmin, double tmax,
                              std::vector<SurfaceHit>& out, TraceStats& stats) const {
  thread_local std::vector<double> found;  // not re-entered: roots() calls no surface
  found.clear();
  roots(ray, tmin, tmax, found, stats);
  for (const double t : found) out.push_back(make_surface_hit(*this, ray, t));
}

bool ConvolutionSurface::occluded(const Ray& ray, double tmin, double tmax,
                                  TraceStats& stats) const {
  thread_local std::vector<double> found;
  found.clear();
  if (impl_->tracer == Tracer::reference) {
    reference_roots(*this, ray, tmin, tmax, found, stats);
    // The contract asks for [tmin, tmax]; filter anyway, so a root just outside never shadows.
    return std::any_of(found.begin(), found.end(), [&](double t) { return t >= tmin && t <= tmax; });
  }
  // A ball left by an earlier shadow ray of the run may settle it (inside_balls.hpp).
  if (InsideBalls::settle(*impl_, ray, tmin, tmax)) {
    ++stats.shadows_settled;
    return true;
  }
  InsideBall inside;
  const bool look = InsideBalls::worth_looking(*impl_);
  find_roots(*impl_, ray, tmin, tmax, RootMode::any, found, stats, nullptr,
             look ? &inside : nullptr, nullptr, NearHits::find(*impl_));
  if (found.empty()) return false;
  InsideBalls::remember(*impl_, look ? &inside : nullptr);
  return true;
}

}  // namespace convray::implicit
