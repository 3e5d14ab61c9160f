#pragma once
// Tokens of one scene or include file, read once (grammar/lexical.hpp): macro bodies, loops
// and repeated includes replay ranges of the same token vector. A token is 32 bytes and owns
// nothing: its text points into the file's text (or, for strings with escapes, into the
// file's decoded strings), so the file must outlive its tokens.
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sdl/keywords.hpp"

namespace convray::sdl {

enum class LexKind : std::uint8_t { identifier, keyword, number, string, symbol, directive, end };

// Two-character symbols, in LexToken::symbol.
inline constexpr char kLessEqual = 'L';     // <=
inline constexpr char kGreaterEqual = 'G';  // >=
inline constexpr char kNotEqual = 'N';      // !=

struct LexToken {
  const char* text = nullptr;  // as written; strings: the decoded contents; directives: name
  double number = 0.0;         // LexKind::number
  std::uint32_t length = 0;
  std::uint32_t line = 0;    // 1-based
  std::uint32_t column = 0;  // 1-based, in bytes
  LexKind kind = LexKind::end;
  Word word = Word::none;  // keywords and directives
  char symbol = 0;         // LexKind::symbol: the character, or kLessEqual ...

  std::string_view view() const { return {text, length}; }
};

struct SourceFile {
  std::string name;  // as shown in messages
  std::string text;
  std::vector<LexToken> tokens;
  std::deque<std::string> decoded_strings;  // strings whose escapes changed them
  std::vector<std::string> warnings;        // "file:line:col: message"
};

// Reads all tokens of `text`. Throws InputError (with the source line and a caret) on an
// unterminated comment or string, an unexpected character or a number out of range.
std::unique_ptr<SourceFile> tokenize(std::string name, std::string text);

}  // namespace convray::sdl
