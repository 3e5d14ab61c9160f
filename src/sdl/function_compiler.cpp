// Compiling a function body (`function (a, b) { expression }`) into a scene::Function, once,
// where it is declared. The grammar is POV-Ray's expression grammar restricted to floats, with
// the same precedence as sdl/expressions.cpp: `?:`, `|`, `&`, comparisons, `+ -`, `* /`, unary
// `- + !`, primaries. An identifier declared outside the body is read as a number now, as
// POV-Ray does; a parameter reads the argument when the function is evaluated. Constant
// subexpressions are folded.
#include <cmath>
#include <string>

#include "scene/color_sources.hpp"
#include "sdl/diagnostics.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {

namespace {

double degrees_of(double v) { return v * 180.0 / kPi; }
double radians_of(double v) { return v * kPi / 180.0; }
double square(double v) { return v * v; }
double trunc_div(double a, double b) { return std::trunc(a / b); }
double abs_of(double v) { return std::abs(v); }

// The one-argument built-ins, as functions.cpp evaluates them at parse time.
double (*math1_of(Word word))(double) {
  switch (word) {
    case Word::abs: return abs_of;
    case Word::acos: return static_cast<double (*)(double)>(std::acos);
    case Word::asin: return static_cast<double (*)(double)>(std::asin);
    case Word::acosh: return static_cast<double (*)(double)>(std::acosh);
    case Word::asinh: return static_cast<double (*)(double)>(std::asinh);
    case Word::atanh: return static_cast<double (*)(double)>(std::atanh);
    case Word::atan: return static_cast<double (*)(double)>(std::atan);
    case Word::ceil: return static_cast<double (*)(double)>(std::ceil);
    case Word::floor: return static_cast<double (*)(double)>(std::floor);
    case Word::int_: return static_cast<double (*)(double)>(std::trunc);
    case Word::cos: return static_cast<double (*)(double)>(std::cos);
    case Word::sin: return static_cast<double (*)(double)>(std::sin);
    case Word::tan: return static_cast<double (*)(double)>(std::tan);
    case Word::cosh: return static_cast<double (*)(double)>(std::cosh);
    case Word::sinh: return static_cast<double (*)(double)>(std::sinh);
    case Word::tanh: return static_cast<double (*)(double)>(std::tanh);
    case Word::degrees: return degrees_of;
    case Word::radians: return radians_of;
    case Word::exp: return static_cast<double (*)(double)>(std::exp);
    case Word::ln: return static_cast<double (*)(double)>(std::log);
    case Word::log: return static_cast<double (*)(double)>(std::log10);
    case Word::sqrt: return static_cast<double (*)(double)>(std::sqrt);
    case Word::sqr: return square;
    default: return nullptr;
  }
}

double (*math2_of(Word word))(double, double) {
  switch (word) {
    case Word::atan2:
    case Word::atan: return static_cast<double (*)(double, double)>(std::atan2);
    case Word::pow: return static_cast<double (*)(double, double)>(std::pow);
    case Word::mod: return static_cast<double (*)(double, double)>(std::fmod);
    case Word::div: return trunc_div;
    default: return nullptr;
  }
}

using scene::FunctionNode;
using scene::FunctionOp;

class FunctionCompiler {
 public:
  FunctionCompiler(Parser::Impl& parser, scene::Function& function, const std::string& name)
      : p_(parser), f_(function), name_(name) {}

  std::uint32_t expression() {
    NestingLevel level(p_);
    const std::uint32_t condition = binary(1);
    if (!p_.plain_symbol('?')) return condition;
    p_.advance();
    const std::uint32_t when_true = expression();
    p_.expect_symbol(':', "in the conditional expression 'a ? b : c'");
    const std::uint32_t when_false = expression();
    return node(FunctionOp::conditional, {condition, when_true, when_false});
  }

 private:
  std::uint32_t node(FunctionOp op, std::initializer_list<std::uint32_t> operands) {
    FunctionNode n;
    n.op = op;
    return folded(f_.add(n, std::span(operands.begin(), operands.size())));
  }
  std::uint32_t folded(std::uint32_t index) {
    double value = 0.0;
    if (f_.node(index).op != FunctionOp::constant && f_.constant_value(index, value)) {
      return f_.add_constant(value);
    }
    return index;
  }

  static int precedence(const LexToken& t) {
    if (t.kind != LexKind::symbol) return 0;
    switch (t.symbol) {
      case '|': return 1;
      case '&': return 2;
      case '<': case '>': case '=': case kLessEqual: case kGreaterEqual: case kNotEqual: return 3;
      case '+': case '-': return 4;
      case '*': case '/': return 5;
      default: return 0;
    }
  }

  static FunctionOp binary_op(char symbol) {
    switch (symbol) {
      case '|': return FunctionOp::logical_or;
      case '&': return FunctionOp::logical_and;
      case '<': return FunctionOp::less;
      case '>': return FunctionOp::greater;
      case '=': return FunctionOp::equal;
      case kLessEqual: return FunctionOp::less_equal;
      case kGreaterEqual: return FunctionOp::greater_equal;
      case kNotEqual: return FunctionOp::not_equal;
      case '+': return FunctionOp::add;
      case '-': return FunctionOp::subtract;
      case '*': return FunctionOp::multiply;
      default: return FunctionOp::divide;
    }
  }

  std::uint32_t binary(int min_precedence) {
    std::uint32_t left = unary();
    for (;;) {
      const LexToken& op = p_.lookahead();
      const int level = precedence(op);
      if (level == 0 || level < min_precedence) return left;
      const char symbol = op.symbol;
      p_.advance();
      const std::uint32_t right = binary(level + 1);
      left = node(binary_op(symbol), {left, right});
    }
  }

  std::uint32_t unary() {
    NestingLevel level(p_);
    const LexToken& t = p_.settle();
    if (Parser::Impl::is_symbol(t, '-') || Parser::Impl::is_symbol(t, '+') ||
        Parser::Impl::is_symbol(t, '!')) {
      const char symbol = t.symbol;
      p_.advance();
      const std::uint32_t operand = unary();
      if (symbol == '+') return operand;
      return node(symbol == '-' ? FunctionOp::negate : FunctionOp::logical_not, {operand});
    }
    return primary();
  }

  std::uint32_t parameter_named(std::string_view name) {
    const auto& parameters = f_.parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      if (parameters[i] != name) continue;
      FunctionNode n;
      n.op = FunctionOp::parameter;
      n.index = std::uint32_t(i);
      return f_.add(n);
    }
    return UINT32_MAX;
  }

  std::uint32_t primary() {
    const LexToken& t = p_.settle();
    const TokenRef at = p_.ref();
    if (t.kind == LexKind::number) {
      const Value value = p_.parse_primary();
      return f_.add_constant(p_.to_float(value, at, ""));
    }
    if (Parser::Impl::is_symbol(t, '(')) {
      p_.advance();
      const std::uint32_t inside = expression();
      p_.expect_symbol(')', "to close the '(' in function '" + name_ + "'");
      return inside;
    }
    if (t.kind == LexKind::identifier || t.kind == LexKind::keyword) {
      if (const std::uint32_t parameter = parameter_named(t.view()); parameter != UINT32_MAX) {
        p_.advance();
        return parameter;
      }
    }
    if (t.kind == LexKind::identifier) return identifier(t, at);
    if (t.kind == LexKind::keyword) return keyword(t, at);
    p_.fail(at, "expected a value in function '" + name_ + "', found " + p_.describe(t));
  }

  std::uint32_t identifier(const LexToken& t, TokenRef at) {
    const std::string name(t.view());
    if (p_.lookup(name) == nullptr) {
      if (const auto found = p_.functions.find(name); found != p_.functions.end()) {
        const std::shared_ptr<const UserFunction> callee = found->second;
        p_.advance();
        return call(*callee, at);
      }
    }
    // A declared value (a float; a vector's component): read now.
    const Value value = p_.parse_postfix();
    if (const double* number = value.get<double>()) return f_.add_constant(*number);
    p_.fail(at, "a function can only use floats: '" + name + "' is " + type_name(value));
  }

  std::uint32_t call(const UserFunction& callee, TokenRef at) {
    if (callee.unsupported) {
      p_.fail_unsupported(p_.loc(at), callee.unsupported->feature + " (at " +
                                          callee.unsupported->feature_at.str() + "): " +
                                          quoted(callee.name) + ", declared at " +
                                          callee.loc.str() + ", needs it",
                          callee.unsupported->feature);
    }
    const std::vector<std::uint32_t> arguments = argument_list("function '" + callee.name + "'");
    const std::size_t wanted = callee.parameters.size();
    if (arguments.size() != wanted) {
      p_.fail(at, "function '" + callee.name + "' takes " + std::to_string(wanted) +
                      " argument" + (wanted == 1 ? "" : "s") + ", found " +
                      std::to_string(arguments.size()));
    }
    if (callee.color_source) return color_component(callee, arguments, at);
    if (p_.plain_symbol('.')) {
      p_.fail(p_.here(), "function '" + callee.name + "' gives a float: no '.' component");
    }
    FunctionNode n;
    n.op = FunctionOp::call;
    n.index = f_.add_callee(callee.compiled);
    return f_.add(n, arguments);
  }

  // `P(x, y, z).red` of a pigment function: a colour needs its component picked.
  std::uint32_t color_component(const UserFunction& callee,
                                const std::vector<std::uint32_t>& arguments, TokenRef at) {
    if (!p_.plain_symbol('.')) {
      p_.fail(at, "function '" + callee.name + "' gives a colour: pick a component with .red, "
                  ".green, .blue, .filter, .transmit, .gray (or .x, .y, .z)");
    }
    p_.advance();
    const LexToken& name = p_.plain();
    FunctionNode n;
    n.op = FunctionOp::color;
    switch (name.word) {
      case Word::x: case Word::u: case Word::red: n.component = scene::ColorComponent::red; break;
      case Word::y: case Word::v: case Word::green:
        n.component = scene::ColorComponent::green;
        break;
      case Word::z: case Word::blue: n.component = scene::ColorComponent::blue; break;
      case Word::t: case Word::filter: n.component = scene::ColorComponent::filter; break;
      case Word::transmit: n.component = scene::ColorComponent::transmit; break;
      case Word::gray: case Word::grey: n.component = scene::ColorComponent::gray; break;
      default:
        p_.fail_here("expected a colour component after '.', found " + p_.describe(name));
    }
    p_.advance();
    n.index = f_.add_color_source(callee.color_source);
    return f_.add(n, arguments);
  }

  std::vector<std::uint32_t> argument_list(const std::string& of) {
    p_.expect_symbol('(', "after " + of);
    ScopedValue not_in_vector(p_.angle_depth, 0);
    std::vector<std::uint32_t> arguments;
    if (p_.accept_symbol(')')) return arguments;
    for (;;) {
      if (arguments.size() == scene::Function::kMaxParameters) {
        p_.fail_here("too many arguments to " + of);
      }
      arguments.push_back(expression());
      if (p_.accept_symbol(',')) continue;
      p_.expect_symbol(')', "after the arguments of " + of);
      return arguments;
    }
  }

  std::uint32_t keyword(const LexToken& t, TokenRef at) {
    const Word word = t.word;
    const std::string text(t.view());
    if (word >= Word::abs && word <= Word::tanh) return builtin(word, text, at);
    if (word >= Word::pi && word <= Word::input_file_name &&
        !(word >= Word::x && word <= Word::v)) {
      const Value value = p_.parse_keyword();
      return f_.add_constant(p_.to_float(value, at, "in a function"));
    }
    if (word == Word::x || word == Word::y || word == Word::z || word == Word::u ||
        word == Word::v || word == Word::t) {
      p_.fail(at, "'" + text + "' is not a parameter of function '" + name_ + "'");
    }
    if (text == "pattern" || text == "pigment") {
      p_.fail(at, "'" + text + "' can only be the whole body of a function: "
                  "function { " + text + " { ... } }");
    }
    if (text == "spline" || text == "transform" || text == "internal") {
      p_.fail_unsupported(p_.loc(at), "'" + text + "' in a function is not supported yet by "
                                      "convray");
    }
    p_.fail(at, "expected a value in function '" + name_ + "', found " + p_.describe(t));
  }

  std::uint32_t builtin(Word word, const std::string& text, TokenRef at) {
    p_.advance();
    const std::vector<std::uint32_t> arguments = argument_list("'" + text + "'");
    const auto arity = [&](std::size_t low, std::size_t high) {
      if (arguments.size() < low || arguments.size() > high) {
        p_.fail(at, "'" + text + "' takes " +
                        (low == high ? std::to_string(low)
                                     : std::to_string(low) + " to " + std::to_string(high)) +
                        " arguments in a function, found " + std::to_string(arguments.size()));
      }
    };
    FunctionNode n;
    if (word == Word::min || word == Word::max) {
      arity(2, scene::Function::kMaxParameters);
      n.op = word == Word::min ? FunctionOp::minimum : FunctionOp::maximum;
    } else if (word == Word::select) {
      arity(3, 4);
      n.op = FunctionOp::select;
    } else if (word == Word::atan && arguments.size() == 2) {
      n.op = FunctionOp::math2;
      n.math2 = math2_of(word);
    } else if (auto* one = math1_of(word)) {
      arity(1, 1);
      n.op = FunctionOp::math1;
      n.math1 = one;
    } else if (auto* two = math2_of(word)) {
      arity(2, 2);
      n.op = FunctionOp::math2;
      n.math2 = two;
    } else {
      p_.fail(at, "'" + text + "' cannot be used in a function");
    }
    return folded(f_.add(n, arguments));
  }

  Parser::Impl& p_;
  scene::Function& f_;
  const std::string& name_;
};

// functions.inc's f_noise3d.
constexpr int kNoise3d = 76;

// f(x, y, z): the red channel (the grey of a pattern) of `source` at (x, y, z), or `component`.
std::shared_ptr<const scene::Function> color_source_function(
    std::shared_ptr<const scene::ColorSource> source,
    scene::ColorComponent component = scene::ColorComponent::red) {
  auto compiled = std::make_shared<scene::Function>(std::vector<std::string>{"x", "y", "z"});
  std::vector<std::uint32_t> operands;
  for (std::uint32_t i = 0; i < 3; ++i) {
    scene::FunctionNode n;
    n.op = scene::FunctionOp::parameter;
    n.index = i;
    operands.push_back(compiled->add(n));
  }
  scene::FunctionNode value;
  value.op = scene::FunctionOp::color;
  value.component = component;
  value.index = compiled->add_color_source(std::move(source));
  compiled->set_root(compiled->add(value, operands));
  return compiled;
}

}  // namespace

// The renderer's pigments, patterns and noise, as the program gave them (scene/color_sources.hpp).
const scene::ColorSources& Parser::Impl::color_sources(TokenRef at) {
  if (!options.color_sources) {
    fail_unsupported(loc(at), "functions of pigments, patterns and noise are not supported "
                              "without the renderer");
  }
  return *options.color_sources;
}

// At `internal ( N )`, the whole body of functions.inc's declarations.
void Parser::Impl::compile_internal(UserFunction& function) {
  const TokenRef at = ref();
  advance();  // internal
  expect_symbol('(', "after 'internal'");
  const TokenRef number_at = ref();
  const int number = to_int(to_float(parse_expression(), number_at, "in internal()"), number_at,
                            "in internal()");
  expect_symbol(')', "after internal(N)");
  if (number == kNoise3d) {
    function.parameters = {"x", "y", "z"};
    function.compiled = color_source_function(color_sources(at).noise());
    return;
  }
  scene::InternalFunction internal{};
  if (!scene::internal_function_of(number, internal)) {
    fail_unsupported(loc(at), "internal function " + std::to_string(number) + " ('" +
                                  function.name + "') is not supported yet by convray");
  }
  std::vector<std::string> parameters = {"x", "y", "z"};
  const int arity = scene::internal_function_arity(internal);
  for (int i = 3; i < arity; ++i) parameters.push_back("P" + std::to_string(i - 3));
  auto compiled = std::make_shared<scene::Function>(parameters);
  std::vector<std::uint32_t> operands;
  for (int i = 0; i < arity; ++i) {
    scene::FunctionNode n;
    n.op = scene::FunctionOp::parameter;
    n.index = std::uint32_t(i);
    operands.push_back(compiled->add(n));
  }
  scene::FunctionNode call;
  call.op = scene::FunctionOp::internal;
  call.internal_function = internal;
  compiled->set_root(compiled->add(call, operands));
  function.parameters = std::move(parameters);
  function.compiled = std::move(compiled);
}

// `function { pigment { P } }` and `function { pattern { P } }`, of x, y and z.
void Parser::Impl::compile_color_function(UserFunction& function) {
  const TokenRef at = ref();
  const bool pigment = settle().view() == "pigment";
  const scene::Pigment read = items::parse_pigment(owner, {});
  function.parameters = {"x", "y", "z"};
  if (pigment) {
    function.color_source = color_sources(at).pigment(read);
  } else {
    function.compiled = color_source_function(color_sources(at).pattern(read.space));
  }
}

void Parser::Impl::compile_function(UserFunction& function) {
  const LexToken& first = settle();
  if (first.word == Word::internal) {
    compile_internal(function);
    return;
  }
  if (first.view() == "pigment" || first.view() == "pattern") {
    compile_color_function(function);
    return;
  }
  auto compiled = std::make_shared<scene::Function>(function.parameters);
  FunctionCompiler compiler(*this, *compiled, function.name);
  compiled->set_root(compiler.expression());
  function.compiled = std::move(compiled);
}

std::shared_ptr<const scene::Function> Parser::parse_pigment_pattern() {
  Parser::Impl& impl = *impl_;
  const TokenRef at = impl.ref();
  // POV-Ray's pigment_pattern is the grey (0.297 R + 0.589 G + 0.114 B) of the pigment,
  // filter and transmit aside (measured with #debug), clipped to [0, 1] as any pattern.
  const scene::Pigment read = items::parse_pigment(*this, {});
  return color_source_function(impl.color_sources(at).pigment(read), scene::ColorComponent::gray);
}

std::shared_ptr<const scene::Function> Parser::parse_function_block() {
  Parser::Impl& impl = *impl_;
  const TokenRef at = impl.ref();
  if (impl.settle().word != Word::function) {
    impl.fail_here("expected 'function { ... }', found " + impl.describe(impl.settle()));
  }
  impl.advance();
  UserFunction function;
  function.name = "function";
  function.loc = impl.loc(at);
  function.parameters = {"x", "y", "z"};
  if (!impl.plain_symbol('{')) {
    impl.fail_here("expected '{' after 'function', found " + impl.describe(impl.plain()));
  }
  impl.compile_function_body(function);
  if (function.unsupported) {
    impl.fail_unsupported(function.unsupported->feature_at, function.unsupported->feature);
  }
  return function.compiled;
}

}  // namespace convray::sdl
