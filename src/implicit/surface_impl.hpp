#pragma once
// Inside ConvolutionSurface: the primitives in flat arrays (numbered as the support index
// numbers them: spheres, capsules, arcs, then triangle groups) and their weighted fields.
// Private to src/implicit.
#include <algorithm>
#include <memory>
#include <vector>

#include "accel/support_index.hpp"
#include "field/arc.hpp"
#include "field/blob.hpp"
#include "field/point.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
#include "implicit/convolution_surface.hpp"

namespace convray::implicit {

struct ConvolutionSurface::Impl {
  // Spheres: skeleton points and POV-Ray blob spheres share the kernel s (1 - d^2/R^2)^2.
  std::vector<Vec3> sphere_centers;
  std::vector<double> sphere_radii, sphere_strengths;
  std::vector<double> sphere_weights;  // strength / radius^4: the sphere sweep's k
  // Capsules: convolution segments (integrals) and blob cylinders (distance kernels).
  std::vector<field::Segment> capsules;
  std::vector<double> capsule_radii, capsule_strengths;
  std::vector<uint8_t> capsule_is_blob;
  std::vector<field::Arc> arcs;
  std::vector<double> arc_radii, arc_strengths;
  // Triangles of every mesh, one group (radius, strength) per mesh component.
  std::vector<field::Triangle> triangles;
  std::vector<field::TriangleFrame> frames;  // one per triangle, for the per-ray batches
  struct Group {
    uint32_t first_triangle, end_triangle;
    double radius, strength;
    uint32_t mesh = 0;  // the mesh component's index in ConvolutionObject::meshes
  };
  std::vector<Group> groups;
  // Triangles left out as exact repeats of another of their mesh (repeated_triangles.hpp):
  // their multiplicity is in their group's strength.
  size_t merged_triangles = 0;

  uint32_t capsule_base = 0, arc_base = 0, triangle_base = 0;
  // Spheres are the points, then the blob spheres; capsules the segments, then the blob
  // cylinders: these say where the second kind starts (for component()).
  uint32_t point_count = 0, segment_count = 0;
  double threshold = 1.0;
  double min_radius = 1.0;  // smallest support radius: the length scale of tolerances
  bool nonnegative = true;  // no component has a negative strength: F only grows with each
  // Distinct for every surface made in this process (thread-local caches key on it: a freed
  // surface's address may be reused).
  uint64_t serial = 0;
  // Nothing but spheres: every ray goes straight to the sphere sweep (sphere_sweep.hpp).
  bool spheres_only = false;
  // First-root searches gather the ray in chunks (surface_roots.cpp), where a line through the
  // bounds crosses enough supports that stopping early beats the extra traversals and the
  // supports that straddle a chunk's end, gathered twice.
  bool gather_in_chunks = false;
  double min_chunk = 0.0;  // the shortest chunk (kChunkWidths mean support widths)
  double mean_support_width() const;
  Tracer tracer = Tracer::fast;
  std::unique_ptr<accel::SupportIndex> index;  // built last, over the arrays above

  Impl(const scene::ConvolutionObject& object, SupportCache* cache);
  // How many supports a random line through the bounds crosses, on average.
  double expected_supports_per_line() const;

  const Group& group_of(uint32_t triangle) const {
    auto it = std::upper_bound(groups.begin(), groups.end(), triangle,
                               [](uint32_t t, const Group& g) { return t < g.end_triangle; });
    return *it;
  }

  // The component primitive `id` belongs to.
  scene::ComponentRef component(uint32_t id) const {
    if (id < capsule_base) {
      return id < point_count ? scene::ComponentRef{scene::ComponentKind::point, id}
                              : scene::ComponentRef{scene::ComponentKind::blob_sphere, id - point_count};
    }
    if (id < arc_base) {
      const uint32_t i = id - capsule_base;
      return i < segment_count ? scene::ComponentRef{scene::ComponentKind::segment, i}
                               : scene::ComponentRef{scene::ComponentKind::blob_cylinder, i - segment_count};
    }
    if (id < triangle_base) return {scene::ComponentKind::arc, id - arc_base};
    return {scene::ComponentKind::mesh, group_of(id - triangle_base).mesh};
  }

  // Weighted field of primitive `id` (the support index's numbering) at p.
  double value(uint32_t id, const Vec3& p) const {
    if (id < capsule_base) {
      return sphere_strengths[id] * field::point_value(p, sphere_centers[id], sphere_radii[id]);
    }
    if (id < arc_base) {
      const uint32_t i = id - capsule_base;
      if (capsule_is_blob[i]) {
        return field::blob_cylinder_field(p, capsules[i].a, capsules[i].b, capsule_radii[i],
                                          capsule_strengths[i]).value;
      }
      return capsule_strengths[i] * field::segment_value(p, capsules[i], capsule_radii[i]);
    }
    if (id < triangle_base) {
      const uint32_t i = id - arc_base;
      return arc_strengths[i] * field::arc_value(p, arcs[i], arc_radii[i]);
    }
    const uint32_t i = id - triangle_base;
    const Group& g = group_of(i);
    return g.strength * field::triangle_value(p, triangles[i], g.radius);
  }

  // How far primitive `id`'s weighted field may bend down anywhere, along any direction: the
  // kernel's Hessian has no eigenvalue below -4 / R^2 (radially -4 (1 - 3 r^2/R^2) / R^2,
  // across -4 (1 - r^2/R^2) / R^2; a blob cylinder's kernel of the distance to its axis adds
  // its slope times the distance's convex bend, no lower), so the field's is no lower than
  // -4 / R^2 times |strength| times the most skeleton within reach of one point: the
  // triangle's area, at most the disk of radius R; the segment's or arc's length, a segment's
  // at most 2 R.
  double bend_bound(uint32_t id) const {
    if (id < capsule_base) {
      const double r = sphere_radii[id];
      return std::abs(sphere_strengths[id]) * 4.0 / (r * r);
    }
    if (id < arc_base) {
      const uint32_t i = id - capsule_base;
      const double r = capsule_radii[i];
      const double reach =
          capsule_is_blob[i] ? 1.0 : std::min(glm::length(capsules[i].b - capsules[i].a), 2.0 * r);
      return std::abs(capsule_strengths[i]) * reach * 4.0 / (r * r);
    }
    if (id < triangle_base) {
      const uint32_t i = id - arc_base;
      const double length = arcs[i].radius * std::min(arcs[i].angle, 2.0 * kPi);
      return std::abs(arc_strengths[i]) * length * 4.0 / (arc_radii[i] * arc_radii[i]);
    }
    const uint32_t i = id - triangle_base;
    const Group& g = group_of(i);
    const double area = std::min(frames[i].area, kPi * g.radius * g.radius);
    return std::abs(g.strength) * area * 4.0 / (g.radius * g.radius);
  }

  field::FieldSample sample(uint32_t id, const Vec3& p) const {
    if (id < capsule_base) {
      return field::point_field(p, sphere_centers[id], sphere_radii[id]) * sphere_strengths[id];
    }
    if (id < arc_base) {
      const uint32_t i = id - capsule_base;
      if (capsule_is_blob[i]) {
        return field::blob_cylinder_field(p, capsules[i].a, capsules[i].b, capsule_radii[i],
                                          capsule_strengths[i]);
      }
      return field::segment_field(p, capsules[i], capsule_radii[i]) * capsule_strengths[i];
    }
    if (id < triangle_base) {
      const uint32_t i = id - arc_base;
      return field::arc_field(p, arcs[i], arc_radii[i]) * arc_strengths[i];
    }
    const uint32_t i = id - triangle_base;
    const Group& g = group_of(i);
    return field::triangle_field(p, triangles[i], g.radius) * g.strength;
  }
};

}  // namespace convray::implicit
