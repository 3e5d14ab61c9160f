#pragma once
// The same scene text read by the installed POV-Ray 3.7 and by our parser, compared through
// what their #debug directives print: POV-Ray's debug stream (+GD to a file; a 1x1 render
// without an output file) against the texts of our `#debug` messages. Tests skip when povray
// is not installed.
#include <string>

#include "reference/povray_debug_stream.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::povray_testing {

using ::convray::povray_testing::povray_installed;
using ::convray::povray_testing::povray_run;
using ::convray::povray_testing::PovRayRun;

// What our #debug directives print for `scene`, each message followed by a newline (the
// scenes in these tests end every #debug text with "\n", which our messages drop).
inline std::string convray_debug(const std::string& scene) {
  const ParseResult result = parse_string(scene, "scene.pov", {});
  std::string debug;
  for (const std::string& warning : result.warnings) {
    const std::size_t at = warning.find(": #debug: ");
    if (at != std::string::npos) debug += warning.substr(at + 10) + "\n";
  }
  return debug;
}

}  // namespace convray::sdl::povray_testing
