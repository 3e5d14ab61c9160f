#include "mesh/self_intersections.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>

#include "mesh/triangle_contact.hpp"

namespace convray::mesh {
namespace {

Corners corners_of(const TriangleSoup& soup, size_t face) {
  const auto c = soup.corners(face);
  return {c[0], c[1], c[2]};
}

bool boxes_overlap(const Box3& a, const Box3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    if (a.hi[axis] < b.lo[axis] || b.hi[axis] < a.lo[axis]) return false;
  }
  return true;
}

// Found pairs, keeping only the first `limit` examples in (lower, higher) order.
struct Findings {
  size_t pairs = 0;
  std::vector<std::array<uint32_t, 2>> examples;

  void add(uint32_t a, uint32_t b, size_t limit) {
    ++pairs;
    if (limit == 0) return;
    examples.push_back({std::min(a, b), std::max(a, b)});
    if (examples.size() >= 2 * limit) trim(limit);
  }
  void trim(size_t limit) {
    std::sort(examples.begin(), examples.end());
    if (examples.size() > limit) examples.resize(limit);
  }
};

// A uniform grid of cubic cells over the faces' boxes, each cell index kept within 21 bits per
// axis so that a cell packs into one 64-bit key.
class CellGrid {
 public:
  CellGrid(const Box3& bounds, double cell) : origin_(bounds.lo), cell_(cell) {}

  glm::i64vec3 index(const Vec3& p) const {
    const glm::dvec3 i = glm::floor((p - origin_) / cell_);
    return glm::clamp(glm::i64vec3(i), glm::i64vec3(0), glm::i64vec3(kMaxIndex));
  }
  static uint64_t key(const glm::i64vec3& i) {
    return (uint64_t(i.x) << 42) | (uint64_t(i.y) << 21) | uint64_t(i.z);
  }
  static size_t cells_between(const glm::i64vec3& lo, const glm::i64vec3& hi) {
    return size_t(hi.x - lo.x + 1) * size_t(hi.y - lo.y + 1) * size_t(hi.z - lo.z + 1);
  }
  static constexpr int64_t kMaxIndex = (int64_t(1) << 21) - 1;

 private:
  Vec3 origin_;
  double cell_;
};

// A cell about twice the mean size of a face's box puts a face in a few cells and a few faces
// in each; a few very large faces could still cover millions of cells, so the cell grows until
// the registrations stay within a small multiple of the face count.
double choose_cell(const std::vector<Box3>& boxes, const std::vector<uint32_t>& faces,
                   const Box3& bounds) {
  double mean = 0.0;
  for (uint32_t f : faces) {
    const Vec3 e = boxes[f].extent();
    mean += std::max({e.x, e.y, e.z});
  }
  mean /= double(faces.size());
  const Vec3 size = bounds.extent();
  const double largest = std::max({size.x, size.y, size.z});
  double cell = std::max({2.0 * mean, largest / double(CellGrid::kMaxIndex), 1e-300});
  for (;;) {
    const CellGrid grid(bounds, cell);
    size_t registrations = 0;
    for (uint32_t f : faces) {
      registrations += CellGrid::cells_between(grid.index(boxes[f].lo), grid.index(boxes[f].hi));
    }
    if (registrations <= 16 * faces.size() + 1024) return cell;
    cell *= 2.0;
  }
}

}  // namespace

SelfIntersections find_self_intersections(const TriangleSoup& soup, size_t max_examples) {
  SelfIntersections result;
  const size_t n = soup.size();
  std::vector<Box3> boxes(n);
  std::vector<uint32_t> faces;  // those with a plane
  Box3 bounds;
  for (size_t f = 0; f < n; ++f) {
    const Corners c = corners_of(soup, f);
    if (is_flat(c)) {
      ++result.flat_faces;
      continue;
    }
    for (const Vec3& p : c) boxes[f].extend(p);
    bounds.extend(boxes[f].lo);
    bounds.extend(boxes[f].hi);
    faces.push_back(uint32_t(f));
  }
  if (faces.size() < 2) return result;

  const CellGrid grid(bounds, choose_cell(boxes, faces, bounds));
  std::vector<std::pair<uint64_t, uint32_t>> entries;  // (cell key, face), sorted by cell
  for (uint32_t f : faces) {
    const glm::i64vec3 lo = grid.index(boxes[f].lo), hi = grid.index(boxes[f].hi);
    for (int64_t x = lo.x; x <= hi.x; ++x) {
      for (int64_t y = lo.y; y <= hi.y; ++y) {
        for (int64_t z = lo.z; z <= hi.z; ++z) entries.push_back({CellGrid::key({x, y, z}), f});
      }
    }
  }
  tbb::parallel_sort(entries.begin(), entries.end());
  std::vector<size_t> starts;  // where each cell's run begins
  for (size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].first != entries[i - 1].first) starts.push_back(i);
  }
  starts.push_back(entries.size());

  tbb::enumerable_thread_specific<Findings> found;
  tbb::parallel_for(size_t(0), starts.size() - 1, [&](size_t run) {
    Findings& mine = found.local();
    const uint64_t cell = entries[starts[run]].first;
    for (size_t i = starts[run]; i < starts[run + 1]; ++i) {
      const uint32_t s = entries[i].second;
      for (size_t j = i + 1; j < starts[run + 1]; ++j) {
        const uint32_t t = entries[j].second;
        if (!boxes_overlap(boxes[s], boxes[t])) continue;
        // Both boxes cover the low corner of their overlap; only that corner's cell tests the
        // pair, so that a pair sharing several cells is counted once.
        if (CellGrid::key(grid.index(glm::max(boxes[s].lo, boxes[t].lo))) != cell) continue;
        if (faces_intersect(corners_of(soup, s), corners_of(soup, t))) mine.add(s, t, max_examples);
      }
    }
  });
  Findings all;
  for (Findings& part : found) {
    all.pairs += part.pairs;
    all.examples.insert(all.examples.end(), part.examples.begin(), part.examples.end());
  }
  all.trim(max_examples);
  result.pairs = all.pairs;
  result.examples = std::move(all.examples);
  return result;
}

SelfIntersections find_self_intersections_brute_force(const TriangleSoup& soup,
                                                      size_t max_examples) {
  SelfIntersections result;
  Findings all;
  for (size_t s = 0; s < soup.size(); ++s) {
    const Corners p = corners_of(soup, s);
    if (is_flat(p)) {
      ++result.flat_faces;
      continue;
    }
    for (size_t t = s + 1; t < soup.size(); ++t) {
      const Corners q = corners_of(soup, t);
      if (!is_flat(q) && faces_intersect(p, q)) all.add(uint32_t(s), uint32_t(t), max_examples);
    }
  }
  all.trim(max_examples);
  result.pairs = all.pairs;
  result.examples = std::move(all.examples);
  return result;
}

}  // namespace convray::mesh
