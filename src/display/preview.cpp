#include "display/preview.hpp"

#include <chrono>
#include <exception>
#include <filesystem>
#include <ostream>
#include <thread>

#include "display/sdl_window.hpp"

namespace convray::display {

namespace {

render::PixelWindow shown_part(const PreviewOptions& o) {
  return o.window.value_or(render::PixelWindow{0, 0, o.width, o.height});
}

PreviewSize window_size(const PreviewOptions& o) {
  const render::PixelWindow shown = shown_part(o);
  return fit_preview(shown.x1 - shown.x0, shown.y1 - shown.y0);
}

// How often the window is redrawn while a render fills it: often enough to look live, seldom
// enough that copying the picture costs nothing next to rendering it.
constexpr int kRedrawMilliseconds = 40;

}  // namespace

std::unique_ptr<Preview> Preview::open(const PreviewOptions& options, std::ostream& err) {
  if (shown_part(options).empty()) return nullptr;  // an empty partial render: nothing to show
  std::unique_ptr<SdlWindow> window;
  try {
    window = std::make_unique<SdlWindow>("convray: " + options.scene, window_size(options));
  } catch (const NoDisplay& e) {
    err << "convray: +D: no display available (" << e.what()
        << "); rendering without the preview window\n";
    return nullptr;
  }
  if (window->unseen()) {
    // SDL_VIDEODRIVER=dummy opens windows nobody sees: said, so that it is not taken for one.
    err << "convray: +D: SDL's video driver '" << window->driver()
        << "' shows no window (SDL_VIDEODRIVER); the preview runs unseen\n";
  }
  return std::unique_ptr<Preview>(new Preview(options, std::move(window)));
}

Preview::Preview(const PreviewOptions& options, std::unique_ptr<SdlWindow> window)
    : options_(options),
      window_(std::move(window)),
      image_(shown_part(options), window_size(options)),
      pixels_(shown_part(options).pixels()) {}

Preview::~Preview() = default;

bool Preview::seen() const { return window_ && !window_->unseen(); }

void Preview::run(const std::string& label, const std::function<void()>& work) {
  if (cancelled_) throw render::RenderCancelled("the preview window was closed");
  label_ = label;
  done_ = 0;
  refining_ = false;
  finished_ = false;
  std::exception_ptr error;
  std::atomic<bool> over{false};
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      error = std::current_exception();
    }
    over = true;
  });
  try {
    while (!over) keep_live(kRedrawMilliseconds);
  } catch (...) {
    // The worker must be joined whatever happens here: told to stop at its next tile.
    cancelled_ = true;
    worker.join();
    throw;
  }
  worker.join();
  keep_live(0);  // the finished picture
  if (error) std::rethrow_exception(error);
}

void Preview::keep_live(int milliseconds) {
  if (!window_) {
    std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
    return;
  }
  // The title first: once it says done, the picture drawn after it is the finished one.
  const std::string now = title();
  if (image_.take_if_changed(levels_)) window_->show(levels_);
  if (now != shown_title_) window_->set_title(now), shown_title_ = now;
  if (window_->wait(milliseconds) == WindowEvent::stop) {
    // Closed, or Escape or q: the render stops at its next tile, and the window goes now.
    cancelled_ = true;
    window_.reset();
  }
}

void Preview::tile_done(const render::FinishedTile& tile) {
  if (cancelled_) throw render::RenderCancelled("the preview window was closed");
  image_.put(tile.area, tile.rgb);
  if (tile.refinement) {
    refining_ = true;
  } else {
    done_ += tile.area.intersection(shown_part(options_)).pixels();
  }
}

void Preview::show_picture(std::span<const float> rgb) {
  image_.put({0, 0, options_.width, options_.height}, rgb);
  finished_ = true;
}

std::string Preview::title() const {
  std::string t = "convray: " + std::filesystem::path(options_.scene).filename().string();
  if (!label_.empty()) t += ", " + label_;
  if (finished_) return t + ", done";
  if (refining_) return t + ", anti-aliasing";
  const uint64_t percent = pixels_ ? 100 * done_ / pixels_ : 100;
  return t + ", " + std::to_string(percent) + "%";
}

void Preview::wait_until_dismissed() {
  if (!seen()) return;
  if (image_.take_if_changed(levels_)) window_->show(levels_);
  window_->set_title(title() + " (press a key or close)");
  while (window_->wait(100) == WindowEvent::none) {
  }
  window_.reset();
}

}  // namespace convray::display
