#include "app/render_options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <string_view>

#include "app/frame_names.hpp"
#include "app/ini_file.hpp"
#include "app/option_values.hpp"

namespace convray::app {

const char* const kRenderUsage =
    "usage: convray SCENE.pov [options]     or POV-Ray's: convray +ISCENE.pov [switches]\n"
    "       convray ANIMATION.ini[SECTION] [options]\n"
    "\n"
    "Renders a POV-Ray-style scene: convolution objects, blobs, primitives, CSG, textures,\n"
    "lights, reflection and refraction; or, with frame options, every frame of an animation\n"
    "(the scene re-read per frame with its clock). Each image appears complete or not at all.\n"
    "\n"
    "Image:\n"
    "  -o, --output FILE   .png (8-bit sRGB), .tif (16-bit), .exr (linear float); a FOLDER/\n"
    "                      keeps the scene's name (+OFILE; default: SCENE.png, here)\n"
    "  --width N, --height N    image size (+WN +HN; default 800x600)\n"
    "  --antialias [T]     adaptive anti-aliasing, threshold T (+A[T]; default off, T 0.3)\n"
    "  --aa-depth N        N x N samples in a supersampled pixel (+RN; default 3)\n"
    "  --jitter [J]        jitter the supersamples by J pixels, reproducibly (+J[J]; -J off)\n"
    "  --threads N         render threads (+WTN; default: every core)\n"
  "Partial image (POV-Ray's; the whole picture is written, black outside the part, so that\n"
  "parts rendered apart add up: scripts/stitch-parts.sh, docs/render-farm.md):\n"
  "  --start-row N, --end-row M          rows N to M only (+SRN +ERM; Start_Row=, End_Row=)\n"
  "  --start-column N, --end-column M    columns N to M (+SCN +ECM; Start_Column=, ...)\n"
  "                      values above 1 count pixels from 1; 0.0 to 1.0 are fractions\n"
    "Scene:\n"
    "  -L, --library DIR   also search DIR for #include files and meshes (+LDIR)\n"
    "  --declare ID=VALUE  declare a float identifier (Declare=ID=VALUE)\n"
    "  --allow-read DIR    also let the scene read files in DIR (by default only in the\n"
    "                      scene's folder, the working folder, -L folders, POV-Ray's\n"
    "                      includes and the output folder, as POV-Ray's I/O restrictions)\n"
    "  --allow-read-anywhere   lift that restriction\n"
    "  --clock VALUE       a still's clock (+KVALUE; default 0)\n"
    "Animation (POV-Ray's options; frames are named OUTPUT plus the zero-padded number):\n"
    "  --initial-frame N   +KFIN (default 1)      --final-frame N   +KFFN (default 1)\n"
    "  --initial-clock X   +KIX (default 0)       --final-clock X   +KFX (default 1)\n"
    "  --cyclic            +KC: the clock wraps, the last frame stops one step short\n"
    "  --subset-start N    +SFN: first frame to render (0 < N < 1: a fraction of them)\n"
    "  --subset-end N      +EFN: last frame to render (same)\n"
    "  --frame-step N      Frame_Step=N: every N-th frame\n"
    "  --continue          +C: skip frames whose image files are already complete\n"
    "  --video FILE        assemble the frames into FILE (.mp4, .webm, .gif) with ffmpeg\n"
    "  --fps N             the video's frame rate (default 25)\n"
    "  --list-frames       print each frame's number, clock and file (tab-separated); render\n"
    "                      nothing (for render-farm scripts: docs/render-farm.md)\n"
    "Preview (POV-Ray's; docs/view.md):\n"
    "  --display           +D, Display=on: a window fills in tile by tile as the picture\n"
    "                      renders; closing it (or Escape, q) stops the render, nothing\n"
    "                      written. Without a display: said once, rendered as with -D\n"
    "  --pause             +P, Pause_When_Done=on: the window stays open at the end until\n"
    "                      a key is pressed in it or it is closed (-P: it closes)\n"
    "Output:\n"
    "  --stats             print rays, timings and memory after each image\n"
    "  --quiet             no summary line\n"
    "  --force             render even when the image's estimated memory exceeds what this\n"
    "                      process can have (physical memory, ulimit -v), or an animation's\n"
    "                      frames may not fit in the free disk space\n"
    "  -h, --help          this message\n"
    "\n"
    "POV-Ray's +V/-V, +X/-X, +F?, +Q? and +G?/-G? (console output) are accepted and do\n"
    "nothing. INI files take POV-Ray's keys (Width=, Final_Frame=,\n"
    "Cyclic_Animation=on, Declare=, Library_Path=, ...), raw switches and [sections].\n"
    "Examples:\n"
    "  convray +Iscenes/soup.pov +Osoup.png +W800 +H600 +A0.3 -D +WT2\n"
    "  convray scenes/animations/walk.ini +SF1 +EF12 --continue\n";

namespace {

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

void set_output(RenderOptions& o, const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": expected a file or folder name");
  o.output = text;
}

void set_scene(RenderOptions& o, const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": expected the scene file");
  o.scene = text;
}

// The partial image's bounds, by their three names: a long option ("--start-row"), an INI key
// ("start_row", lower case) and a switch ("sr", after + or -).
enum class BoundName { long_option, ini_key, switch_key };

// Sets the bound `name` (of the kind `kind`) to the number `value()` gives; false if `name` is
// no bound. `what` names the argument in messages.
template <typename Value>
bool set_partial_bound(RenderOptions& o, BoundName kind, const std::string& name,
                       const std::string& what, Value&& value) {
  struct Names {
    const char* names[3];
    std::optional<PartialBound> PartialImage::*bound;
  };
  static const Names kBounds[] = {
      {{"--start-column", "start_column", "sc"}, &PartialImage::start_column},
      {{"--end-column", "end_column", "ec"}, &PartialImage::end_column},
      {{"--start-row", "start_row", "sr"}, &PartialImage::start_row},
      {{"--end-row", "end_row", "er"}, &PartialImage::end_row}};
  for (const Names& b : kBounds) {
    if (name != b.names[int(kind)]) continue;
    o.partial.*b.bound = PartialBound{number(value(), what), what};
    return true;
  }
  return false;
}

// Frame numbers: POV-Ray's are non-negative; a negative one is clamped by plan_frames.
constexpr long long kFrameLimit = 1'000'000'000;
long long frame_number(const std::string& text, const std::string& what) {
  return whole(text, what, -kFrameLimit, kFrameLimit);
}

// The +K family: +KFIn +KFFn +KIx +KFx +KC / -KC +Kx. `key` is lower case, without the sign.
bool apply_clock_switch(RenderOptions& o, bool on, const std::string& key, const std::string& body,
                        const std::string& arg) {
  AnimationOptions& a = o.animation;
  const auto rest = [&](size_t n) { return body.substr(n); };
  if (key == "kc") {
    a.cyclic = on;
  } else if (!key.starts_with("k") || (!on && body.size() == 1)) {
    return false;  // -K0.5 sets the clock as +K0.5 does; -K alone is not a clock switch
  } else if (key.starts_with("kfi")) {
    a.initial_frame = frame_number(rest(3), arg);
  } else if (key.starts_with("kff")) {
    a.final_frame = frame_number(rest(3), arg);
  } else if (key.starts_with("ki")) {
    a.initial_clock = number(rest(2), arg);
  } else if (key.starts_with("kf")) {
    a.final_clock = number(rest(2), arg);
  } else {
    a.clock = number(rest(1), arg);
  }
  return true;
}

bool is_ignored_switch(const std::string& key) {
  // Verbosity, abort key, console streams, quality, file type: no effect.
  return key == "v" || key == "x" || key.starts_with("g") || key.starts_with("q") ||
         key.starts_with("f");
}

// `--name VALUE` or `--name=VALUE`; advances `i` past a separate value.
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

// The animation's long options; false if `name` is not one.
bool apply_animation_option(RenderOptions& o, const std::vector<std::string>& args, size_t& i,
                            const std::string& name) {
  AnimationOptions& a = o.animation;
  const auto value = [&] { return option_value(args, i, name); };
  if (name == "--clock") {
    a.clock = number(value(), name);
  } else if (name == "--initial-frame") {
    a.initial_frame = frame_number(value(), name);
  } else if (name == "--final-frame") {
    a.final_frame = frame_number(value(), name);
  } else if (name == "--initial-clock") {
    a.initial_clock = number(value(), name);
  } else if (name == "--final-clock") {
    a.final_clock = number(value(), name);
  } else if (name == "--cyclic") {
    a.cyclic = true;
  } else if (name == "--subset-start") {
    a.subset_start = number(value(), name);
  } else if (name == "--subset-end") {
    a.subset_end = number(value(), name);
  } else if (name == "--frame-step") {
    a.frame_step = whole(value(), name, 1, kFrameLimit);
  } else if (name == "--list-frames") {
    o.list_frames = true;
  } else if (name == "--continue") {
    o.continue_trace = true;
  } else if (name == "--video") {
    o.video = value();
    if (o.video.empty()) throw UsageError("--video: expected a file name");
  } else if (name == "--fps") {
    o.video_fps = number(value(), name);
    if (!(o.video_fps > 0.0 && o.video_fps <= 1000.0)) {
      throw UsageError("--fps: expected a rate between 0 and 1000 frames per second");
    }
  } else {
    return false;
  }
  return true;
}

// `--long` and `-o` options; returns false if `args[i]` is not one.
bool apply_long_option(RenderOptions& o, const std::vector<std::string>& args, size_t& i) {
  const std::string& arg = args[i];
  const std::string name = arg.substr(0, arg.find('='));
  if (name == "-o" || name == "--output") {
    set_output(o, option_value(args, i, name), name);
  } else if (name == "--width") {
    o.width = int(whole(option_value(args, i, name), name, 1, 32768));
  } else if (name == "--height") {
    o.height = int(whole(option_value(args, i, name), name, 1, 32768));
  } else if (name == "--antialias") {
    set_aa_threshold(o, optional_number(args, i), name);
  } else if (name == "--aa-depth") {
    o.aa_depth = int(whole(option_value(args, i, name), name, 1, 9));
  } else if (name == "--jitter") {
    set_jitter(o, optional_number(args, i), name);
  } else if (name == "--threads") {
    o.threads = int(whole(option_value(args, i, name), name, 1, 1024));
  } else if (name == "-L" || name == "--library") {
    o.library_paths.push_back(option_value(args, i, name));
  } else if (name == "--allow-read") {
    o.read_folders.push_back(option_value(args, i, name));
  } else if (name == "--allow-read-anywhere") {
    o.read_anywhere = true;
  } else if (name == "--declare") {
    set_declare(o, option_value(args, i, name), name);
  } else if (set_partial_bound(o, BoundName::long_option, name, name,
                               [&] { return option_value(args, i, name); })) {
  } else if (name == "--display") {
    o.display = true;
  } else if (name == "--pause") {
    o.pause_when_done = true;
  } else if (name == "--stats") {
    o.stats = true;
  } else if (name == "--quiet") {
    o.quiet = true;
  } else if (name == "--force") {
    o.force = true;
  } else {
    return apply_animation_option(o, args, i, name);
  }
  return true;
}

// INI keys that change nothing here: display gamma and palette, console streams, file types and bit depths,
// bounding controls. Keys that would change the picture in ways convray does not support
// (shell hooks, alpha) are not here, so they are errors, like unknown keys.
constexpr std::string_view kIgnoredIniKeys[] = {"verbose",          "test_abort",
                                                "test_abort_count", "draw_vistas",
                                                "display_gamma",    "preview_start_size",
                                                "preview_end_size", "video_mode",
                                                "palette",          "output_to_file",
                                                "output_file_type", "bits_per_color",
                                                "quality",          "all_console",
                                                "debug_console",    "fatal_console",
                                                "render_console",   "statistic_console",
                                                "warning_console",  "all_file",
                                                "debug_file",       "fatal_file",
                                                "render_file",      "statistic_file",
                                                "warning_file",     "create_ini",
                                                "bounding",         "bounding_threshold",
                                                "light_buffer",     "vista_buffer",
                                                "remove_bounds",    "split_unions",
                                                "sampling_method",  "buffer_output",
                                                "buffer_size",      "histogram_type",
                                                "histogram_name",   "histogram_grid_size",
                                                "version",          "clock_delta"};

// The INI keys convray reads, for "did you mean" hints.
constexpr std::string_view kIniKeys[] = {"Input_File_Name",
                                         "Output_File_Name",
                                         "Width",
                                         "Height",
                                         "Antialias",
                                         "Antialias_Threshold",
                                         "Antialias_Depth",
                                         "Jitter",
                                         "Jitter_Amount",
                                         "Work_Threads",
                                         "Library_Path",
                                         "Declare",
                                         "Clock",
                                         "Initial_Frame",
                                         "Final_Frame",
                                         "Initial_Clock",
                                         "Final_Clock",
                                         "Cyclic_Animation",
                                         "Subset_Start_Frame",
                                         "Subset_End_Frame",
                                         "Frame_Step",
                                         "Continue_Trace",
                                         "Start_Column",
                                         "End_Column",
                                         "Start_Row",
                                         "End_Row",
                                         "Display",
                                         "Pause_When_Done",
                                         "Include_INI"};

// Edit distance, for suggesting the key someone meant.
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A key no setting has: reported at the key, where a bad value is reported at the value.
class UnknownIniKey : public UsageError {
 public:
  using UsageError::UsageError;
};

[[noreturn]] void unknown_ini_key(const std::string& key) {
  std::string_view best;
  size_t best_distance = 4;  // only close misspellings are suggested
  for (std::string_view known : kIniKeys) {
    const size_t d = edit_distance(lower(key), lower(std::string(known)));
    if (d < best_distance) best = known, best_distance = d;
  }
  std::string message = "unknown INI key '" + key + "'";
  if (!best.empty()) message += "; did you mean " + std::string(best) + "?";
  throw UnknownIniKey(message);
}

// The animation keys; false if `key` (lower case) is not one.
bool apply_ini_animation(RenderOptions& o, const std::string& key, const std::string& value,
                         const std::string& what) {
  AnimationOptions& a = o.animation;
  if (key == "clock") {
    a.clock = number(value, what);
  } else if (key == "initial_frame") {
    a.initial_frame = frame_number(value, what);
  } else if (key == "final_frame") {
    a.final_frame = frame_number(value, what);
  } else if (key == "initial_clock") {
    a.initial_clock = number(value, what);
  } else if (key == "final_clock") {
    a.final_clock = number(value, what);
  } else if (key == "cyclic_animation") {
    a.cyclic = boolean(value, what);
  } else if (key == "subset_start_frame") {
    a.subset_start = number(value, what);
  } else if (key == "subset_end_frame") {
    a.subset_end = number(value, what);
  } else if (key == "frame_step") {
    a.frame_step = whole(value, what, 1, kFrameLimit);
  } else if (key == "continue_trace") {
    o.continue_trace = boolean(value, what);
  } else {
    return false;
  }
  return true;
}

// Reads an INI file's entries into the options; errors point into the file.
void apply_ini_file(RenderOptions& o, const std::string& argument) {
  for (const IniEntry& entry : read_ini(split_ini_argument(argument))) {
    try {
      if (entry.is_switch()) {
        apply_switch(o, entry.value);
      } else {
        apply_ini_setting(o, entry.key, entry.value);
      }
    } catch (const UnknownIniKey& e) {
      throw InputError(entry.loc, e.what());
    } catch (const UsageError& e) {
      throw InputError(entry.is_switch() ? entry.loc : entry.value_loc, e.what());
    }
  }
}

// `Key=value` on the command line, as POV-Ray takes it: Frame_Step=3, Declare=N=2.
bool is_setting_argument(const std::string& arg) {
  const size_t eq = arg.find('=');
  return eq != std::string::npos && eq > 0 &&
         std::all_of(arg.begin(), arg.begin() + std::ptrdiff_t(eq),
                     [](unsigned char c) { return std::isalpha(c) || c == '_'; });
}

}  // namespace

void apply_ini_setting(RenderOptions& o, const std::string& key_as_written,
                       const std::string& value) {
  const std::string key = lower(key_as_written), what = key_as_written;
  if (key == "input_file_name") {
    set_scene(o, value, what);
  } else if (key == "output_file_name") {
    set_output(o, value, what);
  } else if (key == "width") {
    o.width = int(whole(value, what, 1, 32768));
  } else if (key == "height") {
    o.height = int(whole(value, what, 1, 32768));
  } else if (key == "antialias") {
    o.antialias = boolean(value, what);
  } else if (key == "antialias_threshold") {  // POV-Ray: sets the threshold, not the switch
    o.aa_threshold = number(value, what);
    if (!(o.aa_threshold >= 0.0)) throw UsageError(what + ": the threshold must be >= 0");
  } else if (key == "antialias_depth") {
    o.aa_depth = int(whole(value, what, 1, 9));
  } else if (key == "jitter") {
    o.jitter = boolean(value, what);
  } else if (key == "jitter_amount") {
    o.jitter_amount = number(value, what);
    if (o.jitter_amount <= 0.0) o.jitter = false;
  } else if (key == "work_threads") {
    o.threads = int(whole(value, what, 1, 1024));
  } else if (key == "library_path") {
    if (value.empty()) throw UsageError(what + ": expected a folder");
    o.library_paths.push_back(value);
  } else if (key == "declare") {
    set_declare(o, value, what);
  } else if (key == "display") {
    o.display = boolean(value, what);
  } else if (key == "pause_when_done") {
    o.pause_when_done = boolean(value, what);
  } else if (set_partial_bound(o, BoundName::ini_key, key, what, [&] { return value; })) {
  } else if (!apply_ini_animation(o, key, value, what) &&
             std::find(std::begin(kIgnoredIniKeys), std::end(kIgnoredIniKeys), key) ==
                 std::end(kIgnoredIniKeys)) {
    unknown_ini_key(key_as_written);
  }
}

void apply_switch(RenderOptions& o, const std::string& arg) {
  if (arg.size() < 2 || (arg[0] != '+' && arg[0] != '-')) {
    throw UsageError("'" + arg + "' is not a switch (+X or -X)");
  }
  const bool on = arg[0] == '+';
  const std::string body = arg.substr(1), key = lower(body);
  const auto rest = [&](size_t n) { return body.substr(n); };
  // A switch that carries a value reads the same after '-' as after '+' (POV-Ray 3.7 renders
  // with -W320 -H240 -Iscene.pov -Oout.png -Lfolder -R3); '+' alone also takes none.
  const auto given = [&](size_t n) { return on || !rest(n).empty(); };
  if (key.starts_with("wt")) {
    o.threads = int(whole(rest(2), arg, 1, 1024));
  } else if (key.starts_with("w") && given(1)) {
    o.width = int(whole(rest(1), arg, 1, 32768));
  } else if (key.starts_with("h") && given(1)) {
    o.height = int(whole(rest(1), arg, 1, 32768));
  } else if (key.starts_with("i") && given(1)) {
    if (rest(1).empty()) throw UsageError(arg + ": expected the scene file after +I");
    o.scene = rest(1);
  } else if (key.starts_with("o") && given(1)) {
    if (rest(1).empty()) throw UsageError(arg + ": expected the output file after +O");
    o.output = rest(1);
  } else if (key.starts_with("l") && given(1)) {
    if (rest(1).empty()) throw UsageError(arg + ": expected a folder after +L");
    o.library_paths.push_back(rest(1));
  } else if (key.starts_with("am") || key == "a" || (key.starts_with("a") && !on)) {
    if (key.starts_with("am"))
      throw UsageError(arg + ": only POV-Ray's method 1 (+AM1) is supported");
    o.antialias = on;
  } else if (key.starts_with("a")) {
    set_aa_threshold(o, rest(1), arg);
  } else if (key.starts_with("r") && given(1)) {
    o.aa_depth = int(whole(rest(1), arg, 1, 9));
  } else if (key.starts_with("j")) {
    on ? set_jitter(o, rest(1), arg) : void(o.jitter = false);
  } else if (apply_clock_switch(o, on, key, body, arg)) {
  } else if (key.size() >= 2 && given(2) &&
             set_partial_bound(o, BoundName::switch_key, key.substr(0, 2), arg,
                               [&] { return rest(2); })) {
  } else if (key.starts_with("sf") && given(2)) {
    o.animation.subset_start = number(rest(2), arg);
  } else if (key.starts_with("ef") && given(2)) {
    o.animation.subset_end = number(rest(2), arg);
  } else if (key == "c") {
    o.continue_trace = on;
  } else if (key.starts_with("d")) {
    o.display = on;  // POV-Ray's +Dxy: x and y choose a display type and palette; one here
  } else if (key == "p") {
    o.pause_when_done = on;
  } else if (!is_ignored_switch(key)) {
    throw UsageError("unknown switch '" + arg + "'; run 'convray --help' for the supported ones");
  }
}

// `-o /dev/full` names a device, not an image to write beside it as /dev/full.png, which is
// what adding POV-Ray's extension would do.
static void refuse_special_output(const std::string& output) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(output, error);
  if (error || !std::filesystem::exists(status) || std::filesystem::is_directory(status) ||
      std::filesystem::is_regular_file(status)) {
    return;
  }
  throw UsageError("-o " + output +
                   ": not a regular file (a device, pipe or socket); convray writes images "
                   "only to regular files");
}

RenderOptions parse_render_arguments(const std::vector<std::string>& args) {
  RenderOptions o;
  bool positional_scene = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.empty()) throw UsageError("empty argument");
    if (apply_long_option(o, args, i)) continue;
    if (is_setting_argument(arg)) {
      const size_t eq = arg.find('=');
      apply_ini_setting(o, arg.substr(0, eq), arg.substr(eq + 1));
    } else if (arg.size() > 1 && (arg[0] == '+' || arg[0] == '-') && arg[1] != '-') {
      apply_switch(o, arg);
    } else if (arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'; run 'convray --help'");
    } else if (is_ini_argument(arg)) {
      apply_ini_file(o, arg);
    } else if (positional_scene) {
      throw UsageError("one scene at a time: got '" + o.scene + "' and '" + arg + "'");
    } else {
      o.scene = arg;
      positional_scene = true;
    }
  }
  if (o.scene.empty()) {
    throw UsageError(
        "no scene file given (convray SCENE.pov, +ISCENE.pov, or Input_File_Name= "
        "in an INI file)");
  }
  o.window = partial_window(o.partial, o.width, o.height);  // after +W and +H, wherever given
  refuse_special_output(o.output);
  o.output_is_folder = names_folder(o.output);
  o.output = resolve_output(o.output, o.scene);
  plan_frames(o.animation);  // bad frame options are usage errors, found before any work
  return o;
}

}  // namespace convray::app
