#pragma once
// `convray view SCENE.pov` (or a mesh): the scene in a window, rendered coarse first and then
// in full, again whenever a file it read is saved; the mouse moves the camera, keys print it,
// save the picture, edit the convolution under the cursor and scrub the clock (docs/view.md).
#include <iosfwd>
#include <string>

#include "app/view_session.hpp"

namespace convray::app {

struct ViewCommandOptions {
  ViewOptions view;
  double clock = 0.0;        // --clock
  double clock_step = 0.05;  // [ and ] move the clock by this
  std::string output;        // s writes the picture here (default: SCENE's stem + "-view.png")
};

// The keys and the mouse, for --help and the h overlay.
extern const char* const kViewKeys;

// Runs until the window is closed (or q, Escape); 0 then. Without a display: the reason on
// `err` and 1, since there is nothing to show. 2 for bad options.
int run_view(const ViewCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace convray::app
