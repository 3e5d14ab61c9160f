#include "display/preview_layout.hpp"

#include <algorithm>
#include <cmath>

namespace convray::display {

PreviewSize fit_preview(int width, int height, PreviewSize largest) {
  if (width <= largest.width && height <= largest.height) return {width, height};
  const double scale =
      std::min(double(largest.width) / double(width), double(largest.height) / double(height));
  return {std::max(1, int(std::lround(width * scale))), std::max(1, int(std::lround(height * scale)))};
}

int source_of(int shown, int shown_size, int source_size) {
  // The centre of window pixel `shown`, (shown + 0.5) / shown_size of the way across, lies in
  // source pixel floor(that * source_size); integers only, so no rounding decides it.
  const long long s = ((2LL * shown + 1) * source_size) / (2LL * shown_size);
  return int(std::clamp<long long>(s, 0, source_size - 1));
}

ShownRange shown_range(int from, int to, int shown_size, int source_size) {
  // source_of is non-decreasing in `shown`: the window pixels mapping into [from, to) are one
  // run. The first whose centre reaches `from`: (2s + 1) * source >= 2 * from * shown_size.
  const auto first_reaching = [&](int source) {
    const long long need = 2LL * source * shown_size;  // (2s + 1) * source_size >= need
    const long long odd = (need + source_size - 1) / source_size;  // 2s + 1 >= this
    return int(std::clamp<long long>(odd / 2, 0, shown_size));      // the smallest such s
  };
  ShownRange r{first_reaching(from), first_reaching(to)};
  if (r.last < r.first) r.last = r.first;
  return r;
}

}  // namespace convray::display
