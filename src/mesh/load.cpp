#include "mesh/load.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "mesh/format.hpp"
#include "mesh/gzip.hpp"
#include "mesh/load_error.hpp"
#include "mesh/polygon_mesh.hpp"
#include "mesh/readers.hpp"
#include "util/file_kind.hpp"

namespace convray::mesh {
namespace {

// The whole file in one allocation of its size (meshes are read whole: PLY's elements may
// come in any order, OBJ's faces may point forward).
std::string read_file(const std::string& path) {
  // A folder, named pipe (which would wait for a writer), device (/dev/zero never ends) or a
  // loop of links is named as what it is.
  if (const std::optional<std::string> kind = not_a_file(path)) {
    fail(path, "cannot read the file: it " + *kind);
  }
  std::error_code error;
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open the file: ") + std::strerror(errno));
  std::string bytes;
  char buffer[1 << 16];
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (!error) bytes.reserve(static_cast<size_t>(size));
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) bytes.append(buffer, static_cast<size_t>(in.gcount()));
  if (in.bad()) fail(path, std::string("cannot read the file: ") + std::strerror(errno));
  return bytes;
}

PolygonMesh read_format(std::string_view bytes, MeshFormat format, const std::string& name) {
  switch (format) {
    case MeshFormat::Obj: return read_obj(bytes, name);
    case MeshFormat::Ply: return read_ply(bytes, name);
    case MeshFormat::Stl: return read_stl(bytes, name);
    case MeshFormat::Off: return read_off(bytes, name);
  }
  fail(name, "unknown mesh format");
}

[[noreturn]] void fail_nothing_to_render(const LoadedMesh& mesh, const std::string& file) {
  const LoadReport& report = mesh.report;
  if (mesh.soup.vertices.empty()) fail(file, "the file has no vertices, so there is nothing to render");
  std::string what = "nothing left to render:";
  if (report.faces_read > 0)
    what += " all " + std::to_string(report.faces_read) + " faces are degenerate (" +
            std::to_string(report.dropped_zero_area) + " with zero area, " +
            std::to_string(report.dropped_repeated_vertex) + " with a repeated vertex)";
  if (report.faces_read > 0 && report.lines_read > 0) what += ", and";
  if (report.lines_read > 0)
    what += " all " + std::to_string(report.dropped_zero_length) + " segments of the " +
            std::to_string(report.lines_read) + " lines have zero length";
  fail(file, what);
}

}  // namespace

Box3 LoadedMesh::bounds() const {
  Box3 box = soup.bounds();
  for (const Segment& s : segments) box.extend(soup.vertices[s[0]]), box.extend(soup.vertices[s[1]]);
  for (uint32_t p : points) box.extend(soup.vertices[p]);
  return box;
}

LoadedMesh load_mesh(const std::string& path) {
  // Check the name first: an unknown format is reported without reading the file.
  format_from_name(path);
  return load_mesh_from_memory(read_file(path), path);
}

LoadedMesh load_mesh_from_memory(std::string_view bytes, const std::string& name) {
  FileFormat format = format_from_name(name);
  std::vector<char> inflated;
  if (format.gzip) {
    if (bytes.empty()) fail(name, "the file is empty");
    inflated = gunzip(bytes, name);
    bytes = std::string_view(inflated.data(), inflated.size());
  }
  if (bytes.empty()) fail(name, format.gzip ? "the decompressed file is empty" : "the file is empty");

  LoadedMesh mesh = build_soup(read_format(bytes, format.format, name), name);
  if (mesh.soup.triangles.empty() && mesh.segments.empty() && mesh.points.empty()) fail_nothing_to_render(mesh, name);
  if (format.gzip) mesh.format += ", gzip-compressed";
  return mesh;
}

void fit_into_box(LoadedMesh& mesh, double size) { fit_into_box(mesh.soup.vertices, mesh.bounds(), size); }

void require_triangles(const LoadedMesh& mesh, const std::string& file, const std::string& what) {
  if (!mesh.soup.triangles.empty()) return;
  fail(file, what + " needs triangles, but the file has none (" + std::to_string(mesh.segments.size()) +
                 " segments, " + std::to_string(mesh.points.size()) + " points)");
}

}  // namespace convray::mesh
