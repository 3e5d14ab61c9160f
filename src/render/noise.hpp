#pragma once
// POV-Ray 3.7's solid noise, matched to the povray binary (docs/noise.md): the noise-based
// patterns (bozo, spotted, bumps, dents, ...) and the turbulence warp use it, so they draw
// POV-Ray's pictures. The model was measured from the binary's behaviour only:
//   - on each unit lattice cell, the eight corners' ramps value_c + gradient_c . (p - c) are
//     blended with weights s(fx) s(fy) s(fz), s(t) = 3t^2 - 2t^3 (or 1 - s for the low corner);
//   - a corner's value and gradient are windows of one measured table, chosen by an 8-bit
//     hash of its integer coordinates (a 4096-entry permutation applied once per axis);
//   - the default generator (2) maps the blend r to (r + 1.05242) * 0.48985582, generator 1
//     to clamp(r + 0.5, 0, 1).
// Beyond |coordinate| ~ 2^31 POV-Ray's lattice index overflows (it then returns 0 or 1); ours
// keeps repeating every 4096 cells.
#include "util/math.hpp"

namespace convray::render {

// The blend before any range correction (roughly [-1, 1]): POV-Ray's noise without the
// generator's mapping.
double raw_noise(const Vec3& p);

// POV-Ray's noise with its default generator (noise_generator 2): f_noise3d, bozo's value.
double noise(const Vec3& p);

// The noise of POV-Ray's noise_generator 1 ("original") or 2 ("range corrected").
double noise_of_generator(const Vec3& p, int generator);

// 2 noise - 1: functions.inc's f_snoise3d.
double signed_noise(const Vec3& p);

// POV-Ray's vector noise (three blends of the same kind from shifted table windows): the
// turbulence warp's displacement at one octave.
Vec3 vector_noise(const Vec3& p);

// The turbulence warp's displacement: sum over `octaves` of omega^k vector_noise(lambda^k p),
// omega and lambda rounded to single precision as POV-Ray stores them.
Vec3 turbulence_vector(const Vec3& p, int octaves, double omega, double lambda);

// The noise inside POV-Ray's scalar turbulence, granite and wrinkles, before its clamp to
// [0, 1]: 2 noise - 1/2 for generator 2 (measured: 0.97971164 r + 0.53106812), r + 1/2 for
// generator 1.
double unclamped_turbulence_noise(const Vec3& p, int generator);

// The same clamped to [0, 1]: one octave of granite and wrinkles.
double turbulence_noise(const Vec3& p, int generator);

// The scalar turbulence of marble and agate: the first octave clamped, the others not (as
// the binary draws them), turbulence_noise(p) + sum over octaves k = 1.. of
// omega^k unclamped_turbulence_noise(lambda^k p); omega and lambda in single precision.
double turbulence_scalar(const Vec3& p, int octaves, double omega, double lambda, int generator);

}  // namespace convray::render
