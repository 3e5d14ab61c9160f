// convray command line: parse the arguments, hand each subcommand to its run_* function.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/command_field.hpp"
#include "app/command_info.hpp"
#include "app/command_slice.hpp"

namespace {

constexpr const char* kDescription =
    "convray - convolution surfaces of polygon soups and skeletons, in closed form.\n"
    "\n"
    "Examples:\n"
    "  convray info scenes/models/soup.obj\n"
    "  echo '0 0 0' | convray field --mesh scenes/models/soup.obj --radius 0.2\n"
    "  convray slice scenes/models/soup.obj --radius 0.25 --offset 0.1 -o slice.png\n";

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

// "WIDTHxHEIGHT", each 1..32768.
bool parse_size(const std::string& text, int& width, int& height) {
  int consumed = 0;
  return std::sscanf(text.c_str(), "%dx%d%n", &width, &height, &consumed) == 2 &&
         consumed == int(text.size()) && width >= 1 && height >= 1 && width <= 32768 &&
         height <= 32768;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{kDescription, "convray"};
  app.set_version_flag("--version", "convray 0.1.0");
  app.require_subcommand(1);
  app.fallthrough(false);

  std::string info_path;
  CLI::App* info = app.add_subcommand(
      "info", "Report a mesh: triangles, vertices, dropped faces, bounds, edge statistics, "
              "components; what to check before choosing a radius.");
  info->add_option("MESH", info_path, "mesh file: .obj .ply .stl .off, optionally .gz")
      ->required();

  convray::app::FieldOptions field_options;
  CLI::App* field = app.add_subcommand(
      "field", "Evaluate the summed raw field of a mesh's triangles at points read from "
               "standard input ('x y z' per line); writes 'F dF/dx dF/dy dF/dz' per line, "
               "17 significant digits. Exit code 2 and 'stdin:LINE: ...' on a malformed line.");
  field->add_option("--mesh", field_options.mesh_path, "mesh file")->required();
  field->add_option("--radius", field_options.radius, "kernel radius R (support of the kernel)")
      ->required()
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

  try {
    app.parse(argc, argv);
    if (*slice && !parse_size(slice_size, slice_options.width, slice_options.height)) {
      throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 800x600, got " + slice_size);
    }
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
                                        "' (expected info, field or slice)"
                                  : std::string(e.what()))
              << "\nRun 'convray --help' for usage.\n";
    return 2;
  }

  if (*info) return convray::app::run_info(info_path, std::cout, std::cerr);
  if (*slice) return convray::app::run_slice(slice_options, std::cout, std::cerr);
  if (*field) return convray::app::run_field(field_options, std::cin, std::cout, std::cerr);
  return 2;
}
