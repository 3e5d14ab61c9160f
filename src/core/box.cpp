#include "core/box.hpp"

#include <algorithm>

namespace convray {

Box3 transform_box(const Mat4& m, const Box3& box) {
  if (is_empty(box)) return box;
  if (m == Mat4(1.0)) return box;
  // Arvo's method: each output coordinate is a sum of independent terms m_ij * x_j, each
  // extreme at one end of [lo_j, hi_j].
  Box3 out;
  for (int i = 0; i < 3; ++i) {
    double lo = m[3][i], hi = m[3][i];
    for (int j = 0; j < 3; ++j) {
      const double a = m[j][i];  // GLM: column j, row i
      if (a == 0.0) continue;
      const double e0 = a * box.lo[j], e1 = a * box.hi[j];
      lo += std::min(e0, e1);
      hi += std::max(e0, e1);
    }
    out.lo[i] = lo;
    out.hi[i] = hi;
  }
  return out;
}

}  // namespace convray
