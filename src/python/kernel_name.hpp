#pragma once
// kernel="quartic" or "cauchy" (with its sharpness), as a scene's `kernel quartic` and
// `kernel cauchy s` (docs/kernels.md).
#include <string>

#include "field/kernel.hpp"

namespace convray::python {

// Throws a ValueError for another name, or a sharpness that is not positive and finite.
field::Kernel kernel_from(const std::string& name, double sharpness);

}  // namespace convray::python
