// libFuzzer target: the render command's switches and INI files (src/app/render_options.cpp,
// src/app/ini_file.cpp), the text a user or a render farm's script hands convray before any
// scene is read. Every input must end in options or in a UsageError / InputError, never a
// crash, a hang or unbounded memory (issue 17).
//
// The input is split at its first NUL byte: before it, the switches, one per line; after it,
// the text of an INI file, written to a private temporary that the switches can name as
// "@INI" (replaced by its path, with any [section] kept).
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/render_options.hpp"
#include "app/usage_error.hpp"
#include "util/error.hpp"

namespace {

std::string temporary_ini() {
  static const std::string path =
      "/tmp/convray_options_fuzz_" + std::to_string(::getpid()) + ".ini";
  return path;
}

std::vector<std::string> switches(std::string_view text, const std::string& ini) {
  std::vector<std::string> args;
  while (!text.empty()) {
    const size_t end = std::min(text.find('\n'), text.size());
    std::string arg(text.substr(0, end));
    for (size_t at = arg.find("@INI"); at != std::string::npos; at = arg.find("@INI", at + ini.size())) {
      arg.replace(at, 4, ini);
    }
    args.push_back(std::move(arg));
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const size_t split = std::min(input.find('\0'), input.size());
  const std::string ini = temporary_ini();
  {
    std::ofstream file(ini, std::ios::binary | std::ios::trunc);
    if (split < input.size()) file << input.substr(split + 1);
  }
  try {
    convray::app::parse_render_arguments(switches(input.substr(0, split), ini));
  } catch (const convray::app::UsageError&) {
  } catch (const convray::InputError&) {
  }
  return 0;
}
