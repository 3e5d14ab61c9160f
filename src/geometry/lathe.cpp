#include "geometry/lathe.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"
#include "core/polynomial_roots.hpp"

namespace convray::geometry {

namespace {

// |d.y| below this (the direction has unit length): the ray runs in a plane y = const as far
// as the substituted polynomial can tell (its two roots would be closer than its precision).
constexpr double kFlat = 1e-7;

double eval3(const double c[4], double s) { return evaluate_polynomial({c, 4}, s); }
double slope3(const double c[4], double s) { return c[1] + s * (2.0 * c[2] + s * 3.0 * c[3]); }

// The least and greatest values of the cubic c over [0, 1]: at the ends or where c' = 0.
void cubic_range(const double c[4], double& lo, double& hi) {
  lo = std::min(c[0], eval3(c, 1.0));
  hi = std::max(c[0], eval3(c, 1.0));
  const double slope[3] = {c[1], 2.0 * c[2], 3.0 * c[3]};
  double roots[2];
  const int count = polynomial_roots(slope, 0.0, 1.0, roots);
  for (int i = 0; i < count; ++i) {
    lo = std::min(lo, eval3(c, roots[i]));
    hi = std::max(hi, eval3(c, roots[i]));
  }
}

// out = a * b for cubics (out has 7 coefficients).
void product(const double a[4], const double b[4], double out[7]) {
  std::fill(out, out + 7, 0.0);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) out[i + j] += a[i] * b[j];
  }
}

}  // namespace

LatheShape::LatheShape(std::vector<scene::SplinePiece> pieces, SurfaceInfoPtr surface)
    : surface_(std::move(surface)) {
  double area = 0.0;  // twice the signed area of the curve sampled as a closed polygon
  Vec2 first(0.0), last(0.0);
  bool first_piece = true;
  for (const scene::SplinePiece& source : pieces) {
    Piece piece{};
    for (int k = 0; k < 4; ++k) {
      piece.r[k] = source.c[k].x;
      piece.y[k] = source.c[k].y;
    }
    double r_lo, r_hi;
    cubic_range(piece.r, r_lo, r_hi);
    cubic_range(piece.y, piece.y_lo, piece.y_hi);
    piece.r_max = std::max(std::abs(r_lo), std::abs(r_hi));
    box_.extend(Vec3(-piece.r_max, piece.y_lo, -piece.r_max));
    box_.extend(Vec3(piece.r_max, piece.y_hi, piece.r_max));
    for (int k = 0; k < 8; ++k) {
      const Vec2 a(eval3(piece.r, k / 8.0), eval3(piece.y, k / 8.0));
      const Vec2 b(eval3(piece.r, (k + 1) / 8.0), eval3(piece.y, (k + 1) / 8.0));
      area += a.x * b.y - b.x * a.y;
    }
    if (first_piece) first = Vec2(piece.r[0], piece.y[0]);
    first_piece = false;
    last = Vec2(eval3(piece.r, 1.0), eval3(piece.y, 1.0));
    // A piece on the axis (r = 0 throughout) closes the profile but is no surface: a ray
    // through the axis only touches it.
    if (piece.r_max > 0.0) pieces_.push_back(piece);
  }
  area += last.x * first.y - first.x * last.y;
  orientation_ = area < 0.0 ? -1.0 : 1.0;
  margin_ = 1e-9 * std::max(1.0, glm::length(box_.extent()));
}

Box3 LatheShape::bounds() const { return box_; }

// Whether the ray's span [0, span] can reach the piece's ring: inside its y slab and not
// farther from the axis than its greatest radius.
bool LatheShape::may_meet(const Piece& piece, const Ray& ray, double span) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  double lo = 0.0, hi = span;
  if (std::abs(d.y) < kFlat) {
    if (o.y < piece.y_lo - margin_ || o.y > piece.y_hi + margin_) return false;
  } else {
    double a = (piece.y_lo - margin_ - o.y) / d.y, b = (piece.y_hi + margin_ - o.y) / d.y;
    if (a > b) std::swap(a, b);
    lo = std::max(lo, a);
    hi = std::min(hi, b);
    if (lo > hi) return false;
  }
  // x^2 + z^2 along the ray is a quadratic in t: its least value over [lo, hi].
  const double a = d.x * d.x + d.z * d.z, half_b = o.x * d.x + o.z * d.z;
  const double t = a > 0.0 ? std::clamp(-half_b / a, lo, hi) : lo;
  const double reach = piece.r_max + margin_;
  const Vec3 p = ray.at(t);
  return p.x * p.x + p.z * p.z <= reach * reach;
}

// The crossings of the ray (origin near the lathe, t in [0, span]) with one piece.
void LatheShape::piece_roots(const Piece& piece, const Ray& ray, double span,
                             std::vector<Root>& roots) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const double a = d.x * d.x + d.z * d.z, half_b = o.x * d.x + o.z * d.z;
  const double rho2 = o.x * o.x + o.z * o.z;
  double u[4] = {piece.y[0] - o.y, piece.y[1], piece.y[2], piece.y[3]};  // y(s) - o.y
  double s_roots[6];
  // The ray's two times on the circle of radius r(s) in its plane (nearly) y = const.
  auto circle_times = [&](double s, double times[2]) {
    const double r = eval3(piece.r, s);
    return a > 0.0 ? quadratic_roots(a, half_b, rho2 - r * r, times) : 0;
  };
  if (std::abs(d.y) < kFlat) {
    const int count = polynomial_roots(u, 0.0, 1.0, s_roots);
    for (int i = 0; i < count; ++i) {
      double times[2];
      const int n = circle_times(s_roots[i], times);
      if (n == 2 && times[0] == times[1]) continue;  // touches the circle: no crossing
      for (int k = 0; k < n; ++k) roots.push_back({times[k], s_roots[i], &piece});
    }
    return;
  }
  // a u^2 + 2 d.y half_b u + d.y^2 (rho2 - r^2) = 0, a polynomial of degree <= 6 in s.
  double uu[7], rr[7], f[7];
  product(u, u, uu);
  product(piece.r, piece.r, rr);
  for (int k = 0; k < 7; ++k) f[k] = a * uu[k] - d.y * d.y * rr[k];
  for (int k = 0; k < 4; ++k) f[k] += 2.0 * d.y * half_b * u[k];
  f[0] += d.y * d.y * rho2;
  const int count = polynomial_roots(f, 0.0, 1.0, s_roots);
  for (int i = 0; i < count; ++i) {
    const double s = s_roots[i];
    double t = eval3(u, s) / d.y;
    if (std::abs(d.y) < 0.1) {
      // Dividing by a small d.y loses digits: the circle's time nearest to it is exact.
      double times[2];
      const int n = circle_times(s, times);
      if (n == 2) t = std::abs(times[0] - t) < std::abs(times[1] - t) ? times[0] : times[1];
    }
    if (t >= -margin_ && t <= span + margin_) roots.push_back({t, s, &piece});
  }
}

Vec3 LatheShape::outward_normal(const Piece& piece, double s, const Vec3& p) const {
  // The curve's normal in the (r, y) plane, on the side away from the inside.
  const double dr = slope3(piece.r, s), dy = slope3(piece.y, s);
  Vec2 n = orientation_ * Vec2(dy, -dr);
  if (eval3(piece.r, s) < 0.0) n.x = -n.x;  // the mirrored half of the curve
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  const Vec3 radial = rho > 0.0 ? Vec3(p.x / rho, 0.0, p.z / rho) : Vec3(1.0, 0.0, 0.0);
  const Vec3 normal = n.x * radial + Vec3(0.0, n.y, 0.0);
  const double length = glm::length(normal);
  return length > 0.0 ? normal / length : Vec3(0.0, 1.0, 0.0);
}

void LatheShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                           TraceStats& /*stats*/) const {
  Box3 box = box_;
  box.lo -= margin_;
  box.hi += margin_;
  double enter = tmin, leave = tmax;
  if (!clip_to_box(ray, box, enter, leave)) return;
  // Polynomials about the point where the ray enters the box keep their digits.
  const Ray local{ray.at(enter), ray.direction};
  std::vector<Root> roots;
  for (const Piece& piece : pieces_) {
    if (may_meet(piece, local, leave - enter)) piece_roots(piece, local, leave - enter, roots);
  }
  std::sort(roots.begin(), roots.end(), [](const Root& x, const Root& y) { return x.t < y.t; });
  for (const Root& root : roots) {
    const double t = enter + root.t;
    add_crossing(t, outward_normal(*root.piece, root.s, ray.at(t)), surface_.get(), tmin, tmax,
                 out);
  }
}

bool LatheShape::inside(const Vec3& p) const {
  // Parity of the curve's crossings of the half-line from (rho, y) towards r = +infinity.
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  bool in = false;
  for (const Piece& piece : pieces_) {
    if (p.y < piece.y_lo || p.y > piece.y_hi || rho > piece.r_max) continue;
    const double u[4] = {piece.y[0] - p.y, piece.y[1], piece.y[2], piece.y[3]};
    double s_roots[3];
    const int count = polynomial_roots(u, 0.0, 1.0, s_roots);
    for (int i = 0; i < count; ++i) {
      if (s_roots[i] < 1.0 && eval3(piece.r, s_roots[i]) > rho) in = !in;
    }
  }
  return in;
}

}  // namespace convray::geometry
