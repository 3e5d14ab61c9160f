#pragma once
// What every item parser (items.cpp, parse_*.cpp) shares: keywords matched by their text,
// `NAME { ... }` blocks that know where they opened (for a missing `}`) and which words they
// accept (for "did you mean"), parameters of a stated type ("expected a float for radius,
// found a vector"), optional booleans, and the transform keywords.
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "scene/color.hpp"
#include "scene/transform.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::items {

using Keywords = std::span<const std::string_view>;

// Words are matched by their text whether the lexer calls them keywords or identifiers: our
// own words (`convolution`, `segment`, ...) need not be reserved by the lexer.
bool at_word(Parser& parser, std::string_view word);
bool accept_word(Parser& parser, std::string_view word);
bool at_any_word(Parser& parser, Keywords words);

// The closest of `candidates` to `word` when it is a plausible misspelling, else empty.
std::string closest_word(std::string_view word, Keywords first, Keywords second = {},
                         Keywords third = {});

// A block `NAME { ... }` whose keyword was at `keyword_loc`; the constructor expects the `{`.
// Parse its contents with `while (block.more()) { ... }`: more() consumes the closing `}`.
class Block {
 public:
  Block(Parser& parser, std::string name, SourceLoc keyword_loc);

  // Whether something other than the closing `}` follows. At the end of the input fails with
  // "missing '}' to close the NAME opened at LOC".
  bool more();
  // Fails at the next token: "unexpected 'X' in NAME (did you mean 'Y'?)", the suggestion
  // taken from the words the block accepts.
  [[noreturn]] void unexpected(Keywords words, Keywords more = {}, Keywords most = {});

  const std::string& name() const { return name_; }
  const SourceLoc& loc() const { return keyword_loc_; }
  Parser& parser() { return parser_; }

 private:
  Parser& parser_;
  Parser::NestingGuard nesting_;  // blocks in blocks: absurd depths fail instead of crashing
  std::string name_;
  SourceLoc keyword_loc_;
};

// The declared item of type T the next tokens name, consumed: a declared identifier, or an
// element of a declared array (`texture { Textures[i][j] }`, which fails unless it is a T).
// Nothing (and nothing consumed) when the next token names neither. `what` names T in
// messages ("a texture"). `texture { T_Stone ... }` starts from a copy.
template <class T>
std::optional<T> accept_declared(Parser& parser, std::string_view what) {
  const Value* declared = parser.peek_declared();
  if (!declared) return std::nullopt;
  if (const auto* item = declared->get<std::shared_ptr<const T>>(); item && *item) {
    T copy = **item;
    parser.next();
    return copy;
  }
  if (!declared->get<std::shared_ptr<Array>>()) return std::nullopt;
  const SourceLoc loc = parser.peek().loc;
  const Value element = parser.parse_expression();
  if (const auto* item = element.get<std::shared_ptr<const T>>(); item && *item) return **item;
  parser.fail(loc, "expected " + std::string(what) + ", found " + type_name(element));
}

// Consumes the keyword at peek() and returns its location (for Object::loc and messages).
SourceLoc take_keyword(Parser& parser);

// Parameters of a stated type; `what` names the parameter in messages:
// "expected a float for radius, found a vector".
double float_param(Parser& parser, std::string_view what);
int int_param(Parser& parser, std::string_view what);
// A float f is promoted to <f, f, f>, a 2-D vector <u, v> to <u, v, 0>, as POV-Ray does.
Vec3 vector_param(Parser& parser, std::string_view what);
// A colour, with or without the leading `color`/`colour` keyword.
scene::Color color_param(Parser& parser);
// A colour's rgb where POV-Ray also takes a float: `ambient 0.1`, `ambient rgb <...>`.
Vec3 rgb_param(Parser& parser, std::string_view what);
// After a flag keyword (`hollow`, `open`, `jitter`, ...): an optional boolean value
// (on/off/true/false/yes/no or a float expression), true when absent.
bool optional_bool(Parser& parser);
// Whether the next token can start a float expression (for optional values: `metallic`,
// `bumps 0.5`).
bool at_float_start(Parser& parser);

// `{ ... }` with everything inside skipped (nested braces balanced): for blocks that are
// accepted with a warning and ignored (radiosity, photons, looks_like, ...).
void skip_braced(Parser& parser, std::string_view name, const SourceLoc& keyword_loc);

// Transform keywords: translate, rotate, scale, matrix, transform.
extern const std::string_view kTransformWords[5];
// If the next token is a transform keyword, parses it and its value; `keyword_loc` (if
// given) receives where the keyword was, for messages about that transform.
std::optional<scene::Transform> parse_transform_modifier(Parser& parser,
                                                         SourceLoc* keyword_loc = nullptr);
// `transform { ... }` or `transform ID`, at the `transform` keyword.
scene::Transform parse_transform_block(Parser& parser);

// A warning about something convray ignores or approximates, given once per parse: include
// files (textures.inc, shapes.inc) would otherwise repeat it for every item they declare.
// Later cases are recognised by the message, so it must not name the case.
void warn_once(Parser& parser, const SourceLoc& loc, const std::string& message);

// Formats numbers in messages without trailing zeros: 0.5, 1e-07.
std::string number_text(double value);

}  // namespace convray::sdl::items
