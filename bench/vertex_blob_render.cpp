// convray's side of the vertex-blob comparison (bench/table1.sh, docs/benchmarks.md): the blob
// that bench/vertex_blob writes for POV-Ray, built as a ConvolutionObject of blob sphere
// components and rendered by render::render_scene (as `convray quick` renders) with the camera
// and light of table1.sh. Times the surface build and the render separately (wall clock), so the time of
// parsing the .pov file, once the scene parser exists, can be added to compare with POV-Ray.
//
//   vertex_blob_render MESH --radius R [--offset D] [--fit-box 400] [--size WxH]
//                      [--repeat K] [--threads N] [--reference] [-o PICTURE.png]
//
// Prints `key: value` lines: the blob, each repetition's build and render times (wall clock,
// and the render's CPU time summed over threads, steadier on a shared machine), the minimum
// of each over the repetitions, and the tracer's counters of the last repetition.
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "geometry/world.hpp"
#include "implicit/convolution_surface.hpp"
#include "mesh/load.hpp"
#include "core/image_file.hpp"
#include "render/render_scene.hpp"
#include "scene/quick_scene.hpp"
#include "vertex_blob_scene.hpp"

namespace {

using namespace convray;
using Clock = std::chrono::steady_clock;

struct Options {
  std::string mesh;
  double radius = 0.0, offset = -1.0, fit_box = 400.0;
  int width = 800, height = 600, repeat = 1, threads = 0;
  bool reference = false;
  std::string output;
};

constexpr const char* kUsage =
    "usage: vertex_blob_render MESH --radius R [--offset D] [--fit-box 400] [--size WxH]\n"
    "                          [--repeat K] [--threads N] [--reference] [-o PICTURE.png]\n";

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "vertex_blob_render: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

double number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') usage_error(what + ": expected a number, got '" + text + "'");
  return value;
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--reference") {
      o.reference = true;
      continue;
    }
    if (arg.empty() || arg[0] != '-') {
      o.mesh = arg;
      continue;
    }
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--radius") o.radius = number(value, arg);
    else if (arg == "--offset") o.offset = number(value, arg);
    else if (arg == "--fit-box") o.fit_box = number(value, arg);
    else if (arg == "--repeat") o.repeat = int(number(value, arg));
    else if (arg == "--threads") o.threads = int(number(value, arg));
    else if (arg == "-o") o.output = value;
    else if (arg == "--size") {
      if (std::sscanf(value.c_str(), "%dx%d", &o.width, &o.height) != 2) usage_error("--size WxH");
    } else {
      usage_error("unknown option '" + arg + "'");
    }
  }
  if (o.mesh.empty() || !(o.radius > 0.0)) usage_error("a mesh and --radius R > 0 are needed");
  if (o.offset < 0.0) o.offset = 0.5 * o.radius;
  if (o.repeat < 1 || o.width < 1 || o.height < 1) usage_error("bad --repeat or --size");
  return o;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// User and system time of every thread of the process: steadier than the wall clock on a
// machine that other jobs share (it does not count the time spent waiting for a core).
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The view and light of bench/table1.sh.
scene::Camera table1_camera(const Options& o) {
  return scene::look_at_camera({Vec3(-300, 200, -600), Vec3(0.0), 42.0, o.width, o.height});
}
const Vec3 kTable1Light(-300, 500, -500);

void print_counters(const render::RenderStats& s) {
  const TraceStats& t = s.trace;
  const double rays = double(std::max<uint64_t>(t.rays, 1));
  std::printf("camera rays: %llu\nshadow rays: %llu\nhits: %llu\nsurface queries: %llu\n",
              (unsigned long long)s.camera_rays, (unsigned long long)s.shadow_rays,
              (unsigned long long)s.hits, (unsigned long long)t.rays);
  std::printf("supports per query: %.2f\nfits per query: %.2f\nfield evaluations per query: "
              "%.2f\nroots: %llu\n",
              double(t.primitives) / rays, double(t.fits) / rays,
              double(t.field_evaluations) / rays, (unsigned long long)t.roots);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  try {
    std::optional<tbb::global_control> threads;
    if (o.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
    const mesh::LoadedMesh loaded = mesh::load_mesh(o.mesh);
    const bench::VertexBlob blob = bench::make_vertex_blob(loaded.soup, o.fit_box, o.radius,
                                                           o.offset);
    scene::ConvolutionObject object;
    object.blob_spheres.reserve(blob.centres.size());
    for (const Vec3& c : blob.centres) object.blob_spheres.push_back({c, {1.0, o.radius}});
    object.threshold = blob.threshold;
    std::printf("components: %zu\nradius: %.17g\nthreshold: %.17g\n", blob.centres.size(),
                o.radius, blob.threshold);

    const scene::Scene scene = scene::quick_scene(object, table1_camera(o), kTable1Light);
    render::RenderSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.ray_offset = 1e-5 * o.radius;  // as `convray quick`: hits are polished to rounding
    const implicit::Tracer tracer = o.reference ? implicit::Tracer::reference : implicit::Tracer::fast;
    double best_build = 1e300, best_render = 1e300, best_cpu = 1e300;
    for (int k = 0; k < o.repeat; ++k) {
      Clock::time_point start = Clock::now();
      const geometry::World world(scene, nullptr, tracer);
      const double build = seconds_since(start);
      start = Clock::now();
      const double cpu_start = cpu_seconds();
      const render::RenderResult result = render::render_scene(scene, world, settings);
      const double render_s = seconds_since(start), cpu = cpu_seconds() - cpu_start;
      std::printf("run %d: build %.3f s, render %.3f s, total %.3f s, render cpu %.3f s\n",
                  k + 1, build, render_s, build + render_s, cpu);
      best_cpu = std::min(best_cpu, cpu);
      best_build = std::min(best_build, build);
      best_render = std::min(best_render, render_s);
      if (k + 1 < o.repeat) continue;
      print_counters(result.stats);
      if (!o.output.empty()) {
        write_image_atomically(o.output, {o.width, o.height, result.film.rgb(),
                                                  PixelEncoding::linear});
      }
    }
    std::printf("best build: %.3f s\nbest render: %.3f s\nbest total: %.3f s\n"
                "best render cpu: %.3f s\n",
                best_build, best_render, best_build + best_render, best_cpu);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vertex_blob_render: %s\n", error.what());
    return 1;
  }
}
