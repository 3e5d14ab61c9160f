#include "geometry/polynomial_surface.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"

namespace convray::geometry {
namespace {

// a * b, both polynomials in t of the given lengths (coefficient of t^n at [n]).
void multiply(const double* a, int na, const double* b, int nb, double* out) {
  std::fill(out, out + na + nb - 1, 0.0);
  for (int p = 0; p < na; ++p) {
    for (int q = 0; q < nb; ++q) out[p + q] += a[p] * b[q];
  }
}

double power(double x, int n) {
  double r = 1.0;
  for (int k = 0; k < n; ++k) r *= x;
  return r;
}

}  // namespace

PolynomialSurface::PolynomialSurface(int order, std::vector<double> coefficients,
                                     SurfaceInfoPtr surface)
    : order_(order), surface_(std::move(surface)) {
  // POV-Ray's order: i (x) from `order` down, then j (y), then k (z).
  size_t n = 0;
  for (int i = order; i >= 0; --i) {
    for (int j = order - i; j >= 0; --j) {
      for (int k = order - i - j; k >= 0; --k, ++n) {
        if (n < coefficients.size() && coefficients[n] != 0.0) {
          terms_.push_back({i, j, k, coefficients[n]});
        }
      }
    }
  }
}

Box3 PolynomialSurface::bounds() const { return infinite_box(); }

double PolynomialSurface::value(const Vec3& p) const {
  double sum = 0.0;
  for (const Term& t : terms_) sum += t.c * power(p.x, t.i) * power(p.y, t.j) * power(p.z, t.k);
  return sum;
}

Vec3 PolynomialSurface::gradient(const Vec3& p) const {
  Vec3 g(0.0);
  for (const Term& t : terms_) {
    const double x = power(p.x, t.i), y = power(p.y, t.j), z = power(p.z, t.k);
    if (t.i > 0) g.x += t.c * t.i * power(p.x, t.i - 1) * y * z;
    if (t.j > 0) g.y += t.c * t.j * x * power(p.y, t.j - 1) * z;
    if (t.k > 0) g.z += t.c * t.k * x * y * power(p.z, t.k - 1);
  }
  return g;
}

bool PolynomialSurface::inside(const Vec3& p) const { return value(p) < 0.0; }

void PolynomialSurface::crossings(const Ray& ray, double tmin, double tmax,
                                  std::vector<Crossing>& out, TraceStats& /*stats*/) const {
  // Powers of each coordinate along the ray, o + t d, as polynomials in s = t - tmin (about
  // the span's start, where the digits matter).
  const double start = std::isfinite(tmin) ? tmin : 0.0;
  const Vec3 o = ray.at(start), d = ray.direction;
  constexpr int kMax = kMaxPolynomialDegree + 1;
  double powers[3][kMax][kMax] = {};
  for (int axis = 0; axis < 3; ++axis) {
    powers[axis][0][0] = 1.0;
    const double line[2] = {o[axis], d[axis]};
    for (int n = 1; n <= order_; ++n) multiply(powers[axis][n - 1], n, line, 2, powers[axis][n]);
  }
  double c[kMax] = {};
  double xy[kMax], xyz[kMax];
  for (const Term& t : terms_) {
    multiply(powers[0][t.i], t.i + 1, powers[1][t.j], t.j + 1, xy);
    multiply(xy, t.i + t.j + 1, powers[2][t.k], t.k + 1, xyz);
    for (int n = 0; n <= t.i + t.j + t.k; ++n) c[n] += t.c * xyz[n];
  }
  int degree = order_;
  while (degree > 0 && c[degree] == 0.0) --degree;
  if (degree == 0) return;
  // Every real root x has |x| <= 2 max_k |c_(n-k) / c_n|^(1/k) (Fujiwara's bound, with
  // c_0 / 2 for k = n): the unbounded span is clamped to it. Far tighter than Cauchy's
  // 1 + max_k |c_k / c_n| for large coefficients, it spares the root finder halvings.
  double bound = 0.0;
  for (int k = 1; k <= degree; ++k) {
    const double ratio = std::abs(c[degree - k] / c[degree]) * (k == degree ? 0.5 : 1.0);
    bound = std::max(bound, std::pow(ratio, 1.0 / double(k)));
  }
  const double hi = std::min(tmax - start, bound > 0.0 ? 2.0 * bound : 1.0);  // c_n s^n: 0
  if (!(hi > 0.0)) return;
  double roots[kMaxPolynomialDegree];
  const int count = polynomial_roots(std::span<const double>(c, size_t(degree) + 1), 0.0, hi,
                                     roots);
  for (int r = 0; r < count; ++r) {
    const double t = start + roots[r];
    Vec3 normal = gradient(ray.at(t));
    const double length = glm::length(normal);
    normal = length > 0.0 ? normal / length : -ray.direction;
    add_crossing(t, normal, surface_.get(), tmin, tmax, out);
  }
}

}  // namespace convray::geometry
