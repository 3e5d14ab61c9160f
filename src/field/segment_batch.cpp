#include "field/segment_batch.hpp"

#include <algorithm>
#include <cmath>

namespace convray::field {

SegmentBatch::SegmentBatch(std::span<const Segment> segments) {
  for (const Segment& s : segments) {
    const Vec3 axis = s.b - s.a;
    const double length = glm::length(axis);
    // Zero-length segments integrate to 0: a zero direction and length give exactly that.
    const Vec3 u = length > 0.0 && std::isfinite(length) ? axis / length : Vec3(0.0);
    ax_.push_back(s.a.x), ay_.push_back(s.a.y), az_.push_back(s.a.z);
    ux_.push_back(u.x), uy_.push_back(u.y), uz_.push_back(u.z);
    length_.push_back(length > 0.0 && std::isfinite(length) ? length : 0.0);
  }
}

// Same mathematics as segment.cpp: with s measured from the foot of p on the line,
// the kernel is (a - s²/R²)², a = 1 - q²/R², antiderivative G(s) = a² s - 2a s³/(3R²) + s⁵/(5R⁴),
// support |s| <= w = R √a. Gradient: a moves with p as -2 q⃗/R², an end point bound as -u;
// the ±w bounds are constants (zero kernel, zero slope there).
template <bool kGradient>
FieldSample SegmentBatch::evaluate(const Vec3& p, double radius) const {
  const double r2 = radius * radius, inv_r2 = 1.0 / r2;
  const double *ax = ax_.data(), *ay = ay_.data(), *az = az_.data();
  const double *ux = ux_.data(), *uy = uy_.data(), *uz = uz_.data(), *len = length_.data();
  double sum = 0.0, gx = 0.0, gy = 0.0, gz = 0.0;
  const size_t n = size();
#pragma omp simd reduction(+ : sum, gx, gy, gz)
  for (size_t i = 0; i < n; ++i) {
    const double rx = p.x - ax[i], ry = p.y - ay[i], rz = p.z - az[i];
    const double h = rx * ux[i] + ry * uy[i] + rz * uz[i];
    const double ox = rx - h * ux[i], oy = ry - h * uy[i], oz = rz - h * uz[i];
    const double a = 1.0 - (ox * ox + oy * oy + oz * oz) * inv_r2;
    const double w = radius * std::sqrt(a > 0.0 ? a : 0.0);
    const double begin = -h, end = len[i] - h;
    const double lo = std::max(begin, -w), hi = std::min(end, w);
    const bool has = (a > 0.0) & (lo < hi) & (len[i] > 0.0);
    const auto antiderivative = [&](double s) {
      const double s2 = s * s;
      return s * (a * a + s2 * (-(2.0 / 3.0) * a * inv_r2 + 0.2 * s2 * inv_r2 * inv_r2));
    };
    sum += has ? antiderivative(hi) - antiderivative(lo) : 0.0;
    if constexpr (kGradient) {
      // ∂G/∂a = 2a s - 2 s³/(3R²); the kernel at a moving end point bound is (a - s²/R²)².
      const auto d_da = [&](double s) { return s * (2.0 * a - (2.0 / 3.0) * s * s * inv_r2); };
      const auto kernel = [&](double s) {
        const double k = a - s * s * inv_r2;
        return k * k;
      };
      const double da = has ? d_da(hi) - d_da(lo) : 0.0;
      const double d_end = (has & (end <= w)) ? kernel(hi) : 0.0;
      const double d_begin = (has & (begin >= -w)) ? -kernel(lo) : 0.0;
      const double ds = d_end + d_begin;  // both end bounds move with p as -u
      gx += da * (-2.0 * inv_r2) * ox - ds * ux[i];
      gy += da * (-2.0 * inv_r2) * oy - ds * uy[i];
      gz += da * (-2.0 * inv_r2) * oz - ds * uz[i];
    }
  }
  return {sum, {gx, gy, gz}};
}

double SegmentBatch::value(const Vec3& p, double radius) const {
  return evaluate<false>(p, radius).value;
}

FieldSample SegmentBatch::field(const Vec3& p, double radius) const {
  return evaluate<true>(p, radius);
}

PointBatch::PointBatch(std::span<const Vec3> centers) {
  for (const Vec3& c : centers) x_.push_back(c.x), y_.push_back(c.y), z_.push_back(c.z);
}

double PointBatch::value(const Vec3& p, double radius) const {
  const double inv_r2 = 1.0 / (radius * radius);
  const double *x = x_.data(), *y = y_.data(), *z = z_.data();
  double sum = 0.0;
  const size_t n = size();
#pragma omp simd reduction(+ : sum)
  for (size_t i = 0; i < n; ++i) {
    const double dx = p.x - x[i], dy = p.y - y[i], dz = p.z - z[i];
    const double k = 1.0 - (dx * dx + dy * dy + dz * dz) * inv_r2;
    sum += k > 0.0 ? k * k : 0.0;
  }
  return sum;
}

FieldSample PointBatch::field(const Vec3& p, double radius) const {
  const double inv_r2 = 1.0 / (radius * radius);
  const double *x = x_.data(), *y = y_.data(), *z = z_.data();
  double sum = 0.0, gx = 0.0, gy = 0.0, gz = 0.0;
  const size_t n = size();
#pragma omp simd reduction(+ : sum, gx, gy, gz)
  for (size_t i = 0; i < n; ++i) {
    const double dx = p.x - x[i], dy = p.y - y[i], dz = p.z - z[i];
    const double k0 = 1.0 - (dx * dx + dy * dy + dz * dz) * inv_r2;
    const double k = k0 > 0.0 ? k0 : 0.0;
    sum += k * k;
    const double g = -4.0 * k * inv_r2;  // d/dp (1 - d²/R²)² = -4 (1 - d²/R²) (p - c)/R²
    gx += g * dx, gy += g * dy, gz += g * dz;
  }
  return {sum, {gx, gy, gz}};
}

}  // namespace convray::field
