#pragma once
// Builders for the InputErrors of the convention in src/mesh/load.hpp:
//     FILE[:LINE]: WHAT IS WRONG[ (ELEMENT N)]
// Internal to src/mesh.
#include <cstddef>
#include <string>

#include "util/error.hpp"

namespace convray::mesh {

// " (face 12)", " (vertex 3)", " (line 0)": the element a problem is in, counted from 0 in file order.
inline std::string in_face(size_t index) { return " (face " + std::to_string(index) + ")"; }
inline std::string in_vertex(size_t index) { return " (vertex " + std::to_string(index) + ")"; }
inline std::string in_line(size_t index) { return " (line " + std::to_string(index) + ")"; }  // a polyline

// Throws `file[:line]: what`. `line` is 1-based; 0 leaves it out.
[[noreturn]] inline void fail(const std::string& file, const std::string& what, int line = 0) {
  throw InputError(SourceLoc{file, line, 0}, what);
}

}  // namespace convray::mesh
