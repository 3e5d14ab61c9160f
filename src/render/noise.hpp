#pragma once
// Our own solid noise for the noise-based patterns (bozo, granite, agate, ...), turbulence and
// bump normals. Gradient noise in the manner of Perlin's: pseudo-random unit gradients at the
// integer lattice, blended with a quintic fade, so the noise is C2 and zero at every lattice
// point. The gradients come from a hash of the lattice coordinates (not a permutation table),
// so the noise never repeats within double range. It is not POV-Ray's noise: noise-based
// patterns look alike but do not match POV-Ray pixel for pixel.
#include "util/math.hpp"

namespace convray::render {

// Signed gradient noise, roughly in [-1, 1] (|value| <= 1 guaranteed), 0 at lattice points.
double signed_noise(const Vec3& p);

// POV-Ray's convention for pattern noise: values in [0, 1], centred on 0.5.
double noise(const Vec3& p);

// Three independent signed noises: a random vector field (for turbulence and bumps).
Vec3 vector_noise(const Vec3& p);

// The vector turbulence that warps a pattern: sum over `octaves` of
// omega^k * vector_noise(lambda^k p).
Vec3 turbulence_vector(const Vec3& p, int octaves, double omega, double lambda);

// Scalar turbulence: sum over `octaves` of omega^k * |signed_noise(lambda^k p)|.
double turbulence_scalar(const Vec3& p, int octaves, double omega, double lambda);

}  // namespace convray::render
