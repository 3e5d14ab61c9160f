#include "reference/quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <vector>

namespace convray::reference {
namespace {

// Kronrod 15-point nodes (non-negative half) and weights; the odd-indexed nodes are the
// 7-point Gauss nodes, with the Gauss weights below (QUADPACK's qk15 table).
constexpr std::array<double, 8> kKronrodNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

constexpr std::array<double, 4> kLegendre4Nodes = {-0.861136311594052575223946488892809,
                                                   -0.339981043584856264802665759103245,
                                                   0.339981043584856264802665759103245,
                                                   0.861136311594052575223946488892809};
constexpr std::array<double, 4> kLegendre4Weights = {
    0.347854845137453857373063949221999, 0.652145154862546142626936050778001,
    0.652145154862546142626936050778001, 0.347854845137453857373063949221999};
constexpr std::array<double, 8> kLegendre8Nodes = {
    -0.960289856497536231683560868569473, -0.796666477413626739591553936475830,
    -0.525532409916328985817739049189246, -0.183434642495649804939476142360184,
    0.183434642495649804939476142360184,  0.525532409916328985817739049189246,
    0.796666477413626739591553936475830,  0.960289856497536231683560868569473};
constexpr std::array<double, 8> kLegendre8Weights = {
    0.101228536290376259152531354309962, 0.222381034453374470544355994426241,
    0.313706645877887287337962201986601, 0.362683783378361982965150449277196,
    0.362683783378361982965150449277196, 0.313706645877887287337962201986601,
    0.222381034453374470544355994426241, 0.101228536290376259152531354309962};

struct Piece {
  double lo, hi;
  Vec4 integral;
  double error;
  bool operator<(const Piece& other) const { return error < other.error; }
};

// One G7-K15 step on [lo, hi].
Piece integrate_piece(const Integrand4& f, double lo, double hi) {
  const double center = 0.5 * (lo + hi);
  const double half = 0.5 * (hi - lo);
  const Vec4 f_center = f(center);
  Vec4 kronrod = kKronrodWeights[7] * f_center;
  Vec4 gauss = kGaussWeights[3] * f_center;
  for (int i = 0; i < 7; ++i) {
    const double dx = half * kKronrodNodes[i];
    const Vec4 pair = f(center - dx) + f(center + dx);
    kronrod += kKronrodWeights[i] * pair;
    if (i % 2 == 1) gauss += kGaussWeights[i / 2] * pair;
  }
  const Vec4 difference = glm::abs(kronrod - gauss) * std::abs(half);
  const double error = std::max(std::max(difference.x, difference.y),
                                std::max(difference.z, difference.w));
  return {lo, hi, kronrod * half, error};
}

}  // namespace

QuadratureResult integrate_adaptive(const Integrand4& f, double lo, double hi,
                                    std::span<const double> breakpoints, double abs_tolerance,
                                    int max_intervals) {
  QuadratureResult result;
  if (!(hi > lo)) return result.converged = true, result;

  // Split at the breakpoints strictly inside (lo, hi).
  std::vector<double> cuts{lo};
  for (double b : breakpoints)
    if (b > lo && b < hi) cuts.push_back(b);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  std::priority_queue<Piece> pieces;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    pieces.push(integrate_piece(f, cuts[i], cuts[i + 1]));
    result.evaluations += 15;
  }

  // Bisect the worst piece until the summed estimate meets the tolerance.
  auto summed_error = [&pieces] {
    auto copy = pieces;
    double sum = 0.0;
    for (; !copy.empty(); copy.pop()) sum += copy.top().error;
    return sum;
  };
  double total_error = summed_error();
  while (total_error > abs_tolerance && static_cast<int>(pieces.size()) < max_intervals) {
    const Piece worst = pieces.top();
    const double middle = 0.5 * (worst.lo + worst.hi);
    if (!(middle > worst.lo && middle < worst.hi)) break;  // no room left to bisect
    pieces.pop();
    const Piece left = integrate_piece(f, worst.lo, middle);
    const Piece right = integrate_piece(f, middle, worst.hi);
    result.evaluations += 30;
    total_error += left.error + right.error - worst.error;
    pieces.push(left);
    pieces.push(right);
    if (total_error <= abs_tolerance) total_error = summed_error();  // drop accumulated drift
  }

  // Sum the pieces smallest first for a clean total.
  std::vector<Piece> all;
  for (; !pieces.empty(); pieces.pop()) all.push_back(pieces.top());
  std::sort(all.begin(), all.end(), [](const Piece& x, const Piece& y) { return x.lo < y.lo; });
  for (const Piece& piece : all) {
    result.integral += piece.integral;
    result.error_estimate += piece.error;
  }
  result.converged = result.error_estimate <= abs_tolerance;
  return result;
}

GaussLegendreRule gauss_legendre(int points) {
  if (points == 4) return {kLegendre4Nodes, kLegendre4Weights};
  if (points == 8) return {kLegendre8Nodes, kLegendre8Weights};
  throw std::invalid_argument("gauss_legendre: only 4 and 8 points are tabulated");
}

}  // namespace convray::reference
