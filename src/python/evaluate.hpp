#pragma once
// A field at many points, on TBB's threads, without the GIL: what convray.field and
// ConvolutionObject.field share (the command line's `field` evaluates its blocks the same way).
#include <tbb/parallel_for.h>

#include <vector>

#include "field/sample.hpp"
#include "python/arrays.hpp"

namespace convray::python {

// `field(p)` must be thread safe (every evaluator of the libraries is). Call without the GIL.
template <class Field>
std::vector<field::FieldSample> evaluate_points(const Field& field, const std::vector<Vec3>& points) {
  std::vector<field::FieldSample> samples(points.size());
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) { samples[i] = field(points[i]); });
  return samples;
}

}  // namespace convray::python
