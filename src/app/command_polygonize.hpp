#pragma once
// `convray polygonize`: the surface F = T of a mesh's convolution, or of a convolution object
// declared in a scene, as a closed 2-manifold triangle mesh file (src/polygonize/).
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "scene/convolution_object.hpp"

namespace convray::app {

struct PolygonizeOptions {
  std::string input;                       // a mesh file, or a scene file with object_name
  std::string object_name;                 // --object NAME: the declared object of the scene
  std::vector<std::string> library_paths;  // -L, for the scene's includes and meshes
  std::vector<std::string> read_folders;   // --allow-read: more folders the scene may read
  std::optional<double> radius;            // meshes: R (default: the advised radius)
  double strength = 1.0;                   // meshes
  std::optional<double> fit_box;           // meshes: scale the largest extent to this first
  std::optional<double> offset;            // meshes: surface at distance D (default R/2)
  std::optional<double> threshold;         // T itself (overrides a scene object's threshold)
  std::optional<double> cell;              // lattice spacing
  std::optional<double> max_error;         // or: the largest distance from the surface
  bool outer = false;                      // keep only the shells reachable from infinity
  bool stats = false;                      // print the extraction's figures
  std::string output;                      // .obj .ply .stl (.off)
  bool ascii = false;                      // PLY/STL as text
  bool force = false;                      // run a pass whose estimate exceeds the memory
};

// Before each pass of the lattice, its size is estimated (polygonize/size_estimate.hpp);
// a large one is printed to `err`, one that cannot fit in memory refused (exit 2) unless
// `force`. Returns the exit code: 0; 1 when out of memory; 2 for bad input, an empty surface
// included (the message, with file:line:col where it applies, goes to `err`). Nothing is
// written unless it succeeds.
int run_polygonize(const PolygonizeOptions& options, std::ostream& out, std::ostream& err);

// The components' smallest support radius (infinity when there are none): what sets the
// default resolution of polygonize (the command's and the Python module's).
double smallest_radius(const scene::ConvolutionObject& object);

}  // namespace convray::app
