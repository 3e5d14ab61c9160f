// convray.render(scene, width, height, clock, **options): a scene file or scene text rendered
// into a NumPy image by the renderer `convray SCENE.pov` runs, with the command line's options
// parsed by the command line's own parser (app/render_options.hpp).
#include <pybind11/numpy.h>

#include <tbb/task_arena.h>

#include <cmath>
#include <optional>
#include <memory>

#include "app/command_render.hpp"
#include "app/ini_file.hpp"
#include "app/render_options.hpp"
#include "app/size_check.hpp"
#include "core/image_file.hpp"
#include "geometry/world.hpp"
#include "implicit/support_cache.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"
#include "render/render_scene.hpp"
#include "sdl/mesh_library.hpp"
#include "sdl/parser.hpp"

namespace convray::python {

namespace {

// What errors in scene text are reported at: "<string>:LINE:COL: ...".
constexpr const char* kTextName = "<string>";

struct SceneSource {
  bool is_text = false;
  std::string text;  // the scene itself, or its file name
};

// A str with a line break or a brace is scene text; any other str, or an os.PathLike, names
// a file.
SceneSource scene_source(const py::handle& scene) {
  if (!py::isinstance<py::str>(scene)) return {false, path_from(scene)};
  std::string s = scene.cast<std::string>();
  const bool text = s.find_first_of("\n{") != std::string::npos;
  return {text, std::move(s)};
}

std::string number_text(const py::handle& v, const std::string& key) {
  if (py::isinstance<py::bool_>(v) ||
      !(py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v))) {
    throw py::type_error("render(): " + key + " must be a number, got " +
                         py::repr(v).cast<std::string>());
  }
  return py::repr(v).cast<std::string>();
}

// antialias=True / 0.3, jitter=True / 0.5: the switch alone, or with its value.
void optional_value_option(std::vector<std::string>& args, const std::string& option,
                           const py::handle& v, const std::string& key) {
  if (py::isinstance<py::bool_>(v)) {
    if (v.cast<bool>()) args.push_back(option);
    return;
  }
  args.push_back(option + "=" + number_text(v, key));
}

// library="dir" or ["a", "b"]: the option once per folder.
void folder_option(std::vector<std::string>& args, const std::string& option,
                   const py::handle& v) {
  if (py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__")) {
    args.push_back(option + "=" + path_from(v));
    return;
  }
  for (const py::handle item : v) args.push_back(option + "=" + path_from(item));
}

constexpr const char* kOptionNames =
    "antialias, aa_depth, jitter, threads, library, allow_read, allow_read_anywhere, declare, "
    "force, linear";

// The keyword options as the command line's long options (docs/python.md lists them).
void add_options(std::vector<std::string>& args, const py::kwargs& options) {
  for (const auto& [key_handle, v] : options) {
    const std::string key = key_handle.cast<std::string>();
    if (key == "linear") continue;
    if (key == "antialias" || key == "jitter") {
      optional_value_option(args, "--" + key, v, key);
    } else if (key == "aa_depth" || key == "threads") {
      args.push_back((key == "aa_depth" ? "--aa-depth=" : "--threads=") + number_text(v, key));
    } else if (key == "library" || key == "allow_read") {
      folder_option(args, key == "library" ? "--library" : "--allow-read", v);
    } else if (key == "allow_read_anywhere" || key == "force") {
      if (py::cast<bool>(v)) args.push_back(key == "force" ? "--force" : "--allow-read-anywhere");
    } else if (key == "declare") {
      for (const auto& [id, value] : v.cast<py::dict>()) {
        args.push_back("--declare=" + id.cast<std::string>() + "=" + number_text(value, key));
      }
    } else {
      throw py::type_error("render() got an unexpected keyword argument '" + key +
                           "' (its options: " + kOptionNames + ")");
    }
  }
}

app::RenderOptions render_options(const SceneSource& source, int width, int height, double clock,
                                  const py::kwargs& options) {
  if (!std::isfinite(clock)) throw py::value_error("clock must be finite");
  if (!source.is_text && app::is_ini_argument(source.text)) {
    // An INI file describes frames and files to write; render() makes one picture.
    throw py::value_error("render() takes a scene, not an INI file: " + source.text +
                          " (render its Input_File_Name with clock=...)");
  }
  std::vector<std::string> args = {source.is_text ? kTextName : source.text,
                                   "--width=" + std::to_string(width),
                                   "--height=" + std::to_string(height),
                                   "--clock=" + py::repr(py::float_(clock)).cast<std::string>()};
  add_options(args, options);
  return app::parse_render_arguments(args);  // UsageError: a ValueError, the CLI's words
}

// Parses and renders on the calling thread's TBB arena (threads= limits this call only).
render::RenderResult render_scene(const SceneSource& source, const app::RenderOptions& o,
                                  std::vector<std::string>& warnings) {
  const app::FramePlan plan = app::plan_frames(o.animation);
  app::refuse_unless_image_fits(o.width, o.height, "give a smaller width and height", o.force);
  const sdl::ParseOptions parse_options =
      app::scene_parse_options(o, plan.frames[0], std::make_shared<sdl::MeshLibrary>());
  const sdl::ParseResult parsed =
      source.is_text ? sdl::parse_string(source.text, kTextName, parse_options)
                     : reading(o.scene, [&] { return sdl::parse_file(o.scene, parse_options); });
  warnings = parsed.warnings;
  implicit::SupportCache hierarchies;
  const geometry::World world(parsed.scene, &hierarchies);
  try {
    return render::render_scene(parsed.scene, world, app::render_settings(o));
  } catch (const std::invalid_argument& e) {  // a degenerate camera: the scene's fault
    throw InputError({o.scene}, e.what());
  }
}

// The film as (H, W, 4) float32: sRGB-encoded as the PNG stores it (before quantising), or
// the linear values themselves; alpha 1 (the renderer has no transparent background).
py::array_t<float> image_array(const render::Film& film, bool linear) {
  const int w = film.width(), h = film.height();
  py::array_t<float> image({py::ssize_t(h), py::ssize_t(w), py::ssize_t(4)});
  auto out = image.mutable_unchecked<3>();
  const std::span<const float> rgb = film.rgb();
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const size_t at = 3 * (size_t(j) * size_t(w) + size_t(i));
      for (int k = 0; k < 3; ++k) {
        const float v = rgb[at + size_t(k)];
        out(j, i, k) = linear ? v : encode_srgb(v);
      }
      out(j, i, 3) = 1.0f;
    }
  }
  return image;
}

py::array_t<float> render(const py::object& scene, int width, int height, double clock,
                          const py::kwargs& options) {
  const SceneSource source = scene_source(scene);
  const app::RenderOptions o = render_options(source, width, height, clock, options);
  const bool linear = options.contains("linear") && py::cast<bool>(options["linear"]);
  std::vector<std::string> warnings;
  std::optional<render::RenderResult> result;
  {
    py::gil_scoped_release release;
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    arena.execute([&] { result.emplace(render_scene(source, o, warnings)); });
  }
  for (const std::string& w : warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  }
  return image_array(result->film, linear);
}

}  // namespace

void bind_render_function(py::module_& m) {
  m.def("render", &render, py::arg("scene"), py::arg("width") = 800, py::arg("height") = 600,
        py::arg("clock") = 0.0,
        "render(scene, width=800, height=600, clock=0.0, **options) -> (H, W, 4) float32\n\n"
        "Renders a POV-Ray-style scene as `convray SCENE.pov` does. `scene` is a file name "
        "(str or os.PathLike) or the scene text itself (a str with a line break or a brace; "
        "its errors are reported at '<string>:LINE:COL'). The pixels are sRGB-encoded in "
        "[0, 1], exactly what the command line's PNG stores before rounding to 8 bits "
        "(byte = round(255 v)); linear=True gives the linear values instead. Alpha is 1.\n"
        "Options, as the command line's: antialias=True or a threshold (--antialias T), "
        "aa_depth=N, jitter=True or an amount, threads=N (this call only), library=folder(s) "
        "(-L), allow_read=folder(s), allow_read_anywhere=True, declare={'ID': value}, "
        "force=True. Scene errors raise convray.InputError with the command line's message "
        "(file:line:col, the line and a caret); a missing file FileNotFoundError; warnings "
        "are Python UserWarnings.");
}

}  // namespace convray::python
