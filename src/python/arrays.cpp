#include "python/arrays.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "field/threshold.hpp"

namespace convray::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) {
    if (k > 0) s += ", ";
    s += std::to_string(a.shape(k));
  }
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// np.asarray(value): lists and tuples are accepted as NumPy would read them.
py::array as_array(const py::handle& value) {
  return py::module_::import("numpy").attr("asarray")(value).cast<py::array>();
}

void require_rows_of_three(const py::array& a, const char* name, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3) {
    throw py::value_error(std::string(name) + " must have shape (n, 3) (" + what + "), got " +
                          shape_text(a));
  }
}

}  // namespace

std::vector<Vec3> points_from(const py::handle& value, const char* name) {
  const py::array a = as_array(value);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + " must be an array of real numbers (float64; "
                         "integer and float32 arrays are converted), got dtype " +
                         dtype_text(a));
  }
  require_rows_of_three(a, name, "one x, y, z row per point");
  using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Doubles d = Doubles::ensure(a);
  const auto rows = d.unchecked<2>();
  std::vector<Vec3> out(size_t(rows.shape(0)));
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    const Vec3 p{rows(i, 0), rows(i, 1), rows(i, 2)};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      std::ostringstream message;
      message << name << "[" << i << "] is not finite: (" << p.x << ", " << p.y << ", " << p.z
              << ")";
      throw py::value_error(message.str());
    }
    out[size_t(i)] = p;
  }
  return out;
}

Vec3 vector_from(const py::handle& value, const char* name) {
  const py::array a = as_array(value);
  if (a.ndim() != 1 || a.shape(0) != 3) {
    throw py::value_error(std::string(name) + " must be three numbers x, y, z, got shape " +
                          shape_text(a));
  }
  const py::array two_d = a.attr("reshape")(1, 3);
  return points_from(two_d, name)[0];
}

std::vector<mesh::Triangle> faces_from(const py::handle& value, const char* name,
                                       size_t vertex_count) {
  const py::array a = as_array(value);
  const char kind = a.dtype().kind();
  // An empty list reads as float64: no faces, whatever its dtype.
  const bool empty = a.size() == 0;
  if (!empty && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + " must be an integer array of vertex indices, got "
                         "dtype " + dtype_text(a));
  }
  if (empty && a.ndim() == 1) return {};
  require_rows_of_three(a, name, "three vertex indices per triangle");
  using Indices = py::array_t<int64_t, py::array::c_style | py::array::forcecast>;
  // uint64 indices beyond int64 wrap to negative numbers: refused below as out of range.
  const Indices d = Indices::ensure(a);
  const auto rows = d.unchecked<2>();
  std::vector<mesh::Triangle> out(size_t(rows.shape(0)));
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    for (int k = 0; k < 3; ++k) {
      const int64_t index = rows(i, k);
      if (index < 0 || uint64_t(index) >= vertex_count) {
        std::ostringstream message;
        message << name << "[" << i << "] refers to vertex " << index << ", but there are "
                << vertex_count << " vertices";
        throw py::value_error(message.str());
      }
      out[size_t(i)][size_t(k)] = uint32_t(index);
    }
  }
  return out;
}

mesh::TriangleSoup soup_from(const py::handle& vertices, const py::handle& faces) {
  mesh::TriangleSoup soup;
  soup.vertices = points_from(vertices, "V");
  if (soup.vertices.size() > std::numeric_limits<uint32_t>::max()) {
    throw py::value_error("V has more than 2^32 - 1 vertices");
  }
  soup.triangles = faces_from(faces, "F", soup.vertices.size());
  return soup;
}

std::string path_from(const py::handle& path) {
  const py::object text = py::module_::import("os").attr("fspath")(path);
  if (!py::isinstance<py::str>(text)) throw py::type_error("a file name must be a str");
  return text.cast<std::string>();
}

double finite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw py::value_error(std::string(name) + " must be finite, got " + std::to_string(value));
  }
  return value;
}

double radius_checked(double radius) {
  if (!(radius > 0.0)) {
    throw py::value_error("radius must be > 0, got " + std::to_string(radius));
  }
  field::check_radius_in_range(radius);  // std::invalid_argument: a ValueError
  return radius;
}

py::array_t<double> rows_array(const std::vector<Vec3>& rows) {
  py::array_t<double> out({py::ssize_t(rows.size()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i) {
    for (int k = 0; k < 3; ++k) o(py::ssize_t(i), k) = rows[i][k];
  }
  return out;
}

py::array_t<int64_t> faces_array(const std::vector<mesh::Triangle>& faces) {
  py::array_t<int64_t> out({py::ssize_t(faces.size()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (size_t i = 0; i < faces.size(); ++i) {
    for (int k = 0; k < 3; ++k) o(py::ssize_t(i), k) = faces[i][size_t(k)];
  }
  return out;
}

py::array_t<double> values_array(const std::vector<double>& values) {
  py::array_t<double> out(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::tuple samples_tuple(const std::vector<field::FieldSample>& samples) {
  py::array_t<double> values(py::ssize_t(samples.size()));
  py::array_t<double> gradients({py::ssize_t(samples.size()), py::ssize_t(3)});
  auto v = values.mutable_unchecked<1>();
  auto g = gradients.mutable_unchecked<2>();
  for (size_t i = 0; i < samples.size(); ++i) {
    v(py::ssize_t(i)) = samples[i].value;
    for (int k = 0; k < 3; ++k) g(py::ssize_t(i), k) = samples[i].gradient[k];
  }
  return py::make_tuple(values, gradients);
}

}  // namespace convray::python
