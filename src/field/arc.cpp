#include "field/arc.hpp"

#include <algorithm>
#include <cmath>

namespace convray::field {

Vec3 Arc::point_at(double t) const {
  return center + radius * (std::cos(t) * start + std::sin(t) * glm::cross(axis, start));
}

bool arc_through(const Vec3& first, const Vec3& through, const Vec3& last, Arc& out) {
  const Vec3 u = through - first;
  const Vec3 v = last - first;
  const Vec3 w = glm::cross(u, v);
  const double w2 = glm::dot(w, w);
  // Collinear (or coincident) points have no circle through them.
  if (!(w2 > 1e-24 * glm::dot(u, u) * glm::dot(v, v))) return false;
  // Circumcentre relative to `first`.
  const Vec3 to_center =
      (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u)) / (2.0 * w2);
  out.center = first + to_center;
  out.radius = glm::length(to_center);
  out.axis = w / std::sqrt(w2);  // first -> through -> last turns counterclockwise about it
  out.start = -to_center / out.radius;
  const Vec3 e2 = glm::cross(out.axis, out.start);
  const Vec3 to_last = last - out.center;
  double angle = std::atan2(glm::dot(to_last, e2), glm::dot(to_last, out.start));
  if (angle <= 0.0) angle += 2.0 * kPi;
  out.angle = angle;
  return true;
}

namespace {

// Along the arc, with ψ = t - φ measured from the direction φ of p's projection on the arc's
// plane, the squared distance is r^2(ψ) = A - B cos ψ, so the kernel is (k + m cos ψ)^2 with
// k = 1 - A/R^2 and m = B/R^2: trigonometric polynomials with closed-form integrals. The
// support is cos ψ >= (A - R^2)/B, an interval |ψ| <= β around ψ = 0 (mod 2π). The gradient
// is the same kind of integral: ∇F = -(4/R^2) ∫ (k + m cos ψ)(p - q(ψ)) ds, with
// p - q = rel - a (cos ψ e_r + sin ψ e_t).
struct ArcFrame {
  Vec3 rel;            // p - centre
  Vec3 radial;         // e_r: unit in-plane direction towards p (any, if p is on the axis)
  Vec3 tangential;     // e_t = axis x e_r
  double phi = 0.0;    // angle of e_r from arc.start
  double k = 0.0, m = 0.0;
  double half_width = 0.0;  // β; 0 when p is out of reach
  bool reached = false;
};

ArcFrame arc_frame(const Vec3& p, const Arc& arc, double radius) {
  ArcFrame f;
  const Vec3 e1 = arc.start;
  const Vec3 e2 = glm::cross(arc.axis, arc.start);
  f.rel = p - arc.center;
  const double x = glm::dot(f.rel, e1);
  const double y = glm::dot(f.rel, e2);
  const double rho = std::hypot(x, y);
  f.phi = rho > 0.0 ? std::atan2(y, x) : 0.0;
  f.radial = std::cos(f.phi) * e1 + std::sin(f.phi) * e2;
  f.tangential = glm::cross(arc.axis, f.radial);
  const double r2 = radius * radius;
  const double big_a = glm::dot(f.rel, f.rel) + arc.radius * arc.radius;
  const double big_b = 2.0 * arc.radius * rho;
  f.k = 1.0 - big_a / r2;
  f.m = big_b / r2;
  if (big_b > 0.0) {
    const double cos_limit = (big_a - r2) / big_b;
    if (cos_limit >= 1.0) return f;
    f.half_width = cos_limit <= -1.0 ? kPi : std::acos(cos_limit);
  } else {
    if (big_a >= r2) return f;
    f.half_width = kPi;
  }
  f.reached = true;
  return f;
}

// Antiderivatives in ψ of cos^i sin^j products used below.
struct ArcMoments {
  double psi = 0.0, sin = 0.0, cos = 0.0, cos2 = 0.0, sincos = 0.0;

  void add_interval(double lo, double hi) {
    psi += hi - lo;
    sin += std::sin(hi) - std::sin(lo);
    cos += std::cos(hi) - std::cos(lo);
    // ∫cos^2 = ψ/2 + sin 2ψ/4,  ∫sin cos = sin^2/2
    cos2 += 0.5 * (hi - lo) + 0.25 * (std::sin(2.0 * hi) - std::sin(2.0 * lo));
    sincos += 0.5 * (std::sin(hi) * std::sin(hi) - std::sin(lo) * std::sin(lo));
  }
};

// Integrates over the arc's ψ-range [-φ, angle - φ] intersected with the support copies
// [2πj - β, 2πj + β], j = -1, 0, 1 (the ψ-range lies within [-π, 3π]).
ArcMoments arc_moments(const ArcFrame& f, const Arc& arc) {
  ArcMoments mom;
  const double begin = -f.phi;
  const double end = arc.angle - f.phi;
  for (int j = -1; j <= 1; ++j) {
    const double lo = std::max(begin, 2.0 * kPi * j - f.half_width);
    const double hi = std::min(end, 2.0 * kPi * j + f.half_width);
    if (lo < hi) mom.add_interval(lo, hi);
  }
  return mom;
}

}  // namespace

double arc_value(const Vec3& p, const Arc& arc, double radius) {
  return arc_field(p, arc, radius).value;
}

FieldSample arc_field(const Vec3& p, const Arc& arc, double radius) {
  const ArcFrame f = arc_frame(p, arc, radius);
  if (!f.reached) return {};
  const ArcMoments mom = arc_moments(f, arc);
  const double a = arc.radius;
  // ∫ (k + m cos ψ)^2 dψ, times the arc-length factor a.
  const double value = a * (f.k * f.k * mom.psi + 2.0 * f.k * f.m * mom.sin + f.m * f.m * mom.cos2);
  const double i0 = f.k * mom.psi + f.m * mom.sin;        // ∫ (k + m c)
  const double ic = f.k * mom.sin + f.m * mom.cos2;       // ∫ (k + m c) c
  const double is = -f.k * mom.cos + f.m * mom.sincos;    // ∫ (k + m c) s
  const double r2 = radius * radius;
  const Vec3 gradient =
      (-4.0 * a / r2) * (i0 * f.rel - a * (ic * f.radial + is * f.tangential));
  return {value, gradient};
}

}  // namespace convray::field
