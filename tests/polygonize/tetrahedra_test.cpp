// The marching-tetrahedra table (tetrahedra.hpp), by exhaustive enumeration of the 256 corner
// assignments of a cell and on random lattices: each piece sits on crossed Kuhn edges, the
// pieces of all cells join into a closed, consistently oriented surface (every edge in exactly
// two triangles, once each way, whichever diagonal splits the quadrilaterals), and the volume
// it encloses (divergence theorem, vertices at the edge midpoints) is the one counted
// tetrahedron by tetrahedron: a tetrahedron cut at its edge midpoints keeps 0, 1/8, 1/2, 7/8
// or all of its volume inside for 0 to 4 inside corners.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <utility>

#include "polygonize/tetrahedra.hpp"
#include "util/math.hpp"

namespace convray::polygonize {
namespace {

// The six Kuhn tetrahedra of the unit cell: the chains 0 -> e_a -> e_a + e_b -> 7, one per
// order (a, b, c) of the axes (corner bit 0: +x, bit 1: +y, bit 2: +z).
std::vector<std::array<int, 4>> kuhn_tetrahedra() {
  std::vector<std::array<int, 4>> out;
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& o : orders) out.push_back({0, 1 << o[0], (1 << o[0]) | (1 << o[1]), 7});
  return out;
}

int inside_count(const std::array<int, 4>& tet, int mask) {
  int n = 0;
  for (int c : tet) n += (mask >> c) & 1;
  return n;
}

TEST(Tetrahedra, EveryPieceLiesOnCrossedKuhnEdgesOfItsCell) {
  const auto& table = cell_pieces();
  for (int mask = 0; mask < 256; ++mask) {
    const CellPieces& pieces = table[mask];
    auto check = [&](const CubeEdge& e) {
      EXPECT_NE(e.low, e.high) << mask;
      EXPECT_EQ(e.low & e.high, e.low) << mask << ": low must be a subset of high";
      EXPECT_LT(e.high, 8) << mask;
      EXPECT_NE((mask >> e.low) & 1, (mask >> e.high) & 1) << mask << ": the edge is not crossed";
    };
    for (const auto& t : pieces.triangles) {
      for (const CubeEdge& e : t) check(e);
    }
    for (const auto& q : pieces.quads) {
      for (const CubeEdge& e : q) check(e);
    }
    // One triangle per tetrahedron with one corner alone on its side, one quadrilateral per
    // tetrahedron split two and two.
    size_t triangles = 0, quads = 0;
    for (const auto& tet : kuhn_tetrahedra()) {
      const int n = inside_count(tet, mask);
      triangles += n == 1 || n == 3;
      quads += n == 2;
    }
    EXPECT_EQ(pieces.triangles.size(), triangles) << mask;
    EXPECT_EQ(pieces.quads.size(), quads) << mask;
  }
  EXPECT_TRUE(table[0].triangles.empty() && table[0].quads.empty());
  EXPECT_TRUE(table[255].triangles.empty() && table[255].quads.empty());
}

// A lattice of n^3 points with an inside flag each; the surface of all its cells.
struct Lattice {
  int n;
  std::vector<uint8_t> inside;  // point (i, j, k) at (k n + j) n + i
  bool at(int i, int j, int k) const { return inside[(size_t(k) * n + j) * n + i]; }
};

struct Surface {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Vertices at the midpoints of the crossed lattice edges, one per edge whichever cell sees it.
Surface extract(const Lattice& lattice, int diagonal) {
  Surface s;
  std::map<std::pair<std::array<int, 3>, std::array<int, 3>>, int> vertex_of;
  const auto& table = cell_pieces();
  for (int k = 0; k + 1 < lattice.n; ++k) {
    for (int j = 0; j + 1 < lattice.n; ++j) {
      for (int i = 0; i + 1 < lattice.n; ++i) {
        int mask = 0;
        for (int c = 0; c < 8; ++c) {
          mask |= int(lattice.at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))) << c;
        }
        const auto vertex = [&](const CubeEdge& e) {
          const std::array<int, 3> a{i + (e.low & 1), j + ((e.low >> 1) & 1),
                                     k + ((e.low >> 2) & 1)};
          const std::array<int, 3> b{i + (e.high & 1), j + ((e.high >> 1) & 1),
                                     k + ((e.high >> 2) & 1)};
          EXPECT_NE(lattice.at(a[0], a[1], a[2]), lattice.at(b[0], b[1], b[2]));
          const auto [it, added] = vertex_of.try_emplace({a, b}, int(s.vertices.size()));
          if (added) {
            s.vertices.push_back(0.5 * (Vec3(a[0], a[1], a[2]) + Vec3(b[0], b[1], b[2])));
          }
          return it->second;
        };
        for (const auto& t : table[mask].triangles) {
          s.triangles.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
        }
        for (const auto& q : table[mask].quads) {
          const int v[4] = {vertex(q[0]), vertex(q[1]), vertex(q[2]), vertex(q[3])};
          if (diagonal == 0) {
            s.triangles.push_back({v[0], v[1], v[2]});
            s.triangles.push_back({v[0], v[2], v[3]});
          } else {
            s.triangles.push_back({v[1], v[2], v[3]});
            s.triangles.push_back({v[1], v[3], v[0]});
          }
        }
      }
    }
  }
  return s;
}

// Closed and consistently oriented: every directed edge once, and its reverse once.
void expect_closed_and_oriented(const Surface& s, const std::string& what) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : s.triangles) {
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) << what;
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << what << ": edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u)
        << what << ": edge " << edge.first << "-" << edge.second << " has no twin";
  }
}

double enclosed_volume(const Surface& s) {
  double v = 0.0;
  for (const auto& t : s.triangles) {
    v += glm::dot(s.vertices[t[0]], glm::cross(s.vertices[t[1]], s.vertices[t[2]])) / 6.0;
  }
  return v;
}

// The inside volume of the piecewise-linear interpolant's zero set, cut at edge midpoints,
// counted per tetrahedron.
double counted_volume(const Lattice& lattice) {
  const double kept[5] = {0.0, 1.0 / 8.0, 0.5, 7.0 / 8.0, 1.0};
  double v = 0.0;
  for (int k = 0; k + 1 < lattice.n; ++k) {
    for (int j = 0; j + 1 < lattice.n; ++j) {
      for (int i = 0; i + 1 < lattice.n; ++i) {
        for (const auto& tet : kuhn_tetrahedra()) {
          int n = 0;
          for (int c : tet) n += lattice.at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          v += kept[n] / 6.0;
        }
      }
    }
  }
  return v;
}

void check_lattice(const Lattice& lattice, const std::string& what) {
  const double expected = counted_volume(lattice);
  for (int diagonal : {0, 1}) {
    const Surface s = extract(lattice, diagonal);
    expect_closed_and_oriented(s, what);
    EXPECT_NEAR(enclosed_volume(s), expected, 1e-12 * (1.0 + expected)) << what;
    EXPECT_EQ(s.triangles.empty(), expected == 0.0) << what;
  }
}

// Each of the 256 assignments in the middle cell of a 3 x 3 x 3 block of cells whose other
// lattice points are all outside: the pieces of the middle cell and of its neighbours close up.
TEST(Tetrahedra, EveryAssignmentOfOneCellGivesAClosedOrientedSurface) {
  for (int mask = 0; mask < 256; ++mask) {
    Lattice lattice{4, std::vector<uint8_t>(64, 0)};
    for (int c = 0; c < 8; ++c) {
      lattice.inside[(size_t(1 + ((c >> 2) & 1)) * 4 + 1 + ((c >> 1) & 1)) * 4 + 1 + (c & 1)] =
          (mask >> c) & 1;
    }
    check_lattice(lattice, "mask " + std::to_string(mask));
  }
}

// Random inside flags on 8 x 8 x 8 lattices whose boundary points are outside, dense and sparse.
TEST(Tetrahedra, RandomLatticesGiveClosedOrientedSurfaces) {
  std::mt19937_64 rng(1461);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 8;
    const double density = 0.1 + 0.8 * unit(rng);
    Lattice lattice{n, std::vector<uint8_t>(size_t(n) * n * n, 0)};
    for (int k = 1; k + 1 < n; ++k) {
      for (int j = 1; j + 1 < n; ++j) {
        for (int i = 1; i + 1 < n; ++i) {
          lattice.inside[(size_t(k) * n + j) * n + i] = unit(rng) < density;
        }
      }
    }
    check_lattice(lattice, "trial " + std::to_string(trial));
  }
}

}  // namespace
}  // namespace convray::polygonize
