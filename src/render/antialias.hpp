#pragma once
// Anti-aliasing as POV-Ray 3.7's +A0.3 +R3 (sampling method 1, non-recursive adaptive):
// every pixel is first sampled at its centre; a pixel whose colour differs from one of its
// four neighbours by more than the threshold is sampled again on an R x R grid of sub-pixel
// cell centres (moved within their cells when jittering) and gets the mean of those R^2
// samples and its centre sample. Both pixels of a differing pair are supersampled.
//
// Measured on POV-Ray 3.7 (-J, orthographic view of a vertical edge, 16-bit linear output):
// an edge 0.2 of the way into a white pixel gives 0.7 at +R3 (centre + 6 of 9 = 7/10) and
// 13/17 at +R4 (sub-samples at 1/8, 3/8, ...); samples average in linear light. The distance
// is |dr| + |dg| + |db| of the colours clamped to [0, 1] and raised to 1 / 2.5 (POV-Ray's
// Antialias_Gamma, default 2.5): the thresholds at which POV-Ray starts supersampling were
// 0.1714 for greys 0.5/0.6 (formula 0.172) and 0.4995 for 0.05/0.15 (formula 0.4995).
//
// Deterministic: the decision reads only the first-pass film, and a jittered position is a
// hash of the seed, the pixel and the sample, so any thread count gives the same pixels.
#include <cstdint>
#include <vector>

#include "render/film.hpp"
#include "util/math.hpp"

namespace convray::render {

struct AntialiasSettings {
  double threshold = 0.3;
  double gamma = 2.5;  // colours are compared as c^(1 / gamma)
  int depth = 3;       // R: R x R samples per supersampled pixel (at least 1)
  bool jitter = false;
  double jitter_amount = 1.0;  // 1: anywhere within the sample's cell
  uint64_t seed = 0;
};

// |dr| + |dg| + |db| of the colours clamped to [0, 1] and raised to 1 / gamma.
double color_distance(const Vec3& a, const Vec3& b, double gamma = 2.5);

// Row-major flags (1: supersample) for every pixel of the first-pass film.
std::vector<uint8_t> pixels_to_supersample(const Film& film, double threshold, double gamma = 2.5);

// The film positions of pixel (i, j)'s R x R samples (pixel (i, j) covers [i, i+1] x [j, j+1]).
std::vector<Vec2> supersample_positions(int i, int j, const AntialiasSettings& settings);

}  // namespace convray::render
