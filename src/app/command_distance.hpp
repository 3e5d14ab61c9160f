#pragma once
// `convray distance A B`: how far apart two meshes are (mesh/distance.hpp), e.g. a soup and
// the surface `convray polygonize` extracted from it.
#include <cstddef>
#include <ostream>
#include <string>

namespace convray::app {

struct DistanceOptions {
  std::string a_path, b_path;
  size_t samples = 200000;  // surface samples of each mesh, besides its vertices
};

// Prints one `label: value` line per fact (the labels are fixed; docs and scripts rely on
// them): A -> B, B -> A, the symmetric Hausdorff distance and the mean distance, each in the
// meshes' units and as a fraction of the diagonal of the box around both. On an InputError
// (a file that cannot be read), prints its message on `err` and returns 2; otherwise 0.
int run_distance(const DistanceOptions& options, std::ostream& out, std::ostream& err);

}  // namespace convray::app
