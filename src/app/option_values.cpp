#include "app/option_values.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "app/usage_error.hpp"

namespace convray::app {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return text;
}

double number(const std::string& text, const std::string& what) {
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin < end && *begin == '+') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value)) {
    throw UsageError(what + ": expected a number, got '" + text + "'");
  }
  return value;
}

long long whole(const std::string& text, const std::string& what, long long lo, long long hi) {
  const double v = number(text, what);
  if (v != std::floor(v) || v < double(lo) || v > double(hi)) {
    throw UsageError(what + ": expected a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + text + "'");
  }
  return static_cast<long long>(v);
}

bool boolean(const std::string& text, const std::string& what) {
  const std::string word = lower(text);
  if (word.empty() || word == "on" || word == "true" || word == "yes" || word == "1") return true;
  if (word == "off" || word == "false" || word == "no" || word == "0") return false;
  throw UsageError(what + ": expected on or off (true/false, yes/no, 1/0), got '" + text + "'");
}

}  // namespace convray::app
