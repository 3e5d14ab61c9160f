#pragma once
// Telling ASCII from binary STL, and checking what assimp does not: that a binary file has
// exactly the size its triangle count says, and that an ASCII file follows the grammar
// (solid, facet normal, outer loop, three vertices, endloop, endfacet, endsolid). assimp's
// ASCII reader loads a truncated file as fewer triangles without a word, and leaks memory
// whenever it gives up on a malformed one. Internal to src/mesh.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace convray::mesh {

enum class StlEncoding { Ascii, Binary };

struct StlContents {
  StlEncoding encoding = StlEncoding::Binary;
  uint64_t triangle_count = 0;
  size_t text_start = 0;  // ASCII: where "solid" starts (assimp wants no blank lines before it)
};

// Binary when the size is 84 + 50 × (the count at byte 80), as assimp decides; otherwise
// ASCII if the file starts with "solid" and contains no NUL byte (binary headers often
// start with "solid" too, but binary data is full of zeros); otherwise a binary STL of the
// wrong size. Throws InputError for anything malformed.
StlContents check_stl(std::string_view bytes, const std::string& file);

}  // namespace convray::mesh
