#include "polygonize/tetrahedra.hpp"

#include <algorithm>
#include <utility>

#include "util/math.hpp"

namespace convray::polygonize {

namespace {

Vec3 corner_position(int c) { return Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); }

Vec3 midpoint(const CubeEdge& e) {
  return 0.5 * (corner_position(e.low) + corner_position(e.high));
}

CubeEdge edge(int a, int b) {
  // Kuhn tetrahedra are chains 0 ⊂ v1 ⊂ v2 ⊂ 7 of corner bit sets: one end contains the other.
  return (a & b) == a ? CubeEdge{uint8_t(a), uint8_t(b)} : CubeEdge{uint8_t(b), uint8_t(a)};
}

// Whether the polygon through the edge midpoints faces from the inside corners to the outside
// ones. Midpoints stand for the real vertices, which only slide along the same edges and so
// never flip a piece: the test is exact here (small integers and halves).
template <size_t N>
bool faces_outward(const std::array<CubeEdge, N>& polygon, const Vec3& inside_to_outside) {
  const Vec3 p0 = midpoint(polygon[0]);
  const Vec3 normal = glm::cross(midpoint(polygon[1]) - p0, midpoint(polygon[2]) - p0);
  return glm::dot(normal, inside_to_outside) > 0.0;
}

// Appends the piece of one tetrahedron (corners t) for this inside assignment.
void add_tetrahedron_piece(const std::array<int, 4>& t, int inside, CellPieces& out) {
  std::vector<int> in, out_corners;
  for (int c : t) ((inside >> c) & 1 ? in : out_corners).push_back(c);
  if (in.empty() || out_corners.empty()) return;
  Vec3 in_centroid(0.0), out_centroid(0.0);
  for (int c : in) in_centroid += corner_position(c) / double(in.size());
  for (int c : out_corners) out_centroid += corner_position(c) / double(out_corners.size());
  const Vec3 outward = out_centroid - in_centroid;
  if (in.size() == 2) {
    // Corners a, b inside and c, d outside: the crossed edges ac, ad, bd, bc run around a
    // quadrilateral.
    std::array<CubeEdge, 4> quad{edge(in[0], out_corners[0]), edge(in[0], out_corners[1]),
                                 edge(in[1], out_corners[1]), edge(in[1], out_corners[0])};
    if (!faces_outward(quad, outward)) std::reverse(quad.begin(), quad.end());
    out.quads.push_back(quad);
    return;
  }
  // One corner alone on its side: the triangle across its three edges.
  const std::vector<int>& lone = in.size() == 1 ? in : out_corners;
  const std::vector<int>& others = in.size() == 1 ? out_corners : in;
  std::array<CubeEdge, 3> triangle{edge(lone[0], others[0]), edge(lone[0], others[1]),
                                   edge(lone[0], others[2])};
  if (!faces_outward(triangle, outward)) std::swap(triangle[1], triangle[2]);
  out.triangles.push_back(triangle);
}

std::array<CellPieces, 256> make_cell_pieces() {
  // The six tetrahedra 0 -> e_a -> e_a + e_b -> 7, one per order (a, b, c) of the axes.
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::array<CellPieces, 256> table;
  for (int inside = 0; inside < 256; ++inside) {
    for (const auto& order : axes) {
      const int v1 = 1 << order[0];
      const int v2 = v1 | (1 << order[1]);
      add_tetrahedron_piece({0, v1, v2, 7}, inside, table[inside]);
    }
  }
  return table;
}

}  // namespace

const std::array<CellPieces, 256>& cell_pieces() {
  static const std::array<CellPieces, 256> table = make_cell_pieces();
  return table;
}

}  // namespace convray::polygonize
