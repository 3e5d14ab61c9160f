// convray.field(V, F, points, radius, strength, kernel): the summed raw field of a triangle
// soup and its exact gradient, as `convray field --mesh FILE --radius R` computes them.
#include "scene/mesh_skeleton.hpp"
#include "implicit/mesh_field.hpp"
#include "implicit/surface.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/evaluate.hpp"
#include "python/kernel_name.hpp"

namespace convray::python {

namespace {

// The quartic kernel through implicit::MeshField (the grid and SIMD batches the command line
// uses, so the values are the same to the last bit); the Cauchy kernel through its surface.
std::vector<field::FieldSample> soup_field(const mesh::TriangleSoup& soup,
                                           const std::vector<Vec3>& points, double radius,
                                           double strength, const field::Kernel& kernel) {
  if (soup.triangles.empty()) return std::vector<field::FieldSample>(points.size());
  if (kernel.type == field::KernelType::quartic) {
    const implicit::MeshField field(scene::soup_triangles(soup), radius, strength);
    return evaluate_points([&](const Vec3& p) { return field.field(p); }, points);
  }
  scene::ConvolutionObject object;
  object.kernel = kernel;
  scene::MeshComponent mesh;
  mesh.triangles = scene::soup_triangles(soup);
  mesh.weight = {strength, radius};
  object.meshes.push_back(std::move(mesh));
  const auto surface = implicit::make_surface(object);
  return evaluate_points([&](const Vec3& p) { return surface->field(p); }, points);
}

py::tuple field_of_soup(const py::object& vertices, const py::object& faces,
                        const py::object& points_arg, double radius, double strength,
                        const std::string& kernel_name, double sharpness) {
  const field::Kernel kernel = kernel_from(kernel_name, sharpness);
  const mesh::TriangleSoup soup = soup_from(vertices, faces);
  const std::vector<Vec3> points = points_from(points_arg, "points");
  radius_checked(radius);
  finite(strength, "strength");
  std::vector<field::FieldSample> samples;
  {
    py::gil_scoped_release release;
    samples = soup_field(soup, points, radius, strength, kernel);
  }
  return samples_tuple(samples);
}

}  // namespace

void bind_field_function(py::module_& m) {
  m.def("field", &field_of_soup, py::arg("V"), py::arg("F"), py::arg("points"),
        py::arg("radius"), py::arg("strength") = 1.0, py::arg("kernel") = "quartic",
        py::arg("sharpness") = 1.0,
        "field(V, F, points, radius, strength=1.0, kernel=\"quartic\", sharpness=1.0)\n"
        "    -> (values, gradients)\n\n"
        "The summed raw field F of the triangles (V, F) at each row of `points` ((n, 3)), and "
        "its exact gradient: values (n,) and gradients (n, 3), float64. Each triangle is "
        "convolved in closed form with the quartic kernel s (1 - r^2/R^2)^2 of support "
        "R = radius (the values of `convray field --mesh FILE --radius R --strength s`), or "
        "with kernel=\"cauchy\", McCormack and Sherstyuk's s / (1 + sharpness^2 r^2)^2, each "
        "triangle's field cut to zero outside its bounding box grown by R (docs/kernels.md). "
        "Runs on every core, without the GIL.");
}

}  // namespace convray::python
