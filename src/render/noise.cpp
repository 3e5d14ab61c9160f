#include "render/noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/sample_hash.hpp"

namespace convray::render {

namespace {

// The twelve edge midpoints of a cube as gradients (Perlin's 2002 choice): no axis is
// favoured and the dot products need no multiplication by irrational numbers.
constexpr double kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                      {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                      {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

// 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at 0 and 1.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// The gradient at lattice point (i, j, k) of the noise field `seed`, dotted with `offset`.
double lattice_term(int64_t i, int64_t j, int64_t k, uint64_t seed, const Vec3& offset) {
  const uint64_t h = hash_values(uint64_t(i), uint64_t(j), uint64_t(k), seed);
  const double* g = kGradients[h % 12];
  return g[0] * offset.x + g[1] * offset.y + g[2] * offset.z;
}

double gradient_noise(const Vec3& p, uint64_t seed) {
  const Vec3 cell = glm::floor(p);
  const Vec3 f = p - cell;  // position within the cell, in [0, 1)^3
  const int64_t i = int64_t(cell.x), j = int64_t(cell.y), k = int64_t(cell.z);
  const double u = fade(f.x), v = fade(f.y), w = fade(f.z);

  // Trilinear blend (with faded weights) of the eight corners' linear ramps.
  double corners[2][2][2];
  for (int dx = 0; dx < 2; ++dx) {
    for (int dy = 0; dy < 2; ++dy) {
      for (int dz = 0; dz < 2; ++dz) {
        corners[dx][dy][dz] = lattice_term(i + dx, j + dy, k + dz, seed, f - Vec3(dx, dy, dz));
      }
    }
  }
  auto lerp = [](double a, double b, double t) { return a + t * (b - a); };
  const double x00 = lerp(corners[0][0][0], corners[1][0][0], u);
  const double x10 = lerp(corners[0][1][0], corners[1][1][0], u);
  const double x01 = lerp(corners[0][0][1], corners[1][0][1], u);
  const double x11 = lerp(corners[0][1][1], corners[1][1][1], u);
  const double value = lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
  return std::clamp(value, -1.0, 1.0);
}

// Distinct fields for the scalar noise and the three components of the vector noise.
constexpr uint64_t kScalarSeed = 0x5eed0001;
constexpr uint64_t kVectorSeeds[3] = {0x5eed0011, 0x5eed0022, 0x5eed0033};

}  // namespace

double signed_noise(const Vec3& p) { return gradient_noise(p, kScalarSeed); }

double noise(const Vec3& p) { return 0.5 + 0.5 * signed_noise(p); }

Vec3 vector_noise(const Vec3& p) {
  return Vec3(gradient_noise(p, kVectorSeeds[0]), gradient_noise(p, kVectorSeeds[1]),
              gradient_noise(p, kVectorSeeds[2]));
}

Vec3 turbulence_vector(const Vec3& p, int octaves, double omega, double lambda) {
  Vec3 sum(0.0);
  double amplitude = 1.0, frequency = 1.0;
  for (int octave = 0; octave < std::max(octaves, 1); ++octave) {
    sum += amplitude * vector_noise(frequency * p);
    amplitude *= omega;
    frequency *= lambda;
  }
  return sum;
}

double turbulence_scalar(const Vec3& p, int octaves, double omega, double lambda) {
  double sum = 0.0, amplitude = 1.0, frequency = 1.0;
  for (int octave = 0; octave < std::max(octaves, 1); ++octave) {
    sum += amplitude * std::abs(signed_noise(frequency * p));
    amplitude *= omega;
    frequency *= lambda;
  }
  return sum;
}

}  // namespace convray::render
