#include "geometry/torus.hpp"

#include <cmath>

#include "core/box.hpp"
#include "core/bracket_refine.hpp"
#include "core/polynomial_roots.hpp"

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

// The quartic's coefficients lose digits (a torus seen from afar); the distance-like function
// does not. The quartic is that function times (sqrt(x^2 + z^2) + major)^2 + y^2 - minor^2,
// positive where major > minor, so the two change sign together and each bracket of the
// quartic's roots is refined on the distance-like function itself; where their signs at the
// bracket's ends disagree (a spindle torus, or ends that rounding sets apart), on the quartic.
double TorusShape::root_in(const Ray& ray, double enter, std::span<const double> quartic,
                           const RootBracket& bracket) const {
  if (!bracket.exact()) {
    const auto along = [&](double t) { return implicit_value(ray.at(t)); };
    const double lo = enter + bracket.lo, hi = enter + bracket.hi;
    const double f_lo = along(lo), f_hi = along(hi);
    if (f_lo != 0.0 && f_hi != 0.0 && (f_lo < 0.0) != (f_hi < 0.0) &&
        (f_lo < 0.0) == (bracket.f_lo < 0.0)) {
      return refine_bracket(lo, hi, f_lo, f_hi, along);
    }
  }
  return enter + refine_polynomial_root(quartic, bracket);
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
  RootBracket brackets[4];
  const int count = polynomial_brackets(c, 0.0, leave - enter, brackets);
  for (int i = 0; i < count; ++i) {  // disjoint brackets, ascending: so are their roots
    const double t = root_in(ray, enter, c, brackets[i]);
    add_crossing(t, outward_normal(ray.at(t)), surface_.get(), tmin, tmax, out);
  }
}

bool TorusShape::inside(const Vec3& p) const { return implicit_value(p) < 0.0; }

}  // namespace convray::geometry
