// The token stream: frames of tokens (the scene, includes, macro bodies, function bodies),
// the settled token item parsers see, and the public Token made from it.
#include <string>

#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {

const LexToken& Parser::Impl::plain_at_frame_end() {
  for (;;) {
    const Frame& frame = frames.back();
    if (frame.pos < frame.end) return frame.file->tokens[frame.pos];
    if (!leave_finished_frame()) {
      // The end of the scene or of a function body: an end token where the frame ends.
      end_token = frame.file->tokens[frame.end];
      end_token.kind = LexKind::end;
      end_token.word = Word::none;
      end_token.symbol = 0;
      end_token.length = 0;
      return end_token;
    }
  }
}

const LexToken& Parser::Impl::lookahead_through_blocks() {
  for (;;) {
    const LexToken& t = plain();
    if (t.kind != LexKind::directive) return t;
    bool moves_only = t.word == Word::else_ || t.word == Word::elseif || t.word == Word::break_;
    if (t.word == Word::end) {
      const std::vector<Block>& blocks = frames.back().blocks;
      moves_only = !blocks.empty() && (blocks.back().kind == Block::Kind::if_ ||
                                       blocks.back().kind == Block::Kind::switch_);
    }
    if (!moves_only) return t;
    NestingLevel level(*this);
    run_directive();
  }
}

bool Parser::Impl::leave_finished_frame() {
  Frame& frame = frames.back();
  if (!frame.blocks.empty()) fail_unterminated(frame, frame.blocks.back());
  if (frame.kind == Frame::Kind::scene || frame.kind == Frame::Kind::function ||
      int(frames.size()) <= frame_floor) {
    return false;
  }
  if (frame.scope != 0) pop_scope(frame.scope);
  if (frame.kind == Frame::Kind::macro) --macro_depth;
  if (frame.kind == Frame::Kind::include) --include_depth;
  frames.pop_back();
  moved();
  return true;
}

const LexToken& Parser::Impl::settle_next() {
  for (;;) {
    const LexToken& t = plain();
    if (t.kind == LexKind::directive) {
      NestingLevel level(*this);
      run_directive();
      continue;
    }
    if (t.kind == LexKind::identifier && !macros.empty() && expand_if_macro(t)) continue;
    if (is_symbol(t, '#')) {
      // POV-Ray passes over a '#' that starts no directive (`look_at <0, 2, 0>#`).
      warn(here(), "'#' without a directive name, ignored");
      advance();
      continue;
    }
    settled = true;
    current = &t;
    return t;
  }
}

void Parser::Impl::advance() {
  Frame& frame = frames.back();
  if (frame.pos < frame.end) ++frame.pos;
  moved();
  if (++tokens_read > options.max_tokens) {
    fail_here("the scene read more than " + std::to_string(options.max_tokens) +
              " tokens: runaway loop or recursion?");
  }
}

void Parser::Impl::charge(std::size_t tokens) {
  tokens_read += static_cast<long long>(tokens);
  if (tokens_read > options.max_tokens) {
    fail_here("the scene did more work than reading " + std::to_string(options.max_tokens) +
              " tokens (copying strings and arrays counts): runaway loop or recursion?");
  }
}

Frame& Parser::Impl::push_frame(Frame::Kind kind, const SourceFile* file, std::uint32_t begin,
                                std::uint32_t end) {
  Frame& frame = frames.emplace_back();
  frame.kind = kind;
  frame.file = file;
  frame.pos = begin;
  frame.end = end;
  moved();
  return frame;
}

const Token& Parser::Impl::materialize() {
  const LexToken& t = settle();
  if (materialized) return token;
  switch (t.kind) {
    case LexKind::identifier:
      token.kind = Token::Kind::identifier;
      break;
    case LexKind::keyword:
      token.kind = Token::Kind::keyword;
      break;
    case LexKind::number:
      token.kind = Token::Kind::number;
      break;
    case LexKind::string:
      token.kind = Token::Kind::string;
      break;
    case LexKind::symbol:
      token.kind = Token::Kind::symbol;
      break;
    case LexKind::directive:  // settle() never stops at one
    case LexKind::end:
      token.kind = Token::Kind::end;
      break;
  }
  // assign() reuses the strings' buffers: peeking costs no allocation.
  token.text.assign(t.text, t.length);
  token.number = t.number;
  token.loc.file.assign(frames.back().file->name);
  token.loc.line = int(t.line);
  token.loc.column = int(t.column);
  materialized = true;
  return token;
}

SourceLoc Parser::Impl::loc(TokenRef at) const {
  if (at.file == nullptr || at.token == nullptr) return {};
  return {at.file->name, int(at.token->line), int(at.token->column)};
}

SourceLoc Parser::Impl::token_loc(const SourceFile* file, std::uint32_t index) const {
  return loc(TokenRef{file, &file->tokens[index]});
}

std::string Parser::Impl::describe(const LexToken& t) const {
  switch (t.kind) {
    case LexKind::end:
      return "the end of the file";
    case LexKind::string:
      return "the string \"" + std::string(t.view()) + "\"";
    case LexKind::directive:
      return "'#" + std::string(t.view()) + "'";
    default:
      return quoted(t.view());
  }
}

bool Parser::Impl::accept_symbol(char c) {
  if (!is_symbol(settle(), c)) return false;
  advance();
  return true;
}

void Parser::Impl::expect_symbol(char c, std::string_view context) {
  const LexToken& t = settle();
  if (!is_symbol(t, c)) {
    std::string wanted(1, c);
    fail_here("expected '" + wanted + "' " + std::string(context) + ", found " + describe(t));
  }
  advance();
}

std::string_view Parser::Impl::expect_identifier_raw(std::string_view context) {
  const LexToken& t = plain();
  if (t.kind == LexKind::keyword) {
    fail_here(quoted(t.view()) +
              " is a reserved word and cannot be used as an "
              "identifier " +
              std::string(context));
  }
  if (t.kind != LexKind::identifier) {
    fail_here("expected an identifier " + std::string(context) + ", found " + describe(t));
  }
  const std::string_view name = t.view();
  advance();
  return name;
}

}  // namespace convray::sdl
