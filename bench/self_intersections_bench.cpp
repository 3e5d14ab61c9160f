// The exact self-intersection check: the orientation predicate on easy input (the filter
// decides), on exactly coplanar input (the expansion fallback decides), and the whole search
// on closed icospheres of 20 * 4^s faces, where every candidate pair must be tested and none
// intersects. Counters: predicates or faces per second.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "mesh/exact_predicates.hpp"
#include "mesh/procedural.hpp"
#include "mesh/self_intersections.hpp"

namespace {

using namespace convray;

std::vector<Vec3> random_points(size_t count, bool coplanar) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  for (size_t i = 0; i < count; ++i) {
    // On the plane z = 0.25 x + 0.5 y (exact in doubles for these dyadic coordinates).
    const double x = std::ldexp(std::round(std::ldexp(u(random), 20)), -20);
    const double y = std::ldexp(std::round(std::ldexp(u(random), 20)), -20);
    points.push_back(Vec3(x, y, coplanar ? 0.25 * x + 0.5 * y : u(random)));
  }
  return points;
}

void orient3d(benchmark::State& state, bool coplanar) {
  const std::vector<Vec3> p = random_points(4096, coplanar);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mesh::orient3d(p[i], p[i + 1], p[i + 2], p[i + 3]));
    i = (i + 4) % 4092;
  }
  state.counters["predicates/s"] = benchmark::Counter(double(state.iterations()),
                                                      benchmark::Counter::kIsRate);
}
void BM_Orient3dGeneric(benchmark::State& state) { orient3d(state, false); }
void BM_Orient3dCoplanar(benchmark::State& state) { orient3d(state, true); }
BENCHMARK(BM_Orient3dGeneric);
BENCHMARK(BM_Orient3dCoplanar);

void BM_FindSelfIntersectionsIcosphere(benchmark::State& state) {
  const mesh::TriangleSoup sphere = mesh::icosphere(Vec3(0.0), 1.0, int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(mesh::find_self_intersections(sphere).pairs);
  state.counters["faces/s"] = benchmark::Counter(double(state.iterations() * sphere.size()),
                                                 benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FindSelfIntersectionsIcosphere)->Arg(5)->Arg(7)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
