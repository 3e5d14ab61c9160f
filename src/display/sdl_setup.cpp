#include "display/sdl_setup.hpp"

#include <cstdlib>

#include "display/sdl_library.hpp"
#include "display/sdl_window.hpp"

namespace convray::display {

bool environment_set(const char* variable) {
  const char* value = std::getenv(variable);
  return value && *value;
}

// Without a display server to ask for, SDL would try each of its drivers (seconds, and
// libwayland's complaints on standard error) and settle on its offscreen one, which shows
// nothing: a batch render is told at once instead. SDL_VIDEODRIVER, when set, is obeyed.
// Otherwise only the servers named are tried: a DISPLAY whose server is gone fails with
// X11's reason, not after a detour through Wayland that complains on standard error.
namespace {

// The drivers to try, or nullptr for SDL_VIDEODRIVER's; asked before SDL is loaded, so a
// batch render without a display never loads it.
const char* drivers_to_try() {
  if (environment_set("SDL_VIDEODRIVER")) return nullptr;
  if (!environment_set("DISPLAY") && !environment_set("WAYLAND_DISPLAY")) {
    throw NoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
  }
  return !environment_set("WAYLAND_DISPLAY") ? "x11"
         : environment_set("DISPLAY")        ? "wayland,x11"
                                             : "wayland";
}

}  // namespace

void prepare_sdl_video() {
  const char* drivers = drivers_to_try();
  // Ctrl-C must stay convray's: SDL would turn SIGINT and SIGTERM into a quit event, and the
  // handler that removes unfinished files (util/partial_files) would never run.
  sdl().SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  // A window of ours is no reason to keep the screen saver away.
  sdl().SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
  if (drivers) sdl().SDL_SetHint(SDL_HINT_VIDEODRIVER, drivers);
}

}  // namespace convray::display
