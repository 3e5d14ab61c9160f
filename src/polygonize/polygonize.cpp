#include "polygonize/polygonize.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "polygonize/block_grid.hpp"
#include "polygonize/edge_root.hpp"
#include "polygonize/tetrahedra.hpp"
#include "util/unit_vector.hpp"

namespace convray::polygonize {

namespace {

constexpr int kPointsPerSide = kBlockCells + 1;

// A lattice edge: the grid point of its low corner (BlockGrid::point_key) in the low 60 bits,
// the direction (high ^ low corner bits, 1..7) above.
using EdgeKey = uint64_t;

// A crossed lattice edge and the field at its ends, as a block saw it.
struct CrossedEdge {
  EdgeKey key = 0;
  double f_low = 0.0, f_high = 0.0;
  bool operator<(const CrossedEdge& o) const { return key < o.key; }
};

// What one block contributes: its crossed edges (unique within the block) and its pieces as
// edge keys, three per triangle and four per quadrilateral.
struct BlockPieces {
  std::vector<CrossedEdge> edges;
  std::vector<EdgeKey> triangles, quads;
};

int local_index(int i, int j, int k) { return i + kPointsPerSide * (j + kPointsPerSide * k); }

// Samples F at the block's lattice points and marches its cells.
BlockPieces march_block(const FieldSource& source, const BlockGrid& grid, const GridIndex& block,
                        std::vector<double>& values) {
  const int64_t i0 = block.i * kBlockCells, j0 = block.j * kBlockCells, k0 = block.k * kBlockCells;
  values.resize(size_t(kPointsPerSide) * kPointsPerSide * kPointsPerSide);
  for (int k = 0; k < kPointsPerSide; ++k) {
    for (int j = 0; j < kPointsPerSide; ++j) {
      for (int i = 0; i < kPointsPerSide; ++i) {
        values[local_index(i, j, k)] = source.value_at(grid.position(i0 + i, j0 + j, k0 + k));
      }
    }
  }
  BlockPieces out;
  const auto& table = cell_pieces();
  const auto corner_value = [&](int i, int j, int k, int c) {
    return values[local_index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
  };
  for (int k = 0; k < kBlockCells; ++k) {
    for (int j = 0; j < kBlockCells; ++j) {
      for (int i = 0; i < kBlockCells; ++i) {
        int inside = 0;
        for (int c = 0; c < 8; ++c)
          inside |= int(corner_value(i, j, k, c) >= source.threshold) << c;
        if (inside == 0 || inside == 255) continue;
        const auto key_of = [&](const CubeEdge& e) {
          const EdgeKey point = grid.point_key(i0 + i + (e.low & 1), j0 + j + ((e.low >> 1) & 1),
                                               k0 + k + ((e.low >> 2) & 1));
          out.edges.push_back({point | (EdgeKey(e.high ^ e.low) << 60),
                               corner_value(i, j, k, e.low), corner_value(i, j, k, e.high)});
          return out.edges.back().key;
        };
        const CellPieces& pieces = table[inside];
        for (const auto& t : pieces.triangles) {
          for (const CubeEdge& e : t) out.triangles.push_back(key_of(e));
        }
        for (const auto& q : pieces.quads) {
          for (const CubeEdge& e : q) out.quads.push_back(key_of(e));
        }
      }
    }
  }
  std::sort(out.edges.begin(), out.edges.end());
  out.edges.erase(std::unique(out.edges.begin(), out.edges.end(),
                              [](const auto& a, const auto& b) { return a.key == b.key; }),
                  out.edges.end());
  return out;
}

// The two ends of a lattice edge.
std::array<Vec3, 2> edge_ends(const BlockGrid& grid, EdgeKey key) {
  const GridIndex p = grid.point_from_key(key & ((EdgeKey(1) << 60) - 1));
  const int d = int(key >> 60);
  return {grid.position(p.i, p.j, p.k),
          grid.position(p.i + (d & 1), p.j + ((d >> 1) & 1), p.k + ((d >> 2) & 1))};
}

uint32_t vertex_of(const std::vector<CrossedEdge>& edges, EdgeKey key) {
  const auto it = std::lower_bound(edges.begin(), edges.end(), CrossedEdge{key});
  return uint32_t(it - edges.begin());
}

// A quadrilateral's two triangles, split along the shorter diagonal: the better-shaped pair.
void split_quad(const std::array<uint32_t, 4>& q, const std::vector<Vec3>& positions,
                std::vector<mesh::Triangle>& out) {
  const double d02 = glm::distance(positions[q[0]], positions[q[2]]);
  const double d13 = glm::distance(positions[q[1]], positions[q[3]]);
  if (d02 <= d13) {
    out.push_back({q[0], q[1], q[2]});
    out.push_back({q[0], q[2], q[3]});
  } else {
    out.push_back({q[1], q[2], q[3]});
    out.push_back({q[1], q[3], q[0]});
  }
}

}  // namespace

SurfaceMesh polygonize(const FieldSource& source, const PolygonizeOptions& options,
                       PolygonizeStats* stats) {
  if (!(source.threshold > 0.0) || !std::isfinite(source.threshold)) {
    throw std::invalid_argument("the threshold must be > 0 (the surface is F = T, outside F < T)");
  }
  Box3 bounds;
  for (const Box3& box : source.supports) {
    if (!box.empty()) bounds.extend(box.lo), bounds.extend(box.hi);
  }
  SurfaceMesh result;
  if (bounds.empty()) return result;
  if (options.before_pass) options.before_pass(options.cell);
  const BlockGrid grid(bounds, options.cell);
  const std::vector<uint64_t> block_keys = grid.touched_blocks(source.supports);
  if (options.on_start) options.on_start(block_keys.size());

  // Sample and march every block, in parallel.
  std::vector<BlockPieces> blocks(block_keys.size());
  tbb::enumerable_thread_specific<std::vector<double>> scratch;
  tbb::parallel_for(size_t(0), block_keys.size(), [&](size_t b) {
    blocks[b] = march_block(source, grid, grid.block_from_key(block_keys[b]), scratch.local());
    if (options.on_blocks_done) options.on_blocks_done(1);
  });

  // One vertex per crossed edge: sorted keys give every edge one index, whatever the order the
  // blocks finished in.
  std::vector<CrossedEdge> edges;
  for (const BlockPieces& b : blocks) edges.insert(edges.end(), b.edges.begin(), b.edges.end());
  tbb::parallel_sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const auto& a, const auto& b) { return a.key == b.key; }),
              edges.end());

  // Each vertex on the exact surface, along its edge.
  result.soup.vertices.resize(edges.size());
  result.normals.resize(edges.size());
  std::atomic<size_t> evaluations{0}, unconverged{0};
  std::vector<double> residuals(edges.size());
  tbb::parallel_for(size_t(0), edges.size(), [&](size_t v) {
    const auto [a, b] = edge_ends(grid, edges[v].key);
    const EdgeRoot root =
        find_edge_root(source, a, edges[v].f_low, b, edges[v].f_high, options.tolerance);
    result.soup.vertices[v] = root.position;
    // Outwards, where the field falls; scaled first for extreme strengths (1e200, 1e-160).
    const Vec3 unit = unit_or_zero(root.sample.gradient);
    result.normals[v] = unit == Vec3(0.0) ? Vec3(0.0) : -unit;
    residuals[v] = std::abs(root.sample.value - source.threshold) / source.threshold;
    evaluations += size_t(root.evaluations);
    if (!root.converged) ++unconverged;
  });

  // The triangles, block by block in key order: the same mesh for any number of threads.
  for (const BlockPieces& b : blocks) {
    for (size_t n = 0; n < b.triangles.size(); n += 3) {
      result.soup.triangles.push_back({vertex_of(edges, b.triangles[n]),
                                       vertex_of(edges, b.triangles[n + 1]),
                                       vertex_of(edges, b.triangles[n + 2])});
    }
    for (size_t n = 0; n < b.quads.size(); n += 4) {
      const std::array<uint32_t, 4> q{
          vertex_of(edges, b.quads[n]), vertex_of(edges, b.quads[n + 1]),
          vertex_of(edges, b.quads[n + 2]), vertex_of(edges, b.quads[n + 3])};
      split_quad(q, result.soup.vertices, result.soup.triangles);
    }
  }
  if (stats) {
    stats->blocks = block_keys.size();
    stats->field_evaluations =
        evaluations + block_keys.size() * size_t(kPointsPerSide * kPointsPerSide * kPointsPerSide);
    stats->max_residual =
        residuals.empty() ? 0.0 : *std::max_element(residuals.begin(), residuals.end());
    stats->unconverged = unconverged;
  }
  return result;
}

}  // namespace convray::polygonize
