// convray command line: parse the arguments, hand each subcommand to its run_* function.
#include <charconv>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/command_distance.hpp"
#include "app/command_field.hpp"
#include "app/command_info.hpp"
#include "app/command_polygonize.hpp"
#include "app/command_quick.hpp"
#include "app/command_step.hpp"
#include "app/command_view.hpp"
#include "app/malloc_tunables.hpp"
#include "app/command_render.hpp"
#include "app/command_slice.hpp"
#include "app/render_options.hpp"
#include "util/error.hpp"

namespace {

constexpr const char* kDescription =
    "convray - convolution surfaces of polygon soups and skeletons, in closed form.\n"
    "\n"
    "Render a scene:   convray SCENE.pov [options]   (run 'convray SCENE.pov --help' for them)\n"
    "  or as POV-Ray:  convray +ISCENE.pov +OOUT.png +W800 +H600 +A0.3 -D +WT2\n"
    "\n"
    "Examples:\n"
    "  convray scenes/soup.pov -o soup.png\n"
    "  convray info scenes/models/soup.obj\n"
    "  echo '0 0 0' | convray field --mesh scenes/models/soup.obj --radius 0.2\n"
    "  echo '0 0 0' | convray field scenes/soup.pov --object Soup\n"
    "  convray slice scenes/models/soup.obj --radius 0.25 --offset 0.1 -o slice.png\n"
    "  convray quick scenes/models/soup.obj --radius 0.2 -o soup.png\n"
    "  convray view scenes/soup.pov   (a window: edit, save, see; docs/view.md)\n"
    "  convray polygonize scenes/models/soup.obj --radius 0.25 --offset 0.1 -o soup_surface.obj\n"
    "  convray distance scenes/models/soup.obj soup_surface.obj\n";

// The whole text as a decimal number (std::from_chars: no hex, no trailing junk, no throw).
std::optional<double> parse_number(const std::string& text) {
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin < end && *begin == '+') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

CLI::Validator number_check(bool positive) {
  return CLI::Validator(
      [positive](const std::string& text) -> std::string {
        const std::optional<double> v = parse_number(text);
        if (!v) return "expected a number, got '" + text + "'";
        if (!std::isfinite(*v)) return "must be finite, got '" + text + "'";
        if (positive && !(*v > 0.0)) return "must be > 0, got '" + text + "'";
        return "";
      },
      positive ? "POSITIVE" : "FINITE");
}

// Radii and sizes; strengths and coordinates.
const CLI::Validator kPositive = number_check(true);
const CLI::Validator kFinite = number_check(false);

// Camera angles: strictly between 0 and 180 degrees, as POV-Ray's camera `angle`.
const CLI::Validator kAngle(
    [](const std::string& text) -> std::string {
      const std::optional<double> v = parse_number(text);
      if (v && *v > 0.0 && *v < 180.0) return "";
      return "expected degrees with 0 < angle < 180, got '" + text + "'";
    },
    "DEGREES");

// "X,Y,Z": three finite numbers separated by single commas, nothing else (no spaces).
std::optional<convray::Vec3> parse_vector(const std::string& text) {
  convray::Vec3 v;
  size_t begin = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const size_t comma = text.find(',', begin);
    if ((axis < 2) != (comma != std::string::npos)) return std::nullopt;
    const std::optional<double> x = parse_number(text.substr(begin, comma - begin));
    if (!x || !std::isfinite(*x)) return std::nullopt;
    v[axis] = *x;
    begin = comma + 1;
  }
  return v;
}

// Points and positions: --camera, --look-at, --light.
const CLI::Validator kVector(
    [](const std::string& text) -> std::string {
      if (parse_vector(text)) return "";
      return "expected X,Y,Z (three finite numbers, no spaces), got '" + text + "'";
    },
    "X,Y,Z");

// "WIDTHxHEIGHT", each 1..32768.
bool parse_size(const std::string& text, int& width, int& height) {
  int consumed = 0;
  return std::sscanf(text.c_str(), "%dx%d%n", &width, &height, &consumed) == 2 &&
         consumed == int(text.size()) && width >= 1 && height >= 1 && width <= 32768 &&
         height <= 32768;
}

// `convray quick`: the options CLI11 fills in, and those it leaves as text for
// finish_quick_options: the size, and the vectors (which their validator has checked).
struct QuickArguments {
  convray::app::QuickOptions options;
  std::string size = "800x600", camera, look_at, light;
};

CLI::App* add_quick_command(CLI::App& app, QuickArguments& q) {
  CLI::App* quick = app.add_subcommand(
      "quick",
      "Render a picture of a mesh's convolution surface: every triangle (and every segment and "
      "point of a file's polylines, edges or point cloud) convolved with the "
      "kernel (1 - r^2/R^2)^2, the surface F = T ray traced through a POV-Ray-style perspective "
      "camera, lit by one point light with hard shadows and Phong shading. Tiles run on all "
      "cores; a progress bar shows on a terminal. The image appears complete or not at all. "
      "Lengths are in the model's units (after --fit-box); coordinates are POV-Ray's "
      "(left-handed, y up).\n"
      "Example: convray quick bunny.ply.gz --fit-box 400 --radius 2 -o bunny.png");
  quick->add_option("MESH", q.options.mesh_path, "mesh file: .obj .ply .stl .off, optionally .gz")
      ->required();
  quick->add_option("--radius", q.options.radius,
                    "kernel radius R, model units (default: what 'convray info' advises: the "
                    "smaller of the mean edge length (segment length; twice the point spacing) "
                    "and a tenth of the largest extent)")
      ->check(kPositive);
  auto* offset = quick->add_option("--offset", q.options.offset,
                                   "surface at distance D from flat parts of the mesh (from "
                                   "segments for a line set, points for a point cloud), model "
                                   "units, 0 <= D < R (default R/2)");
  offset->check(kFinite);
  quick->add_option("--threshold", q.options.threshold,
                    "raw threshold T > 0 of the surface F = T, instead of --offset")
      ->check(kPositive)
      ->excludes(offset);
  quick->add_option("--size", q.size,
                    "image size in pixels, WIDTHxHEIGHT, each 1..32768 (default 800x600)");
  quick->add_option("--fit-box", q.options.fit_box,
                    "scale the model uniformly so its largest extent is S, model units, and "
                    "centre its box at the origin; 400 fills the paper's (-200..200)^3 "
                    "(default: the model as is)")
      ->check(kPositive);
  auto* camera = quick->add_option("--camera", q.camera,
                                   "camera location X,Y,Z (default: framed automatically, from "
                                   "the -z side and a little above, the whole surface in view)");
  auto* look_at = quick->add_option("--look-at", q.look_at, "point X,Y,Z the camera looks at");
  camera->check(kVector)->needs(look_at);
  look_at->check(kVector)->needs(camera);
  quick->add_option("--angle", q.options.angle,
                    "horizontal field of view in degrees, as POV-Ray's camera angle (default 40)")
      ->check(kAngle);
  quick->add_option("--light", q.light,
                    "point light position X,Y,Z (default: above, left of and behind the camera)")
      ->check(kVector);
  quick->add_flag("--reference", q.options.reference,
                  "trace with the slow exact reference tracer instead of the fast path");
  quick->add_flag("--stats", q.options.stats,
                  "after the render, print rays, primitives per ray, field evaluations, roots, "
                  "fits, subdivisions, fallbacks, surface memory and the time of each phase");
  quick->add_flag("--force", q.options.force,
                  "render even when the image's estimated memory exceeds what this process "
                  "can have (physical memory, ulimit -v)");
  quick->add_option("-o,--output", q.options.output,
                    "image file: .png 8-bit sRGB, .tif 16-bit sRGB, .exr linear float "
                    "(default quick.png)");
  return quick;
}

void finish_quick_options(QuickArguments& q) {
  if (!parse_size(q.size, q.options.width, q.options.height)) {
    throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 800x600, got " + q.size);
  }
  if (!q.camera.empty()) q.options.camera = parse_vector(q.camera);
  if (!q.look_at.empty()) q.options.look_at = parse_vector(q.look_at);
  if (!q.light.empty()) q.options.light = parse_vector(q.light);
}

bool is_command(const std::string& word) {
  return word == "info" || word == "field" || word == "slice" || word == "quick" ||
         word == "polygonize" || word == "distance" || word == "view";
}

// `convray SCENE.pov ...` and `convray +ISCENE.pov ...`: not a subcommand, so the render.
int render_main(const std::vector<std::string>& args) {
  for (const std::string& arg : args) {
    if (arg == "-h" || arg == "--help") {
      std::cout << convray::app::kRenderUsage;
      return 0;
    }
  }
  convray::app::RenderOptions options;
  try {
    options = convray::app::parse_render_arguments(args);
  } catch (const convray::app::UsageError& e) {
    std::cerr << "convray: " << e.what() << "\nRun 'convray --help' for usage.\n";
    return 2;
  } catch (const convray::InputError& e) {  // a bad line in an INI file: file:line:col
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {  // the frames are planned here, up to 10^7 of them
    return convray::app::CommandStep("planning the frames", "give fewer frames (+KFI, +KFF)")
        .out_of_memory(std::cerr);
  }
  const std::filesystem::path scene(options.scene);
  if (!scene.has_extension() && !std::filesystem::exists(scene)) {
    std::cerr << "convray: unknown command '" << options.scene
              << "' (expected info, field, slice, quick, polygonize, distance, view or a "
                 "scene file)\n"
                 "Run 'convray --help' for usage.\n";
    return 2;
  }
  return convray::app::run_render(options, std::cout, std::cerr);
}

// `convray polygonize`: the options straight into PolygonizeOptions.
CLI::App* add_polygonize_command(CLI::App& app, convray::app::PolygonizeOptions& p) {
  CLI::App* cmd = app.add_subcommand(
      "polygonize",
      "Write the convolution surface F = T as a closed, 2-manifold, consistently oriented "
      "triangle mesh without self-intersections: of a mesh's triangles (convolved with "
      "(1 - r^2/R^2)^2), or of a convolution object or blob declared in a scene (--object). "
      "Marching tetrahedra on a sparse lattice that only visits the primitives' supports; "
      "every vertex on the exact surface (|F - T| <= 1e-6 T), normals from the exact gradient. "
      "By default the lattice is refined until every triangle's centre is within R/50 of the "
      "surface. Example: convray polygonize bunny.obj --radius 0.004 --offset 0.002 --outer "
      "-o bunny_closed.obj");
  cmd->add_option("INPUT", p.input, "mesh file (.obj .ply .stl .off, optionally .gz), or a "
                  "scene file with --object")->required();
  cmd->add_option("--object", p.object_name, "the declared convolution object or blob of the "
                  "scene, placed by its transforms");
  cmd->add_option("-L,--library", p.library_paths,
                  "also search this folder for the scene's #include and mesh files");
  cmd->add_option("--allow-read", p.read_folders,
                  "also let the scene read files in this folder (POV-Ray's I/O restrictions)");
  cmd->add_option("--radius", p.radius, "meshes: kernel radius R (default: the advised "
                  "radius of 'convray info')")->check(kPositive);
  cmd->add_option("--strength", p.strength, "meshes: strength s (default 1)")->check(kPositive);
  cmd->add_option("--fit-box", p.fit_box, "meshes: first scale the largest extent to SIZE, "
                  "centred at the origin (the paper's protocol: 400)")->check(kPositive);
  auto* offset = cmd->add_option("--offset", p.offset,
                                 "meshes: surface at distance D from flat regions (from segments "
                                 "for a line set, points for a point cloud; default R/2)");
  offset->check(kFinite);
  cmd->add_option("--threshold", p.threshold, "the raw threshold T (overrides --offset, or a "
                  "scene object's threshold)")->check(kFinite)->excludes(offset);
  auto* cell = cmd->add_option("--cell", p.cell, "lattice spacing H")->check(kPositive);
  cmd->add_option("--max-error", p.max_error, "refine the lattice until every triangle's centre "
                  "is within E of the surface (default R/50)")->check(kPositive)->excludes(cell);
  cmd->add_flag("--outer", p.outer, "keep only the shells reachable from infinity (a closed "
                "input otherwise gives an outer and an inner shell)");
  cmd->add_flag("--stats", p.stats, "also print blocks visited and field evaluations");
  cmd->add_flag("--ascii", p.ascii, "PLY and STL as text (default binary)");
  cmd->add_flag("--force", p.force, "run a lattice pass even when its estimated memory "
                "exceeds what this process can have (physical memory, ulimit -v)");
  cmd->add_option("-o,--output", p.output, "mesh file to write: .obj .ply .stl (.off)")
      ->required();
  return cmd;
}

CLI::App* add_distance_command(CLI::App& app, convray::app::DistanceOptions& d) {
  CLI::App* distance = app.add_subcommand(
      "distance",
      "How far apart two meshes are: the one-sided Hausdorff distances A -> B and "
      "B -> A (the largest distance from a point of one to the other), the "
      "symmetric one (the larger), and the mean distances, measured at the vertices "
      "and at surface samples spread evenly by area, exact to the nearest triangle. "
      "In the meshes' units and as a fraction of the diagonal of the box around "
      "both.\nExample: convray distance bunny.obj bunny_surface.obj");
  distance->add_option("A", d.a_path, "mesh file: .obj .ply .stl .off, optionally .gz")->required();
  distance->add_option("B", d.b_path, "mesh file")->required();
  distance
      ->add_option("--samples", d.samples,
                   "surface samples of each mesh, besides its vertices (default 200000); "
                   "more samples catch narrower spikes")
      ->check(CLI::Range(size_t{1}, size_t{100000000}));
  return distance;
}

// `convray view`: the options straight into ViewCommandOptions, but the size (as quick's).
struct ViewArguments {
  convray::app::ViewCommandOptions options;
  std::string size = "800x600";
};

CLI::App* add_view_command(CLI::App& app, ViewArguments& v) {
  static const std::string description =
      std::string(
          "Show a scene (or a mesh, as 'quick' renders it) in a window and keep it live: a "
          "coarse picture (one ray per 8x8 block) at once, then the full one; saving the scene, "
          "an include or a mesh renders it again, and a parse error shows file:line:col in the "
          "window and on standard error while the last good picture stays. Needs a display "
          "(X11 or Wayland). docs/view.md.\nMouse and keys:\n") +
      convray::app::kViewKeys +
      "\nExample: convray view scenes/soup.pov --size 640x480";
  CLI::App* view = app.add_subcommand("view", description);
  view->add_option("INPUT", v.options.view.input,
                   "scene file, or mesh file (.obj .ply .stl .off, optionally .gz)")
      ->required();
  view->add_option("--size", v.size, "picture size WIDTHxHEIGHT (default 800x600)");
  view->add_option("--clock", v.options.clock, "the scene's clock (default 0); [ and ] move it")
      ->check(kFinite);
  view->add_option("--clock-step", v.options.clock_step, "what [ and ] add (default 0.05)")
      ->check(kPositive);
  view->add_flag("--antialias", v.options.view.antialias,
                 "anti-alias the full picture (+A0.3; the coarse one never is)");
  view->add_option("-L,--library", v.options.view.library_paths,
                   "also search this folder for the scene's #include and mesh files");
  view->add_option("--allow-read", v.options.view.read_folders,
                   "also let the scene read files in this folder (POV-Ray's I/O restrictions)");
  view->add_option("-o,--output", v.options.output,
                   "where s writes the full picture (default: INPUT's name + -view.png)");
  return view;
}

// Checks what CLI11 cannot: a scene with --object, or a mesh with --radius.
void check_field_options(const convray::app::FieldOptions& o, const CLI::App& field) {
  if (!o.scene_path.empty()) {
    if (!o.mesh_path.empty()) throw CLI::ValidationError("field", "give a SCENE or --mesh, not both");
    if (o.object_name.empty()) {
      throw CLI::ValidationError("field", "a SCENE needs --object NAME (a declared object)");
    }
  } else {
    if (o.mesh_path.empty()) throw CLI::ValidationError("field", "give --mesh MESH or a SCENE");
    if (field.count("--radius") == 0) throw CLI::ValidationError("field", "--mesh needs --radius");
  }
}

}  // namespace

int main(int argc, char** argv) {
  convray::app::reexec_with_malloc_tunables(argv);
  // A file-size limit (ulimit -f) then fails the write with EFBIG, which the atomic writer
  // reports and cleans up, instead of killing the process mid-file.
  std::signal(SIGXFSZ, SIG_IGN);
  if (argc >= 2) {
    const std::string first = argv[1];
    if (!is_command(first) && first != "-h" && first != "--help" && first != "--version") {
      return render_main(std::vector<std::string>(argv + 1, argv + argc));
    }
  }
  CLI::App app{kDescription, "convray"};
  app.set_version_flag("--version", "convray 0.1.0");
  app.require_subcommand(1);
  app.fallthrough(false);

  std::string info_path;
  bool info_self_intersections = false;
  CLI::App* info = app.add_subcommand(
      "info", "Report a mesh: triangles, segments, points, vertices, dropped faces, bounds, "
              "edge statistics, components, point spacing; what to check before choosing a "
              "radius.");
  info->add_option("MESH", info_path, "mesh file: .obj .ply .stl .off, optionally .gz")
      ->required();
  info->add_flag("--self-intersections", info_self_intersections,
                 "also count the pairs of faces that intersect beyond their shared corners, "
                 "in exact arithmetic, and list the first five (faces numbered from 1 among "
                 "the triangles kept; under a second per million faces on two cores)");

  convray::app::FieldOptions field_options;
  CLI::App* field = app.add_subcommand(
      "field", "Evaluate the summed raw field of a mesh's triangles (segments, points) at points read from "
               "standard input ('x y z' per line); writes 'F dF/dx dF/dy dF/dz' per line, "
               "17 significant digits. Exit code 2 and 'stdin:LINE: ...' on a malformed line.");
  field->add_option("SCENE", field_options.scene_path,
                    "a scene file; with --object NAME, the declared convolution object or blob "
                    "NAME is evaluated (its raw field, placed by its transforms)");
  field->add_option("--object", field_options.object_name, "the declared object of SCENE");
  field->add_option("-L,--library", field_options.library_paths,
                    "also search this folder for the scene's #include and mesh files");
  field->add_option("--allow-read", field_options.read_folders,
                    "also let the scene read files in this folder (POV-Ray's I/O restrictions)");
  field->add_option("--mesh", field_options.mesh_path, "mesh file");
  field->add_option("--radius", field_options.radius,
                    "kernel radius R (support of the kernel), with --mesh")
      ->check(kPositive);
  field->add_option("--strength", field_options.strength, "strength s (default 1)")
      ->check(kFinite);

  convray::app::SliceOptions slice_options;
  std::string slice_size = "800x600";
  CLI::App* slice = app.add_subcommand(
      "slice", "Picture the field on a plane through a mesh: colour by F/T, the surface F = T "
               "as a white contour, the triangles' cross-section in black.");
  slice->add_option("MESH", slice_options.mesh_path, "mesh file")->required();
  slice->add_option("--radius", slice_options.radius, "kernel radius R")->required()->check(kPositive);
  slice->add_option("--strength", slice_options.strength, "strength s (default 1)")->check(kFinite);
  auto* offset = slice->add_option("--offset", slice_options.offset,
                                   "surface at distance D from flat regions (default R/2)");
  offset->check(kFinite);
  slice->add_option("--threshold", slice_options.threshold, "raw threshold T")
      ->check(kFinite)
      ->excludes(offset);
  slice->add_option("--axis", slice_options.axis, "the plane's normal axis: x, y or z")
      ->check(CLI::IsMember({'x', 'y', 'z'}));
  slice->add_option("--at", slice_options.at, "the plane's coordinate on that axis")->check(kFinite);
  slice->add_option("--size", slice_size, "image size WIDTHxHEIGHT (default 800x600)");
  slice->add_option("-o,--output", slice_options.output, "image file (.png, .exr, .tif, ...)");
  slice->add_flag("--force", slice_options.force,
                  "draw even when the image's estimated memory exceeds what this process can "
                  "have (physical memory, ulimit -v)");

  QuickArguments quick_arguments;
  CLI::App* quick = add_quick_command(app, quick_arguments);

  convray::app::PolygonizeOptions polygonize_options;
  CLI::App* polygonize = add_polygonize_command(app, polygonize_options);

  convray::app::DistanceOptions distance_options;
  CLI::App* distance = add_distance_command(app, distance_options);

  ViewArguments view_arguments;
  CLI::App* view = add_view_command(app, view_arguments);

  try {
    app.parse(argc, argv);
    if (*slice && !parse_size(slice_size, slice_options.width, slice_options.height)) {
      throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 800x600, got " + slice_size);
    }
    if (*quick) finish_quick_options(quick_arguments);
    if (*view && !parse_size(view_arguments.size, view_arguments.options.view.width,
                             view_arguments.options.view.height)) {
      throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 800x600, got " +
                                               view_arguments.size);
    }
    if (*field) check_field_options(field_options, *field);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Name an unknown command outright rather than CLI11's "a subcommand is required".
    const auto is_command = [&](const std::string& name) {
      for (const CLI::App* sub : app.get_subcommands({})) {
        if (sub->get_name() == name) return true;
      }
      return false;
    };
    const bool unknown_command = argc > 1 && argv[1][0] != '-' && !is_command(argv[1]);
    std::cerr << "convray: "
              << (unknown_command ? "unknown command '" + std::string(argv[1]) +
                                        "' (expected info, field, slice, quick, polygonize, "
                                        "distance or view)"
                                  : std::string(e.what()))
              << "\nRun 'convray --help' for usage.\n";
    return 2;
  }

  if (*info) {
    return convray::app::run_info(info_path, info_self_intersections, std::cout, std::cerr);
  }
  if (*slice) return convray::app::run_slice(slice_options, std::cout, std::cerr);
  if (*quick) return convray::app::run_quick(quick_arguments.options, std::cout, std::cerr);
  if (*field) return convray::app::run_field(field_options, std::cin, std::cout, std::cerr);
  if (*polygonize) return convray::app::run_polygonize(polygonize_options, std::cout, std::cerr);
  if (*distance) return convray::app::run_distance(distance_options, std::cout, std::cerr);
  if (*view) return convray::app::run_view(view_arguments.options, std::cout, std::cerr);
  return 2;
}
