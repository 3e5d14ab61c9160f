#pragma once
// `convray scene.pov [options]`: the render command's options, from our own
// long options or POV-Ray's switches (`+Iscene.pov +Oout.png +W800 +H600 +A0.3
// -D +WT2`), which may be mixed.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace convray::app {

struct RenderOptions {
  std::string scene;              // +I / the positional argument
  std::string output;             // +O / -o; default: the scene's name with .png, here
  int width = 800, height = 600;  // +W +H
  bool antialias = false;         // +A[threshold] / -A
  double aa_threshold = 0.3;
  int aa_depth = 3;     // +R n: n x n samples where a pixel is supersampled
  bool jitter = false;  // +J[amount] / -J (reproducible either way)
  double jitter_amount = 1.0;
  int threads = 0;                                       // +WT n; 0: every core
  std::vector<std::string> library_paths;                // +L path
  std::vector<std::pair<std::string, double>> declares;  // Declare=ID=value
  double clock = 0.0;                                    // +K value
  bool clock_given = false;
  bool stats = false;  // --stats
  bool quiet = false;  // --quiet: no summary line
};

// A command line the render command cannot accept; the message names the
// argument.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads the arguments after the program name. POV-Ray's switches are
// case-insensitive and start with + (on) or - (off); unknown ones are errors,
// never silently ignored, except the display and console switches POV-Ray users
// habitually pass (+D -D +V -V +P -P -GA ...), which do nothing here.
RenderOptions parse_render_arguments(const std::vector<std::string>& args);

// The output file POV-Ray would write: the scene's base name with .png, in the
// current folder.
std::string default_output_name(const std::string& scene);

extern const char* const kRenderUsage;

}  // namespace convray::app
