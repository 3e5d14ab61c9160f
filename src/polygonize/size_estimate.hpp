#pragma once
// How big a polygonization will be before it starts (issue 17): a cell a hundred times too
// small runs for hours and fills memory without a word. The estimate is cheap next to the job
// it sizes, and only as exact as a decision to go ahead or refuse needs.
#include <cstdint>

#include "polygonize/field_source.hpp"

namespace convray::polygonize {

struct SizeEstimate {
  uint64_t blocks = 0;     // lattice blocks the extraction visits (an upper estimate)
  uint64_t triangles = 0;  // output triangles (0 when not sampled: a small job)
  uint64_t bytes = 0;      // memory the extraction and its output take
  double seconds = 0.0;    // wall time, from the sample pass on this machine (0 if none)
};

// Blocks at which a job is worth estimating beyond a count: below it, the whole job costs
// about as much as the sample pass would.
inline constexpr uint64_t kSampledBlocks = 20000;

// Blocks: the blocks touched by the supports on a lattice coarsened until it has at most a
// million blocks in all, times the coarsening cubed. Above kSampledBlocks (and below a TB of
// blocks alone), triangles and time: a sample pass on a lattice coarsened to about
// kSampledBlocks / 20 blocks (a twentieth of the smallest job sampled), its
// triangles times the coarsening squared (a surface's area), its time times the ratio of
// blocks. Throws as polygonize() does for a lattice too large per axis.
SizeEstimate estimate_size(const FieldSource& source, double cell);

}  // namespace convray::polygonize
