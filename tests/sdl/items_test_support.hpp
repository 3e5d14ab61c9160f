#pragma once
// Shared by the item parser tests (tests/sdl/items_*_test.cpp): parse a scene from a string,
// catch the error a scene must give, reach into object records.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "program_options.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::testing {

inline ParseResult parse(const std::string& text, const ParseOptions& options = program_options()) {
  return parse_string(text, "test.pov", options);
}

// Options that let a scene read the files a test wrote into `folder` (a scene reads only
// from the allowed folders: docs/files.md).
inline ParseOptions reading_from(const std::string& folder) {
  ParseOptions options;
  options.read_folders.push_back(folder);
  return options;
}

// The error a scene gives (its loc and message), or a test failure when it parses.
struct ParseFailure {
  SourceLoc loc;
  std::string message;
};

inline ParseFailure parse_error(const std::string& text, const ParseOptions& options = program_options()) {
  try {
    parse(text, options);
  } catch (const InputError& error) {
    return {error.loc(), error.message()};
  }
  ADD_FAILURE() << "expected an error from:\n" << text;
  return {};
}

// Whether the error is at line:col and its message contains `part`.
inline ::testing::AssertionResult fails_with(const std::string& text, int line, int column,
                                             const std::string& part) {
  const ParseFailure failure = parse_error(text);
  if (failure.loc.line != line || failure.loc.column != column ||
      failure.message.find(part) == std::string::npos) {
    return ::testing::AssertionFailure()
           << "got " << failure.loc.str() << ": " << failure.message << "\nexpected " << line << ":"
           << column << " and a message containing '" << part << "'";
  }
  return ::testing::AssertionSuccess();
}

// Whether some warning contains `part`.
inline bool has_warning(const ParseResult& result, const std::string& part) {
  for (const std::string& warning : result.warnings) {
    if (warning.find(part) != std::string::npos) return true;
  }
  return false;
}

// The only object of a scene (a test failure when there is not exactly one).
inline scene::ObjectPtr only_object(const ParseResult& result) {
  EXPECT_EQ(result.scene.objects.size(), 1u);
  return result.scene.objects.empty() ? nullptr : result.scene.objects.front();
}

// A copy of the object's shape record: returned by value so that
// `const auto& sphere = shape_of<scene::Sphere>(only_object(parse("...")));` stays valid
// after the parse result is gone.
template <class Shape>
Shape shape_of(const scene::ObjectPtr& object) {
  return std::get<Shape>(object->shape);
}

inline void expect_near(const Vec3& actual, const Vec3& expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance)
      << "x of <" << actual.x << ", " << actual.y << ", " << actual.z << ">";
  EXPECT_NEAR(actual.y, expected.y, tolerance)
      << "y of <" << actual.x << ", " << actual.y << ", " << actual.z << ">";
  EXPECT_NEAR(actual.z, expected.z, tolerance)
      << "z of <" << actual.x << ", " << actual.y << ", " << actual.z << ">";
}

}  // namespace convray::sdl::testing
