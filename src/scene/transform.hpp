#pragma once
// An affine transform from an object's own space to the space it is placed in, kept together
// with its inverse so that rays and points can go both ways without inverting per query.
//
// POV-Ray's conventions (left-handed coordinates): points are row vectors transformed as
// p' = p M, and `translate`, `rotate`, `scale`, `matrix` each append to the transform already
// there. `rotate <a, b, c>` turns about x by a degrees, then y by b, then z by c; about y,
// <1, 0, 0> rotated by 90 degrees becomes <0, 0, -1>.
#include <array>

#include <glm/glm.hpp>

#include "util/math.hpp"

namespace convray::scene {

class Transform {
 public:
  Transform() = default;

  static Transform translation(const Vec3& offset);
  static Transform rotation(const Vec3& degrees);  // x, then y, then z, as POV-Ray
  static Transform scaling(const Vec3& factors);   // throws std::invalid_argument on a zero factor
  // POV-Ray's `matrix <m00, m01, m02, m10, m11, m12, m20, m21, m22, m30, m31, m32>`: the first
  // three rows are the linear part (row vectors), the last the translation. Throws
  // std::invalid_argument when the linear part is singular.
  static Transform matrix(const std::array<double, 12>& m);

  // `this` followed by `next`: p -> next(this(p)).
  Transform then(const Transform& next) const;
  Transform inverse() const;

  Vec3 point(const Vec3& p) const;           // object -> placed space
  Vec3 vector(const Vec3& v) const;          // directions: no translation
  Vec3 normal(const Vec3& n) const;          // inverse transpose; not normalised
  Vec3 inverse_point(const Vec3& p) const;   // placed -> object space
  Vec3 inverse_vector(const Vec3& v) const;

  bool is_identity() const { return identity_; }
  // The linear part is a rotation times a uniform scale (rays keep their shape, spheres stay
  // spheres); `uniform_scale()` is then that scale factor.
  bool is_similarity(double tolerance = 1e-12) const;
  double uniform_scale() const;

  // Column-major 4x4 matrices acting on column vectors (GLM's convention): forward() maps
  // object -> placed space.
  const glm::dmat4& forward() const { return forward_; }
  const glm::dmat4& backward() const { return backward_; }

 private:
  Transform(const glm::dmat4& forward, const glm::dmat4& backward);

  glm::dmat4 forward_{1.0};
  glm::dmat4 backward_{1.0};
  bool identity_ = true;
};

}  // namespace convray::scene
