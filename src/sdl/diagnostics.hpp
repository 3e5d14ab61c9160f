#pragma once
// Error messages that show where: the message, then the source line and a caret under the
// column, as compilers print them.
#include <string>
#include <string_view>

#include "util/error.hpp"

namespace convray::sdl {

// 'text' in single quotes. (Also sidesteps GCC 12's false -Wrestrict on "'" + string.)
inline std::string quoted(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '\'';
  out += text;
  out += '\'';
  return out;
}

// The shortest text that reads back as `value`: 5, 0.1, 1e+300.
std::string number_text(double value);

// `message`, a newline, the 1-based `line` of `text` indented by four spaces, and a caret
// under `column` (tabs kept, so the caret lines up). Only `message` when the line is not in
// the text.
std::string with_source_line(const std::string& message, std::string_view text, int line,
                             int column);

// The number of single-character edits (insert, delete, substitute, swap two neighbours) from
// a to b, ignoring case: `foo` is 0 from `Foo`. For "did you mean" suggestions.
int edit_distance(std::string_view a, std::string_view b);

}  // namespace convray::sdl
