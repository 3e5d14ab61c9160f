#include "reference/triangle_cases.hpp"

#include <algorithm>
#include <cmath>

namespace convray::reference {
namespace {

using Rng = std::mt19937_64;
using Planar = std::array<Vec2, 3>;  // triangle in its plane, O at the origin

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
bool coin(Rng& rng, double probability) { return uniform(rng, 0.0, 1.0) < probability; }
int pick(Rng& rng, int count) { return std::uniform_int_distribution<int>(0, count - 1)(rng); }
Vec2 polar(double r, double angle) { return {r * std::cos(angle), r * std::sin(angle)}; }
Vec2 in_disk(Rng& rng, double r) {
  return polar(r * std::sqrt(uniform(rng, 0.0, 1.0)), uniform(rng, 0.0, 2.0 * kPi));
}
Vec2 in_box(Rng& rng, double half) { return {uniform(rng, -half, half), uniform(rng, -half, half)}; }
Vec3 unit_vector(Rng& rng) {
  const double z = uniform(rng, -1.0, 1.0);
  const Vec2 xy = polar(std::sqrt(1.0 - z * z), uniform(rng, 0.0, 2.0 * kPi));
  return {xy.x, xy.y, z};
}

// Where P sits relative to the plane, in the generator's local length unit.
enum class Height { kAny, kInPlane, kNearRadius, kOutside };

struct Setting {
  double radius = 1.0;  // R
  double h = 0.0;       // signed height of P above the plane
  double r0 = 1.0;      // circle radius the geometry is built around (nominal when |h| >= R)
  bool exact = false;   // integer (h, r0, R), dyadic coordinates, axis-aligned embedding
};

Height random_height(Rng& rng) {
  const double u = uniform(rng, 0.0, 1.0);
  if (u < 0.62) return Height::kAny;
  if (u < 0.80) return Height::kInPlane;
  if (u < 0.94) return Height::kNearRadius;
  return Height::kOutside;
}

Setting exact_setting(Rng& rng, Height height) {
  // Integer triples (h, r0, R) with h^2 + r0^2 = R^2: r0^2 = R^2 - h^2 holds exactly.
  struct Triple { double h, r0, radius; };
  static constexpr Triple kAny[] = {{3, 4, 5},   {4, 3, 5},   {5, 12, 13}, {12, 5, 13},
                                    {8, 15, 17}, {15, 8, 17}, {20, 21, 29}, {0, 8, 8}};
  static constexpr Triple kInPlane[] = {{0, 8, 8}, {0, 5, 5}, {0, 13, 13}};
  static constexpr Triple kNear[] = {{65535, 512, 65537}, {1048575, 2048, 1048577}};
  Triple t{};
  switch (height) {
    case Height::kAny: t = kAny[pick(rng, 8)]; break;
    case Height::kInPlane: t = kInPlane[pick(rng, 3)]; break;
    case Height::kNearRadius: t = kNear[pick(rng, 2)]; break;
    case Height::kOutside: t = {coin(rng, 0.5) ? 8.0 : 9.0, 4.0, 8.0}; break;  // h = R or R + 1
  }
  const double sign = coin(rng, 0.5) ? 1.0 : -1.0;
  return {t.radius, sign * t.h, t.r0, true};
}

Setting choose_setting(Rng& rng, Height height, bool allow_exact) {
  if (allow_exact && coin(rng, 0.4)) return exact_setting(rng, height);
  Setting s;
  const double sign = coin(rng, 0.5) ? 1.0 : -1.0;
  switch (height) {
    case Height::kAny: s.r0 = uniform(rng, 0.02, 1.0); break;
    case Height::kInPlane: s.r0 = 1.0; break;
    case Height::kNearRadius: s.r0 = std::pow(10.0, uniform(rng, -6.0, -2.0)); break;
    case Height::kOutside:
      s.r0 = 0.5;
      s.h = sign * (coin(rng, 0.3) ? 1.0 : 1.0 + std::pow(10.0, uniform(rng, -12.0, 0.0)));
      return s;
  }
  s.h = sign * std::sqrt(1.0 - s.r0 * s.r0);
  return s;
}

// Exact settings need dyadic coordinates: snap to a 1/64 grid of the local unit.
Planar snapped(const Setting& s, Planar v) {
  if (s.exact)
    for (Vec2& x : v) x = glm::round(x * 64.0) / 64.0;
  return v;
}

// Places the planar triangle in space: O at `origin`, P at O + h n; random vertex order.
TriangleCase embed(Rng& rng, const Setting& s, Planar v, std::string_view name) {
  std::rotate(v.begin(), v.begin() + pick(rng, 3), v.end());
  if (coin(rng, 0.5)) std::swap(v[1], v[2]);  // both orientations of the normal

  double scale = 1.0;
  Vec3 e1, e2, normal, origin;
  if (s.exact) {
    // Power-of-two scale, axes permuted with signs, integer offset: every product is exact.
    const double target = std::pow(10.0, uniform(rng, -3.0, 3.0));
    scale = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(target / s.radius))));
    std::array<int, 3> axes = {0, 1, 2};
    std::shuffle(axes.begin(), axes.end(), rng);
    std::array<Vec3, 3> frame;
    for (int k = 0; k < 3; ++k) {
      frame[k] = Vec3(0.0);
      frame[k][axes[k]] = coin(rng, 0.5) ? 1.0 : -1.0;
    }
    e1 = frame[0], e2 = frame[1], normal = frame[2];
    const int reach = coin(rng, 0.3) ? 4096 : 8;
    for (int k = 0; k < 3; ++k) origin[k] = scale * static_cast<double>(pick(rng, 2 * reach + 1) - reach);
  } else {
    scale = std::pow(10.0, uniform(rng, -3.0, 3.0));
    normal = unit_vector(rng);
    e1 = glm::normalize(glm::cross(normal, unit_vector(rng)));
    e2 = glm::cross(normal, e1);
    const double u = uniform(rng, 0.0, 1.0);
    if (u < 0.3) {
      origin = unit_vector(rng) * (scale * std::pow(10.0, uniform(rng, 2.0, 4.0)));
    } else if (u < 0.4) {
      origin = Vec3(0.0);
    } else {
      origin = scale * Vec3(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
    }
  }
  const auto place = [&](const Vec2& x) { return origin + (scale * x.x) * e1 + (scale * x.y) * e2; };
  TriangleCase tc;
  tc.a = place(v[0]);
  tc.b = place(v[1]);
  tc.c = place(v[2]);
  tc.p = origin + (scale * s.h) * normal;
  tc.radius = scale * s.radius;
  tc.generator = name;
  tc.exact = s.exact;
  return tc;
}

Planar random_triangle(Rng& rng, double half) {
  return {in_box(rng, half), in_box(rng, half), in_box(rng, half)};
}

// --- Paper Fig. 1 configurations -------------------------------------------------------------

TriangleCase make_triangle_inside_disk(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  const double r = 0.97 * s.r0;
  return embed(rng, s, snapped(s, {in_disk(rng, r), in_disk(rng, r), in_disk(rng, r)}),
               "triangle inside disk");
}

TriangleCase make_disk_inside_triangle(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  // Three lines n_i . x = d_i with d_i > r0 whose normals leave no gap of pi or more.
  std::array<double, 3> angle;
  do {
    for (double& t : angle) t = uniform(rng, 0.0, 2.0 * kPi);
    std::sort(angle.begin(), angle.end());
  } while (angle[1] - angle[0] > 0.9 * kPi || angle[2] - angle[1] > 0.9 * kPi ||
           angle[0] + 2.0 * kPi - angle[2] > 0.9 * kPi);
  std::array<double, 3> distance;
  for (double& d : distance) d = s.r0 * uniform(rng, 1.02, 3.0);
  Planar v;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const Vec2 ni = polar(1.0, angle[i]), nj = polar(1.0, angle[j]);
    const double det = ni.x * nj.y - ni.y * nj.x;
    v[i] = Vec2(distance[i] * nj.y - distance[j] * ni.y, ni.x * distance[j] - nj.x * distance[i]) / det;
  }
  return embed(rng, s, snapped(s, v), "disk inside triangle");
}

TriangleCase make_disjoint(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  Planar v;  // all beyond the line x = r0
  for (Vec2& x : v) x = s.r0 * Vec2(uniform(rng, 1.02, 4.0), uniform(rng, -3.0, 3.0));
  return embed(rng, s, snapped(s, v), "disk and triangle disjoint");
}

// An edge on the line x = d that crosses the circle, reaching past it at both ends.
std::array<Vec2, 2> chord_edge(Rng& rng, double r0, double d) {
  const double half = std::sqrt(r0 * r0 - d * d);
  return {Vec2(d, -half - r0 * uniform(rng, 0.03, 2.0)), Vec2(d, half + r0 * uniform(rng, 0.03, 2.0))};
}

TriangleCase make_one_edge_twice(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  const double d = s.r0 * uniform(rng, -0.95, 0.95);
  const auto [v0, v1] = chord_edge(rng, s.r0, d);
  const double away = d >= 0.0 ? 1.0 : -1.0;
  // Third vertex beyond the chord (cap inside the triangle) or far behind O (O inside).
  const Vec2 v2 = coin(rng, 0.7) ? Vec2(d + away * s.r0 * uniform(rng, 0.05, 4.0), s.r0 * uniform(rng, -3.0, 3.0))
                                  : Vec2(d - away * s.r0 * uniform(rng, 4.0, 8.0), s.r0 * uniform(rng, -1.0, 1.0));
  return embed(rng, s, snapped(s, {v0, v1, v2}), "one edge cut twice");
}

TriangleCase make_two_edges_once(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  const double t = uniform(rng, 0.0, 2.0 * kPi);
  const Planar v = {in_disk(rng, 0.95 * s.r0), polar(s.r0 * uniform(rng, 1.05, 3.0), t),
                    polar(s.r0 * uniform(rng, 1.05, 3.0), t + uniform(rng, 0.1, 2.0))};
  return embed(rng, s, snapped(s, v), "two edges cut once");
}

TriangleCase make_two_edges_twice(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  // Two edges from a far vertex, both aimed inside the circle's silhouette.
  const double distance = s.r0 * uniform(rng, 1.2, 4.0);
  const double cone = std::asin(s.r0 / distance);
  const double a1 = cone * uniform(rng, -0.95, 0.95);
  double a2 = cone * uniform(rng, -0.95, 0.95);
  if (std::abs(a2 - a1) < 0.05 * cone) a2 = -a1;
  const Vec2 v0(-distance, 0.0);
  const Planar v = {v0, v0 + polar(distance + s.r0 * uniform(rng, 1.05, 3.0), a1),
                    v0 + polar(distance + s.r0 * uniform(rng, 1.05, 3.0), a2)};
  return embed(rng, s, snapped(s, v), "two edges cut twice");
}

TriangleCase make_one_edge_twice_two_once(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  const double d = s.r0 * uniform(rng, -0.9, 0.9);
  const auto [v1, v2] = chord_edge(rng, s.r0, d);
  // Third vertex inside the circle, on either side of the chord.
  const double side = coin(rng, 0.5) ? 1.0 : -1.0;
  Vec2 v0;
  do v0 = in_disk(rng, 0.97 * s.r0);
  while (side * (v0.x - d) < 0.01 * s.r0);
  return embed(rng, s, snapped(s, {v0, v1, v2}), "one edge twice, two edges once");
}

TriangleCase make_six_points(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  // Roughly equilateral, inradius below r0 and circumradius (twice the inradius) above it.
  const double inradius = s.r0 * uniform(rng, 0.55, 0.95);
  const double turn = uniform(rng, 0.0, 2.0 * kPi);
  const Vec2 shift = in_disk(rng, 0.05 * s.r0);
  Planar v;
  for (int i = 0; i < 3; ++i)
    v[i] = shift + polar(2.0 * inradius, turn + i * 2.0 * kPi / 3.0) + in_disk(rng, 0.05 * s.r0);
  return embed(rng, s, snapped(s, v), "six points");
}

TriangleCase make_random(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  return embed(rng, s, snapped(s, random_triangle(rng, 2.5 * s.r0)), "random");
}

// --- Degenerate positions and contacts -------------------------------------------------------

TriangleCase make_o_on_edge(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  Planar v = snapped(s, random_triangle(rng, 2.0 * s.r0));
  const int i = pick(rng, 3);
  const double t = (1 + pick(rng, 7)) / 8.0;  // dyadic: exact on the grid
  const Vec2 foot = v[i] + t * (v[(i + 1) % 3] - v[i]);
  for (Vec2& x : v) x -= foot;
  return embed(rng, s, v, "O on an edge");
}

TriangleCase make_o_on_vertex(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  Planar v = snapped(s, random_triangle(rng, 2.0 * s.r0));
  const Vec2 corner = v[pick(rng, 3)];
  for (Vec2& x : v) x -= corner;
  return embed(rng, s, v, "O on a vertex");
}

TriangleCase make_edge_tangent(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  const Planar v = {Vec2(s.r0, -s.r0 * uniform(rng, 0.05, 3.0)), Vec2(s.r0, s.r0 * uniform(rng, 0.05, 3.0)),
                    in_box(rng, 2.5 * s.r0)};
  return embed(rng, s, snapped(s, v), "edge tangent to the circle");
}

TriangleCase make_vertex_on_circle(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  Planar v = snapped(s, random_triangle(rng, 2.0 * s.r0));
  v[0] = Vec2(s.r0, 0.0);
  return embed(rng, s, v, "vertex on the circle");
}

// --- Shapes ----------------------------------------------------------------------------------

TriangleCase make_needle(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), false);
  const Vec2 v0 = in_box(rng, 2.0 * s.r0);
  const Vec2 v1 = v0 + polar(s.r0 * uniform(rng, 0.5, 3.0), uniform(rng, 0.0, 2.0 * kPi));
  const double tiny = glm::length(v1 - v0) * std::pow(10.0, uniform(rng, -8.0, -3.0));
  return embed(rng, s, {v0, v1, v1 + polar(tiny, uniform(rng, 0.0, 2.0 * kPi))}, "needle sliver");
}

TriangleCase make_cap(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), false);
  const Vec2 v0 = in_box(rng, 2.0 * s.r0);
  const Vec2 v1 = v0 + polar(s.r0 * uniform(rng, 0.5, 4.0), uniform(rng, 0.0, 2.0 * kPi));
  const Vec2 side(v0.y - v1.y, v1.x - v0.x);  // perpendicular, |side| = |v1 - v0|
  const double bulge = std::pow(10.0, uniform(rng, -8.0, -3.0)) * (coin(rng, 0.5) ? 1.0 : -1.0);
  return embed(rng, s, {v0, v1, v0 + uniform(rng, 0.2, 0.8) * (v1 - v0) + bulge * side}, "cap sliver");
}

TriangleCase make_zero_area(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  Planar v = snapped(s, random_triangle(rng, 2.0 * s.r0));
  if (s.exact && coin(rng, 0.7)) {
    v[2] = v[0] + ((pick(rng, 13) - 4) / 4.0) * (v[1] - v[0]);  // collinear, exactly
    return embed(rng, s, v, "zero area");
  }
  // A repeated vertex, copied after embedding: with -march=native the compiler may contract
  // the embedding into FMAs differently at different call sites.
  TriangleCase tc = embed(rng, s, v, "zero area");
  const int copy = pick(rng, 3);
  if (copy == 0) tc.c = tc.a;
  else if (copy == 1) tc.c = tc.b;
  else tc.b = tc.a;
  return tc;
}

// --- Heights ---------------------------------------------------------------------------------

TriangleCase make_sphere_misses_plane(Rng& rng) {
  const Setting s = choose_setting(rng, Height::kOutside, true);
  return embed(rng, s, snapped(s, random_triangle(rng, 2.0 * s.r0)), "sphere misses the plane");
}

TriangleCase make_h_near_radius(Rng& rng) {
  const Setting s = choose_setting(rng, Height::kNearRadius, true);
  // A triangle of size ~R with the tiny circle near one of its edges or vertices.
  Planar v = snapped(s, random_triangle(rng, s.radius));
  const int i = pick(rng, 3);
  const Vec2 edge = v[(i + 1) % 3] - v[i];
  const Vec2 across = Vec2(-edge.y, edge.x) / glm::length(edge);
  const double t = coin(rng, 0.3) ? 0.0 : uniform(rng, 0.0, 1.0);
  const Vec2 target = v[i] + t * edge + s.r0 * uniform(rng, -2.0, 2.0) * across;
  for (Vec2& x : v) x -= target;
  return embed(rng, s, snapped(s, v), "h close to R");
}

TriangleCase make_large_triangle(Rng& rng) {
  const Setting s = choose_setting(rng, random_height(rng), true);
  // Edges of 10 to 10^4 R, with the circle near one of the edges or vertices.
  const double size = s.radius * std::pow(10.0, uniform(rng, 1.0, 4.0));
  Planar v = random_triangle(rng, size);
  const int i = pick(rng, 3);
  const Vec2 edge = v[(i + 1) % 3] - v[i];
  const Vec2 across = Vec2(-edge.y, edge.x) / glm::length(edge);
  const double t = coin(rng, 0.3) ? 0.0 : uniform(rng, 0.0, 1.0);
  const Vec2 target = v[i] + t * edge + s.r0 * uniform(rng, -1.5, 1.5) * across;
  for (Vec2& x : v) x -= target;
  return embed(rng, s, snapped(s, v), "large triangle");
}

constexpr TriangleGenerator kGenerators[] = {
    {"triangle inside disk", make_triangle_inside_disk},
    {"disk inside triangle", make_disk_inside_triangle},
    {"disk and triangle disjoint", make_disjoint},
    {"one edge cut twice", make_one_edge_twice},
    {"two edges cut once", make_two_edges_once},
    {"two edges cut twice", make_two_edges_twice},
    {"one edge twice, two edges once", make_one_edge_twice_two_once},
    {"six points", make_six_points},
    {"random", make_random},
    {"O on an edge", make_o_on_edge},
    {"O on a vertex", make_o_on_vertex},
    {"edge tangent to the circle", make_edge_tangent},
    {"vertex on the circle", make_vertex_on_circle},
    {"needle sliver", make_needle},
    {"cap sliver", make_cap},
    {"zero area", make_zero_area},
    {"sphere misses the plane", make_sphere_misses_plane},
    {"h close to R", make_h_near_radius},
    {"large triangle", make_large_triangle},
};

}  // namespace

std::span<const TriangleGenerator> triangle_generators() { return kGenerators; }

}  // namespace convray::reference
