#pragma once
// A progress bar for long renders: one line on a terminal, redrawn in place ('\r'), with the
// percentage done, the time elapsed and an estimate of the time left:
//
//   render [##############----------------]  47%  elapsed 0:12  ETA 0:13
//
// Any thread may report work; at most one redraws at a time, and no more often than every
// 100 ms, so reporting costs an atomic add. Disabled (silent), it costs the same and prints
// nothing: pipes and log files get no control characters.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <string>

namespace convray {

class Progress {
 public:
  // Draws on `out` only when `enabled`; `label` starts the line. `total` units make 100%.
  Progress(std::string label, uint64_t total, std::ostream& out, bool enabled);
  // Ends an unfinished line (a render that threw), so the error starts on a fresh line.
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Whether standard error is a terminal: where a progress bar belongs.
  static bool stderr_is_terminal();

  // Reports `units` more done; thread safe.
  void advance(uint64_t units);
  // Draws the full bar and ends the line.
  void finish();

 private:
  void draw(uint64_t done);

  std::string label_;
  uint64_t total_;
  std::ostream& out_;
  bool enabled_;
  bool line_open_ = false;
  std::chrono::steady_clock::time_point start_;
  std::atomic<uint64_t> done_{0};
  std::atomic<int64_t> next_draw_ns_{0};  // since start_
  std::mutex drawing_;
};

// The line drawn (without '\r'): label, a bar of `bar_width` cells, percentage, elapsed time
// and, while unfinished and once something is done, the estimated time left.
std::string format_progress(const std::string& label, uint64_t done, uint64_t total,
                            double elapsed_seconds, int bar_width = 30);

// "m:ss", or "h:mm:ss" from an hour on.
std::string format_duration(double seconds);

}  // namespace convray
