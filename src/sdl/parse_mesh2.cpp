// mesh2 { vertex_vectors {n, ...} normal_vectors {n, ...} texture_list {n, ...}
//         face_indices {n, <a,b,c> [, t [, t2, t3]] ...} normal_indices {n, ...} ... }
// Counts must match what the lists hold and every index must be in range: errors name the
// list and the entry.
#include <glm/geometric.hpp>

#include <cmath>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

// Reads `NAME { n, item, item, ... }` with `read_item` and checks the count; each item read
// counts one element in `counted` (the scene's budget, not the declared n: a count of 10^9 with
// nothing behind it takes no memory).
template <class ReadItem>
void parse_counted_list(Parser& parser, ElementCount& counted, const std::string& name,
                        ReadItem read_item) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, name, loc);
  // The float reader stops at a '<': `14 <-1, -1, -1>` is a count and a first vector, not
  // 14 < -1 (objects/mesh2.pov), as POV-Ray reads it.
  const double count = parser.parse_float_before_points();
  if (!std::isfinite(count) || std::abs(count) > 1e9) {
    parser.fail(loc, name + ": the count must be a number of items");
  }
  const int declared = int(count);
  if (declared < 0) parser.fail(loc, name + ": the count must not be negative");
  int listed = 0;
  while (true) {
    parser.accept_comma();
    if (!block.more()) break;
    parser.count_mesh_elements(counted, counted.count() + 1, parser.peek().loc);
    read_item(listed);
    ++listed;
  }
  if (listed != declared) {
    parser.fail(
        loc, name + " says " + std::to_string(declared) + " but lists " + std::to_string(listed));
  }
}

std::array<int, 3> index_triple(Parser& parser, const std::string& what) {
  const SourceLoc loc = parser.peek().loc;
  const Vec3 v = vector_param(parser, what);
  std::array<int, 3> indices{};
  for (int k = 0; k < 3; ++k) {
    if (v[k] != std::floor(v[k]) || v[k] < 0.0 || v[k] > 2e9) {
      parser.fail(loc, what + ": indices must be whole numbers >= 0, found " + number_text(v[k]));
    }
    indices[size_t(k)] = int(v[k]);
  }
  return indices;
}

struct Mesh2Lists {
  std::vector<Vec3> vertices, normals;
  std::vector<scene::TexturePtr> textures;
  std::vector<std::array<int, 3>> faces, normal_faces;
  std::vector<int> face_textures;  // -1: none
  bool has_normal_indices = false;
  ElementCount counted;  // every item of every list, in the scene's element budget
};

void parse_face_indices(Parser& parser, Mesh2Lists& lists) {
  parse_counted_list(parser, lists.counted, "face_indices", [&](int index) {
    lists.faces.push_back(index_triple(parser, "face " + std::to_string(index)));
    int texture = -1;
    parser.accept_comma();
    if (at_float_start(parser)) {
      texture = int_param(parser, "the texture index of face " + std::to_string(index));
      parser.accept_comma();
      if (at_float_start(parser)) {
        // Three texture indices interpolate textures across the face: not supported; the
        // first corner's texture is used.
        const SourceLoc loc = parser.peek().loc;
        int_param(parser, "texture index 2");
        parser.accept_comma();
        int_param(parser, "texture index 3");
        warn_once(parser, loc,
                  "per-corner texture indices: each face uses its first corner's texture");
      }
    }
    lists.face_textures.push_back(texture);
  });
}

void parse_mesh2_lists(Parser& parser, Mesh2Lists& lists, const std::string& word) {
  if (word == "vertex_vectors") {
    parse_counted_list(parser, lists.counted, word,
                       [&](int) { lists.vertices.push_back(vector_param(parser, "a vertex")); });
  } else if (word == "normal_vectors") {
    parse_counted_list(parser, lists.counted, word,
                       [&](int) { lists.normals.push_back(vector_param(parser, "a normal")); });
  } else if (word == "texture_list") {
    parse_counted_list(parser, lists.counted, word, [&](int) {
      if (!at_word(parser, "texture")) parser.fail_here("expected a texture in texture_list");
      lists.textures.push_back(
          std::make_shared<const scene::Texture>(parse_texture(parser, parser.defaults().texture)));
    });
  } else if (word == "face_indices") {
    parse_face_indices(parser, lists);
  } else if (word == "normal_indices") {
    lists.has_normal_indices = true;
    parse_counted_list(parser, lists.counted, word, [&](int index) {
      lists.normal_faces.push_back(
          index_triple(parser, "normals of face " + std::to_string(index)));
    });
  } else {  // uv_vectors, uv_indices
    const SourceLoc loc = parser.peek().loc;
    skip_braced(parser, word, take_keyword(parser));
    warn_once(parser, loc, word + " are ignored: convray has no uv mapping");
  }
}

void check_range(Parser& parser, const SourceLoc& loc, const std::array<int, 3>& indices,
                 size_t count, const std::string& what, size_t face) {
  for (int index : indices) {
    if (size_t(index) >= count) {
      parser.fail(loc, "mesh2: face " + std::to_string(face) + " refers to " + what + " " +
                           std::to_string(index) + ", but there are " + std::to_string(count));
    }
  }
}

scene::TriangleMesh build_mesh2(Parser& parser, const SourceLoc& loc, Mesh2Lists& lists) {
  if (lists.vertices.empty()) parser.fail(loc, "mesh2 needs vertex_vectors");
  if (lists.faces.empty()) parser.fail(loc, "mesh2 needs face_indices");
  const bool smooth = !lists.normals.empty();
  if (smooth && !lists.has_normal_indices) lists.normal_faces = lists.faces;  // POV-Ray's rule
  if (smooth && lists.normal_faces.size() != lists.faces.size()) {
    parser.fail(loc, "mesh2: normal_indices must list as many faces as face_indices");
  }
  scene::TriangleMesh mesh;
  mesh.counted = std::move(lists.counted);
  mesh.vertices = std::move(lists.vertices);
  mesh.normals = std::move(lists.normals);
  mesh.textures = std::move(lists.textures);
  for (size_t f = 0; f < lists.faces.size(); ++f) {
    check_range(parser, loc, lists.faces[f], mesh.vertices.size(), "vertex", f);
    scene::MeshFace face;
    face.vertices = lists.faces[f];
    if (smooth) {
      check_range(parser, loc, lists.normal_faces[f], mesh.normals.size(), "normal", f);
      face.normals = lists.normal_faces[f];
    }
    face.texture = lists.face_textures[f];
    if (face.texture >= int(mesh.textures.size())) {
      parser.fail(loc, "mesh2: face " + std::to_string(f) + " refers to texture " +
                           std::to_string(face.texture) + ", but texture_list has " +
                           std::to_string(mesh.textures.size()));
    }
    const auto& v = mesh.vertices;
    const Vec3 area = glm::cross(v[size_t(face.vertices[1])] - v[size_t(face.vertices[0])],
                                 v[size_t(face.vertices[2])] - v[size_t(face.vertices[0])]);
    if (area != Vec3(0.0)) mesh.faces.push_back(face);  // degenerate faces are dropped
  }
  const size_t dropped = lists.faces.size() - mesh.faces.size();
  if (dropped > 0) {
    parser.warn(loc, "mesh2: " + std::to_string(dropped) + " degenerate face(s) dropped");
  }
  if (mesh.faces.empty()) parser.fail(loc, "mesh2 has no triangle with an area");
  return mesh;
}

}  // namespace

scene::ObjectPtr parse_mesh2(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "mesh2", loc);
  static constexpr std::string_view kLists[] = {
      "vertex_vectors", "normal_vectors", "uv_vectors", "texture_list",
      "face_indices",   "normal_indices", "uv_indices"};
  Mesh2Lists lists;
  while (at_any_word(parser, kLists)) {
    const std::string word = parser.peek().text;  // a copy: peek() changes as tokens go
    parse_mesh2_lists(parser, lists, word);
  }
  scene::Object object;
  object.loc = loc;
  object.shape = build_mesh2(parser, loc, lists);
  static constexpr std::string_view kOwn[] = {"inside_vector",  "hierarchy",      "vertex_vectors",
                                              "normal_vectors", "uv_vectors",     "texture_list",
                                              "face_indices",   "normal_indices", "uv_indices"};
  return parse_modifiers(block, std::move(object), kOwn, [&](ObjectBuilder& builder) {
    auto& mesh = std::get<scene::TriangleMesh>(builder.object().shape);
    if (at_any_word(parser, kLists)) {
      if (builder.modified()) builder.fail_after_modifiers("mesh2's lists");
      parser.fail_here("mesh2: " + parser.peek().text +
                       " must come before inside_vector and hierarchy");
    }
    if (accept_word(parser, "inside_vector")) {
      mesh.inside_vector = vector_param(parser, "inside_vector");
      if (*mesh.inside_vector == Vec3(0.0)) parser.fail(loc, "inside_vector must not be 0");
      return true;
    }
    if (accept_word(parser, "hierarchy")) {
      optional_bool(parser);
      return true;
    }
    return false;
  });
}

}  // namespace convray::sdl::items
