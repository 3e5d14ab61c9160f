#pragma once
// Collects error/tolerance ratios of one kind of check over many random cases: every ratio
// above 1 fails, the first few are reported with their inputs, and the worst is remembered
// (printed in the summary even when everything passes).
#include <gtest/gtest.h>

#include <string>

#include "reference/checks.hpp"

namespace convray::reference {

class RatioCheck {
 public:
  explicit RatioCheck(std::string what) : what_(std::move(what)) {}

  void add(double ratio, const std::string& inputs) {
    ++checked_;
    worst_.update(ratio, inputs);
    if (!(ratio <= 1.0) && ++failures_ <= kFailuresShown)
      ADD_FAILURE() << what_ << ": error / tolerance = " << ratio << " for " << inputs;
  }

  // Call once all cases were added.
  void expect_no_failure() const {
    EXPECT_EQ(failures_, 0) << what_ << ": " << failures_ << " of " << checked_
                            << " cases fail; worst error / tolerance " << worst_.ratio << " for "
                            << worst_.inputs;
  }

  const std::string& what() const { return what_; }
  int checked() const { return checked_; }
  int failures() const { return failures_; }
  const WorstCase& worst() const { return worst_; }

 private:
  static constexpr int kFailuresShown = 10;
  std::string what_;
  int checked_ = 0;
  int failures_ = 0;
  WorstCase worst_;
};

}  // namespace convray::reference
