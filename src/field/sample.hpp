#pragma once
// The answer of every field evaluator: the value and its exact gradient at one point.
#include "util/math.hpp"

namespace convray::field {

struct FieldSample {
  double value = 0.0;
  Vec3 gradient{0.0};

  FieldSample& operator+=(const FieldSample& o) {
    value += o.value;
    gradient += o.gradient;
    return *this;
  }
  FieldSample operator*(double s) const { return {value * s, gradient * s}; }
};

}  // namespace convray::field
