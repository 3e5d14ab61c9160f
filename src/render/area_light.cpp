#include "render/area_light.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace convray::render {

namespace {

// The grid's visibilities, each traced on first demand (corners are shared by rectangles).
class VisibilityGrid {
 public:
  VisibilityGrid(int size1, int size2, const std::function<Vec3(int, int)>& visibility)
      : size1_(size1), visibility_(visibility), known_(size_t(size1) * size_t(size2)) {}

  Vec3 at(int i, int j) {
    std::optional<Vec3>& slot = known_[size_t(j) * size_t(size1_) + size_t(i)];
    if (!slot) slot = visibility_(i, j);
    return *slot;
  }

 private:
  int size1_;
  const std::function<Vec3(int, int)>& visibility_;
  std::vector<std::optional<Vec3>> known_;
};

// A range of lights [lo, hi] along one axis.
struct Span {
  int lo, hi;
};

// The span itself, or its two halves at the middle light when it covers more than one cell;
// returns how many.
int split(const Span& span, Span out[2]) {
  if (span.hi - span.lo <= 1) {
    out[0] = span;
    return 1;
  }
  const int middle = (span.lo + span.hi) / 2;
  out[0] = {span.lo, middle};
  out[1] = {middle, span.hi};
  return 2;
}

// The visibility of the rectangle of lights [i0, i1] x [j0, j1] (inclusive), `depth`
// subdivisions below the whole grid.
Vec3 rectangle_visibility(VisibilityGrid& grid, int i0, int i1, int j0, int j1, int depth,
                          int adaptive) {
  const Vec3 c00 = grid.at(i0, j0), c10 = grid.at(i1, j0);
  const Vec3 c01 = grid.at(i0, j1), c11 = grid.at(i1, j1);
  const bool single_cell = i1 - i0 <= 1 && j1 - j0 <= 1;
  const bool corners_agree = c00 == c10 && c00 == c01 && c00 == c11;
  if (single_cell || (depth >= adaptive && corners_agree)) return 0.25 * (c00 + c10 + c01 + c11);

  Span across[2], along[2];
  const int n_across = split({i0, i1}, across), n_along = split({j0, j1}, along);
  Vec3 sum(0.0);
  for (int a = 0; a < n_across; ++a) {
    for (int b = 0; b < n_along; ++b) {
      sum += rectangle_visibility(grid, across[a].lo, across[a].hi, along[b].lo, along[b].hi,
                                  depth + 1, adaptive);
    }
  }
  return sum / double(n_across * n_along);
}

}  // namespace

Vec3 area_light_visibility(int size1, int size2, int adaptive,
                           const std::function<Vec3(int, int)>& visibility) {
  size1 = std::max(size1, 1);
  size2 = std::max(size2, 1);
  VisibilityGrid grid(size1, size2, visibility);
  return rectangle_visibility(grid, 0, size1 - 1, 0, size2 - 1, 0, adaptive);
}

}  // namespace convray::render
