#include "geometry/torus.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"
#include "geometry/polynomial.hpp"

namespace convray::geometry {

TorusShape::TorusShape(double major, double minor, SurfaceInfoPtr surface)
    : major_(major), minor_(minor), surface_(std::move(surface)) {}

Box3 TorusShape::bounds() const {
  const double reach = major_ + minor_;
  return Box3{Vec3(-reach, -minor_, -reach), Vec3(reach, minor_, reach)};
}

double TorusShape::implicit_value(const Vec3& p) const {
  const double from_ring = std::sqrt(p.x * p.x + p.z * p.z) - major_;
  return from_ring * from_ring + p.y * p.y - minor_ * minor_;
}

Vec3 TorusShape::outward_normal(const Vec3& p) const {
  // From the nearest point of the core circle towards p.
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  const double scale = rho > 0.0 ? (rho - major_) / rho : 0.0;
  const Vec3 away(p.x * scale, p.y, p.z * scale);
  const double length = glm::length(away);
  return length > 0.0 ? away / length : Vec3(0.0, 1.0, 0.0);
}

double TorusShape::polish(const Ray& ray, double t) const {
  // Newton on the distance-like function, kept only while it improves the residual.
  double best = t, best_residual = std::abs(implicit_value(ray.at(t)));
  for (int step = 0; step < 3 && best_residual > 0.0; ++step) {
    const Vec3 p = ray.at(best);
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    if (rho == 0.0) break;
    const double rho_slope = (p.x * ray.direction.x + p.z * ray.direction.z) / rho;
    const double slope = 2.0 * (rho - major_) * rho_slope + 2.0 * p.y * ray.direction.y;
    if (slope == 0.0) break;
    const double next = best - implicit_value(p) / slope;
    const double residual = std::abs(implicit_value(ray.at(next)));
    if (!(residual < best_residual)) break;
    best = next;
    best_residual = residual;
  }
  return best;
}

void TorusShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                           TraceStats& /*stats*/) const {
  // The span of the ray inside the (slightly grown) box holds every root.
  Box3 box = bounds();
  const double margin = 1e-9 * (major_ + minor_);
  box.lo -= margin;
  box.hi += margin;
  double enter = tmin, leave = tmax;
  if (!clip_to_box(ray, box, enter, leave)) return;
  // Compute the quartic's coefficients in s = t - enter, about a point near the torus.
  const Vec3 o = ray.at(enter), d = ray.direction;
  const double R2 = major_ * major_;
  const double b = glm::dot(o, d);
  const double k = glm::dot(o, o) + R2 - minor_ * minor_;
  const double d_plane = d.x * d.x + d.z * d.z;
  const double c[5] = {
      k * k - 4.0 * R2 * (o.x * o.x + o.z * o.z),
      4.0 * b * k - 8.0 * R2 * (o.x * d.x + o.z * d.z),
      4.0 * b * b + 2.0 * k - 4.0 * R2 * d_plane,
      4.0 * b,
      1.0,
  };
  double roots[4];
  const int count = polynomial_roots(c, 0.0, leave - enter, roots);
  for (int i = 0; i < count; ++i) roots[i] = polish(ray, enter + roots[i]);
  // Polishing may swap two nearly equal roots: restore the order (insertion sort).
  for (int i = 1; i < count; ++i) {
    for (int j = i; j > 0 && roots[j] < roots[j - 1]; --j) std::swap(roots[j], roots[j - 1]);
  }
  for (int i = 0; i < count; ++i) {
    add_crossing(roots[i], outward_normal(ray.at(roots[i])), surface_.get(), tmin, tmax, out);
  }
}

bool TorusShape::inside(const Vec3& p) const { return implicit_value(p) < 0.0; }

}  // namespace convray::geometry
