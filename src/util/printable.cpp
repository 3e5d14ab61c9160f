#include "util/printable.hpp"

#include <algorithm>
#include <cstdio>

namespace convray {

namespace {

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t'; }

// One byte as the terminal should see it.
void append_escaped(std::string& out, char c) {
  const unsigned char u = static_cast<unsigned char>(c);
  if (c == '\n' || c == '\t' || (u >= 0x20 && u != 0x7f)) {
    out += c;
    return;
  }
  switch (c) {
    case '\r': out += "\\r"; return;
    case '\0': out += "\\0"; return;
    default: {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(u));
      out += hex;
    }
  }
}

void append_run(std::string& out, std::string_view run, size_t max_run) {
  if (run.size() <= max_run) {
    for (char c : run) append_escaped(out, c);
    return;
  }
  // Keep both ends: the start says what the token was, the end where it stopped. The marker
  // (at most 30 bytes) fits within max_run, so printing printed text again changes nothing.
  const size_t kept = max_run > 40 ? max_run - 30 : 10;
  const size_t head = kept * 3 / 4, tail = kept - head;
  for (char c : run.substr(0, head)) append_escaped(out, c);
  out += "...(" + std::to_string(run.size() - head - tail) + " bytes)...";
  for (char c : run.substr(run.size() - tail)) append_escaped(out, c);
}

}  // namespace

std::string printable(std::string_view text, size_t max_run) {
  std::string out;
  out.reserve(std::min(text.size(), size_t{1} << 16));
  size_t i = 0;
  while (i < text.size()) {
    if (is_space(text[i])) {
      out += text[i++];
      continue;
    }
    size_t end = i;
    while (end < text.size() && !is_space(text[end])) ++end;
    append_run(out, text.substr(i, end - i), max_run);
    i = end;
  }
  return out;
}

}  // namespace convray
