#include "app/command_polygonize.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "app/command_step.hpp"
#include "app/declared_object.hpp"
#include "app/parse_hooks.hpp"
#include "app/short_number.hpp"
#include "app/size_check.hpp"
#include "app/usage_error.hpp"
#include "implicit/placed_field.hpp"
#include "implicit/mesh_field.hpp"
#include "scene/mesh_skeleton.hpp"
#include "field/threshold.hpp"
#include "mesh/format.hpp"
#include "mesh/load.hpp"
#include "mesh/skeleton_stats.hpp"
#include "mesh/write.hpp"
#include "polygonize/outer_shells.hpp"
#include "polygonize/size_estimate.hpp"
#include "polygonize/surface_error.hpp"
#include "core/progress.hpp"
#include "sdl/parser.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/memory_limit.hpp"

namespace convray::app {

namespace {

const SourceLoc kCommandLine{"command line"};

// The field to polygonize, the objects it reads from, and the kernel radius that sets the
// default resolution.
struct PreparedField {
  polygonize::FieldSource source;
  double radius = 1.0;
  std::shared_ptr<const void> owner;  // keeps the evaluator the source's functions call alive
};

// A file of triangles only: MeshField's SIMD fast path classifies the lattice and leads the
// searches; the scalar closed form (its exact twin) places the vertices, so |F - T| <= 1e-6 T
// holds on the exact field.
void prepare_triangles(PreparedField& prepared, const mesh::LoadedMesh& loaded, double strength) {
  auto field = std::make_shared<implicit::MeshField>(scene::soup_triangles(loaded.soup), prepared.radius, strength);
  prepared.source.supports = polygonize::triangle_support_boxes(field->triangles(), prepared.radius);
  prepared.source.field = [field](const Vec3& p) { return field->field_exact(p); };
  prepared.source.value = [field](const Vec3& p) { return field->value(p); };
  prepared.owner = field;
}

// The field of `object` placed by `placed` (objects the kernel cannot describe: `loc`).
void place_surface(PreparedField& prepared, const scene::ConvolutionObject& object,
                   const scene::Transform& placed, const SourceLoc& loc);

PreparedField prepare_mesh(const PolygonizeOptions& o) {
  mesh::LoadedMesh loaded = mesh::load_mesh(o.input);
  if (o.fit_box) mesh::fit_into_box(loaded, *o.fit_box);
  PreparedField prepared;
  prepared.radius = o.radius ? *o.radius
                             : mesh::advise_radius(mesh::compute_stats(loaded.soup),
                                                   mesh::compute_skeleton_stats(loaded))
                                   .radius;
  scene::MeshSkeleton skeleton = scene::skeleton_of(loaded);
  try {
    prepared.source.threshold = field::resolve_threshold(o.strength, prepared.radius, o.offset,
                                                            o.threshold, skeleton.offset_from());
  } catch (const std::invalid_argument& e) {
    throw InputError(kCommandLine, e.what());
  }
  if (skeleton.segments.empty() && skeleton.points.empty()) {
    prepare_triangles(prepared, loaded, o.strength);
    return prepared;
  }
  // Segments and points: the exact field of the whole skeleton's convolution surface.
  scene::ConvolutionObject object;
  object.threshold = prepared.source.threshold;
  scene::add_skeleton(std::move(skeleton), {o.strength, prepared.radius}, object);
  place_surface(prepared, object, scene::Transform{}, kCommandLine);
  return prepared;
}

void place_surface(PreparedField& prepared, const scene::ConvolutionObject& object,
                   const scene::Transform& placed, const SourceLoc& loc) {
  std::shared_ptr<const implicit::Surface> surface;
  try {
    surface = implicit::make_surface(object);
  } catch (const std::invalid_argument& e) {
    throw InputError(loc, e.what());
  }
  prepared.source.supports = implicit::placed_support_boxes(*surface, placed);
  prepared.source.field = [surface, placed](const Vec3& p) {
    return implicit::placed_field(*surface, placed, p);
  };
  prepared.owner = surface;
}

// A declared object, placed by its transform: the mesh comes out where the scene puts it.
PreparedField prepare_scene(const PolygonizeOptions& o) {
  sdl::ParseOptions parse_options;
  parse_options.library_paths = o.library_paths;
  parse_options.read_folders = o.read_folders;
  use_program_hooks(parse_options);
  const sdl::ParseResult parsed = sdl::parse_file(o.input, parse_options);
  const scene::Object& object = declared_implicit(parsed, o.input, o.object_name);
  const scene::ConvolutionObject& convolution = std::get<scene::Implicit>(object.shape).object;
  PreparedField prepared;
  prepared.radius = smallest_radius(convolution);
  if (!std::isfinite(prepared.radius)) {
    throw InputError(SourceLoc{o.input}, "'" + o.object_name + "' has no components");
  }
  // The scene's own threshold, unless the command line gives one; the placement scales
  // lengths, so the default resolution follows it.
  prepared.source.threshold = o.threshold.value_or(convolution.threshold);
  const scene::Transform placed = object.transform;
  if (placed.is_similarity(1e-9)) prepared.radius *= placed.uniform_scale();
  // Under kernel cauchy the field jumps at the truncation boxes' faces, where no vertex can
  // meet |F - T| <= 1e-6 T (reported).
  place_surface(prepared, convolution, placed, object.loc);
  return prepared;
}

void check_options(const PolygonizeOptions& o) {
  const bool scene = !o.object_name.empty();
  if (scene && (o.radius || o.offset || o.fit_box || o.strength != 1.0)) {
    throw InputError(kCommandLine,
                     "--radius, --strength, --offset and --fit-box are for meshes; a scene "
                     "object has its own (--threshold T overrides its threshold)");
  }
  if (o.threshold && !(*o.threshold > 0.0)) {
    throw InputError(kCommandLine,
                     "--threshold must be > 0: the outside of every support, where "
                     "F = 0, must be outside the surface");
  }
  if (!scene && !(o.strength > 0.0)) {
    throw InputError(kCommandLine,
                     "--strength must be > 0 for a mesh (a negative field has no "
                     "surface at a positive threshold)");
  }
  if (o.output.empty()) throw InputError(kCommandLine, "-o OUT.(obj|ply|stl) is required");
}

struct Extraction {
  polygonize::SurfaceMesh mesh;
  polygonize::PolygonizeStats stats;
  double cell = 0.0;
  double error = -1.0;  // max distance from the surface, when measured
  int passes = 1;
};

std::string number(double value) { return short_number(value, 4); }

// "40 s", "12 min", "15 h": an estimate's time, to two digits.
std::string duration(double seconds) {
  if (seconds < 120.0) return short_number(seconds, 2) + " s";
  if (seconds < 7200.0) return short_number(seconds / 60.0, 2) + " min";
  return short_number(seconds / 3600.0, 2) + " h";
}

// Sizes each pass before it runs (issue 17): a large one is announced with its estimate, one
// that cannot fit in memory refused unless --force.
// `predicted`: the cell --max-error (or its default) will need, sized after the first pass.
void size_pass(const polygonize::FieldSource& source, double cell, bool predicted,
               const PolygonizeOptions& o, std::ostream& err) {
  polygonize::SizeEstimate e;
  try {
    e = polygonize::estimate_size(source, cell);
  } catch (const std::invalid_argument& error) {  // a lattice too large per axis
    if (!predicted) throw;
    throw UsageError("the error bound needs a cell of about " + number(cell) + ": " +
                     error.what() + "; give a larger --max-error, or a --cell");
  }
  if (e.blocks < polygonize::kSampledBlocks) return;
  std::string details = number(double(e.blocks)) + " lattice blocks";
  if (e.triangles > 0) details += ", " + number(double(e.triangles)) + " triangles";
  const std::string job = predicted ? "the error bound, at a predicted cell of " + number(cell) + ","
                                    : "polygonizing at cell " + number(cell);
  err << "polygonize: " << (predicted ? "predicted cell " : "cell ") << number(cell) << ": about "
      << details << ", " << byte_size(e.bytes);
  if (e.seconds > 0.0) err << ", " << duration(e.seconds);
  err << "\n";
  refuse_unless_fits(e.bytes, job, details, "give a larger --cell or --max-error", o.force);
}

Extraction extract(const PreparedField& prepared, const PolygonizeOptions& o, std::ostream& err) {
  std::unique_ptr<Progress> progress;
  polygonize::PolygonizeOptions options;
  options.before_pass = [&](double cell) { size_pass(prepared.source, cell, false, o, err); };
  options.on_predicted_cell = [&](double cell) { size_pass(prepared.source, cell, true, o, err); };
  const bool terminal = Progress::stderr_is_terminal();
  options.on_start = [&](uint64_t blocks) {
    progress = std::make_unique<Progress>("polygonize", blocks, err, terminal);
  };
  options.on_blocks_done = [&](uint64_t blocks) { progress->advance(blocks); };
  Extraction result;
  if (o.cell) {
    options.cell = *o.cell;
    result.mesh = polygonize::polygonize(prepared.source, options, &result.stats);
    result.cell = *o.cell;
  } else {
    // Default: within R/50 of the surface, starting from a cell of R/2.
    const double bound = o.max_error.value_or(prepared.radius / 50.0);
    polygonize::ErrorBoundedResult r = polygonize::polygonize_to_error(
        prepared.source, bound, 0.5 * prepared.radius, options, &result.stats);
    result.mesh = std::move(r.mesh);
    result.cell = r.cell;
    result.error = r.error;
    result.passes = r.passes;
  }
  if (progress) progress->finish();
  return result;
}

void report(const Extraction& e, const mesh::MeshStats& topology, size_t shells_kept,
            const PolygonizeOptions& o, double seconds, std::ostream& out) {
  out << "polygonize: " << topology.triangles << " triangles, " << topology.vertices
      << " vertices, cell " << number(e.cell);
  if (e.error >= 0.0) {
    out << " (" << e.passes << (e.passes == 1 ? " pass" : " passes")
        << ", max distance from the surface " << number(e.error) << ")";
  }
  out << "\n  boundary edges " << topology.boundary_edges << ", non-manifold edges "
      << topology.non_manifold_edges << ", inconsistently oriented edges "
      << topology.inconsistent_edges << ", components " << topology.connected_components
      << ", Euler characteristic " << topology.euler_characteristic() << "\n";
  if (o.outer) out << "  --outer: kept " << shells_kept << " shell(s) reachable from infinity\n";
  out << "  max |F - T| / T at the vertices: " << number(e.stats.max_residual);
  if (e.stats.unconverged) out << " (" << e.stats.unconverged << " at jumps of the field)";
  out << "\n";
  if (o.stats) {
    out << "  blocks " << e.stats.blocks << ", field evaluations " << e.stats.field_evaluations
        << "\n";
  }
  out << "wrote " << o.output << " in " << number(seconds) << " s\n";
}

}  // namespace

double smallest_radius(const scene::ConvolutionObject& object) {
  double r = std::numeric_limits<double>::infinity();
  for (const auto& c : object.meshes) r = std::min(r, c.weight.radius);
  for (const auto& c : object.segments) r = std::min(r, c.weight.radius);
  for (const auto& c : object.arcs) r = std::min(r, c.weight.radius);
  for (const auto& c : object.points) r = std::min(r, c.weight.radius);
  for (const auto& c : object.blob_spheres) r = std::min(r, c.weight.radius);
  for (const auto& c : object.blob_cylinders) r = std::min(r, c.weight.radius);
  return r;
}

int run_polygonize(const PolygonizeOptions& o, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  CommandStep step("checking the options", kFreeMemory);
  try {
    check_options(o);
    // The output's format is checked before the work, not after it.
    if (mesh::format_from_name(o.output).gzip) {
      throw InputError(kCommandLine, "cannot write .gz meshes: " + o.output);
    }
    check_writable_destination(o.output, "the mesh");
    step.now("reading " + o.input + " and building its field", kFreeMemory);
    const PreparedField prepared = o.object_name.empty() ? prepare_mesh(o) : prepare_scene(o);
    step.now("polygonizing", "give a larger --cell or --max-error");
    Extraction e = extract(prepared, o, err);
    size_t shells_kept = 0;
    if (o.outer) shells_kept = polygonize::keep_outer_shells(e.mesh);
    if (e.mesh.soup.triangles.empty()) {
      // The input's fault (a threshold no point reaches), so exit 2 like any bad input.
      err << "convray polygonize: the surface is empty: the field stays below T = "
          << number(prepared.source.threshold)
          << " everywhere; nothing written (lower --threshold or --offset, or raise --radius or "
             "--strength)\n";
      return 2;
    }
    step.now("writing " + o.output, "give a larger --cell or --max-error");
    mesh::save_mesh(e.mesh.soup, o.output,
                    o.ascii ? mesh::MeshEncoding::Ascii : mesh::MeshEncoding::Default,
                    &e.mesh.normals);
    const mesh::MeshStats topology = mesh::compute_stats(e.mesh.soup);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report(e, topology, shells_kept, o, seconds, out);
    return 0;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    err << "convray polygonize: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  } catch (const std::runtime_error& e) {
    err << "convray polygonize: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace convray::app
