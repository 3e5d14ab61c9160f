// A compact dual contouring (Ju et al. 2002) of F = T, the hand-written candidate of the
// evaluation: a sparse grid of 8^3-node blocks covering the triangles' supports, one vertex
// per crossed cell placed by the QEF of the edge crossings' tangent planes (exact gradient as
// normals), one quad per crossed edge split into two triangles. A prototype: no octree, no
// manifold fix-up, so what it produces is what plain DC produces.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "polygonizer_eval.hpp"

namespace convray::bench {

namespace {

constexpr int kBlock = 8;           // nodes per block side
constexpr int64_t kBias = 1 << 20;  // node indices are packed as 21-bit unsigned fields

uint64_t pack(const glm::i64vec3& n) {
  return (static_cast<uint64_t>(n.x + kBias) << 42) | (static_cast<uint64_t>(n.y + kBias) << 21) |
         static_cast<uint64_t>(n.z + kBias);
}

glm::i64vec3 floor_div(const glm::i64vec3& n, int64_t d) {
  auto f = [d](int64_t v) { return v >= 0 ? v / d : -((-v + d - 1) / d); };
  return {f(n.x), f(n.y), f(n.z)};
}

// Node values F - T (positive inside) on the blocks that the supports touch; any other node
// is outside every support, so F = 0 there and its value is -T.
class SparseGrid {
 public:
  explicit SparseGrid(const Problem& problem) : h_(problem.cell), outside_(-problem.threshold) {
    const double reach = problem.field->radius() + h_;  // a cell's margin: see DC's edge loop
    const auto& soup = *problem.soup;
    for (size_t t = 0; t < soup.triangles.size(); ++t) {
      Box3 box;
      for (const Vec3& p : soup.corners(t)) box.extend(p);
      const glm::i64vec3 lo = floor_div(node_floor(box.lo - reach), kBlock);
      const glm::i64vec3 hi = floor_div(node_floor(box.hi + reach) + int64_t{1}, kBlock);
      for (int64_t x = lo.x; x <= hi.x; ++x) {
        for (int64_t y = lo.y; y <= hi.y; ++y) {
          for (int64_t z = lo.z; z <= hi.z; ++z) {
            const glm::i64vec3 b(x, y, z);
            if (index_.emplace(pack(b), origins_.size()).second)
              origins_.push_back(b * int64_t{kBlock});
          }
        }
      }
    }
    values_.resize(origins_.size() * kBlock * kBlock * kBlock);
    tbb::parallel_for(size_t{0}, origins_.size(), [&](size_t b) {
      for (int i = 0; i < kBlock * kBlock * kBlock; ++i) {
        const glm::i64vec3 n = origins_[b] + glm::i64vec3(i / 64, (i / 8) % 8, i % 8);
        values_[b * 512 + i] =
            static_cast<float>(problem.field->value(position(n)) - problem.threshold);
      }
    });
  }

  Vec3 position(const glm::i64vec3& n) const { return Vec3(n) * h_; }
  glm::i64vec3 node_floor(const Vec3& p) const { return glm::i64vec3(glm::floor(p / h_)); }

  double value(const glm::i64vec3& n) const {
    const glm::i64vec3 b = floor_div(n, kBlock);
    const auto it = index_.find(pack(b));
    if (it == index_.end()) return outside_;
    const glm::i64vec3 l = n - b * int64_t{kBlock};
    return values_[it->second * 512 + l.x * 64 + l.y * 8 + l.z];
  }

  const std::vector<glm::i64vec3>& block_origins() const { return origins_; }

 private:
  double h_, outside_;
  std::unordered_map<uint64_t, size_t> index_;
  std::vector<glm::i64vec3> origins_;
  std::vector<float> values_;
};

struct Crossing {
  glm::i64vec3 node;  // the edge runs from node to node + e_axis
  int axis = 0;
  bool starts_inside = false;
  Vec3 point{0.0}, normal{0.0};  // on the surface; unit, outward (-grad F)
};

// The zero of F - T on the segment p0 p1 by the Illinois variant of regula falsi on the
// exact field, then its outward unit normal.
void locate_crossing(const Problem& problem, const Vec3& p0, const Vec3& p1, Crossing& c) {
  const double t = problem.threshold;
  double s0 = 0.0, s1 = 1.0;
  double g0 = problem.field->value(p0) - t, g1 = problem.field->value(p1) - t;
  double s = 0.5;
  if ((g0 > 0) != (g1 > 0)) {
    int side = 0;
    for (int it = 0; it < 60; ++it) {
      s = (s0 * g1 - s1 * g0) / (g1 - g0);
      const double g = problem.field->value(p0 + s * (p1 - p0)) - t;
      if (std::abs(g) <= 1e-9 * t) break;
      if ((g > 0) == (g0 > 0)) {
        s0 = s, g0 = g;
        if (side == -1) g1 *= 0.5;
        side = -1;
      } else {
        s1 = s, g1 = g;
        if (side == 1) g0 *= 0.5;
        side = 1;
      }
    }
  } else {
    s = std::abs(g0) < std::abs(g1) ? 0.0 : 1.0;  // float node values disagreed: rare
  }
  c.point = p0 + s * (p1 - p0);
  const Vec3 g = problem.field->field(c.point).gradient;
  const double l = glm::length(g);
  c.normal = l > 0 ? -g / l : Vec3(0.0);
}

const glm::i64vec3 kAxis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// The vertex of a cell: the minimiser of sum (n_i . (x - p_i))^2 + lambda |x - c|^2 with c
// the crossings' mass point. The small lambda fixes the directions the planes leave free
// (flat regions) without pulling a sharp corner away; the result is clamped into the cell.
Vec3 cell_vertex(const std::vector<const Crossing*>& crossings, const Vec3& lo, double h) {
  Vec3 mass(0.0);
  for (const Crossing* c : crossings) mass += c->point;
  mass /= static_cast<double>(crossings.size());
  constexpr double kLambda = 0.05;
  glm::dmat3 ata(kLambda);
  Vec3 atb(0.0);
  for (const Crossing* c : crossings) {
    ata += glm::outerProduct(c->normal, c->normal);
    atb += c->normal * glm::dot(c->normal, c->point - mass);
  }
  const Vec3 x = mass + glm::inverse(ata) * atb;
  return glm::clamp(x, lo, lo + Vec3(h));
}

}  // namespace

PolygonizerOutput polygonize_dual_contouring(const Problem& problem) {
  const auto start = std::chrono::steady_clock::now();
  const SparseGrid grid(problem);
  const double h = problem.cell;

  // Crossed edges, gathered per block (in parallel), then located on the exact field.
  const auto& origins = grid.block_origins();
  std::vector<std::vector<Crossing>> per_block(origins.size());
  tbb::parallel_for(size_t{0}, origins.size(), [&](size_t b) {
    for (int i = 0; i < 512; ++i) {
      const glm::i64vec3 n = origins[b] + glm::i64vec3(i / 64, (i / 8) % 8, i % 8);
      const bool inside = grid.value(n) > 0;
      for (int a = 0; a < 3; ++a) {
        if ((grid.value(n + kAxis[a]) > 0) == inside) continue;
        Crossing c;
        c.node = n, c.axis = a, c.starts_inside = inside;
        locate_crossing(problem, grid.position(n), grid.position(n + kAxis[a]), c);
        per_block[b].push_back(c);
      }
    }
  });
  std::vector<Crossing> crossings;
  for (auto& list : per_block) crossings.insert(crossings.end(), list.begin(), list.end());
  per_block.clear();

  // Cells around each crossed edge get a vertex; each collects the crossings of its edges.
  std::unordered_map<uint64_t, uint32_t> cell_index;
  std::vector<glm::i64vec3> cells;
  std::vector<std::vector<const Crossing*>> cell_crossings;
  auto around = [](const Crossing& c, int k) {  // the 4 cells, counter-clockwise about +axis
    const int b = (c.axis + 1) % 3, d = (c.axis + 2) % 3;
    static const int kOffset[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
    return c.node + kAxis[b] * int64_t{kOffset[k][0]} + kAxis[d] * int64_t{kOffset[k][1]};
  };
  for (const Crossing& c : crossings) {
    for (int k = 0; k < 4; ++k) {
      const glm::i64vec3 cell = around(c, k);
      const auto [it, added] = cell_index.emplace(pack(cell), cells.size());
      if (added) cells.push_back(cell), cell_crossings.emplace_back();
      cell_crossings[it->second].push_back(&c);
    }
  }
  mesh::TriangleSoup out;
  out.vertices.resize(cells.size());
  tbb::parallel_for(size_t{0}, cells.size(), [&](size_t i) {
    out.vertices[i] = cell_vertex(cell_crossings[i], grid.position(cells[i]), h);
  });

  // One quad per crossed edge, facing the way the edge leaves the inside; split along the
  // shorter diagonal.
  for (const Crossing& c : crossings) {
    std::array<uint32_t, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = cell_index.at(pack(around(c, k)));
    if (!c.starts_inside) std::swap(q[1], q[3]);
    const auto& v = out.vertices;
    if (glm::length(v[q[0]] - v[q[2]]) <= glm::length(v[q[1]] - v[q[3]])) {
      out.triangles.push_back({q[0], q[1], q[2]});
      out.triangles.push_back({q[0], q[2], q[3]});
    } else {
      out.triangles.push_back({q[0], q[1], q[3]});
      out.triangles.push_back({q[1], q[2], q[3]});
    }
  }
  PolygonizerOutput result;
  result.mesh = std::move(out);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.note = "sampling, edge location and vertex placement on TBB threads; quads serial";
  return result;
}

}  // namespace convray::bench
