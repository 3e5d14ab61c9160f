#include "field/triangle_quartic.hpp"

#include <algorithm>

#include "util/simd_width.hpp"

namespace convray::field {

namespace {

// Dunavant's degree-4 rule: two orbits of three points (barycentric a, b, b and its
// permutations), weights summing to 1 (times the area).
constexpr double kWeight1 = 0.223381589678011, kA1 = 0.108103018168070, kB1 = 0.445948490915965;
constexpr double kWeight2 = 0.109951743655322, kA2 = 0.816847572980459, kB2 = 0.091576213509771;

// Plain doubles, so that the batch's lane loop vectorizes after inlining.
struct P {
  double x, y, z;
};

struct Coefficients {
  double c0, c1, c2, c3, c4;
};

// One triangle's quartic (corners a, b, c; its area) along origin o + s direction d: the
// weighted sum over the rule's six points, then times the area. The scalar and the batched
// function both run this, operation for operation (no contraction in this file): the same bits.
[[gnu::always_inline]] inline Coefficients line_quartic(P a, P b, P c, double area, P o, P d,
                                                        double inv_r2) {
  double c0 = 0.0, c1 = 0.0, c2 = 0.0, c3 = 0.0, c4 = 0.0;
  // |p(s) - q|^2 = s^2 + 2 s (d.w) + |w|^2 with w = origin - q, so the kernel's base is
  // u = A + B s + C s^2 and u^2 = A^2 + 2AB s + (B^2 + 2AC) s^2 + 2BC s^3 + C^2 s^4.
  const auto add_point = [&](double x, double y, double z, double weight) {
    const double qx = x * a.x + y * b.x + z * c.x, qy = x * a.y + y * b.y + z * c.y,
                 qz = x * a.z + y * b.z + z * c.z;
    const double wx = o.x - qx, wy = o.y - qy, wz = o.z - qz;
    const double pa = 1.0 - (wx * wx + wy * wy + wz * wz) * inv_r2;
    const double pb = -2.0 * (d.x * wx + d.y * wy + d.z * wz) * inv_r2;
    const double pc = -inv_r2;
    c0 += weight * pa * pa;
    c1 += weight * 2.0 * pa * pb;
    c2 += weight * (pb * pb + 2.0 * pa * pc);
    c3 += weight * 2.0 * pb * pc;
    c4 += weight * pc * pc;
  };
  const double z1 = 1.0 - kA1 - kB1, z2 = 1.0 - kA2 - kB2;
  add_point(kA1, kB1, z1, kWeight1);
  add_point(kB1, z1, kA1, kWeight1);
  add_point(z1, kA1, kB1, kWeight1);
  add_point(kA2, kB2, z2, kWeight2);
  add_point(kB2, z2, kA2, kWeight2);
  add_point(z2, kA2, kB2, kWeight2);
  return {c0 * area, c1 * area, c2 * area, c3 * area, c4 * area};
}

P p_of(const Vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

LineQuartic triangle_line_quartic(const Triangle& t, double area, const Vec3& origin,
                                  const Vec3& direction, double radius) {
  const Coefficients q = line_quartic(p_of(t.a), p_of(t.b), p_of(t.c), area, p_of(origin),
                                     p_of(direction), 1.0 / (radius * radius));
  return {{q.c0, q.c1, q.c2, q.c3, q.c4}};
}

void triangle_line_quartics(std::span<const Triangle> triangles,
                            std::span<const TriangleFrame> frames, std::span<const uint32_t> ids,
                            const Vec3& origin, const Vec3& direction, double radius,
                            std::span<LineQuartic> out) {
  const P o = p_of(origin), d = p_of(direction);
  const double inv_r2 = 1.0 / (radius * radius);
  // A chunk of lanes at a time: the corners gathered side by side, the coefficients out the
  // same way (the vectorizer takes neither a Triangle's nor a LineQuartic's stride).
  constexpr size_t kLanes = 32;
  static_assert(kLanes % kSimdWidth == 0);
  double corner[9][kLanes], area[kLanes], c[5][kLanes];
  for (size_t base = 0; base < ids.size(); base += kLanes) {
    const size_t lanes = std::min(kLanes, ids.size() - base);
    const size_t whole = whole_simd_widths(lanes);
    for (size_t k = 0; k < whole; ++k) {
      const uint32_t id = ids[base + std::min(k, lanes - 1)];  // the last one repeated
      const Triangle& t = triangles[id];
      const Vec3* v[3] = {&t.a, &t.b, &t.c};
      for (int i = 0; i < 3; ++i) {
        corner[3 * i][k] = v[i]->x;
        corner[3 * i + 1][k] = v[i]->y;
        corner[3 * i + 2][k] = v[i]->z;
      }
      area[k] = frames[id].area;
    }
#pragma omp simd
    for (size_t k = 0; k < whole; ++k) {
      const Coefficients q = line_quartic({corner[0][k], corner[1][k], corner[2][k]},
                                          {corner[3][k], corner[4][k], corner[5][k]},
                                          {corner[6][k], corner[7][k], corner[8][k]}, area[k],
                                          o, d, inv_r2);
      c[0][k] = q.c0, c[1][k] = q.c1, c[2][k] = q.c2, c[3][k] = q.c3, c[4][k] = q.c4;
    }
    for (size_t k = 0; k < lanes; ++k) {
      for (int j = 0; j < 5; ++j) out[base + k].c[j] = c[j][k];
    }
  }
}

}  // namespace convray::field
