#pragma once
// The values of options, switches and INI settings, checked: each throws UsageError naming
// `what` (the option as the user wrote it) and the text it could not accept.
#include <string>

namespace convray::app {

std::string lower(std::string text);

// The whole text as a finite decimal number (a leading + allowed).
double number(const std::string& text, const std::string& what);
// A whole number in [lo, hi].
long long whole(const std::string& text, const std::string& what, long long lo, long long hi);
// POV-Ray's booleans: on/off, true/false, yes/no, 1/0 (any case); empty means on.
bool boolean(const std::string& text, const std::string& what);

}  // namespace convray::app
