#pragma once
// What a render hands back: the picture (linear RGB) and what it took.
#include "render/film.hpp"
#include "render/render_stats.hpp"

namespace convray::render {

struct RenderResult {
  Film film;
  RenderStats stats;
};

}  // namespace convray::render
