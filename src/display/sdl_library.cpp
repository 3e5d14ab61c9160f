#include "display/sdl_library.hpp"

#include <dlfcn.h>

#include <atomic>
#include <mutex>
#include <string>

#include "display/sdl_window.hpp"

namespace convray::display {
namespace {

// The sonames Debian's libsdl2-2.0-0 and libsdl2-ttf-2.0-0 install.
constexpr const char* kSdl = "libSDL2-2.0.so.0";
constexpr const char* kTtf = "libSDL2_ttf-2.0.so.0";

struct Loaded {
  SdlLibrary functions;
  std::string failure;  // empty when every function was found
};

void* open_library(const char* name, std::string& failure) {
  void* handle = ::dlopen(name, RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    failure = std::string("cannot load ") + name + " (" + (why ? why : "unknown reason") +
              "; apt-get install libsdl2-2.0-0 libsdl2-ttf-2.0-0)";
  }
  return handle;
}

// Fills `to` with the symbol `name` of `handle`; false (and `failure` said) when it is missing.
template <class Function>
bool find(void* handle, const char* library, const char* name, Function& to, std::string& failure) {
  to = reinterpret_cast<Function>(::dlsym(handle, name));
  if (!to && failure.empty()) failure = std::string(library) + " lacks " + name;
  return to != nullptr;
}

Loaded load() {
  Loaded out;
  void* sdl = open_library(kSdl, out.failure);
  void* ttf = sdl ? open_library(kTtf, out.failure) : nullptr;
  if (!ttf) return out;
#define CONVRAY_SDL_FIND(name) find(sdl, kSdl, #name, out.functions.name, out.failure);
  CONVRAY_SDL_FUNCTIONS(CONVRAY_SDL_FIND)
#undef CONVRAY_SDL_FIND
#define CONVRAY_TTF_FIND(name) find(ttf, kTtf, #name, out.functions.name, out.failure);
  CONVRAY_TTF_FUNCTIONS(CONVRAY_TTF_FIND)
#undef CONVRAY_TTF_FIND
  return out;  // the libraries stay open for the process's life
}

std::atomic<bool> loaded{false};

}  // namespace

const SdlLibrary& sdl() {
  static const Loaded library = load();  // thread-safe, once
  if (!library.failure.empty()) throw NoDisplay("SDL2: " + library.failure);
  loaded.store(true, std::memory_order_release);
  return library.functions;
}

bool sdl_loaded() { return loaded.load(std::memory_order_acquire); }

}  // namespace convray::display
