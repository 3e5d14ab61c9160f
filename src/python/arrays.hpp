#pragma once
// NumPy arrays in and out of the module: every array a caller hands us is checked here (shape,
// dtype, finite values, indices in range) with a message naming the argument, so that nothing
// malformed reaches the C++ code, and results go back as fresh float64 / int64 arrays.
//
// The rules, as docs/python.md states them: points and vertices are (n, 3) arrays of real
// numbers; float64 is used as is, other real dtypes (float32, integers) are converted to
// float64; bool, complex, object and string arrays are a TypeError. Faces are (m, 3) integer
// arrays (any integer dtype); floats there are a TypeError. A wrong shape, a NaN or an infinity,
// an index out of range is a ValueError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "field/sample.hpp"
#include "mesh/soup.hpp"
#include "util/math.hpp"

namespace convray::python {

namespace py = pybind11;

// (n, 3) rows of finite numbers, as Vec3.
std::vector<Vec3> points_from(const py::handle& array, const char* name);

// One finite 3-vector: a sequence or array of three numbers.
Vec3 vector_from(const py::handle& value, const char* name);

// (m, 3) vertex indices, each in [0, vertex_count).
std::vector<mesh::Triangle> faces_from(const py::handle& array, const char* name,
                                       size_t vertex_count);

// A soup from the arrays V (vertices) and F (faces).
mesh::TriangleSoup soup_from(const py::handle& vertices, const py::handle& faces);

// A file name: a str or an os.PathLike.
std::string path_from(const py::handle& path);

// A finite number (strengths, thresholds); a ValueError names `name` otherwise.
double finite(double value, const char* name);

// A kernel radius double precision carries (field::check_radius_in_range), else ValueError.
double radius_checked(double radius);

// Results: (n, 3) float64, (m, 3) int64, (n,) float64.
py::array_t<double> rows_array(const std::vector<Vec3>& rows);
py::array_t<int64_t> faces_array(const std::vector<mesh::Triangle>& faces);
py::array_t<double> values_array(const std::vector<double>& values);

// (values, gradients) of field samples: (n,) and (n, 3) float64.
py::tuple samples_tuple(const std::vector<field::FieldSample>& samples);

}  // namespace convray::python
