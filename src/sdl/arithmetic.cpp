// Operators on values. Floats and vectors mix as in POV-Ray: a float used with a vector
// stands for that float in every component; vectors of different sizes are padded with
// zeros; the result is a colour when either side is one.
#include <algorithm>
#include <cmath>
#include <string>

#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

std::string operator_text(char op) {
  switch (op) {
    case kLessEqual:
      return "<=";
    case kGreaterEqual:
      return ">=";
    case kNotEqual:
      return "!=";
    default:
      return std::string(1, op);
  }
}

bool is_arithmetic(char op) { return op == '+' || op == '-' || op == '*' || op == '/'; }

}  // namespace

void Parser::Impl::math_error(TokenRef at, const std::string& message) const {
  if (quiet_math > 0) return;  // a discarded branch of ?:, & or |
  fail(at, message);
}

Value Parser::Impl::finite(double value, TokenRef at) const {
  // Infinities would reach the scene records (and NaN after them): 1e308 * 10 is an error.
  if (std::isfinite(value)) return make_value(value);
  math_error(at, "overflow: the result is not finite");
  return make_value(0.0);
}

Value Parser::Impl::apply_binary(char op, const Value& a, const Value& b, TokenRef at) {
  const double* fa = a.get<double>();
  const double* fb = b.get<double>();
  if (fa != nullptr && fb != nullptr) {
    const double x = *fa, y = *fb;
    switch (op) {
      case '+':
        return finite(x + y, at);
      case '-':
        return finite(x - y, at);
      case '*':
        return finite(x * y, at);
      case '/':
        if (y == 0.0) {
          math_error(at, "division by zero");
          return make_value(0.0);
        }
        return finite(x / y, at);
      case '<':
        return make_value(x < y ? 1.0 : 0.0);
      case kLessEqual:
        return make_value(x <= y ? 1.0 : 0.0);
      case '=':
        return make_value(std::abs(x - y) < kEpsilon ? 1.0 : 0.0);
      case kNotEqual:
        return make_value(std::abs(x - y) < kEpsilon ? 0.0 : 1.0);
      case kGreaterEqual:
        return make_value(x >= y ? 1.0 : 0.0);
      case '>':
        return make_value(x > y ? 1.0 : 0.0);
      case '&':
        return make_value(is_true(x) && is_true(y) ? 1.0 : 0.0);
      case '|':
        return make_value(is_true(x) || is_true(y) ? 1.0 : 0.0);
      default:
        break;
    }
  }
  const Value& odd = fa == nullptr ? a : b;
  if (!is_arithmetic(op)) {
    fail(at, "'" + operator_text(op) + "' compares floats, found " + type_name(odd));
  }
  const Vector* va = a.get<Vector>();
  const Vector* vb = b.get<Vector>();
  if ((fa == nullptr && va == nullptr) || (fb == nullptr && vb == nullptr)) {
    const Value& wrong = (fa == nullptr && va == nullptr) ? a : b;
    fail(at, "'" + operator_text(op) + "' needs floats or vectors, found " + type_name(wrong));
  }
  Vector result;
  result.size = std::max(va ? va->size : 0, vb ? vb->size : 0);
  result.color = (va && va->color) || (vb && vb->color);
  for (size_t i = 0; i < size_t(result.size); ++i) {
    const bool a_given = fa != nullptr || int(i) < va->size;
    const bool b_given = fb != nullptr || int(i) < vb->size;
    const double x = fa ? *fa : va->v[i];
    const double y = fb ? *fb : vb->v[i];
    double& r = result.v[i];
    switch (op) {
      case '+':
        r = x + y;
        break;
      case '-':
        r = x - y;
        break;
      case '*':
        r = x * y;
        break;
      default:  // '/'
        if (y != 0.0) {
          r = x / y;
        } else if (b_given && a_given) {
          math_error(at, "division by zero (component " + std::to_string(i + 1) + ")");
          r = 0.0;
        } else {
          r = 0.0;  // padding of a shorter vector
        }
        break;
    }
    if (!std::isfinite(r)) {
      math_error(at, "overflow: the result is not finite");
      r = 0.0;
    }
  }
  return make_value(result);
}

Value Parser::Impl::apply_unary(char op, const Value& a, TokenRef at) {
  if (op == '!') return make_value(is_true(to_float(a, at, "after '!'")) ? 0.0 : 1.0);
  if (const double* f = a.get<double>()) return make_value(op == '-' ? -*f : *f);
  if (const Vector* vector = a.get<Vector>()) {
    if (op == '+') return a;
    Vector negated = *vector;
    for (double& component : negated.v) component = -component;
    return make_value(negated);
  }
  fail(at, "unary '" + std::string(1, op) + "' needs a float or a vector, found " + type_name(a));
}

}  // namespace convray::sdl
