#include "app/animation.hpp"

#include <algorithm>
#include <cmath>

#include "app/usage_error.hpp"

namespace convray::app {
namespace {

// A frame count beyond which an animation is surely a typo: ten million frames are 111 hours
// of film at 25 frames per second.
constexpr long long kMaxFrames = 10'000'000;

FrameClock still_frame(const AnimationOptions& o) {
  FrameClock f;
  // POV-Ray: +K sets clock_on even for a still; the other identifiers stay 0.
  f.clock = o.clock.value_or(0.0);
  f.clock_on = o.clock.has_value();
  return f;
}

// A subset bound (+SF / +EF) as a frame number: fractions strictly between 0 and 1 are a share
// of the `count` frames, rounded down and not offset by the initial frame (POV-Ray's rule).
long long subset_frame(double value, long long count, const char* what) {
  if (!std::isfinite(value)) throw UsageError(std::string(what) + ": not a finite number");
  if (value > 0.0 && value < 1.0) return static_cast<long long>(std::floor(value * double(count)));
  if (value != std::floor(value) || std::abs(value) > 1e15) {
    throw UsageError(std::string(what) +
                     ": expected a whole frame number or a fraction between 0 " + "and 1, got " +
                     std::to_string(value));
  }
  return static_cast<long long>(value);
}

// Clamps a subset bound into [first, last], warning when it moves.
long long clamp_subset(long long frame, long long first, long long last, const char* what,
                       std::vector<std::string>& warnings) {
  const long long clamped = std::clamp(frame, first, last);
  if (clamped != frame) {
    warnings.push_back(std::string(what) + " " + std::to_string(frame) +
                       " lies outside the animation's frames " + std::to_string(first) + ".." +
                       std::to_string(last) + "; using " + std::to_string(clamped));
  }
  return clamped;
}

}  // namespace

FrameList::FrameList(const FrameClock& pattern, long long start, long long step, size_t count,
                     long long clock_steps)
    : pattern_(pattern), start_(start), count_(count), step_(step), clock_steps_(clock_steps) {}

FrameClock FrameList::operator[](size_t i) const {
  FrameClock f = pattern_;
  if (step_ == 0) return f;  // the still
  const long long frame = start_ + (long long)(i)*step_;
  f.frame_number = frame;
  // Interpolated rather than accumulated, so that the last frame lands on final_clock.
  f.clock = clock_steps_ > 0
                ? f.initial_clock + (f.final_clock - f.initial_clock) *
                                        double(frame - f.initial_frame) / double(clock_steps_)
                : f.initial_clock;
  return f;
}

int decimal_digits(long long n) {
  int digits = 1;
  for (; n >= 10; n /= 10) ++digits;
  return digits;
}

FramePlan plan_frames(const AnimationOptions& o) {
  FramePlan plan;
  if (o.frame_step < 1) {
    throw UsageError("Frame_Step: expected a whole number >= 1, got " +
                     std::to_string(o.frame_step));
  }
  if (!std::isfinite(o.initial_clock) || !std::isfinite(o.final_clock)) {
    throw UsageError("the initial and final clock must be finite numbers");
  }
  if (!o.initial_frame && !o.final_frame) {
    plan.frames = FrameList(still_frame(o));
    return plan;
  }
  plan.animated = true;
  long long first = o.initial_frame.value_or(1);
  if (first < 0) {  // POV-Ray's frames start at 0 at the earliest
    plan.warnings.push_back("initial frame " + std::to_string(first) + " is negative; using 0");
    first = 0;
  }
  long long last = o.final_frame.value_or(std::max<long long>(first, 1));
  if (last < first) {
    throw UsageError("the final frame (" + std::to_string(last) + ") comes before the initial " +
                     "frame (" + std::to_string(first) + ")");
  }
  if (last - first >= kMaxFrames) {
    throw UsageError("the animation has " + std::to_string(last - first + 1) + " frames; at most " +
                     std::to_string(kMaxFrames) + " are rendered in one run");
  }
  // Cyclic: the clock steps over one frame more, so that the frame after the last would show
  // the first again; POV-Ray's final_frame identifier reports that extra frame.
  const long long clock_last = o.cyclic ? last + 1 : last;
  const long long steps = clock_last - first;
  const double delta = steps > 0 ? (o.final_clock - o.initial_clock) / double(steps) : 0.0;

  const long long count = clock_last - first + 1;
  long long start = first, end = last;
  if (o.subset_start) {
    start = clamp_subset(subset_frame(*o.subset_start, count, "+SF (subset start frame)"), first,
                         last, "the subset start frame", plan.warnings);
  }
  if (o.subset_end) {
    end = clamp_subset(subset_frame(*o.subset_end, count, "+EF (subset end frame)"), first, last,
                       "the subset end frame", plan.warnings);
  }
  if (end < start) {
    throw UsageError("the subset ends (frame " + std::to_string(end) +
                     ") before it starts (frame " + std::to_string(start) + ")");
  }
  plan.name_digits = decimal_digits(clock_last);
  FrameClock pattern;
  pattern.clock_on = true;
  pattern.initial_frame = first;
  pattern.final_frame = clock_last;
  pattern.initial_clock = o.initial_clock;
  pattern.final_clock = o.final_clock;
  pattern.clock_delta = delta;
  const auto frames = size_t((end - start) / o.frame_step + 1);
  plan.frames = FrameList(pattern, start, o.frame_step, frames, steps);
  return plan;
}

}  // namespace convray::app
