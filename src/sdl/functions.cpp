// Built-in functions. Math errors (sqrt(-1), log(0), division by zero, results that are not
// finite) are errors, except in a discarded branch of ?:, & or |.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "scene/transform.hpp"
#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

struct Arity {
  std::size_t min, max;
};

constexpr std::size_t kMany = 1000;

Arity arity_of(Word word) {
  switch (word) {
    case Word::atan2:
    case Word::div:
    case Word::mod:
    case Word::pow:
    case Word::vdot:
    case Word::vcross:
    case Word::vrotate:
    case Word::strcmp:
    case Word::dimension_size:
      return {2, 2};
    case Word::max:
    case Word::min:
    case Word::bitwise_and:
    case Word::bitwise_or:
    case Word::bitwise_xor:
      return {2, kMany};
    case Word::select:
      return {3, 4};
    case Word::vaxis_rotate:
    case Word::str:
    case Word::substr:
      return {3, 3};
    case Word::vstr:
      return {5, 5};
    case Word::concat:
      return {1, kMany};
    case Word::atan:
      return {1, 2};  // atan(y, x) is atan2, as POV-Ray 3.7 allows
    default:
      return {1, 1};
  }
}

// POV-Ray 3.7's rand(): a 32-bit linear congruential generator, state = 1812433253 * state +
// 12345 (mod 2^32), each number the new state over 2^32 - 1 (so 0 and 1 can both occur).
// Derived from the numbers the povray binary prints (seed(0) starts 12345 / (2^32 - 1));
// tests/sdl/povray_rand_test.cpp compares thousands of draws with it.
double next_povray_random(std::uint32_t& state) {
  state = state * 1812433253u + 12345u;
  return double(state) / 4294967295.0;
}

// seed(v)'s starting state: v truncated to a 32-bit integer, as POV-Ray does; values outside
// the int range (and NaN) all give the state 2^31, as the povray binary shows (seed(1e12) and
// seed(-2147483649) draw what seed(2147483648) draws).
std::uint32_t povray_seed_state(double v) {
  const double t = std::trunc(v);
  if (!(t >= -2147483648.0 && t <= 2147483647.0)) return 0x80000000u;
  return std::uint32_t(std::int32_t(t));
}

}  // namespace

double Parser::Impl::next_random(double stream, TokenRef at) {
  const double index = std::trunc(stream);
  if (!(index >= 0.0 && index < double(random_streams.size()))) {
    fail(at, "rand() needs a stream made by seed(), found " + number_text(stream));
  }
  return next_povray_random(random_streams[size_t(index)]);
}

Value Parser::Impl::call_builtin(const LexToken& name, TokenRef at) {
  const Word word = name.word;
  const std::string function(name.view());
  if (word == Word::defined) {
    advance();
    expect_symbol('(', "after 'defined'");
    const std::string_view identifier = expect_identifier_raw("in defined()");
    expect_symbol(')', "after the identifier in defined()");
    return make_value(is_declared(identifier) ? 1.0 : 0.0);
  }
  advance();
  const Arity arity = arity_of(word);
  std::vector<Value> args = parse_arguments(name, arity.min, arity.max);
  if (word >= Word::concat || word == Word::strlen || word == Word::val || word == Word::asc ||
      word == Word::strcmp || word == Word::file_exists || word == Word::dimensions ||
      word == Word::dimension_size) {
    return call_string_function(word, args, at);
  }
  if (word >= Word::vlength) return call_vector_function(word, args, at);

  const std::string what = "in " + function + "()";
  const auto arg = [&](std::size_t i) { return to_float(args[i], at, what); };
  const auto domain = [&](bool ok, const std::string& message) {
    if (!ok) math_error(at, function + "(): " + message);
    return ok;
  };
  double result = 0.0;
  switch (word) {
    case Word::abs:
      result = std::abs(arg(0));
      break;
    case Word::acos:
      if (domain(std::abs(arg(0)) <= 1.0, "argument outside [-1, 1]")) result = std::acos(arg(0));
      break;
    case Word::asin:
      if (domain(std::abs(arg(0)) <= 1.0, "argument outside [-1, 1]")) result = std::asin(arg(0));
      break;
    case Word::acosh:
      if (domain(arg(0) >= 1.0, "argument below 1")) result = std::acosh(arg(0));
      break;
    case Word::atanh:
      if (domain(std::abs(arg(0)) < 1.0, "argument outside (-1, 1)")) result = std::atanh(arg(0));
      break;
    case Word::asinh:
      result = std::asinh(arg(0));
      break;
    case Word::atan:
      result = args.size() == 2 ? std::atan2(arg(0), arg(1)) : std::atan(arg(0));
      break;
    case Word::atan2:
      result = std::atan2(arg(0), arg(1));
      break;
    case Word::ceil:
      result = std::ceil(arg(0));
      break;
    case Word::floor:
      result = std::floor(arg(0));
      break;
    case Word::int_:
      result = std::trunc(arg(0));
      break;
    case Word::cos:
      result = std::cos(arg(0));
      break;
    case Word::sin:
      result = std::sin(arg(0));
      break;
    case Word::tan:
      result = std::tan(arg(0));
      break;
    case Word::cosh:
      result = std::cosh(arg(0));
      break;
    case Word::sinh:
      result = std::sinh(arg(0));
      break;
    case Word::tanh:
      result = std::tanh(arg(0));
      break;
    case Word::degrees:
      result = arg(0) * 180.0 / kPi;
      break;
    case Word::radians:
      result = arg(0) * kPi / 180.0;
      break;
    case Word::exp:
      result = std::exp(arg(0));
      break;
    case Word::ln:
      if (domain(arg(0) > 0.0, "argument not positive")) result = std::log(arg(0));
      break;
    case Word::log:
      if (domain(arg(0) > 0.0, "argument not positive")) result = std::log10(arg(0));
      break;
    case Word::sqrt:
      if (domain(arg(0) >= 0.0, "negative argument")) result = std::sqrt(arg(0));
      break;
    case Word::sqr:
      result = arg(0) * arg(0);
      break;
    case Word::pow:
      if (domain(!(arg(0) == 0.0 && arg(1) < 0.0), "division by zero (0 to a negative power)") &&
          domain(!(arg(0) < 0.0 && arg(1) != std::trunc(arg(1))),
                 "a negative number to a fractional power")) {
        result = std::pow(arg(0), arg(1));
      }
      break;
    case Word::mod:
      if (domain(arg(1) != 0.0, "division by zero")) result = std::fmod(arg(0), arg(1));
      break;
    case Word::div:
      if (domain(arg(1) != 0.0, "division by zero")) result = std::trunc(arg(0) / arg(1));
      break;
    case Word::min:
    case Word::max: {
      result = arg(0);
      for (std::size_t i = 1; i < args.size(); ++i) {
        result = word == Word::min ? std::min(result, arg(i)) : std::max(result, arg(i));
      }
      break;
    }
    case Word::select: {
      // select(A, B, C): A < 0 ? B : C; select(A, B, C, D): A < 0, A = 0, A > 0.
      const double a = arg(0);
      std::size_t chosen = 0;
      if (args.size() == 3) {
        chosen = a < 0.0 ? 1 : 2;
      } else {
        chosen = a < 0.0 ? 1 : (a == 0.0 ? 2 : 3);
      }
      return args[chosen];
    }
    case Word::bitwise_and:
    case Word::bitwise_or:
    case Word::bitwise_xor: {
      const auto integer = [&](std::size_t i) {
        const double value = arg(i);
        if (!(std::abs(value) < 0x1.0p53)) fail(at, function + "(): argument out of range");
        return std::int64_t(value);
      };
      std::int64_t bits = integer(0);
      for (std::size_t i = 1; i < args.size(); ++i) {
        if (word == Word::bitwise_and) bits &= integer(i);
        if (word == Word::bitwise_or) bits |= integer(i);
        if (word == Word::bitwise_xor) bits ^= integer(i);
      }
      result = double(bits);
      break;
    }
    case Word::seed: {
      random_streams.push_back(povray_seed_state(arg(0)));
      result = double(random_streams.size() - 1);
      break;
    }
    case Word::rand:
      result = next_random(arg(0), at);
      break;
    default:
      fail(at, "'" + function + "' is not a function of floats");
  }
  if (!std::isfinite(result)) {
    math_error(at, function + "() gives a result that is not finite");
    result = 0.0;
  }
  return make_value(result);
}

Value Parser::Impl::call_vector_function(Word word, std::vector<Value>& args, TokenRef at) {
  const std::string what = "in " + std::string(at.token->view()) + "()";
  const auto vec = [&](std::size_t i) { return to_vector(args[i], at, what).xyz(); };
  const auto result = [&](const Vec3& v) {
    Vector out;
    out.v = {v.x, v.y, v.z, 0.0, 0.0};
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      math_error(at, std::string(at.token->view()) + "() gives a result that is not finite");
      out.v = {0.0, 0.0, 0.0, 0.0, 0.0};
    }
    return make_value(out);
  };
  switch (word) {
    case Word::vlength: {
      const Vector v = to_vector(args[0], at, what);
      double sum = 0.0;
      for (int i = 0; i < v.size; ++i) sum += v.v[size_t(i)] * v.v[size_t(i)];
      return make_value(std::sqrt(sum));
    }
    case Word::vdot:
      return make_value(glm::dot(vec(0), vec(1)));
    case Word::vcross:
      return result(glm::cross(vec(0), vec(1)));
    case Word::vnormalize: {
      const Vec3 v = vec(0);
      const double length = glm::length(v);
      if (length == 0.0) {
        math_error(at, "vnormalize(): the vector has length zero");
        return result(Vec3(0.0));
      }
      return result(v / length);
    }
    case Word::vrotate:
      return result(scene::Transform::rotation(vec(1)).vector(vec(0)));
    case Word::vaxis_rotate: {
      // Rodrigues' rotation about the unit axis; in POV-Ray's left-handed frame this is the
      // same turn as `rotate` about that axis (vaxis_rotate(v, y, a) = vrotate(v, a * y)).
      const Vec3 v = vec(0);
      const Vec3 axis = vec(1);
      const double length = glm::length(axis);
      if (length == 0.0) {
        math_error(at, "vaxis_rotate(): the axis has length zero");
        return result(v);
      }
      const Vec3 n = axis / length;
      const double angle = to_float(args[2], at, what) * kPi / 180.0;
      const double c = std::cos(angle), s = std::sin(angle);
      return result(v * c + glm::cross(n, v) * s + n * glm::dot(n, v) * (1.0 - c));
    }
    default:
      fail(at, quoted(at.token->view()) + " is not a vector function");
  }
}

}  // namespace convray::sdl
