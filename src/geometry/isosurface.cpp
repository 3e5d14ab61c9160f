#include "geometry/isosurface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/box.hpp"
#include "core/bracket_refine.hpp"

namespace convray::geometry {

namespace {

// A bound on the work of one ray: steps of at least `accuracy` across the container, and never
// more than this many (a container 10^6 times the accuracy is drawn coarser rather than hang).
constexpr int kMaxSteps = 1 << 20;

}  // namespace

IsosurfaceShape::IsosurfaceShape(const scene::Isosurface& iso, SurfaceInfoPtr surface)
    : iso_(iso), surface_(std::move(surface)) {}

Box3 IsosurfaceShape::bounds() const {
  if (iso_.sphere_container) {
    return Box3{iso_.center - Vec3(iso_.radius), iso_.center + Vec3(iso_.radius)};
  }
  return Box3{iso_.box_lo, iso_.box_hi};
}

bool IsosurfaceShape::in_container(const Vec3& p) const {
  if (iso_.sphere_container) return glm::length(p - iso_.center) <= iso_.radius;
  return p.x >= iso_.box_lo.x && p.y >= iso_.box_lo.y && p.z >= iso_.box_lo.z &&
         p.x <= iso_.box_hi.x && p.y <= iso_.box_hi.y && p.z <= iso_.box_hi.z;
}

bool IsosurfaceShape::inside(const Vec3& p) const { return in_container(p) && value(p) < 0.0; }

// The whole stretch of the line inside the container (not limited to the query's interval).
bool IsosurfaceShape::clip_to_container(const Ray& ray, double& enter, double& leave) const {
  enter = -std::numeric_limits<double>::infinity();
  leave = std::numeric_limits<double>::infinity();
  if (!iso_.sphere_container) return clip_to_box(ray, Box3{iso_.box_lo, iso_.box_hi}, enter, leave);
  const Vec3 oc = ray.origin - iso_.center;
  const double b = glm::dot(oc, ray.direction);
  const double c = glm::dot(oc, oc) - iso_.radius * iso_.radius;
  const double discriminant = b * b - c;
  if (!(discriminant > 0.0)) return false;
  const double root = std::sqrt(discriminant);
  enter = -b - root;
  leave = -b + root;
  return true;
}

Vec3 IsosurfaceShape::container_normal(const Vec3& p) const {
  if (iso_.sphere_container) return glm::normalize(p - iso_.center);
  const Vec3 center = 0.5 * (iso_.box_lo + iso_.box_hi);
  const Vec3 half = 0.5 * (iso_.box_hi - iso_.box_lo);
  const Vec3 d = (p - center) / glm::max(half, Vec3(1e-300));
  const Vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return Vec3(d.x < 0.0 ? -1.0 : 1.0, 0.0, 0.0);
  if (a.y >= a.z) return Vec3(0.0, d.y < 0.0 ? -1.0 : 1.0, 0.0);
  return Vec3(0.0, 0.0, d.z < 0.0 ? -1.0 : 1.0);
}

Vec3 IsosurfaceShape::outward_normal(const Vec3& p) const {
  const double h = iso_.accuracy > 0.0 ? iso_.accuracy : 1e-3;
  const double f = value(p);
  const Vec3 g(value(p + Vec3(h, 0, 0)) - f, value(p + Vec3(0, h, 0)) - f,
               value(p + Vec3(0, 0, h)) - f);
  const double length = glm::length(g);
  if (std::isfinite(length) && length > 0.0) return g / length;
  return Vec3(0.0, 1.0, 0.0);  // a flat spot of f: any direction is as good
}

double IsosurfaceShape::povray_crossing(double root, double from, double to) const {
  const double length = to - from;
  if (!(iso_.accuracy > 0.0) || !std::isfinite(length) || !(length > 0.0)) return root;
  double piece = length;
  while (piece > iso_.accuracy) piece *= 0.5;
  return std::min(to, from + std::ceil((root - from) / piece) * piece);
}

void IsosurfaceShape::march(const Ray& ray, double tmin, double tmax, bool first_only,
                            std::vector<Crossing>& out) const {
  double enter = 0.0, leave = 0.0;
  if (!clip_to_container(ray, enter, leave)) return;
  const double a = std::max(enter, tmin), b = std::min(leave, tmax);
  if (!(a < b)) return;
  const auto g = [&](double t) { return value(ray.at(t)); };
  // The container's surface where the solid reaches it.
  if (!iso_.open && enter > tmin && g(enter) < 0.0) {
    add_crossing(enter, container_normal(ray.at(enter)), surface_.get(), tmin, tmax, out);
    if (first_only) return;
  }
  const double gradient = iso_.max_gradient > 0.0 ? iso_.max_gradient : 1.1;
  const double least_step = std::max(iso_.accuracy, (b - a) / kMaxSteps);
  // POV-Ray's minimum depth: no crossing is reported within 5 accuracies of the ray's start.
  // A ray that starts inside the solid (a shadow or reflected ray leaving a crossing, which
  // lies past the root), or whose first crossing would lie that close, is searched from
  // there instead, and the pieces are halved from there (measured as above: trace() from
  // points inside and outside the solid, at three accuracies).
  const double min_depth = 5.0 * std::max(iso_.accuracy, 0.0);
  double t = a, g0 = g(t);
  double pieces_from = a;  // where POV-Ray's halving starts
  if (a < min_depth && g0 < 0.0 && min_depth < b) {
    t = pieces_from = min_depth;
    g0 = g(t);
  }
  while (t < b) {
    const double step = std::isfinite(g0) ? std::max(std::abs(g0) / gradient, least_step)
                                          : least_step;
    const double t1 = std::min(t + step, b);
    const double g1 = g(t1);
    if ((g0 < 0.0) != (g1 < 0.0) && std::isfinite(g0) && std::isfinite(g1)) {
      double root = povray_crossing(refine_bracket(t, t1, g0, g1, g), pieces_from, leave);
      if (root < min_depth && pieces_from < min_depth) {
        // Too shallow: the search starts again at the minimum depth (as POV-Ray's does).
        if (!(min_depth < b)) break;
        t = pieces_from = min_depth;
        g0 = g(t);
        continue;
      }
      add_crossing(root, outward_normal(ray.at(root)), surface_.get(), tmin, tmax, out);
      if (first_only && !out.empty()) return;
    }
    t = t1;
    g0 = g1;
  }
  if (!iso_.open && leave < tmax && g(leave) < 0.0) {
    add_crossing(leave, container_normal(ray.at(leave)), surface_.get(), tmin, tmax, out);
  }
}

void IsosurfaceShape::crossings(const Ray& ray, double tmin, double tmax,
                                std::vector<Crossing>& out, TraceStats& /*stats*/) const {
  march(ray, tmin, tmax, false, out);
}

std::optional<Crossing> IsosurfaceShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                        TraceStats& /*stats*/) const {
  std::vector<Crossing> found;
  march(ray, tmin, tmax, true, found);
  if (found.empty()) return std::nullopt;
  return found.front();
}

}  // namespace convray::geometry
