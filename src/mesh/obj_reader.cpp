// OBJ through tinyobjloader.
//
// tinyobjloader sees only the `v` and `f` lines, which scan_obj() has checked before: the
// rest of its parser (materials, tags, skin weights, ...) is code convray does not need and
// that fuzzing found undefined behaviour in (an out-of-range float-to-int conversion in `vw`).
//
// Debian's libtinyobjloader.so is built with float coordinates, and a library we link is not
// instrumented when fuzzing. So this file compiles tinyobjloader's (header-only) implementation
// itself, in double precision, inside a namespace of its own so that its symbols cannot clash
// with the shared library's.
#include <istream>
#include <map>
#include <streambuf>
#include <string>
#include <vector>

#define TINYOBJLOADER_IMPLEMENTATION
#define TINYOBJLOADER_USE_DOUBLE
#define tinyobj convray_mesh_tinyobj
#include <tiny_obj_loader.h>
#undef tinyobj

#include "mesh/load_error.hpp"
#include "mesh/obj_check.hpp"
#include "mesh/readers.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

namespace tinyobj = ::convray_mesh_tinyobj;

// An istream over bytes we already hold, without copying them.
class ViewBuffer : public std::streambuf {
 public:
  explicit ViewBuffer(std::string_view bytes) {
    char* begin = const_cast<char*>(bytes.data());  // a get area is only ever read
    setg(begin, begin, begin + bytes.size());
  }
};

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

struct TinyObjResult {
  tinyobj::attrib_t attributes;
  std::vector<tinyobj::shape_t> shapes;
};

TinyObjResult run_tinyobj(std::string_view text, const std::string& file) {
  ViewBuffer buffer(text);
  std::istream stream(&buffer);
  TinyObjResult result;
  std::vector<tinyobj::material_t> materials;  // no material reader: mtllib lines are skipped
  std::string warnings, errors;
  bool ok = tinyobj::LoadObj(&result.attributes, &result.shapes, &materials, &warnings, &errors, &stream,
                             /*readMatFn=*/nullptr, /*triangulate=*/false, /*default_vcols_fallback=*/false);
  if (!ok) fail(file, "OBJ reader: " + first_line(errors));
  return result;
}

// The `v` and `f` lines of the text, nothing else.
std::string vertex_and_face_lines(std::string_view text) {
  std::string kept;
  LineReader lines(text);
  std::string_view line;
  while (lines.next(line)) {
    TokenReader tokens(line);
    std::string_view keyword;
    if (tokens.next(keyword) && (keyword == "v" || keyword == "f")) {
      kept.append(line);
      kept += '\n';
    }
  }
  return kept;
}

[[noreturn]] void fail_disagreement(const std::string& file, const std::string& what) {
  fail(file, "OBJ reader and convray's own check of the file disagree about " + what +
                 "; the file uses OBJ syntax convray does not understand");
}

// tinyobjloader must have seen the very faces the scan saw, in the same order.
void compare_faces(const TinyObjResult& read, const PolygonMesh& scanned, const std::string& file) {
  size_t f = 0, corner = 0;
  for (const tinyobj::shape_t& shape : read.shapes) {
    size_t offset = 0;
    for (unsigned char corner_count : shape.mesh.num_face_vertices) {
      if (f >= scanned.face_count() || scanned.face(f).size() != corner_count ||
          offset + corner_count > shape.mesh.indices.size())
        fail_disagreement(file, "face " + std::to_string(f));
      for (size_t k = 0; k < corner_count; ++k, ++corner) {
        if (shape.mesh.indices[offset + k].vertex_index != scanned.corners[corner])
          fail_disagreement(file, "face " + std::to_string(f));
      }
      offset += corner_count;
      ++f;
    }
  }
  if (f != scanned.face_count()) fail_disagreement(file, "the number of faces");
}

}  // namespace

PolygonMesh read_obj(std::string_view text, const std::string& file) {
  PolygonMesh scanned = scan_obj(text, file);
  TinyObjResult read = run_tinyobj(vertex_and_face_lines(text), file);
  if (read.attributes.vertices.size() != 3 * scanned.vertices.size())
    fail_disagreement(file, "the number of vertices");
  compare_faces(read, scanned, file);
  // The faces agree; the positions are the scan's, which are correctly rounded.
  return scanned;
}

}  // namespace convray::mesh
