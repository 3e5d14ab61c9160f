// Meshes: reading files (every format `convray info` reads), exact self-intersections and
// Hausdorff distances (`convray info --self-intersections`, `convray distance`).
#include <pybind11/stl.h>

#include <limits>

#include "mesh/distance.hpp"
#include "mesh/load.hpp"
#include "mesh/self_intersections.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"

namespace convray::python {

namespace {

mesh::LoadedMesh load(const std::string& path) {
  py::gil_scoped_release release;
  return reading(path, [&] { return mesh::load_mesh(path); });
}

py::tuple load_mesh(const py::object& path_like) {
  const mesh::LoadedMesh loaded = load(path_from(path_like));
  return py::make_tuple(rows_array(loaded.soup.vertices), faces_array(loaded.soup.triangles));
}

py::array_t<int64_t> self_intersections(const py::object& vertices, const py::object& faces) {
  const mesh::TriangleSoup soup = soup_from(vertices, faces);
  mesh::SelfIntersections found;
  {
    py::gil_scoped_release release;
    found = mesh::find_self_intersections(soup, std::numeric_limits<size_t>::max());
  }
  py::array_t<int64_t> pairs({py::ssize_t(found.examples.size()), py::ssize_t(2)});
  auto out = pairs.mutable_unchecked<2>();
  for (size_t i = 0; i < found.examples.size(); ++i) {
    out(py::ssize_t(i), 0) = found.examples[i][0];
    out(py::ssize_t(i), 1) = found.examples[i][1];
  }
  return pairs;
}

// A mesh argument of distance(): a file name, or a (V, F) pair.
mesh::TriangleSoup soup_argument(const py::object& value, const char* name) {
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
    const std::string path = path_from(value);
    mesh::LoadedMesh loaded = load(path);
    mesh::require_triangles(loaded, path, "distance");
    return std::move(loaded.soup);
  }
  if (!py::isinstance<py::sequence>(value) || py::len(value) != 2) {
    throw py::type_error(std::string(name) + " must be a mesh file name or a (V, F) pair");
  }
  const py::sequence pair = value.cast<py::sequence>();
  mesh::TriangleSoup soup = soup_from(pair[0], pair[1]);
  if (soup.triangles.empty()) throw py::value_error(std::string(name) + " has no triangles");
  return soup;
}

py::dict distance(const py::object& a_arg, const py::object& b_arg, size_t samples) {
  if (samples < 1 || samples > 100000000) {
    throw py::value_error("samples must be in 1..100000000, got " + std::to_string(samples));
  }
  const mesh::TriangleSoup a = soup_argument(a_arg, "A");
  const mesh::TriangleSoup b = soup_argument(b_arg, "B");
  mesh::HausdorffDistance d;
  {
    py::gil_scoped_release release;
    d = mesh::hausdorff_distance(a, b, {.samples = samples});
  }
  // The box around both, as `convray distance` reports its fractions of.
  Box3 both = a.bounds();
  both.extend(b.bounds().lo);
  both.extend(b.bounds().hi);
  py::dict out;
  out["hausdorff"] = d.symmetric();
  out["mean"] = d.mean();
  out["a_to_b"] = d.a_to_b.max;
  out["b_to_a"] = d.b_to_a.max;
  out["a_to_b_mean"] = d.a_to_b.mean;
  out["b_to_a_mean"] = d.b_to_a.mean;
  out["a_to_b_points"] = d.a_to_b.points;
  out["b_to_a_points"] = d.b_to_a.points;
  out["diagonal"] = glm::length(both.extent());
  return out;
}

}  // namespace

void bind_mesh_functions(py::module_& m) {
  m.def("load_mesh", &load_mesh, py::arg("path"),
        "load_mesh(path) -> (V, F)\n\n"
        "Reads a mesh file as `convray info` does: OBJ, PLY (ascii and binary), STL (ascii and "
        "binary) and OFF, each optionally .gz. V: (n, 3) float64 vertices; F: (m, 3) int64 "
        "triangles (polygons triangulated, zero-area and repeated-vertex faces dropped). Lines "
        "and points of the file are not in F (ConvolutionObject.add_file uses them).\n"
        "Raises FileNotFoundError for a missing file and convray.InputError for a malformed "
        "one, with the command line's message ('file:line: what is wrong (face N)').");
  m.def("self_intersections", &self_intersections, py::arg("V"), py::arg("F"),
        "self_intersections(V, F) -> (k, 2) int64 array\n\n"
        "Every pair of faces (i < j, rows of F counted from 0) that intersect beyond the corners "
        "they share, decided in exact arithmetic, as `convray info --self-intersections` counts "
        "them (which numbers faces from 1). Faces with collinear corners are not tested.");
  m.def("distance", &distance, py::arg("A"), py::arg("B"), py::arg("samples") = 200000,
        "distance(A, B, samples=200000) -> dict\n\n"
        "How far apart two triangle meshes are, as `convray distance` measures it: A and B are "
        "file names or (V, F) pairs. Keys: 'a_to_b' and 'b_to_a' (one-sided Hausdorff "
        "distances), 'hausdorff' (the larger), 'a_to_b_mean', 'b_to_a_mean', 'mean' (of the "
        "two), 'a_to_b_points', 'b_to_a_points' (vertices and surface samples measured), "
        "'diagonal' (of the box around both).");
}

}  // namespace convray::python
