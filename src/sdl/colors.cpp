// Colour expressions, POV-Ray 3.7 style:
//   color rgb <r, g, b>          rgbf, rgbt, rgbft: with filter and/or transmit
//   srgb <r, g, b>                sRGB-encoded, decoded to linear here (and srgbf, ...)
//   color red 1 green 0.5         components from zero; blue, filter, transmit, gray too
//   color Red filter 0.5          an identifier (or any colour expression) and modifiers
// `color` / `colour` is optional. A float operand stands for every component the keyword
// sets (rgbf 1 is <1, 1, 1, 1, 0>); a vector used as a colour gives r, g, b (a 4th component
// is filter, a 5th transmit).
#include <cmath>

#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

// Precedence of + and -: keyword operands are additive expressions (no comparisons), so that
// `red 0.5 green 1` stops at `green`.
constexpr int kAdditive = 4;

double srgb_to_linear(double c) {
  const double magnitude = std::abs(c);
  const double linear =
      magnitude <= 0.04045 ? magnitude / 12.92 : std::pow((magnitude + 0.055) / 1.055, 2.4);
  return c < 0.0 ? -linear : linear;
}

bool is_srgb(Word word) {
  return word == Word::srgb || word == Word::srgbf || word == Word::srgbt || word == Word::srgbft;
}

bool is_whole_color_word(Word word) {
  return is_srgb(word) || word == Word::rgb || word == Word::rgbf || word == Word::rgbt ||
         word == Word::rgbft;
}

}  // namespace

bool Parser::Impl::is_color_modifier(const LexToken& t) {
  if (t.kind != LexKind::keyword) return false;
  switch (t.word) {
    case Word::red:
    case Word::green:
    case Word::blue:
    case Word::filter:
    case Word::transmit:
    case Word::gray:
    case Word::grey:
      return true;
    default:
      return false;
  }
}

bool Parser::Impl::is_color_keyword(const LexToken& t) {
  if (is_color_modifier(t)) return true;
  if (t.kind != LexKind::keyword) return false;
  switch (t.word) {
    case Word::color:
    case Word::colour:
    case Word::rgb:
    case Word::rgbf:
    case Word::rgbt:
    case Word::rgbft:
    case Word::srgb:
    case Word::srgbf:
    case Word::srgbt:
    case Word::srgbft:
      return true;
    default:
      return false;
  }
}

Vector Parser::Impl::to_color(const Vector& v) {
  Vector color = v;
  for (int i = v.size; i < 5; ++i) color.v[size_t(i)] = 0.0;
  color.size = 5;
  color.color = true;
  return color;
}

Value Parser::Impl::parse_color_group() {
  Vector color;
  color.size = 5;
  color.color = true;
  const LexToken& first = settle();
  // A whole colour was given (rgb..., or color EXPRESSION): a further rgb... starts the next
  // colour, as in POV-Ray's `checker rgb 1 rgb 0`.
  bool whole = false;
  if (first.word == Word::color || first.word == Word::colour) {
    const TokenRef at = ref();
    advance();
    if (!is_color_keyword(settle())) {
      whole = true;
      const Value base = parse_binary(kAdditive);
      if (const double* f = base.get<double>()) {
        color.v = {*f, *f, *f, 0.0, 0.0};
      } else {
        color = to_color(to_vector(base, at, "after 'color'"));
      }
    }
  }
  for (;;) {
    const LexToken& t = lookahead();
    if (!is_color_keyword(t) || t.word == Word::color || t.word == Word::colour) break;
    const Word word = t.word;
    if (whole && is_whole_color_word(word)) break;
    const TokenRef at = ref();
    advance();
    const Value operand = parse_binary(kAdditive);
    const std::string what = "after '" + std::string(at.token->view()) + "'";
    switch (word) {
      case Word::red:
        color.v[0] = to_float(operand, at, what);
        continue;
      case Word::green:
        color.v[1] = to_float(operand, at, what);
        continue;
      case Word::blue:
        color.v[2] = to_float(operand, at, what);
        continue;
      case Word::filter:
        color.v[3] = to_float(operand, at, what);
        continue;
      case Word::transmit:
        color.v[4] = to_float(operand, at, what);
        continue;
      case Word::gray:
      case Word::grey: {
        const double g = to_float(operand, at, what);
        color.v[0] = color.v[1] = color.v[2] = g;
        continue;
      }
      default:
        break;
    }
    // rgb, rgbf, rgbt, rgbft and their srgb forms.
    whole = true;
    Vector given;
    if (const double* f = operand.get<double>()) {
      given.v = {*f, *f, *f, *f, *f};
    } else {
      given = to_vector(operand, at, what);
      for (int i = given.size; i < 5; ++i) given.v[size_t(i)] = 0.0;
    }
    for (int i = 0; i < 3; ++i) {
      color.v[size_t(i)] = is_srgb(word) ? srgb_to_linear(given.v[size_t(i)]) : given.v[size_t(i)];
    }
    if (word == Word::rgbf || word == Word::srgbf) color.v[3] = given.v[3];
    if (word == Word::rgbt || word == Word::srgbt) color.v[4] = given.v[3];
    if (word == Word::rgbft || word == Word::srgbft) {
      color.v[3] = given.v[3];
      color.v[4] = given.v[4];
    }
  }
  return make_value(color);
}

Value Parser::Impl::apply_color_modifiers(Value value) {
  Vector color = to_color(*value.get<Vector>());
  while (is_color_modifier(lookahead())) {
    const Word word = plain().word;
    const TokenRef at = ref();
    advance();
    const double f =
        to_float(parse_binary(kAdditive), at, "after '" + std::string(at.token->view()) + "'");
    switch (word) {
      case Word::red:
        color.v[0] = f;
        break;
      case Word::green:
        color.v[1] = f;
        break;
      case Word::blue:
        color.v[2] = f;
        break;
      case Word::filter:
        color.v[3] = f;
        break;
      case Word::transmit:
        color.v[4] = f;
        break;
      default:
        color.v[0] = color.v[1] = color.v[2] = f;
        break;  // gray
    }
  }
  return make_value(color);
}

}  // namespace convray::sdl
