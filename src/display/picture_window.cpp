#include "display/picture_window.hpp"

#include <cstdlib>

#include "display/sdl_library.hpp"
#include "display/sdl_setup.hpp"
#include "display/sdl_window.hpp"

namespace convray::display {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw NoDisplay(what + ": " + sdl().SDL_GetError());
}

}  // namespace

PictureWindow::PictureWindow(const std::string& title, PreviewSize size) : size_(size) {
  prepare_sdl_video();
  if (sdl().SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
    const char* display = std::getenv("DISPLAY");
    fail(display ? "DISPLAY=" + std::string(display) : "SDL_Init");
  }
  sdl_.video = true;
  sdl_.window =
      sdl().SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                             size.width, size.height, SDL_WINDOW_SHOWN);
  if (!sdl_.window) fail("SDL_CreateWindow");
  // The software renderer copies our bytes to the window as they are: the picture on screen
  // is the file's, with no GPU, driver or colour management in between.
  sdl_.renderer = sdl().SDL_CreateRenderer(sdl_.window, -1, SDL_RENDERER_SOFTWARE);
  if (!sdl_.renderer) fail("SDL_CreateRenderer");
  sdl_.texture = sdl().SDL_CreateTexture(sdl_.renderer, SDL_PIXELFORMAT_RGB24,
                                         SDL_TEXTUREACCESS_STREAMING, size.width, size.height);
  if (!sdl_.texture) fail("SDL_CreateTexture");
  sdl().SDL_SetRenderDrawColor(sdl_.renderer, 0, 0, 0, 255);
  sdl().SDL_RenderClear(sdl_.renderer);
  sdl().SDL_RenderPresent(sdl_.renderer);
}

PictureWindow::Handles::~Handles() {
  if (!sdl_loaded()) return;  // SDL2 could not be loaded: nothing was opened
  if (texture) sdl().SDL_DestroyTexture(texture);
  if (renderer) sdl().SDL_DestroyRenderer(renderer);
  if (window) sdl().SDL_DestroyWindow(window);
  if (video) sdl().SDL_QuitSubSystem(SDL_INIT_VIDEO);
  sdl().SDL_Quit();
}

std::string PictureWindow::driver() const {
  const char* name = sdl().SDL_GetCurrentVideoDriver();
  return name ? name : "";
}

bool PictureWindow::unseen() const {
  const std::string name = driver();
  return name == "dummy" || name == "offscreen";
}

void PictureWindow::set_title(const std::string& title) {
  sdl().SDL_SetWindowTitle(sdl_.window, title.c_str());
}

void PictureWindow::draw(const std::vector<uint8_t>& levels) {
  sdl().SDL_UpdateTexture(sdl_.texture, nullptr, levels.data(), 3 * size_.width);
  redraw();
}

void PictureWindow::redraw() {
  sdl().SDL_RenderCopy(sdl_.renderer, sdl_.texture, nullptr, nullptr);
}

void PictureWindow::present() { sdl().SDL_RenderPresent(sdl_.renderer); }

}  // namespace convray::display
