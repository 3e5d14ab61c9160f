#pragma once
// POV-Ray's polynomial surfaces (`poly`, `cubic`, `quartic`, `quadric`): P(x, y, z) = 0 with
// the inside where P < 0, unbounded (scenes bound them with clipped_by or CSG).
//
// Along a ray P is a polynomial in t of the surface's order: each term's powers of
// (o + t d) are multiplied out, its roots isolated on the ray's span (clamped to Cauchy's
// bound on the roots) by the derivatives' roots (polynomial.hpp), and the normal is P's
// gradient.
#include <vector>

#include "core/polynomial_roots.hpp"
#include "geometry/primitive.hpp"

namespace convray::geometry {

class PolynomialSurface final : public Shape {
 public:
  // `coefficients` in POV-Ray's order (scene::Polynomial); order from 1 to
  // kMaxPolynomialDegree.
  PolynomialSurface(int order, std::vector<double> coefficients, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;

 private:
  struct Term {
    int i, j, k;  // exponents of x, y, z
    double c;
  };
  int order_;
  std::vector<Term> terms_;  // the nonzero ones
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
