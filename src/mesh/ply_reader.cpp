// PLY by its specification (Greg Turk's "The PLY Polygon File Format", and the element
// conventions of the Stanford and MeshLab files): elements in any order, any number of
// other elements and properties (skipped by their declared types), every scalar and list
// type, text and both binary byte orders.
//
// What is read:
//   vertex     x, y, z (any scalar type); everything else skipped
//   face       `vertex_indices` or `vertex_index` (a list of integers): one polygon each
//   tristrips  `vertex_indices`: triangle strips, -1 restarting the strip (MeshLab, Cyberware)
//   edge       `vertex1`, `vertex2`: one segment each
// Every other element (camera, range_grid, material, ...) is skipped.
//
// One pass over the body, streaming: each value is read once, in file order, and indices are
// checked against the vertex count the header declares as they are read, so an error names
// the line (text) and the element even when faces come before the vertices. Whatever follows
// the declared data (values at the end of a text line, bytes or lines after the last element)
// is ignored, as line-based readers ignore it: writers leave such things behind.
#include <algorithm>
#include <cmath>

#include "mesh/load_error.hpp"
#include "mesh/ply_body.hpp"
#include "mesh/readers.hpp"

namespace convray::mesh {
namespace {

// What a property is read for.
enum class Use : uint8_t { skip, x, y, z, face, strip, edge_first, edge_second };

struct ElementPlan {
  const PlyElement* element = nullptr;
  std::vector<Use> uses;  // one per property
  bool is_vertex = false;
  bool is_edge = false;
  bool is_face = false;
  bool is_one_face_list = false;  // a face element whose only property is its index list
  bool skipped = true;    // no property is read

  // Bytes per instance when no property is a list; 0 otherwise.
  uint64_t fixed_size() const {
    uint64_t size = 0;
    for (const PlyProperty& property : element->properties) {
      if (property.is_list) return 0;
      size += size_of(property.type);
    }
    return size;
  }
};

class Planner {
 public:
  explicit Planner(const std::string& file) : file_(file) {}

  ElementPlan plan(const PlyElement& element) {
    ElementPlan plan{&element, std::vector<Use>(element.properties.size(), Use::skip)};
    if (element.count == 0) return plan;
    if (element.name == "vertex") plan_vertex(plan);
    else if (element.name == "face") plan_indices(plan, Use::face);
    else if (element.name == "tristrips") plan_indices(plan, Use::strip);
    else if (element.name == "edge") plan_edge(plan);
    plan.is_face = element.name == "face";
    plan.is_one_face_list = plan.is_face && plan.uses.size() == 1;
    plan.skipped = std::all_of(plan.uses.begin(), plan.uses.end(), [](Use use) { return use == Use::skip; });
    return plan;
  }

 private:
  void plan_vertex(ElementPlan& plan) {
    plan.is_vertex = true;
    const Use axes[] = {Use::x, Use::y, Use::z};
    const char* names[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      size_t at = index_of(*plan.element, names[k]);
      if (at == kNone || plan.element->properties[at].is_list)
        fail(file_, std::string("the PLY vertex element has no scalar property '") + names[k] + "'");
      plan.uses[at] = axes[k];
    }
  }

  void plan_indices(ElementPlan& plan, Use use) {
    const PlyElement& element = *plan.element;
    size_t indices = index_of(element, "vertex_indices");
    size_t index = use == Use::face ? index_of(element, "vertex_index") : kNone;
    if (indices != kNone && index != kNone)
      fail(file_, "the PLY face element has both 'vertex_indices' and 'vertex_index'");
    size_t at = indices != kNone ? indices : index;
    if (at == kNone || !element.properties[at].is_list || !is_integer(element.properties[at].type))
      fail(file_, "the PLY " + element.name + " element has no list of integer 'vertex_indices'");
    plan.uses[at] = use;
  }

  void plan_edge(ElementPlan& plan) {
    plan.is_edge = true;
    const Use ends[] = {Use::edge_first, Use::edge_second};
    const char* names[] = {"vertex1", "vertex2"};
    for (int k = 0; k < 2; ++k) {
      size_t at = index_of(*plan.element, names[k]);
      if (at == kNone || plan.element->properties[at].is_list || !is_integer(plan.element->properties[at].type))
        fail(file_, std::string("the PLY edge element has no integer property '") + names[k] + "'");
      plan.uses[at] = ends[k];
    }
  }

  static constexpr size_t kNone = SIZE_MAX;
  static size_t index_of(const PlyElement& element, std::string_view name) {
    for (size_t k = 0; k < element.properties.size(); ++k) {
      if (element.properties[k].name == name) return k;
    }
    return kNone;
  }

  const std::string& file_;
};

// Reads every element the plan asks for into `mesh`, from either kind of body.
template <class Body>
class ElementWalk {
 public:
  ElementWalk(Body& body, PolygonMesh& mesh, uint64_t vertex_count, const std::string& file)
      : body_(body), mesh_(mesh), vertex_count_(vertex_count), file_(file) {}

  void read(const ElementPlan& plan) {
    const PlyElement& element = *plan.element;
    if (element.properties.empty() || element.count == 0) return;
    if constexpr (Body::kBinary) {
      // Elements of fixed size are checked in one step, before anything is allocated.
      const uint64_t size = plan.fixed_size();
      if (size > 0 && plan.skipped) return body_.skip_fixed(element, size);
      if (size > 0 && element.count > body_.remaining() / size) body_.skip_fixed(element, size);  // fails
    }
    // Text needs at least two bytes ("0\n") per instance, binary one: a header that claims
    // more instances than the bytes can hold reserves no more than they can.
    if (plan.is_vertex) mesh_.vertices.reserve(std::min<uint64_t>(element.count, body_.remaining() / 2 + 1));
    if (plan.is_face) reserve_faces(element.count);
    for (uint64_t i = 0; i < element.count; ++i) read_instance(plan, i);
  }

 private:
  void read_instance(const ElementPlan& plan, uint64_t i) {
    const PlyElement& element = *plan.element;
    element_ = &element, index_ = i;
    if constexpr (!Body::kBinary) {
      if (plan.is_one_face_list && body_.read_plain_list(element, i, element.properties[0], corners_))
        return add_face();
    }
    body_.begin(element, i);
    Vec3 position(0.0);
    int64_t edge[2] = {0, 0};
    for (size_t k = 0; k < plan.uses.size(); ++k) {
      const PlyProperty& property = element.properties[k];
      switch (plan.uses[k]) {
        case Use::skip: skip(property); break;
        case Use::x: position.x = body_.real(property.type, property); break;
        case Use::y: position.y = body_.real(property.type, property); break;
        case Use::z: position.z = body_.real(property.type, property); break;
        case Use::face: read_face(property); break;
        case Use::strip: read_strip(property); break;
        case Use::edge_first: edge[0] = checked_index(body_.integer(property.type, property)); break;
        case Use::edge_second: edge[1] = checked_index(body_.integer(property.type, property)); break;
      }
    }
    body_.end();
    if (plan.is_vertex) add_vertex(position, i);
    if (plan.is_edge) mesh_.lines.add(edge);
  }

  // Room for `count` triangles more, or as many as the bytes left could hold as text
  // ("3 0 1 2\n"), whichever is fewer: growing the lists of a large mesh a doubling at a time
  // copied each index about twice, and a header that claims billions of faces must not make
  // us reserve more than four times the file's size (polygons, and binary files of tiny
  // indices, grow the lists beyond it as before).
  void reserve_faces(uint64_t count) {
    const uint64_t faces = std::min<uint64_t>(count, body_.remaining() / 8 + 1);
    IndexLists& lists = mesh_.faces;
    lists.ends.reserve(lists.ends.size() + faces);
    lists.items.reserve(lists.items.size() + 3 * faces);
  }

  void skip(const PlyProperty& property) {
    uint64_t count = property.is_list ? list_length(property) : 1;
    body_.skip(property.type, count, property);
  }

  uint64_t list_length(const PlyProperty& property) {
    int64_t count = body_.integer(property.count_type, property);
    if (count < 0) fail_here("list '" + property.name + "' has a negative length");
    return static_cast<uint64_t>(count);
  }

  void read_list(const PlyProperty& property) {
    uint64_t count = list_length(property);
    // A binary item takes at least one byte: a count beyond the bytes left is a truncated file
    // (found before anything is allocated). Text runs out of values on its line first.
    if constexpr (Body::kBinary) {
      if (count > body_.remaining()) body_.skip(property.type, count, property);  // fails
    }
    corners_.clear();
    for (uint64_t k = 0; k < count; ++k) corners_.push_back(body_.integer(property.type, property));
  }

  void read_face(const PlyProperty& property) {
    read_list(property);
    add_face();
  }

  // The face read into corners_.
  void add_face() {
    if (corners_.size() < 3) fail_here("face has " + std::to_string(corners_.size()) + " corners; at least 3 are needed");
    for (int64_t corner : corners_) checked_index(corner);
    mesh_.add_face(corners_);
  }

  // A strip v0 v1 v2 v3 ... is the triangles (v0 v1 v2), (v2 v1 v3), (v2 v3 v4), ...: every
  // other one reversed, so that all face the same way. -1 ends a strip and starts the next.
  // Triangles that name a vertex twice only stitch strips together; they are not faces.
  void read_strip(const PlyProperty& property) {
    read_list(property);
    size_t start = 0;
    for (size_t k = 0; k < corners_.size(); ++k) {
      if (corners_[k] == -1) {
        start = k + 1;
        continue;
      }
      checked_index(corners_[k]);
      if (k < start + 2) continue;
      const bool odd = (k - start) % 2 == 1;
      const int64_t triangle[3] = {corners_[odd ? k - 1 : k - 2], corners_[odd ? k - 2 : k - 1], corners_[k]};
      if (triangle[0] != triangle[1] && triangle[1] != triangle[2] && triangle[2] != triangle[0])
        mesh_.add_face(triangle);
    }
  }

  // The message is made apart, so that the check itself is inlined (it runs once per corner).
  int64_t checked_index(int64_t index) {
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count_) fail_index(index);
    return index;
  }

  [[noreturn]] [[gnu::noinline]] void fail_index(int64_t index) const {
    fail_here(std::string(element_->name == "edge" ? "edge" : "face") + " refers to vertex " +
              std::to_string(index) + ", but the file has " + std::to_string(vertex_count_) + " vertices");
  }

  void add_vertex(const Vec3& position, uint64_t i) {
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
      fail(file_, "vertex has a non-finite coordinate" + in_vertex(i), body_.line());
    mesh_.vertices.push_back(position);
  }

  [[noreturn]] void fail_here(const std::string& what) const {
    fail(file_, what + element_label(*element_, index_), body_.line());
  }

  Body& body_;
  PolygonMesh& mesh_;
  uint64_t vertex_count_;
  const std::string& file_;
  std::vector<int64_t> corners_;
  const PlyElement* element_ = nullptr;
  uint64_t index_ = 0;
};

template <class Body>
void read_elements(Body& body, const std::vector<ElementPlan>& plans, PolygonMesh& mesh, uint64_t vertex_count,
                   const std::string& file) {
  ElementWalk<Body> walk(body, mesh, vertex_count, file);
  for (const ElementPlan& plan : plans) walk.read(plan);
}

}  // namespace

PolygonMesh read_ply(std::string_view bytes, const std::string& file) {
  PlyHeader header = parse_ply_header(bytes, file);
  const PlyElement* vertex = header.find("vertex");
  if (!vertex) fail(file, "the PLY header declares no 'vertex' element, so there is nothing to render");
  Planner planner(file);
  std::vector<ElementPlan> plans;
  for (const PlyElement& element : header.elements) plans.push_back(planner.plan(element));

  PolygonMesh mesh;
  mesh.format = std::string("PLY ") + name_of(header.encoding);
  if (header.encoding == PlyEncoding::Ascii) {
    AsciiPlyBody body(bytes, header.body_offset, header.body_line, file);
    read_elements(body, plans, mesh, vertex->count, file);
  } else if (header.encoding == PlyEncoding::BinaryLittleEndian) {
    BinaryPlyBody<false> body(bytes, header.body_offset, file);
    read_elements(body, plans, mesh, vertex->count, file);
  } else {
    BinaryPlyBody<true> body(bytes, header.body_offset, file);
    read_elements(body, plans, mesh, vertex->count, file);
  }
  return mesh;
}

}  // namespace convray::mesh
