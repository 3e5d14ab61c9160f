#include "app/command_render.hpp"

#include <tbb/global_control.h>

#include <chrono>
#include <memory>
#include <new>
#include <stdexcept>
#include <ostream>

#include "geometry/world.hpp"
#include "render/image_file.hpp"
#include "render/progress.hpp"
#include "render/render_scene.hpp"
#include "sdl/parser.hpp"
#include "util/error.hpp"

namespace convray::app {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

sdl::ParseOptions parse_options(const RenderOptions& o) {
  sdl::ParseOptions p;
  p.image_width = o.width;
  p.image_height = o.height;
  p.clock = o.clock;
  p.library_paths = o.library_paths;
  p.declares = o.declares;
  return p;
}

render::RenderSettings render_settings(const RenderOptions& o) {
  render::RenderSettings s;
  s.width = o.width;
  s.height = o.height;
  s.antialias = o.antialias;
  s.aa_threshold = o.aa_threshold;
  s.aa_depth = o.aa_depth;
  s.jitter = o.jitter;
  s.jitter_amount = o.jitter_amount;
  return s;
}

struct PhaseTimes {
  double parse = 0, build = 0, render = 0, write = 0;
  double total() const { return parse + build + render + write; }
};

void print_stats(const render::RenderStats& s, const PhaseTimes& t, std::ostream& out) {
  out << "rays: camera " << s.camera_rays << ", shadow " << s.shadow_rays << "\n"
      << "camera rays that hit: " << s.hits << "\n"
      << "field evaluations: " << s.trace.field_evaluations << ", roots: " << s.trace.roots
      << ", fits: " << s.trace.fits << "\n"
      << "time parse: " << t.parse << " s\n"
      << "time build: " << t.build << " s\n"
      << "time render: " << t.render << " s\n"
      << "time write: " << t.write << " s\n"
      << "time total: " << t.total() << " s\n";
}

void render_scene_file(const RenderOptions& o, std::ostream& out, std::ostream& err) {
  // Everything that can be checked before the work starts is checked first.
  render::check_image_destination(o.output);
  std::unique_ptr<tbb::global_control> threads;
  if (o.threads > 0) {
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    size_t(o.threads));
  }
  PhaseTimes times;
  Clock::time_point start = Clock::now();
  const sdl::ParseResult parsed = sdl::parse_file(o.scene, parse_options(o));
  for (const std::string& warning : parsed.warnings) err << warning << "\n";
  times.parse = seconds_since(start);

  start = Clock::now();
  const geometry::World world(parsed.scene);
  times.build = seconds_since(start);

  start = Clock::now();
  // A bar only where someone watches: on a terminal, never into a pipe or a log file.
  render::Progress progress("render", uint64_t(o.width) * uint64_t(o.height), err,
                            render::Progress::stderr_is_terminal());
  const render::RenderResult result =
      render::render_scene(parsed.scene, world, render_settings(o), &progress);
  times.render = seconds_since(start);

  start = Clock::now();
  render::write_image_atomically(
      o.output, {o.width, o.height, result.film.rgb(), render::PixelEncoding::linear});
  times.write = seconds_since(start);

  if (!o.quiet) {
    out << "convray: " << o.scene << ": wrote " << o.output << " (" << o.width << "x" << o.height
        << ", " << parsed.scene.objects.size() << " objects, " << times.total() << " s)\n";
  }
  if (o.stats) print_stats(result.stats, times, out);
}

}  // namespace

int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  try {
    render_scene_file(options, out, err);
    return 0;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    // What the scene asked for cannot be rendered (a degenerate camera, say): still its fault.
    err << options.scene << ": " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    err << "convray: out of memory (try a smaller image or scene)\n";
    return 1;
  } catch (const std::exception& e) {
    err << "convray: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace convray::app
