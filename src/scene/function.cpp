#include "scene/function.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace convray::scene {

std::uint32_t Function::add(FunctionNode node, std::span<const std::uint32_t> operands) {
  node.first = std::uint32_t(operands_.size());
  node.count = std::uint32_t(operands.size());
  operands_.insert(operands_.end(), operands.begin(), operands.end());
  nodes_.push_back(node);
  return std::uint32_t(nodes_.size() - 1);
}

std::uint32_t Function::add_constant(double value) {
  FunctionNode node;
  node.op = FunctionOp::constant;
  node.value = value;
  return add(node);
}

std::uint32_t Function::add_callee(FunctionPtr callee) {
  callees_.push_back(std::move(callee));
  return std::uint32_t(callees_.size() - 1);
}

std::uint32_t Function::add_color_source(std::shared_ptr<const ColorSource> source) {
  color_sources_.push_back(std::move(source));
  return std::uint32_t(color_sources_.size() - 1);
}

double component_of(const Color& color, ColorComponent component) {
  switch (component) {
    case ColorComponent::red: return color.rgb.r;
    case ColorComponent::green: return color.rgb.g;
    case ColorComponent::blue: return color.rgb.b;
    case ColorComponent::filter: return color.filter;
    case ColorComponent::transmit: return color.transmit;
    case ColorComponent::gray:
      // POV-Ray's grey of a colour (reference manual, colour operators).
      return 0.297 * color.rgb.r + 0.589 * color.rgb.g + 0.114 * color.rgb.b;
  }
  return 0.0;
}

bool Function::constant_value(std::uint32_t node, double& out) const {
  const FunctionNode& n = nodes_[node];
  if (n.op == FunctionOp::parameter || n.op == FunctionOp::color) {
    // A colour source's colour at a constant point could be folded too; it is rare.
    return false;
  }
  if (n.op == FunctionOp::constant) {
    out = n.value;
    return true;
  }
  for (std::uint32_t i = 0; i < n.count; ++i) {
    double ignored = 0.0;
    if (!constant_value(operands_[n.first + i], ignored)) return false;
  }
  out = at(node, nullptr);  // no operand reads a parameter
  return true;
}

double Function::at(std::uint32_t index, const double* arguments) const {
  const FunctionNode& n = nodes_[index];
  const auto a = [&](std::uint32_t i) { return operand(n, i, arguments); };
  switch (n.op) {
    case FunctionOp::constant:
      return n.value;
    case FunctionOp::parameter:
      return arguments[n.index];
    case FunctionOp::add:
      return a(0) + a(1);
    case FunctionOp::subtract:
      return a(0) - a(1);
    case FunctionOp::multiply:
      return a(0) * a(1);
    case FunctionOp::divide:
      return a(0) / a(1);
    case FunctionOp::power:
      return std::pow(a(0), a(1));
    case FunctionOp::negate:
      return -a(0);
    case FunctionOp::logical_not:
      return a(0) == 0.0 ? 1.0 : 0.0;
    case FunctionOp::less:
      return a(0) < a(1) ? 1.0 : 0.0;
    case FunctionOp::less_equal:
      return a(0) <= a(1) ? 1.0 : 0.0;
    case FunctionOp::greater:
      return a(0) > a(1) ? 1.0 : 0.0;
    case FunctionOp::greater_equal:
      return a(0) >= a(1) ? 1.0 : 0.0;
    case FunctionOp::equal:
      return a(0) == a(1) ? 1.0 : 0.0;
    case FunctionOp::not_equal:
      return a(0) != a(1) ? 1.0 : 0.0;
    case FunctionOp::logical_and:
      return a(0) != 0.0 && a(1) != 0.0 ? 1.0 : 0.0;
    case FunctionOp::logical_or:
      return a(0) != 0.0 || a(1) != 0.0 ? 1.0 : 0.0;
    case FunctionOp::conditional:
      return a(0) != 0.0 ? a(1) : a(2);
    case FunctionOp::math1:
      return n.math1(a(0));
    case FunctionOp::math2:
      return n.math2(a(0), a(1));
    case FunctionOp::minimum:
    case FunctionOp::maximum: {
      double result = a(0);
      for (std::uint32_t i = 1; i < n.count; ++i) {
        result = n.op == FunctionOp::minimum ? std::min(result, a(i)) : std::max(result, a(i));
      }
      return result;
    }
    case FunctionOp::select: {
      const double s = a(0);
      if (n.count == 3) return s < 0.0 ? a(1) : a(2);
      return s < 0.0 ? a(1) : s == 0.0 ? a(2) : a(3);
    }
    case FunctionOp::color:
      return component_of(color_sources_[n.index]->at(Vec3(a(0), a(1), a(2))), n.component);
    case FunctionOp::call:
    case FunctionOp::internal: {
      std::array<double, kMaxParameters> values{};
      for (std::uint32_t i = 0; i < n.count; ++i) values[i] = a(i);
      const std::span<const double> passed(values.data(), n.count);
      if (n.op == FunctionOp::call) return callees_[n.index]->evaluate(passed);
      return evaluate_internal(n.internal_function, passed);
    }
  }
  return 0.0;
}

}  // namespace convray::scene
