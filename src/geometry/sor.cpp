#include "geometry/sor.hpp"

#include <algorithm>
#include <cmath>

#include "core/polynomial_roots.hpp"

namespace convray::geometry {

namespace {

// The slope d(r^2)/dh at point j from its neighbours.
double slope_at(const std::vector<Vec2>& p, size_t j) {
  return 2.0 * p[j].x * (p[j + 1].x - p[j - 1].x) / (p[j + 1].y - p[j - 1].y);
}

// The largest value of the cubic sum c[k] t^k on [0, 1]: at an end or where it turns.
double cubic_max(const std::array<double, 4>& c) {
  double best = std::max(c[0], c[0] + c[1] + c[2] + c[3]);
  double turns[2];
  const int n = quadratic_roots(3.0 * c[3], c[2], c[1], turns);
  for (int k = 0; k < n; ++k) {
    if (turns[k] > 0.0 && turns[k] < 1.0) {
      best = std::max(best, evaluate_polynomial(c, turns[k]));
    }
  }
  return best;
}

// The coefficients of sum c[k] (t0 + t1 s)^k in s (Horner on polynomials).
std::array<double, 4> composed(const std::array<double, 4>& c, double t0, double t1) {
  std::array<double, 4> r{c[3], 0.0, 0.0, 0.0};
  for (int k = 2; k >= 0; --k) {
    std::array<double, 4> next{};
    for (int j = 0; j < 3; ++j) {
      next[size_t(j)] += r[size_t(j)] * t0;
      next[size_t(j) + 1] += r[size_t(j)] * t1;
    }
    next[0] += c[size_t(k)];
    r = next;
  }
  return r;
}

}  // namespace

SorShape::SorShape(const std::vector<Vec2>& p, bool open, SurfaceInfoPtr surface)
    : open_(open), surface_(std::move(surface)) {
  max_radius_ = 0.0;
  for (size_t i = 1; i + 2 < p.size(); ++i) {
    Segment s;
    s.h0 = p[i].y;
    s.length = p[i + 1].y - p[i].y;
    const double w0 = p[i].x * p[i].x, w1 = p[i + 1].x * p[i + 1].x;
    const double m0 = s.length * slope_at(p, i), m1 = s.length * slope_at(p, i + 1);
    // The Hermite basis expanded in powers of t.
    s.c = {w0, m0, -3.0 * w0 - 2.0 * m0 + 3.0 * w1 - m1, 2.0 * w0 + m0 - 2.0 * w1 + m1};
    max_radius_ = std::max(max_radius_, std::sqrt(std::max(0.0, cubic_max(s.c))));
    segments_.push_back(s);
  }
  bottom_ = p[1].y;
  top_ = p[p.size() - 2].y;
  bottom_radius_ = p[1].x;
  top_radius_ = p[p.size() - 2].x;
}

Box3 SorShape::bounds() const {
  return Box3{Vec3(-max_radius_, bottom_, -max_radius_), Vec3(max_radius_, top_, max_radius_)};
}

Box3 SorShape::inside_bounds() const { return open_ ? Box3{} : bounds(); }

const SorShape::Segment& SorShape::segment_at(double y) const {
  const auto after = std::upper_bound(segments_.begin(), segments_.end(), y,
                                      [](double v, const Segment& s) { return v < s.h0; });
  return after == segments_.begin() ? segments_.front() : *(after - 1);
}

double SorShape::radius_squared(double y) const {
  const Segment& s = segment_at(y);
  return evaluate_polynomial(s.c, (y - s.h0) / s.length);
}

bool SorShape::inside(const Vec3& p) const {
  if (open_ || !(p.y > bottom_ && p.y < top_)) return false;
  return p.x * p.x + p.z * p.z < radius_squared(p.y);
}

void SorShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                         TraceStats& /*stats*/) const {
  const size_t first = out.size();
  append_crossings(ray, tmin, tmax, out);
  // Ascending, and a root on the height where two segments meet counted once.
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
  out.erase(std::unique(out.begin() + std::ptrdiff_t(first), out.end(),
                        [](const Crossing& a, const Crossing& b) {
                          return std::abs(a.t - b.t) <= 1e-10 * (1.0 + std::abs(a.t));
                        }),
            out.end());
}

void SorShape::append_crossings(const Ray& ray, double tmin, double tmax,
                                std::vector<Crossing>& out) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const std::array<double, 3> q = {o.x * o.x + o.z * o.z, 2.0 * (o.x * d.x + o.z * d.z),
                                   d.x * d.x + d.z * d.z};
  for (const Segment& s : segments_) {
    // The ray's stretch within the segment's heights.
    double lo = tmin, hi = tmax;
    if (d.y != 0.0) {
      const double a = (s.h0 - o.y) / d.y, b = (s.h0 + s.length - o.y) / d.y;
      lo = std::max(lo, std::min(a, b));
      hi = std::min(hi, std::max(a, b));
    } else if (!(o.y >= s.h0 && o.y <= s.h0 + s.length)) {
      continue;
    }
    if (!(lo < hi)) continue;
    const std::array<double, 4> p = composed(s.c, (o.y - s.h0) / s.length, d.y / s.length);
    const std::array<double, 4> f = {q[0] - p[0], q[1] - p[1], q[2] - p[2], -p[3]};
    double roots[kMaxPolynomialDegree];
    const int n = polynomial_roots(f, lo, hi, roots);
    for (int k = 0; k < n; ++k) {
      const Vec3 at = ray.at(roots[k]);
      const double t = (at.y - s.h0) / s.length;
      const double dp = s.c[1] + t * (2.0 * s.c[2] + t * 3.0 * s.c[3]);  // d(r^2)/dt
      const Vec3 gradient(2.0 * at.x, -dp / s.length, 2.0 * at.z);
      out.push_back({roots[k], glm::normalize(gradient), surface_.get()});
    }
  }
  if (open_ || d.y == 0.0) return;
  const auto cap = [&](double height, double radius, double normal_y) {
    const double t = (height - o.y) / d.y;
    if (!(t > tmin && t < tmax)) return;
    const Vec3 at = ray.at(t);
    if (at.x * at.x + at.z * at.z > radius * radius) return;
    out.push_back({t, Vec3(0.0, normal_y, 0.0), surface_.get()});
  };
  cap(bottom_, bottom_radius_, -1.0);
  cap(top_, top_radius_, 1.0);
}

}  // namespace convray::geometry
