#include "reference/reference_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "reference/quadrature.hpp"

namespace convray::reference {
namespace {

// Everything below works in units of R (R = 1): a field of dimension length^k is R^k times
// the unit-radius field at p / R, and its gradient R^(k-1) times the unit-radius gradient.

// Angle of t reduced to [0, 2 pi).
double wrap_angle(double t) {
  t = std::fmod(t, 2.0 * kPi);
  return t < 0.0 ? t + 2.0 * kPi : t;
}

double cross2(const Vec2& u, const Vec2& v) { return u.x * v.y - u.y * v.x; }

}  // namespace

ReferenceSample reference_point(const Vec3& p, const Vec3& center, double radius) {
  const Vec3 offset = (p - center) / radius;
  const double inside = 1.0 - glm::dot(offset, offset);
  if (inside <= 0.0) return {};
  return {inside * inside, (-4.0 / radius) * inside * offset};
}

ReferenceSample reference_segment(const Vec3& p, const Vec3& a, const Vec3& b, double radius) {
  const Vec3 start = (a - p) / radius;  // Q(a) - P
  const Vec3 span = (b - a) / radius;
  const double length = glm::length(span);
  if (length == 0.0) return {};
  const Vec3 direction = span / length;

  // Integrate in tau, the position along the line measured from the foot of the perpendicular
  // from P: Q - P = across + tau direction. Near the support |tau| <= 1, so the quadrature nodes
  // there carry no rounding from the segment's length, however long it is.
  const double along = glm::dot(start, direction);
  const Vec3 across = start - along * direction;
  const double half_chord_sq = 1.0 - glm::dot(across, across);
  std::vector<double> breakpoints;
  if (half_chord_sq > 0.0) breakpoints = {-std::sqrt(half_chord_sq), std::sqrt(half_chord_sq)};

  // Value (1 - |Q-P|^2)^2 and gradient -4 (1 - |Q-P|^2) (P - Q), per unit length.
  const auto integrand = [&](double tau) -> Vec4 {
    const Vec3 q = across + tau * direction;
    const double inside = 1.0 - glm::dot(q, q);
    if (inside <= 0.0) return Vec4(0.0);
    return Vec4(inside * inside, 4.0 * inside * q);
  };
  const QuadratureResult r =
      integrate_adaptive(integrand, along, along + length, breakpoints, kReferenceTolerance);
  return {radius * r.integral.x, Vec3(r.integral.y, r.integral.z, r.integral.w),
          radius * r.error_estimate, r.converged};
}

ReferenceSample reference_arc(const Vec3& p, const Vec3& center, const Vec3& axis,
                              const Vec3& start, double arc_radius, double angle, double radius) {
  const Vec3 c = (center - p) / radius;
  const double a = arc_radius / radius;
  const Vec3 quarter = glm::cross(axis, start);

  // t0: the parameter of the arc point nearest to P (any, when P is on the axis). With
  // tau = t - t0: |Q - P|^2 = d^2 + 4 a rho sin^2(tau/2), d = |Q(t0) - P|, rho = distance from P's
  // projection on the arc's plane to the centre. So the support is |tau| < spread (mod 2 pi).
  const double cs = glm::dot(c, start);
  const double cq = glm::dot(c, quarter);
  const double rho = std::hypot(cs, cq);
  const double t0 = rho > 0.0 ? std::atan2(-cq, -cs) : 0.0;
  const Vec3 nearest = c + a * (std::cos(t0) * start + std::sin(t0) * quarter);
  const double nearest_sq = glm::dot(nearest, nearest);
  if (nearest_sq >= 1.0 || a == 0.0) return {};
  const double sin_half_spread_sq = (1.0 - nearest_sq) / (4.0 * a * rho);
  const double spread = sin_half_spread_sq < 1.0 ? 2.0 * std::asin(std::sqrt(sin_half_spread_sq)) : kPi;

  // Points are taken as chords from Q(t0): Q(t) - Q(t0) = 2 a sin(tau/2) (cos m quarter -
  // sin m start), m = t0 + tau/2; so arcs much larger than R lose no precision. Arc length
  // element: a dt.
  const auto integrand = [&](double tau) -> Vec4 {
    const double m = t0 + 0.5 * tau;
    const Vec3 q = nearest + (2.0 * a * std::sin(0.5 * tau)) * (std::cos(m) * quarter - std::sin(m) * start);
    const double inside = 1.0 - glm::dot(q, q);
    if (inside <= 0.0) return Vec4(0.0);
    return a * Vec4(inside * inside, 4.0 * inside * q);
  };

  // Split [0, angle] where it enters or leaves the support; integrate each piece in tau measured
  // from the copy t0 + 2 pi k nearest to the piece, so that nodes near the support are small
  // numbers (an arc that nearly closes may meet the support at both of its ends).
  std::vector<double> cuts = {0.0, angle};
  if (spread < kPi) {
    for (double edge : {t0 - spread, t0 + spread}) {
      const double t = wrap_angle(edge);
      if (t > 0.0 && t < angle) cuts.push_back(t);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  const double support[] = {-spread, spread};
  const double piece_tolerance = kReferenceTolerance / static_cast<double>(cuts.size() - 1);
  ReferenceSample sample;
  Vec4 total(0.0);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double middle = 0.5 * (cuts[i] + cuts[i + 1]);
    const double origin = t0 + 2.0 * kPi * std::round((middle - t0) / (2.0 * kPi));
    const QuadratureResult r = integrate_adaptive(integrand, cuts[i] - origin, cuts[i + 1] - origin, support,
                                                  piece_tolerance);
    total += r.integral;
    sample.error_estimate += radius * r.error_estimate;
    sample.converged = sample.converged && r.converged;
  }
  sample.value = radius * total.x;
  sample.gradient = Vec3(total.y, total.z, total.w);
  return sample;
}

ReferenceSample reference_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                   double radius) {
  // Zero area decided on the inputs themselves: scaling by 1/R could round collinear points
  // off their line.
  if (glm::cross(b - a, c - a) == Vec3(0.0)) return {};
  const std::array<Vec3, 3> vertex = {(a - p) / radius, (b - p) / radius, (c - p) / radius};
  const Vec3 area_normal = glm::cross(vertex[1] - vertex[0], vertex[2] - vertex[0]);
  const double twice_area = glm::length(area_normal);
  if (twice_area == 0.0) return {};
  const Vec3 normal = area_normal / twice_area;

  // P = O + h normal, with O the projection of P (the origin here) on the plane.
  const double h =
      -(glm::dot(normal, vertex[0]) + glm::dot(normal, vertex[1]) + glm::dot(normal, vertex[2])) /
      3.0;
  const double r0_sq = (1.0 - std::abs(h)) * (1.0 + std::abs(h));
  if (r0_sq <= 0.0) return {};
  const double r0 = std::sqrt(r0_sq);

  // In-plane frame (e1, e2, normal), right-handed, so a-b-c runs counter-clockwise.
  int longest = 0;
  for (int i = 1; i < 3; ++i)
    if (glm::length(vertex[(i + 1) % 3] - vertex[i]) >
        glm::length(vertex[(longest + 1) % 3] - vertex[longest]))
      longest = i;
  const Vec3 e1 = glm::normalize(vertex[(longest + 1) % 3] - vertex[longest]);
  const Vec3 e2 = glm::cross(normal, e1);
  std::array<Vec2, 3> x;  // vertices relative to O
  for (int i = 0; i < 3; ++i) x[i] = {glm::dot(vertex[i], e1), glm::dot(vertex[i], e2)};
  if (cross2(x[1] - x[0], x[2] - x[0]) <= 0.0) return {};  // flat at this precision

  // Edge i (x[i] -> x[i+1]) as a half-plane m.x >= offset, m the unit inward normal.
  std::array<Vec2, 3> inward;
  std::array<double, 3> offset;
  for (int i = 0; i < 3; ++i) {
    const Vec2 edge = x[(i + 1) % 3] - x[i];
    inward[i] = Vec2(-edge.y, edge.x) / glm::length(edge);
    offset[i] = glm::dot(inward[i], x[i]);
  }

  // Kinks of the angular integrand: vertex directions, and directions of the points where
  // the circle of radius r0 crosses an edge.
  std::vector<double> breakpoints;
  for (int i = 0; i < 3; ++i) {
    if (x[i] != Vec2(0.0)) breakpoints.push_back(std::atan2(x[i].y, x[i].x));
    // From the foot of the perpendicular: no cancellation for edges much longer than r0.
    const Vec2 edge = x[(i + 1) % 3] - x[i];
    const double foot = -glm::dot(x[i], edge) / glm::dot(edge, edge);
    const double distance = std::abs(offset[i]);
    if (distance > r0) continue;
    const double half_chord = std::sqrt((r0 - distance) * (r0 + distance)) / glm::length(edge);
    for (double s : {foot - half_chord, foot + half_chord}) {
      if (s < 0.0 || s > 1.0) continue;
      const Vec2 crossing = x[i] + s * edge;
      if (crossing != Vec2(0.0)) breakpoints.push_back(std::atan2(crossing.y, crossing.x));
    }
  }
  // When O is at a small distance d from an edge's line, the ray meets that line at
  // d / sin(phi), phi the angle to the line: near phi = 0 and pi the integrand changes on every
  // scale from d / r0 up. Breakpoints graded geometrically there let the adaptive rule see it.
  for (int i = 0; i < 3; ++i) {
    const double distance = std::abs(offset[i]);
    if (distance == 0.0 || distance > 0.5 * r0) continue;
    const Vec2 edge = x[(i + 1) % 3] - x[i];
    const double along = std::atan2(edge.y, edge.x);
    for (double step = std::max(distance / r0, 1e-16); step < 1.0; step *= 2.0)
      for (double direction : {along, along + kPi})
        for (double side : {-1.0, 1.0})
          breakpoints.push_back(std::remainder(direction + side * step, 2.0 * kPi));
  }

  // Angular integrand: radial integrals over the ray's span inside triangle and disk.
  // Components: value, gradient along e1, e2, normal (unit-radius field).
  const GaussLegendreRule rule = gauss_legendre(4);
  const auto integrand = [&](double theta) -> Vec4 {
    const Vec2 u(std::cos(theta), std::sin(theta));
    double lo = 0.0;
    double hi = r0;
    for (int i = 0; i < 3; ++i) {
      const double slope = glm::dot(inward[i], u);
      if (slope > 0.0) {
        lo = std::max(lo, offset[i] / slope);
      } else if (slope < 0.0) {
        hi = std::min(hi, offset[i] / slope);
      } else if (offset[i] > 0.0) {
        return Vec4(0.0);
      }
    }
    if (!(hi > lo)) return Vec4(0.0);
    const double mid = 0.5 * (lo + hi);
    const double half = 0.5 * (hi - lo);
    double value = 0.0, normal_part = 0.0, planar_part = 0.0;
    for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
      const double rho = mid + half * rule.nodes[k];
      const double w = half * rule.weights[k] * rho;  // area element rho d(rho)
      const double inside = r0_sq - rho * rho;        // 1 - |P-Q|^2
      value += w * inside * inside;
      normal_part += w * inside;
      planar_part += w * inside * rho;
    }
    // -4 (1 - |P-Q|^2) (P - Q) with P - Q = h normal - rho u.
    return {value, 4.0 * planar_part * u.x, 4.0 * planar_part * u.y, -4.0 * h * normal_part};
  };

  const double lo = -kPi;
  const QuadratureResult r =
      integrate_adaptive(integrand, lo, lo + 2.0 * kPi, breakpoints, kReferenceTolerance);
  const Vec3 gradient = r.integral.y * e1 + r.integral.z * e2 + r.integral.w * normal;
  return {radius * radius * r.integral.x, radius * gradient, radius * radius * r.error_estimate,
          r.converged};
}

}  // namespace convray::reference
