// PLY, STL and OFF through assimp 5.2, after our own checks (src/mesh/*_check.hpp).
//
// assimp is given only bytes those checks accepted, and only the one importer for the
// format: assimp would otherwise try every importer whose signature test a byte sequence
// happens to pass, and several of them crash on malformed input. What assimp then reads
// is compared with what the checks read, so a misreading cannot slip through either.
#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <memory>
#include <span>
#include <vector>

#include "mesh/load_error.hpp"
#include "mesh/off_check.hpp"
#include "mesh/ply_check.hpp"
#include "mesh/readers.hpp"
#include "mesh/stl_check.hpp"

namespace convray::mesh {
namespace {

const char* format_label(MeshFormat format) {
  switch (format) {
    case MeshFormat::Ply: return "PLY";
    case MeshFormat::Stl: return "STL";
    case MeshFormat::Off: return "OFF";
    case MeshFormat::Obj: return "OBJ";
  }
  return "?";
}

// An Importer that knows one format only. assimp does not delete the importers it is asked
// to unregister, so this class does. assimp's logger stays the silent default NullLogger:
// we never create one.
class SingleFormatImporter {
 public:
  SingleFormatImporter(MeshFormat format, const std::string& file) {
    int keep = importer_.GetImporterIndex(extension_of(format));
    if (keep < 0) fail(file, std::string("this assimp has no ") + format_label(format) + " importer");
    std::vector<Assimp::BaseImporter*> others;
    for (size_t i = 0; i < importer_.GetImporterCount(); ++i) {
      if (static_cast<int>(i) != keep) others.push_back(importer_.GetImporter(i));
    }
    for (Assimp::BaseImporter* other : others) {
      importer_.UnregisterLoader(other);
      unregistered_.emplace_back(other);
    }
  }

  Assimp::Importer& get() { return importer_; }

 private:
  std::vector<std::unique_ptr<Assimp::BaseImporter>> unregistered_;  // destroyed after importer_
  Assimp::Importer importer_;
};

// assimp's messages can quote the rest of the file; one line of at most 200 bytes is enough.
std::string shortened(std::string message) {
  constexpr size_t kMaxLength = 200;
  message = message.substr(0, message.find_first_of("\r\n"));
  if (message.size() > kMaxLength) message = message.substr(0, kMaxLength) + "...";
  return message;
}

const aiScene* import(SingleFormatImporter& importer, std::string_view bytes, MeshFormat format,
                      const std::string& file) {
  // No aiProcess_Triangulate: build_soup() triangulates every format the same way and counts
  // what it did. No JoinIdenticalVertices or anything else that changes the triangles.
  const aiScene* scene = importer.get().ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_ValidateDataStructure,
                                                           extension_of(format));
  if (!scene) fail(file, std::string(format_label(format)) + " reader: " + shortened(importer.get().GetErrorString()));
  return scene;
}

// All meshes of the scene, one after the other (ASCII STL makes one mesh per solid).
PolygonMesh collect_polygons(const aiScene& scene) {
  PolygonMesh polygons;
  std::vector<int64_t> corners;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    const int64_t base = static_cast<int64_t>(polygons.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      polygons.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      corners.assign(face.mIndices, face.mIndices + face.mNumIndices);
      for (int64_t& corner : corners) corner += base;
      polygons.add_face(corners);
    }
  }
  return polygons;
}

[[noreturn]] void fail_disagreement(const std::string& file, MeshFormat format, const std::string& what) {
  fail(file, std::string(format_label(format)) + " reader and convray's own check of the file disagree about " +
                 what + "; the file uses " + format_label(format) + " syntax convray does not understand");
}

// assimp must have read exactly the vertices and faces our check found.
void compare(const PolygonMesh& read, uint64_t vertex_count, const PolygonMesh& checked, MeshFormat format,
             const std::string& file) {
  if (read.vertices.size() != vertex_count) fail_disagreement(file, format, "the number of vertices");
  if (read.face_count() != checked.face_count()) fail_disagreement(file, format, "the number of faces");
  if (read.face_ends != checked.face_ends) fail_disagreement(file, format, "the corners of the faces");
  for (size_t f = 0; f < checked.face_count(); ++f) {
    std::span<const int64_t> a = read.face(f), b = checked.face(f);
    if (!std::equal(a.begin(), a.end(), b.begin(), b.end()))
      fail_disagreement(file, format, "face " + std::to_string(f));
  }
}

PolygonMesh read_checked(std::string_view bytes, MeshFormat format, uint64_t vertex_count, PolygonMesh checked,
                         const std::string& file) {
  SingleFormatImporter importer(format, file);
  PolygonMesh read = collect_polygons(*import(importer, bytes, format, file));
  compare(read, vertex_count, checked, format, file);
  read.format = checked.format;
  return read;
}

// assimp's line reader for ASCII PLY can run past its buffer on a "\r" at the end of a
// 16 MiB block, and drops a last line without "\n" in files of more than one block; a copy
// with plain "\n" line ends avoids both.
std::string with_plain_line_ends(std::string_view bytes) {
  std::string text;
  text.reserve(bytes.size() + 1);
  for (size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i] == '\r' && i + 1 < bytes.size() && bytes[i + 1] == '\n') continue;
    text += bytes[i];
  }
  if (text.empty() || text.back() != '\n') text += '\n';
  return text;
}

PolygonMesh read_ply(std::string_view bytes, const std::string& file) {
  PlyContents contents = check_ply(bytes, file);
  if (contents.faces.face_count() == 0) return std::move(contents.faces);  // build_soup reports "no triangles"
  bool plain = bytes.find('\r') == std::string_view::npos && bytes.back() == '\n';
  if (contents.encoding == PlyEncoding::Ascii && !plain) {
    std::string text = with_plain_line_ends(bytes);
    return read_checked(text, MeshFormat::Ply, contents.vertex_count, std::move(contents.faces), file);
  }
  return read_checked(bytes, MeshFormat::Ply, contents.vertex_count, std::move(contents.faces), file);
}

PolygonMesh read_off(std::string_view bytes, const std::string& file) {
  OffContents contents = check_off(bytes, file);
  return read_checked(bytes, MeshFormat::Off, contents.vertex_count, std::move(contents.faces), file);
}

PolygonMesh read_stl(std::string_view bytes, const std::string& file) {
  StlContents contents = check_stl(bytes, file);
  PolygonMesh empty;
  empty.format = contents.encoding == StlEncoding::Ascii ? "STL ascii" : "STL binary";
  if (contents.triangle_count == 0) return empty;  // build_soup reports "no triangles"
  SingleFormatImporter importer(MeshFormat::Stl, file);
  PolygonMesh read = collect_polygons(*import(importer, bytes.substr(contents.text_start), MeshFormat::Stl, file));
  if (read.face_count() != contents.triangle_count) fail_disagreement(file, MeshFormat::Stl, "the number of triangles");
  read.format = empty.format;
  read.vertex_per_corner = true;
  return read;
}

}  // namespace

PolygonMesh read_with_assimp(std::string_view bytes, MeshFormat format, const std::string& file) {
  switch (format) {
    case MeshFormat::Ply: return read_ply(bytes, file);
    case MeshFormat::Off: return read_off(bytes, file);
    case MeshFormat::Stl: return read_stl(bytes, file);
    case MeshFormat::Obj: break;
  }
  fail(file, "internal error: OBJ is not read through assimp");
}

}  // namespace convray::mesh
