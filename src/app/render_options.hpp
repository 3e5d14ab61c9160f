#pragma once
// `convray scene.pov [options]`: the render command's options, from our own
// long options, POV-Ray's switches (`+Iscene.pov +Oout.png +W800 +H600 +A0.3
// -D +WT2`) and POV-Ray's INI files (`convray walk.ini[Fast]`), which may be mixed;
// later settings override earlier ones, as in POV-Ray.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "app/partial_image.hpp"
#include "app/usage_error.hpp"

namespace convray::app {

struct RenderOptions {
  std::string scene;  // +I / the positional argument
  // +O / -o, resolved by frame_names.hpp: the still's file; frames insert their number.
  std::string output;
  bool output_is_folder = false;  // +Oout/: the folder is created when missing
  int width = 800, height = 600;  // +W +H
  bool antialias = false;         // +A[threshold] / -A
  double aa_threshold = 0.3;
  int aa_depth = 3;     // +R n: n x n samples where a pixel is supersampled
  bool jitter = false;  // +J[amount] / -J (reproducible either way)
  double jitter_amount = 1.0;
  PartialImage partial;  // +SC +EC +SR +ER: only a rectangle of the picture
  std::optional<render::PixelWindow> window;  // the rectangle's pixels, from `partial`
  int threads = 0;                                       // +WT n; 0: every core
  std::vector<std::string> library_paths;                // +L path
  std::vector<std::string> read_folders;                 // --allow-read DIR
  bool read_anywhere = false;                            // --allow-read-anywhere
  std::vector<std::pair<std::string, double>> declares;  // Declare=ID=value
  AnimationOptions animation;   // +K +KFI +KFF +KI +KF +KC +SF +EF, Frame_Step
  bool continue_trace = false;  // +C: skip frames whose files are already complete
  std::string video;            // --video FILE: assemble the frames with ffmpeg
  double video_fps = 25.0;      // --fps
  bool list_frames = false;     // --list-frames: print the frames (number, clock, file) only
  bool display = false;         // +D / Display=on / --display: the preview window (display/)
  bool pause_when_done = false;  // +P / Pause_When_Done=on / --pause: it stays open at the end
  bool stats = false;           // --stats
  bool quiet = false;           // --quiet: no summary line
  bool force = false;           // --force: render an image larger than the memory estimate allows
};

// Reads the arguments after the program name. POV-Ray's switches are
// case-insensitive and start with + (on) or - (off); unknown ones are errors,
// never silently ignored, except the console switches POV-Ray users habitually pass
// (+V -V -GA +X ...), which do nothing here. An argument
// ending in .ini (or .ini[Section]) is an INI file, read in place (ini_file.hpp).
// Throws UsageError, or InputError (file:line:col) for a bad line in an INI file.
RenderOptions parse_render_arguments(const std::vector<std::string>& args);

// One POV-Ray switch ("+W640", "-A") or INI setting ("Width", "640"), as the
// command line and INI files give them. Throw UsageError.
void apply_switch(RenderOptions& options, const std::string& argument);
void apply_ini_setting(RenderOptions& options, const std::string& key, const std::string& value);

extern const char* const kRenderUsage;

}  // namespace convray::app
