#include "sdl/lexer.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "grammar/lexical.hpp"
#include "sdl/diagnostics.hpp"
#include "util/error.hpp"

namespace convray::sdl {
namespace {

namespace pegtl = tao::pegtl;
namespace grammar = convray::grammar;

// Raised by the grammar's error rules and by actions: a message at a place in the text.
struct LexicalError {
  std::string message;
  const char* where;
};

template <typename Rule>
struct Control : pegtl::normal<Rule> {
  template <typename ParseInput, typename... States>
  [[noreturn]] static void raise(const ParseInput& in, States&&...) {
    const char* at = in.current();
    std::string message = grammar::error_message<Rule>;
    if constexpr (std::is_same_v<Rule, grammar::unexpected_character>) {
      const unsigned char c = static_cast<unsigned char>(*at);
      if (c >= 0x20 && c < 0x7f) {
        message += std::string(" '") + char(c) + "'";
      } else {
        static const char* hex = "0123456789abcdef";
        message += std::string(" (byte 0x") + hex[c >> 4] + hex[c & 15] + ")";
      }
    }
    throw LexicalError{message, at};
  }
};

// The tokens made so far, and the line count up to the last token: PEGTL's lazy input does
// not track lines (eager tracking costs a test per byte), so the actions count newlines
// between tokens with memchr.
struct LexState {
  SourceFile& file;
  const char* counted_to;  // newlines before this point are counted
  const char* line_start;
  std::uint32_t line = 1;

  // Line and column of p, at or after the previous call's.
  void locate(const char* p, std::uint32_t& token_line, std::uint32_t& token_column) {
    while (const void* newline = std::memchr(counted_to, '\n', std::size_t(p - counted_to))) {
      ++line;
      counted_to = line_start = static_cast<const char*>(newline) + 1;
    }
    counted_to = p;
    token_line = line;
    token_column = std::uint32_t(p - line_start + 1);
  }
};

template <typename ActionInput>
LexToken start_token(const ActionInput& in, LexKind kind, LexState& state) {
  LexToken token;
  token.kind = kind;
  token.text = in.begin();
  token.length = std::uint32_t(in.size());
  state.locate(in.begin(), token.line, token.column);
  return token;
}

// Line and column of p (for errors): counted from the start.
void line_and_column(std::string_view text, const char* p, int& line, int& column) {
  line = 1;
  std::size_t line_start = 0;
  const std::size_t offset = std::size_t(p - text.data());
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  column = int(offset - line_start) + 1;
}

template <typename Rule>
struct Action : pegtl::nothing<Rule> {};

template <>
struct Action<grammar::number> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, LexState& state) {
    LexToken token = start_token(in, LexKind::number, state);
    const char* first = in.begin();
    const char* last = in.end();
    const auto [stop, error] = std::from_chars(first, last, token.number);
    // from_chars accepts every form the grammar does ("1.", ".5", "1e-3"). Out of range is
    // either underflow (1e-400: a fine number, about zero) or overflow (1e999: an error);
    // strtod tells which.
    if (error == std::errc::result_out_of_range) {
      token.number = std::strtod(std::string(first, last).c_str(), nullptr);
    }
    if ((error != std::errc() && error != std::errc::result_out_of_range) || stop != last ||
        !std::isfinite(token.number)) {
      throw LexicalError{"number out of range: " + std::string(in.string_view()), in.begin()};
    }
    state.file.tokens.push_back(token);
  }
};

// The character an escape stands for, or 0 for an unknown escape (kept as written).
char unescape(char c) {
  switch (c) {
    case '"':
      return '"';
    case '\\':
      return '\\';
    case '\'':
      return '\'';
    case 'n':
      return '\n';
    case 't':
      return '\t';
    case 'r':
      return '\r';
    case 'a':
      return '\a';
    case 'b':
      return '\b';
    case 'f':
      return '\f';
    case 'v':
      return '\v';
    default:
      return 0;
  }
}

template <>
struct Action<grammar::string_literal> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, LexState& state) {
    LexToken token = start_token(in, LexKind::string, state);
    const std::string_view quoted = in.string_view();
    const std::string_view contents = quoted.substr(1, quoted.size() - 2);
    token.text = contents.data();
    token.length = std::uint32_t(contents.size());
    if (contents.find('\\') != std::string_view::npos) {
      std::string decoded;
      decoded.reserve(contents.size());
      for (size_t i = 0; i < contents.size(); ++i) {
        if (contents[i] != '\\') {
          decoded += contents[i];
          continue;
        }
        const char escaped = contents[++i];  // the grammar guarantees a character follows
        if (const char c = unescape(escaped)) {
          decoded += c;
        } else {
          decoded += '\\';
          decoded += escaped;
          state.file.warnings.push_back(
              SourceLoc{state.file.name, int(token.line), int(token.column)}.str() +
              ": unknown escape sequence '\\" + std::string(1, escaped) +
              "' in a string, kept as written");
        }
      }
      const std::string& stored = state.file.decoded_strings.emplace_back(std::move(decoded));
      token.text = stored.data();
      token.length = std::uint32_t(stored.size());
    }
    state.file.tokens.push_back(token);
  }
};

template <>
struct Action<grammar::directive> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, LexState& state) {
    // At the '#'; the text is the name after it (and after blanks: "# declare").
    LexToken token = start_token(in, LexKind::directive, state);
    std::string_view text = in.string_view();
    text.remove_prefix(text.find_first_not_of("# \t"));
    token.text = text.data();
    token.length = std::uint32_t(text.size());
    token.word = classify_word(text);
    state.file.tokens.push_back(token);
  }
};

template <>
struct Action<grammar::word> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, LexState& state) {
    LexToken token = start_token(in, LexKind::identifier, state);
    token.word = classify_word(in.string_view());
    if (token.word != Word::none) token.kind = LexKind::keyword;
    state.file.tokens.push_back(token);
  }
};

template <>
struct Action<grammar::symbol> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, LexState& state) {
    LexToken token = start_token(in, LexKind::symbol, state);
    const std::string_view text = in.string_view();
    token.symbol = text[0];
    if (text == "<=") token.symbol = kLessEqual;
    if (text == ">=") token.symbol = kGreaterEqual;
    if (text == "!=") token.symbol = kNotEqual;
    state.file.tokens.push_back(token);
  }
};

}  // namespace

std::unique_ptr<SourceFile> tokenize(std::string name, std::string text) {
  auto file = std::make_unique<SourceFile>();
  file->name = std::move(name);
  file->text = std::move(text);
  if (file->text.size() >= std::numeric_limits<std::uint32_t>::max()) {
    throw InputError({file->name}, "file too large (4 GiB or more)");
  }
  // A token per three bytes is about what dense scenes (numbers and commas) have.
  file->tokens.reserve(file->text.size() / 3 + 16);
  LexState state{*file, file->text.data(), file->text.data()};
  pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf> input(
      file->text.data(), file->text.size(), file->name);
  try {
    if (!pegtl::parse<grammar::file, Action, Control>(input, state)) {
      throw LexicalError{"unreadable text", input.current()};
    }
  } catch (const LexicalError& error) {
    SourceLoc loc{file->name, 0, 0};
    line_and_column(file->text, error.where, loc.line, loc.column);
    throw InputError(loc, with_source_line(error.message, file->text, loc.line, loc.column));
  }
  LexToken end;
  end.kind = LexKind::end;
  end.text = file->text.data() + file->text.size();
  state.locate(end.text, end.line, end.column);
  file->tokens.push_back(end);
  return file;
}

}  // namespace convray::sdl
