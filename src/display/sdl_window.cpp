#include "display/sdl_window.hpp"

#include <algorithm>

#include "display/picture_window.hpp"
#include "display/sdl_library.hpp"
#include "display/sdl_setup.hpp"

namespace convray::display {

SdlWindow::SdlWindow(const std::string& title, PreviewSize size)
    : picture_(std::make_unique<PictureWindow>(title, size)) {
  if (unseen() && !environment_set("SDL_VIDEODRIVER")) {
    throw NoDisplay("SDL found only its '" + driver() + "' driver, which shows nothing");
  }
}

SdlWindow::~SdlWindow() = default;

std::string SdlWindow::driver() const { return picture_->driver(); }

bool SdlWindow::unseen() const { return picture_->unseen(); }

void SdlWindow::set_title(const std::string& title) { picture_->set_title(title); }

void SdlWindow::show(const std::vector<uint8_t>& levels) {
  picture_->draw(levels);
  picture_->present();
}

WindowEvent SdlWindow::wait(int milliseconds) {
  WindowEvent said = WindowEvent::none;
  SDL_Event event;
  bool any = sdl().SDL_WaitEventTimeout(&event, milliseconds) != 0;
  while (any) {
    if (event.type == SDL_QUIT ||
        (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE)) {
      said = WindowEvent::stop;
    } else if (event.type == SDL_KEYDOWN) {
      const SDL_Keycode k = event.key.keysym.sym;
      const bool stop = k == SDLK_ESCAPE || k == SDLK_q;
      said = std::max(said, stop ? WindowEvent::stop : WindowEvent::key);
    } else if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_EXPOSED) {
      picture_->redraw();
      picture_->present();
    }
    any = sdl().SDL_PollEvent(&event) != 0;
  }
  return said;
}

}  // namespace convray::display
