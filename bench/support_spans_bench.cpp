// Exact spans of triangle supports along a line per second on one core: the scalar twin
// (accel::triangle_span, one call per triangle, as the Embree callbacks used to do) and the
// SIMD batch (accel::TriangleSpanBatch). Triangles of mean edge 2 scattered around a ray, at
// R = 1 and R = 5 (the dragon rows of issue 15), about half of them crossed; and the batch
// with the line's terms beside the spans (what the window march asks for).
// Run: build/bench/support_spans_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <numeric>
#include <random>
#include <vector>

#include "accel/support_shapes.hpp"
#include "accel/triangle_span_batch.hpp"
#include "field/triangle_frame.hpp"

namespace {

using convray::Vec3;
using convray::field::Triangle;

constexpr size_t kTriangles = 256;

std::vector<Triangle> make_triangles(double radius) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Triangle> tris;
  while (tris.size() < kTriangles) {
    // Centres within 1.3 (R + 1) of the z axis, along 0 <= z <= 100.
    const Vec3 centre(1.3 * (radius + 1.0) * unit(rng), 1.3 * (radius + 1.0) * unit(rng),
                      50.0 + 50.0 * unit(rng));
    const auto corner = [&] { return centre + 1.2 * Vec3(unit(rng), unit(rng), unit(rng)); };
    tris.push_back({corner(), corner(), corner()});
  }
  return tris;
}

const Vec3 kOrigin(0.05, -0.03, -10.0);
const Vec3 kDirection(0.0, 0.0, 1.0);

void scalar_spans(benchmark::State& state) {
  const double radius = double(state.range(0));
  const auto tris = make_triangles(radius);
  for (auto _ : state) {
    double sum = 0.0;
    for (const Triangle& t : tris) {
      const auto s = convray::accel::triangle_span(kOrigin, kDirection, t, radius);
      if (!s.empty()) sum += s.exit - s.enter;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

void batch_spans(benchmark::State& state) {
  const double radius = double(state.range(0));
  const auto tris = make_triangles(radius);
  std::vector<uint32_t> ids(tris.size());
  std::iota(ids.begin(), ids.end(), 0u);
  const auto frames = convray::field::triangle_frames(tris);  // once per mesh, as a surface's
  convray::accel::TriangleSpanBatch batch;
  for (auto _ : state) {
    batch.gather(tris, frames, ids);
    batch.compute(kOrigin, kDirection, radius);
    double sum = 0.0;
    for (size_t k = 0; k < batch.size(); ++k) {
      const auto s = batch.span(k);
      if (!s.empty()) sum += s.exit - s.enter;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

// The same with the line's terms beside the spans (accel::TriangleLineTable), as the window
// march asks for them.
void batch_spans_and_terms(benchmark::State& state) {
  const double radius = double(state.range(0));
  const auto tris = make_triangles(radius);
  std::vector<uint32_t> ids(tris.size());
  std::iota(ids.begin(), ids.end(), 0u);
  const auto frames = convray::field::triangle_frames(tris);
  convray::accel::TriangleSpanBatch batch;
  convray::accel::TriangleLineTable table;
  for (auto _ : state) {
    table.clear();
    batch.gather(tris, frames, ids);
    const size_t row = batch.compute(kOrigin, kDirection, radius, table);
    double sum = 0.0;
    for (size_t k = 0; k < batch.size(); ++k) {
      const auto s = batch.span(k);
      if (!s.empty()) sum += s.exit - s.enter + table.twice_area(row + k);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tris.size()));
}

}  // namespace

BENCHMARK(scalar_spans)->Arg(1)->Arg(5);
BENCHMARK(batch_spans)->Arg(1)->Arg(5);
BENCHMARK(batch_spans_and_terms)->Arg(1)->Arg(5);
BENCHMARK_MAIN();
