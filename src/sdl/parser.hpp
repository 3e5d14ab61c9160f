#pragma once
// The scene parser's core: tokens from the lexer (grammar/), with POV-Ray's directives,
// macros and includes carried out as the tokens are read, so the code that parses scene items
// (items.hpp) only ever sees plain tokens; and expressions, evaluated as they are parsed, as
// POV-Ray does.
//
// Errors are InputError at `file:line:col` of the offending token. The parser knows nothing
// of rendering: it produces a scene::Scene of plain records.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.hpp"
#include "sdl/options.hpp"
#include "sdl/value.hpp"
#include "util/error.hpp"

namespace convray::sdl {

struct Token {
  enum class Kind { identifier, keyword, number, string, symbol, end };
  Kind kind = Kind::end;
  std::string text;     // as written (strings: the decoded contents)
  double number = 0.0;  // Kind::number
  SourceLoc loc;
};

// Defaults set by `#default { texture {...} pigment {...} finish {...} }`.
struct Defaults {
  scene::Texture texture = scene::default_texture();
};

class Parser {
 public:
  Parser(std::string file_name, std::string text, ParseOptions options);
  ~Parser();
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;

  // The whole scene file: top-level statements until the end of the text.
  scene::Scene parse_scene();

  // --- Tokens, after directives, macro calls and includes have been carried out.
  const Token& peek();
  Token next();
  // Whether the next token is this keyword or symbol ("sphere", "{", "<", ...).
  bool at(std::string_view text);
  // Consumes the next token if it is `text`.
  bool accept(std::string_view text);
  // Consumes `text` or fails with "expected TEXT in WHAT, found ...". A `what` that starts
  // with its own preposition ("to close sphere (opened at 2:1)", "after ...") is used as it
  // is: "expected '}' to close sphere (opened at 2:1), found 'texure'".
  Token expect(std::string_view text, std::string_view what);

  // --- Expressions, evaluated.
  Value parse_expression();       // any type: float, vector, colour, string, array, item
  double parse_float();           // a float expression
  int parse_int();                // a float expression with an integer value
  Vec3 parse_vector();            // a vector expression; a float f is promoted to <f, f, f>
  scene::Color parse_color();     // colour keywords and expressions: rgb, rgbf, red ..., srgb
  std::string parse_string();     // a string expression (concat, str, ...)
  // A float inside `< >` that an item writes out itself (matrix <m00, ..., m32>): a bare '>'
  // ends it instead of comparing, as in the core's own vector literals.
  double parse_float_in_angle_brackets();
  // A float followed by a list of points without a comma (`prism { 0, 1, 4 <-1, 0>, ...`):
  // a '<' after it starts the first point instead of comparing, as in POV-Ray.
  double parse_float_before_points();
  // The same for a point followed by the next without a comma (`<1, 0, 2> <1, -1, 2>`, as
  // teapot.inc lists a bicubic_patch's points).
  Vec3 parse_vector_before_points();
  // After `[`, `(`: the optional comma between items, as POV-Ray accepts it.
  void accept_comma() { accept(","); }

  // The value of an identifier that is declared, if the next token is one (not consumed):
  // item parsers use it for `texture { T_Stone }`, `object { Thing }`, `pigment { P }`.
  const Value* peek_declared();
  // At `function { body }` (isosurfaces, function patterns): the body compiled as a function
  // of x, y and z (function_compiler.cpp). What convray cannot evaluate yet fails here.
  std::shared_ptr<const scene::Function> parse_function_block();
  // At `pigment_pattern { PIGMENT }`: f(x, y, z), the grey of the pigment's colour there
  // (function_compiler.cpp).
  std::shared_ptr<const scene::Function> parse_pigment_pattern();

  // --- Context.
  const ParseOptions& options() const;
  // global_settings gave assumed_gamma: POV-Ray's gamma rule for scenes older than 3.7
  // (applied when the scene ends) does not apply.
  void note_assumed_gamma();
  // Runs `action` once the whole scene is read, with its final settings (an image_map's
  // colours depend on the scene's gamma, which global_settings may give after it).
  void at_parse_end(std::function<void(const scene::Scene&)> action);
  Defaults& defaults();
  // A file named in the scene (mesh, include), resolved as POV-Ray resolves includes: the
  // scene's folder, the +L paths, the installed include folder. Fails at `loc` if not found.
  std::string resolve_file(const std::string& name, const SourceLoc& loc) const;
  // The same, trying NAME + `file_type` when NAME itself is not found, as POV-Ray appends a
  // file's type (`text { ttf "cyrvetic" ... }` reads cyrvetic.ttf).
  std::string resolve_file(const std::string& name, const SourceLoc& loc,
                           const std::string& file_type) const;

  // Makes `held` count `count` elements of a mesh built in the scene (one per vertex, normal,
  // texture and face), in the one budget of the scene's arrays, strings and meshes
  // (ParseOptions::max_live_array_elements); fails at `loc` beyond it.
  void count_mesh_elements(ElementCount& held, std::size_t count, const SourceLoc& loc);
  // Fails at `loc` when `more` elements would take that budget past its limit.
  void check_element_budget(std::size_t more, const SourceLoc& loc) const;

  // Errors and warnings, with the source line and a caret when the location has one.
  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const;
  [[noreturn]] void fail_here(const std::string& message);  // at peek()
  void warn(const SourceLoc& loc, const std::string& message);
  const std::vector<std::string>& warnings() const;
  // For what convray knows and cannot render yet: an UnsupportedError, which a declaration
  // may defer (parse_or_skip_unsupported).
  [[noreturn]] void fail_unsupported(const SourceLoc& loc, const std::string& message) const;
  [[noreturn]] void fail_unsupported_here(const std::string& message);

  // `#declare T = texture { A } texture { B }`: the parser stores T after its first texture
  // (looking further would run a following directive too early), so the texture statements
  // read right after the declaration are its further layers: whether one is next, and then
  // the layer read, laid over T (or, when the layer needs what convray cannot render yet,
  // T becomes unusable with it).
  bool texture_declared_just_before();
  void add_declared_texture_layer(const std::optional<scene::Texture>& layer,
                                  const std::optional<UnsupportedItem>& unsupported);

  // --- Declarations that need what convray cannot render yet.
  // items::Block reports each `{` it opens and each `}` that closes one.
  void block_opened();
  void block_closed();
  // Runs `parse`. When it fails with an UnsupportedError inside braces that it opened
  // itself, the rest of those braces is read past and the error is returned instead: the
  // item declared with it stands until it is used (peek_declared and expressions then fail
  // with the error). Other failures, and unsupported ones outside braces, propagate.
  std::optional<UnsupportedItem> parse_or_skip_unsupported(const std::function<void()>& parse);

  // Global identifiers after parsing (for `convray field scene.pov --object NAME`).
  const std::map<std::string, Value>& globals() const;

  // " (did you mean 'foo'?)" when a declared identifier or reserved word is a likely typo
  // of `name`, else "": for messages about unknown words.
  std::string did_you_mean(std::string_view name) const;

  // Item parsers that recurse (CSG in CSG, ...) hold one per level: input nested absurdly
  // deep then fails with an error instead of overflowing the stack. Expressions and
  // directives count into the same limit.
  class NestingGuard {
   public:
    explicit NestingGuard(Parser& parser);
    ~NestingGuard();
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

   private:
    Parser& parser_;
  };

  struct Impl;

 private:
  void apply_legacy_gamma(scene::Scene& scene);

  std::unique_ptr<Impl> impl_;
};

// Parse a scene file or a string. Both throw InputError on bad input.
struct ParseResult {
  scene::Scene scene;
  std::map<std::string, Value> globals;
  std::vector<std::string> warnings;
};
ParseResult parse_file(const std::string& path, const ParseOptions& options);
ParseResult parse_string(const std::string& text, const std::string& name,
                         const ParseOptions& options);

}  // namespace convray::sdl
