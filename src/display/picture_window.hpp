#pragma once
// SDL's video, one window, its software renderer and a streaming RGB24 texture of the
// window's size: what both of convray's windows (+D's SdlWindow, convray view's ViewWindow)
// show their picture with. Only src/display includes it; its sources include SDL.
#include <cstdint>
#include <string>
#include <vector>

#include "display/preview_layout.hpp"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace convray::display {

class PictureWindow {
 public:
  // Sets SDL's hints, starts its video and opens a `size` window titled `title`, cleared to
  // black. Throws NoDisplay (sdl_window.hpp) with SDL's reason when any step fails.
  PictureWindow(const std::string& title, PreviewSize size);
  PictureWindow(const PictureWindow&) = delete;
  PictureWindow& operator=(const PictureWindow&) = delete;

  // The video driver SDL chose ("x11", "wayland", "dummy", ...).
  std::string driver() const;
  // Whether nobody can see this driver's windows (SDL_VIDEODRIVER=dummy or offscreen).
  bool unseen() const;
  void set_title(const std::string& title);
  // Copies `levels` (8-bit RGB, the window's size, top row first) to the window's texture and
  // draws it; nothing shows before present().
  void draw(const std::vector<uint8_t>& levels);
  // Draws the texture as it was last given (a window uncovered), without presenting.
  void redraw();
  void present();

  SDL_Renderer* renderer() const { return sdl_.renderer; }

 private:
  // A member, so that what a constructor that throws part way made is released too.
  struct Handles {
    bool video = false;  // SDL_InitSubSystem(SDL_INIT_VIDEO) succeeded
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;
    ~Handles();  // closes the window and SDL
  };
  PreviewSize size_;
  Handles sdl_;
};

}  // namespace convray::display
