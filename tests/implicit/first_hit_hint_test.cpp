// A first hit with a normal ends its first chunk just past the last hit of its run of coherent
// rays (surface_roots.cpp's hinted_first_chunk, core/coherent_rays.hpp). The hint may only
// change how much is gathered: every hinted answer is checked against the same ray searched
// in a fresh run (no hint) and against the first of all its roots (no chunks at all).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/coherent_rays.hpp"
#include "field/threshold.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/surface_impl.hpp"
#include "test_objects.hpp"

namespace convray::implicit {
namespace {

constexpr double kRadius = 0.3;

// A dense torus: many supports a line, so its first-hit searches gather in chunks.
ConvolutionSurface dense_torus() {
  scene::ConvolutionObject object;
  object.meshes.push_back(test_objects::torus_mesh(96, 48, kRadius));
  object.threshold = field::threshold_for_offset(1.0, kRadius, 0.5 * kRadius);
  return ConvolutionSurface(object, nullptr, Tracer::fast);
}

struct Answer {
  std::optional<double> t;
  uint64_t primitives = 0;
};

Answer first_hit(const ConvolutionSurface& surface, const Ray& ray) {
  TraceStats stats;
  const auto hit = surface.first_hit(ray, 0.0, INFINITY, stats);
  return {hit ? std::optional<double>(hit->t) : std::nullopt, stats.primitives};
}

Answer fresh_first_hit(const ConvolutionSurface& surface, const Ray& ray) {
  begin_coherent_rays();
  return first_hit(surface, ray);
}

std::optional<double> first_root(const ConvolutionSurface& surface, const Ray& ray) {
  TraceStats stats;
  std::vector<double> roots;
  surface.roots(ray, 0.0, INFINITY, roots, stats);
  return roots.empty() ? std::nullopt : std::optional<double>(roots.front());
}

void expect_same(const std::optional<double>& a, const std::optional<double>& b, int ray) {
  ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << ray;
  if (a) EXPECT_NEAR(*a, *b, 1e-8 * kRadius) << "ray " << ray;
}

// A camera's grid of rays in pixel order, all in one run: the hinted hits are the unhinted
// ones, and the hints gathered fewer supports.
TEST(FirstHitHint, CoherentGridFindsWhatFreshSearchesFind) {
  const ConvolutionSurface surface = dense_torus();
  ASSERT_TRUE(surface.impl().gather_in_chunks);
  const Vec3 eye{0.4, 2.5, -4.0};
  const Vec3 forward = glm::normalize(-eye);
  const Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), forward));
  const Vec3 up = glm::cross(forward, right);
  const int size = 40;
  std::vector<Ray> rays;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = 0.8 * ((i + 0.5) / size - 0.5), y = 0.8 * ((j + 0.5) / size - 0.5);
      rays.push_back({eye, glm::normalize(forward + x * right + y * up)});
    }
  }
  begin_coherent_rays();
  std::vector<Answer> hinted;
  for (const Ray& ray : rays) hinted.push_back(first_hit(surface, ray));
  uint64_t hinted_primitives = 0, fresh_primitives = 0;
  int hits = 0;
  for (size_t k = 0; k < rays.size(); ++k) {
    const Answer fresh = fresh_first_hit(surface, rays[k]);
    expect_same(hinted[k].t, fresh.t, int(k));
    expect_same(hinted[k].t, first_root(surface, rays[k]), int(k));
    hinted_primitives += hinted[k].primitives;
    fresh_primitives += fresh.primitives;
    hits += fresh.t.has_value();
  }
  EXPECT_GT(hits, int(rays.size()) / 4);
  EXPECT_LT(hinted_primitives, fresh_primitives);
}

// Hints that mislead: each ray follows, in its run, a hit at a random point it passes near,
// so its hint lies before its own hit, past it, or where it misses the surface altogether.
TEST(FirstHitHint, MisleadingHintsChangeNothing) {
  const ConvolutionSurface surface = dense_torus();
  std::mt19937_64 rng(1507);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double reach = surface.impl().min_chunk;
  int used = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 eye = 4.0 * glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
    const Ray hint_ray{eye, glm::normalize(0.8 * Vec3(unit(rng), unit(rng), unit(rng)) - eye)};
    begin_coherent_rays();
    const Answer hint = first_hit(surface, hint_ray);
    if (!hint.t) continue;
    const Vec3 near = hint_ray.at(*hint.t) +
                      0.7 * reach * Vec3(unit(rng), unit(rng), unit(rng)) / std::sqrt(3.0);
    const Vec3 origin = eye + 0.1 * Vec3(unit(rng), unit(rng), unit(rng));
    const Ray ray{origin, glm::normalize(near - origin)};
    const Answer hinted = first_hit(surface, ray);
    const Answer fresh = fresh_first_hit(surface, ray);
    expect_same(hinted.t, fresh.t, k);
    expect_same(hinted.t, first_root(surface, ray), k);
    used += hinted.primitives != fresh.primitives;
  }
  EXPECT_GT(used, 100);  // the hints did change what was gathered
}

}  // namespace
}  // namespace convray::implicit
