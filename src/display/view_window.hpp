#pragma once
// `convray view`'s window (docs/view.md): the picture, text over it (values, errors, the
// keys) set in DejaVu Sans Mono by SDL2_ttf, and what the mouse and keys did, as plain
// events for the command to act on. Everything here runs on the thread that opened it.
#include <memory>
#include <string>
#include <vector>

#include "display/preview_layout.hpp"
#include "display/sdl_window.hpp"

namespace convray::display {

// Debian's fonts-dejavu-core puts it here.
constexpr const char* kOverlayFont = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";

// The window could open but the overlay font could not be had; what() says which file.
class NoFont : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ViewEvent {
  enum class Kind { quit, key, drag, wheel, exposed };  // exposed: draw it again
  Kind kind = Kind::quit;
  char key = 0;       // key: the character typed ('c', 'R', '?', ...); 0 for others
  std::string name;   // key: SDL's name of the key ("Home", "Left", ...)
  int button = 0;     // drag: 1 left, 2 middle, 3 right
  int x = 0, y = 0;   // the mouse, in window pixels
  int dx = 0, dy = 0;  // drag: the motion since the last event, window pixels
  int wheel = 0;       // wheel: steps away from the user (positive) or towards
};

// The text drawn over the picture: lines at the top left (values, help) and an error, in
// red, at the bottom; empty ones draw nothing.
struct Overlay {
  std::vector<std::string> lines;
  std::string error;
  bool operator==(const Overlay&) const = default;
};

class ViewWindow {
 public:
  // Opens a `size` window. Throws NoDisplay as SdlWindow does, NoFont for a missing font.
  ViewWindow(const std::string& title, PreviewSize size, const std::string& font = kOverlayFont);
  ~ViewWindow();
  ViewWindow(const ViewWindow&) = delete;
  ViewWindow& operator=(const ViewWindow&) = delete;

  PreviewSize size() const { return size_; }
  // Whether nobody can see this driver's windows (SDL_VIDEODRIVER=dummy or offscreen).
  bool unseen() const;
  std::string driver() const;
  void set_title(const std::string& title);
  // Draws `levels` (8-bit RGB, the window's size) and `overlay` over them.
  void show(const std::vector<uint8_t>& levels, const Overlay& overlay);
  // The events that arrive within `milliseconds` (at least those waiting), in order.
  std::vector<ViewEvent> events(int milliseconds);

 private:
  struct Handles;
  void draw_text(const std::string& text, int x, int y, bool error);
  std::unique_ptr<Handles> sdl_;
  PreviewSize size_;
  bool dragging_ = false;
  int drag_button_ = 0;
};

}  // namespace convray::display
