#include "scene/transform.hpp"

#include <cmath>
#include <stdexcept>

namespace convray::scene {

Transform::Transform(const glm::dmat4& forward, const glm::dmat4& backward)
    : forward_(forward), backward_(backward), identity_(forward == glm::dmat4(1.0)) {}

Transform Transform::translation(const Vec3& offset) {
  glm::dmat4 f(1.0), b(1.0);
  f[3] = glm::dvec4(offset, 1.0);
  b[3] = glm::dvec4(-offset, 1.0);
  return Transform(f, b);
}

namespace {

// POV-Ray's rotation about one axis (left-handed): with row vectors p' = p M, about y by a,
// x' = x cos a + z sin a, z' = -x sin a + z cos a. As a column-vector matrix that is the
// transpose; cyclic for x (y, z) and z (x, y).
glm::dmat4 axis_rotation(int axis, double degrees) {
  const double a = degrees * kPi / 180.0;
  // Exact quarter turns keep exact zeros: rotate 90*y must not leave 6e-17 behind.
  double c = std::cos(a), s = std::sin(a);
  const double quarters = degrees / 90.0;
  if (quarters == std::round(quarters)) {
    const int q = ((int(std::round(quarters)) % 4) + 4) % 4;
    const double cs[4] = {1.0, 0.0, -1.0, 0.0}, sn[4] = {0.0, 1.0, 0.0, -1.0};
    c = cs[q];
    s = sn[q];
  }
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane turned: (y,z), (z,x), (x,y)
  glm::dmat4 m(1.0);
  // GLM indexes m[column][row]; for axis y (i = z, j = x) this gives x' = c x + s z and
  // z' = -s x + c z, POV-Ray's formula above.
  m[i][i] = c;
  m[j][j] = c;
  m[i][j] = s;   // column i, row j: x'_j gets s * p_i
  m[j][i] = -s;  // column j, row i: x'_i gets -s * p_j
  return m;
}

}  // namespace

Transform Transform::rotation(const Vec3& degrees) {
  glm::dmat4 f(1.0);
  for (int axis = 0; axis < 3; ++axis) {
    if (degrees[axis] != 0.0) f = axis_rotation(axis, degrees[axis]) * f;
  }
  return Transform(f, glm::transpose(f));
}

Transform Transform::scaling(const Vec3& factors) {
  if (factors.x == 0.0 || factors.y == 0.0 || factors.z == 0.0) {
    throw std::invalid_argument("scale by zero");
  }
  glm::dmat4 f(1.0), b(1.0);
  for (int k = 0; k < 3; ++k) {
    f[k][k] = factors[k];
    b[k][k] = 1.0 / factors[k];
  }
  return Transform(f, b);
}

Transform Transform::matrix(const std::array<double, 12>& m) {
  glm::dmat4 f(1.0);
  // Row r of POV-Ray's matrix is what x, y, z (r = 0, 1, 2) become: column r in GLM's form.
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 3; ++c) f[r][c] = m[size_t(3 * r + c)];
  }
  const double det = glm::determinant(glm::dmat3(f));
  if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) {
    throw std::invalid_argument("singular matrix");
  }
  return Transform(f, glm::inverse(f));
}

Transform Transform::then(const Transform& next) const {
  if (identity_) return next;
  if (next.identity_) return *this;
  return Transform(next.forward_ * forward_, backward_ * next.backward_);
}

Transform Transform::inverse() const { return Transform(backward_, forward_); }

Vec3 Transform::point(const Vec3& p) const {
  return identity_ ? p : Vec3(forward_ * glm::dvec4(p, 1.0));
}
Vec3 Transform::vector(const Vec3& v) const {
  return identity_ ? v : Vec3(forward_ * glm::dvec4(v, 0.0));
}
Vec3 Transform::normal(const Vec3& n) const {
  return identity_ ? n : Vec3(glm::transpose(backward_) * glm::dvec4(n, 0.0));
}
Vec3 Transform::inverse_point(const Vec3& p) const {
  return identity_ ? p : Vec3(backward_ * glm::dvec4(p, 1.0));
}
Vec3 Transform::inverse_vector(const Vec3& v) const {
  return identity_ ? v : Vec3(backward_ * glm::dvec4(v, 0.0));
}

bool Transform::is_similarity(double tolerance) const {
  const glm::dmat3 l(forward_);
  const glm::dmat3 g = glm::transpose(l) * l;  // s^2 I for a scaled rotation
  const double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::abs(g[i][j] - (i == j ? s2 : 0.0)) > tolerance * s2) return false;
    }
  }
  return true;
}

double Transform::uniform_scale() const {
  return std::cbrt(std::abs(glm::determinant(glm::dmat3(forward_))));
}

}  // namespace convray::scene
