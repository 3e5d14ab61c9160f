#pragma once
#include <stdexcept>

namespace convray::app {

// A command line the program cannot accept; the message names the argument.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace convray::app
