#include "sdl/item_helpers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace convray::sdl::items {

namespace {

bool is_word_token(const Token& token) {
  return token.kind == Token::Kind::keyword || token.kind == Token::Kind::identifier;
}

// Edit distance with adjacent transpositions counted as one edit ("pigmnet" -> "pigment").
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

// Words that start a top-level statement: met inside a block they usually mean that the
// block's `}` is missing.
constexpr std::string_view kStatementWords[] = {
    "camera",       "light_source", "background",      "fog",      "sky_sphere", "global_settings",
    "sphere",       "box",          "plane",           "cylinder", "cone",       "torus",
    "disc",         "triangle",     "smooth_triangle", "mesh",     "mesh2",      "union",
    "intersection", "difference",   "merge",           "object",   "blob",       "convolution"};

bool is_statement_word(std::string_view word) {
  return std::find(std::begin(kStatementWords), std::end(kStatementWords), word) !=
         std::end(kStatementWords);
}

// Identifiers that name a float: an optional value may start with one of these.
constexpr std::string_view kFloatWords[] = {
    "on",          "off",      "true",          "false",       "yes",           "no",
    "clock",       "pi",       "tau",           "image_width", "image_height",  "frame_number",
    "clock_delta", "clock_on", "initial_clock", "final_clock", "initial_frame", "final_frame",
    "version",     "abs",      "int",           "floor",       "ceil",          "min",
    "max",         "sqrt",     "pow",           "sin",         "cos",           "tan",
    "mod",         "div",      "select",        "vlength",     "vdot",          "strlen",
    "val",         "defined",  "rand",          "asc",         "exp",           "log",
    "ln",          "radians",  "degrees",       "atan2",       "atan",          "asin",
    "acos",        "sinh",     "cosh",          "tanh"};

std::string token_text(const Token& token) {
  switch (token.kind) {
    case Token::Kind::end:
      return "the end of the input";
    case Token::Kind::string:
      return "\"" + token.text + "\"";
    default:
      return "'" + token.text + "'";
  }
}

}  // namespace

bool at_word(Parser& parser, std::string_view word) {
  const Token& token = parser.peek();
  return is_word_token(token) && token.text == word;
}

bool accept_word(Parser& parser, std::string_view word) {
  if (!at_word(parser, word)) return false;
  parser.next();
  return true;
}

bool at_any_word(Parser& parser, Keywords words) {
  const Token& token = parser.peek();
  if (!is_word_token(token)) return false;
  return std::find(words.begin(), words.end(), token.text) != words.end();
}

std::string closest_word(std::string_view word, Keywords first, Keywords second, Keywords third) {
  const size_t allowed = word.size() <= 4 ? 1 : word.size() <= 8 ? 2 : 3;
  std::string best;
  size_t best_distance = allowed + 1;
  for (Keywords words : {first, second, third}) {
    for (std::string_view candidate : words) {
      const size_t distance = edit_distance(word, candidate);
      if (distance > 0 && distance < best_distance) {
        best_distance = distance;
        best = std::string(candidate);
      }
    }
  }
  return best;
}

Block::Block(Parser& parser, std::string name, SourceLoc keyword_loc)
    : parser_(parser),
      nesting_(parser),
      name_(std::move(name)),
      keyword_loc_(std::move(keyword_loc)) {
  parser_.expect("{", name_);
  parser_.block_opened();
}

bool Block::more() {
  const Token& token = parser_.peek();
  if (token.kind == Token::Kind::end) {
    parser_.fail(token.loc,
                 "missing '}' to close the " + name_ + " opened at " + keyword_loc_.str());
  }
  if (token.kind == Token::Kind::symbol && token.text == "}") {
    parser_.next();
    parser_.block_closed();
    return false;
  }
  return true;
}

void Block::unexpected(Keywords words, Keywords more, Keywords most) {
  const Token token = parser_.peek();
  std::string message = "unexpected " + token_text(token) + " in " + name_;
  if (const Value* declared = parser_.peek_declared()) {
    const std::string type = type_name(*declared);
    message += " (" + token.text + " is " + type + ")";
  } else if (is_word_token(token)) {
    const std::string suggestion = closest_word(token.text, words, more, most);
    if (!suggestion.empty()) {
      message += " (did you mean '" + suggestion + "'?)";
    } else if (is_statement_word(token.text)) {
      message += " (is the '}' of the " + name_ + " at " + keyword_loc_.str() + " missing?)";
    }
  }
  parser_.fail(token.loc, message);
}

SourceLoc take_keyword(Parser& parser) { return parser.next().loc; }

namespace {

// The next token, for "found ..." when there is no value to name.
[[noreturn]] void fail_expected(Parser& parser, std::string_view type, std::string_view what,
                                const SourceLoc& loc, const std::string& found) {
  parser.fail(loc,
              "expected " + std::string(type) + " for " + std::string(what) + ", found " + found);
}

Value value_param(Parser& parser, std::string_view type, std::string_view what) {
  const Token& token = parser.peek();
  if (token.kind == Token::Kind::end ||
      (token.kind == Token::Kind::symbol && (token.text == "}" || token.text == "{"))) {
    fail_expected(parser, type, what, token.loc, token_text(token));
  }
  return parser.parse_expression();
}

}  // namespace

double float_param(Parser& parser, std::string_view what) {
  const SourceLoc loc = parser.peek().loc;
  const Value value = value_param(parser, "a float", what);
  if (const double* number = value.get<double>()) return *number;
  fail_expected(parser, "a float", what, loc, type_name(value));
}

int int_param(Parser& parser, std::string_view what) {
  const SourceLoc loc = parser.peek().loc;
  const double number = float_param(parser, what);
  if (number != std::floor(number) || std::abs(number) > 2e9) {
    parser.fail(loc,
                "expected an integer for " + std::string(what) + ", found " + number_text(number));
  }
  return int(number);
}

Vec3 vector_param(Parser& parser, std::string_view what) {
  const SourceLoc loc = parser.peek().loc;
  const Value value = value_param(parser, "a vector", what);
  if (const double* number = value.get<double>()) return Vec3(*number);
  if (const Vector* vector = value.get<Vector>()) {
    if (!vector->color && vector->size <= 3) return vector->xyz();
    if (vector->size > 3) {
      parser.fail(loc, "expected a 3-D vector for " + std::string(what) + ", found a " +
                           std::to_string(vector->size) + "-D vector");
    }
  }
  fail_expected(parser, "a vector", what, loc, type_name(value));
}

scene::Color color_param(Parser& parser) {
  if (!accept_word(parser, "color")) accept_word(parser, "colour");
  return parser.parse_color();
}

Vec3 rgb_param(Parser& parser, std::string_view what) {
  static constexpr std::string_view kColorWords[] = {
      "color",  "colour", "rgb",   "rgbf", "rgbt",   "rgbft",    "srgb", "srgbf", "srgbt",
      "srgbft", "red",    "green", "blue", "filter", "transmit", "gray", "grey"};
  if (at_any_word(parser, kColorWords)) return color_param(parser).rgb;
  const SourceLoc loc = parser.peek().loc;
  const Value value = value_param(parser, "a float or color", what);
  if (const double* number = value.get<double>()) return Vec3(*number);
  if (const Vector* vector = value.get<Vector>()) return vector->xyz();
  fail_expected(parser, "a float or color", what, loc, type_name(value));
}

bool at_float_start(Parser& parser) {
  const Token& token = parser.peek();
  switch (token.kind) {
    case Token::Kind::number:
      return true;
    case Token::Kind::symbol:
      return token.text == "(" || token.text == "-" || token.text == "+" || token.text == "!";
    case Token::Kind::keyword:
    case Token::Kind::identifier: {
      if (const Value* declared = parser.peek_declared()) return declared->get<double>();
      return std::find(std::begin(kFloatWords), std::end(kFloatWords), token.text) !=
             std::end(kFloatWords);
    }
    default:
      return false;
  }
}

bool optional_bool(Parser& parser) {
  if (accept_word(parser, "on") || accept_word(parser, "true") || accept_word(parser, "yes"))
    return true;
  if (accept_word(parser, "off") || accept_word(parser, "false") || accept_word(parser, "no"))
    return false;
  if (at_float_start(parser)) return float_param(parser, "the flag") != 0.0;
  return true;
}

void skip_braced(Parser& parser, std::string_view name, const SourceLoc& keyword_loc) {
  parser.expect("{", name);
  int depth = 1;
  while (depth > 0) {
    const Token token = parser.next();
    if (token.kind == Token::Kind::end) {
      parser.fail(token.loc, "missing '}' to close the " + std::string(name) + " opened at " +
                                 keyword_loc.str());
    }
    if (token.kind != Token::Kind::symbol) continue;
    if (token.text == "{") ++depth;
    if (token.text == "}") --depth;
  }
}

const std::string_view kTransformWords[5] = {"translate", "rotate", "scale", "matrix", "transform"};

namespace {

scene::Transform parse_scale(Parser& parser, const SourceLoc& loc) {
  Vec3 factors = vector_param(parser, "scale");
  for (int axis = 0; axis < 3; ++axis) {
    if (factors[axis] == 0.0) {
      // POV-Ray's rule: a zero factor would flatten the object; it is replaced by 1.
      parser.warn(loc, std::string("scale by 0 along ") + "xyz"[axis] + " changed to 1");
      factors[axis] = 1.0;
    }
  }
  return scene::Transform::scaling(factors);
}

scene::Transform parse_matrix(Parser& parser, const SourceLoc& loc) {
  parser.expect("<", "matrix");
  std::array<double, 12> m{};
  for (size_t k = 0; k < m.size(); ++k) {
    if (k > 0) parser.expect(",", "matrix (it has 12 values)");
    // The last value may be any expression (`CamL.z` in screen.inc): a '>' after it ends
    // the matrix instead of comparing, as in POV-Ray.
    m[k] = k + 1 < m.size() ? float_param(parser, "matrix element " + std::to_string(k + 1))
                            : parser.parse_float_in_angle_brackets();
  }
  parser.expect(">", "matrix (it has 12 values)");
  try {
    return scene::Transform::matrix(m);
  } catch (const std::invalid_argument&) {
    parser.fail(loc, "matrix is singular: it flattens space, so it has no inverse");
  }
}

}  // namespace

std::optional<scene::Transform> parse_transform_modifier(Parser& parser, SourceLoc* keyword_loc) {
  if (!at_any_word(parser, kTransformWords)) return std::nullopt;
  const SourceLoc loc = parser.peek().loc;
  if (keyword_loc) *keyword_loc = loc;
  if (at_word(parser, "transform")) return parse_transform_block(parser);
  const std::string word = parser.next().text;
  if (word == "translate") return scene::Transform::translation(vector_param(parser, "translate"));
  if (word == "rotate") return scene::Transform::rotation(vector_param(parser, "rotate"));
  if (word == "scale") return parse_scale(parser, loc);
  return parse_matrix(parser, loc);
}

namespace {

// A declared transform, if the next token names one (consumed).
std::optional<scene::Transform> declared_transform(Parser& parser) {
  const Value* declared = parser.peek_declared();
  if (!declared) return std::nullopt;
  const auto* transform = declared->get<std::shared_ptr<const scene::Transform>>();
  if (!transform) {
    parser.fail_here("expected a transform, found " + parser.peek().text + " (" +
                     type_name(*declared) + ")");
  }
  scene::Transform result = **transform;
  parser.next();
  return result;
}

}  // namespace

scene::Transform parse_transform_block(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  if (!parser.at("{")) {
    if (auto named = declared_transform(parser)) return *named;
    parser.fail_here("expected '{' or a declared transform after 'transform'");
  }
  static constexpr std::string_view kWords[] = {"translate", "rotate",    "scale",
                                                "matrix",    "transform", "inverse"};
  Block block(parser, "transform", loc);
  scene::Transform result;
  while (block.more()) {
    if (auto step = parse_transform_modifier(parser)) {
      result = result.then(*step);
    } else if (accept_word(parser, "inverse")) {
      result = result.inverse();
    } else if (auto named = declared_transform(parser)) {
      result = result.then(*named);
    } else {
      block.unexpected(kWords);
    }
  }
  return result;
}

void warn_once(Parser& parser, const SourceLoc& loc, const std::string& message) {
  const std::string text = message + " (reported once)";
  for (const std::string& warning : parser.warnings()) {
    if (warning.find(text) != std::string::npos) return;
  }
  parser.warn(loc, text);
}

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace convray::sdl::items
