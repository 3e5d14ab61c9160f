// The window march's vectorized downward curvature sums (implicit/down_bend_table.hpp)
// (filled as the march fills it: a triangle's terms made without a LineCurvature) against
// their scalar twin: LineCurvature::down (and down_anywhere) of each member whose
// support meets the window, summed member after member. The same bits are expected: the
// lanes compute the very formula (triangle_reach.hpp) and the sum keeps the members' order.
// That the twin bounds the field's second derivative is line_curvature_test.cpp's part.
#include "implicit/down_bend_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "implicit/convolution_surface.hpp"
#include "reference/random_vectors.hpp"

namespace convray::implicit {
namespace {

using testing::random_point;
using testing::random_unit;

// Primitives of every kind with positive strengths, and triangles small and large against R,
// among them one without area (it bends nothing).
scene::ConvolutionObject mixed_object(std::mt19937_64& rng) {
  auto point = [&] { return random_point(rng, 1.0); };
  scene::ConvolutionObject o;
  for (int i = 0; i < 3; ++i) o.points.push_back({point(), {0.7, 0.5 + 0.3 * i}});
  o.blob_spheres.push_back({point(), {0.8, 0.9}});
  o.blob_cylinders.push_back({point(), point(), {1.1, 0.6}});
  o.segments.push_back({{point(), 3.0 * point()}, {0.9, 0.5}});
  field::Arc arc;
  if (field::arc_through(point(), point(), 2.0 * point(), arc)) o.arcs.push_back({arc, {1.2, 0.5}});
  scene::MeshComponent small, large;
  for (int i = 0; i < 40; ++i) {
    const Vec3 p = point();
    small.triangles.push_back({p, p + 0.3 * point(), p + 0.3 * point()});
  }
  small.triangles.push_back({Vec3(0.1), Vec3(0.2), Vec3(0.3)});  // collinear: no area
  small.weight = {1.0, 0.4};
  for (int i = 0; i < 5; ++i) {
    large.triangles.push_back({3.0 * point(), 3.0 * point(), 3.0 * point()});
  }
  large.weight = {0.6, 0.7};
  o.meshes.push_back(small);
  o.meshes.push_back(large);
  o.threshold = 0.5;
  return o;
}

TEST(DownBendTable, SumsEqualTheScalarBoundsMemberByMember) {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int windows = 0, with_members = 0;
  for (int object = 0; object < 4; ++object) {
    const ConvolutionSurface surface(mixed_object(rng));
    const ConvolutionSurface::Impl& s = surface.impl();
    for (int line = 0; line < 60; ++line) {
      const Vec3 direction = random_unit(rng);
      const Ray ray{random_point(rng, 1.0) - 4.0 * direction, direction};
      std::vector<accel::SupportInterval> members;
      s.index->intersect(ray.origin, ray.direction, -kInfinity, kInfinity, members);
      std::sort(members.begin(), members.end(),
                [](const auto& a, const auto& b) { return a.enter < b.enter; });
      std::vector<LineCurvature> bounds;
      std::vector<LineCurvature::DownTerms> terms_of;
      DownBendTable table;
      table.reset(members.size());
      for (size_t k = 0; k < members.size(); ++k) {
        const uint32_t id = members[k].primitive;
        bounds.emplace_back(s, id, ray);
        LineCurvature::DownTerms terms = bounds.back().down_terms();
        if (id >= s.triangle_base) {  // as the march makes them, without a LineCurvature
          const uint32_t i = id - s.triangle_base;
          const auto& group = s.group_of(i);
          terms = LineCurvature::triangle_down_terms(s.triangles[i], s.frames[i], group.strength,
                                                     group.radius, ray);
        }
        table.add(members[k].enter, members[k].exit, terms);
        terms_of.push_back(terms);
      }
      ASSERT_EQ(table.size(), members.size());
      for (int w = 0; w < 25; ++w) {
        const double a = 8.0 * unit(rng), b = a + (w % 5 == 0 ? 2.0 : 0.3) * unit(rng);
        double exact = 0.0, anywhere = 0.0;
        for (size_t k = 0; k < members.size(); ++k) {
          if (members[k].enter > b || members[k].exit < a) continue;
          exact += bounds[k].down(a, b);
          anywhere += bounds[k].down_anywhere();
        }
        EXPECT_EQ(table.sum(a, b, false), exact) << "object " << object << " line " << line;
        // Holding only the members that enter by b (as the march adds them) changes nothing.
        DownBendTable entered;
        entered.reset(members.size());
        for (size_t k = 0; k < members.size() && members[k].enter <= b; ++k) {
          entered.add(members[k].enter, members[k].exit, terms_of[k]);
        }
        EXPECT_EQ(entered.sum(a, b, false), exact) << "object " << object << " line " << line;
        EXPECT_EQ(entered.sum(a, b, true), table.sum(a, b, true));
        EXPECT_EQ(table.sum(a, b, true), anywhere) << "object " << object << " line " << line;
        EXPECT_LE(exact, anywhere * (1.0 + 1e-12));
        ++windows;
        if (exact > 0.0) ++with_members;
      }
    }
  }
  EXPECT_GT(with_members, windows / 4);  // the windows do meet supports
}

}  // namespace
}  // namespace convray::implicit
