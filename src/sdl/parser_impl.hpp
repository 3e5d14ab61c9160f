#pragma once
// Parser::Impl: the state of one parse, shared by the files of the parser core.
//
//   token_stream.cpp  frames (scene, include, macro body, function body); peek and advance,
//                     where directives run and macro calls expand
//   directives.cpp    #declare #local #undef #include #version #debug #warning #error #default
//   control_flow.cpp  #if #ifdef #ifndef #elseif #else #while #for #switch #case #range #break
//                     #end, and the fast skipping of branches not taken
//   macros.cpp        #macro definitions and calls; user functions (`function (x) {...}`)
//   expressions.cpp   the expression grammar: ?:, binary operators, unary, postfix, primary
//   arithmetic.cpp    operators on values, with POV-Ray's float -> vector promotion
//   colors.cpp        colour expressions: color, rgb..., srgb..., red ..., filter ...
//   functions.cpp     built-in float, vector and string functions
//   arrays.cpp        array declarations, indexing, element assignment
//   symbols.cpp       scopes, lookup, "did you mean"
//   parser.cpp        Parser's public API, parse_file, parse_string
//
// How tokens flow: `plain()` is the next token of the innermost frame, finished frames popped
// (macro bodies and includes end there); `settle()` also runs directives and expands macro
// calls until a plain token remains, which is what item parsers see. Expressions look ahead
// with plain(): a directive never continues an expression, so `#declare A = 1` followed by
// `#declare B = A;` stores A before the next directive runs (POV-Ray needs the `;` there).
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/color_sources.hpp"
#include "scene/function.hpp"
#include "sdl/lexer.hpp"
#include "sdl/parser.hpp"
#include "util/read_permissions.hpp"

namespace convray::sdl {

// POV-Ray's tolerance: `=` holds when |a - b| < kEpsilon; a condition is true when
// |value| > kEpsilon.
inline constexpr double kEpsilon = 1e-10;
// Guards against input built to exhaust memory or the stack.
inline constexpr int kMaxNestingDepth = 512;  // expressions, items, directives
inline constexpr std::size_t kMaxArrayElements = 1u << 21;
inline constexpr std::size_t kMaxStringLength = 1u << 20;
// Copying strings and arrays is work a loop can repeat without reading many tokens; it is
// charged against ParseOptions::max_tokens at one token per this many bytes or elements, so
// that the token limit bounds all the work of a runaway scene.
inline constexpr std::size_t kBytesPerToken = 64;
inline constexpr std::size_t kElementsPerToken = 8;

struct StringHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};
template <class T>
using NameMap = std::unordered_map<std::string, T, StringHash, std::equal_to<>>;

// A token and the file it is in: enough to make a SourceLoc, only when a message needs one.
struct TokenRef {
  const SourceFile* file = nullptr;
  const LexToken* token = nullptr;
};

// An open #if, #while, #for or #switch of a frame.
struct Block {
  enum class Kind : std::uint8_t { if_, while_, for_, switch_ };
  Kind kind = Kind::if_;
  std::uint32_t opened_at = 0;   // token index of the opening directive
  std::uint32_t loop_start = 0;  // while: the condition's first token; for: the body's
  long long iterations = 0;  // of this loop, and of the loops run inside it (counted once each)
  long long own_iterations = 0;
  std::string variable;  // for: the loop variable, its last value and step
  double last = 0.0, step = 1.0;
};

// A range of tokens being read.
struct Frame {
  enum class Kind : std::uint8_t { scene, include, macro, function };
  Kind kind = Kind::scene;
  const SourceFile* file = nullptr;
  std::uint32_t pos = 0, end = 0;  // next token, one past the last
  std::vector<Block> blocks;
  std::uint64_t scope = 0;  // serial of the scope this frame opened, 0: none
  std::string name;         // macro or function name, for messages
};

// A macro parameter passed by reference (POV-Ray passes an argument that is a bare identifier
// or array element that way): the caller's variable, or an element of its array, itself.
struct Alias {
  std::uint64_t scope = 0;          // serial of the scope that holds the variable
  std::string name;                 // the variable's name there
  std::vector<std::size_t> element; // the element's path in the variable's array; empty: all
};

struct Scope {
  std::uint64_t serial = 0;
  NameMap<Value> values;
  NameMap<Alias> aliases;  // names that stand for another scope's variable; never in values
};

struct MacroParameter {
  std::string name;
  bool optional = false;
};

struct Macro {
  std::string name;
  const SourceFile* file = nullptr;
  std::uint32_t body_begin = 0, body_end = 0;  // body_end: the #end
  std::vector<MacroParameter> parameters;
  SourceLoc loc;
};

// `#declare F = function (a, b) { expression }`: compiled where it is declared, evaluated
// wherever it is called (expressions, patterns, isosurfaces).
struct UserFunction {
  std::string name;
  SourceLoc loc;  // of the declaration
  std::vector<std::string> parameters;
  // Compiled when declared (function_compiler.cpp); null when the body needs what convray
  // cannot evaluate yet, which is then `unsupported` (a call fails with it).
  std::shared_ptr<const scene::Function> compiled;
  // `function { pigment { P } }`: a colour at (x, y, z) instead (compiled is null).
  std::shared_ptr<const scene::ColorSource> color_source;
  std::optional<UnsupportedItem> unsupported;
};

struct Deprecation {
  std::string message;
  bool once = false, warned = false;
};

// A file a scene opened with #fopen (sdl/file_io.cpp): read whole when opened, or written
// whole (atomically) when closed.
struct OpenFile {
  std::string path;
  bool writing = false;
  std::string text;        // read: the contents; write: what #write gave so far
  std::size_t pos = 0;     // read: the next byte
};

// Directive stops for skip(): which directives end a skip at nesting depth 0.
enum class SkipStop : std::uint8_t { end, if_branch, switch_clause };

struct Parser::Impl {
  Impl(Parser& owner, ParseOptions options);

  Parser& owner;
  ParseOptions options;
  ReadPermissions readable;  // the folders files may be read from (POV-Ray's I/O restrictions)
  Defaults defaults;
  std::vector<std::unique_ptr<SourceFile>> files;
  NameMap<const SourceFile*> files_by_name;  // tokenized once, by resolved path
  std::deque<Frame> frames;
  std::vector<Scope> scopes;  // [0]: global
  std::uint64_t next_scope_serial = 1;
  NameMap<std::shared_ptr<const Macro>> macros;
  NameMap<std::shared_ptr<const UserFunction>> functions;
  NameMap<Deprecation> deprecations;
  const LexToken* last_deprecated_use = nullptr;
  std::vector<std::uint32_t> random_streams;  // the states of seed()'s streams
  std::vector<std::string> warnings;
  std::map<std::string, Value> globals_view;
  double language_version = 3.7;
  bool version_given = false;        // a #version directive was read
  bool assumed_gamma_given = false;  // global_settings { assumed_gamma ... } was read
  std::vector<std::function<void(const scene::Scene&)>> parse_end_actions;  // at_parse_end
  NameMap<OpenFile> open_files;  // by the identifier #fopen gave them
  std::set<std::string, std::less<>> ended_files;  // closed by #read at their end

  int nesting_depth = 0;
  int open_blocks = 0;
  // The texture the last #declare stored and the token count right after it: a texture
  // statement read just there is its next layer (layer_onto_declared_texture).
  std::string last_texture_name;
  long long last_texture_end = -1;
  // That texture's (or unusable item's) value, if no token was read since it was declared.
  Value* texture_declared_just_before();  // braces items::Block opened and has not closed (deferred_unsupported)
  int macro_depth = 0, include_depth = 0;
  int quiet_math = 0;   // > 0: math errors in a branch whose value is discarded
  int angle_depth = 0;
  int less_starts_vector = 0;  // > 0: a '<' ends the float (parse_float_before_points)  // > 0: directly inside < >, where '>' ends the vector
  int frame_floor = 0;  // frames at or below this count are not left by lookahead
  long long tokens_read = 0;
  // The elements of every live array (sdl::ElementCount), against
  // ParseOptions::max_live_array_elements.
  ElementCount::Live live_array_elements = std::make_shared<std::atomic<std::size_t>>(0);

  // The settled token and the public Token made from it, valid until the stream moves.
  bool settled = false;
  const LexToken* current = nullptr;
  bool materialized = false;
  Token token;
  LexToken end_token;

  // --- token_stream.cpp
  // The fast paths are inline: every token passes here several times.
  const LexToken& plain() {
    const Frame& frame = frames.back();
    return frame.pos < frame.end ? frame.file->tokens[frame.pos] : plain_at_frame_end();
  }
  const LexToken& settle() { return settled ? *current : settle_next(); }
  const LexToken& plain_at_frame_end();
  const LexToken& settle_next();
  void advance();
  void charge(std::size_t tokens);  // work other than reading tokens, in tokens
  // One more iteration of the innermost loop `loop`: counted for it and for every loop it runs
  // inside (a nested loop's iterations are its enclosing loops' work), against
  // ParseOptions::max_loop_iterations.
  void count_iteration(Block& loop);
  // Fails at `at` when `count` more array elements would take the live arrays past
  // ParseOptions::max_live_array_elements; otherwise returns their count, for the new array
  // to hold.
  ElementCount reserve_elements(std::size_t count, TokenRef at);
  // Makes `held` count `count` elements, failing at `at` when the growth would take the budget
  // past ParseOptions::max_live_array_elements.
  void recount_elements(ElementCount& held, std::size_t count, const SourceLoc& at);
  void check_element_budget(std::size_t more, const SourceLoc& at) const;
  // What a value held in an array counts beyond its element: a long string's characters.
  static std::size_t string_elements(const Value& value);
  void moved() {
    settled = false;
    materialized = false;
  }
  bool leave_finished_frame();
  Frame& push_frame(Frame::Kind kind, const SourceFile* file, std::uint32_t begin,
                    std::uint32_t end);
  const Token& materialize();
  TokenRef ref() { return {frames.back().file, &plain()}; }
  SourceLoc loc(TokenRef at) const;
  SourceLoc here() { return loc(ref()); }
  SourceLoc token_loc(const SourceFile* file, std::uint32_t index) const;
  std::string describe(const LexToken& t) const;
  bool at_symbol(char c) {
    const LexToken& t = settle();
    return is_symbol(t, c);
  }
  bool accept_symbol(char c);
  void expect_symbol(char c, std::string_view context);
  // The next token for an expression that may continue: plain(), after the directives that
  // only move through blocks (#else, #elseif, #break, #end of an #if or #switch), which
  // cannot change a value: `N * F(N - 1)` continues after an #else in F's body.
  const LexToken& lookahead() {
    const LexToken& t = plain();
    return t.kind == LexKind::directive ? lookahead_through_blocks() : t;
  }
  const LexToken& lookahead_through_blocks();
  bool plain_symbol(char c) { return is_symbol(lookahead(), c); }
  static bool is_symbol(const LexToken& t, char c) {
    return t.kind == LexKind::symbol && t.symbol == c;
  }
  std::string_view expect_identifier_raw(std::string_view context);

  // --- parser.cpp / diagnostics
  [[noreturn]] void fail(const SourceLoc& at, const std::string& message) const;
  [[noreturn]] void fail(TokenRef at, const std::string& message) const { fail(loc(at), message); }
  [[noreturn]] void fail_here(const std::string& message) { fail(ref(), message); }
  // An UnsupportedError; `feature` (default: the message) is what a deferring declaration
  // keeps.
  [[noreturn]] void fail_unsupported(const SourceLoc& at, const std::string& message,
                                     const std::string& feature = "") const;
  // Fails at `at` if `value` (the identifier `name`'s) is an UnsupportedItem.
  void check_usable(const Value& value, std::string_view name, TokenRef at) const;
  void warn(const SourceLoc& at, const std::string& message);
  const SourceFile& load_file(const std::string& path, const SourceLoc& requested_at);
  std::string resolve(const std::string& name, const SourceLoc& at, bool must_exist) const;
  void allow_reads_for(const std::string& scene_name);
  std::string allowed_folders_text() const;
  void enter_nesting();
  void leave_nesting() { --nesting_depth; }

  // --- directives.cpp
  void run_directive();
  void directive_declare(bool local, TokenRef at);
  void directive_undef();
  void directive_include(TokenRef at);
  void directive_message(Word kind, TokenRef at);
  void directive_default();
  void accept_optional_semicolon();
  Value parse_rvalue();

  // --- file_io.cpp: #fopen #fclose #read #write; files still open when the parse ends are
  // closed (written) by close_open_files.
  void directive_fopen(TokenRef at);
  void directive_fclose(TokenRef at);
  void directive_write(TokenRef at);
  void directive_read(TokenRef at);
  void close_open_files();
  std::string writable_path(const std::string& name, TokenRef at) const;

  // --- control_flow.cpp
  void directive_if(Word kind, std::uint32_t at);
  void directive_else(Word kind, TokenRef at);
  void directive_while(std::uint32_t at);
  void directive_for(std::uint32_t at);
  void directive_switch(std::uint32_t at);
  void directive_case(Word kind, TokenRef at);
  void directive_break(TokenRef at);
  void directive_end(TokenRef at);
  double parse_condition();
  bool parse_defined_condition();
  Word skip(int depth, SkipStop stop, std::uint32_t opened_at);
  bool seek_switch_clause(double value, std::uint32_t opened_at);
  [[noreturn]] void fail_unterminated(const Frame& frame, const Block& block) const;

  // --- macros.cpp
  void directive_macro(TokenRef at);
  bool expand_if_macro(const LexToken& name);
  void call_macro(std::shared_ptr<const Macro> macro, TokenRef at);
  std::optional<Alias> parse_reference_argument();
  bool reference_argument_ahead() const;
  void declare_function(const std::string& name);
  Value call_function(const UserFunction& function, TokenRef at);
  // --- function_compiler.cpp: the body, at its first token, into function.compiled.
  void compile_function_body(UserFunction& function);
  void compile_function(UserFunction& function);
  void compile_internal(UserFunction& function);
  const scene::ColorSources& color_sources(TokenRef at);
  void compile_color_function(UserFunction& function);
  std::uint32_t find_closing_brace(std::uint32_t opened_at);

  // --- expressions.cpp
  Value parse_expression();
  Value parse_ternary();
  Value parse_binary(int min_precedence);
  Value parse_unary();
  Value parse_postfix();
  Value parse_primary();
  Value parse_parenthesized();
  Value parse_vector_literal();
  Value parse_identifier();
  Value parse_keyword();
  Value parse_component(const Value& value, TokenRef dot);
  std::vector<Value> parse_arguments(const LexToken& name, std::size_t min, std::size_t max);
  int binary_precedence(const LexToken& t) const;
  double to_float(const Value& v, TokenRef at, std::string_view what) const;
  Vector to_vector(const Value& v, TokenRef at, std::string_view what) const;
  const std::string& to_string(const Value& v, TokenRef at, std::string_view what) const;
  int to_int(double v, TokenRef at, std::string_view what) const;

  // --- arithmetic.cpp
  Value apply_binary(char op, const Value& a, const Value& b, TokenRef at);
  Value apply_unary(char op, const Value& a, TokenRef at);
  void math_error(TokenRef at, const std::string& message) const;
  Value finite(double value, TokenRef at) const;

  // --- colors.cpp
  Value parse_color_group();
  Value apply_color_modifiers(Value color);
  static bool is_color_keyword(const LexToken& t);
  static bool is_color_modifier(const LexToken& t);
  static Vector to_color(const Vector& v);

  // --- functions.cpp
  Value call_builtin(const LexToken& name, TokenRef at);
  // --- object_functions.cpp: min_extent, max_extent, trace (the name not yet consumed).
  Value call_object_function(const LexToken& name, TokenRef at);
  Value call_string_function(Word word, std::vector<Value>& args, TokenRef at);
  Value call_vector_function(Word word, std::vector<Value>& args, TokenRef at);
  double next_random(double stream, TokenRef at);

  // --- arrays.cpp
  Value parse_array_declaration();
  void parse_array_initializer(Array& array, std::size_t dimension, std::size_t& next);
  std::size_t parse_index_group(const Array& array, std::string_view name);
  Value index_array(const Value& array_value, TokenRef at, std::string_view name);
  std::vector<std::size_t> parse_element_path(const Value& root, std::string_view name);
  Value* element_at(Value& root, const std::vector<std::size_t>& path, bool for_write,
                    std::string_view name, TokenRef at);
  // `#declare A[i]... = value`: the element written (unsharing arrays on the way), a long
  // string counted in the element budget.
  void store_element(Value& root, const std::vector<std::size_t>& path, Value value,
                     std::string_view name, TokenRef at);

  // --- symbols.cpp
  Value* lookup(std::string_view name);
  const Value* lookup(std::string_view name) const;
  bool is_declared(std::string_view name) const;
  void declare_global(std::string_view name, Value value);
  void declare_local(std::string_view name, Value value);
  void store(std::uint64_t scope_serial, std::string_view name, Value value);
  const Alias* innermost_alias(std::string_view name) const;
  std::optional<Alias> alias_of(std::string_view name) const;
  Value* resolve(const Alias& alias);
  void store_through(const Alias& alias, Value value, TokenRef at);
  std::uint64_t push_scope();
  void pop_scope(std::uint64_t serial);
  bool undeclare(std::string_view name);
  std::string did_you_mean(std::string_view name) const;
  void check_deprecated(std::string_view name, TokenRef at);
};

// Marks one level of nesting for the duration of a scope (expressions, items, directives).
class NestingLevel {
 public:
  explicit NestingLevel(Parser::Impl& impl) : impl_(impl) { impl_.enter_nesting(); }
  ~NestingLevel() { impl_.leave_nesting(); }
  NestingLevel(const NestingLevel&) = delete;
  NestingLevel& operator=(const NestingLevel&) = delete;

 private:
  Parser::Impl& impl_;
};

// Sets a counter for a scope and restores it after: quiet_math, angle_depth.
class ScopedValue {
 public:
  ScopedValue(int& target, int value) : target_(target), saved_(target) { target_ = value; }
  ~ScopedValue() { target_ = saved_; }
  ScopedValue(const ScopedValue&) = delete;
  ScopedValue& operator=(const ScopedValue&) = delete;

 private:
  int& target_;
  int saved_;
};

inline Value make_value(double f) { return Value{f, {}}; }
inline Value make_value(const Vector& v) { return Value{v, {}}; }
inline Value make_value(std::string s) { return Value{std::move(s), {}}; }
inline bool is_true(double f) { return f > kEpsilon || f < -kEpsilon; }

// Reads a whole regular file (scenes, includes, #read files); false when it cannot be read.
bool read_file(const std::string& path, std::string& text);

}  // namespace convray::sdl
