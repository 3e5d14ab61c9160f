#pragma once
// Runs of coherent rays. The renderer traces a tile's pixels one after the other on one
// thread, and neighbouring rays meet a surface at nearly the same depth: a surface may keep
// where the last ray of the run hit it and plan the next search from there (implicit's
// first-hit chunks, surface_roots.cpp). Such a hint changes how much a search gathers, not
// what it finds; but the root is found to a tolerance, and its last bits depend on the
// search's pieces. So the renderer starts a new run at every tile, and a hint is used only
// within the run that made it: a picture never depends on which thread traced which tile
// before. Callers outside the renderer's tiles share one run per thread.
#include <cstdint>

namespace convray {

// Starts a new run of coherent rays on this thread.
void begin_coherent_rays();
// This thread's current run.
uint64_t coherent_run();

}  // namespace convray
