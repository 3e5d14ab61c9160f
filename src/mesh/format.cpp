#include "mesh/format.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "mesh/load_error.hpp"

namespace convray::mesh {
namespace {

const char* const kExpected = "(expected .obj, .ply, .stl, .off, optionally .gz)";

// ".PLY" -> ".ply"; "" when the file name has no extension.
std::string lowercase_extension(const std::string& name) {
  size_t slash = name.find_last_of("/\\");
  size_t dot = name.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = name.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

std::optional<MeshFormat> format_of_extension(const std::string& extension) {
  if (extension == ".obj") return MeshFormat::Obj;
  if (extension == ".ply") return MeshFormat::Ply;
  if (extension == ".stl") return MeshFormat::Stl;
  if (extension == ".off") return MeshFormat::Off;
  return std::nullopt;
}

[[noreturn]] void fail_unknown(const std::string& name, const std::string& extension) {
  if (extension.empty()) fail(name, std::string("unknown mesh format: the name has no extension ") + kExpected);
  fail(name, "unknown mesh format '" + extension + "' " + kExpected);
}

}  // namespace

FileFormat format_from_name(const std::string& name) {
  std::string extension = lowercase_extension(name);
  bool gzip = extension == ".gz";
  if (gzip) extension = lowercase_extension(name.substr(0, name.size() - 3));
  std::optional<MeshFormat> format = format_of_extension(extension);
  if (!format) fail_unknown(name, gzip ? extension + ".gz" : extension);
  return {*format, gzip};
}

const char* extension_of(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj: return "obj";
    case MeshFormat::Ply: return "ply";
    case MeshFormat::Stl: return "stl";
    case MeshFormat::Off: return "off";
  }
  return "";
}

bool is_mesh_file_name(const std::string& name) {
  std::string extension = lowercase_extension(name);
  if (extension == ".gz") extension = lowercase_extension(name.substr(0, name.size() - 3));
  return format_of_extension(extension).has_value();
}

}  // namespace convray::mesh
