#include "app/render_options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace convray::app {

const char* const kRenderUsage =
    "usage: convray SCENE.pov [options]        (or POV-Ray's switches: "
    "+ISCENE.pov ...)\n"
    "\n"
    "Renders a POV-Ray-style scene: convolution objects, blobs, primitives, "
    "CSG, textures,\n"
    "lights, reflection and refraction. The image appears complete or not at "
    "all.\n"
    "\n"
    "  -o, --output FILE   image file: .png (8-bit sRGB), .tif (16-bit), .exr "
    "(linear float)\n"
    "                      (+OFILE; default: the scene's name with .png, in "
    "this folder)\n"
    "  --width N, --height N    image size (+WN +HN; default 800x600)\n"
    "  --antialias [T]     adaptive anti-aliasing, threshold T (+A[T]; default "
    "off, T 0.3)\n"
    "  --aa-depth N        N x N samples in a supersampled pixel (+RN; default "
    "3)\n"
    "  --jitter [J]        jitter the supersamples by J pixels' worth, "
    "reproducibly (+J[J]; -J off)\n"
    "  --threads N         render threads (+WTN; default: every core)\n"
    "  -L, --library DIR   also search DIR for #include files and meshes "
    "(+LDIR)\n"
    "  --declare ID=VALUE  declare a float identifier (Declare=ID=VALUE)\n"
    "  --clock VALUE       the scene's clock (+KVALUE; default 0)\n"
    "  --stats             print rays, timings and memory after the render\n"
    "  --quiet             no summary line\n"
    "  -h, --help          this message\n"
    "\n"
    "POV-Ray's +D/-D (display), +V/-V, +P/-P, +X/-X and +G?/-G? (console "
    "output) are accepted\n"
    "and do nothing. Example:\n"
    "  convray +Iscenes/soup.pov +Osoup.png +W800 +H600 +A0.3 -D +WT2\n";

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// The whole text as a finite number, or a UsageError naming `what`.
double number(const std::string& text, const std::string& what) {
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin < end && *begin == '+') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value)) {
    throw UsageError(what + ": expected a number, got '" + text + "'");
  }
  return value;
}

int whole(const std::string& text, const std::string& what, int lo, int hi) {
  const double v = number(text, what);
  if (v != std::floor(v) || v < lo || v > hi) {
    throw UsageError(what + ": expected a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + text + "'");
  }
  return int(v);
}

void set_aa_threshold(RenderOptions& o, const std::string& text, const std::string& what) {
  o.antialias = true;
  if (text.empty()) return;
  o.aa_threshold = number(text, what);
  if (!(o.aa_threshold >= 0.0)) throw UsageError(what + ": the threshold must be >= 0");
}

void set_jitter(RenderOptions& o, const std::string& text, const std::string& what) {
  o.jitter = true;
  if (text.empty()) return;
  o.jitter_amount = number(text, what);
  if (o.jitter_amount <= 0.0) o.jitter = false;  // POV-Ray: +J0 turns jitter off
}

void set_declare(RenderOptions& o, const std::string& text, const std::string& what) {
  const size_t eq = text.find('=');
  const std::string id = text.substr(0, eq);
  const bool valid_id = !id.empty() && (std::isalpha((unsigned char)id[0]) || id[0] == '_') &&
                        std::all_of(id.begin(), id.end(),
                                    [](unsigned char c) { return std::isalnum(c) || c == '_'; });
  if (eq == std::string::npos || !valid_id) {
    throw UsageError(what + ": expected ID=VALUE, got '" + text + "'");
  }
  o.declares.emplace_back(id, number(text.substr(eq + 1), what + " " + id));
}

// One POV-Ray switch: `on` is true for '+', the body follows the sign.
void apply_switch(RenderOptions& o, bool on, const std::string& arg) {
  const std::string body = arg.substr(1), key = lower(body);
  const auto rest = [&](size_t n) { return body.substr(n); };
  if (key.starts_with("wt")) {
    o.threads = whole(rest(2), arg, 1, 1024);
  } else if (key.starts_with("w") && on) {
    o.width = whole(rest(1), arg, 1, 32768);
  } else if (key.starts_with("h") && on) {
    o.height = whole(rest(1), arg, 1, 32768);
  } else if (key.starts_with("i") && on) {
    if (rest(1).empty()) throw UsageError(arg + ": expected the scene file after +I");
    o.scene = rest(1);
  } else if (key.starts_with("o") && on) {
    if (rest(1).empty()) throw UsageError(arg + ": expected the output file after +O");
    o.output = rest(1);
  } else if (key.starts_with("l") && on) {
    if (rest(1).empty()) throw UsageError(arg + ": expected a folder after +L");
    o.library_paths.push_back(rest(1));
  } else if (key.starts_with("am") || key == "a" || (key.starts_with("a") && !on)) {
    if (key.starts_with("am"))
      throw UsageError(arg + ": only POV-Ray's method 1 (+AM1) is supported");
    o.antialias = on;
  } else if (key.starts_with("a")) {
    set_aa_threshold(o, rest(1), arg);
  } else if (key.starts_with("r") && on) {
    o.aa_depth = whole(rest(1), arg, 1, 9);
  } else if (key.starts_with("j")) {
    if (on)
      set_jitter(o, rest(1), arg);
    else
      o.jitter = false;
  } else if (key.starts_with("k") && on && key.size() > 1 &&
             (std::isdigit((unsigned char)key[1]) || key[1] == '.' || key[1] == '-')) {
    o.clock = number(rest(1), arg);
    o.clock_given = true;
  } else if (key.starts_with("d") || key == "v" || key == "p" || key == "x" ||
             key.starts_with("g") || key.starts_with("q") || key.starts_with("f")) {
    // Display, verbosity, pause, abort key, console streams, quality, file
    // type: no effect.
  } else {
    throw UsageError("unknown switch '" + arg + "'; run 'convray --help' for the supported ones");
  }
}

// The value of `--name VALUE` or `--name=VALUE`; advances `i` past a separate
// value.
std::string option_value(const std::vector<std::string>& args, size_t& i, const std::string& name) {
  const std::string& arg = args[i];
  const size_t eq = arg.find('=');
  if (eq != std::string::npos) return arg.substr(eq + 1);
  if (i + 1 >= args.size()) throw UsageError(name + ": expected a value after it");
  return args[++i];
}

// An optional value: taken when the next argument is a number.
std::string optional_number(const std::vector<std::string>& args, size_t& i) {
  const std::string& arg = args[i];
  const size_t eq = arg.find('=');
  if (eq != std::string::npos) return arg.substr(eq + 1);
  if (i + 1 < args.size()) {
    double v;
    const std::string& next = args[i + 1];
    const auto [stop, error] = std::from_chars(next.data(), next.data() + next.size(), v);
    if (error == std::errc() && stop == next.data() + next.size()) return args[++i];
  }
  return "";
}

// `--long` and `-o` options; returns false if `args[i]` is not one.
bool apply_long_option(RenderOptions& o, const std::vector<std::string>& args, size_t& i) {
  const std::string& arg = args[i];
  const std::string name = arg.substr(0, arg.find('='));
  if (name == "-o" || name == "--output") {
    o.output = option_value(args, i, name);
  } else if (name == "--width") {
    o.width = whole(option_value(args, i, name), name, 1, 32768);
  } else if (name == "--height") {
    o.height = whole(option_value(args, i, name), name, 1, 32768);
  } else if (name == "--antialias") {
    set_aa_threshold(o, optional_number(args, i), name);
  } else if (name == "--aa-depth") {
    o.aa_depth = whole(option_value(args, i, name), name, 1, 9);
  } else if (name == "--jitter") {
    set_jitter(o, optional_number(args, i), name);
  } else if (name == "--threads") {
    o.threads = whole(option_value(args, i, name), name, 1, 1024);
  } else if (name == "-L" || name == "--library") {
    o.library_paths.push_back(option_value(args, i, name));
  } else if (name == "--declare") {
    set_declare(o, option_value(args, i, name), name);
  } else if (name == "--clock") {
    o.clock = number(option_value(args, i, name), name);
    o.clock_given = true;
  } else if (name == "--stats") {
    o.stats = true;
  } else if (name == "--quiet") {
    o.quiet = true;
  } else {
    return false;
  }
  return true;
}

}  // namespace

RenderOptions parse_render_arguments(const std::vector<std::string>& args) {
  RenderOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.empty()) throw UsageError("empty argument");
    if (apply_long_option(o, args, i)) continue;
    if (lower(arg).starts_with("declare=")) {
      set_declare(o, arg.substr(8), "Declare=");
    } else if (arg.size() > 1 && (arg[0] == '+' || arg[0] == '-') && arg[1] != '-') {
      apply_switch(o, arg[0] == '+', arg);
    } else if (arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'; run 'convray --help'");
    } else if (o.scene.empty()) {
      o.scene = arg;
    } else {
      throw UsageError("one scene at a time: got '" + o.scene + "' and '" + arg + "'");
    }
  }
  if (o.scene.empty()) throw UsageError("no scene file given (convray SCENE.pov, or +ISCENE.pov)");
  if (o.output.empty()) o.output = default_output_name(o.scene);
  return o;
}

std::string default_output_name(const std::string& scene) {
  return std::filesystem::path(scene).filename().replace_extension(".png").string();
}

}  // namespace convray::app
