// Triangles: `triangle`, `smooth_triangle`, and `mesh { triangle {} smooth_triangle {} ... }`,
// all recorded as scene::TriangleMesh (mesh2 is in parse_mesh2.cpp).
#include <glm/geometric.hpp>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

struct ParsedTriangle {
  std::array<Vec3, 3> corners;
  std::array<Vec3, 3> normals;
  bool smooth = false;
  std::optional<scene::Texture> texture;
  SourceLoc loc;
};

bool degenerate(const ParsedTriangle& triangle) {
  const auto& c = triangle.corners;
  return glm::cross(c[1] - c[0], c[2] - c[0]) == Vec3(0.0);
}

// triangle { a, b, c [texture {...}] } or smooth_triangle { a, na, b, nb, c, nc ... }.
// Inside a mesh only textures (and ignored uv_vectors) may follow; alone, any modifier.
ParsedTriangle parse_triangle_corners(Parser& parser, Block& block, bool smooth) {
  ParsedTriangle triangle;
  triangle.smooth = smooth;
  triangle.loc = block.loc();
  for (int k = 0; k < 3; ++k) {
    if (k > 0) parser.accept_comma();
    triangle.corners[size_t(k)] = vector_param(parser, "corner " + std::to_string(k + 1));
    if (smooth) {
      parser.accept_comma();
      triangle.normals[size_t(k)] = vector_param(parser, "normal " + std::to_string(k + 1));
      if (triangle.normals[size_t(k)] == Vec3(0.0)) {
        parser.fail(block.loc(),
                    "smooth_triangle normal " + std::to_string(k + 1) + " must not be <0, 0, 0>");
      }
    }
  }
  return triangle;
}

ParsedTriangle parse_mesh_triangle(Parser& parser) {
  const bool smooth = at_word(parser, "smooth_triangle");
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, smooth ? "smooth_triangle" : "triangle", loc);
  ParsedTriangle triangle = parse_triangle_corners(parser, block, smooth);
  static constexpr std::string_view kWords[] = {"texture", "uv_vectors"};
  while (block.more()) {
    if (at_word(parser, "texture")) {
      triangle.texture = parse_texture(parser, parser.defaults().texture);
    } else if (at_word(parser, "uv_vectors")) {
      warn_once(parser, take_keyword(parser), "uv_vectors are ignored: convray has no uv mapping");
      for (int k = 0; k < 3; ++k) {
        if (k > 0) parser.accept_comma();
        parser.parse_expression();
      }
    } else {
      block.unexpected(kWords);
    }
  }
  return triangle;
}

void add_triangle(scene::TriangleMesh& mesh, ParsedTriangle triangle, int texture) {
  scene::MeshFace face;
  for (size_t k = 0; k < 3; ++k) {
    face.vertices[k] = int(mesh.vertices.size());
    mesh.vertices.push_back(triangle.corners[k]);
    if (triangle.smooth) {
      face.normals[k] = int(mesh.normals.size());
      mesh.normals.push_back(triangle.normals[k]);
    }
  }
  face.texture = texture;
  mesh.faces.push_back(face);
}

}  // namespace

scene::ObjectPtr parse_triangle(Parser& parser) {
  const bool smooth = at_word(parser, "smooth_triangle");
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, smooth ? "smooth_triangle" : "triangle", loc);
  ParsedTriangle triangle = parse_triangle_corners(parser, block, smooth);
  if (degenerate(triangle)) parser.fail(loc, block.name() + ": its corners are collinear");
  scene::Object object;
  object.loc = loc;
  scene::TriangleMesh mesh;
  add_triangle(mesh, std::move(triangle), -1);
  object.shape = std::move(mesh);
  return parse_modifiers(block, std::move(object));
}

scene::ObjectPtr parse_mesh(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "mesh", loc);
  scene::Object object;
  object.loc = loc;
  object.shape = scene::TriangleMesh{};
  size_t dropped = 0;
  static constexpr std::string_view kOwn[] = {"triangle", "smooth_triangle", "inside_vector",
                                              "hierarchy"};
  auto own = [&](ObjectBuilder& builder) {
    auto& mesh = std::get<scene::TriangleMesh>(builder.object().shape);
    if (at_word(parser, "triangle") || at_word(parser, "smooth_triangle")) {
      if (builder.modified()) builder.fail_after_modifiers("the mesh's triangles");
      ParsedTriangle triangle = parse_mesh_triangle(parser);
      if (degenerate(triangle)) {
        ++dropped;  // POV-Ray drops these too
        return true;
      }
      // Its corners, normals, texture and face, in the scene's element budget.
      const std::size_t elements = (triangle.smooth ? 7 : 4) + (triangle.texture ? 1 : 0);
      parser.count_mesh_elements(mesh.counted, mesh.counted.count() + elements, triangle.loc);
      int texture = -1;
      if (triangle.texture) {
        texture = int(mesh.textures.size());
        mesh.textures.push_back(std::make_shared<const scene::Texture>(*triangle.texture));
      }
      add_triangle(mesh, std::move(triangle), texture);
    } else if (accept_word(parser, "inside_vector")) {
      mesh.inside_vector = vector_param(parser, "inside_vector");
      if (*mesh.inside_vector == Vec3(0.0)) parser.fail(loc, "inside_vector must not be 0");
    } else if (accept_word(parser, "hierarchy")) {
      optional_bool(parser);  // a bounding-box hint; our meshes are always bounded
    } else {
      return false;
    }
    return true;
  };
  scene::ObjectPtr result = parse_modifiers(block, std::move(object), kOwn, own);
  if (dropped > 0) {
    parser.warn(loc, "mesh: " + std::to_string(dropped) +
                         " degenerate triangle(s) (collinear corners) dropped");
  }
  if (std::get<scene::TriangleMesh>(result->shape).faces.empty()) {
    parser.fail(loc, "mesh has no triangles");
  }
  return result;
}

}  // namespace convray::sdl::items
