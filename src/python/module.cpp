// `import convray`: the convolution surfaces, meshes and renderer of convray for NumPy users
// (docs/python.md). Every heavy call releases the GIL and runs on TBB's threads, as the
// command line does.
#include <pybind11/pybind11.h>

#include "python/bindings.hpp"
#include "python/errors.hpp"

PYBIND11_MODULE(convray, m) {
  namespace python = convray::python;
  m.doc() =
      "convray: convolution surfaces of polygon soups and skeletons (the quartic kernel "
      "(1 - r^2/R^2)^2 with finite support R, in closed form), their polygonization and ray "
      "tracing, and a renderer for POV-Ray-style scenes. Arrays are NumPy float64 (n, 3) "
      "points and int64 (m, 3) faces; see docs/python.md.";
  m.attr("__version__") = "0.1.0";
  python::register_exceptions(m);
  python::bind_mesh_functions(m);
  python::bind_field_function(m);
  python::bind_convolution_object(m);
  python::bind_render_function(m);
}
