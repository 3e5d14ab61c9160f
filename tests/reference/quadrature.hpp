#pragma once
// Generic numerical quadrature for the reference fields: adaptive Gauss-Kronrod (G7-K15) in one
// dimension and fixed Gauss-Legendre rules. Nothing here knows about convolution kernels; the
// reference fields (reference_fields.hpp) are built on top of it, independently of src/field.
#include <functional>
#include <span>

#include <glm/glm.hpp>

namespace convray::reference {

// Four integrands at once: the field value and the three components of its gradient.
using Vec4 = glm::dvec4;
using Integrand4 = std::function<Vec4(double)>;

struct QuadratureResult {
  Vec4 integral{0.0};
  double error_estimate = 0.0;  // sum over the final intervals of max_k |K15_k - G7_k|
  int evaluations = 0;
  bool converged = false;  // error_estimate <= the requested tolerance
};

// Integrates f over [lo, hi]. The interval is first split at every breakpoint that lies
// strictly inside it (kinks of the integrand belong there; order and duplicates do not matter),
// then the interval with the largest error estimate is bisected until the summed estimate is at
// most abs_tolerance or max_intervals is reached. The error estimate |K15 - G7| is the
// conservative one (no QUADPACK rescaling), taken as the maximum over the four components.
QuadratureResult integrate_adaptive(const Integrand4& f, double lo, double hi,
                                    std::span<const double> breakpoints, double abs_tolerance,
                                    int max_intervals = 20000);

// n-point Gauss-Legendre rule on [-1, 1]: exact for polynomials of degree 2n - 1.
struct GaussLegendreRule {
  std::span<const double> nodes;
  std::span<const double> weights;
};
// Available orders: 4 and 8.
GaussLegendreRule gauss_legendre(int points);

}  // namespace convray::reference
