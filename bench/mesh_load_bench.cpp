// How fast mesh::load_mesh reads files: the reading `convray info` does before its statistics
// (bench/mesh_reading.sh makes the dragon in three formats and runs this on them).
//
//   build/bench/mesh_load_bench FILE... [--benchmark_repetitions=N ...]
//
// One benchmark per file, named after it; each iteration reads the whole file from disk
// (the page cache, after the first) into triangles, segments and points.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

#include "mesh/load.hpp"

namespace {

void load_file(benchmark::State& state, const std::string& path) {
  size_t triangles = 0;
  for (auto _ : state) {
    convray::mesh::LoadedMesh mesh = convray::mesh::load_mesh(path);
    triangles = mesh.soup.size();
    benchmark::DoNotOptimize(mesh.soup.vertices.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: mesh_load_bench FILE... [benchmark options]\n");
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    const std::string path = argv[i];
    benchmark::RegisterBenchmark(("load/" + path).c_str(), [path](benchmark::State& state) { load_file(state, path); })
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime()
        ->UseRealTime();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
