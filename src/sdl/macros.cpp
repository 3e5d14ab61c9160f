// Macros and user functions.
//
// A macro body is a range of the defining file's tokens, replayed in a new frame when the
// macro is called; its parameters are #local values of a new scope, so #local inside the
// body is local to the call. As in POV-Ray, an argument that is a bare identifier or array
// element (`M(A)`, `M(Arr[i])`) is passed by reference: the parameter is an Alias of the
// caller's variable, which #declare and #local of the parameter assign; any other expression
// is passed by value. A parameter marked `optional` may be left out; it is then not declared
// in the body (test it with #ifdef).
//
// `#declare F = function (a, b) { expression }` is compiled where it is declared
// (function_compiler.cpp); a call F(1, 2) evaluates the compiled function. Without a parameter
// list the parameters are x, y, z.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {

namespace {

// An object, texture, pigment, ...: a value that is not a number, vector, string or array.
bool is_scene_item(const Value& value) {
  return value.is_set() && !value.get<double>() && !value.get<Vector>() &&
         !value.get<std::string>() && !value.get<std::shared_ptr<Array>>();
}

}  // namespace
void Parser::Impl::directive_macro(TokenRef at) {
  auto macro = std::make_shared<Macro>();
  macro->name = std::string(expect_identifier_raw("after #macro"));
  macro->loc = loc(at);
  if (!plain_symbol('(')) {
    fail_here("expected '(' after '#macro " + macro->name + "', found " + describe(plain()));
  }
  advance();
  while (!plain_symbol(')')) {
    MacroParameter parameter;
    if (plain().word == Word::optional) {
      parameter.optional = true;
      advance();
    }
    parameter.name =
        std::string(expect_identifier_raw("as a parameter of macro '" + macro->name + "'"));
    for (const MacroParameter& other : macro->parameters) {
      if (other.name == parameter.name) {
        fail_here("parameter '" + parameter.name + "' appears twice in macro '" + macro->name +
                  "'");
      }
    }
    macro->parameters.push_back(std::move(parameter));
    if (plain_symbol(',')) {
      advance();
    } else if (!plain_symbol(')')) {
      fail_here("expected ',' or ')' in the parameters of macro '" + macro->name + "', found " +
                describe(plain()));
    }
  }
  advance();  // ')'
  Frame& frame = frames.back();
  macro->file = frame.file;
  macro->body_begin = frame.pos;
  const auto opened_at = std::uint32_t(at.token - frame.file->tokens.data());
  skip(0, SkipStop::end, opened_at);
  macro->body_end = frames.back().pos - 1;  // the #end
  // A name is one thing: the macro replaces a global variable or function of that name.
  scopes.front().values.erase(macro->name);
  functions.erase(macro->name);
  macros[macro->name] = std::move(macro);
}

bool Parser::Impl::expand_if_macro(const LexToken& name) {
  const auto found = macros.find(name.view());
  if (found == macros.end()) return false;
  if (lookup(name.view()) != nullptr) return false;  // a local of that name hides the macro
  const std::shared_ptr<const Macro> macro = found->second;
  const TokenRef at = ref();
  advance();
  call_macro(macro, at);
  return true;
}

void Parser::Impl::call_macro(std::shared_ptr<const Macro> macro, TokenRef at) {
  const std::string& name = macro->name;
  const std::size_t wanted = macro->parameters.size();
  const auto arity_error = [&](std::size_t found) {
    return "macro '" + name + "' (defined at " + macro->loc.str() + ") takes " +
           std::to_string(wanted) + " argument" + (wanted == 1 ? "" : "s") + ", found " +
           std::to_string(found);
  };
  NestingLevel level(*this);  // arguments may call macros: M(M(M(...)))
  expect_symbol('(', "after the macro name '" + name + "'");
  std::vector<Value> arguments(wanted);
  std::vector<std::optional<Alias>> references(wanted);
  std::size_t count = 0;
  if (!accept_symbol(')')) {
    ScopedValue not_in_vector(angle_depth, 0);
    for (;;) {
      const TokenRef argument_at = ref();
      const bool empty = at_symbol(',') || at_symbol(')');
      if (count == wanted) {
        // Count the rest for the message.
        std::size_t found = count + 1;
        if (!empty) parse_rvalue();
        while (accept_symbol(',')) {
          ++found;
          if (!at_symbol(',') && !at_symbol(')')) parse_rvalue();
        }
        fail(argument_at, arity_error(found));
      }
      if (empty) {
        if (!macro->parameters[count].optional) {
          fail(argument_at,
               "missing argument '" + macro->parameters[count].name + "' of macro '" + name + "'");
        }
      } else {
        references[count] = parse_reference_argument();
        if (!references[count]) arguments[count] = parse_rvalue();
      }
      ++count;
      if (accept_symbol(',')) continue;
      // POV-Ray reads the next argument without a comma after an item, which no operator can
      // continue (incdemo/shapes.pov: `Align_Object(Center_Object(...) -y, ...)`).
      if (!at_symbol(')') && count < wanted && is_scene_item(arguments[count - 1])) continue;
      expect_symbol(')', "after the arguments of macro '" + name + "'");
      break;
    }
  }
  for (std::size_t i = count; i < wanted; ++i) {
    if (!macro->parameters[i].optional) fail(at, arity_error(count));
  }
  if (macro_depth >= options.max_macro_depth) {
    fail(at, "macro '" + name + "' called more than " + std::to_string(options.max_macro_depth) +
                 " levels deep: runaway recursion?");
  }
  const std::uint64_t scope = push_scope();
  for (std::size_t i = 0; i < wanted; ++i) {
    if (references[i]) {
      scopes.back().aliases.insert_or_assign(macro->parameters[i].name, std::move(*references[i]));
    } else if (arguments[i].is_set()) {
      scopes.back().values.insert_or_assign(macro->parameters[i].name, std::move(arguments[i]));
    }
  }
  Frame& frame = push_frame(Frame::Kind::macro, macro->file, macro->body_begin, macro->body_end);
  frame.scope = scope;
  frame.name = name;
  ++macro_depth;
}

// At a bare identifier or array element that ends the argument (`A,`, `A)`, `A[i][j])`):
// decided on the tokens alone, before anything is evaluated.
bool Parser::Impl::reference_argument_ahead() const {
  const Frame& frame = frames.back();
  const auto& tokens = frame.file->tokens;
  if (frame.pos >= frame.end || tokens[frame.pos].kind != LexKind::identifier) return false;
  std::uint32_t i = frame.pos + 1;
  while (i < frame.end && is_symbol(tokens[i], '[')) {
    int depth = 0;
    for (; i < frame.end; ++i) {
      if (tokens[i].kind == LexKind::directive) return false;  // too clever: by value
      if (is_symbol(tokens[i], '[')) ++depth;
      if (is_symbol(tokens[i], ']') && --depth == 0) break;
    }
    ++i;
  }
  return i < frame.end && (is_symbol(tokens[i], ',') || is_symbol(tokens[i], ')'));
}

// A macro argument passed by reference, read; nullopt (nothing read) for one passed by value.
// An undeclared identifier or unset element is left to parse_rvalue(), whose error POV-Ray
// gives too ("Cannot pass uninitialized identifier").
std::optional<Alias> Parser::Impl::parse_reference_argument() {
  const LexToken& t = settle();  // runs directives, expands a macro call
  const Frame& frame = frames.back();
  if (frame.pos >= frame.end || &t != &frame.file->tokens[frame.pos]) return std::nullopt;
  if (!reference_argument_ahead()) return std::nullopt;
  const std::string name(t.view());
  std::optional<Alias> alias = alias_of(name);
  const Value* value = alias ? resolve(*alias) : nullptr;
  if (value == nullptr || !value->is_set()) return std::nullopt;
  const bool element = frame.pos + 1 < frame.end && is_symbol(frame.file->tokens[frame.pos + 1], '[');
  if (element && value->get<std::shared_ptr<Array>>() == nullptr) return std::nullopt;
  const TokenRef at = ref();
  advance();
  if (element) {
    const Value root = *value;  // the path is read before anything changes the variable
    for (const std::size_t flat : parse_element_path(root, name)) alias->element.push_back(flat);
    const Value* target = resolve(*alias);
    if (target == nullptr || !target->is_set()) {
      fail(at, "an element of " + quoted(name) + " is read before it was given a value");
    }
  }
  return alias;
}

std::uint32_t Parser::Impl::find_closing_brace(std::uint32_t opened_at) {
  const Frame& frame = frames.back();
  int depth = 0;
  for (std::uint32_t i = opened_at; i < frame.end; ++i) {
    const LexToken& t = frame.file->tokens[i];
    if (is_symbol(t, '{')) ++depth;
    if (is_symbol(t, '}') && --depth == 0) return i;
  }
  fail(token_loc(frame.file, opened_at), "this '{' is never closed");
}

void Parser::Impl::declare_function(const std::string& name) {
  const TokenRef at = ref();
  advance();  // function
  auto function = std::make_shared<UserFunction>();
  function->name = name;
  function->loc = loc(at);
  if (plain_symbol('(')) {
    advance();
    while (!plain_symbol(')')) {
      const LexToken& t = plain();
      if (t.kind != LexKind::identifier && t.kind != LexKind::keyword) {
        fail_here("expected a parameter name in function '" + name + "', found " + describe(t));
      }
      function->parameters.emplace_back(t.view());
      advance();
      if (plain_symbol(',')) {
        advance();
      } else if (!plain_symbol(')')) {
        fail_here("expected ',' or ')' in the parameters of function '" + name + "', found " +
                  describe(plain()));
      }
    }
    advance();
    if (function->parameters.size() > scene::Function::kMaxParameters) {
      fail(at, "function '" + name + "' has more than " +
                   std::to_string(scene::Function::kMaxParameters) + " parameters");
    }
  } else {
    function->parameters = {"x", "y", "z"};
  }
  if (!plain_symbol('{')) {
    fail_here("expected '{' to start the body of function '" + name + "', found " +
              describe(plain()));
  }
  compile_function_body(*function);
  scopes.front().values.erase(name);
  macros.erase(name);
  functions[name] = std::move(function);
}

// At the body's '{': compiled inside a frame of its own, so that the expression cannot run past
// the closing brace. A body that needs what convray cannot evaluate yet (functions.inc declares
// pattern and pigment functions) is read past; calling the function fails with it.
void Parser::Impl::compile_function_body(UserFunction& function) {
  Frame& outer = frames.back();
  const std::uint32_t open = outer.pos;
  const std::uint32_t close = find_closing_brace(open);
  const SourceFile* file = outer.file;
  const std::size_t depth = frames.size();
  outer.pos = close + 1;
  moved();
  Frame& frame = push_frame(Frame::Kind::function, file, open + 1, close);
  frame.name = function.name;
  const int blocks_open = open_blocks;
  try {
    compile_function(function);
    if (plain().kind != LexKind::end || frames.size() != depth + 1) {
      fail_here("expected the end of the body of function '" + function.name + "', found " +
                describe(plain()));
    }
  } catch (const UnsupportedError& error) {
    open_blocks = blocks_open;  // the item parsers' braces left open by the error
    function.compiled = nullptr;
    function.color_source = nullptr;
    function.unsupported = UnsupportedItem{error.feature(), error.loc()};
  }
  frames.resize(depth);
  moved();
}

Value Parser::Impl::call_function(const UserFunction& function, TokenRef at) {
  if (function.unsupported) {
    fail_unsupported(loc(at), function.unsupported->feature + " (at " +
                                  function.unsupported->feature_at.str() + "): " +
                                  quoted(function.name) + ", declared at " +
                                  function.loc.str() + ", needs it",
                     function.unsupported->feature);
  }
  const std::size_t wanted = function.parameters.size();
  expect_symbol('(', "after the function name '" + function.name + "'");
  std::vector<double> arguments;
  {
    ScopedValue not_in_vector(angle_depth, 0);
    if (!accept_symbol(')')) {
      for (;;) {
        const TokenRef argument_at = ref();
        arguments.push_back(
            to_float(parse_expression(), argument_at, "as an argument of a function"));
        if (accept_symbol(',')) continue;
        expect_symbol(')', "after the arguments of function '" + function.name + "'");
        break;
      }
    }
  }
  if (arguments.size() != wanted) {
    fail(at, "function '" + function.name + "' takes " + std::to_string(wanted) + " argument" +
                 (wanted == 1 ? "" : "s") + ", found " + std::to_string(arguments.size()));
  }
  if (function.color_source) {
    const scene::Color color =
        function.color_source->at(Vec3(arguments[0], arguments[1], arguments[2]));
    Vector vector;
    vector.size = 5;
    vector.color = true;
    vector.v = {color.rgb.r, color.rgb.g, color.rgb.b, color.filter, color.transmit};
    return make_value(vector);
  }
  const double result = function.compiled->evaluate(arguments);
  if (!std::isfinite(result)) {
    math_error(at, "function '" + function.name + "' gives a result that is not finite");
  }
  return make_value(result);
}

}  // namespace convray::sdl
