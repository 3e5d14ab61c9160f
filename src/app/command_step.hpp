#pragma once
// What a command is doing, so that running out of memory anywhere in it is reported as one
// message naming the step and what to change (issue 17):
//   convray: out of memory while WHAT: ADVICE
// with exit code 1. Nothing is left half-written: every output goes through AtomicFile, whose
// temporary is removed as the exception unwinds.
#include <new>
#include <ostream>
#include <stdexcept>
#include <string>

namespace convray::app {

class CommandStep {
 public:
  CommandStep(std::string what, std::string advice)
      : what_(std::move(what)), advice_(std::move(advice)) {}

  // The step now under way. If memory is so short that these strings cannot be made, the
  // exception that follows still names the step before.
  void now(std::string what, std::string advice) {
    what_ = std::move(what);
    advice_ = std::move(advice);
  }

  // The message and the exit code, for a command's catch of std::bad_alloc (and of
  // std::length_error: a container asked for more than it can ever hold).
  int out_of_memory(std::ostream& err) const {
    err << "convray: out of memory while " << what_ << ": " << advice_ << "\n";
    return 1;
  }

 private:
  std::string what_, advice_;
};

// The advice for a step whose size the user does not choose by an option.
inline constexpr const char* kFreeMemory =
    "free memory or raise the memory limit (ulimit -v), or give a smaller input";

}  // namespace convray::app
