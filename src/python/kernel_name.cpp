#include "python/kernel_name.hpp"

#include <pybind11/pybind11.h>

#include <cmath>

namespace convray::python {

namespace py = pybind11;

field::Kernel kernel_from(const std::string& name, double sharpness) {
  if (name == "quartic") return {};
  if (name == "cauchy") {
    if (!(sharpness > 0.0 && std::isfinite(sharpness))) {
      throw py::value_error("kernel cauchy: the sharpness s must be positive, found " +
                            std::to_string(sharpness));
    }
    return {field::KernelType::cauchy, sharpness};
  }
  throw py::value_error("kernel must be \"quartic\" or \"cauchy\", got \"" + name + "\"");
}

}  // namespace convray::python
