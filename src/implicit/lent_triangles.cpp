#include "implicit/lent_triangles.hpp"

#include <algorithm>

namespace convray::implicit {
namespace {

thread_local std::vector<std::vector<field::Triangle>*> lent;

}  // namespace

LentTriangles::LentTriangles(std::vector<std::vector<field::Triangle>*> meshes)
    : meshes_(std::move(meshes)) {
  lent.insert(lent.end(), meshes_.begin(), meshes_.end());
}

LentTriangles::~LentTriangles() {
  for (std::vector<field::Triangle>* mesh : meshes_) {
    const auto at = std::find(lent.begin(), lent.end(), mesh);
    if (at != lent.end()) lent.erase(at);
  }
}

std::vector<field::Triangle>* LentTriangles::take(const std::vector<field::Triangle>& mesh) {
  const auto at = std::find(lent.begin(), lent.end(), &mesh);
  if (at == lent.end()) return nullptr;
  std::vector<field::Triangle>* found = *at;
  lent.erase(at);  // once: a second surface of the same mesh copies (nothing is left)
  return found;
}

}  // namespace convray::implicit
