#pragma once
// POV-Ray's animation options (+KFI +KFF +KI +KF +KC +K +SF +EF, Frame_Step) and the frames
// they ask for, with the values of the scene's animation identifiers in each: clock,
// clock_delta, clock_on, frame_number, initial_frame, final_frame, initial_clock, final_clock.
//
// The values are POV-Ray 3.7's, as its renders print them (tests/app/animation_test.cpp
// checks them against the povray binary), including its cyclic case: with +KC the clock runs
// over final_frame + 1 - initial_frame steps, so the last frame stops one step short of
// final_clock, and the scene's final_frame reads one more than given. Where POV-Ray's answer
// is a defect we differ, and say so (docs/animations.md):
//  - a one-frame animation (+KFF1) has clock = initial_clock and clock_delta 0 (POV-Ray: NaN);
//  - a subset end past the final frame is clamped to it, with a warning (POV-Ray renders
//    frames past the end, extrapolating the clock); a subset that ends before it starts, and
//    a final frame before the initial one, are errors (POV-Ray renders one frame with a NaN).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace convray::app {

struct AnimationOptions {
  std::optional<long long> initial_frame, final_frame;  // +KFIn +KFFn (either: an animation)
  double initial_clock = 0.0, final_clock = 1.0;        // +KIn.n +KFn.n
  bool cyclic = false;                                  // +KC
  // +SFn +EFn: a frame number, or a fraction of the frames when strictly between 0 and 1.
  std::optional<double> subset_start, subset_end;
  long long frame_step = 1;     // Frame_Step: every n-th frame of the subset
  std::optional<double> clock;  // +Kn.n: a still's clock (ignored by animations, as POV-Ray)
};

// What one frame's scene sees.
struct FrameClock {
  long long frame_number = 0;
  double clock = 0.0, clock_delta = 0.0;
  bool clock_on = false;
  long long initial_frame = 0, final_frame = 0;
  double initial_clock = 0.0, final_clock = 0.0;
};

// The frames of a plan, each computed when it is asked for: ten million frames take a few
// numbers here, not the 800 MB a list of them would (issue 17).
class FrameList {
 public:
  class Iterator {
   public:
    Iterator(const FrameList& list, size_t index) : list_(&list), index_(index) {}
    FrameClock operator*() const { return (*list_)[index_]; }
    Iterator& operator++() {
      ++index_;
      return *this;
    }
    bool operator!=(const Iterator& other) const { return index_ != other.index_; }

   private:
    const FrameList* list_;
    size_t index_;
  };

  // One still frame.
  explicit FrameList(const FrameClock& still = {}) : pattern_(still), count_(1), step_(0) {}
  // Frames start, start + step, ... (`count` of them), numbered and clocked as in `pattern`
  // (initial and final frame and clock, clock_delta); `clock_steps` steps of the clock from
  // pattern.initial_frame run from initial_clock to final_clock.
  FrameList(const FrameClock& pattern, long long start, long long step, size_t count,
            long long clock_steps);

  size_t size() const { return count_; }
  FrameClock operator[](size_t i) const;
  Iterator begin() const { return {*this, 0}; }
  Iterator end() const { return {*this, count_}; }

 private:
  FrameClock pattern_;
  long long start_ = 0;
  size_t count_ = 0;
  long long step_ = 0;
  long long clock_steps_ = 0;
};

struct FramePlan {
  bool animated = false;  // false: one still image, no frame number in its file name
  int name_digits = 0;    // frame numbers in file names are zero-padded to this width
  FrameList frames;       // in rendering order (ascending frame numbers)
  std::vector<std::string> warnings;
};

// Throws UsageError (render_options.hpp) for options that describe no frames.
FramePlan plan_frames(const AnimationOptions& options);

// The number of decimal digits of n >= 0.
int decimal_digits(long long n);

}  // namespace convray::app
