#pragma once
// Errors that point at their cause: a file, and where it applies a line and column in it.
#include <stdexcept>
#include <string>

#include "util/printable.hpp"

namespace convray {

struct SourceLoc {
  std::string file;
  int line = 0;    // 1-based; 0 when the error concerns the whole file
  int column = 0;  // 1-based; 0 when unknown

  // "file", "file:line" or "file:line:col", as compilers print them.
  std::string str() const {
    std::string s = file;
    if (line > 0) s.append(":").append(std::to_string(line));
    if (line > 0 && column > 0) s.append(":").append(std::to_string(column));
    return s;
  }
};

// An error caused by the user's input (scene, mesh, command line): reported, never a crash.
// Its text is made printable (util/printable.hpp): what it quotes from the input reaches the
// terminal with control characters escaped and long tokens cut.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLoc loc, const std::string& message)
      : std::runtime_error(printable(loc.str() + ": " + message)),
        loc_(std::move(loc)),
        message_(printable(message)) {}

  const SourceLoc& loc() const { return loc_; }
  const std::string& message() const { return message_; }

 private:
  SourceLoc loc_;
  std::string message_;
};

// A feature of the input that convray knows and cannot render yet ("'crackle' is not supported
// yet by convray"). `feature()` is the message without the source line under it: the scene
// parser lets a declaration that needs such a feature stand, and quotes it where the
// declaration is used.
class UnsupportedError : public InputError {
 public:
  UnsupportedError(SourceLoc loc, const std::string& message, std::string feature)
      : InputError(std::move(loc), message), feature_(printable(feature)) {}

  const std::string& feature() const { return feature_; }

 private:
  std::string feature_;
};

}  // namespace convray
