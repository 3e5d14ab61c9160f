#pragma once
// Which reader a file name selects: its extension, case-insensitive, with an optional `.gz`
// in front of which the real extension sits (`dragon_vrip.ply.gz`). Internal to src/mesh.
#include <string>

namespace convray::mesh {

enum class MeshFormat { Obj, Ply, Stl, Off };

struct FileFormat {
  MeshFormat format;
  bool gzip;  // the bytes are gzip-compressed
};

// Throws InputError `NAME: unknown mesh format '.xyz' (expected .obj, .ply, .stl, .off,
// optionally .gz)` when the name does not end in one of those.
FileFormat format_from_name(const std::string& name);

// "obj", "ply", "stl", "off".
const char* extension_of(MeshFormat format);

}  // namespace convray::mesh
