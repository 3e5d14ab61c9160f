#pragma once
// POV-Ray's user-defined functions (`#declare F = function (a, b) { expression }`), compiled
// once, when declared, into a tree of nodes held in one vector; evaluating walks the tree with
// the arguments in a caller's array. A compiled function is immutable, so every render thread
// may evaluate it at once (isosurfaces, function patterns).
//
// What the tree holds is what POV-Ray's function language has (reference manual, "User-Defined
// Functions"): numbers (identifiers declared outside are read once, when the function is
// compiled), the parameters, + - * / ^ and unary - + !, comparisons (1 or 0), & and |,
// `a ? b : c`, the built-in float functions, calls of other functions and of POV-Ray's internal
// functions (functions.inc's f_...).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "scene/color.hpp"

namespace convray::scene {

// A colour at every point that a function reads (`function { pigment { P } }`, and
// `function { pattern { P } }` as a grey): render/ implements it (render/function_sources.hpp)
// and the parser hands it to the compiler, so that this module needs nothing of render/.
class ColorSource {
 public:
  virtual ~ColorSource() = default;
  virtual Color at(const Vec3& point) const = 0;
};

// Which number of a colour `.red`, `.x`, `.gray` ... picks.
enum class ColorComponent : std::uint8_t { red, green, blue, filter, transmit, gray };
double component_of(const Color& color, ColorComponent component);

// POV-Ray's internal functions that convray has: `function { internal(N) }` in functions.inc.
enum class InternalFunction : std::uint8_t {
  rounded_box,  // internal(60): f_rounded_box(x, y, z, radius, half sizes x y z)
  r,            // internal(57): f_r(x, y, z) = |p|
  sphere,       // internal(61): f_sphere(x, y, z, radius) = |p| - radius
  torus,        // internal(70): f_torus(x, y, z, major, minor)
};

// The number convray knows internal(N) by, or false: internal(N) with N from functions.inc.
bool internal_function_of(int pov_number, InternalFunction& out);
// Its arity: x, y, z and the extra parameters functions.inc lists.
int internal_function_arity(InternalFunction f);
double evaluate_internal(InternalFunction f, std::span<const double> arguments);

enum class FunctionOp : std::uint8_t {
  constant,
  parameter,
  add, subtract, multiply, divide, power,  // two operands
  negate, logical_not,                     // one operand
  less, less_equal, greater, greater_equal, equal, not_equal,  // 1 or 0
  logical_and, logical_or,
  conditional,  // operands: condition, when true, when false
  math1,        // one operand through `math1`
  math2,        // two operands through `math2`
  minimum, maximum,  // any number of operands
  select,       // select(a, b, c[, d]): b where a < 0, c where a = 0 (or a >= 0 for 3), d
  call,         // `callee`, the operands as its arguments
  internal,     // `internal_function`, the operands as its arguments
  color,        // `component` of colour source `index` at the operands (x, y, z)
};

struct FunctionNode {
  FunctionOp op = FunctionOp::constant;
  std::uint32_t first = 0, count = 0;  // operands: nodes in Function::operands_
  double value = 0.0;                  // constant
  std::uint32_t index = 0;             // parameter number; callee number
  InternalFunction internal_function = InternalFunction::r;
  ColorComponent component = ColorComponent::red;
  double (*math1)(double) = nullptr;
  double (*math2)(double, double) = nullptr;
};

class Function;
using FunctionPtr = std::shared_ptr<const Function>;

class Function {
 public:
  // The most parameters a function may have (POV-Ray's limit is larger; the examples use 10).
  static constexpr std::size_t kMaxParameters = 32;

  explicit Function(std::vector<std::string> parameters) : parameters_(std::move(parameters)) {}

  const std::vector<std::string>& parameters() const { return parameters_; }

  // `arguments` has one value per parameter.
  double evaluate(std::span<const double> arguments) const { return at(root_, arguments.data()); }
  double operator()(double x, double y, double z) const {
    const double xyz[3] = {x, y, z};
    return at(root_, xyz);
  }

  // --- building (function_compiler.cpp): nodes are added children first.
  std::uint32_t add(FunctionNode node, std::span<const std::uint32_t> operands = {});
  std::uint32_t add_constant(double value);
  std::uint32_t add_callee(FunctionPtr callee);
  std::uint32_t add_color_source(std::shared_ptr<const ColorSource> source);
  void set_root(std::uint32_t node) { root_ = node; }
  // The node's value if it needs no parameter (constant folding), else false.
  bool constant_value(std::uint32_t node, double& out) const;
  const FunctionNode& node(std::uint32_t index) const { return nodes_[index]; }

 private:
  double at(std::uint32_t node, const double* arguments) const;
  double operand(const FunctionNode& n, std::uint32_t i, const double* arguments) const {
    return at(operands_[n.first + i], arguments);
  }

  std::vector<std::string> parameters_;
  std::vector<FunctionNode> nodes_;
  std::vector<std::uint32_t> operands_;
  std::vector<FunctionPtr> callees_;
  std::vector<std::shared_ptr<const ColorSource>> color_sources_;
  std::uint32_t root_ = 0;
};

}  // namespace convray::scene
