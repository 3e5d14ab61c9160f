#include "mesh/stats.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <vector>

namespace convray::mesh {
namespace {

constexpr uint32_t kUnused = UINT32_MAX;

// Welding: every vertex index used by a triangle gets the id of its position.
struct Welded {
  std::vector<uint32_t> id_of_vertex;  // kUnused for vertices no triangle uses
  std::vector<Vec3> positions;         // one per id
};

// Equal doubles have equal bits, except -0 and +0 (made equal here) and NaNs (which are
// only ever equal to themselves bit for bit, which is good enough for grouping).
std::array<uint64_t, 3> position_key(const Vec3& p) {
  return {std::bit_cast<uint64_t>(p.x + 0.0), std::bit_cast<uint64_t>(p.y + 0.0), std::bit_cast<uint64_t>(p.z + 0.0)};
}

Welded weld(const TriangleSoup& soup) {
  std::vector<uint32_t> used;
  std::vector<bool> seen(soup.vertices.size(), false);
  for (const Triangle& t : soup.triangles) {
    for (uint32_t v : t) {
      if (!seen[v]) used.push_back(v);
      seen[v] = true;
    }
  }
  std::vector<std::array<uint64_t, 3>> keys(soup.vertices.size());
  for (uint32_t v : used) keys[v] = position_key(soup.vertices[v]);
  std::sort(used.begin(), used.end(), [&keys](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });

  Welded welded;
  welded.id_of_vertex.assign(soup.vertices.size(), kUnused);
  for (size_t i = 0; i < used.size(); ++i) {
    if (i == 0 || keys[used[i]] != keys[used[i - 1]]) welded.positions.push_back(soup.vertices[used[i]]);
    welded.id_of_vertex[used[i]] = static_cast<uint32_t>(welded.positions.size() - 1);
  }
  return welded;
}

// One triangle side, from `from` to `to`, filed under the unordered pair.
struct HalfEdge {
  uint64_t pair;  // (smaller id << 32) | larger id
  bool forward;   // from < to

  bool operator<(const HalfEdge& other) const { return pair < other.pair; }
};

void count_edges(const std::vector<HalfEdge>& half_edges, const Welded& welded, MeshStats& stats) {
  double total_length = 0.0;
  for (size_t begin = 0; begin < half_edges.size();) {
    size_t end = begin;
    size_t forward = 0;
    while (end < half_edges.size() && half_edges[end].pair == half_edges[begin].pair) forward += half_edges[end++].forward;
    size_t uses = end - begin;
    ++stats.edges;
    if (uses == 1) ++stats.boundary_edges;
    if (uses >= 3) ++stats.non_manifold_edges;
    if (uses == 2 && forward != 1) ++stats.inconsistent_edges;
    uint64_t pair = half_edges[begin].pair;
    total_length += glm::length(welded.positions[pair >> 32] - welded.positions[pair & 0xffffffffu]);
    begin = end;
  }
  stats.mean_edge_length = stats.edges ? total_length / static_cast<double>(stats.edges) : 0.0;
}

// Union-find with path halving and union by size.
class Components {
 public:
  explicit Components(size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), uint32_t{0}); }

  uint32_t find(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void join(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }
  size_t count() {
    size_t roots = 0;
    for (uint32_t x = 0; x < parent_.size(); ++x) roots += find(x) == x;
    return roots;
  }

 private:
  std::vector<uint32_t> parent_;
  std::vector<uint32_t> size_;
};

}  // namespace

MeshStats compute_stats(const TriangleSoup& soup) {
  MeshStats stats;
  stats.triangles = soup.size();
  Welded welded = weld(soup);
  stats.vertices = welded.positions.size();
  for (const Vec3& p : welded.positions) stats.bounds.extend(p);

  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * soup.size());
  Components components(welded.positions.size());
  for (const Triangle& t : soup.triangles) {
    std::array<uint32_t, 3> ids = {welded.id_of_vertex[t[0]], welded.id_of_vertex[t[1]], welded.id_of_vertex[t[2]]};
    components.join(ids[0], ids[1]);
    components.join(ids[1], ids[2]);
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0]) {
      ++stats.degenerate_triangles;  // no proper edges to speak of
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      uint32_t from = ids[k], to = ids[(k + 1) % 3];
      uint64_t pair = uint64_t{std::min(from, to)} << 32 | std::max(from, to);
      half_edges.push_back({pair, from < to});
    }
  }
  std::sort(half_edges.begin(), half_edges.end());
  count_edges(half_edges, welded, stats);
  stats.connected_components = components.count();
  return stats;
}

double advised_radius(const MeshStats& stats) {
  const Vec3 size = stats.bounds.extent();
  return std::min(stats.mean_edge_length, std::max({size.x, size.y, size.z}) / 10.0);
}

}  // namespace convray::mesh
