// Triangle-field evaluations per second on one core: scalar (the exact twin) and batched
// (SIMD lanes over triangles), for triangles wholly inside the support sphere and for
// triangles clipped by it. Run: build/bench/field_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "field/segment.hpp"
#include "field/segment_batch.hpp"
#include "field/triangle.hpp"
#include "field/triangle_batch.hpp"

namespace {

using convray::Vec3;
using convray::field::Triangle;

constexpr size_t kTriangles = 4096;  // 4096 * 264 bytes stays in L2

// Triangles around the origin, evaluated at the origin. Wholly inside: R = 10 contains them
// all. Clipped: corners 0.5 to 1.5 away with R = 1, so the sphere cuts every triangle.
std::vector<Triangle> make_triangles(bool clipped) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> dist(0.5, 1.5);
  const auto corner = [&] {
    Vec3 d;
    do d = Vec3(unit(rng), unit(rng), unit(rng));
    while (glm::length(d) < 0.1 || glm::length(d) > 1.0);
    return (clipped ? dist(rng) : 2.0) * glm::normalize(d);
  };
  std::vector<Triangle> tris;
  while (tris.size() < kTriangles) {
    const Triangle t{corner(), corner(), corner()};
    const Vec3 n = glm::cross(t.b - t.a, t.c - t.a);
    if (glm::length(n) < 0.05) continue;
    // Keep the plane within the sphere so every triangle really is evaluated, not rejected.
    if (std::abs(glm::dot(t.a, glm::normalize(n))) > 0.6) continue;
    tris.push_back(t);
  }
  return tris;
}

double radius_for(bool clipped) { return clipped ? 1.0 : 10.0; }

void scalar_value(benchmark::State& state, bool clipped) {
  const auto tris = make_triangles(clipped);
  const double r = radius_for(clipped);
  for (auto _ : state) {
    double sum = 0.0;
    for (const Triangle& t : tris) sum += convray::field::triangle_value(Vec3(0.0), t, r);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

void scalar_field(benchmark::State& state, bool clipped) {
  const auto tris = make_triangles(clipped);
  const double r = radius_for(clipped);
  for (auto _ : state) {
    convray::field::FieldSample sum;
    for (const Triangle& t : tris) sum += convray::field::triangle_field(Vec3(0.0), t, r);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

void batch_value(benchmark::State& state, bool clipped) {
  const auto tris = make_triangles(clipped);
  const convray::field::TriangleBatch batch(tris);
  const double r = radius_for(clipped);
  for (auto _ : state) benchmark::DoNotOptimize(batch.value(Vec3(0.0), r));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

void batch_field(benchmark::State& state, bool clipped) {
  const auto tris = make_triangles(clipped);
  const convray::field::TriangleBatch batch(tris);
  const double r = radius_for(clipped);
  for (auto _ : state) benchmark::DoNotOptimize(batch.field(Vec3(0.0), r));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

// The window march's calls: a few listed lanes (state.range(0) of a cluster's 32 triangles)
// per call, as one sample of a ray's cluster evaluates the triangles whose support holds the
// point; counts that are not a multiple of the SIMD width show the cost of the padding. With
// the gradient (a hit's normal), or values only (the bracketing and refining samples, which
// list clipped triangles only and so skip the wholly-inside path).
template <bool kGradient>
void batch_listed(benchmark::State& state, bool clipped) {
  auto tris = make_triangles(clipped);
  tris.resize(32);
  const convray::field::TriangleBatch batch(tris);
  const double r = radius_for(clipped);
  std::vector<uint32_t> lanes;
  for (uint32_t i = 0; i < uint32_t(state.range(0)); ++i) lanes.push_back(i * 32 / uint32_t(state.range(0)));
  for (auto _ : state) {
    if constexpr (kGradient) {
      benchmark::DoNotOptimize(batch.field(Vec3(0.0), r, lanes));
    } else {
      benchmark::DoNotOptimize(batch.value(Vec3(0.0), r, lanes, false));
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(lanes.size()));
}
void batch_field_listed(benchmark::State& state, bool clipped) { batch_listed<true>(state, clipped); }
void batch_value_listed(benchmark::State& state, bool clipped) { batch_listed<false>(state, clipped); }

std::vector<convray::field::Segment> make_segments() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<convray::field::Segment> segs(kTriangles);
  for (auto& s : segs) s = {{unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)}};
  return segs;
}

void segment_batch_value(benchmark::State& state) {
  const convray::field::SegmentBatch batch(make_segments());
  for (auto _ : state) benchmark::DoNotOptimize(batch.value(Vec3(0.0), 1.0));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(batch.size()));
}

void segment_value(benchmark::State& state) {
  const auto segs = make_segments();
  for (auto _ : state) {
    double sum = 0.0;
    for (const auto& s : segs) sum += convray::field::segment_value(Vec3(0.0), s, 1.0);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(segs.size()));
}

}  // namespace

BENCHMARK_CAPTURE(scalar_value, wholly_inside, false);
BENCHMARK_CAPTURE(scalar_value, clipped, true);
BENCHMARK_CAPTURE(batch_value, wholly_inside, false);
BENCHMARK_CAPTURE(batch_value, clipped, true);
BENCHMARK_CAPTURE(scalar_field, wholly_inside, false);
BENCHMARK_CAPTURE(scalar_field, clipped, true);
BENCHMARK_CAPTURE(batch_field, wholly_inside, false);
BENCHMARK_CAPTURE(batch_field, clipped, true);
BENCHMARK_CAPTURE(batch_field_listed, wholly_inside, false)->Arg(8)->Arg(9)->Arg(10)->Arg(11)->Arg(12)->Arg(13)->Arg(16);
BENCHMARK_CAPTURE(batch_field_listed, clipped, true)->Arg(5)->Arg(8)->Arg(9)->Arg(11);
BENCHMARK_CAPTURE(batch_value_listed, clipped, true)->Arg(3)->Arg(5)->Arg(8)->Arg(11)->Arg(32);
BENCHMARK(segment_value);
BENCHMARK(segment_batch_value);

BENCHMARK_MAIN();
