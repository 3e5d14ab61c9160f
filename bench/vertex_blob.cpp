// Writes the POV-Ray 3.7 reference scene of bench/table1.sh: a blob with one sphere component
// per vertex of a mesh, seen by the camera and lit by the light that `convray quick` is given.
//
//   vertex_blob MESH --radius R [--offset D] [--fit-box 400] [--size WxH]
//               --camera X,Y,Z --look-at X,Y,Z --angle DEG --light X,Y,Z -o SCENE.pov
//
// Geometry and threshold: bench/vertex_blob_scene.hpp (shared with bench/vertex_blob_render).
// Each distinct vertex position used by a triangle becomes `sphere { <x,y,z>, R, 1 }`, written
// with 17 significant digits, so POV-Ray reads back exactly the doubles we computed.
//
// Standard output: `key: value` lines (triangles, vertices, area, rho, threshold, ...) that
// bench/table1.sh reads. Exit status 2 on a usage error, 1 on an input error.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/load.hpp"
#include "util/math.hpp"
#include "vertex_blob_scene.hpp"

namespace {

using convray::Vec3;

struct Options {
  std::string mesh;
  double radius = 0.0;
  double offset = -1.0;  // negative: R/2
  double fit_box = 400.0;
  int width = 800, height = 600;
  Vec3 camera{0.0}, look_at{0.0}, light{0.0};
  double angle = 0.0;
  std::string output;
  bool has_camera = false, has_look_at = false, has_light = false;
};

constexpr const char* kUsage =
    "usage: vertex_blob MESH --radius R [--offset D] [--fit-box 400] [--size WxH]\n"
    "                   --camera X,Y,Z --look-at X,Y,Z --angle DEG --light X,Y,Z -o SCENE.pov\n"
    "Writes a POV-Ray 3.7 blob with one sphere component per vertex of MESH (fitted into the\n"
    "box as `convray quick --fit-box` does); threshold rho (pi/3) R^2 (1 - D^2/R^2)^3 with\n"
    "rho = vertices / surface area, D = R/2 unless given. Prints key: value lines.\n";

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "vertex_blob: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

double parse_number(std::string_view text, const std::string& what) {
  double value = 0.0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || stop != text.data() + text.size() || !std::isfinite(value))
    usage_error(what + ": expected a finite number, got '" + std::string(text) + "'");
  return value;
}

Vec3 parse_vector(const std::string& text, const std::string& what) {
  std::array<double, 3> v{};
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = i < 2 ? text.find(',', start) : text.size();
    if (comma == std::string::npos) usage_error(what + ": expected X,Y,Z, got '" + text + "'");
    v[i] = parse_number(std::string_view(text).substr(start, comma - start), what);
    start = comma + 1;
  }
  return Vec3(v[0], v[1], v[2]);
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (arg.empty() || arg[0] != '-') {
      if (!o.mesh.empty()) usage_error("more than one mesh: '" + arg + "'");
      o.mesh = arg;
      continue;
    }
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--radius") o.radius = parse_number(value, arg);
    else if (arg == "--offset") o.offset = parse_number(value, arg);
    else if (arg == "--fit-box") o.fit_box = parse_number(value, arg);
    else if (arg == "--angle") o.angle = parse_number(value, arg);
    else if (arg == "--camera") o.camera = parse_vector(value, arg), o.has_camera = true;
    else if (arg == "--look-at") o.look_at = parse_vector(value, arg), o.has_look_at = true;
    else if (arg == "--light") o.light = parse_vector(value, arg), o.has_light = true;
    else if (arg == "-o") o.output = value;
    else if (arg == "--size") {
      int consumed = 0;
      if (std::sscanf(value.c_str(), "%dx%d%n", &o.width, &o.height, &consumed) != 2 ||
          consumed != int(value.size()) || o.width < 1 || o.height < 1)
        usage_error("--size: expected WIDTHxHEIGHT, got '" + value + "'");
    } else {
      usage_error("unknown option '" + arg + "'");
    }
  }
  if (o.mesh.empty()) usage_error("no mesh given");
  if (!(o.radius > 0.0)) usage_error("--radius must be > 0");
  if (o.offset < 0.0) o.offset = 0.5 * o.radius;
  if (!(o.offset < o.radius)) usage_error("--offset must be smaller than --radius");
  if (!(o.fit_box > 0.0)) usage_error("--fit-box must be > 0");
  if (!(o.angle > 0.0 && o.angle < 180.0)) usage_error("--angle must be in (0, 180)");
  if (!o.has_camera || !o.has_look_at || !o.has_light)
    usage_error("--camera, --look-at and --light are required");
  if (o.output.empty()) usage_error("no output file (-o SCENE.pov)");
  return o;
}

std::string vec(const Vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "<%.17g, %.17g, %.17g>", v.x, v.y, v.z);
  return text;
}

void write_scene(const Options& o, const std::vector<Vec3>& centres, double threshold,
                 const std::string& header) {
  const std::string temporary = o.output + ".part";
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(temporary.c_str(), "w"), &std::fclose);
  if (!file) throw std::runtime_error(temporary + ": cannot open for writing");
  FILE* f = file.get();
  std::fputs(header.c_str(), f);
  // Linear light, sRGB-encoded PNG (POV-Ray's default File_Gamma), like convray's image_file.
  std::fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n");
  std::fprintf(f, "background { color rgb <0.015, 0.018, 0.025> }\n\n");
  // Left-handed, y up, `angle` the horizontal field of view: the conventions of `convray
  // quick`. right/up/sky and angle come before look_at so look_at orients the final frame.
  std::fprintf(f,
               "camera {\n  perspective\n  right x*%d/%d\n  up y\n  sky y\n  angle %.17g\n"
               "  location %s\n  look_at %s\n}\n\n",
               o.width, o.height, o.angle, vec(o.camera).c_str(), vec(o.look_at).c_str());
  std::fprintf(f, "light_source { %s color rgb 1 }\n\n", vec(o.light).c_str());
  std::fprintf(f, "blob {\n  threshold %.17g\n", threshold);
  for (const Vec3& c : centres)
    std::fprintf(f, "  sphere { %s, %.17g, 1 }\n", vec(c).c_str(), o.radius);
  // The defaults of `convray quick` (src/scene/quick_scene.cpp: quick_texture): the same
  // POV-Ray finish.
  std::fprintf(f,
               "  pigment { color rgb <0.80, 0.60, 0.42> }\n"
               "  finish { ambient 0.08 diffuse 0.85 phong 0.30 phong_size 40 }\n}\n");
  if (std::ferror(f) || std::fflush(f) != 0)
    throw std::runtime_error(temporary + ": write failed");
  file.reset();
  if (std::rename(temporary.c_str(), o.output.c_str()) != 0)
    throw std::runtime_error(o.output + ": cannot rename " + temporary);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  try {
    const convray::mesh::LoadedMesh loaded = convray::mesh::load_mesh(o.mesh);
    const convray::mesh::TriangleSoup& soup = loaded.soup;

    convray::bench::VertexBlob blob;
    try {
      blob = convray::bench::make_vertex_blob(soup, o.fit_box, o.radius, o.offset);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(o.mesh + ": " + error.what());
    }
    const std::vector<Vec3>& centres = blob.centres;
    const double scale = blob.scale, area = blob.area, rho = blob.rho;
    const double threshold = blob.threshold;

    char summary[1024];
    std::snprintf(summary, sizeof summary,
                  "triangles: %zu\nvertices: %zu\nscale: %.17g\narea: %.17g\nrho: %.17g\n"
                  "radius: %.17g\noffset: %.17g\nthreshold: %.17g\n",
                  soup.size(), centres.size(), scale, area, rho, o.radius, o.offset, threshold);
    std::string header = "// POV-Ray 3.7 reference scene for bench/table1.sh, written by "
                         "bench/vertex_blob from\n// " + o.mesh + "\n";
    for (std::string_view rest = summary; !rest.empty();) {
      const size_t end = rest.find('\n');
      header += "// " + std::string(rest.substr(0, end)) + "\n";
      rest.remove_prefix(end + 1);
    }
    write_scene(o, centres, threshold, header + "\n");
    std::fputs(summary, stdout);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vertex_blob: %s\n", error.what());
    return 1;
  }
}
