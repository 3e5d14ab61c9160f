#include "sdl/convolution_components.hpp"

#include <cmath>
#include <exception>
#include <new>
#include <stdexcept>
#include <glm/geometric.hpp>

#include "field/threshold.hpp"
#include "sdl/component_modifiers.hpp"
#include "sdl/diagnostics.hpp"
#include "sdl/item_helpers.hpp"
#include "sdl/mesh_library.hpp"

namespace convray::sdl::items {

namespace {

using Kind = scene::Implicit::Kind;

constexpr std::string_view kComponentWords[] = {"mesh", "triangle", "segment", "arc", "point"};

// `strength s`, `radius r`, transforms and a texture, up to the component's `}`.
void parse_component_tail(Parser& parser, Block& block, PendingComponent& component,
                          ComponentModifiers& modifiers) {
  static constexpr std::string_view kWords[] = {"strength", "radius", "translate", "rotate",
                                                "scale",    "matrix", "transform", "texture",
                                                "pigment",  "finish", "normal"};
  while (block.more()) {
    if (accept_word(parser, "strength")) {
      component.strength = float_param(parser, "strength");
    } else if (at_word(parser, "radius")) {
      const SourceLoc loc = take_keyword(parser);
      const double radius = float_param(parser, "radius");
      if (!(radius > 0.0)) {
        parser.fail(loc, "convolution " + block.name() + " radius must be positive, found " +
                             number_text(radius));
      }
      component.radius = radius;
    } else if (!modifiers.parse()) {
      block.unexpected(kWords);
    }
  }
  component.radius_scale = modifiers.scale();
  component.texture = modifiers.texture();
}

SharedSkeleton load_mesh_skeleton(Parser& parser, const SourceLoc& loc, const std::string& name) {
  const std::string path = parser.resolve_file(name, loc);
  try {
    MeshLibrary* library = parser.options().mesh_library.get();
    return library ? library->load(path) : MeshLibrary::read(path);
  } catch (const std::bad_alloc&) {
    throw;  // the command reports it with its step ("out of memory while parsing SCENE")
  } catch (const std::length_error&) {
    throw;
  } catch (const std::exception& error) {  // InputError from the readers
    parser.fail(loc, "cannot load mesh \"" + name + "\": " + error.what());
  }
}

// The component keeps the file's triangles (shared with every frame that reads the file) and
// the placement, besides the placed copy everything else reads; the file's segments and
// points (polylines, edges, point clouds) are placed too and become components of their own.
void parse_mesh_component(Parser& parser, Block& block, PendingComponent& component) {
  const std::string name = parser.parse_string();
  ComponentModifiers modifiers(parser, "convolution mesh");
  parse_component_tail(parser, block, component, modifiers);
  const SharedSkeleton skeleton = load_mesh_skeleton(parser, component.loc, name);
  const scene::Transform& transform = modifiers.transform();
  if (!skeleton->triangles.empty()) {
    // The skeleton owns the triangles: share them with it (shared_ptr's aliasing constructor).
    const std::shared_ptr<const std::vector<field::Triangle>> local(skeleton, &skeleton->triangles);
    component.source = scene::MeshSource{local, transform.forward()};
  }
  component.triangles.reserve(skeleton->triangles.size());
  for (const field::Triangle& triangle : skeleton->triangles) {
    component.triangles.push_back(
        {transform.point(triangle.a), transform.point(triangle.b), transform.point(triangle.c)});
  }
  component.segments.reserve(skeleton->segments.size());
  for (const field::Segment& s : skeleton->segments) component.segments.push_back({transform.point(s.a), transform.point(s.b)});
  component.points.reserve(skeleton->points.size());
  for (const Vec3& p : skeleton->points) component.points.push_back(transform.point(p));
}

void parse_triangle_component(Parser& parser, Block& block, PendingComponent& component) {
  field::Triangle triangle;
  triangle.a = vector_param(parser, "corner 1");
  parser.accept_comma();
  triangle.b = vector_param(parser, "corner 2");
  parser.accept_comma();
  triangle.c = vector_param(parser, "corner 3");
  if (glm::cross(triangle.b - triangle.a, triangle.c - triangle.a) == Vec3(0.0)) {
    parser.fail(component.loc, "convolution triangle: its corners are collinear");
  }
  ComponentModifiers modifiers(parser, "convolution triangle");
  parse_component_tail(parser, block, component, modifiers);
  const scene::Transform& transform = modifiers.transform();
  component.triangles = {
      {transform.point(triangle.a), transform.point(triangle.b), transform.point(triangle.c)}};
  component.single_triangle = true;
}

void parse_segment_component(Parser& parser, Block& block, PendingComponent& component) {
  Vec3 a = vector_param(parser, "end point 1");
  parser.accept_comma();
  Vec3 b = vector_param(parser, "end point 2");
  if (a == b) parser.fail(component.loc, "convolution segment: its two end points coincide");
  ComponentModifiers modifiers(parser, "convolution segment");
  parse_component_tail(parser, block, component, modifiers);
  component.segment = {modifiers.transform().point(a), modifiers.transform().point(b)};
}

void parse_arc_component(Parser& parser, Block& block, PendingComponent& component) {
  std::array<Vec3, 3> points;
  const char* names[] = {"the arc's first point", "the arc's middle point", "the arc's last point"};
  for (size_t k = 0; k < 3; ++k) {
    if (k > 0) parser.accept_comma();
    points[k] = vector_param(parser, names[k]);
  }
  ComponentModifiers modifiers(parser, "convolution arc");
  parse_component_tail(parser, block, component, modifiers);
  for (Vec3& p : points) p = modifiers.transform().point(p);
  if (!field::arc_through(points[0], points[1], points[2], component.arc)) {
    parser.fail(component.loc,
                "convolution arc: its three points are collinear (or two coincide), so no "
                "circle passes through them; use a segment");
  }
}

void parse_point_component(Parser& parser, Block& block, PendingComponent& component) {
  const Vec3 center = vector_param(parser, "center");
  ComponentModifiers modifiers(parser, "convolution point");
  parse_component_tail(parser, block, component, modifiers);
  component.point = modifiers.transform().point(center);
}

}  // namespace

bool at_convolution_component(Parser& parser) { return at_any_word(parser, kComponentWords); }

PendingComponent parse_convolution_component(Parser& parser) {
  const std::string word = parser.peek().text;
  PendingComponent component;
  component.loc = take_keyword(parser);
  Block block(parser, word, component.loc);
  if (word == "mesh") {
    component.kind = Kind::mesh;
    parse_mesh_component(parser, block, component);
  } else if (word == "triangle") {
    component.kind = Kind::mesh;
    parse_triangle_component(parser, block, component);
  } else if (word == "segment") {
    component.kind = Kind::segment;
    parse_segment_component(parser, block, component);
  } else if (word == "arc") {
    component.kind = Kind::arc;
    parse_arc_component(parser, block, component);
  } else {
    component.kind = Kind::point;
    parse_point_component(parser, block, component);
  }
  return component;
}

namespace {

bool same_weight(const scene::Weight& a, const scene::Weight& b) {
  return a.strength == b.strength && a.radius == b.radius;
}

// A mesh file's segments and points, each a component of the mesh's weight and texture.
void add_file_segments_and_points(const PendingComponent& component, const scene::Weight& weight,
                                  scene::Implicit& implicit) {
  scene::ConvolutionObject& object = implicit.object;
  for (const field::Segment& segment : component.segments) {
    add_component_texture(implicit, component.texture);
    implicit.component_order.emplace_back(Kind::segment, object.segments.size());
    object.segments.push_back({segment, weight});
  }
  for (const Vec3& point : component.points) {
    add_component_texture(implicit, component.texture);
    implicit.component_order.emplace_back(Kind::point, object.points.size());
    object.points.push_back({point, weight});
  }
}

// Appends `component` to the vectors of `implicit` and notes its place in listing order.
void add_component(PendingComponent& component, const scene::Weight& weight,
                   scene::Implicit& implicit) {
  if (component.kind == Kind::mesh && (!component.segments.empty() || !component.points.empty())) {
    add_file_segments_and_points(component, weight, implicit);
    if (component.triangles.empty()) return;  // a point cloud or a line set
  }
  scene::ConvolutionObject& object = implicit.object;
  size_t index = 0;
  switch (component.kind) {
    case Kind::mesh:
      index = object.meshes.size();
      object.meshes.push_back(
          {std::move(component.triangles), weight, std::move(component.source)});
      break;
    case Kind::segment:
      index = object.segments.size();
      object.segments.push_back({component.segment, weight});
      break;
    case Kind::arc:
      index = object.arcs.size();
      object.arcs.push_back({component.arc, weight});
      break;
    default:
      index = object.points.size();
      object.points.push_back({component.point, weight});
      break;
  }
  add_component_texture(implicit, component.texture);
  implicit.component_order.emplace_back(component.kind, index);
}

// What double precision carries (field::check_radius_in_range; strengths within 1e+-290,
// as the threshold): beyond it the field overflows or sinks into subnormals and the picture
// is silently wrong.
void check_weight_in_range(const SourceLoc& loc, const scene::Weight& weight) {
  try {
    field::check_radius_in_range(weight.radius);
  } catch (const std::invalid_argument& e) {
    throw InputError(loc, std::string("convolution component: ") + e.what());
  }
  const double s = std::abs(weight.strength);
  if (s == 0.0 || (s >= 1e-290 && s <= 1e290)) return;
  throw InputError(loc, "convolution component: the strength " + number_text(weight.strength) +
                            " is outside what double precision evaluates safely (1e-290 to "
                            "1e290 in size); scale the strengths and the threshold together");
}

}  // namespace

void resolve_components(std::vector<PendingComponent>& components,
                        const ConvolutionDefaults& defaults, scene::Implicit& implicit) {
  bool last_is_triangle_group = false;
  for (PendingComponent& component : components) {
    const scene::Weight weight{
        component.strength.value_or(defaults.strength),
        component.radius.value_or(defaults.radius) * component.radius_scale};
    check_weight_in_range(component.loc, weight);
    const bool groupable = component.single_triangle && !component.texture;
    if (groupable && last_is_triangle_group &&
        same_weight(implicit.object.meshes.back().weight, weight)) {
      auto& triangles = implicit.object.meshes.back().triangles;
      triangles.insert(triangles.end(), component.triangles.begin(), component.triangles.end());
      continue;
    }
    add_component(component, weight, implicit);
    last_is_triangle_group = groupable;
  }
}

}  // namespace convray::sdl::items
