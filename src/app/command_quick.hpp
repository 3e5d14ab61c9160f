#pragma once
#include <iosfwd>
#include <optional>
#include <string>

#include "util/math.hpp"

namespace convray::app {

// `convray quick`: everything a picture of one mesh's convolution surface needs, until the
// scene language arrives. Lengths are in the model's units after --fit-box.
struct QuickOptions {
  std::string mesh_path;
  std::optional<double> radius;     // default: the radius `convray info` advises
  std::optional<double> offset;     // surface at this distance from flat regions (R/2), or
  std::optional<double> threshold;  // a raw threshold T
  int width = 800, height = 600;
  std::optional<double> fit_box;  // scale the largest extent to this, centred at the origin
  std::optional<Vec3> camera;     // with look_at; default: framed automatically
  std::optional<Vec3> look_at;
  double angle = 40.0;        // horizontal field of view, degrees
  std::optional<Vec3> light;  // default: above, left of and behind the camera
  bool reference = false;     // the exact reference tracer instead of the fast path
  bool stats = false;         // print counters and timings after the render
  bool force = false;         // render an image larger than the memory estimate allows
  std::string output = "quick.png";
};

// Loads, builds, renders and writes; returns the exit code: 0, 2 for any problem with the
// input (message on `err`, no image written), 1 for an internal failure.
int run_quick(const QuickOptions& options, std::ostream& out, std::ostream& err);

}  // namespace convray::app
