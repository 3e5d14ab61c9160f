#pragma once
// `convray view`'s render thread: takes the latest request (overrides), loads the scene (or
// only moves the camera, when nothing else changed), renders the coarse picture and then the
// full one into a display::PreviewImage, tile by tile. A new request stops the render at its
// next tile (RenderCancelled) and starts over; a scene that fails to load leaves the last
// good picture where it is and says why. The window's thread only posts and reads.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/view_session.hpp"
#include "display/preview_image.hpp"

namespace convray::app {

class ViewWorker {
 public:
  // loading: parsing and building; coarse: the coarse pass; full: the full-resolution pass.
  enum class Stage { loading, coarse, full, done, failed };

  // What the window shows besides the picture.
  struct State {
    uint64_t request = 0;  // the request this state answers
    Stage stage = Stage::loading;
    double percent = 0;                   // of the full pass
    std::optional<std::string> error;     // the last load's, first line: file:line:col: ...
    std::string error_text;               // all of it: the source line and a caret follow
    std::shared_ptr<const ViewFrame> frame;  // the last good one
    std::shared_ptr<const std::vector<float>> picture;  // its full film, once done
    std::vector<std::string> files;       // to watch
    double coarse_seconds = 0;            // from the request to the coarse picture
  };

  ViewWorker(ViewSession& session, display::PreviewImage& image);
  ~ViewWorker();  // stops the render and joins the thread
  ViewWorker(const ViewWorker&) = delete;
  ViewWorker& operator=(const ViewWorker&) = delete;

  // Asks for a render with `overrides`; `reparse`: the files changed (else a change of camera
  // alone reuses the last frame). Returns the request's number.
  uint64_t request(const ViewOverrides& overrides, bool reparse);
  State state() const;

 private:
  class Observer;
  void run();
  void serve(uint64_t number, const ViewOverrides& overrides, bool reparse);
  // The frame to render: the last one seen through a new camera, or a new load (`parsed`).
  std::shared_ptr<const ViewFrame> frame_for(const ViewOverrides& overrides, bool reparse,
                                             bool& parsed);
  void publish(const std::function<void(State&)>& change);

  ViewSession& session_;
  display::PreviewImage& image_;
  mutable std::mutex lock_;
  std::condition_variable wake_;
  std::optional<ViewOverrides> pending_;
  bool pending_reparse_ = false;
  std::atomic<uint64_t> latest_{0};
  bool stop_ = false;
  State state_;
  // The worker's own: the last good frame and what it was loaded with.
  std::shared_ptr<const ViewFrame> loaded_;
  std::optional<ViewOverrides> loaded_with_;
  std::thread thread_;
};

}  // namespace convray::app
