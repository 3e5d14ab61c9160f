// The window march's certificate (implicit/line_curvature.hpp): each primitive's one-sided
// bounds on f'' over a window of a line, against central second differences of the exact
// field at points of the window, for every kind of primitive and strengths of both signs;
// and, for a plane, against the second derivative of its closed-form field.
#include "implicit/line_curvature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "field/threshold.hpp"
#include "implicit/convolution_surface.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// One primitive of each kind, big and small against R, with strengths of both signs.
scene::ConvolutionObject one_of_each(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  scene::ConvolutionObject o;
  o.points.push_back({point(), {1.3, 0.7}});
  o.blob_spheres.push_back({point(), {-0.8, 0.9}});
  o.blob_cylinders.push_back({point(), point(), {1.1, 0.6}});
  o.segments.push_back({{point(), point()}, {0.9, 0.5}});
  o.segments.push_back({{point(), 5.0 * point()}, {-1.0, 0.4}});  // much longer than 2R
  field::Arc arc;
  if (field::arc_through(point(), point(), 2.0 * point(), arc)) o.arcs.push_back({arc, {1.2, 0.5}});
  scene::MeshComponent small, large;
  small.triangles.push_back({point(), point(), point()});
  small.weight = {1.0, 0.8};
  large.triangles.push_back({4.0 * point(), 4.0 * point(), 4.0 * point()});  // area >> pi R^2
  large.weight = {-0.7, 0.3};
  o.meshes.push_back(small);
  o.meshes.push_back(large);
  o.threshold = 0.5;
  return o;
}

// The central difference's step: it is a weighted mean of f'' over [t - h, t + h], so a bound
// it is held to must cover that stretch (the bounds hold point by point).
constexpr double kDifferenceStep = 1e-4;

// f'' along the ray at t by a central difference (the kernel's second derivative jumps where
// the line leaves a support, where a difference sees a value between the two sides: still
// within the bounds of both).
double second_difference(const ConvolutionSurface::Impl& s, uint32_t id, const Ray& ray,
                         double t) {
  const double h = kDifferenceStep;
  return (s.value(id, ray.at(t + h)) - 2.0 * s.value(id, ray.at(t)) + s.value(id, ray.at(t - h))) /
         (h * h);
}

TEST(LineCurvature, BoundsHoldOverRandomWindowsForEveryKind) {
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  // The largest measured f'' / up and -f'' / down: the bounds must keep both <= 1.
  double tightest_up = 0.0, tightest_down = 0.0;
  for (int object = 0; object < 8; ++object) {
    const ConvolutionSurface surface(one_of_each(rng));
    const ConvolutionSurface::Impl& s = surface.impl();
    for (uint32_t id = 0; id < surface.primitive_count(); ++id) {
      for (int line = 0; line < 200; ++line) {
        const Vec3 near = 1.5 * unit(rng) * random_unit(rng);
        const Ray ray{near - 2.0 * random_unit(rng), random_unit(rng)};
        const double a = 4.0 * unit(rng), b = a + 0.8 * unit(rng) * unit(rng);
        const CurvatureBounds bounds =
            LineCurvature(s, id, ray).over(a - kDifferenceStep, b + kDifferenceStep);
        ASSERT_GE(bounds.up, 0.0);
        ASSERT_GE(bounds.down, 0.0);
        for (int k = 0; k <= 4; ++k) {
          const double second = second_difference(s, id, ray, a + 0.25 * k * (b - a));
          EXPECT_LE(second, bounds.up * (1.0 + 1e-4) + 1e-5) << "primitive " << id;
          EXPECT_GE(second, -bounds.down * (1.0 + 1e-4) - 1e-5) << "primitive " << id;
          if (bounds.up > 0.0) tightest_up = std::max(tightest_up, second / bounds.up);
          if (bounds.down > 0.0) tightest_down = std::max(tightest_down, -second / bounds.down);
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 40000);
  // Bounds far too loose would make the march crawl: random windows come within a factor of
  // a few of both.
  EXPECT_GT(tightest_up, 0.25);
  EXPECT_GT(tightest_down, 0.25);
  std::printf("points %d, largest f''/up %.3f, -f''/down %.3f\n", checked, tightest_up,
              tightest_down);
}

// A triangle far wider than the kernel's ball acts as a plane near its middle, whose field is
// (pi R^2 / 3)(1 - h^2/R^2)^3 at height h: along the normal F'' = -2 pi (1 - x)(1 - 5x),
// x = h^2/R^2, which is -2 pi at h = 0 (the downward bound, 2 pi, is reached) and at most
// 1.6 pi, at x = 0.6 (within the upward bound, 2 pi). Random directions stay within both.
// A segment much longer than 2R, nearly across the line, that the line passes close to near
// one of its ends: there u.x is nearly the same on the part within R, while over the whole
// segment it averages out, so the moments of the whole skeleton bound the integral of (u.x)^2
// over the part within R only when weighed by the whole length (the part's length with the
// whole's mean square is up to three times too small here).
TEST(LineCurvature, LongSegmentNearItsEndUsesTheWholeSkeletonsMoments) {
  const double R = 1.0, L = 20.0;
  const double slope = 1.8 * R / L;  // u.d: u.x changes by 1.8 R along the whole segment
  const Vec3 d(slope, std::sqrt(1.0 - slope * slope), 0.0);
  int checked = 0;
  double tightest = 0.0;
  for (double offset = 0.5; offset <= 0.95; offset += 0.05) {
    // The ray along x passes offset R (along x) from the point 0.5 R short of the end.
    const Vec3 near_end = Vec3(10.0 + offset * R, 0.0, 0.0);
    const Vec3 b = near_end + 0.5 * R * d, a = b - L * d;
    scene::ConvolutionObject object;
    object.segments.push_back({{a, b}, {1.0, R}});
    object.threshold = 0.5;
    const ConvolutionSurface surface(object);
    const ConvolutionSurface::Impl& s = surface.impl();
    const Ray ray{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
    for (double t = 9.0; t <= 11.0; t += 0.05) {
      const double up = LineCurvature(s, 0, ray).up(t - 0.01, t + 0.01);
      const double second = second_difference(s, 0, ray, t);
      EXPECT_LE(second, up * (1.0 + 1e-4) + 1e-6) << "offset " << offset << ", t " << t;
      if (up > 0.0) tightest = std::max(tightest, second / up);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(tightest, 0.2);  // the configuration does load the bound
}

// One triangle far wider than R in the plane z = 0, strength 1.
scene::ConvolutionObject wide_triangle(double R) {
  scene::ConvolutionObject object;
  scene::MeshComponent mesh;
  mesh.triangles.push_back({{-3, -3, 0}, {3, -3, 0}, {0, 3, 0}});
  mesh.weight = {1.0, R};
  object.meshes.push_back(mesh);
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  return object;
}

TEST(LineCurvature, WideTriangleAgainstThePlanesClosedForm) {
  const double R = 0.2;
  const ConvolutionSurface surface(wide_triangle(R));
  const ConvolutionSurface::Impl& s = surface.impl();
  const uint32_t id = s.triangle_base;
  // Along the normal, from below the plane: t is R + h.
  const Ray normal{{0.1, -0.2, -R}, {0, 0, 1}};
  for (double x : {0.0, 0.2, 0.6, 0.9}) {
    const double h = R * std::sqrt(x), t = R + h;
    const double exact = -2.0 * kPi * (1.0 - x) * (1.0 - 5.0 * x);
    EXPECT_NEAR(second_difference(s, id, normal, t), exact, 1e-4) << "x = " << x;
    const CurvatureBounds bounds = LineCurvature(s, id, normal).over(t - 1e-3, t + 1e-3);
    EXPECT_LE(exact, bounds.up);
    EXPECT_GE(exact, -bounds.down * (1.0 + 1e-12));
  }
  EXPECT_NEAR(LineCurvature(s, id, normal).over(R - 1e-3, R + 1e-3).down, 2.0 * kPi, 1e-12);
  std::mt19937_64 rng(73);
  std::uniform_real_distribution<> u(-1.0, 1.0);
  for (int line = 0; line < 3000; ++line) {
    const Ray ray{{u(rng), u(rng), -2.0 * R}, random_unit(rng)};
    const double a = std::abs(u(rng)), b = a + 0.5 * R * std::abs(u(rng));
    const CurvatureBounds bounds =
        LineCurvature(s, id, ray).over(a - kDifferenceStep, b + kDifferenceStep);
    for (double t : {a, 0.5 * (a + b), b}) {
      const double second = second_difference(s, id, ray, t);
      EXPECT_LE(second, bounds.up * (1.0 + 1e-4) + 1e-6) << "line " << line;
      EXPECT_GE(second, -bounds.down * (1.0 + 1e-4) - 1e-6) << "line " << line;
    }
  }
}

// The integral over the whole plane of how far the kernel bends down along u at height h
// (R = 1 units times 1/R^2 and R^2 cancel): [4 (1 - s) - 8 (u.x)^2]^+ over the disk where the
// ball meets the plane, by the midpoint rule in polar coordinates around the foot.
double plane_downward_bend_by_quadrature(double h, const Vec3& u) {
  const int radial = 600, angular = 1200;
  const double rho = std::sqrt(1.0 - h * h);
  double sum = 0.0;
  for (int i = 0; i < radial; ++i) {
    const double r = (i + 0.5) * rho / radial;
    for (int j = 0; j < angular; ++j) {
      const double theta = (j + 0.5) * 2.0 * kPi / angular;
      const Vec3 x(-r * std::cos(theta), -r * std::sin(theta), h);  // p - q, p above the foot
      const double s = glm::dot(x, x), ux = glm::dot(u, x);
      sum += std::max(0.0, 4.0 * (1.0 - s) - 8.0 * ux * ux) * r;
    }
  }
  return sum * (rho / radial) * (2.0 * kPi / angular);
}

// Near the middle of a triangle far wider than R, the downward bound is the plane's own:
// the whole plane's downward bend at the window's height (triangle_down_limit's closed form),
// which quadrature confirms for lines from along the normal to along the plane. It is what
// the plane's field reaches along the normal at h = 0 (-2 pi), and along the plane a line
// that grazes a surface sees 1 / sqrt(3) of it.
TEST(LineCurvature, WideTrianglesDownwardBoundIsThePlanesByQuadrature) {
  const double R = 1.0;
  const ConvolutionSurface surface(wide_triangle(R));
  const ConvolutionSurface::Impl& s = surface.impl();
  const uint32_t id = s.triangle_base;
  for (double normal_part : {0.0, 0.3, 0.6, 0.9, 1.0}) {
    const Vec3 u(std::sqrt(1.0 - normal_part * normal_part), 0.0, normal_part);
    for (double h : {0.0, 0.2, 0.45}) {
      // The line passes height h above the foot (0, -0.5, 0) at t = 1.
      const Ray ray{Vec3(0.0, -0.5, h) - u, u};
      const double down = LineCurvature(s, id, ray).down(1.0, 1.0);
      const double quadrature = plane_downward_bend_by_quadrature(h, u);
      EXPECT_NEAR(down, quadrature, 2e-3 * 2.0 * kPi) << "u_n " << normal_part << ", h " << h;
    }
  }
  const Ray along_plane{{-2.0, -0.5, 0.0}, {1.0, 0.0, 0.0}};
  EXPECT_NEAR(LineCurvature(s, id, along_plane).down(2.0, 2.0), 2.0 * kPi / std::sqrt(3.0),
              1e-12);
}

// The kernel bends down along u only where (1 - s) > 2 (u.x)^2 / R^2, which needs
// |u.x| < R / sqrt(3): a ray approaching a wide triangle along its normal sees no downward
// bend at all while every point of the window lies further than R / sqrt(3) from the plane
// (the plane's F'' = -2 pi (1 - x)(1 - 5 x), x = h^2 / R^2, is positive beyond h = R / sqrt(5)),
// and nearer it the bound still holds the closed form. The weight 4 (1 - s) / R^2 alone gave
// 2 pi (1 - x)^2 there (0.89 pi at x = 1/3, where this bound is 0).
TEST(LineCurvature, NoDownwardBendFurtherThanRootThreeOfRFromAWideTriangle) {
  const double R = 0.2;
  const ConvolutionSurface surface(wide_triangle(R));
  const ConvolutionSurface::Impl& s = surface.impl();
  const uint32_t id = s.triangle_base;
  const Ray normal{{0.1, -0.2, -R}, {0, 0, 1}};  // t = R + h, h the height above the plane
  const double far = R / std::sqrt(3.0);
  for (double h : {0.58 * R, 0.7 * R, 0.9 * R}) {
    ASSERT_GT(h, far);
    EXPECT_EQ(LineCurvature(s, id, normal).down(R + h, R + h + 0.05 * R), 0.0) << h / R;
    EXPECT_EQ(LineCurvature(s, id, normal).down(R - h - 0.05 * R, R - h), 0.0) << h / R;
  }
  for (double x = 0.0; x <= 1.0; x += 1.0 / 64.0) {
    const double h = R * std::sqrt(x), exact = -2.0 * kPi * (1.0 - x) * (1.0 - 5.0 * x);
    const double down = LineCurvature(s, id, normal).down(R + h - 1e-6, R + h + 1e-6);
    EXPECT_GE(exact, -down * (1.0 + 1e-9) - 1e-9) << "x = " << x;
    if (x > 1.0 / 3.0 + 1e-3) EXPECT_EQ(down, 0.0) << "x = " << x;
  }
}

}  // namespace
}  // namespace convray::implicit

namespace convray::implicit {
namespace {

// Triangles wider than R tile a plane (a grid of squares of side 2R, two triangles each): each
// one counts only for its part of the disk where the ball meets the plane, so the sums of the
// bounds over the triangles whose support meets a short window hold the summed field's
// second differences and, at the plane, stay within a factor 6 of the plane's 2 pi, where
// each triangle counted for up to 2 pi would give 16 pi (8 triangles reach a point's ball).
TEST(LineCurvature, WideTrianglesTilingAPlaneCountForTheirPartOfTheDisk) {
  const double R = 0.5, side = 2.0 * R;
  scene::ConvolutionObject object;
  scene::MeshComponent mesh;
  for (int i = -5; i < 5; ++i) {
    for (int j = -5; j < 5; ++j) {
      const Vec3 p(i * side, j * side, 0.0), dx(side, 0, 0), dy(0, side, 0);
      mesh.triangles.push_back({p, p + dx, p + dx + dy});
      mesh.triangles.push_back({p, p + dx + dy, p + dy});
    }
  }
  mesh.weight = {1.0, R};
  object.meshes.push_back(mesh);
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  const ConvolutionSurface surface(object);
  const ConvolutionSurface::Impl& s = surface.impl();
  std::mt19937_64 rng(74);
  std::uniform_real_distribution<> u(-1.0, 1.0);
  double widest_sum_at_plane = 0.0;
  for (int line = 0; line < 400; ++line) {
    const bool along_normal = line % 4 == 0;
    const Vec3 foot(1.5 * u(rng), 1.5 * u(rng), 0.0);
    const Vec3 direction = along_normal ? Vec3(0, 0, 1) : Vec3(random_unit(rng));
    const Ray ray{foot - 2.0 * R * direction, direction};
    // Windows around where the line meets the plane (t = 2R), of length up to R/2.
    const double a = 2.0 * R + R * u(rng), b = a + 0.5 * R * std::abs(u(rng));
    CurvatureBounds sum;
    double second[3] = {0.0, 0.0, 0.0};
    const double at[3] = {a, 0.5 * (a + b), b};
    for (uint32_t id = s.triangle_base; id < surface.primitive_count(); ++id) {
      const CurvatureBounds c =
          LineCurvature(s, id, ray).over(a - kDifferenceStep, b + kDifferenceStep);
      sum.up += c.up;
      sum.down += c.down;
      for (int k = 0; k < 3; ++k) second[k] += second_difference(s, id, ray, at[k]);
    }
    for (double f2 : second) {
      EXPECT_LE(f2, sum.up * (1.0 + 1e-4) + 1e-6) << "line " << line;
      EXPECT_GE(f2, -sum.down * (1.0 + 1e-4) - 1e-6) << "line " << line;
    }
    if (along_normal && a <= 2.0 * R && 2.0 * R <= b && b - a < 0.1 * R) {
      widest_sum_at_plane = std::max(widest_sum_at_plane, sum.down);
    }
  }
  std::printf("largest downward sum at the plane: %.2f pi\n", widest_sum_at_plane / kPi);
  EXPECT_GT(widest_sum_at_plane, 0.0);
  EXPECT_LT(widest_sum_at_plane, 6.0 * 2.0 * kPi);
}

}  // namespace
}  // namespace convray::implicit
