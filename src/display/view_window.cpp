#include "display/view_window.hpp"

#include <algorithm>
#include <filesystem>

#include "display/picture_window.hpp"
#include "display/sdl_library.hpp"

namespace convray::display {

// The font is closed (and SDL2_ttf left) before the window and SDL close.
struct ViewWindow::Handles {
  std::unique_ptr<PictureWindow> picture;
  TTF_Font* font = nullptr;
  bool ttf = false;

  ~Handles() {
    if (font) sdl().TTF_CloseFont(font);
    if (ttf) sdl().TTF_Quit();
  }
};

namespace {

// Text 13 pixels high: readable, and a dozen lines leave most of a 640 x 480 picture free.
constexpr int kFontPoints = 13;

}  // namespace

ViewWindow::ViewWindow(const std::string& title, PreviewSize size, const std::string& font)
    : sdl_(std::make_unique<Handles>()), size_(size) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(font, error)) {
    throw NoFont("the overlay font " + font +
                 " is missing (apt-get install fonts-dejavu-core; bash scripts/setup.sh "
                 "installs it)");
  }
  sdl_->picture = std::make_unique<PictureWindow>(title, size);
  if (sdl().TTF_Init() != 0) throw NoFont(std::string("SDL2_ttf: ") + sdl().SDL_GetError());
  sdl_->ttf = true;
  sdl_->font = sdl().TTF_OpenFont(font.c_str(), kFontPoints);
  if (!sdl_->font) throw NoFont("cannot open the font " + font + ": " + sdl().SDL_GetError());
  sdl().SDL_SetRenderDrawBlendMode(sdl_->picture->renderer(), SDL_BLENDMODE_BLEND);
}

ViewWindow::~ViewWindow() = default;

std::string ViewWindow::driver() const { return sdl_->picture->driver(); }

bool ViewWindow::unseen() const { return sdl_->picture->unseen(); }

void ViewWindow::set_title(const std::string& title) { sdl_->picture->set_title(title); }

// One line of text on a dark translucent band, so that it reads on any picture.
void ViewWindow::draw_text(const std::string& text, int x, int y, bool error) {
  if (text.empty()) return;
  const SDL_Color colour = error ? SDL_Color{255, 110, 100, 255} : SDL_Color{235, 235, 235, 255};
  SDL_Surface* surface = sdl().TTF_RenderUTF8_Blended(sdl_->font, text.c_str(), colour);
  if (!surface) return;  // a line SDL2_ttf cannot set is left out, not fatal
  SDL_Renderer* renderer = sdl_->picture->renderer();
  SDL_Texture* texture = sdl().SDL_CreateTextureFromSurface(renderer, surface);
  const SDL_Rect band{x - 3, y, surface->w + 6, surface->h};
  const SDL_Rect at{x, y, surface->w, surface->h};
  sdl().SDL_FreeSurface(surface);
  if (!texture) return;
  sdl().SDL_SetRenderDrawColor(renderer, 0, 0, 0, 170);
  sdl().SDL_RenderFillRect(renderer, &band);
  sdl().SDL_RenderCopy(renderer, texture, nullptr, &at);
  sdl().SDL_DestroyTexture(texture);
}

void ViewWindow::show(const std::vector<uint8_t>& levels, const Overlay& overlay) {
  sdl_->picture->draw(levels);
  const int line = sdl().TTF_FontLineSkip(sdl_->font);
  int y = 4;
  for (const std::string& text : overlay.lines) draw_text(text, 6, y, false), y += line;
  // The error wraps (monospace: a fixed number of characters a line), its last line at the
  // bottom, so that a long path does not push the message out of the window; three lines at
  // most, so that the picture stays in view (the terminal has all of it).
  int advance = 8;
  sdl().TTF_GlyphMetrics(sdl_->font, 'M', nullptr, nullptr, nullptr, nullptr, &advance);
  const size_t columns = size_t(std::max(10, (size_.width - 12) / std::max(1, advance)));
  const std::string& error = overlay.error;
  const size_t rows = std::min<size_t>(3, (error.size() + columns - 1) / columns);
  for (size_t r = 0; r < rows; ++r) {
    const int at = size_.height - int(rows - r) * line - 4;
    draw_text(error.substr(r * columns, columns), 6, at, true);
  }
  sdl_->picture->present();
}

std::vector<ViewEvent> ViewWindow::events(int milliseconds) {
  std::vector<ViewEvent> out;
  SDL_Event e;
  bool any = sdl().SDL_WaitEventTimeout(&e, milliseconds) != 0;
  for (; any; any = sdl().SDL_PollEvent(&e) != 0) {
    ViewEvent v;
    sdl().SDL_GetMouseState(&v.x, &v.y);
    if (e.type == SDL_QUIT ||
        (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE)) {
      out.push_back(v);  // Kind::quit
    } else if (e.type == SDL_TEXTINPUT) {
      v.kind = ViewEvent::Kind::key;
      v.key = e.text.text[1] == 0 ? e.text.text[0] : 0;  // one ASCII character, as typed
      if (v.key) out.push_back(v);
    } else if (e.type == SDL_KEYDOWN) {
      // Keys that type no character (Escape, Home, arrows) come by name.
      const SDL_Keycode k = e.key.keysym.sym;
      if (k >= 32 && k < 127) continue;  // typed: SDL_TEXTINPUT says which character
      v.kind = ViewEvent::Kind::key;
      v.name = sdl().SDL_GetKeyName(k);
      out.push_back(v);
    } else if (e.type == SDL_MOUSEBUTTONDOWN) {
      dragging_ = true, drag_button_ = e.button.button;
    } else if (e.type == SDL_MOUSEBUTTONUP) {
      dragging_ = false;
    } else if (e.type == SDL_MOUSEMOTION && dragging_) {
      v.kind = ViewEvent::Kind::drag;
      v.button = drag_button_;
      v.x = e.motion.x, v.y = e.motion.y, v.dx = e.motion.xrel, v.dy = e.motion.yrel;
      out.push_back(v);
    } else if (e.type == SDL_MOUSEWHEEL) {
      v.kind = ViewEvent::Kind::wheel;
      v.wheel = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
      out.push_back(v);
    } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_EXPOSED) {
      v.kind = ViewEvent::Kind::exposed;
      out.push_back(v);
    }
  }
  return out;
}

}  // namespace convray::display
