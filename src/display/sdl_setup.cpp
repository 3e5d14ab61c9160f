#include "display/sdl_setup.hpp"

#include <SDL.h>

#include <cstdlib>

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

void choose_a_driver() {
  if (environment_set("SDL_VIDEODRIVER")) return;
  if (!environment_set("DISPLAY") && !environment_set("WAYLAND_DISPLAY")) {
    throw NoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
  }
  const char* drivers = !environment_set("WAYLAND_DISPLAY") ? "x11"
                        : environment_set("DISPLAY")        ? "wayland,x11"
                                                            : "wayland";
  SDL_SetHint(SDL_HINT_VIDEODRIVER, drivers);
}

}  // namespace

void prepare_sdl_video() {
  // Ctrl-C must stay convray's: SDL would turn SIGINT and SIGTERM into a quit event, and the
  // handler that removes unfinished files (util/partial_files) would never run.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  // A window of ours is no reason to keep the screen saver away.
  SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
  choose_a_driver();
}

}  // namespace convray::display
