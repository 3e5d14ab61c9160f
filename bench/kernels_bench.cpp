// Field evaluations per second under the two kernels (docs/kernels.md): the paper's quartic
// (1 - r^2/R^2)^2 and McCormack and Sherstyuk's Cauchy kernel 1 / (1 + s^2 r^2)^2, as the
// paper's Fig. 6 compares them (one triangle, 165 M/s for Cauchy and 150-223 M/s for theirs
// on a Pentium 4), and through a whole mesh object (scenes/models/soup.obj, every triangle's
// support or truncation box asked through the object's point query). One core.
// Run: build/bench/kernels_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "field/cauchy.hpp"
#include "field/triangle.hpp"
#include "implicit/cauchy_surface.hpp"
#include "implicit/convolution_surface.hpp"
#include "mesh/load.hpp"

namespace {

using convray::Vec3;
using convray::field::Triangle;

constexpr size_t kPoints = 4096;
// The triangle of scenes/kernels/triangle.pov, with its quartic radius and Cauchy sharpness.
const Triangle kTriangle{{-0.8, 0.0, -0.5}, {0.8, 0.0, -0.5}, {0.1, 0.0, 0.8}};
constexpr double kQuarticRadius = 0.25;
constexpr double kCauchySharpness = 4.0;

// Points spread through a box around `bounds`, where a renderer asks for the field.
std::vector<Vec3> points_in(const convray::Box3& bounds) {
  std::mt19937_64 rng(42);
  std::vector<Vec3> points;
  for (size_t i = 0; i < kPoints; ++i) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      p[k] = std::uniform_real_distribution<double>(bounds.lo[k], bounds.hi[k])(rng);
    }
    points.push_back(p);
  }
  return points;
}

// The triangle's box grown by the quartic radius: where its quartic field can be non-zero.
convray::Box3 triangle_region() {
  convray::Box3 box;
  for (const Vec3& v : {kTriangle.a, kTriangle.b, kTriangle.c}) box.extend(v);
  box.lo -= Vec3(kQuarticRadius);
  box.hi += Vec3(kQuarticRadius);
  return box;
}

template <class Evaluate>
void per_point(benchmark::State& state, const std::vector<Vec3>& points, Evaluate&& evaluate) {
  for (auto _ : state) {
    double sum = 0.0;
    for (const Vec3& p : points) sum += evaluate(p);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(points.size()));
}

void BM_TriangleQuarticValue(benchmark::State& state) {
  per_point(state, points_in(triangle_region()), [](const Vec3& p) {
    return convray::field::triangle_value(p, kTriangle, kQuarticRadius);
  });
}
void BM_TriangleCauchyValue(benchmark::State& state) {
  per_point(state, points_in(triangle_region()), [](const Vec3& p) {
    return convray::field::cauchy_triangle_value(p, kTriangle, kCauchySharpness);
  });
}
void BM_TriangleQuarticField(benchmark::State& state) {
  per_point(state, points_in(triangle_region()), [](const Vec3& p) {
    return convray::field::triangle_field(p, kTriangle, kQuarticRadius).gradient.x;
  });
}
void BM_TriangleCauchyField(benchmark::State& state) {
  per_point(state, points_in(triangle_region()), [](const Vec3& p) {
    return convray::field::cauchy_triangle_field(p, kTriangle, kCauchySharpness).gradient.x;
  });
}

// The soup of scenes/kernels/model.pov under either kernel.
convray::scene::ConvolutionObject soup_object(bool cauchy) {
  const auto loaded = convray::mesh::load_mesh(CONVRAY_SOURCE_DIR "/scenes/models/soup.obj");
  convray::scene::MeshComponent mesh;
  for (const auto& t : loaded.soup.triangles) {
    const auto& v = loaded.soup.vertices;
    mesh.triangles.push_back({v[t[0]], v[t[1]], v[t[2]]});
  }
  mesh.weight = {1.0, 0.4};
  convray::scene::ConvolutionObject object;
  object.meshes.push_back(mesh);
  if (cauchy) object.kernel = {convray::field::KernelType::cauchy, kCauchySharpness};
  return object;
}

// Field queries through the whole object, and the triangles each query evaluates on average
// (counted once in set-up), so the rate per triangle can be compared with the single one.
template <class Surface>
void whole_mesh(benchmark::State& state, const Surface& surface) {
  const auto points = points_in(surface.bounds());
  std::vector<convray::implicit::ComponentValue> values;
  for (const Vec3& p : points) surface.component_values(p, values);
  per_point(state, points, [&](const Vec3& p) { return surface.field(p).value; });
  state.counters["triangles_per_query"] = double(values.size()) / double(points.size());
  state.counters["triangle_evaluations_per_s"] =
      benchmark::Counter(double(values.size()) / double(points.size()) *
                             double(state.iterations()) * double(points.size()),
                         benchmark::Counter::kIsRate);
}

void BM_MeshQuarticField(benchmark::State& state) {
  const convray::implicit::ConvolutionSurface surface(soup_object(false));
  whole_mesh(state, surface);
}
void BM_MeshCauchyField(benchmark::State& state) {
  const convray::implicit::CauchySurface surface(soup_object(true));
  whole_mesh(state, surface);
}

}  // namespace

BENCHMARK(BM_TriangleQuarticValue);
BENCHMARK(BM_TriangleCauchyValue);
BENCHMARK(BM_TriangleQuarticField);
BENCHMARK(BM_TriangleCauchyField);
BENCHMARK(BM_MeshQuarticField);
BENCHMARK(BM_MeshCauchyField);
BENCHMARK_MAIN();
