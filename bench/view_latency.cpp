// convray view's latency: from a change to the first, coarse picture (one ray per 8 x 8
// block) of scenes/soup.pov at its default size (800 x 600), with the session's caches warm
// as they are in a running view. No window: the work the render thread does for each change
// (src/app/view_session.hpp), timed end to end. The goal (issue 18): under 0.2 s on the
// project's 2-core machine. docs/benchmarks.md has the figures.
//
//   build/bench/view_latency [--benchmark_filter=...]
//
// file_saved: the scene parsed again (its mesh file read once, kept by the mesh library),
//   the World built (the mesh's support hierarchy kept by the support cache), the coarse pass;
// radius_changed: the same with the right-hand object's radius edited, so that its support
//   hierarchy is built anew each time (two radii alternate; each frame drops the other's);
// camera_moved: the last frame seen through a moved camera (no parse, no build), coarse pass.
// Add the watcher's poll (50 ms at most, 25 ms on average) for a save; input events wait at
// most 15 ms.
#include <benchmark/benchmark.h>

#include <string>

#include "app/view_edits.hpp"
#include "app/view_session.hpp"

namespace {

using namespace convray;

app::ViewOptions soup() {
  app::ViewOptions o;
  o.input = std::string(CONVRAY_SOURCE_DIR) + "/scenes/soup.pov";
  o.width = 800;
  o.height = 600;
  return o;
}

void file_saved(benchmark::State& state) {
  app::ViewSession session(soup());
  session.render(*session.load({}), app::kCoarseBlock);  // a running view: caches warm
  for (auto _ : state) {
    const auto frame = session.load({});
    benchmark::DoNotOptimize(session.render(*frame, app::kCoarseBlock));
  }
}
BENCHMARK(file_saved)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void radius_changed(benchmark::State& state) {
  app::ViewSession session(soup());
  const sdl::ConvolutionHeader right = session.load({})->convolutions.at(1);
  const sdl::ConvolutionHeader sizes[2] = {app::edited_header(right, 'R'),
                                           app::edited_header(right, 'r')};
  int turn = 0;
  for (auto _ : state) {
    app::ViewOverrides overrides;
    app::set_edit(overrides.edits, sizes[turn ^= 1]);
    const auto frame = session.load(overrides);
    benchmark::DoNotOptimize(session.render(*frame, app::kCoarseBlock));
  }
}
BENCHMARK(radius_changed)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void camera_moved(benchmark::State& state) {
  app::ViewSession session(soup());
  const auto frame = session.load({});
  double yaw = 0.0;
  for (auto _ : state) {
    const auto moved =
        app::ViewSession::with_camera(*frame, app::orbit(frame->camera, yaw += 0.01, 0.0));
    benchmark::DoNotOptimize(session.render(*moved, app::kCoarseBlock));
  }
}
BENCHMARK(camera_moved)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();
