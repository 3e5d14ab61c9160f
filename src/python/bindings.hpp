#pragma once
// One function per part of the module; module.cpp calls them in order.
#include <pybind11/pybind11.h>

namespace convray::python {

namespace py = pybind11;

void bind_mesh_functions(py::module_& m);        // load_mesh, self_intersections, distance
void bind_field_function(py::module_& m);        // field
void bind_convolution_object(py::module_& m);    // ConvolutionObject
void bind_render_function(py::module_& m);       // render

}  // namespace convray::python
