// Mesh scenes traced like a picture (a pinhole grid of rays, with shadow-ray-like queries
// from the hits), fast path against the exact reference tracer: hit/miss disagreements at
// most 0.05 % of the rays, hit distances within 1e-6 R.
#include <gtest/gtest.h>

#include <string>

#include <cmath>

#include "fixtures/defective_soups.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "field/threshold.hpp"
#include "mesh/procedural.hpp"
#include "scene/mesh_skeleton.hpp"

namespace convray::implicit {
namespace {

scene::MeshComponent component(const mesh::TriangleSoup& soup, double radius) {
  scene::MeshComponent m;
  m.triangles = scene::soup_triangles(soup);
  m.weight = {1.0, radius};
  return m;
}

struct Comparison {
  int rays = 0, disagreements = 0, hits = 0;
  double worst = 0.0;
};

Comparison compare_on_grid(const ConvolutionSurface& surface, double radius, const Vec3& eye,
                           int size) {
  Comparison c;
  TraceStats stats;
  const Vec3 forward = glm::normalize(-eye);
  const Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), forward));
  const Vec3 up = glm::cross(forward, right);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = 0.7 * ((i + 0.5) / size - 0.5), y = 0.7 * ((j + 0.5) / size - 0.5);
      const Ray ray{eye, glm::normalize(forward + x * right + y * up)};
      const auto fast = surface.first_hit(ray, 0.0, INFINITY, stats);
      const auto exact = reference_first_hit(surface, ray, 0.0, INFINITY, stats);
      ++c.rays;
      if (fast.has_value() != exact.has_value()) {
        ++c.disagreements;
        continue;
      }
      if (!fast) continue;
      ++c.hits;
      c.worst = std::max(c.worst, std::abs(fast->t - exact->t) / radius);
      // A secondary ray from just off the surface, as shadows and reflections cast them.
      const Ray bounce{fast->point + 1e-7 * radius * fast->normal,
                       glm::normalize(fast->normal + Vec3(0.3, 0.5, -0.2))};
      const bool blocked = surface.occluded(bounce, 0.0, INFINITY, stats);
      std::vector<double> roots;
      reference_roots(surface, bounce, 0.0, INFINITY, roots, stats);
      ++c.rays;
      if (blocked != !roots.empty()) ++c.disagreements;
    }
  }
  std::printf("rays %d, hits %d, disagreements %d, worst |dt|/R %.3g\n", c.rays, c.hits,
              c.disagreements, c.worst);
  return c;
}

void expect_agreement(const Comparison& c) {
  EXPECT_GT(c.hits, c.rays / 10);
  EXPECT_LE(c.disagreements, c.rays * 5 / 10000 + 1);
  EXPECT_LE(c.worst, 1e-6);
}

// The fast window march and the paper's fits, each against the reference tracer.
class MeshSurfaceTracer : public ::testing::TestWithParam<Tracer> {};

INSTANTIATE_TEST_SUITE_P(Tracers, MeshSurfaceTracer, ::testing::Values(Tracer::fast, Tracer::fits),
                         [](const auto& info) {
                           return std::string(info.param == Tracer::fast ? "WindowMarch" : "Fits");
                         });

TEST_P(MeshSurfaceTracer, TorusAgreesWithTheReference) {
  scene::ConvolutionObject object;
  const double R = 0.3;
  object.meshes.push_back(component(mesh::torus(1.0, 0.35, 24, 12), R));
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  expect_agreement(compare_on_grid(ConvolutionSurface(object, nullptr, GetParam()), R, {0.5, 2.0, -4.0}, 36));
}

TEST_P(MeshSurfaceTracer, DefectiveSoupAndSheetWithHoleAgreeWithTheReference) {
  scene::ConvolutionObject object;
  const double R = 0.25;
  object.meshes.push_back(component(mesh::defective_soup(), R));
  mesh::TriangleSoup sheet = mesh::sheet_with_hole(1.5, 12, 0.5);
  for (Vec3& v : sheet.vertices) v = Vec3(v.x, v.y - 0.0, v.z - 1.4);
  object.meshes.push_back(component(sheet, 0.2));
  object.segments.push_back({{{-1.5, 1.2, 0}, {1.5, 1.2, 0.3}}, {2.0, 0.4}});
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  expect_agreement(compare_on_grid(ConvolutionSurface(object, nullptr, GetParam()), 0.2, {1.0, 1.5, -4.0}, 36));
}

}  // namespace
}  // namespace convray::implicit
