// The expression grammar, evaluated as it is parsed (as POV-Ray does). From loosest to
// tightest: `?:`, `|`, `&`, comparisons `< <= = != >= >`, `+ -`, `* /`, unary `- + !`,
// postfix `.x` `[i]` and colour modifiers, then primaries: numbers, strings, `( )`,
// `< >` vectors, identifiers, constants, colours and function calls.
#include <cmath>
#include <limits>
#include <string>

#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

// "expected a float as the condition, found a vector".
std::string expected_message(const char* wanted, std::string_view what, const Value& found) {
  std::string message = "expected ";
  message += wanted;
  if (!what.empty()) {
    message += ' ';
    message += what;
  }
  message += ", found ";
  message += type_name(found);
  return message;
}

// Whether `t` can start an expression (to tell a missing ',' from a stray token).
bool starts_value(const LexToken& t) {
  switch (t.kind) {
    case LexKind::number:
    case LexKind::string:
    case LexKind::identifier:
      return true;
    case LexKind::symbol:
      return t.symbol == '(' || t.symbol == '<' || t.symbol == '-' || t.symbol == '+' ||
             t.symbol == '!';
    case LexKind::keyword:
      return t.word != Word::other;
    default:
      return false;
  }
}

}  // namespace

Value Parser::Impl::parse_expression() {
  NestingLevel level(*this);
  return parse_ternary();
}

Value Parser::Impl::parse_ternary() {
  Value condition = parse_binary(1);
  if (!plain_symbol('?')) return condition;
  const TokenRef at = ref();
  advance();
  const bool chosen = is_true(to_float(condition, at, "before '?'"));
  // Both branches are parsed (POV-Ray evaluates as it reads); the one not chosen may divide
  // by zero without failing: `(N = 0 ? 0 : 1 / N)`.
  Value when_true, when_false;
  {
    ScopedValue quiet(quiet_math, quiet_math + (chosen ? 0 : 1));
    when_true = parse_expression();
  }
  expect_symbol(':', "in the conditional expression 'a ? b : c'");
  {
    ScopedValue quiet(quiet_math, quiet_math + (chosen ? 1 : 0));
    when_false = parse_expression();
  }
  return chosen ? std::move(when_true) : std::move(when_false);
}

int Parser::Impl::binary_precedence(const LexToken& t) const {
  if (t.kind != LexKind::symbol) return 0;
  switch (t.symbol) {
    case '|':
      return 1;
    case '&':
      return 2;
    // Before a list of points written without a comma, a '<' starts the first point.
    case '<':
    case kLessEqual:
      return less_starts_vector > 0 ? 0 : 3;
    case '=':
    case kNotEqual:
      return 3;
    // Directly inside < >, a '>' ends the vector: comparisons need parentheses there.
    case '>':
    case kGreaterEqual:
      return angle_depth > 0 ? 0 : 3;
    case '+':
    case '-':
      return 4;
    case '*':
    case '/':
      return 5;
    default:
      return 0;
  }
}

Value Parser::Impl::parse_binary(int min_precedence) {
  // Precedence climbing: recursion only goes up the five levels, never along a chain.
  Value left = parse_unary();
  for (;;) {
    const LexToken& op = lookahead();
    const int precedence = binary_precedence(op);
    if (precedence == 0 || precedence < min_precedence) return left;
    // POV-Ray compares only floats: after a vector, '<' starts the next vector, as in
    // `box { <0, 0, 0> <1, 1, 1> }` (commas are optional).
    if (precedence == 3 && left.get<double>() == nullptr) return left;
    const TokenRef at = ref();
    const char symbol = op.symbol;
    advance();
    Value right;
    if (symbol == '&' || symbol == '|') {
      // When the left side decides, the right side's math errors do not count.
      const bool left_true = is_true(to_float(left, at, std::string("before '") + symbol + "'"));
      const bool decided = symbol == '&' ? !left_true : left_true;
      ScopedValue quiet(quiet_math, quiet_math + (decided ? 1 : 0));
      right = parse_binary(precedence + 1);
    } else {
      right = parse_binary(precedence + 1);
    }
    left = apply_binary(symbol, left, right, at);
  }
}

Value Parser::Impl::parse_unary() {
  // Every operand passes here: the nesting count bounds all recursion through operands
  // (`rgb rgb rgb ...` included). Prefix operators are collected in a loop, not by
  // recursion: "- - - - 1" from a fuzzer must not grow the stack.
  NestingLevel level(*this);
  struct Prefix {
    char op;
    TokenRef at;
  };
  std::vector<Prefix> prefixes;
  for (;;) {
    const LexToken& t = settle();
    if (!(is_symbol(t, '-') || is_symbol(t, '+') || is_symbol(t, '!'))) break;
    prefixes.push_back({t.symbol, ref()});
    advance();
  }
  Value value = parse_postfix();
  for (auto prefix = prefixes.rbegin(); prefix != prefixes.rend(); ++prefix) {
    value = apply_unary(prefix->op, value, prefix->at);
  }
  return value;
}

Value Parser::Impl::parse_postfix() {
  Value value = parse_primary();
  for (;;) {
    const LexToken& t = lookahead();
    if (is_symbol(t, '.')) {
      const TokenRef dot = ref();
      advance();
      value = parse_component(value, dot);
    } else if (is_symbol(t, '[') && value.get<std::shared_ptr<Array>>() != nullptr) {
      value = index_array(value, ref(), {});
    } else if (is_color_modifier(t) && value.get<Vector>() != nullptr &&
               value.get<Vector>()->color) {
      value = apply_color_modifiers(std::move(value));
    } else {
      return value;
    }
  }
}

Value Parser::Impl::parse_component(const Value& value, TokenRef dot) {
  const LexToken& name = plain();
  int index = -1;
  bool gray = false;
  switch (name.word) {
    case Word::x:
    case Word::u:
    case Word::red:
      index = 0;
      break;
    case Word::y:
    case Word::v:
    case Word::green:
      index = 1;
      break;
    case Word::z:
    case Word::blue:
      index = 2;
      break;
    case Word::t:
    case Word::filter:
      index = 3;
      break;
    case Word::transmit:
      index = 4;
      break;
    case Word::gray:
    case Word::grey:
      gray = true;
      break;
    default:
      fail_here(
          "expected a component after '.' (x, y, z, t, u, v, red, green, blue, filter, "
          "transmit, gray), found " +
          describe(name));
  }
  advance();
  // A float stands for a vector of that float in every component, as POV-Ray promotes it.
  if (const double* f = value.get<double>()) {
    return make_value(gray ? *f * (0.297 + 0.589 + 0.114) : *f);
  }
  const Vector* vector = value.get<Vector>();
  if (vector == nullptr) {
    fail(dot, "'.' needs a vector or a colour, found " + type_name(value));
  }
  if (gray) {
    // POV-Ray's luminance weights for `.gray`.
    return make_value(0.297 * vector->v[0] + 0.589 * vector->v[1] + 0.114 * vector->v[2]);
  }
  return make_value(vector->v[size_t(index)]);  // components past the size are 0
}

Value Parser::Impl::parse_primary() {
  const LexToken& t = settle();
  switch (t.kind) {
    case LexKind::number: {
      const double number = t.number;
      advance();
      return make_value(number);
    }
    case LexKind::string: {
      std::string text(t.view());
      advance();
      return make_value(std::move(text));
    }
    case LexKind::symbol:
      if (t.symbol == '(') return parse_parenthesized();
      if (t.symbol == '<') return parse_vector_literal();
      break;
    case LexKind::identifier:
      return parse_identifier();
    case LexKind::keyword:
      return parse_keyword();
    default:
      break;
  }
  fail_here("expected a value (a number, vector, colour, string or identifier), found " +
            describe(t));
}

Value Parser::Impl::parse_parenthesized() {
  const TokenRef open = ref();
  advance();
  ScopedValue not_in_vector(angle_depth, 0);
  ScopedValue compare_again(less_starts_vector, 0);
  Value value = parse_expression();
  const LexToken& t = settle();
  if (!is_symbol(t, ')')) {
    fail_here("expected ')' to close the '(' at " + std::to_string(open.token->line) + ":" +
              std::to_string(open.token->column) + ", found " + describe(t));
  }
  advance();
  return value;
}

Value Parser::Impl::parse_vector_literal() {
  const TokenRef open = ref();
  advance();
  ScopedValue in_vector(angle_depth, 1);
  Vector vector;
  vector.size = 0;
  for (;;) {
    const TokenRef at = ref();
    const Value component = parse_expression();
    if (vector.size == 5) fail(at, "a vector has at most 5 components");
    vector.v[size_t(vector.size++)] = to_float(component, at, "as a vector component");
    // POV-Ray's commas between components are optional: `< -1 0 0 >` (woods.inc).
    if (is_symbol(settle(), ',')) advance();
    const LexToken& t = settle();
    if (is_symbol(t, '>')) {
      advance();
      break;
    }
    if (!starts_value(t)) {
      fail_here("expected ',' or '>' in the vector opened at " + std::to_string(open.token->line) +
                ":" + std::to_string(open.token->column) + ", found " + describe(t));
    }
  }
  if (vector.size < 2) fail(open, "a vector needs at least 2 components");
  return make_value(vector);
}

Value Parser::Impl::parse_identifier() {
  const LexToken& t = settle();
  const std::string_view name = t.view();
  const TokenRef at = ref();
  if (const Value* value = lookup(name)) {
    if (!deprecations.empty()) check_deprecated(name, at);
    if (const std::string* text = value->get<std::string>()) charge(text->size() / kBytesPerToken);
    check_usable(*value, name, at);
    Value copy = *value;
    advance();
    if (!copy.is_set()) fail(at, quoted(name) + " has no value");
    // Indexing here rather than in parse_postfix, so that messages name the array.
    if (copy.get<std::shared_ptr<Array>>() != nullptr && plain_symbol('[')) {
      Value element = index_array(copy, ref(), name);
      check_usable(element, name, at);
      return element;
    }
    return copy;
  }
  if (const auto function = functions.find(name); function != functions.end()) {
    const std::shared_ptr<const UserFunction> called = function->second;
    advance();
    return call_function(*called, at);
  }
  fail(at, "undeclared identifier '" + std::string(name) + "'" + did_you_mean(name));
}

Value Parser::Impl::parse_keyword() {
  const LexToken& t = settle();
  const TokenRef at = ref();
  const auto constant = [&](Value value) {
    advance();
    return value;
  };
  const auto axis = [&](int size, int index) {
    Vector vector;
    vector.size = size;
    vector.v[size_t(index)] = 1.0;
    return constant(make_value(vector));
  };
  // Colour keywords and component modifiers (colors.cpp knows which they are).
  if (is_color_keyword(t)) return parse_color_group();
  switch (t.word) {
    case Word::pi:
      return constant(make_value(kPi));
    case Word::tau:
      return constant(make_value(2.0 * kPi));
    case Word::true_:
    case Word::yes:
    case Word::on:
      return constant(make_value(1.0));
    case Word::false_:
    case Word::no:
    case Word::off:
      return constant(make_value(0.0));
    case Word::x:
      return axis(3, 0);
    case Word::y:
      return axis(3, 1);
    case Word::z:
      return axis(3, 2);
    case Word::t:
      return axis(4, 3);
    case Word::u:
      return axis(2, 0);
    case Word::v:
      return axis(2, 1);
    case Word::clock:
      return constant(make_value(options.clock));
    case Word::clock_delta:
      return constant(make_value(options.clock_delta));
    case Word::clock_on:
      return constant(make_value(options.clock_on ? 1.0 : 0.0));
    case Word::frame_number:
      return constant(make_value(double(options.frame_number)));
    case Word::initial_frame:
      return constant(make_value(double(options.initial_frame)));
    case Word::final_frame:
      return constant(make_value(double(options.final_frame)));
    case Word::initial_clock:
      return constant(make_value(options.initial_clock));
    case Word::final_clock:
      return constant(make_value(options.final_clock));
    case Word::image_width:
      return constant(make_value(double(options.image_width)));
    case Word::image_height:
      return constant(make_value(double(options.image_height)));
    case Word::version:
      return constant(make_value(language_version));
    case Word::input_file_name:
      return constant(make_value(files.front()->name));
    case Word::internal:
      fail(at, "'internal' can only be the body of a function: function { internal(N) }");
    case Word::array:
      fail(at, "an array can only be declared: #declare Name = array[N]");
    case Word::function:
      fail(at, "a function can only be declared: #declare Name = function (x) { ... }");
    case Word::none:
    case Word::other:
      break;
    default:
      if (t.word >= Word::abs && t.word <= Word::vstr) return call_builtin(t, at);
      break;
  }
  // POV-Ray's functions of objects and patterns.
  if (t.view() == "trace" || t.view() == "min_extent" || t.view() == "max_extent") {
    return call_object_function(t, at);
  }
  for (std::string_view unsupported : {"inside", "vturbulence", "eval_pigment"}) {
    if (t.view() == unsupported) {
      fail_unsupported(loc(at), quoted(unsupported) + " is not supported yet by convray");
    }
  }
  fail(at, "expected a value, found " + describe(t));
}

std::vector<Value> Parser::Impl::parse_arguments(const LexToken& name, std::size_t min,
                                                 std::size_t max) {
  const std::string function(name.view());
  expect_symbol('(', "after '" + function + "'");
  ScopedValue not_in_vector(angle_depth, 0);
  std::vector<Value> arguments;
  if (!accept_symbol(')')) {
    for (;;) {
      if (arguments.size() == max) {
        fail_here("too many arguments: '" + function + "' takes " + (min == max ? "" : "at most ") +
                  std::to_string(max));
      }
      arguments.push_back(parse_expression());
      if (accept_symbol(',')) continue;
      expect_symbol(')', "after the arguments of '" + function + "'");
      break;
    }
  }
  if (arguments.size() < min) {
    fail_here("too few arguments: '" + function + "' takes " + (min == max ? "" : "at least ") +
              std::to_string(min) + ", found " + std::to_string(arguments.size()));
  }
  return arguments;
}

double Parser::Impl::to_float(const Value& v, TokenRef at, std::string_view what) const {
  if (const double* f = v.get<double>()) return *f;
  fail(at, expected_message("a float", what, v));
}

Vector Parser::Impl::to_vector(const Value& v, TokenRef at, std::string_view what) const {
  if (const Vector* vector = v.get<Vector>()) return *vector;
  if (const double* f = v.get<double>()) {
    Vector promoted;
    promoted.v = {*f, *f, *f, 0.0, 0.0};
    return promoted;
  }
  fail(at, expected_message("a vector", what, v));
}

const std::string& Parser::Impl::to_string(const Value& v, TokenRef at,
                                           std::string_view what) const {
  if (const std::string* s = v.get<std::string>()) return *s;
  fail(at, expected_message("a string", what, v));
}

int Parser::Impl::to_int(double v, TokenRef at, std::string_view what) const {
  // POV-Ray truncates; a value a rounding error below an integer counts as that integer.
  const double rounded = std::round(v);
  const double value = std::abs(v - rounded) < 1e-9 ? rounded : std::trunc(v);
  if (!(std::abs(value) <= double(std::numeric_limits<int>::max()))) {
    std::string message = "integer out of range";
    if (!what.empty()) {
      message += ' ';
      message += what;
    }
    fail(at, message + ": " + number_text(v));
  }
  return int(value);
}

}  // namespace convray::sdl
