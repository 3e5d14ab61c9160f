#pragma once
// POV-Ray's +D: a window that fills in tile by tile as the render proceeds, and +P (Pause_When_
// Done), which keeps it open at the end until a key is pressed in it or it is closed.
//
//  - The window is the picture's size (a partial render's: its rectangle only), scaled down to
//    fit 1280 x 1024 (preview_layout.hpp); its title names the scene, the frame and progress.
//  - It shows the 8-bit sRGB levels the PNG file gets (preview_image.hpp); at the end of each
//    frame the finished film replaces the tiles, so the window then shows the file's pixels.
//  - Closing it, or Escape or q in it, during a render stops the render (RenderCancelled): the
//    frame is not written, an earlier file of that name stays as it was (files appear whole or
//    not at all), and convray exits non-zero, as POV-Ray's display stops its render.
//  - Where no window can be had (no DISPLAY or WAYLAND_DISPLAY, SDL fails) open() says so in
//    one line and gives nullptr: the render goes on without it, and writes the same bytes.
//
// SDL wants its window handled by one thread: the one that opened the preview keeps it live
// in run(), while the work runs on a thread of its own.
#include <atomic>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "display/preview_image.hpp"
#include "render/pixel_window.hpp"
#include "render/render_observer.hpp"

namespace convray::display {

class SdlWindow;

struct PreviewOptions {
  std::string scene;  // named in the title
  int width = 0, height = 0;                  // the picture's
  std::optional<render::PixelWindow> window;  // a partial render's rectangle
};

class Preview final : public render::RenderObserver {
 public:
  // The preview window, or nullptr when none can be opened, which is said in one line on
  // `err`. Call on the thread that will call run() and wait_until_dismissed().
  static std::unique_ptr<Preview> open(const PreviewOptions& options, std::ostream& err);
  ~Preview() override;

  // Runs `work` on a thread of its own while this thread keeps the window drawn and listens
  // to it; `label` ("frame 3 (3/10)", or empty) goes in the title. Rethrows what `work`
  // threw: RenderCancelled (from tile_done) if the window was closed meanwhile. Throws
  // RenderCancelled without running `work` if it was closed before.
  void run(const std::string& label, const std::function<void()>& work);

  // From any thread: one finished tile; throws RenderCancelled once the window is closed.
  void tile_done(const render::FinishedTile& tile) override;

  // From any thread: the finished picture (width * height * 3 linear floats, as written).
  void show_picture(std::span<const float> rgb);

  // Whether a person can see the window: it is open, on a driver that shows windows.
  bool seen() const;

  // +P: keeps the window open until a key is pressed in it or it is closed. Returns at once
  // unless seen().
  void wait_until_dismissed();

 private:
  Preview(const PreviewOptions& options, std::unique_ptr<SdlWindow> window);
  // Draws what changed, updates the title, and handles what arrives within `milliseconds`.
  void keep_live(int milliseconds);
  std::string title() const;

  PreviewOptions options_;
  std::unique_ptr<SdlWindow> window_;
  PreviewImage image_;
  std::vector<uint8_t> levels_;  // the window thread's copy, handed to SDL
  std::string label_;
  uint64_t pixels_ = 0;               // the shown part's, for the title's percentage
  std::atomic<uint64_t> done_{0};     // pixels of the first pass done in this frame
  std::atomic<bool> refining_{false};  // anti-aliasing's pass has started
  std::atomic<bool> finished_{false};  // the frame's picture is in
  std::atomic<bool> cancelled_{false};
  std::string shown_title_;
};

}  // namespace convray::display
