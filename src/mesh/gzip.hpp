#pragma once
// Decompressing `.gz` meshes (the Stanford models ship as .ply.gz). Internal to src/mesh.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace convray::mesh {

// Decompression bombs: the output may be at most kMaxInflationRatio times the compressed
// size (real meshes compress 3-10x), but never less than kMinInflatedLimit so tiny files
// still work, and never more than kMaxInflatedBytes.
inline constexpr uint64_t kMaxInflationRatio = 100;
inline constexpr uint64_t kMinInflatedLimit = uint64_t{1} << 20;   // 1 MiB
inline constexpr uint64_t kMaxInflatedBytes = uint64_t{4} << 30;   // 4 GiB

// The limit those constants give for `compressed_size` bytes of input.
uint64_t inflated_size_limit(uint64_t compressed_size);

// Decompresses gzip data (one member or several back to back; bytes after the last member
// are ignored, as gzip(1) ignores them). Throws InputError named after `file` for corrupt
// or truncated data and for output beyond inflated_size_limit().
// The output goes into one allocation, never grown: of the size the gzip trailer states where
// that size is right (one pass), else of the size a first, counting pass finds; either way a
// bomb is refused before more than the limit is held.
std::vector<char> gunzip(std::string_view compressed, const std::string& file);

}  // namespace convray::mesh
