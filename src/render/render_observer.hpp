#pragma once
// Someone watching a render as it goes (POV-Ray's +D preview window, src/display/): told of
// each tile as soon as its pixels are computed. The renderer knows only this interface, so it
// never depends on how, or whether, the pixels are shown.
#include <span>
#include <stdexcept>

#include "render/pixel_window.hpp"

namespace convray::render {

// A finished tile: its rectangle (inside the partial render's window, if any) and its pixels,
// row-major, three floats each, in the linear light the image writer receives (assumed_gamma
// and gamma correction already applied, as for the final film). With anti-aliasing, a tile of
// the second pass replaces the first pass's pixels there.
struct FinishedTile {
  PixelWindow area;
  std::span<const float> rgb;
  bool refinement = false;  // true: anti-aliasing's pass; false: the first pass
};

class RenderObserver {
 public:
  virtual ~RenderObserver() = default;
  // Called from any of the render's threads, concurrently, once per tile and pass. It may throw
  // (RenderCancelled) to stop the render: the exception leaves render_scene, no film is handed
  // back, and nothing is written.
  virtual void tile_done(const FinishedTile& tile) = 0;
};

// Thrown by an observer whose user asked to stop the render (closed the preview window).
class RenderCancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace convray::render
