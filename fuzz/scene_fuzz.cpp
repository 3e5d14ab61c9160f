// libFuzzer target for the scene parser (src/sdl): any text must either parse or fail with an
// InputError (file:line:col: message). A crash, a sanitizer report, a hang, a leak or any
// other exception is a bug. scripts/fuzz-scene.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "sdl/parser.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  convray::sdl::ParseOptions options;
  // Runaway scenes must stop by their limits, well inside libFuzzer's per-input timeout.
  options.max_loop_iterations = 10'000;
  options.max_tokens = 2'000'000;
  options.max_macro_depth = 64;
  options.max_include_depth = 8;
  // Includes: only POV-Ray's installed files; nothing of the fuzzer's own folder.
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    convray::sdl::parse_string(text, "fuzz.pov", options);
  } catch (const convray::InputError&) {
    // Bad input, reported as it should be.
  }
  return 0;
}
