#pragma once
#include <iosfwd>
#include <optional>
#include <string>

namespace convray::app {

struct SliceOptions {
  std::string mesh_path;
  double radius = 1.0;
  double strength = 1.0;
  std::optional<double> offset;     // surface at this distance from flat regions, or
  std::optional<double> threshold;  // a raw threshold T
  char axis = 'z';                  // the slicing plane is axis = at
  double at = 0.0;
  int width = 800, height = 600;
  std::string output = "slice.png";
  bool force = false;  // draw an image larger than the memory estimate allows
};

// `convray slice`: pictures the field on a plane through the mesh: colour by F/T, the
// surface F = T as a white contour, the triangles' cross-section in black.
int run_slice(const SliceOptions& options, std::ostream& out, std::ostream& err);

}  // namespace convray::app
