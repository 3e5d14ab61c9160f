#include "display/sdl_window.hpp"

#include <SDL.h>

#include <algorithm>
#include <cstdlib>

namespace convray::display {

struct SdlWindow::Handles {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  bool video = false;  // SDL_InitSubSystem(SDL_INIT_VIDEO) succeeded

  ~Handles() {
    if (texture) SDL_DestroyTexture(texture);
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    if (video) SDL_QuitSubSystem(SDL_INIT_VIDEO);
    SDL_Quit();
  }
};

namespace {

[[noreturn]] void fail(const char* what) {
  throw NoDisplay(std::string(what) + ": " + SDL_GetError());
}

bool set(const char* variable) {
  const char* value = std::getenv(variable);
  return value && *value;
}

// Without a display server to ask for, SDL would try each of its drivers (seconds, and
// libwayland's complaints on standard error) and settle on its offscreen one, which shows
// nothing: a batch render is told at once instead. SDL_VIDEODRIVER, when set, is obeyed.
// Otherwise only the servers named are tried: a DISPLAY whose server is gone fails with
// X11's reason, not after a detour through Wayland that complains on standard error.
void choose_a_driver() {
  if (set("SDL_VIDEODRIVER")) return;
  if (!set("DISPLAY") && !set("WAYLAND_DISPLAY")) {
    throw NoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
  }
  const char* drivers = !set("WAYLAND_DISPLAY") ? "x11" : set("DISPLAY") ? "wayland,x11" : "wayland";
  SDL_SetHint(SDL_HINT_VIDEODRIVER, drivers);
}

}  // namespace

SdlWindow::SdlWindow(const std::string& title, PreviewSize size)
    : sdl_(std::make_unique<Handles>()), size_(size) {
  // Ctrl-C must stay convray's: SDL would turn SIGINT and SIGTERM into a quit event, and the
  // handler that removes unfinished files (util/partial_files) would never run.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  // A preview is no reason to keep the screen saver away.
  SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
  choose_a_driver();
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
    const char* display = std::getenv("DISPLAY");
    fail(display ? ("DISPLAY=" + std::string(display)).c_str() : "SDL_Init");
  }
  sdl_->video = true;
  if (unseen() && !set("SDL_VIDEODRIVER")) {
    throw NoDisplay("SDL found only its '" + driver() + "' driver, which shows nothing");
  }
  sdl_->window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                  size.width, size.height, SDL_WINDOW_SHOWN);
  if (!sdl_->window) fail("SDL_CreateWindow");
  // The software renderer copies our bytes to the window as they are: the picture on screen
  // is the file's, with no GPU, driver or colour management in between.
  sdl_->renderer = SDL_CreateRenderer(sdl_->window, -1, SDL_RENDERER_SOFTWARE);
  if (!sdl_->renderer) fail("SDL_CreateRenderer");
  sdl_->texture = SDL_CreateTexture(sdl_->renderer, SDL_PIXELFORMAT_RGB24,
                                    SDL_TEXTUREACCESS_STREAMING, size.width, size.height);
  if (!sdl_->texture) fail("SDL_CreateTexture");
  SDL_SetRenderDrawColor(sdl_->renderer, 0, 0, 0, 255);
  SDL_RenderClear(sdl_->renderer);
  SDL_RenderPresent(sdl_->renderer);
}

SdlWindow::~SdlWindow() = default;

std::string SdlWindow::driver() const {
  const char* name = SDL_GetCurrentVideoDriver();
  return name ? name : "";
}

bool SdlWindow::unseen() const {
  const std::string name = driver();
  return name == "dummy" || name == "offscreen";
}

void SdlWindow::set_title(const std::string& title) {
  SDL_SetWindowTitle(sdl_->window, title.c_str());
}

void SdlWindow::show(const std::vector<uint8_t>& levels) {
  SDL_UpdateTexture(sdl_->texture, nullptr, levels.data(), 3 * size_.width);
  SDL_RenderCopy(sdl_->renderer, sdl_->texture, nullptr, nullptr);
  SDL_RenderPresent(sdl_->renderer);
}

WindowEvent SdlWindow::wait(int milliseconds) {
  WindowEvent said = WindowEvent::none;
  SDL_Event event;
  bool any = SDL_WaitEventTimeout(&event, milliseconds) != 0;
  while (any) {
    if (event.type == SDL_QUIT ||
        (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE)) {
      said = WindowEvent::stop;
    } else if (event.type == SDL_KEYDOWN) {
      const SDL_Keycode k = event.key.keysym.sym;
      const bool stop = k == SDLK_ESCAPE || k == SDLK_q;
      said = std::max(said, stop ? WindowEvent::stop : WindowEvent::key);
    } else if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_EXPOSED) {
      SDL_RenderCopy(sdl_->renderer, sdl_->texture, nullptr, nullptr);
      SDL_RenderPresent(sdl_->renderer);
    }
    any = SDL_PollEvent(&event) != 0;
  }
  return said;
}

}  // namespace convray::display
