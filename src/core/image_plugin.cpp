#include "core/image_plugin.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "core/oiio_plugin_api.hpp"
#include "util/error.hpp"

namespace convray::image_plugin {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPluginName = "libconvray_oiio.so";

struct Plugin {
  ConvrayOiioCanWriteFn* can_write = nullptr;
  ConvrayOiioWriteFn* write = nullptr;
  ConvrayOiioReadsWholeFn* reads_whole = nullptr;
  ConvrayOiioReadFn* read = nullptr;
  std::string problem;  // why it could not be loaded; empty once loaded
};

// Beside the running program, the way $ORIGIN finds a library: a build folder and an
// installed copy both carry the plugin next to the executable. When this code is itself in a
// shared object (the Python module, src/python/), the program is python3, so the plugin is
// looked for beside that object instead, where the build puts a link to it.
fs::path plugin_file() {
  Dl_info self{};
  if (::dladdr(reinterpret_cast<const void*>(&plugin_file), &self) != 0 && self.dli_fname &&
      std::string_view(self.dli_fname).ends_with(".so")) {
    std::error_code error;
    const fs::path object = fs::absolute(fs::path(self.dli_fname), error);
    if (!error) return object.parent_path() / kPluginName;
  }
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  return (error ? fs::path(".") : program.parent_path()) / kPluginName;
}

Plugin load() {
  Plugin plugin;
  const fs::path file = plugin_file();
  // Never closed: OpenImageIO keeps threads and caches for the life of the process.
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* error = ::dlerror();
    std::string reason = error ? error : "no reason given";
    if (reason.starts_with(file.string() + ": ")) reason.erase(0, file.string().size() + 2);
    plugin.problem = "formats other than .png need the plugin " + file.string() +
                     ", which cannot be loaded: " + reason +
                     " (it is built beside convray, by the same build)";
    return plugin;
  }
  auto* version =
      reinterpret_cast<ConvrayOiioVersionFn*>(::dlsym(handle, CONVRAY_OIIO_VERSION_SYMBOL));
  plugin.can_write =
      reinterpret_cast<ConvrayOiioCanWriteFn*>(::dlsym(handle, CONVRAY_OIIO_CAN_WRITE_SYMBOL));
  plugin.write = reinterpret_cast<ConvrayOiioWriteFn*>(::dlsym(handle, CONVRAY_OIIO_WRITE_SYMBOL));
  plugin.reads_whole =
      reinterpret_cast<ConvrayOiioReadsWholeFn*>(::dlsym(handle, CONVRAY_OIIO_READS_WHOLE_SYMBOL));
  plugin.read = reinterpret_cast<ConvrayOiioReadFn*>(::dlsym(handle, CONVRAY_OIIO_READ_SYMBOL));
  if (!version || version() != CONVRAY_OIIO_PLUGIN_VERSION || !plugin.can_write || !plugin.write ||
      !plugin.reads_whole || !plugin.read) {
    plugin.problem = "formats other than .png need the plugin " + file.string() +
                     ", which is from another version of convray (rebuild it with convray)";
  }
  return plugin;
}

// The plugin, loaded once (thread-safe: a function-local static); throws when it is missing.
const Plugin& plugin_for(const std::string& path) {
  static const Plugin plugin = load();
  if (!plugin.problem.empty()) throw InputError({path}, plugin.problem);
  return plugin;
}

}  // namespace

bool can_write(const std::string& path) { return plugin_for(path).can_write(path.c_str()) != 0; }

void write(const std::string& format_path, const std::string& file, int width, int height, int bits,
           const std::string& color_space, const float* values) {
  char message[512] = "";
  const int written = plugin_for(format_path)
                          .write(format_path.c_str(), file.c_str(), width, height, bits,
                                 color_space.c_str(), values, message, sizeof message);
  if (!written) {
    const std::string reason = message[0] ? message : "the writer gave no reason";
    throw InputError({format_path}, "cannot write the image: " + reason);
  }
}

bool reads_whole(const std::string& path, int width, int height) {
  return plugin_for(path).reads_whole(path.c_str(), width, height) != 0;
}

ReadImage read(const std::string& path) {
  char message[512] = "";
  int width = 0, height = 0, linear = 0, bits = 8, grey = 0;
  float* values = nullptr;
  const int done = plugin_for(path).read(path.c_str(), &width, &height, &linear, &bits, &grey,
                                         &values, message, sizeof message);
  if (!done) {
    const std::string reason = message[0] ? message : "the reader gave no reason";
    throw InputError({path}, "cannot read the image: " + reason);
  }
  ReadImage image;
  image.width = width;
  image.height = height;
  image.linear = linear != 0;
  image.bits = bits;
  image.grey = grey != 0;
  image.rgba.assign(values, values + size_t(width) * size_t(height) * 4);
  std::free(values);
  return image;
}

}  // namespace convray::image_plugin
