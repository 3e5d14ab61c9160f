// Mesh triangles lent to the surface being built (implicit/lent_triangles.hpp): the surface
// of a lent mesh answers exactly as the surface of a copy (field and first hits, bit for bit),
// the lent vector is left empty whether the surface took it whole or made its own arrangement
// of repeats, and what was not lent, or was lent and already taken, is left alone.
#include "implicit/lent_triangles.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "field/threshold.hpp"
#include "implicit/convolution_surface.hpp"
#include "reference/random_vectors.hpp"
#include "test_objects.hpp"

namespace convray::implicit {
namespace {

scene::ConvolutionObject torus_object(bool with_repeats) {
  scene::ConvolutionObject object;
  const double radius = 0.3;
  object.meshes.push_back(test_objects::torus_mesh(16, 8, radius));
  if (with_repeats) {  // three triangles twice more, one of them turned around
    auto& t = object.meshes.front().triangles;
    t.push_back(t[3]);
    t.push_back(t[7]);
    t.push_back({t[11].b, t[11].c, t[11].a});
  }
  object.threshold = field::threshold_for_offset(1.0, radius, 0.5 * radius);
  return object;
}

// The same answers, bit for bit: field values and gradients at random points, first hits.
void expect_same_surface(const ConvolutionSurface& a, const ConvolutionSurface& b) {
  std::mt19937_64 rng(5);
  TraceStats stats;
  for (int k = 0; k < 300; ++k) {
    const Vec3 p = testing::random_point(rng, 1.5);
    EXPECT_EQ(a.field(p).value, b.field(p).value);
    EXPECT_EQ(a.field(p).gradient, b.field(p).gradient);
    const Ray ray{4.0 * testing::random_unit(rng), Vec3(0.0)};
    const Ray aimed{ray.origin, glm::normalize(testing::random_point(rng, 0.8) - ray.origin)};
    const auto ha = a.first_hit(aimed, 0.0, INFINITY, stats);
    const auto hb = b.first_hit(aimed, 0.0, INFINITY, stats);
    ASSERT_EQ(ha.has_value(), hb.has_value());
    if (ha) {
      EXPECT_EQ(ha->t, hb->t);
      EXPECT_EQ(ha->normal, hb->normal);
    }
  }
}

TEST(LentTriangles, ASurfaceTakesALentMeshAndAnswersAsFromACopy) {
  for (const bool repeats : {false, true}) {
    const scene::ConvolutionObject copy = torus_object(repeats);
    scene::ConvolutionObject owned = torus_object(repeats);
    const ConvolutionSurface from_copy(copy);
    std::vector<field::Triangle>& mesh = owned.meshes.front().triangles;
    std::optional<ConvolutionSurface> from_lent;
    {
      const LentTriangles lent({&mesh});
      from_lent.emplace(owned);
    }
    EXPECT_TRUE(mesh.empty()) << "repeats " << repeats;
    EXPECT_EQ(mesh.capacity(), 0u) << "repeats " << repeats;  // freed, not only emptied
    EXPECT_EQ(from_lent->merged_triangle_count(), from_copy.merged_triangle_count());
    EXPECT_EQ(from_copy.merged_triangle_count(), repeats ? 3u : 0u);
    expect_same_surface(*from_lent, from_copy);
  }
}

TEST(LentTriangles, OnlyWhatIsLentIsTakenAndOnlyOnce) {
  scene::ConvolutionObject owned = torus_object(false);
  const scene::ConvolutionObject other = torus_object(false);
  std::vector<field::Triangle>& mesh = owned.meshes.front().triangles;
  const size_t count = mesh.size();
  {
    const LentTriangles lent({&mesh});
    const ConvolutionSurface not_lent(other);  // another vector: copied
    EXPECT_EQ(other.meshes.front().triangles.size(), count);
    EXPECT_EQ(LentTriangles::take(other.meshes.front().triangles), nullptr);
    EXPECT_EQ(LentTriangles::take(mesh), &mesh);  // taken here, so no surface takes it
    EXPECT_EQ(LentTriangles::take(mesh), nullptr);
    const ConvolutionSurface copied(owned);
    EXPECT_EQ(mesh.size(), count);
  }
  EXPECT_EQ(LentTriangles::take(mesh), nullptr);  // the lend ended with its scope
  const ConvolutionSurface after(owned);
  EXPECT_EQ(mesh.size(), count);
}

}  // namespace
}  // namespace convray::implicit
