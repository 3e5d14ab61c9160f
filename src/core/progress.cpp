#include "core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace convray {

namespace {

constexpr int64_t kRedrawIntervalNs = 100'000'000;  // 10 redraws a second at most

}  // namespace

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

std::string format_progress(const std::string& label, uint64_t done, uint64_t total,
                            double elapsed_seconds, int bar_width) {
  const double fraction = total == 0 ? 1.0 : std::min(1.0, double(done) / double(total));
  const int filled = int(fraction * bar_width);
  std::string line = label + " [" + std::string(size_t(filled), '#') +
                     std::string(size_t(bar_width - filled), '-') + "]";
  char percent[16];
  std::snprintf(percent, sizeof percent, " %3d%%", int(fraction * 100.0));
  line.append(percent).append("  elapsed ").append(format_duration(elapsed_seconds));
  if (fraction < 1.0) {
    // Assumes the rest goes at the average rate so far.
    line.append("  ETA ").append(
        done == 0 ? std::string("--:--")
                  : format_duration(elapsed_seconds * (1.0 - fraction) / fraction));
  }
  return line;
}

Progress::Progress(std::string label, uint64_t total, std::ostream& out, bool enabled)
    : label_(std::move(label)),
      total_(total),
      out_(out),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()) {
  if (enabled_) draw(0);
}

Progress::~Progress() {
  if (enabled_ && line_open_) out_ << "\n" << std::flush;
}

bool Progress::stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

void Progress::advance(uint64_t units) {
  const uint64_t done = done_.fetch_add(units, std::memory_order_relaxed) + units;
  if (!enabled_) return;
  const int64_t now_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                             std::chrono::steady_clock::now() - start_)
                             .count();
  int64_t due = next_draw_ns_.load(std::memory_order_relaxed);
  if (now_ns < due) return;
  // One thread wins the right to draw this time; the others go back to work.
  if (!next_draw_ns_.compare_exchange_strong(due, now_ns + kRedrawIntervalNs)) return;
  std::unique_lock lock(drawing_, std::try_to_lock);
  if (lock.owns_lock()) draw(done);
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard lock(drawing_);
  draw(total_);
  out_ << "\n" << std::flush;
  line_open_ = false;
}

void Progress::draw(uint64_t done) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // '\r' returns to the line's start; ESC[K clears what a longer earlier line left.
  out_ << '\r' << format_progress(label_, done, total_, elapsed) << "\x1b[K" << std::flush;
  line_open_ = true;
}

}  // namespace convray
