// Conditional and loop directives. Open blocks live on their frame (file, include or macro
// body), so an #if must end in the file that opened it. Branches not taken are skipped by a
// scan of the frame's tokens for directive tokens, counting nested blocks: nothing in them
// is evaluated. Loops jump back to their start in the token vector.
#include <cmath>
#include <string>

#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

Block make_block(Block::Kind kind, std::uint32_t opened_at, std::uint32_t loop_start = 0) {
  Block block;
  block.kind = kind;
  block.opened_at = opened_at;
  block.loop_start = loop_start;
  return block;
}

std::string line_column(const SourceLoc& loc) {
  return std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

}  // namespace

double Parser::Impl::parse_condition() {
  expect_symbol('(', "after the directive");
  const TokenRef at = ref();
  ScopedValue not_in_vector(angle_depth, 0);
  const double value = to_float(parse_expression(), at, "as the condition");
  expect_symbol(')', "after the condition");
  return value;
}

bool Parser::Impl::parse_defined_condition() {
  // #ifdef (Name) and #ifdef (Array[i]): the name is not evaluated, nor a macro called.
  if (!plain_symbol('('))
    fail_here("expected '(' after #ifdef / #ifndef, found " + describe(plain()));
  advance();
  const TokenRef name_at = ref();
  const std::string_view name = expect_identifier_raw("in #ifdef / #ifndef");
  bool defined = is_declared(name);
  if (plain_symbol('[')) {
    const Value* root = lookup(name);
    if (root == nullptr) fail(name_at, "undeclared identifier '" + std::string(name) + "'");
    const Value held = *root;
    const std::vector<std::size_t> path = parse_element_path(held, name);
    Value copy = held;
    defined = element_at(copy, path, false, name, name_at)->is_set();
  }
  if (!plain_symbol(')'))
    fail_here("expected ')' after the identifier, found " + describe(plain()));
  advance();
  return defined;
}

void Parser::Impl::fail_unterminated(const Frame& frame, const Block& block) const {
  const LexToken& opening = frame.file->tokens[block.opened_at];
  const SourceLoc end = token_loc(frame.file, frame.end);
  const std::string where = frame.kind == Frame::Kind::macro
                                ? "the end of macro '" + frame.name + "'"
                                : "the end of the file";
  fail(end, "unterminated #" + std::string(opening.view()) + " (opened at " +
                line_column(token_loc(frame.file, block.opened_at)) + "): expected #end before " +
                where);
}

Word Parser::Impl::skip(int depth, SkipStop stop, std::uint32_t opened_at) {
  Frame& frame = frames.back();
  const std::vector<LexToken>& tokens = frame.file->tokens;
  for (std::uint32_t i = frame.pos; i < frame.end; ++i) {
    const LexToken& t = tokens[i];
    if (t.kind != LexKind::directive) continue;
    bool stops = false;
    switch (t.word) {
      case Word::if_:
      case Word::ifdef:
      case Word::ifndef:
      case Word::while_:
      case Word::for_:
      case Word::switch_:
      case Word::macro:
        ++depth;
        break;
      case Word::end:
        if (depth == 0) {
          stops = true;
        } else {
          --depth;
        }
        break;
      case Word::else_:
        stops = depth == 0 && stop != SkipStop::end;
        break;
      case Word::elseif:
        stops = depth == 0 && stop == SkipStop::if_branch;
        break;
      case Word::case_:
      case Word::range:
        stops = depth == 0 && stop == SkipStop::switch_clause;
        break;
      default:
        break;
    }
    if (stops) {
      frame.pos = i + 1;
      moved();
      return t.word;
    }
  }
  Block block;
  block.opened_at = opened_at;
  fail_unterminated(frame, block);
}

void Parser::Impl::directive_if(Word kind, std::uint32_t at) {
  const std::size_t depth = frames.size();
  bool condition = kind == Word::if_ ? is_true(parse_condition())
                                     : parse_defined_condition() == (kind == Word::ifdef);
  if (frames.size() != depth) fail_here("the condition of an #if must end in its own file");
  for (;;) {
    if (condition) {
      frames.back().blocks.push_back(make_block(Block::Kind::if_, at));
      return;
    }
    const Word stop = skip(0, SkipStop::if_branch, at);
    if (stop == Word::end) return;
    condition = stop == Word::else_ || is_true(parse_condition());
    if (frames.size() != depth) fail_here("the condition of an #elseif must end in its own file");
  }
}

void Parser::Impl::directive_else(Word kind, TokenRef at) {
  Frame& frame = frames.back();
  const std::string name = kind == Word::else_ ? "#else" : "#elseif";
  if (frame.blocks.empty()) fail(at, name + " without #if");
  const Block& block = frame.blocks.back();
  // Reached after a branch that ran: the rest of the #if (or #switch) is skipped.
  if (block.kind == Block::Kind::if_ ||
      (block.kind == Block::Kind::switch_ && kind == Word::else_)) {
    skip(0, SkipStop::end, block.opened_at);
    frames.back().blocks.pop_back();
    return;
  }
  fail(at, name + " without #if");
}

void Parser::Impl::directive_while(std::uint32_t at) {
  const std::size_t depth = frames.size();
  const std::uint32_t condition_start = frames.back().pos;
  const bool condition = is_true(parse_condition());
  if (frames.size() != depth) fail_here("the condition of a #while must end in its own file");
  if (!condition) {
    skip(0, SkipStop::end, at);
    return;
  }
  Block block = make_block(Block::Kind::while_, at, condition_start);
  frames.back().blocks.push_back(std::move(block));
}

void Parser::Impl::directive_for(std::uint32_t at) {
  // #for (Identifier, Start, End [, Step]): the identifier is a #local.
  const std::size_t depth = frames.size();
  expect_symbol('(', "after #for");
  const std::string variable(expect_identifier_raw("as the #for loop variable"));
  expect_symbol(',', "after the #for loop variable");
  const auto number = [&](const char* what) {
    const TokenRef where = ref();
    return to_float(parse_expression(), where, what);
  };
  const double start = number("as the start of the #for loop");
  expect_symbol(',', "after the start of the #for loop");
  const double last = number("as the end of the #for loop");
  double step = 1.0;
  if (accept_symbol(',')) step = number("as the step of the #for loop");
  expect_symbol(')', "after the #for loop's range");
  if (frames.size() != depth) fail_here("a #for loop's range must end in its own file");
  if (step == 0.0)
    fail(token_loc(frames.back().file, at), "#for loop with a step of zero never ends");
  declare_local(variable, make_value(start));
  const bool runs = step > 0.0 ? start <= last + kEpsilon : start >= last - kEpsilon;
  if (!runs) {
    skip(0, SkipStop::end, at);
    return;
  }
  Block block = make_block(Block::Kind::for_, at, frames.back().pos);
  block.variable = variable;
  block.last = last;
  block.step = step;
  frames.back().blocks.push_back(std::move(block));
}

bool Parser::Impl::seek_switch_clause(double value, std::uint32_t opened_at) {
  const std::size_t depth = frames.size();
  for (;;) {
    const Word stop = skip(0, SkipStop::switch_clause, opened_at);
    bool matches = false;
    if (stop == Word::end) return false;
    if (stop == Word::else_) return true;
    if (stop == Word::case_) {
      matches = std::abs(parse_condition() - value) < kEpsilon;
    } else {  // #range (low, high)
      expect_symbol('(', "after #range");
      const TokenRef at = ref();
      const double low = to_float(parse_expression(), at, "as the low end of #range");
      expect_symbol(',', "between the ends of #range");
      const TokenRef high_at = ref();
      const double high = to_float(parse_expression(), high_at, "as the high end of #range");
      expect_symbol(')', "after #range's ends");
      matches = low <= value && value <= high;
    }
    if (frames.size() != depth) fail_here("a #case or #range must end in its own file");
    if (matches) return true;
  }
}

void Parser::Impl::directive_switch(std::uint32_t at) {
  const std::size_t depth = frames.size();
  const double value = parse_condition();
  if (frames.size() != depth) fail_here("the value of a #switch must end in its own file");
  if (seek_switch_clause(value, at)) {
    frames.back().blocks.push_back(make_block(Block::Kind::switch_, at));
  }
}

void Parser::Impl::directive_case(Word kind, TokenRef at) {
  // Reached from a clause that ran without #break: POV-Ray falls through into this one.
  const Frame& frame = frames.back();
  if (frame.blocks.empty() || frame.blocks.back().kind != Block::Kind::switch_) {
    fail(at, std::string(kind == Word::case_ ? "#case" : "#range") + " without #switch");
  }
  ScopedValue quiet(quiet_math, quiet_math + 1);
  if (kind == Word::case_) {
    parse_condition();
  } else {
    expect_symbol('(', "after #range");
    parse_expression();
    expect_symbol(',', "between the ends of #range");
    parse_expression();
    expect_symbol(')', "after #range's ends");
  }
}

void Parser::Impl::directive_break(TokenRef at) {
  Frame& frame = frames.back();
  std::size_t target = frame.blocks.size();
  while (target > 0 && frame.blocks[target - 1].kind == Block::Kind::if_) --target;
  if (target == 0) {
    // POV-Ray 3.7 also leaves a macro with #break.
    if (frame.kind == Frame::Kind::macro) {
      frame.blocks.clear();
      frame.pos = frame.end;
      moved();
      return;
    }
    fail(at, "#break outside #switch, #while, #for or a macro");
  }
  const std::size_t inner = frame.blocks.size() - target;  // #if blocks inside the target
  skip(int(inner), SkipStop::end, frame.blocks[target - 1].opened_at);
  frames.back().blocks.resize(target - 1);
}

void Parser::Impl::directive_end(TokenRef at) {
  Frame& frame = frames.back();
  if (frame.blocks.empty()) fail(at, "#end without #if, #while, #for, #switch or #macro");
  Block& block = frame.blocks.back();
  switch (block.kind) {
    case Block::Kind::if_:
    case Block::Kind::switch_:
      frame.blocks.pop_back();
      return;
    case Block::Kind::while_: {
      const std::size_t depth = frames.size();
      const std::uint32_t after_end = frame.pos;
      frame.pos = block.loop_start;
      moved();
      const bool again = is_true(parse_condition());
      if (frames.size() != depth) fail_here("the condition of a #while must end in its own file");
      Block& loop = frames.back().blocks.back();
      if (!again) {
        frames.back().pos = after_end;
        moved();
        frames.back().blocks.pop_back();
        return;
      }
      count_iteration(loop);
      return;
    }
    case Block::Kind::for_: {
      Value* variable = lookup(block.variable);
      const double* current_value = variable ? variable->get<double>() : nullptr;
      if (current_value == nullptr) {
        fail(at, "the #for loop variable '" + block.variable + "' is no longer a float");
      }
      const double value = *current_value + block.step;
      *variable = make_value(value);
      const bool runs =
          block.step > 0.0 ? value <= block.last + kEpsilon : value >= block.last - kEpsilon;
      if (!runs) {
        frame.blocks.pop_back();
        return;
      }
      count_iteration(block);
      frame.pos = block.loop_start;
      moved();
      return;
    }
  }
}

void Parser::Impl::count_iteration(Block& loop) {
  ++loop.own_iterations;
  for (Frame& frame : frames) {
    for (Block& block : frame.blocks) {
      if (block.kind != Block::Kind::while_ && block.kind != Block::Kind::for_) continue;
      if (++block.iterations < options.max_loop_iterations) continue;
      const char* kind = block.kind == Block::Kind::while_ ? "#while" : "#for";
      const bool nested = block.iterations != block.own_iterations;
      fail(token_loc(frame.file, block.opened_at),
           std::string(kind) + " loop exceeded " + std::to_string(options.max_loop_iterations) +
               " iterations" + (nested ? " (counting those of the loops inside it)" : ""));
    }
  }
}

}  // namespace convray::sdl
