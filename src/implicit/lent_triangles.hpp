#pragma once
// Triangles lent to the convolution surfaces built while a LentTriangles lives on this thread:
// the owner of a convolution object's mesh (a std::vector it may change, such as `quick`'s
// own object) lends it, and a surface made from that mesh takes the triangles instead of
// copying them (or frees them once it has its own arrangement of merged repeats), before the
// rest of the surface is made. A big mesh is then not held twice at the surface's peak: on
// the dragon at R = 1 (14.6 MB of triangles) a twentieth of the whole process, where memory
// touched for the first time costs about 2.5 ms a MB (docs/benchmarks.md). The owner must
// not need the triangles afterwards: the vector is left empty.
#include <vector>

#include "field/triangle.hpp"

namespace convray::implicit {

class LentTriangles {
 public:
  // Lends every vector of `meshes` until this is destroyed (nested lends add up).
  explicit LentTriangles(std::vector<std::vector<field::Triangle>*> meshes);
  ~LentTriangles();
  LentTriangles(const LentTriangles&) = delete;
  LentTriangles& operator=(const LentTriangles&) = delete;

  // The lent vector at this address on this thread, or null (not lent, or already taken).
  static std::vector<field::Triangle>* take(const std::vector<field::Triangle>& mesh);

 private:
  std::vector<std::vector<field::Triangle>*> meshes_;
};

}  // namespace convray::implicit
