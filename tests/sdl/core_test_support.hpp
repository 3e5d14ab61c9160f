#pragma once
// Shared by the parser core's tests (lexer, expressions, functions, directives, control
// flow, macros, includes, errors): evaluate an expression or run directives from a string,
// read the globals they declare, catch the error a text must give.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "reference/test_folder.hpp"
#include "program_options.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::core_testing {

// The value of one expression, after any directives before it; the whole text must be used.
inline Value eval(const std::string& text, const ParseOptions& options = program_options()) {
  Parser parser("test.pov", text, options);
  Value value = parser.parse_expression();
  EXPECT_EQ(parser.peek().kind, Token::Kind::end)
      << "left over: '" << parser.peek().text << "' in: " << text;
  return value;
}

inline double eval_float(const std::string& text, const ParseOptions& options = program_options()) {
  const Value value = eval(text, options);
  EXPECT_NE(value.get<double>(), nullptr) << text << " gave " << type_name(value);
  return value.get<double>() ? *value.get<double>() : -12345.0;
}

inline Vector eval_vector(const std::string& text) {
  const Value value = eval(text);
  EXPECT_NE(value.get<Vector>(), nullptr) << text << " gave " << type_name(value);
  return value.get<Vector>() ? *value.get<Vector>() : Vector{};
}

inline std::string eval_string(const std::string& text) {
  const Value value = eval(text);
  EXPECT_NE(value.get<std::string>(), nullptr) << text << " gave " << type_name(value);
  return value.get<std::string>() ? *value.get<std::string>() : std::string("<not a string>");
}

// The globals and warnings of a scene of directives (and items).
inline ParseResult run(const std::string& text, const ParseOptions& options = program_options()) {
  return parse_string(text, "test.pov", options);
}

inline double global_float(const ParseResult& result, const std::string& name) {
  const auto found = result.globals.find(name);
  if (found == result.globals.end()) {
    ADD_FAILURE() << "'" << name << "' is not declared";
    return -12345.0;
  }
  const double* value = found->second.get<double>();
  EXPECT_NE(value, nullptr) << name << " is " << type_name(found->second);
  return value ? *value : -12345.0;
}

inline std::string global_string(const ParseResult& result, const std::string& name) {
  const auto found = result.globals.find(name);
  if (found == result.globals.end() || found->second.get<std::string>() == nullptr) {
    ADD_FAILURE() << "'" << name << "' is not a declared string";
    return {};
  }
  return *found->second.get<std::string>();
}

// The float a scene of directives declares as `name`.
inline double declared(const std::string& text, const std::string& name,
                       const ParseOptions& options = program_options()) {
  return global_float(run(text, options), name);
}

// The error a text gives as a scene (or as an expression, for `expression_error`).
struct Failure {
  SourceLoc loc;
  std::string message;     // the whole message: first line, source line, caret
  std::string first_line;  // what is wrong
};

inline Failure to_failure(const InputError& error) {
  const std::string& message = error.message();
  return {error.loc(), message, message.substr(0, message.find('\n'))};
}

inline Failure scene_error(const std::string& text, const ParseOptions& options = program_options()) {
  try {
    run(text, options);
  } catch (const InputError& error) {
    return to_failure(error);
  }
  ADD_FAILURE() << "expected an error from:\n" << text;
  return {};
}

inline Failure expression_error(const std::string& text) {
  try {
    Parser parser("test.pov", text, program_options());
    parser.parse_expression();
  } catch (const InputError& error) {
    return to_failure(error);
  }
  ADD_FAILURE() << "expected an error from: " << text;
  return {};
}

// A folder of files for include tests, removed afterwards.
class TempFolder {
 public:
  // Writes `text` to `name` in the folder (sub-folders created) and returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = folder_.path() / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file.string();
  }
  std::string path() const { return folder_.path().string(); }

 private:
  convray::testing::TestFolder folder_{"sdl"};
};

}  // namespace convray::sdl::core_testing
