// The lexical grammar (grammar/lexical.hpp) through tokenize(): every token form, where each
// token is, and the lexical errors.
#include "sdl/lexer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

std::vector<LexToken> lex(const std::string& text) {
  static std::vector<std::unique_ptr<SourceFile>> keep;  // tokens point into their file
  keep.push_back(tokenize("lex.pov", text));
  return keep.back()->tokens;
}

std::vector<std::string> texts(const std::string& text) {
  std::vector<std::string> out;
  for (const LexToken& t : lex(text)) {
    if (t.kind != LexKind::end) out.emplace_back(t.view());
  }
  return out;
}

core_testing::Failure lex_error(const std::string& text) {
  try {
    tokenize("lex.pov", text);
  } catch (const InputError& error) {
    return core_testing::to_failure(error);
  }
  ADD_FAILURE() << "expected a lexical error from: " << text;
  return {};
}

TEST(Lexer, NumbersInEveryForm) {
  const std::vector<LexToken> tokens = lex("1 1.5 .5 1. 1e-3 2E+4 0.12345678901234567 7e2");
  const std::vector<double> expected = {1.0, 1.5, 0.5, 1.0, 1e-3, 2e4, 0.12345678901234567, 700.0};
  ASSERT_EQ(tokens.size(), expected.size() + 1);
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(tokens[i].kind, LexKind::number) << i;
    EXPECT_EQ(tokens[i].number, expected[i]) << i;
  }
  EXPECT_EQ(tokens.back().kind, LexKind::end);
}

TEST(Lexer, NumbersKeepTheirTextAndSignsAreSymbols) {
  EXPECT_EQ(texts("-1.25e+2"), (std::vector<std::string>{"-", "1.25e+2"}));
  // ".x" is a dot and a word; "1.x" is the number "1." and a word.
  EXPECT_EQ(texts("V.x 1.x"), (std::vector<std::string>{"V", ".", "x", "1.", "x"}));
}

TEST(Lexer, TinyNumbersUnderflowToZeroAndHugeOnesFail) {
  EXPECT_EQ(lex("1e-400")[0].number, 0.0);
  const core_testing::Failure failure = lex_error("x = 1e999");
  EXPECT_EQ(failure.first_line, "number out of range: 1e999");
  EXPECT_EQ(failure.loc.line, 1);
  EXPECT_EQ(failure.loc.column, 5);
}

TEST(Lexer, StringsDecodeEscapes) {
  const std::vector<LexToken> tokens =
      lex(R"("plain" "q\"uote" "back\\slash" "\n\t\r\a\b\f\v\'" "")");
  ASSERT_EQ(tokens.size(), 6u);
  EXPECT_EQ(tokens[0].view(), "plain");
  EXPECT_EQ(tokens[1].view(), "q\"uote");
  EXPECT_EQ(tokens[2].view(), "back\\slash");
  EXPECT_EQ(tokens[3].view(), "\n\t\r\a\b\f\v'");
  EXPECT_EQ(tokens[4].view(), "");
  for (int i = 0; i < 5; ++i) EXPECT_EQ(tokens[size_t(i)].kind, LexKind::string);
}

TEST(Lexer, UnknownEscapesAreKeptWithAWarning) {
  const auto file = tokenize("lex.pov", R"(#include "C:\scenes\x.inc")");
  ASSERT_EQ(file->tokens.size(), 3u);
  EXPECT_EQ(file->tokens[1].view(), R"(C:\scenes\x.inc)");
  ASSERT_EQ(file->warnings.size(), 2u);  // \s and \x
  EXPECT_NE(file->warnings[0].find("lex.pov:1:10: unknown escape sequence '\\s'"),
            std::string::npos)
      << file->warnings[0];
}

TEST(Lexer, CommentsLineAndNestedBlock) {
  EXPECT_EQ(texts("a // b c\nd /* e /* f */ g */ h /**/ i"),
            (std::vector<std::string>{"a", "d", "h", "i"}));
  EXPECT_EQ(texts("a /* // not a line comment */ b // /* not a block\nc"),
            (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(texts("// only a comment"), (std::vector<std::string>{}));
}

TEST(Lexer, WordsAreKeywordsOrIdentifiers) {
  const std::vector<LexToken> tokens = lex("sphere Sphere my_thing _x1 rgb sin declare");
  EXPECT_EQ(tokens[0].kind, LexKind::keyword);
  EXPECT_EQ(tokens[0].word, Word::other);
  EXPECT_EQ(tokens[1].kind, LexKind::identifier);  // case matters
  EXPECT_EQ(tokens[2].kind, LexKind::identifier);
  EXPECT_EQ(tokens[3].kind, LexKind::identifier);
  EXPECT_EQ(tokens[4].word, Word::rgb);
  EXPECT_EQ(tokens[5].word, Word::sin);
  EXPECT_EQ(tokens[6].word, Word::declare);  // reserved even without '#'
}

TEST(Lexer, DirectivesTolerateBlanksAfterTheHash) {
  const std::vector<LexToken> tokens = lex("#declare # \t local #foo");
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0].kind, LexKind::directive);
  EXPECT_EQ(tokens[0].view(), "declare");
  EXPECT_EQ(tokens[0].word, Word::declare);
  EXPECT_EQ(tokens[1].view(), "local");
  EXPECT_EQ(tokens[1].column, 10u);  // at the '#'
  EXPECT_EQ(tokens[2].view(), "foo");
  EXPECT_EQ(tokens[2].word, Word::none);
  // A '#' followed by no name is a symbol (the parser reports it).
  EXPECT_EQ(lex("# 1")[0].kind, LexKind::symbol);
}

TEST(Lexer, EverySymbol) {
  EXPECT_EQ(
      texts("{}()[]<><=>==!=,;+-*/?:!&|.#"),
      (std::vector<std::string>{"{", "}", "(", ")", "[", "]", "<", ">", "<=", ">=", "=", "!=", ",",
                                ";", "+", "-", "*", "/", "?", ":", "!", "&",  "|",  ".", "#"}));
  const std::vector<LexToken> tokens = lex("<= >= != <");
  EXPECT_EQ(tokens[0].symbol, kLessEqual);
  EXPECT_EQ(tokens[1].symbol, kGreaterEqual);
  EXPECT_EQ(tokens[2].symbol, kNotEqual);
  EXPECT_EQ(tokens[3].symbol, '<');
}

TEST(Lexer, TokensKnowTheirLineAndColumn) {
  const std::vector<LexToken> tokens = lex("a\n  bb /* x\n y */ c\r\n\td \"s\"\n");
  ASSERT_EQ(tokens.size(), 6u);
  const std::vector<std::pair<unsigned, unsigned>> expected = {{1, 1}, {2, 3}, {3, 7},
                                                               {4, 2}, {4, 4}, {5, 1}};
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(tokens[i].line, expected[i].first) << i;
    EXPECT_EQ(tokens[i].column, expected[i].second) << i;
  }
}

TEST(Lexer, ByteOrderMarkIsSkipped) {
  EXPECT_EQ(texts("\xEF\xBB\xBF"
                  "a"),
            (std::vector<std::string>{"a"}));
}

TEST(Lexer, UnterminatedCommentFailsAtItsOpening) {
  const core_testing::Failure failure = lex_error("a\n  /* one /* two */\nb");
  EXPECT_EQ(failure.first_line, "unterminated comment: this '/*' has no matching '*/'");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 3);
  EXPECT_EQ(failure.message,
            "unterminated comment: this '/*' has no matching '*/'\n"
            "      /* one /* two */\n"
            "      ^");
}

TEST(Lexer, UnterminatedStringFailsAtItsQuote) {
  const core_testing::Failure failure = lex_error("#declare S = \"abc\n\n");
  EXPECT_EQ(failure.first_line, "unterminated string: this '\"' has no closing quote");
  EXPECT_EQ(failure.loc.line, 1);
  EXPECT_EQ(failure.loc.column, 14);
  // A backslash at the very end escapes nothing.
  EXPECT_EQ(lex_error("\"abc\\").loc.column, 1);
}

TEST(Lexer, UnexpectedCharacters) {
  core_testing::Failure failure = lex_error("a = 1 @ 2");
  EXPECT_EQ(failure.first_line, "unexpected character '@'");
  EXPECT_EQ(failure.loc.column, 7);
  failure = lex_error("x\n \x01");
  EXPECT_EQ(failure.first_line, "unexpected character (byte 0x01)");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 2);
}

TEST(Lexer, DeeplyNestedCommentsDoNotRecurse) {
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "/*";
  for (int i = 0; i < 100000; ++i) text += "*/";
  EXPECT_EQ(texts(text + " a"), (std::vector<std::string>{"a"}));
}

TEST(Lexer, TheEndTokenIsAfterTheLastCharacter) {
  const std::vector<LexToken> tokens = lex("a\nbc");
  EXPECT_EQ(tokens.back().kind, LexKind::end);
  EXPECT_EQ(tokens.back().line, 2u);
  EXPECT_EQ(tokens.back().column, 3u);
}

}  // namespace
}  // namespace convray::sdl
