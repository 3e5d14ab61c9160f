// Polygonization throughput: the convolution surface of an icosphere soup (1,280 triangles,
// R = 0.3, offset 0.1) through polygonize() at three lattice cells, single-threaded and on all
// cores. Counters: triangles out per second and field evaluations per second.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <memory>

#include "implicit/mesh_field.hpp"
#include "field/threshold.hpp"
#include "mesh/procedural.hpp"
#include "polygonize/polygonize.hpp"

namespace {

using namespace convray;

struct SoupSource {
  std::unique_ptr<implicit::MeshField> field;
  polygonize::FieldSource source;
};

const SoupSource& icosphere_source() {
  static const SoupSource soup = [] {
    const mesh::TriangleSoup sphere = mesh::icosphere(Vec3(0.0), 1.0, 3);
    std::vector<field::Triangle> triangles;
    for (size_t t = 0; t < sphere.size(); ++t) {
      const auto [a, b, c] = sphere.corners(t);
      triangles.push_back({a, b, c});
    }
    SoupSource s;
    s.field = std::make_unique<implicit::MeshField>(triangles, 0.3);
    s.source.supports = polygonize::triangle_support_boxes(s.field->triangles(), 0.3);
    s.source.threshold = field::threshold_for_offset(1.0, 0.3, 0.1);
    const implicit::MeshField* f = s.field.get();
    s.source.field = [f](const Vec3& p) { return f->field(p); };
    s.source.value = [f](const Vec3& p) { return f->value(p); };
    return s;
  }();
  return soup;
}

void BM_PolygonizeIcosphereSoup(benchmark::State& state) {
  const double cell = 0.01 * double(state.range(0));
  const int threads = int(state.range(1));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  const SoupSource& soup = icosphere_source();
  size_t triangles = 0, evaluations = 0;
  for (auto _ : state) {
    polygonize::PolygonizeStats stats;
    const polygonize::SurfaceMesh m = polygonize::polygonize(soup.source, {.cell = cell}, &stats);
    triangles += m.soup.triangles.size();
    evaluations += stats.field_evaluations;
    benchmark::DoNotOptimize(m.soup.vertices.data());
  }
  state.counters["triangles/s"] = benchmark::Counter(double(triangles), benchmark::Counter::kIsRate);
  state.counters["evaluations/s"] =
      benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
}
// Cells 0.08, 0.04, 0.02 (in hundredths); 1 thread and 2.
BENCHMARK(BM_PolygonizeIcosphereSoup)
    ->ArgsProduct({{8, 4, 2}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
