#include "render/noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/povray_noise_tables.hpp"

namespace convray::render {

namespace {

namespace pn = povray_noise;

// The corner weight: the blend of the measured probes is exact with this cubic.
double fade(double t) { return t * t * (3.0 - 2.0 * t); }

// The lattice coordinate as the hash sees it: floor, offset, modulo the table size.
int lattice_index(int64_t cell) {
  return int((cell + pn::kLatticeOffset) & int64_t(pn::kHashSize - 1));
}

// The 8-bit hash of lattice point (i, j, k): one permutation applied per axis, XOR between.
int corner_hash(int64_t i, int64_t j, int64_t k) {
  const auto& perm = pn::kPermutation;
  return perm[perm[perm[lattice_index(i)] ^ lattice_index(j)] ^ lattice_index(k)] & 255;
}

// The blend of one noise: `window` shifts the corners' table windows (0 for the scalar noise
// and the vector's x, 4 for y, 8 for z).
double blend(const Vec3& p, int window) {
  const Vec3 cell = glm::floor(p);
  const Vec3 f = p - cell;
  const int64_t i = int64_t(cell.x), j = int64_t(cell.y), k = int64_t(cell.z);
  const double wx[2] = {1.0 - fade(f.x), fade(f.x)};
  const double wy[2] = {1.0 - fade(f.y), fade(f.y)};
  const double wz[2] = {1.0 - fade(f.z), fade(f.z)};
  double sum = 0.0;
  for (int dx = 0; dx < 2; ++dx) {
    for (int dy = 0; dy < 2; ++dy) {
      for (int dz = 0; dz < 2; ++dz) {
        // Entry e of the table sits at index e + 1; the value is entry h - 1 + window.
        const double* t = &pn::kCornerTable[corner_hash(i + dx, j + dy, k + dz) + window];
        const double ramp =
            0.5 * t[0] + t[1] * (f.x - dx) + t[2] * (f.y - dy) + t[3] * (f.z - dz);
        sum += wx[dx] * wy[dy] * wz[dz] * ramp;
      }
    }
  }
  return sum;
}

// Octave k of a turbulence sum has amplitude omega^k and frequency lambda^k, omega and
// lambda rounded to single precision: with omega 0.7 a double differs from the binary's
// values by 1e-9, with lambda 2.3 by 1e-6; powers match it to 1e-16 where a running product
// leaves 4e-15.
class SinglePrecisionOctaves {
 public:
  SinglePrecisionOctaves(double omega, double lambda) : omega_(float(omega)), lambda_(float(lambda)) {}
  double amplitude(int octave) const { return std::pow(omega_, octave); }
  double frequency(int octave) const { return std::pow(lambda_, octave); }

 private:
  double omega_, lambda_;
};

}  // namespace

double raw_noise(const Vec3& p) { return blend(p, 0); }

double noise(const Vec3& p) { return (raw_noise(p) + pn::kRangeBias) * pn::kRangeScale; }

double noise_of_generator(const Vec3& p, int generator) {
  if (generator == 1) return std::clamp(raw_noise(p) + 0.5, 0.0, 1.0);
  return noise(p);
}

double signed_noise(const Vec3& p) { return 2.0 * noise(p) - 1.0; }

Vec3 vector_noise(const Vec3& p) { return Vec3(blend(p, 0), blend(p, 4), blend(p, 8)); }

Vec3 turbulence_vector(const Vec3& p, int octaves, double omega, double lambda) {
  const SinglePrecisionOctaves octave_scale(omega, lambda);
  Vec3 sum(0.0);
  for (int octave = 0; octave < std::max(octaves, 1); ++octave) {
    sum += octave_scale.amplitude(octave) * vector_noise(p * octave_scale.frequency(octave));
  }
  return sum;
}

double unclamped_turbulence_noise(const Vec3& p, int generator) {
  if (generator == 1) return raw_noise(p) + 0.5;
  return 2.0 * noise(p) - 0.5;
}

double turbulence_noise(const Vec3& p, int generator) {
  return std::clamp(unclamped_turbulence_noise(p, generator), 0.0, 1.0);
}

double turbulence_scalar(const Vec3& p, int octaves, double omega, double lambda, int generator) {
  const SinglePrecisionOctaves octave_scale(omega, lambda);
  double sum = turbulence_noise(p, generator);
  for (int octave = 1; octave < octaves; ++octave) {
    sum += octave_scale.amplitude(octave) *
           unclamped_turbulence_noise(p * octave_scale.frequency(octave), generator);
  }
  return sum;
}

}  // namespace convray::render
