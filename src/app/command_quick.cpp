#include "app/command_quick.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <new>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <variant>
#include <vector>

#include "scene/quick_scene.hpp"
#include "app/command_step.hpp"
#include "app/short_number.hpp"
#include "app/size_check.hpp"
#include "app/usage_error.hpp"
#include "geometry/implicit_shape.hpp"
#include "geometry/world.hpp"
#include "implicit/lent_triangles.hpp"
#include "implicit/surface.hpp"
#include "scene/mesh_skeleton.hpp"
#include "field/threshold.hpp"
#include "mesh/load.hpp"
#include "mesh/skeleton_stats.hpp"
#include "core/image_file.hpp"
#include "core/progress.hpp"
#include "render/render_scene.hpp"
#include "util/error.hpp"

namespace convray::app {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string number(double value) { return short_number(value, 6); }

const SourceLoc kCommandLine{"command line"};

struct PhaseTimes {
  double load = 0, build = 0, render = 0, write = 0;
};

// T from --threshold or --offset (default R/2, from the skeleton's triangles, else its
// segments, else its points) for a skeleton of strength 1; a bad offset is a command-line
// error.
double quick_threshold(const QuickOptions& o, double radius,
                       field::OffsetFrom from = field::OffsetFrom::plane) {
  try {
    return field::resolve_threshold(1.0, radius, o.offset, o.threshold, from);
  } catch (const std::invalid_argument& e) {
    throw InputError(kCommandLine, e.what());
  }
}

struct QuickObject {
  scene::ConvolutionObject object;  // one file's skeleton, strength 1
  double radius = 0.0;
  size_t triangles = 0, segments = 0, points = 0;
};

// The file read, fitted into its box, and made a convolution object with its radius and
// threshold resolved.
QuickObject load_object(const QuickOptions& o) {
  mesh::LoadedMesh loaded = mesh::load_mesh(o.mesh_path);
  if (o.fit_box) mesh::fit_into_box(loaded, *o.fit_box);
  QuickObject model;
  model.radius = o.radius ? *o.radius
                          : mesh::advise_radius(mesh::compute_stats(loaded.soup),
                                                mesh::compute_skeleton_stats(loaded))
                                .radius;
  scene::MeshSkeleton skeleton = scene::skeleton_of(loaded);
  model.triangles = skeleton.triangles.size();
  model.segments = skeleton.segments.size();
  model.points = skeleton.points.size();
  model.object.threshold = quick_threshold(o, model.radius, skeleton.offset_from());
  scene::add_skeleton(std::move(skeleton), {1.0, model.radius}, model.object);
  return model;
}

// "12 triangles", "0 triangles, 5000 points", "1 triangle, 1 point": what the skeleton is.
std::string skeleton_summary(const QuickObject& model) {
  auto count = [](size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
  std::string summary = count(model.triangles, "triangle");
  if (model.segments > 0) summary += ", " + count(model.segments, "segment");
  if (model.points > 0) summary += ", " + count(model.points, "point");
  return summary;
}

// The camera the options ask for; POV-Ray's own checks (distinct points, a view that is not
// vertical) reported as command-line errors.
scene::Camera make_camera(const scene::LookAtView& view) {
  try {
    return scene::look_at_camera(view);
  } catch (const std::invalid_argument& e) {
    throw InputError(kCommandLine, std::string("--camera/--look-at: ") + e.what());
  }
}

scene::LookAtView camera_view(const QuickOptions& o, const Box3& bounds) {
  if (o.camera && o.look_at) return {*o.camera, *o.look_at, o.angle, o.width, o.height};
  return scene::frame_bounds(bounds, o.width, o.height, o.angle);
}

// The one convolution object of a quick scene (placed as it is: no transform), as the world
// built it.
const implicit::Surface& quick_surface(const geometry::World& world) {
  return dynamic_cast<const geometry::ImplicitShape&>(world.shape(0)).surface();
}

// `bytes`: the surface's memory_bytes().
void print_stats(const QuickOptions& o, size_t bytes, const QuickObject& model,
                 const render::RenderStats& s, const PhaseTimes& t, std::ostream& out) {
  const TraceStats& trace = s.trace;
  const double per_query = trace.rays ? double(trace.primitives) / double(trace.rays) : 0.0;
  const size_t primitives = model.triangles + model.segments + model.points;
  out << "image: " << o.width << "x" << o.height << " (" << uint64_t(o.width) * uint64_t(o.height)
      << " pixels)\n"
      << "tracer: "
      << (o.reference ? "reference (exact field, Lipschitz-safe march)"
                      : "fast (window march on the summed exact field)")
      << "\n"
      << "rays: " << s.camera_rays + s.shadow_rays << " (camera " << s.camera_rays << ", shadow "
      << s.shadow_rays << ")\n"
      << "rays reaching the surface's bounds: " << trace.rays << "\n"
      << "camera rays that hit: " << s.hits << "\n"
      << "primitives per ray: " << number(per_query) << " (support intervals crossed)\n"
      << "field evaluations: " << trace.field_evaluations << "\n"
      << "roots: " << trace.roots << "\n"
      << "fits: " << trace.fits << (o.reference ? "" : " (window-march steps; spheres entered)") << "\n"
      << "subdivisions: " << trace.subdivisions << "\n"
      << "fallbacks: " << trace.fallbacks << "\n"
      << "shadow rays settled inside: " << trace.shadows_settled << "\n"
      << "surface memory: " << number(double(bytes) / (1024.0 * 1024.0)) << " MiB ("
      << number(primitives ? double(bytes) / double(primitives) : 0.0) << " bytes per "
      << (primitives == model.triangles ? "triangle" : "primitive") << ")\n"
      << "time load: " << number(t.load) << " s\n"
      << "time build: " << number(t.build) << " s\n"
      << "time render: " << number(t.render) << " s\n"
      << "time write: " << number(t.write) << " s\n"
      << "time total: " << number(t.load + t.build + t.render + t.write) << " s\n";
}

// The whole command once the options are known to be well formed.
void render_quick(const QuickOptions& o, std::ostream& out, std::ostream& err, CommandStep& step) {
  // Everything that can be checked before the work starts is checked first.
  check_image_destination(o.output);
  refuse_unless_image_fits(o.width, o.height, "give a smaller --size", o.force);
  if (o.radius) quick_threshold(o, *o.radius);
  if (o.camera && o.look_at) make_camera(camera_view(o, Box3{}));

  PhaseTimes times;
  Clock::time_point start = Clock::now();
  step.now("reading " + o.mesh_path, kFreeMemory);
  QuickObject model = load_object(o);
  times.load = seconds_since(start);
  const double radius = model.radius, threshold = model.object.threshold;

  // The camera waits for the bounds, which the world knows once built; it is set after.
  start = Clock::now();
  step.now("building the surface of " + o.mesh_path, kFreeMemory);
  std::shared_ptr<scene::Object> record;
  scene::Scene view =
      scene::quick_scene(std::move(model.object), scene::Camera{}, Vec3(0.0), &record);
  // Nothing reads the skeleton's triangles once the surface has them: lent, they are not held
  // twice while it is made (implicit/lent_triangles.hpp).
  std::vector<std::vector<field::Triangle>*> meshes;
  for (scene::MeshComponent& m : std::get<scene::Implicit>(record->shape).object.meshes) {
    meshes.push_back(&m.triangles);
  }
  const implicit::LentTriangles lent(std::move(meshes));
  // Let go of before the picture is written, whose buffers then reuse its memory.
  std::optional<const geometry::World> built;
  built.emplace(view, nullptr, o.reference ? implicit::Tracer::reference : implicit::Tracer::fast);
  const geometry::World& world = *built;
  times.build = seconds_since(start);

  start = Clock::now();
  const Box3 bounds = world.bounds();
  view.camera = make_camera(camera_view(o, bounds));
  view.lights.front().position =
      o.light ? *o.light : scene::default_light_position(view.camera, bounds);
  render::RenderSettings settings;
  settings.width = o.width;
  settings.height = o.height;
  // Hit points are polished to rounding level; features are no thinner than about R.
  settings.ray_offset = 1e-5 * radius;
  // A bar only where someone watches: on a terminal, never into a pipe or a log file.
  step.now("rendering the " + std::to_string(o.width) + "x" + std::to_string(o.height) + " image",
           "give a smaller --size");
  Progress progress("render", uint64_t(o.width) * uint64_t(o.height), err,
                            Progress::stderr_is_terminal());
  const render::RenderResult result = render::render_scene(view, world, settings, &progress);
  times.render = seconds_since(start);
  const size_t surface_bytes = quick_surface(world).memory_bytes();
  built.reset();

  start = Clock::now();
  step.now("writing " + o.output, "give a smaller --size");
  write_image_atomically(
      o.output, {o.width, o.height, result.film.rgb(), PixelEncoding::linear});
  times.write = seconds_since(start);

  out << "quick: " << o.mesh_path << " (" << skeleton_summary(model) << ", R = " << number(radius)
      << ", T = " << number(threshold) << "): wrote " << o.output << " (" << o.width << "x"
      << o.height << ", " << number(times.load + times.build + times.render + times.write)
      << " s)\n";
  if (o.stats) print_stats(o, surface_bytes, model, result.stats, times, out);
}

}  // namespace

int run_quick(const QuickOptions& options, std::ostream& out, std::ostream& err) {
  CommandStep step("checking the options", kFreeMemory);
  try {
    render_quick(options, out, err, step);
    return 0;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    err << "convray quick: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  } catch (const std::exception& e) {
    err << "convray quick: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace convray::app
