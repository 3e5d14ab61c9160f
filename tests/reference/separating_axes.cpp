#include "reference/separating_axes.hpp"

#include <algorithm>

namespace convray::reference {
namespace {

// Directions in 128 bits: differences stay below 2^21, their cross products below 2^43, and
// cross products of those with differences below 2^65; projections below 2^87.
struct Direction {
  __int128 x, y, z;
};

Direction minus(const IntPoint& p, const IntPoint& q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }

Direction cross(const Direction& u, const Direction& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

bool is_zero(const Direction& u) { return u.x == 0 && u.y == 0 && u.z == 0; }

__int128 dot(const Direction& axis, const IntPoint& p) {
  return axis.x * p.x + axis.y * p.y + axis.z * p.z;
}

bool separates(const Direction& axis, const std::vector<IntPoint>& a,
               const std::vector<IntPoint>& b) {
  __int128 a_lo = dot(axis, a[0]), a_hi = a_lo, b_lo = dot(axis, b[0]), b_hi = b_lo;
  for (const IntPoint& p : a)
    a_lo = std::min(a_lo, dot(axis, p)), a_hi = std::max(a_hi, dot(axis, p));
  for (const IntPoint& p : b)
    b_lo = std::min(b_lo, dot(axis, p)), b_hi = std::max(b_hi, dot(axis, p));
  return a_hi < b_lo || b_hi < a_lo;
}

}  // namespace

bool convex_hulls_meet(const std::vector<IntPoint>& a, const std::vector<IntPoint>& b) {
  std::vector<Direction> directions;
  for (const auto* hull : {&a, &b}) {
    for (size_t i = 0; i < hull->size(); ++i) {
      for (size_t j = i + 1; j < hull->size(); ++j) {
        const Direction d = minus((*hull)[i], (*hull)[j]);
        if (!is_zero(d)) directions.push_back(d);
      }
    }
  }
  std::vector<Direction> axes = directions;
  for (size_t i = 0; i < directions.size(); ++i) {
    for (size_t j = i + 1; j < directions.size(); ++j) {
      const Direction n = cross(directions[i], directions[j]);
      if (is_zero(n)) continue;
      axes.push_back(n);
      for (const Direction& d : directions) {
        const Direction in_plane = cross(n, d);
        if (!is_zero(in_plane)) axes.push_back(in_plane);
      }
    }
  }
  return std::none_of(axes.begin(), axes.end(),
                      [&](const Direction& axis) { return separates(axis, a, b); });
}

}  // namespace convray::reference
