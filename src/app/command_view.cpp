#include "app/command_view.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "app/file_watch.hpp"
#include "app/view_edits.hpp"
#include "app/view_worker.hpp"
#include "core/image_file.hpp"
#include "display/preview_image.hpp"
#include "display/view_window.hpp"
#include "util/error.hpp"

namespace convray::app {

const char* const kViewKeys =
    "left drag: orbit around look_at\n"
    "right or middle drag: pan; wheel: zoom\n"
    "Home or 0: back to the scene's camera\n"
    "c: print the view as a camera { } block\n"
    "s: write the full picture (-o FILE)\n"
    "r / R: radius of the convolution under the cursor\n"
    "o / O: its offset (both: down / up)\n"
    "[ / ]: clock down / up (--clock-step)\n"
    "h or ?: these keys; q or Escape: quit";

namespace {

using Clock = std::chrono::steady_clock;
using Event = display::ViewEvent;

// How often the files are looked at: a few stat calls, cheap enough 20 times a second, so
// that a save starts its render within 50 ms (the coarse picture follows in well under 0.2 s).
constexpr int kWatchMilliseconds = 50;
constexpr int kEventMilliseconds = 15;
constexpr std::chrono::seconds kMessageTime{4};
constexpr std::chrono::milliseconds kCameraPatience{200};

std::string default_output(const std::string& input) {
  return std::filesystem::path(input).stem().string() + "-view.png";
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

class ViewCommand {
 public:
  ViewCommand(const ViewCommandOptions& o, display::ViewWindow& window, std::ostream& out,
              std::ostream& err)
      : o_(o), window_(window), out_(out), err_(err), session_(o.view),
        image_({0, 0, o.view.width, o.view.height}, window.size()),
        worker_(session_, image_) {
    overrides_.clock = o.clock;
  }

  void run() {
    ask(true);
    Clock::time_point watched = Clock::now();
    while (!quit_) {
      for (const Event& e : window_.events(kEventMilliseconds)) handle(e);
      send_camera();
      if (Clock::now() - watched > std::chrono::milliseconds(kWatchMilliseconds)) {
        watched = Clock::now();
        watch_files();
      }
      refresh();
    }
  }

 private:
  void handle(const Event& e) {
    switch (e.kind) {
      case Event::Kind::quit: quit_ = true; return;
      case Event::Kind::exposed: redraw_ = true; return;
      case Event::Kind::wheel: return move(zoom(current_camera(), std::pow(0.9, e.wheel)));
      case Event::Kind::drag: return drag(e);
      case Event::Kind::key: return key(e);
    }
  }

  void drag(const Event& e) {
    const double w = window_.size().width, h = window_.size().height;
    if (e.button == 1) {
      move(orbit(current_camera(), -kPi * e.dx / w, kPi * 0.5 * e.dy / h));
    } else {
      move(pan(current_camera(), -e.dx / w, e.dy / h));
    }
  }

  void key(const Event& e) {
    if (e.name == "Escape") return void(quit_ = true);
    if (e.name == "Home") return reset_camera();
    switch (e.key) {
      case 'q': quit_ = true; return;
      case 'c': return print_camera();
      case 's': return save_picture();
      case '0': return reset_camera();
      case 'h': case '?': help_ = !help_, redraw_ = true; return;
      case '[': return set_clock(overrides_.clock - o_.clock_step);
      case ']': return set_clock(overrides_.clock + o_.clock_step);
      case 'r': case 'R': case 'o': case 'O': return edit(e);
      default: return;
    }
  }

  // The camera as it is now: the override, or the scene's own as the last frame has it.
  ViewCamera current_camera() const {
    if (overrides_.camera) return *overrides_.camera;
    const ViewWorker::State s = worker_.state();
    return s.frame ? s.frame->camera : ViewCamera{};
  }

  // A drag sends dozens of moves a second: each waits until the last one's coarse picture is
  // shown (or 0.2 s passed), so that the view follows the mouse in coarse pictures instead of
  // starting over at every move and showing none.
  void move(const ViewCamera& camera) {
    if (!overrides_.camera && !worker_.state().frame) return;  // nothing to move yet
    overrides_.camera = camera;
    camera_waits_ = true;
  }

  void send_camera() {
    if (!camera_waits_) return;
    const ViewWorker::State s = worker_.state();
    const bool shown = s.request == asked_ && s.stage != ViewWorker::Stage::loading &&
                       s.stage != ViewWorker::Stage::coarse;
    if (!shown && Clock::now() - asked_at_ < kCameraPatience) return;
    ask(false);
  }

  void ask(bool reparse) {
    asked_ = worker_.request(overrides_, reparse);
    asked_at_ = Clock::now();
    camera_waits_ = false;  // what it waited for goes with this request
  }

  void reset_camera() {
    overrides_.camera.reset();
    ask(true);
  }

  void set_clock(double clock) {
    overrides_.clock = clock;
    ask(true);
    say("clock " + exact_number(clock));
  }

  void print_camera() {
    out_ << "// convray view: the current view of " << o_.view.input << "\n"
         << camera_block(current_camera()) << std::flush;
    say("camera block printed on standard output");
  }

  void save_picture() {
    const ViewWorker::State s = state();
    if (s.stage != ViewWorker::Stage::done || !s.picture) {
      say("the full picture is not finished yet: s again when it is");
      return;
    }
    const std::string file = o_.output.empty() ? default_output(o_.view.input) : o_.output;
    try {
      write_image_atomically(file, {o_.view.width, o_.view.height, *s.picture,
                                    PixelEncoding::linear});
      out_ << "convray view: wrote " << file << "\n" << std::flush;
      say("wrote " + file);
    } catch (const InputError& e) {
      err_ << e.what() << "\n";
      say(e.what());
    }
  }

  void edit(const Event& e) {
    const ViewWorker::State s = worker_.state();
    if (!s.frame) return;
    const int x = e.x * o_.view.width / window_.size().width;
    const int y = e.y * o_.view.height / window_.size().height;
    const auto header = convolution_at(*s.frame, o_.view.width, o_.view.height, x, y);
    if (!header) {
      say("no convolution object under the cursor");
      return;
    }
    const sdl::ConvolutionHeader edited = edited_header(*header, e.key);
    set_edit(overrides_.edits, edited);
    ask(false);
    out_ << convolution_header_text(edited) << std::flush;
    say("radius " + exact_number(edited.radius) + "  offset " + exact_number(*edited.offset) +
            "  (" + header->loc.str() + ")",
        true);
  }

  // A line over the picture for a few seconds: long enough to read, gone before it hides
  // what the next look at the picture wants to see; an edit's values stay until the next line.
  void say(const std::string& message, bool stays = false) {
    message_ = message;
    said_ = Clock::now();
    message_stays_ = stays;
  }

  void watch_files() {
    const ViewWorker::State s = worker_.state();
    if (s.files.empty()) return;
    watch_.watch(s.files);
    if (watch_.changed()) ask(true);
  }

  // The worker's state, as loading until it has taken up the last request: a title that
  // said `done` then would speak of the picture before the change.
  ViewWorker::State state() const {
    ViewWorker::State s = worker_.state();
    if (s.request != asked_ || camera_waits_) s.stage = ViewWorker::Stage::loading;
    return s;
  }

  // Reports each new error once on the terminal, and redraws what changed.
  void refresh() {
    const ViewWorker::State s = state();
    if (s.error_text != reported_) {
      if (!s.error_text.empty()) err_ << s.error_text << "\n" << std::flush;
      else if (!reported_.empty()) err_ << "convray view: " << o_.view.input << ": reloaded\n";
      reported_ = s.error_text;
    }
    const display::Overlay overlay = overlay_of(s);
    const bool changed = image_.take_if_changed(levels_);
    if (changed || redraw_ || !(overlay == shown_)) {
      if (!levels_.empty()) window_.show(levels_, overlay);
      shown_ = overlay;
      redraw_ = false;
    }
    const std::string title = title_of(s);
    if (title != title_) window_.set_title(title), title_ = title;
  }

  display::Overlay overlay_of(const ViewWorker::State& s) const {
    display::Overlay overlay;
    if (!message_.empty() && (message_stays_ || Clock::now() - said_ < kMessageTime)) {
      overlay.lines.push_back(message_);
    }
    if (overrides_.clock != 0.0 || o_.clock != 0.0) {
      overlay.lines.push_back("clock " + exact_number(overrides_.clock));
    }
    if (help_) {
      for (const std::string& line : split_lines(kViewKeys)) overlay.lines.push_back(line);
    }
    if (s.error) overlay.error = *s.error + "  (the last good picture is shown)";
    return overlay;
  }

  std::string title_of(const ViewWorker::State& s) const {
    std::string t = "convray view: " + std::filesystem::path(o_.view.input).filename().string();
    switch (s.stage) {
      case ViewWorker::Stage::loading: return t + ", loading";
      case ViewWorker::Stage::coarse: return t + ", coarse";
      case ViewWorker::Stage::full:  // the first pass's percentage, then --antialias's pass
        if (s.percent >= 100) return t + ", anti-aliasing";
        return t + ", " + std::to_string(int(s.percent)) + "%";
      case ViewWorker::Stage::done: return t + ", done";
      case ViewWorker::Stage::failed: return t + ", error";
    }
    return t;
  }

  const ViewCommandOptions& o_;
  display::ViewWindow& window_;
  std::ostream& out_;
  std::ostream& err_;
  ViewSession session_;
  display::PreviewImage image_;
  ViewWorker worker_;
  ViewOverrides overrides_;
  FileWatch watch_;
  std::vector<uint8_t> levels_;
  display::Overlay shown_;
  std::string title_, reported_, message_;
  Clock::time_point said_, asked_at_;
  uint64_t asked_ = 0;
  bool camera_waits_ = false;
  bool quit_ = false, help_ = false, redraw_ = false, message_stays_ = false;
};

}  // namespace

int run_view(const ViewCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(options.view.input, error)) {
    err << "convray view: " << options.view.input << ": no such file\n";
    return 2;
  }
  const display::PreviewSize size = display::fit_preview(options.view.width, options.view.height);
  std::unique_ptr<display::ViewWindow> window;
  try {
    window = std::make_unique<display::ViewWindow>("convray view: " + options.view.input, size);
  } catch (const display::NoDisplay& e) {
    err << "convray view: no display available (" << e.what()
        << "); view needs a window: render to a file with 'convray " << options.view.input
        << "' instead\n";
    return 1;
  } catch (const display::NoFont& e) {
    err << "convray view: " << e.what() << "\n";
    return 1;
  }
  if (window->unseen()) {
    err << "convray view: SDL's video driver '" << window->driver()
        << "' shows no window (SDL_VIDEODRIVER); view needs one\n";
    return 1;
  }
  ViewCommand command(options, *window, out, err);
  command.run();
  return 0;
}

}  // namespace convray::app
