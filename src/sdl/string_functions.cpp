// Built-in functions on strings (and the few that take arrays or file names).
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

// POV-Ray's str(F, L, P): at least |L| characters (padded with zeros when L < 0, spaces
// otherwise), P digits after the point; P < 0 prints the shortest form that reads back as F
// up to six significant digits ("%g").
std::string format_float(double value, int length, int precision) {
  length = std::clamp(length, -64, 64);
  precision = std::min(precision, 32);
  std::string format = "%";
  if (length < 0) format += "0";
  format += std::to_string(std::abs(length));
  if (precision >= 0) {
    format += '.';
    format += std::to_string(precision);
    format += 'f';
  } else {
    format += 'g';
  }
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format.c_str(), value);
  return buffer;
}

}  // namespace

Value Parser::Impl::call_string_function(Word word, std::vector<Value>& args, TokenRef at) {
  const std::string function(at.token->view());
  const std::string what = "in " + function + "()";
  const auto text = [&](std::size_t i) -> const std::string& {
    return to_string(args[i], at, what);
  };
  const auto number = [&](std::size_t i) { return to_float(args[i], at, what); };
  const auto integer = [&](std::size_t i) { return to_int(number(i), at, what); };
  const auto checked = [&](std::string s) {
    if (s.size() > kMaxStringLength) fail(at, function + "(): the string would be too long");
    charge(s.size() / kBytesPerToken);
    return make_value(std::move(s));
  };
  switch (word) {
    case Word::strlen:
      return make_value(double(text(0).size()));
    case Word::val: {
      // Like atof: the number at the start of the string, 0 when there is none.
      return make_value(std::strtod(text(0).c_str(), nullptr));
    }
    case Word::asc: {
      const std::string& s = text(0);
      return make_value(s.empty() ? 0.0 : double(static_cast<unsigned char>(s[0])));
    }
    case Word::strcmp: {
      const int order = text(0).compare(text(1));
      return make_value(order < 0 ? -1.0 : (order > 0 ? 1.0 : 0.0));
    }
    case Word::file_exists:
      return make_value(resolve(text(0), loc(at), false).empty() ? 0.0 : 1.0);
    case Word::dimensions:
    case Word::dimension_size: {
      const auto* array = args[0].get<std::shared_ptr<Array>>();
      if (array == nullptr) fail(at, function + "() needs an array, found " + type_name(args[0]));
      const std::vector<int>& dimensions = (*array)->dimensions;
      if (word == Word::dimensions) return make_value(double(dimensions.size()));
      const int which = integer(1);
      if (which < 1 || which > int(dimensions.size())) {
        fail(at, "dimension_size(): the array has " + std::to_string(dimensions.size()) +
                     " dimension(s), asked for dimension " + std::to_string(which));
      }
      return make_value(double(dimensions[size_t(which - 1)]));
    }
    case Word::concat: {
      std::string joined;
      for (std::size_t i = 0; i < args.size(); ++i) {
        joined += text(i);
        if (joined.size() > kMaxStringLength) fail(at, "concat(): the string is too long");
      }
      return checked(std::move(joined));
    }
    case Word::str:
      return checked(format_float(number(0), integer(1), integer(2)));
    case Word::vstr: {
      // vstr(N, V, Separator, L, P): the first N components of V, each as str(.., L, P).
      const int count = integer(0);
      const Vector v = to_vector(args[1], at, what);
      if (count < 1 || count > 5) fail(at, "vstr(): the count must be 1 to 5");
      std::string joined;
      for (int i = 0; i < count; ++i) {
        if (i > 0) joined += text(2);
        joined += format_float(v.v[size_t(i)], integer(3), integer(4));
      }
      return checked(std::move(joined));
    }
    case Word::chr: {
      const int code = integer(0);
      if (code < 1 || code > 255) fail(at, "chr(): the code must be 1 to 255");
      return make_value(std::string(1, char(code)));
    }
    case Word::substr: {
      // substr(S, P, L): L characters from position P, counted from 1.
      const std::string& s = text(0);
      const int start = integer(1), length = integer(2);
      if (start < 1 || length < 0 || std::size_t(start - 1) + std::size_t(length) > s.size()) {
        fail(at, "substr(): characters " + std::to_string(start) + " to " +
                     std::to_string(start + length - 1) + " are outside the string (length " +
                     std::to_string(s.size()) + ")");
      }
      return checked(s.substr(size_t(start - 1), size_t(length)));
    }
    case Word::strupr:
    case Word::strlwr: {
      std::string s = text(0);
      for (char& c : s) {
        const auto byte = static_cast<unsigned char>(c);
        c = char(word == Word::strupr ? std::toupper(byte) : std::tolower(byte));
      }
      return checked(std::move(s));
    }
    default:
      fail(at, "'" + function + "' is not a string function");
  }
}

}  // namespace convray::sdl
