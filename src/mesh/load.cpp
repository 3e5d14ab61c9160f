#include "mesh/load.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesh/format.hpp"
#include "mesh/gzip.hpp"
#include "mesh/load_error.hpp"
#include "mesh/polygon_mesh.hpp"
#include "mesh/readers.hpp"

namespace convray::mesh {
namespace {

std::string read_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) fail(path, "cannot read the file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open the file: ") + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) fail(path, std::string("cannot read the file: ") + std::strerror(errno));
  return std::move(bytes).str();
}

[[noreturn]] void fail_no_triangles(const LoadReport& report, const std::string& file) {
  if (report.faces_read == 0) fail(file, "the file has no faces, so there are no triangles to render");
  fail(file, "no triangles left: all " + std::to_string(report.faces_read) + " faces are degenerate (" +
                 std::to_string(report.dropped_zero_area) + " with zero area, " +
                 std::to_string(report.dropped_repeated_vertex) + " with a repeated vertex)");
}

}  // namespace

LoadedMesh load_mesh(const std::string& path) {
  // Check the name first: an unknown format is reported without reading the file.
  format_from_name(path);
  return load_mesh_from_memory(read_file(path), path);
}

LoadedMesh load_mesh_from_memory(std::string_view bytes, const std::string& name) {
  FileFormat format = format_from_name(name);
  std::string inflated;
  if (format.gzip) {
    if (bytes.empty()) fail(name, "the file is empty");
    inflated = gunzip(bytes, name);
    bytes = inflated;
  }
  if (bytes.empty()) fail(name, format.gzip ? "the decompressed file is empty" : "the file is empty");

  PolygonMesh polygons = format.format == MeshFormat::Obj ? read_obj(bytes, name)
                                                          : read_with_assimp(bytes, format.format, name);
  LoadedMesh mesh = build_soup(std::move(polygons), name);
  if (mesh.soup.triangles.empty()) fail_no_triangles(mesh.report, name);
  if (format.gzip) mesh.format += ", gzip-compressed";
  return mesh;
}

}  // namespace convray::mesh
