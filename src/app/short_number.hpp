#pragma once
// Numbers in the commands' reports: a few significant digits, enough to compare sizes, short
// enough to read ("%.6g" by default, as `convray info` prints).
#include <cstdio>
#include <string>

namespace convray::app {

inline std::string short_number(double value, int digits = 6) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace convray::app
