#pragma once
// Telling ASCII from binary STL, and checking what assimp does not: that a binary file has
// exactly the size its triangle count says, and that an ASCII file is text that ends with
// `endsolid` (a truncated one otherwise loads as fewer triangles without a word).
// Internal to src/mesh.
#include <cstdint>
#include <string>
#include <string_view>

namespace convray::mesh {

enum class StlEncoding { Ascii, Binary };

struct StlContents {
  StlEncoding encoding = StlEncoding::Binary;
  uint64_t triangle_count = 0;  // binary only: the count in the header
};

// Binary when the size is 84 + 50 × (the count at byte 80), as assimp decides; otherwise
// ASCII if the file starts with "solid" and contains no NUL byte (binary headers often
// start with "solid" too, but binary data is full of zeros); otherwise a binary STL of the
// wrong size. Throws InputError for anything malformed.
StlContents check_stl(std::string_view bytes, const std::string& file);

}  // namespace convray::mesh
