#include "reference/cauchy_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "reference/quadrature.hpp"

namespace convray::reference {
namespace {

// Value and gradient of the kernel at P for a skeleton point Q, as four numbers.
Vec4 kernel_terms(const Vec3& p, const Vec3& q, double s) {
  const Vec3 rel = p - q;
  const double k = 1.0 / (1.0 + s * s * glm::dot(rel, rel));
  return Vec4(k * k, (-4.0 * s * s * k * k * k) * rel);
}

// Relative tolerance of the quadratures, times the primitive's natural scale.
constexpr double kTolerance = 1e-13;

}  // namespace

ReferenceSample reference_cauchy_point(const Vec3& p, const Vec3& center, double s) {
  const Vec4 t = kernel_terms(p, center, s);
  return {t.x, Vec3(t.y, t.z, t.w)};
}

ReferenceSample reference_cauchy_segment(const Vec3& p, const Vec3& a, const Vec3& b, double s) {
  const double length = glm::length(b - a);
  if (length == 0.0) return {};
  const Vec3 direction = (b - a) / length;
  const double foot = glm::dot(p - a, direction);
  // Where the kernel changes fastest: around the foot, at the kernel's width 1/s.
  const std::array<double, 3> breakpoints = {foot - 1.0 / s, foot, foot + 1.0 / s};
  const auto integrand = [&](double x) { return kernel_terms(p, a + x * direction, s); };
  const QuadratureResult r =
      integrate_adaptive(integrand, 0.0, length, breakpoints, kTolerance / s);
  return {r.integral.x, Vec3(r.integral.y, r.integral.z, r.integral.w), r.error_estimate,
          r.converged};
}

ReferenceSample reference_cauchy_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c, double s) {
  const Vec3 e1 = b - a, e2 = c - a;
  const double jacobian = glm::length(glm::cross(e1, e2));  // twice the area
  if (jacobian == 0.0) return {};
  const double e2_sq = glm::dot(e2, e2);
  bool converged = true;
  const auto inner = [&](double u) -> Vec4 {
    const Vec3 start = a + u * e1;
    const double top = 1.0 - u;
    if (top <= 0.0) return Vec4(0.0);
    const double nearest = glm::dot(p - start, e2) / e2_sq;  // v of the point nearest to p
    const double width = 1.0 / (s * std::sqrt(e2_sq));       // kernel width, in v
    const std::array<double, 3> breakpoints = {nearest - width, nearest, nearest + width};
    const auto f = [&](double v) { return kernel_terms(p, start + v * e2, s); };
    const QuadratureResult r =
        integrate_adaptive(f, 0.0, top, breakpoints, kTolerance / (s * s * jacobian));
    converged = converged && r.converged;
    return r.integral;
  };
  // The outer breakpoints: where u puts the line nearest to p's foot (the peak of the inner
  // integral), at the kernel's width around it.
  const Vec3 n = glm::cross(e1, e2) / jacobian;
  const Vec3 m = glm::cross(n, e2);  // in-plane, orthogonal to e2: measures u
  const double u_peak = glm::dot(p - a, m) / glm::dot(e1, m);
  const double u_width = 1.0 / (s * std::abs(glm::dot(e1, glm::normalize(m))));
  const std::array<double, 3> breakpoints = {u_peak - u_width, u_peak, u_peak + u_width};
  const QuadratureResult r =
      integrate_adaptive(inner, 0.0, 1.0, breakpoints, kTolerance / (s * s * jacobian));
  const Vec4 total = jacobian * r.integral;
  return {total.x, Vec3(total.y, total.z, total.w), jacobian * (r.error_estimate),
          converged && r.converged};
}

}  // namespace convray::reference
