#pragma once
// The scene language's lexical grammar: POV-Ray 3.7's tokens as PEGTL rules. src/sdl/lexer.cpp
// runs `file` over a whole scene or include file once, with actions that turn the matches of
// number, string_literal, directive, word and symbol into tokens; everything above the tokens
// (directives, macros, expressions, scene items) is the parser's (see README.md).
//
// The error rules (unterminated_string, unexpected_character, and block_comment when it
// reaches the end of the text) raise through the Control with their error_message below.
#include <cstddef>
#include <tao/pegtl.hpp>

namespace convray::grammar {

namespace pegtl = tao::pegtl;

// --- Whitespace and comments --------------------------------------------------------------

// `// ...` to the end of the line.
struct line_comment : pegtl::seq<pegtl::two<'/'>, pegtl::until<pegtl::eolf>> {};

// `/* ... */`, nested as POV-Ray nests them: `/* a /* b */ c */` is one comment. Matched by a
// counting loop instead of a recursive rule, so that a file of ten thousand `/*` cannot
// exhaust the stack. An unterminated comment raises at its opening `/*`.
struct block_comment {
  using rule_t = block_comment;
  using subs_t = pegtl::empty_list;

  template <pegtl::apply_mode, pegtl::rewind_mode, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  static bool match(ParseInput& in, States&&... states) {
    if (in.size(2) < 2 || in.peek_char(0) != '/' || in.peek_char(1) != '*') return false;
    const auto opening = in.iterator();
    in.bump(2);
    std::size_t depth = 1;
    while (depth > 0) {
      if (in.size(2) < 2) {
        in.iterator() = opening;  // report the comment where it starts
        Control<block_comment>::raise(in, states...);
      }
      const char c0 = in.peek_char(0), c1 = in.peek_char(1);
      if (c0 == '/' && c1 == '*') {
        ++depth;
        in.bump(2);
      } else if (c0 == '*' && c1 == '/') {
        --depth;
        in.bump(2);
      } else {
        in.bump(1);  // bump() counts lines and columns through newlines
      }
    }
    return true;
  }
};

struct separator : pegtl::star<pegtl::sor<pegtl::plus<pegtl::space>, line_comment, block_comment>> {
};

// --- Numbers: 1  1.5  .5  1.  1e-3  2E+4 (a sign is the parser's unary operator) -----------

struct digits : pegtl::plus<pegtl::digit> {};
struct mantissa
    : pegtl::sor<pegtl::seq<digits, pegtl::opt<pegtl::one<'.'>, pegtl::star<pegtl::digit>>>,
                 pegtl::seq<pegtl::one<'.'>, digits>> {};
struct exponent : pegtl::seq<pegtl::one<'e', 'E'>, pegtl::opt<pegtl::one<'+', '-'>>, digits> {};
struct number : pegtl::seq<mantissa, pegtl::opt<exponent>> {};

// --- Strings: "..." with POV-Ray's escapes \" \\ \n \t \r \a \b \f \v \' -----------------
// Other escapes are kept as written (a Windows path "C:\scenes" stays intact); the lexer
// warns about them.

struct escape : pegtl::seq<pegtl::one<'\\'>, pegtl::any> {};
struct string_char : pegtl::sor<escape, pegtl::not_one<'"', '\\'>> {};
struct string_literal : pegtl::seq<pegtl::one<'"'>, pegtl::until<pegtl::one<'"'>, string_char>> {};
// Tried after string_literal: a quote that starts no complete string.
struct unterminated_string
    : pegtl::seq<pegtl::at<pegtl::one<'"'>>, pegtl::raise<unterminated_string>> {};

// --- Words and directives -----------------------------------------------------------------

// Identifiers and reserved words: [A-Za-z_][A-Za-z0-9_]*. Which words are reserved is a
// table (src/sdl/keywords.cpp), not grammar.
struct word : pegtl::identifier {};

// `#` and a directive's name; POV-Ray tolerates blanks between them (`# declare`).
struct directive_name : pegtl::identifier {};
struct directive : pegtl::seq<pegtl::one<'#'>, pegtl::star<pegtl::blank>, directive_name> {};

// --- Punctuation and operators ------------------------------------------------------------

struct symbol
    : pegtl::sor<pegtl::string<'<', '='>, pegtl::string<'>', '='>, pegtl::string<'!', '='>,
                 pegtl::one<'{', '}', '(', ')', '[', ']', '<', '>', '=', ',', ';', '+', '-', '*',
                            '/', '?', ':', '!', '&', '|', '.', '#'>> {};

// Anything else where a token should start (not the end of the text).
struct unexpected_character
    : pegtl::seq<pegtl::at<pegtl::any>, pegtl::raise<unexpected_character>> {};

// --- A file -------------------------------------------------------------------------------

// Numbers come before symbols (".5" is a number, ".x" a dot and a word).
struct token : pegtl::sor<number, string_literal, unterminated_string, directive, word, symbol,
                          unexpected_character> {};

struct byte_order_mark : pegtl::string<'\xEF', '\xBB', '\xBF'> {};

struct file : pegtl::seq<pegtl::opt<byte_order_mark>, separator, pegtl::star<token, separator>,
                         pegtl::eof> {};

// --- Errors -------------------------------------------------------------------------------

template <typename Rule>
inline constexpr const char* error_message = "syntax error";
template <>
inline constexpr const char* error_message<block_comment> =
    "unterminated comment: this '/*' has no matching '*/'";
template <>
inline constexpr const char* error_message<unterminated_string> =
    "unterminated string: this '\"' has no closing quote";
template <>
inline constexpr const char* error_message<unexpected_character> = "unexpected character";

}  // namespace convray::grammar
