#pragma once
// The components of a `convolution { }` as they are read: each keeps its own strength and
// radius only if it gave them, so that the object's defaults (which may come later in the
// block) fill in the rest when the object is complete.
#include <optional>
#include <vector>

#include "field/arc.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "scene/object.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::items {

struct PendingComponent {
  scene::Implicit::Kind kind = scene::Implicit::Kind::point;
  SourceLoc loc;
  std::optional<double> strength, radius;
  double radius_scale = 1.0;     // from the component's uniform scale
  bool single_triangle = false;  // `triangle { }`: grouped with its neighbours of equal weight
  std::vector<field::Triangle> triangles;  // mesh, triangle
  std::optional<scene::MeshSource> source;  // mesh: the file's triangles and placement
  std::vector<field::Segment> segments;    // mesh: the file's polylines and edges, placed
  std::vector<Vec3> points;                // mesh: the file's points, placed
  field::Segment segment;
  field::Arc arc;
  Vec3 point{0.0};
  scene::TexturePtr texture;
};

// At one of mesh, triangle, segment, arc, point: parses the component.
bool at_convolution_component(Parser& parser);
PendingComponent parse_convolution_component(Parser& parser);

// The object's defaults, and the components resolved into `implicit` (in listing order,
// consecutive untextured triangles of equal weight merged into one mesh component).
struct ConvolutionDefaults {
  double strength = 1.0;
  double radius = 1.0;
};
void resolve_components(std::vector<PendingComponent>& components,
                        const ConvolutionDefaults& defaults, scene::Implicit& implicit);

}  // namespace convray::sdl::items
