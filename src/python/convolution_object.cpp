// convray.ConvolutionObject: a convolution object built from Python (meshes, segments, arcs,
// points, each with its radius and strength) and queried as the renderer and the command
// line query theirs: through one implicit::Surface, made when first needed.
#include <pybind11/stl.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>

#include "app/command_polygonize.hpp"
#include "app/size_check.hpp"
#include "field/threshold.hpp"
#include "implicit/surface.hpp"
#include "mesh/load.hpp"
#include "polygonize/outer_shells.hpp"
#include "polygonize/polygonize.hpp"
#include "polygonize/size_estimate.hpp"
#include "polygonize/surface_error.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"
#include "python/evaluate.hpp"
#include "python/kernel_name.hpp"
#include "scene/mesh_skeleton.hpp"

namespace convray::python {

namespace {

scene::Weight weight_of(double radius, double strength) {
  return {finite(strength, "strength"), radius_checked(radius)};
}

// The one weight of the components an offset is measured from: triangles, else segments and
// arcs, else points (as `convray polygonize --offset` measures it for a file).
scene::Weight offset_weight(const scene::ConvolutionObject& o, field::OffsetFrom& from) {
  std::vector<scene::Weight> weights;
  const char* kind = "triangles";
  from = field::OffsetFrom::plane;
  for (const auto& c : o.meshes) weights.push_back(c.weight);
  if (weights.empty()) {
    from = field::OffsetFrom::line, kind = "segments and arcs";
    for (const auto& c : o.segments) weights.push_back(c.weight);
    for (const auto& c : o.arcs) weights.push_back(c.weight);
  }
  if (weights.empty()) {
    from = field::OffsetFrom::point, kind = "points";
    for (const auto& c : o.points) weights.push_back(c.weight);
  }
  if (weights.empty()) throw py::value_error("the object has no components yet");
  for (const scene::Weight& w : weights) {
    if (w.radius != weights[0].radius || w.strength != weights[0].strength) {
      throw py::value_error(std::string("threshold_for_offset needs the ") + kind +
                            " to share one radius and strength; set .threshold yourself");
    }
  }
  return weights[0];
}

class ConvolutionObject {
 public:
  ConvolutionObject(const std::string& kernel, double sharpness, double threshold) {
    record_.kernel = kernel_from(kernel, sharpness);
    set_threshold(threshold);
  }

  double threshold() const { return record_.threshold; }
  void set_threshold(double t) {
    if (!(t > 0.0 && std::isfinite(t))) {
      throw py::value_error("threshold must be positive and finite, got " + std::to_string(t));
    }
    change([&] { record_.threshold = t; });
  }
  std::string kernel() const {
    return record_.kernel.type == field::KernelType::cauchy ? "cauchy" : "quartic";
  }

  void add_mesh(const py::object& v, const py::object& f, double radius, double strength) {
    const mesh::TriangleSoup soup = soup_from(v, f);
    scene::MeshComponent c;
    c.triangles = scene::soup_triangles(soup);
    c.weight = weight_of(radius, strength);
    change([&] { record_.meshes.push_back(std::move(c)); });
  }

  void add_file(const py::object& path_like, double radius, double strength) {
    const scene::Weight weight = weight_of(radius, strength);
    const std::string path = path_from(path_like);
    scene::MeshSkeleton skeleton;
    {
      py::gil_scoped_release release;
      skeleton = scene::skeleton_of(reading(path, [&] { return mesh::load_mesh(path); }));
    }
    change([&] { scene::add_skeleton(std::move(skeleton), weight, record_); });
  }

  void add_segment(const py::object& a, const py::object& b, double radius, double strength) {
    const field::Segment s{vector_from(a, "a"), vector_from(b, "b")};
    const scene::Weight w = weight_of(radius, strength);
    change([&] { record_.segments.push_back({s, w}); });
  }

  void add_arc(const py::object& first, const py::object& through, const py::object& last,
               double radius, double strength) {
    if (record_.kernel.type == field::KernelType::cauchy) {
      throw py::value_error("kernel cauchy supports points, segments and triangles (meshes), "
                            "not arcs");
    }
    field::Arc arc;
    if (!field::arc_through(vector_from(first, "first"), vector_from(through, "through"),
                            vector_from(last, "last"), arc)) {
      throw py::value_error("an arc needs three distinct points that are not collinear");
    }
    const scene::Weight w = weight_of(radius, strength);
    change([&] { record_.arcs.push_back({arc, w}); });
  }

  void add_point(const py::object& center, double radius, double strength) {
    const Vec3 c = vector_from(center, "center");
    const scene::Weight w = weight_of(radius, strength);
    change([&] { record_.points.push_back({c, w}); });
  }

  double threshold_for_offset(double offset) const {
    std::lock_guard lock(mutex_);
    field::OffsetFrom from;
    const scene::Weight w = offset_weight(record_, from);
    if (record_.kernel.type == field::KernelType::quartic) {
      return field::resolve_threshold(w.strength, w.radius, offset, std::nullopt, from);
    }
    if (from != field::OffsetFrom::plane) {
      throw py::value_error("kernel cauchy: an offset is measured from triangles; this object "
                            "has none, so set .threshold yourself");
    }
    field::resolve_threshold(w.strength, w.radius, offset, std::nullopt, from);  // the checks
    return field::plane_threshold(record_.kernel, w.strength, w.radius, offset);
  }

  py::tuple field(const py::object& points_arg) {
    const std::vector<Vec3> points = points_from(points_arg, "points");
    std::vector<field::FieldSample> samples;
    {
      py::gil_scoped_release release;
      const auto s = surface();
      samples = evaluate_points([&](const Vec3& p) { return s->field(p); }, points);
    }
    return samples_tuple(samples);
  }

  py::tuple polygonize(std::optional<double> cell, std::optional<double> max_error, bool outer,
                       bool force);

  py::tuple intersect(const py::object& origins_arg, const py::object& directions_arg,
                      double tmin, double tmax);

  std::string repr() const {
    std::lock_guard lock(mutex_);
    size_t triangles = 0;
    for (const auto& c : record_.meshes) triangles += c.triangles.size();
    return "ConvolutionObject(kernel='" + kernel() + "', threshold=" +
           py::repr(py::float_(record_.threshold)).cast<std::string>() + ", meshes=" +
           std::to_string(record_.meshes.size()) + " (" + std::to_string(triangles) +
           " triangles), segments=" + std::to_string(record_.segments.size()) + ", arcs=" +
           std::to_string(record_.arcs.size()) + ", points=" +
           std::to_string(record_.points.size()) + ")";
  }

 private:
  // Changes the record; the surface made from the old one is dropped. Held queries keep
  // their own reference to it, so a change from another thread never pulls it from under them.
  template <class Change>
  void change(Change&& c) {
    std::lock_guard lock(mutex_);
    c();
    surface_.reset();
  }

  // The surface of the record as it is now, made on first use. Call without the GIL.
  std::shared_ptr<const implicit::Surface> surface() {
    std::lock_guard lock(mutex_);
    if (!surface_) {
      if (record_.meshes.empty() && record_.segments.empty() && record_.arcs.empty() &&
          record_.points.empty()) {
        throw std::invalid_argument("the object has no components: add a mesh, file, segment, "
                                    "arc or point first");
      }
      surface_ = implicit::make_surface(record_);
    }
    return surface_;
  }

  mutable std::mutex mutex_;
  scene::ConvolutionObject record_;
  std::shared_ptr<const implicit::Surface> surface_;
};

// The pass sizes `convray polygonize` checks before each pass: a lattice that cannot fit in
// memory is refused (a ValueError naming its size) unless force=True.
void check_pass_size(const polygonize::FieldSource& source, double cell, bool force) {
  const polygonize::SizeEstimate e = polygonize::estimate_size(source, cell);
  app::refuse_unless_fits(e.bytes, "polygonizing at cell " + std::to_string(cell),
                          std::to_string(e.blocks) + " lattice blocks",
                          "give a larger cell or max_error", force);
}

py::tuple ConvolutionObject::polygonize(std::optional<double> cell,
                                        std::optional<double> max_error, bool outer,
                                        bool force) {
  if (cell && max_error) throw py::value_error("give cell or max_error, not both");
  if (cell && !(*cell > 0.0 && std::isfinite(*cell))) throw py::value_error("cell must be > 0");
  if (max_error && !(*max_error > 0.0 && std::isfinite(*max_error))) {
    throw py::value_error("max_error must be > 0");
  }
  polygonize::SurfaceMesh mesh;
  {
    py::gil_scoped_release release;
    const auto s = surface();
    double radius;
    {
      std::lock_guard lock(mutex_);
      radius = app::smallest_radius(record_);
    }
    polygonize::FieldSource source;
    source.supports = s->support_boxes();
    source.field = [s](const Vec3& p) { return s->field(p); };
    source.threshold = s->threshold();
    polygonize::PolygonizeOptions options;
    options.before_pass = [&](double c) { check_pass_size(source, c, force); };
    options.on_predicted_cell = options.before_pass;
    if (cell) {
      options.cell = *cell;
      mesh = polygonize::polygonize(source, options);
    } else {
      // As the command line: within R/50 of the surface, starting from a cell of R/2.
      mesh = polygonize::polygonize_to_error(source, max_error.value_or(radius / 50.0),
                                             0.5 * radius, options)
                 .mesh;
    }
    if (outer) polygonize::keep_outer_shells(mesh);
  }
  return py::make_tuple(rows_array(mesh.soup.vertices), faces_array(mesh.soup.triangles));
}

py::tuple ConvolutionObject::intersect(const py::object& origins_arg,
                                       const py::object& directions_arg, double tmin,
                                       double tmax) {
  const std::vector<Vec3> origins = points_from(origins_arg, "origins");
  const std::vector<Vec3> directions = points_from(directions_arg, "directions");
  const size_t n = std::max(origins.size(), directions.size());
  if (origins.size() != directions.size() && origins.size() != 1 && directions.size() != 1) {
    throw py::value_error("origins and directions must have the same number of rows (or one of "
                          "them one row), got " + std::to_string(origins.size()) + " and " +
                          std::to_string(directions.size()));
  }
  for (size_t i = 0; i < directions.size(); ++i) {
    if (!(glm::length(directions[i]) > 0.0)) {
      throw py::value_error("directions[" + std::to_string(i) + "] has zero length");
    }
  }
  if (!(tmin >= 0.0 && std::isfinite(tmin)) || !(tmax > tmin) || std::isnan(tmax)) {
    throw py::value_error("need 0 <= tmin < tmax (tmin finite)");
  }
  std::vector<double> t(n, std::numeric_limits<double>::infinity());
  std::vector<Vec3> normals(n, Vec3(0.0));
  {
    py::gil_scoped_release release;
    const auto s = surface();
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
      const Vec3& d = directions[directions.size() == 1 ? 0 : i];
      const double length = glm::length(d);
      const Ray ray{origins[origins.size() == 1 ? 0 : i], d / length};
      TraceStats stats;
      // The surface measures t along the unit direction; the caller along d as given.
      const auto hit = s->first_hit(ray, tmin * length, tmax * length, stats);
      if (hit) t[i] = hit->t / length, normals[i] = hit->normal;
    });
  }
  return py::make_tuple(values_array(t), rows_array(normals));
}

}  // namespace

void bind_convolution_object(py::module_& m) {
  py::class_<ConvolutionObject>(
      m, "ConvolutionObject",
      "A convolution object: skeleton parts (triangle meshes, segments, arcs, points), each "
      "convolved with the kernel with its own support radius R and strength s, summed into one "
      "field F; its surface is F = threshold. The same object a scene's convolution { } "
      "describes (docs/language.md). Every add_* returns the object, so calls chain.")
      .def(py::init<const std::string&, double, double>(), py::arg("kernel") = "quartic",
           py::arg("sharpness") = 1.0, py::arg("threshold") = 1.0,
           "ConvolutionObject(kernel=\"quartic\", sharpness=1.0, threshold=1.0)")
      .def_property("threshold", &ConvolutionObject::threshold, &ConvolutionObject::set_threshold,
                    "T of the surface F = T (> 0); see threshold_for_offset.")
      .def_property_readonly("kernel", &ConvolutionObject::kernel)
      .def("add_mesh",
           [](py::object self, const py::object& v, const py::object& f, double radius,
              double strength) {
             self.cast<ConvolutionObject&>().add_mesh(v, f, radius, strength);
             return self;
           },
           py::arg("V"), py::arg("F"), py::arg("radius"), py::arg("strength") = 1.0,
           "Adds the triangles (V, F) with one radius and strength.")
      .def("add_file",
           [](py::object self, const py::object& path, double radius, double strength) {
             self.cast<ConvolutionObject&>().add_file(path, radius, strength);
             return self;
           },
           py::arg("path"), py::arg("radius"), py::arg("strength") = 1.0,
           "Adds a mesh file's skeleton (every format load_mesh reads): its triangles, its "
           "lines as segments and its points, as `convray quick` and `polygonize` take a file.")
      .def("add_segment",
           [](py::object self, const py::object& a, const py::object& b, double radius,
              double strength) {
             self.cast<ConvolutionObject&>().add_segment(a, b, radius, strength);
             return self;
           },
           py::arg("a"), py::arg("b"), py::arg("radius"), py::arg("strength") = 1.0)
      .def("add_arc",
           [](py::object self, const py::object& first, const py::object& through,
              const py::object& last, double radius, double strength) {
             self.cast<ConvolutionObject&>().add_arc(first, through, last, radius, strength);
             return self;
           },
           py::arg("first"), py::arg("through"), py::arg("last"), py::arg("radius"),
           py::arg("strength") = 1.0,
           "Adds the circular arc from `first` through `through` to `last` (quartic kernel).")
      .def("add_point",
           [](py::object self, const py::object& center, double radius, double strength) {
             self.cast<ConvolutionObject&>().add_point(center, radius, strength);
             return self;
           },
           py::arg("center"), py::arg("radius"), py::arg("strength") = 1.0)
      .def("threshold_for_offset", &ConvolutionObject::threshold_for_offset, py::arg("offset"),
           "The threshold T that puts the surface `offset` away from the flat parts of the "
           "triangles (else from segments and arcs, else from points), as `convray polygonize "
           "--offset` computes it; those components must share one radius and strength. "
           "Returns T; set obj.threshold = T to use it.")
      .def("field", &ConvolutionObject::field, py::arg("points"),
           "field(points) -> (values, gradients): F and its exact gradient at (n, 3) points.")
      .def("polygonize", &ConvolutionObject::polygonize, py::arg("cell") = py::none(),
           py::arg("max_error") = py::none(), py::arg("outer") = false,
           py::arg("force") = false,
           "polygonize(cell=None, max_error=None, outer=False, force=False) -> (V, F)\n\n"
           "The surface F = threshold as a closed, 2-manifold, consistently oriented triangle "
           "mesh (`convray polygonize`): every vertex on the exact surface (|F - T| <= 1e-6 T); "
           "by default refined until every triangle's centre is within R/50 of the surface "
           "(R the smallest radius; or max_error), or on a lattice of spacing `cell`. "
           "outer=True keeps only the shells reachable from infinity. An empty surface gives "
           "empty arrays. A lattice too large for memory is a ValueError unless force=True.")
      .def("intersect", &ConvolutionObject::intersect, py::arg("origins"),
           py::arg("directions"), py::arg("tmin") = 0.0,
           py::arg("tmax") = std::numeric_limits<double>::infinity(),
           "intersect(origins, directions, tmin=0, tmax=inf) -> (t, normals)\n\n"
           "The first crossing of the surface along each ray origins[i] + t * directions[i], "
           "t in [tmin, tmax] (t in units of the direction as given; either array may have one "
           "row, shared by all rays): t (n,) float64, inf where a ray misses; normals (n, 3), "
           "the outward unit normal -grad F / |grad F| at the hit, zero where it misses.")
      .def("__repr__", &ConvolutionObject::repr);
}

}  // namespace convray::python
