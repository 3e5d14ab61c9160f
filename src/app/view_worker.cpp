#include "app/view_worker.hpp"

#include <chrono>
#include <functional>

#include "render/pixel_window.hpp"
#include "util/error.hpp"

namespace convray::app {

namespace {

using Clock = std::chrono::steady_clock;

// An InputError's first line ("file:line:col: message"); the source line and caret follow it
// on the terminal only.
std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

bool same_scene(const ViewOverrides& a, const ViewOverrides& b) {
  if (a.clock != b.clock || a.edits.size() != b.edits.size()) return false;
  for (size_t i = 0; i < a.edits.size(); ++i) {
    const sdl::ConvolutionEdit &x = a.edits[i], &y = b.edits[i];
    if (!sdl::same_place(x.loc, y.loc) || x.radius != y.radius || x.offset != y.offset) {
      return false;
    }
  }
  return true;
}

}  // namespace

// Puts each tile in the picture, and stops the render once a newer request is waiting.
class ViewWorker::Observer final : public render::RenderObserver {
 public:
  Observer(ViewWorker& worker, uint64_t number, int width, int height, bool full)
      : worker_(worker), number_(number), pixels_(uint64_t(width) * uint64_t(height)),
        full_(full) {}
  void tile_done(const render::FinishedTile& tile) override {
    if (worker_.latest_ != number_) throw render::RenderCancelled("a newer view was asked for");
    worker_.image_.put(tile.area, tile.rgb);
    if (!full_ || tile.refinement) return;
    const double percent = 100.0 * double(done_ += tile.area.pixels()) / double(pixels_);
    worker_.publish([&](State& s) { s.percent = percent; });
  }

 private:
  ViewWorker& worker_;
  uint64_t number_, pixels_;
  bool full_;
  std::atomic<uint64_t> done_{0};
};

ViewWorker::ViewWorker(ViewSession& session, display::PreviewImage& image)
    : session_(session), image_(image), thread_([this] { run(); }) {}

ViewWorker::~ViewWorker() {
  {
    std::lock_guard<std::mutex> hold(lock_);
    stop_ = true;
    ++latest_;  // the render under way stops at its next tile
  }
  wake_.notify_all();
  thread_.join();
}

uint64_t ViewWorker::request(const ViewOverrides& overrides, bool reparse) {
  std::lock_guard<std::mutex> hold(lock_);
  pending_ = overrides;
  pending_reparse_ = pending_reparse_ || reparse;  // a reparse asked for is never dropped
  const uint64_t number = ++latest_;
  wake_.notify_all();
  return number;
}

ViewWorker::State ViewWorker::state() const {
  std::lock_guard<std::mutex> hold(lock_);
  return state_;
}

void ViewWorker::publish(const std::function<void(State&)>& change) {
  std::lock_guard<std::mutex> hold(lock_);
  change(state_);
}

void ViewWorker::run() {
  for (;;) {
    ViewOverrides overrides;
    bool reparse = false;
    uint64_t number = 0;
    {
      std::unique_lock<std::mutex> hold(lock_);
      wake_.wait(hold, [&] { return stop_ || pending_; });
      if (stop_) return;
      overrides = std::move(*pending_);
      pending_.reset();
      reparse = pending_reparse_;
      pending_reparse_ = false;
      number = latest_;
    }
    serve(number, overrides, reparse);
  }
}

std::shared_ptr<const ViewFrame> ViewWorker::frame_for(const ViewOverrides& overrides,
                                                       bool reparse, bool& parsed) {
  parsed = false;
  if (!reparse && loaded_ && loaded_with_ && same_scene(*loaded_with_, overrides)) {
    if (!overrides.camera) return loaded_;
    return ViewSession::with_camera(*loaded_, *overrides.camera);
  }
  parsed = true;
  return session_.load(overrides);
}

void ViewWorker::serve(uint64_t number, const ViewOverrides& overrides, bool reparse) {
  const Clock::time_point start = Clock::now();
  publish([&](State& s) { s.request = number, s.stage = Stage::loading, s.percent = 0; });
  // Stage::coarse: the coarse picture is being drawn (after the load).
  try {
    bool parsed = false;
    std::shared_ptr<const ViewFrame> frame = frame_for(overrides, reparse, parsed);
    if (parsed) loaded_with_ = overrides;
    loaded_ = frame;
    publish([&](State& s) {
      if (parsed) s.error.reset(), s.error_text.clear();  // else the scene's error still holds
      s.frame = frame;
      s.files = session_.watched_files();
    });
    publish([&](State& s) { s.stage = Stage::coarse; });
    const int w = session_.options().width, h = session_.options().height;
    Observer coarse(*this, number, w, h, false);
    session_.render(*frame, kCoarseBlock, &coarse);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    publish([&](State& s) { s.stage = Stage::full, s.coarse_seconds = seconds; });
    Observer full(*this, number, w, h, true);
    const render::RenderResult result = session_.render(*frame, 1, &full);
    // The finished film replaces the tiles (anti-aliasing's pass included).
    image_.put({0, 0, w, h}, result.film.rgb());
    auto picture = std::make_shared<const std::vector<float>>(result.film.rgb().begin(),
                                                              result.film.rgb().end());
    publish([&](State& s) { s.stage = Stage::done, s.picture = picture, s.percent = 100; });
  } catch (const render::RenderCancelled&) {
    // A newer request is waiting: it starts at once.
  } catch (const InputError& e) {
    publish([&](State& s) {
      s.stage = Stage::failed;
      s.error = first_line(e.what());
      s.error_text = e.what();
      s.files = session_.watched_files();
    });
  } catch (const std::exception& e) {
    publish([&](State& s) {
      s.stage = Stage::failed;
      s.error = std::string("convray view: ") + e.what();
      s.error_text = *s.error;
      s.files = session_.watched_files();
    });
  }
}

}  // namespace convray::app
