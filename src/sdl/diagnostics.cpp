#include "sdl/diagnostics.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <vector>

namespace convray::sdl {

std::string with_source_line(const std::string& message, std::string_view text, int line,
                             int column) {
  if (line <= 0) return message;
  // Find the line: count newlines (errors are rare; no line index needed).
  size_t start = 0;
  for (int l = 1; l < line; ++l) {
    const size_t newline = text.find('\n', start);
    if (newline == std::string_view::npos) return message;
    start = newline + 1;
  }
  size_t stop = text.find('\n', start);
  if (stop == std::string_view::npos) stop = text.size();
  std::string_view source_line = text.substr(start, stop - start);
  if (!source_line.empty() && source_line.back() == '\r') source_line.remove_suffix(1);
  // Very long lines (generated scenes) are cut around the column.
  constexpr size_t kMaxShown = 160;
  size_t first = 0;
  if (source_line.size() > kMaxShown && column > 0 && size_t(column) > kMaxShown / 2) {
    first = size_t(column) - kMaxShown / 2;
  }
  std::string_view shown = source_line.substr(first, kMaxShown);

  std::string out = message;
  out += "\n    ";
  out += shown;
  if (column > 0) {
    out += "\n    ";
    const size_t caret = std::min(size_t(column) - 1 - first, shown.size());
    for (size_t i = 0; i < caret; ++i) out += shown[i] == '\t' ? '\t' : ' ';
    out += '^';
  }
  return out;
}

std::string number_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

int edit_distance(std::string_view a, std::string_view b) {
  const auto same = [](char p, char q) {
    return std::tolower(static_cast<unsigned char>(p)) ==
           std::tolower(static_cast<unsigned char>(q));
  };
  // Optimal string alignment distance, three rolling rows.
  const size_t n = b.size();
  std::vector<int> before(n + 1), previous(n + 1), current(n + 1);
  for (size_t j = 0; j <= n; ++j) previous[j] = int(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = int(i);
    for (size_t j = 1; j <= n; ++j) {
      const int cost = same(a[i - 1], b[j - 1]) ? 0 : 1;
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1])) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[n];
}

}  // namespace convray::sdl
