#include "app/command_render.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <memory>
#include <new>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "app/command_step.hpp"
#include "app/frame_names.hpp"
#include "app/parse_hooks.hpp"
#include "app/size_check.hpp"
#include "app/video.hpp"
#include "display/preview.hpp"
#include "geometry/world.hpp"
#include "implicit/support_cache.hpp"
#include "core/image_file.hpp"
#include "core/progress.hpp"
#include "render/render_scene.hpp"
#include "sdl/mesh_library.hpp"
#include "sdl/parser.hpp"
#include "util/error.hpp"

namespace convray::app {

namespace {

int clamp_to_int(long long v) {
  return int(
      std::clamp<long long>(v, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

}  // namespace

sdl::ParseOptions scene_parse_options(const RenderOptions& o, const FrameClock& frame,
                                      std::shared_ptr<sdl::MeshLibrary> meshes) {
  sdl::ParseOptions p;
  p.mesh_library = std::move(meshes);
  p.image_width = o.width;
  p.image_height = o.height;
  p.clock = frame.clock;
  p.clock_delta = frame.clock_delta;
  p.clock_on = frame.clock_on;
  p.frame_number = clamp_to_int(frame.frame_number);
  p.initial_frame = clamp_to_int(frame.initial_frame);
  p.final_frame = clamp_to_int(frame.final_frame);
  p.initial_clock = frame.initial_clock;
  p.final_clock = frame.final_clock;
  p.library_paths = o.library_paths;
  p.read_folders = o.read_folders;
  p.read_folders.push_back(std::filesystem::path(o.output).parent_path().string());
  p.write_folder = std::filesystem::path(o.output).parent_path().string();
  if (p.write_folder.empty()) p.write_folder = ".";
  p.read_anywhere = o.read_anywhere;
  p.declares = o.declares;
  use_program_hooks(p);
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
  s.window = o.window;
  return s;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct PhaseTimes {
  double parse = 0, build = 0, render = 0, write = 0;
  double total() const { return parse + build + render + write; }
};

void print_stats(const render::RenderStats& s, const PhaseTimes& t,
                 const implicit::SupportCache& cache, std::ostream& out) {
  const implicit::SupportCache::Counts reuse = cache.counts();
  out << "mesh hierarchies: " << reuse.builds << " built, " << reuse.reuses
      << " reused (this animation so far)\n"
      << "rays: camera " << s.camera_rays << ", shadow " << s.shadow_rays << "\n"
      << "camera rays that hit: " << s.hits << "\n"
      << "field evaluations: " << s.trace.field_evaluations << ", roots: " << s.trace.roots
      << ", fits: " << s.trace.fits << ", shadow rays settled inside: " << s.trace.shadows_settled
      << "\n"
      << "time parse: " << t.parse << " s\n"
      << "time build: " << t.build << " s\n"
      << "time render: " << t.render << " s\n"
      << "time write: " << t.write << " s\n"
      << "time total: " << t.total() << " s\n";
}

// One animation's frames rendered in order; everything a frame needs that does not change
// from frame to frame lives here: the mesh files read so far, and the hierarchies over the
// supports of mesh components, which a frame with the same mesh, radius and placement (or a
// rigid move of it) takes over from the frame before (docs/animations.md).
class FrameRenderer {
 public:
  FrameRenderer(const RenderOptions& options, const FramePlan& plan, std::ostream& out,
                std::ostream& err, CommandStep& step, display::Preview* preview)
      : o_(options), plan_(plan), out_(out), err_(err), step_(step), preview_(preview) {}

  // Parses the frame's scene, builds it, renders it and writes `file`; with a preview window,
  // on a thread of its own while this one keeps the window live.
  void render(const FrameClock& frame, size_t position, const std::string& file) {
    if (!preview_) return render_here(frame, position, file);
    const std::string label = plan_.animated ? progress_label(frame, position) : "";
    preview_->run(label, [&] { render_here(frame, position, file); });
  }

 private:
  void render_here(const FrameClock& frame, size_t position, const std::string& file) {
    PhaseTimes times;
    Clock::time_point start = Clock::now();
    const std::string label = plan_.animated ? " (" + progress_label(frame, position) + ")" : "";
    step_.now("parsing " + o_.scene + label, kFreeMemory);
    const sdl::ParseResult parsed =
        sdl::parse_file(o_.scene, scene_parse_options(o_, frame, meshes_));
    for (const std::string& warning : parsed.warnings) err_ << warning << "\n";
    times.parse = seconds_since(start);

    start = Clock::now();
    step_.now("building the scene" + label, "give a scene with fewer or smaller objects");
    const geometry::World world(parsed.scene, &hierarchies_);
    hierarchies_.next_frame();  // keeps what this frame used, drops the rest
    times.build = seconds_since(start);

    start = Clock::now();
    step_.now("rendering the " + std::to_string(o_.width) + "x" + std::to_string(o_.height) +
                  " image" + label, "give a smaller +W and +H");
    // A bar only where someone watches: on a terminal, never into a pipe or a log file.
    const uint64_t pixels =
        o_.window ? o_.window->pixels() : uint64_t(o_.width) * uint64_t(o_.height);
    Progress progress(progress_label(frame, position), pixels, err_,
                      Progress::stderr_is_terminal());
    const render::RenderResult result =
        render::render_scene(parsed.scene, world, render_settings(o_), &progress, preview_);
    times.render = seconds_since(start);
    // The finished film replaces the tiles: what the window shows is then what is written.
    if (preview_) preview_->show_picture(result.film.rgb());

    start = Clock::now();
    step_.now("writing " + file, "give a smaller +W and +H");
    write_image_atomically(
        file, {o_.width, o_.height, result.film.rgb(), PixelEncoding::linear});
    times.write = seconds_since(start);
    report(frame, position, file, parsed.scene.objects.size(), times);
    if (o_.stats) print_stats(result.stats, times, hierarchies_, out_);
  }

  std::string progress_label(const FrameClock& frame, size_t position) const {
    if (!plan_.animated) return "render";
    return "frame " + std::to_string(frame.frame_number) + " (" + std::to_string(position + 1) +
           "/" + std::to_string(plan_.frames.size()) + ")";
  }

  void report(const FrameClock& frame, size_t position, const std::string& file, size_t objects,
              const PhaseTimes& times) const {
    if (o_.quiet) return;
    if (!plan_.animated) {
      out_ << "convray: " << o_.scene << ": wrote " << file << " (" << o_.width << "x" << o_.height
           << window_text() << ", " << objects << " objects, " << times.total() << " s)\n";
      return;
    }
    out_ << "convray: " << progress_label(frame, position) << ", clock " << frame.clock
         << ": wrote " << file << " (" << objects << " objects, " << std::fixed
         << std::setprecision(3) << times.total() << " s)\n"
         << std::defaultfloat << std::setprecision(6);
  }

  // ", columns 1-64, rows 10-20" for a partial render (numbered from 1, as POV-Ray says them).
  std::string window_text() const {
    if (!o_.window) return "";
    const render::PixelWindow& w = *o_.window;
    return ", columns " + std::to_string(w.x0 + 1) + "-" + std::to_string(w.x1) + ", rows " +
           std::to_string(w.y0 + 1) + "-" + std::to_string(w.y1);
  }

  const RenderOptions& o_;
  const FramePlan& plan_;
  std::shared_ptr<sdl::MeshLibrary> meshes_ = std::make_shared<sdl::MeshLibrary>();
  implicit::SupportCache hierarchies_;
  std::ostream& out_;
  std::ostream& err_;
  CommandStep& step_;
  display::Preview* preview_;  // null: no +D, or no display to show it on
};

// Everything that can be checked before the work starts: the destination, the image's memory,
// the frames' disk space, the video tool.
void check_before_rendering(const RenderOptions& o, const FramePlan& plan) {
  if (o.output_is_folder) {
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(o.output).parent_path(), error);
    if (error) {
      throw InputError({o.output}, "cannot create the output folder: " + error.message());
    }
  }
  check_image_destination(o.output);
  refuse_unless_image_fits(o.width, o.height, "give a smaller +W and +H", o.force);
  if (plan.animated) {
    refuse_unless_frames_fit_on_disk(plan.frames.size(), o.width, o.height,
                                     image_format_for(o.output).bits, o.output, o.force);
  }
  if (!o.video.empty()) check_video_tools(o.video);
}

// A library folder that is not there finds nothing: said once, then the render goes on (as
// POV-Ray goes on), so that a mistyped -L does not pass without a word.
// A start after its end renders nothing: POV-Ray writes the black picture without a word; a
// word is said here, since it is seldom what was meant.
void warn_about_an_empty_window(const RenderOptions& o, std::ostream& err) {
  if (o.window && o.window->empty()) {
    err << "convray: warning: the partial image's start is after its end (+SC/+EC, +SR/+ER): "
           "nothing is rendered and the picture is black, as POV-Ray does\n";
  }
}

void warn_about_missing_library_folders(const RenderOptions& o, std::ostream& err) {
  for (const std::string& folder : o.library_paths) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) {
      err << "convray: warning: library path '" << folder << "' is not a folder; ignored\n";
    }
  }
}

display::PreviewOptions preview_options(const RenderOptions& o) {
  display::PreviewOptions p;
  p.scene = o.scene;
  p.width = o.width;
  p.height = o.height;
  p.window = o.window;
  return p;
}

std::string file_of(const RenderOptions& o, const FramePlan& plan, const FrameClock& frame) {
  return plan.animated ? frame_file_name(o.output, frame.frame_number, plan.name_digits) : o.output;
}

// --list-frames: "number<TAB>clock<TAB>file" per frame, clocks to 17 significant digits.
void list_frames(const RenderOptions& o, const FramePlan& plan, std::ostream& out) {
  out << std::setprecision(17);
  for (const FrameClock& frame : plan.frames) {
    out << frame.frame_number << "\t" << frame.clock << "\t" << file_of(o, plan, frame) << "\n";
  }
}

void render_frames(const RenderOptions& o, std::ostream& out, std::ostream& err,
                   CommandStep& step) {
  const FramePlan plan = plan_frames(o.animation);
  for (const std::string& warning : plan.warnings) err << "convray: warning: " << warning << "\n";
  if (o.list_frames) return list_frames(o, plan, out);
  check_before_rendering(o, plan);
  warn_about_missing_library_folders(o, err);
  warn_about_an_empty_window(o, err);
  std::unique_ptr<tbb::global_control> threads;
  if (o.threads > 0) {
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    size_t(o.threads));
  }
  std::unique_ptr<display::Preview> preview;
  if (o.display) preview = display::Preview::open(preview_options(o), err);
  const Clock::time_point start = Clock::now();
  FrameRenderer renderer(o, plan, out, err, step, preview.get());
  std::vector<std::string> files;  // for the video only: millions of frames need no list
  size_t skipped = 0;
  for (size_t i = 0; i < plan.frames.size(); ++i) {
    const FrameClock frame = plan.frames[i];
    const std::string file = file_of(o, plan, frame);
    if (!o.video.empty()) files.push_back(file);
    if (o.continue_trace && image_file_is_complete(file, o.width, o.height)) {
      ++skipped;
      if (!o.quiet) out << "convray: " << file << " is complete; skipped (+C)\n";
      continue;
    }
    renderer.render(frame, i, file);
  }
  if (plan.animated && !o.quiet) {
    out << "convray: " << o.scene << ": " << plan.frames.size() - skipped << " frames rendered"
        << (skipped ? ", " + std::to_string(skipped) + " already complete" : std::string()) << " ("
        << seconds_since(start) << " s)\n";
  }
  if (!o.video.empty()) {
    step.now("assembling " + o.video, kFreeMemory);
    assemble_video(files, o.video, o.video_fps);
    if (!o.quiet) out << "convray: wrote " << o.video << " (" << files.size() << " frames)\n";
  }
  if (preview && o.pause_when_done && preview->seen()) {
    if (!o.quiet) err << "convray: +P: press a key in the preview window, or close it\n";
    preview->wait_until_dismissed();
  }
}

}  // namespace

int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  CommandStep step("planning the frames", "give fewer frames (+KFI, +KFF)");
  try {
    render_frames(options, out, err, step);
    return 0;
  } catch (const render::RenderCancelled&) {
    // The file being rendered was not written (an earlier one of its name is intact); frames
    // already written stay.
    err << "convray: " << options.scene
        << ": render stopped: the preview window was closed (or Escape or q pressed in it); "
           "the image being rendered was not written\n";
    return 1;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    err << "convray: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    // What the scene asked for cannot be rendered (a degenerate camera, say): still its fault.
    err << options.scene << ": " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  } catch (const std::exception& e) {
    err << "convray: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace convray::app
