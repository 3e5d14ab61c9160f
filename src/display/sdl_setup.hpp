#pragma once
// What every convray window does before SDL opens one (the +D preview, convray view): SDL's
// hints (Ctrl-C stays convray's, no screen-saver block) and the choice of video driver. Only
// src/display includes it; its sources include SDL.
#include <string>

namespace convray::display {

// Sets the hints and picks the driver; throws NoDisplay (sdl_window.hpp) when neither DISPLAY
// nor WAYLAND_DISPLAY is set (and SDL_VIDEODRIVER does not say otherwise).
void prepare_sdl_video();

// Whether the environment variable is set and not empty.
bool environment_set(const char* variable);

}  // namespace convray::display
