#include "implicit/cauchy_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/bracket_refine.hpp"
#include "field/cauchy.hpp"
#include "implicit/repeated_triangles.hpp"

namespace convray::implicit {

namespace {

// The march's smallest step, as a fraction of the smaller of the kernel's width 1/s and the
// smallest truncation margin: far below any feature of the surface, large enough that a ray
// grazing the surface takes a bounded number of steps.
constexpr double kMinStepFraction = 1e-3;
// Bounds on F - T this close to zero (times T) are re-evaluated rather than trusted: the
// shifts by entering and leaving primitives accumulate rounding.
constexpr double kBoundsRounding = 1e-12;
// How far before tmin a sweep starts (relative to 1 + |tmin|).
constexpr double kStartBefore = 1e-9;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// Distance from p to the nearest point of the box (0 inside).
double box_distance(const Box3& box, const Vec3& p) {
  const Vec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), Vec3(0.0));
  return glm::length(outside);
}

Box3 grown(Box3 box, double margin) {
  box.lo -= Vec3(margin);
  box.hi += Vec3(margin);
  return box;
}

}  // namespace

CauchySurface::CauchySurface(const scene::ConvolutionObject& object)
    : s_(object.kernel.sharpness), threshold_(object.threshold) {
  require(object.arcs.empty(),
          "kernel cauchy supports points, segments and triangles (meshes), not arcs");
  require(object.blob_spheres.empty() && object.blob_cylinders.empty(),
          "kernel cauchy supports points, segments and triangles (meshes), not blob components");
  require(s_ > 0.0 && std::isfinite(s_), "kernel cauchy: the sharpness s must be positive");
  require(threshold_ > 0.0 && std::isfinite(threshold_), "convolution threshold must be positive");
  std::vector<Box3> boxes;
  double smallest_margin = 1.0 / s_;
  const double no_cap = std::numeric_limits<double>::infinity();
  const auto add = [&](CauchyPrimitive primitive, const scene::Weight& weight, int corners, double measure,
                       double cap) {
    require(weight.radius > 0.0 && std::isfinite(weight.radius),
            "kernel cauchy: the truncation radius must be positive");
    for (int k = 0; k < corners; ++k) primitive.extent.extend(primitive.v[k]);
    primitive.strength = weight.strength;
    primitive.weighted_measure = std::abs(weight.strength) * measure;
    primitive.slope_cap = std::abs(weight.strength) * cap;
    boxes.push_back(grown(primitive.extent, weight.radius));
    primitives_.push_back(primitive);
    smallest_margin = std::min(smallest_margin, weight.radius);
  };
  for (size_t m = 0; m < object.meshes.size(); ++m) {
    const scene::MeshComponent& mesh = object.meshes[m];
    // Exactly repeated triangles (issue 17) have the same field and the same truncation box:
    // each distinct one once, with its multiplicity times the mesh's strength.
    const std::optional<DistinctTriangles> merged = merge_repeated(mesh.triangles);
    const size_t distinct = merged ? merged->size() : mesh.triangles.size();
    if (merged) merged_triangles_ += mesh.triangles.size() - distinct;
    for (size_t i = 0; i < distinct; ++i) {
      const field::Triangle& t = mesh.triangles[merged ? merged->first[i] : i];
      const double area = 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
      if (!(area > 0.0)) continue;  // zero field: nothing to truncate
      CauchyPrimitive p;
      p.shape = CauchyPrimitive::Shape::triangle;
      p.v[0] = t.a, p.v[1] = t.b, p.v[2] = t.c;
      p.component = {scene::ComponentKind::mesh, uint32_t(m)};
      scene::Weight weight = mesh.weight;
      if (merged) weight.strength *= double(merged->multiplicity[i]);
      add(p, weight, 3, area, kPi * kPi / (2.0 * s_));
    }
  }
  for (size_t i = 0; i < object.segments.size(); ++i) {
    const field::Segment& seg = object.segments[i].segment;
    CauchyPrimitive p;
    p.shape = CauchyPrimitive::Shape::segment;
    p.v[0] = seg.a, p.v[1] = seg.b;
    p.component = {scene::ComponentKind::segment, uint32_t(i)};
    add(p, object.segments[i].weight, 2, glm::length(seg.b - seg.a), no_cap);
  }
  for (size_t i = 0; i < object.points.size(); ++i) {
    CauchyPrimitive p;
    p.v[0] = object.points[i].center;
    p.component = {scene::ComponentKind::point, uint32_t(i)};
    add(p, object.points[i].weight, 1, 1.0, no_cap);
  }
  min_step_ = kMinStepFraction * smallest_margin;
  bvh_ = BoxBvh(std::move(boxes));
}

size_t CauchySurface::memory_bytes() const {
  return sizeof(*this) + primitives_.capacity() * sizeof(CauchyPrimitive) + bvh_.memory_bytes();
}

field::FieldSample CauchySurface::primitive_field(size_t i, const Vec3& p) const {
  const CauchyPrimitive& q = primitives_[i];
  switch (q.shape) {
    case CauchyPrimitive::Shape::triangle:
      return field::cauchy_triangle_field(p, {q.v[0], q.v[1], q.v[2]}, s_) * q.strength;
    case CauchyPrimitive::Shape::segment:
      return field::cauchy_segment_field(p, {q.v[0], q.v[1]}, s_) * q.strength;
    case CauchyPrimitive::Shape::point:
      break;
  }
  return field::cauchy_point_field(p, q.v[0], s_) * q.strength;
}

double CauchySurface::primitive_value(size_t i, const Vec3& p) const {
  const CauchyPrimitive& q = primitives_[i];
  switch (q.shape) {
    case CauchyPrimitive::Shape::triangle:
      return q.strength * field::cauchy_triangle_value(p, {q.v[0], q.v[1], q.v[2]}, s_);
    case CauchyPrimitive::Shape::segment:
      return q.strength * field::cauchy_segment_value(p, {q.v[0], q.v[1]}, s_);
    case CauchyPrimitive::Shape::point:
      break;
  }
  return q.strength * field::cauchy_point_value(p, q.v[0], s_);
}

field::FieldSample CauchySurface::field(const Vec3& p) const {
  thread_local std::vector<uint32_t> ids;
  ids.clear();
  bvh_.contain(p, ids);
  field::FieldSample sum;
  for (const uint32_t id : ids) sum += primitive_field(id, p);
  return sum;
}

void CauchySurface::component_values(const Vec3& p, std::vector<ComponentValue>& out) const {
  thread_local std::vector<uint32_t> ids;
  ids.clear();
  bvh_.contain(p, ids);
  for (const uint32_t id : ids) {
    out.push_back({primitives_[id].component, primitive_value(id, p)});
  }
}

// ---- tracing ------------------------------------------------------------------------------

// One ray's sweep: the pieces between consecutive box entries and exits, each with the set of
// primitives active on it, marched and refined; `visit(hit)` returns false to stop the sweep.
struct CauchySurface::Tracer {
  const CauchySurface& surface;
  const Ray& ray;
  TraceStats& stats;
  bool want_normals = false;
  std::vector<uint32_t>& active;
  bool has_previous = false;     // a piece before the current one (none at tmin)
  bool previous_inside = false;  // F >= T at the end of that piece
  uint32_t last_event_box = 0;   // a box entered or left where the current piece starts
  // Bounds on F - T over the active set at the sweep's current t: exact values where they
  // were computed, widened by slope x length over pieces that were skipped, shifted by the
  // exact field of each primitive entering or leaving. Far from the surface they prove the
  // sign without evaluating every active primitive.
  double low = 0.0, high = 0.0;

  // Whether the bounds decide inside or outside (with a margin for their rounding).
  bool sign_known() const {
    const double tiny = kBoundsRounding * surface.threshold_;
    return low > tiny || high < -tiny;
  }
  // Makes the bounds exact at t unless they already decide the sign.
  void settle(double t) {
    if (!sign_known()) low = high = excess(t);
  }
  bool inside() const { return low >= 0.0; }
  // A primitive entering (+1) or leaving (-1) the active set at t.
  void shift(uint32_t id, double t, double sign) {
    const double value = sign * surface.primitive_value(id, ray.at(t));
    ++stats.field_evaluations;
    low += value;
    high += value;
  }

  // F - T at ray.at(t), over the active primitives only (the field's smooth extension).
  double excess(double t) const {
    const Vec3 p = ray.at(t);
    double sum = 0.0;
    for (const uint32_t id : active) sum += surface.primitive_value(id, p);
    stats.field_evaluations += active.size();
    return sum - surface.threshold_;
  }

  // The bound on |grad F| over the ball of radius `reach` around p: each active primitive is
  // at least (distance to its box - reach) from every point there, so its slope is bounded
  // by cauchy_kernel_slope_beyond that distance (and by its cap). Falls as `reach` shrinks.
  double slope_within(const Vec3& p, double reach) const {
    double slope = 0.0;
    for (const uint32_t id : active) {
      const CauchyPrimitive& q = surface.primitives_[id];
      const double gap = std::max(box_distance(q.extent, p) - reach, 0.0);
      slope += std::min(q.weighted_measure * field::cauchy_kernel_slope_beyond(gap, surface.s_),
                        q.slope_cap);
    }
    return slope;
  }

  // A step from ray.at(t) that cannot jump over a crossing: a reach r is safe when
  // slope_within(r) r <= |f|. The rest of the piece if that is safe; else |f| / slope_within
  // (rest), safe because the slope only falls as the reach shrinks, then lengthened once to
  // |f| / slope_within(that) if that is safe too. Never below min_step.
  double safe_step(double t, double f, double rest) const {
    const Vec3 p = ray.at(t);
    const double speed = glm::length(ray.direction), margin = std::abs(f);
    const double whole = rest * speed;
    const double slope = slope_within(p, whole);
    if (slope * whole <= margin) return rest;
    double reach = margin / slope;
    const double longer = margin / slope_within(p, reach);
    if (longer > reach && slope_within(p, longer) * longer <= margin) reach = longer;
    return std::max(reach / speed, surface.min_step_);
  }

  // A sign change of F - T in [t0, t1] (f0, f1 its values), refined on the exact field by the
  // tracers' one bracketed refiner, to a few ulps.
  double refine(double t0, double t1, double f0, double f1) const {
    return refine_bracket(t0, t1, f0, f1, [&](double t) { return excess(t); });
  }

  SurfaceHit smooth_hit(double t) const {
    if (!want_normals) return SurfaceHit{t, ray.at(t), -ray.direction};
    Vec3 gradient(0.0);
    const Vec3 p = ray.at(t);
    for (const uint32_t id : active) gradient += surface.primitive_field(id, p).gradient;
    // Normalised without overflow or underflow at extreme strengths (1e200, 1e-160).
    return surface_hit_from_gradient(ray, t, gradient);
  }

  // A jump of F - T across a box face at t: the face's normal, out of the solid.
  SurfaceHit face_hit(double t, bool entering_solid) const {
    SurfaceHit hit{t, ray.at(t), -ray.direction};
    const Box3& box = surface.bvh_.boxes()[last_event_box];
    int axis = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double gap =
          std::min(std::abs(hit.point[k] - box.lo[k]), std::abs(hit.point[k] - box.hi[k]));
      if (gap < nearest) nearest = gap, axis = k;
    }
    if (ray.direction[axis] != 0.0) {
      const double along = ray.direction[axis] > 0.0 ? 1.0 : -1.0;
      hit.normal = Vec3(0.0);
      hit.normal[axis] = entering_solid ? -along : along;
    }
    return hit;
  }

  // The piece [a, b] with the current active set: a jump at a across the faces just crossed,
  // then, unless the bounds prove F - T keeps its sign all along, a march on the exact field.
  template <class Visit>
  bool piece(double a, double b, Visit& visit) {
    settle(a);
    if (has_previous && inside() != previous_inside) {
      ++stats.roots;
      if (!visit(face_hit(a, inside()))) return false;
    }
    has_previous = true;
    if (!active.empty()) {
      const double length = (b - a) * glm::length(ray.direction);
      const double change = slope_within(ray.at(a), length) * length;
      if (low - change > 0.0 || high + change < 0.0) {
        low -= change;  // no crossing inside: carry the bounds over to b
        high += change;
      } else if (!march(a, b, visit)) {
        return false;
      }
    }
    settle(b);
    previous_inside = inside();
    return true;
  }

  // Steps through [a, b] on the exact field, refining every sign change; leaves the bounds
  // exact at b.
  template <class Visit>
  bool march(double a, double b, Visit& visit) {
    double t = a, f = low == high ? low : excess(a);
    while (t < b) {
      const double step = safe_step(t, f, b - t);
      double next = step >= b - t ? b : t + step;
      if (!(next > t)) next = b;  // a step below rounding at this t
      const double f_next = excess(next);
      if ((f >= 0.0) != (f_next >= 0.0)) {
        ++stats.roots;
        if (!visit(smooth_hit(refine(t, next, f, f_next)))) return false;
      }
      t = next;
      f = f_next;
    }
    low = high = f;
    return true;
  }
};

namespace {

struct BoxEvent {
  double t = 0.0;
  uint32_t id = 0;
  bool enter = false;
};

}  // namespace

template <class Visit>
void CauchySurface::trace(const Ray& ray, double tmin, double tmax, TraceStats& stats,
                          bool want_normals, Visit&& visit) const {
  ++stats.rays;
  if (!(tmin <= tmax)) return;
  thread_local std::vector<BoxBvh::Span> spans;
  thread_local std::vector<BoxEvent> events;
  thread_local std::vector<uint32_t> active;
  spans.clear();
  events.clear();
  active.clear();
  // The sweep starts a hair before tmin, so that a box whose face lies at tmin is entered
  // from a piece before it and a jump there is seen; nothing before tmin is reported.
  const double start = tmin - kStartBefore * (1.0 + std::abs(tmin));
  bvh_.crossed(ray, start, tmax, spans);
  if (spans.empty()) return;
  stats.primitives += spans.size();
  for (const BoxBvh::Span& span : spans) {
    if (!(span.t1 > span.t0)) continue;  // grazes an edge or a corner: no length inside
    events.push_back({span.t0, span.id, true});
    events.push_back({span.t1, span.id, false});
  }
  std::sort(events.begin(), events.end(),
            [](const BoxEvent& x, const BoxEvent& y) { return x.t < y.t; });
  const auto report = [&](const SurfaceHit& hit) { return hit.t < tmin || visit(hit); };
  Tracer tracer{*this, ray, stats, want_normals, active};
  tracer.low = tracer.high = -threshold_;  // nothing active yet: F = 0
  double current = start;
  for (size_t k = 0; k < events.size();) {
    const double t = events[k].t;
    if (t > current) {
      if (!tracer.piece(current, t, report)) return;
      current = t;
    }
    // Every box entered or left at t changes the active set before the next piece.
    for (; k < events.size() && events[k].t == t; ++k) {
      const BoxEvent& e = events[k];
      if (e.enter) {
        active.push_back(e.id);
        tracer.shift(e.id, t, 1.0);
      } else {
        const auto it = std::find(active.begin(), active.end(), e.id);
        *it = active.back();
        active.pop_back();
        tracer.shift(e.id, t, -1.0);
      }
      tracer.last_event_box = e.id;
    }
  }
  if (tmax > current) tracer.piece(current, tmax, report);
}

void CauchySurface::hits(const Ray& ray, double tmin, double tmax, std::vector<SurfaceHit>& out,
                         TraceStats& stats) const {
  trace(ray, tmin, tmax, stats, true, [&](const SurfaceHit& hit) {
    out.push_back(hit);
    return true;
  });
}

void CauchySurface::roots(const Ray& ray, double tmin, double tmax, std::vector<double>& out,
                          TraceStats& stats) const {
  trace(ray, tmin, tmax, stats, false, [&](const SurfaceHit& hit) {
    out.push_back(hit.t);
    return true;
  });
}

std::optional<SurfaceHit> CauchySurface::first_hit(const Ray& ray, double tmin, double tmax,
                                                   TraceStats& stats) const {
  std::optional<SurfaceHit> first;
  trace(ray, tmin, tmax, stats, true, [&](const SurfaceHit& hit) {
    first = hit;
    return false;
  });
  return first;
}

bool CauchySurface::occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const {
  bool any = false;
  trace(ray, tmin, tmax, stats, false, [&](const SurfaceHit&) {
    any = true;
    return false;
  });
  return any;
}

// ---- the slow exact twin ------------------------------------------------------------------

double cauchy_brute_force_value(const CauchySurface& surface, const Vec3& p) {
  const auto& boxes = surface.support_boxes();
  double sum = 0.0;
  for (size_t i = 0; i < boxes.size(); ++i) {
    const Box3& b = boxes[i];
    const bool inside = p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y &&
                        p.z >= b.lo.z && p.z <= b.hi.z;
    if (inside) sum += surface.primitive_value(i, p);
  }
  return sum;
}

void cauchy_reference_roots(const CauchySurface& surface, const Ray& ray, double tmin, double tmax,
                            double step, std::vector<double>& out) {
  const auto excess = [&](double t) {
    return cauchy_brute_force_value(surface, ray.at(t)) - surface.threshold();
  };
  const long count = std::max(1L, long(std::ceil((tmax - tmin) / step)));
  double t0 = tmin;
  bool inside0 = excess(t0) >= 0.0;
  for (long k = 1; k <= count; ++k) {
    const double t1 = k == count ? tmax : tmin + (tmax - tmin) * double(k) / double(count);
    const bool inside1 = excess(t1) >= 0.0;
    if (inside1 != inside0) {
      // inside(t0) == inside0 != inside(t1)
      out.push_back(bisect_to_rounding(
          t0, t1, [&](double t) { return (excess(t) >= 0.0) == inside0; }));
    }
    t0 = t1;
    inside0 = inside1;
  }
}

}  // namespace convray::implicit
