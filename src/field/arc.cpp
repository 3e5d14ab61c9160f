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

// Along the arc, with ψ = t − φ measured from the direction φ of p's projection on the arc's
// plane, the squared distance is r² = q² + B (1 − cos ψ), where q² = (ρ − a)² + z² is the
// squared distance to the arc's circle and B = 2aρ. So the kernel is (κ − μ c)² with
// c = 1 − cos ψ, κ = 1 − q²/R² and μ = B/R². Written around the closest point like this,
// nothing cancels when the arc is much larger than R (μ huge, support |ψ| <= β tiny); the
// textbook form (k + m cos ψ)² loses every digit there. The gradient is the same kind of
// integral: ∇F = −(4a/R²) ∫ (κ − μ c)(p − q(ψ)) dψ with p − q = rel − a (cos ψ e_r + sin ψ e_t).
struct ArcFrame {
  Vec3 radial;           // e_r: unit in-plane direction towards p (any, if p is on the axis)
  Vec3 tangential;       // e_t = axis x e_r
  double rho = 0.0;      // in-plane distance of p from the axis
  double height = 0.0;   // z: signed distance of p from the arc's plane
  double phi = 0.0;      // angle of e_r from arc.start
  double kappa = 0.0, mu = 0.0;
  double half_width = 0.0;  // β
  bool reached = false;
};

ArcFrame arc_frame(const Vec3& p, const Arc& arc, double radius) {
  ArcFrame f;
  const Vec3 e1 = arc.start;
  const Vec3 e2 = glm::cross(arc.axis, arc.start);
  const Vec3 rel = p - arc.center;
  const double x = glm::dot(rel, e1);
  const double y = glm::dot(rel, e2);
  f.height = glm::dot(rel, arc.axis);
  f.rho = std::hypot(x, y);
  f.phi = f.rho > 0.0 ? std::atan2(y, x) : 0.0;
  f.radial = std::cos(f.phi) * e1 + std::sin(f.phi) * e2;
  f.tangential = glm::cross(arc.axis, f.radial);
  const double r2 = radius * radius;
  const double gap = f.rho - arc.radius;
  f.kappa = 1.0 - (gap * gap + f.height * f.height) / r2;
  f.mu = 2.0 * arc.radius * f.rho / r2;
  if (!(f.kappa > 0.0)) return f;
  // Support: μ c <= κ, i.e. 2 sin²(ψ/2) <= κ/μ.
  const double half_chord = f.mu > 0.0 ? std::sqrt(0.5 * f.kappa / f.mu) : 2.0;
  f.half_width = half_chord < 1.0 ? 2.0 * std::asin(half_chord) : kPi;
  f.reached = true;
  return f;
}

// Antiderivatives of c = 1 − cos ψ and c², exact to rounding even for tiny ψ, where the
// closed forms ψ − sin ψ and 3ψ/2 − 2 sin ψ + sin 2ψ/4 cancel catastrophically.
double integral_of_c(double psi) {
  if (std::abs(psi) >= 0.5) return psi - std::sin(psi);
  // Σ_{n>=1} (−1)^(n+1) ψ^(2n+1)/(2n+1)!
  const double p2 = psi * psi;
  double term = psi * p2 / 6.0, sum = 0.0;
  for (int n = 1; n < 12; ++n) {
    sum += term;
    term *= -p2 / ((2.0 * n + 2.0) * (2.0 * n + 3.0));
  }
  return sum;
}

double integral_of_c_squared(double psi) {
  if (std::abs(psi) >= 0.5) return 1.5 * psi - 2.0 * std::sin(psi) + 0.25 * std::sin(2.0 * psi);
  // (1 − cos ψ)² = Σ_{n>=2} (−1)^n (2^(2n−1) − 2) ψ^(2n)/(2n)!, integrated term by term.
  const double p2 = psi * psi;
  double power = psi * p2 * p2 / 24.0;  // ψ^(2n+1)/(2n)! at n = 2
  double two_pow = 8.0;                 // 2^(2n−1) at n = 2
  double sum = 0.0;
  for (int n = 2; n < 14; ++n) {
    const double sign = (n % 2 == 0) ? 1.0 : -1.0;
    sum += sign * (two_pow - 2.0) * power / (2.0 * n + 1.0);
    power *= p2 / ((2.0 * n + 1.0) * (2.0 * n + 2.0));
    two_pow *= 4.0;
  }
  return sum;
}

// Integrals over ψ of 1, c, c², and of c' = sin ψ weighted by 1 and c (as c and c²/2).
struct ArcMoments {
  double one = 0.0, c = 0.0, c2 = 0.0, sin = 0.0, sin_c = 0.0;

  // lo, hi within [−π, π] (pieces are shifted there first: the integrand is 2π-periodic).
  void add_interval(double lo, double hi) {
    const auto c_of = [](double psi) {
      const double s = std::sin(0.5 * psi);
      return 2.0 * s * s;
    };
    one += hi - lo;
    c += integral_of_c(hi) - integral_of_c(lo);
    c2 += integral_of_c_squared(hi) - integral_of_c_squared(lo);
    const double c_hi = c_of(hi), c_lo = c_of(lo);
    sin += c_hi - c_lo;                                // ∫ sin ψ = 1 − cos ψ
    sin_c += 0.5 * (c_hi * c_hi - c_lo * c_lo);        // ∫ (1 − cos ψ) sin ψ = c²/2
  }
};

// Integrates over the arc's ψ-range [−φ, angle − φ] intersected with the support copies
// [2πj − β, 2πj + β], j = −1, 0, 1 (the ψ-range lies within [−π, 3π]).
ArcMoments arc_moments(const ArcFrame& f, const Arc& arc) {
  ArcMoments mom;
  const double begin = -f.phi;
  const double end = arc.angle - f.phi;
  for (int j = -1; j <= 1; ++j) {
    const double shift = 2.0 * kPi * j;
    const double lo = std::max(begin, shift - f.half_width);
    const double hi = std::min(end, shift + f.half_width);
    if (lo < hi) mom.add_interval(lo - shift, hi - shift);
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
  const ArcMoments m = arc_moments(f, arc);
  const double a = arc.radius;
  const double kappa = f.kappa, mu = f.mu;
  // ∫ (κ − μc)² dψ, times the arc-length factor a.
  const double value = a * (kappa * kappa * m.one - 2.0 * kappa * mu * m.c + mu * mu * m.c2);
  const double i0 = kappa * m.one - mu * m.c;      // ∫ (κ − μc)
  const double j1 = kappa * m.c - mu * m.c2;       // ∫ (κ − μc) c
  const double is = kappa * m.sin - mu * m.sin_c;  // ∫ (κ − μc) sin ψ
  // Radial part ρ i0 − a ∫(κ − μc) cos ψ, rewritten as (ρ − a) i0 + a j1 so nothing cancels.
  const double radial = (f.rho - a) * i0 + a * j1;
  const double r2 = radius * radius;
  const Vec3 gradient = (-4.0 * a / r2) *
                        (radial * f.radial - a * is * f.tangential + f.height * i0 * arc.axis);
  return {value, gradient};
}

}  // namespace convray::field
