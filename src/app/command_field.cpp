#include "app/command_field.hpp"

#include <tbb/parallel_for.h>

#include <charconv>
#include <cmath>
#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/command_step.hpp"
#include "app/declared_object.hpp"
#include "app/parse_hooks.hpp"
#include "implicit/placed_field.hpp"
#include "implicit/mesh_field.hpp"
#include "scene/mesh_skeleton.hpp"
#include "mesh/load.hpp"
#include "sdl/parser.hpp"
#include "util/error.hpp"
#include "util/printable.hpp"

namespace convray::app {

namespace {

constexpr size_t kLinesPerBlock = 1 << 16;

// Parses "x y z" (spaces or tabs, nothing else). Returns an error message, or
// nothing.
std::optional<std::string> parse_point(std::string_view line, Vec3& out) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // tolerate CRLF files
  const char* p = line.data();
  const char* end = p + line.size();
  const auto skip_blanks = [&] {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
  };
  const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    skip_blanks();
    if (p == end) {
      return "expected three numbers 'x y z', found " + std::to_string(k) +
             (k == 1 ? " number" : " numbers");
    }
    double v = 0.0;
    const char* start = p;
    if (*p == '+') ++p;  // from_chars rejects a leading '+', people write it
    const auto [next, ec] = std::from_chars(p, end, v);
    if (ec != std::errc() || (next < end && *next != ' ' && *next != '\t')) {
      const char* stop = start;
      while (stop < end && *stop != ' ' && *stop != '\t') ++stop;
      return std::string(names[k]) + " is not a number: '" + std::string(start, stop) + "'";
    }
    if (!std::isfinite(v)) return std::string(names[k]) + " is not finite";
    out[k] = v;
    p = next;
  }
  skip_blanks();
  if (p != end) return "unexpected text after 'x y z': '" + std::string(p, end) + "'";
  return std::nullopt;
}

void append_number(std::string& out, double v) {
  char buffer[32];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17);
  out.append(buffer, ec == std::errc() ? end : buffer);
}

using FieldFunction = std::function<field::FieldSample(const Vec3&)>;

// "x y z" needs a few dozen characters; a longer line (input without line breaks, binary
// data) is refused at its line instead of growing a string until memory runs out.
constexpr size_t kMaxLineLength = 4096;

enum class LineRead { line, end, too_long };

LineRead read_line(std::streambuf& in, std::string& line) {
  line.clear();
  for (int c = in.sbumpc(); c != std::char_traits<char>::eof(); c = in.sbumpc()) {
    if (c == '\n') return LineRead::line;
    if (line.size() == kMaxLineLength) return LineRead::too_long;
    line.push_back(char(c));
  }
  return line.empty() ? LineRead::end : LineRead::line;
}

// Answers every "x y z" line of `in`; returns the exit code.
int answer_points(const FieldFunction& field, std::istream& in, std::ostream& out,
                  std::ostream& err) {
  std::vector<std::string> lines;
  std::vector<Vec3> points;
  std::vector<std::string> answers;
  size_t line_number = 0;
  for (bool more = true; more;) {
    // Read a block, parse it serially (the first bad line stops everything
    // after it), evaluate it in parallel, print it in order.
    lines.clear();
    std::string line;
    LineRead status = LineRead::line;
    while (lines.size() < kLinesPerBlock &&
           (status = read_line(*in.rdbuf(), line)) == LineRead::line) {
      lines.push_back(std::move(line));
    }
    more = status == LineRead::line;
    points.resize(lines.size());
    std::optional<std::string> problem;
    size_t good = 0;
    for (; good < lines.size(); ++good) {
      if ((problem = parse_point(lines[good], points[good]))) break;
    }
    if (!problem && status == LineRead::too_long) {
      problem = "the line is longer than " + std::to_string(kMaxLineLength) + " characters";
    }
    answers.assign(good, {});
    tbb::parallel_for(size_t(0), good, [&](size_t i) {
      const field::FieldSample s = field(points[i]);
      std::string& a = answers[i];
      append_number(a, s.value);
      for (int k = 0; k < 3; ++k) a += ' ', append_number(a, s.gradient[k]);
      a += '\n';
    });
    for (const std::string& a : answers) out << a;
    if (problem) {
      out.flush();
      // The line is the user's text: escaped and cut before it reaches the terminal.
      err << "stdin:" << line_number + good + 1 << ": " << printable(*problem) << "\n";
      return 2;
    }
    line_number += lines.size();
  }
  out.flush();
  return 0;
}

int run_scene_field(const FieldOptions& o, std::istream& in, std::ostream& out, std::ostream& err,
                    CommandStep& step) {
  sdl::ParseOptions parse_options;
  parse_options.library_paths = o.library_paths;
  parse_options.read_folders = o.read_folders;
  use_program_hooks(parse_options);
  const sdl::ParseResult parsed = sdl::parse_file(o.scene_path, parse_options);
  const scene::Object& object = declared_implicit(parsed, o.scene_path, o.object_name);
  const scene::ConvolutionObject& record = std::get<scene::Implicit>(object.shape).object;
  const scene::Transform& placed = object.transform;
  step.now("building the field of '" + o.object_name + "'", "give an object with fewer components");
  std::unique_ptr<const implicit::Surface> surface;
  try {
    surface = implicit::make_surface(record);
  } catch (const std::invalid_argument& e) {
    throw InputError(object.loc, e.what());
  }
  step.now("evaluating the points", kFreeMemory);
  return answer_points([&](const Vec3& p) { return implicit::placed_field(*surface, placed, p); },
                       in, out, err);
}

// A file's field: its triangles through MeshField (grid and SIMD batches); a file with
// segments or points through the convolution surface of its whole skeleton.
int run_mesh_field(const FieldOptions& o, std::istream& in, std::ostream& out, std::ostream& err,
                   CommandStep& step) {
  const mesh::LoadedMesh loaded = mesh::load_mesh(o.mesh_path);
  step.now("building the field of " + o.mesh_path, kFreeMemory);
  if (loaded.segments.empty() && loaded.points.empty()) {
    const implicit::MeshField field(scene::soup_triangles(loaded.soup), o.radius, o.strength);
    step.now("evaluating the points", kFreeMemory);
    return answer_points([&](const Vec3& p) { return field.field(p); }, in, out, err);
  }
  scene::ConvolutionObject object;
  scene::add_skeleton(scene::skeleton_of(loaded), {o.strength, o.radius}, object);
  const auto surface = implicit::make_surface(object);  // its threshold (1) is not used here
  step.now("evaluating the points", kFreeMemory);
  return answer_points([&](const Vec3& p) { return surface->field(p); }, in, out, err);
}

}  // namespace

int run_field(const FieldOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  CommandStep step("reading " + (options.scene_path.empty() ? options.mesh_path : options.scene_path),
                   kFreeMemory);
  try {
    if (!options.scene_path.empty()) return run_scene_field(options, in, out, err, step);
    return run_mesh_field(options, in, out, err, step);
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  }
}

}  // namespace convray::app
