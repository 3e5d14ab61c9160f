#include "display/sdl_window.hpp"

#include "display/sdl_setup.hpp"

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

}  // namespace

SdlWindow::SdlWindow(const std::string& title, PreviewSize size)
    : sdl_(std::make_unique<Handles>()), size_(size) {
  prepare_sdl_video();
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
    const char* display = std::getenv("DISPLAY");
    fail(display ? ("DISPLAY=" + std::string(display)).c_str() : "SDL_Init");
  }
  sdl_->video = true;
  if (unseen() && !environment_set("SDL_VIDEODRIVER")) {
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
