#pragma once
// The one window of the preview, through SDL2: the only code in convray that includes SDL
// (docs/architecture.md). Everything here must be called on the thread that opened it (SDL's
// video calls belong to one thread): the preview keeps that thread for the window and renders
// on another (preview.hpp).
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "display/preview_layout.hpp"

namespace convray::display {

class PictureWindow;

// SDL could not give us a window; what() is SDL's reason.
class NoDisplay : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the person at the window did since the last look.
enum class WindowEvent {  // in order of strength
  none,
  key,   // pressed a key other than Escape and q
  stop,  // closed the window, or pressed Escape or q
};

class SdlWindow {
 public:
  // Opens a `size` window titled `title`. Throws NoDisplay when SDL finds no display or
  // cannot make the window.
  SdlWindow(const std::string& title, PreviewSize size);
  ~SdlWindow();
  SdlWindow(const SdlWindow&) = delete;
  SdlWindow& operator=(const SdlWindow&) = delete;

  // The video driver SDL chose ("x11", "wayland", "dummy", ...).
  std::string driver() const;
  // Whether nobody can see this driver's windows (SDL_VIDEODRIVER=dummy or offscreen).
  bool unseen() const;

  void set_title(const std::string& title);
  // Draws `levels` (8-bit RGB, the window's size, top row first) and shows them.
  void show(const std::vector<uint8_t>& levels);
  // Handles the events that arrive within `milliseconds` (at least the waiting ones); says
  // the strongest: stop over key over none. An uncovered window is redrawn here.
  WindowEvent wait(int milliseconds);

 private:
  std::unique_ptr<PictureWindow> picture_;
};

}  // namespace convray::display
