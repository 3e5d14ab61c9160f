#pragma once
// Text that came from the user's files (scene sources, #debug strings, tokens of a mesh or of
// `field`'s input) made safe to print on a terminal: control characters and escape sequences
// are shown escaped (`\x1b`, `\r`), never sent raw, and very long runs without spaces (a
// 10 MB token) are cut, with the number of bytes left out.
#include <cstddef>
#include <string>
#include <string_view>

namespace convray {

// The longest run of non-space characters printed whole by default; longer ones keep their
// first and last characters around "...(N bytes)...".
inline constexpr size_t kMaxPrintedRun = 200;

// `text` with every control character but newline and tab escaped (C-style: \r, \x1b, \x7f),
// and every run of more than `max_run` non-space bytes cut. Bytes of 0x80 and above pass
// through (UTF-8 text stays readable).
std::string printable(std::string_view text, size_t max_run = kMaxPrintedRun);

}  // namespace convray
