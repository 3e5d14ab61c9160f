#include "mesh/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace convray::mesh {
namespace {

// Index of the vertex halfway between a and b on the unit sphere, made once per edge.
uint32_t midpoint(uint32_t a, uint32_t b, std::vector<Vec3>& unit, std::map<std::pair<uint32_t, uint32_t>, uint32_t>& cache) {
  auto key = std::minmax(a, b);
  auto [it, inserted] = cache.try_emplace(key, static_cast<uint32_t>(unit.size()));
  if (inserted) unit.push_back(glm::normalize(unit[a] + unit[b]));
  return it->second;
}

TriangleSoup unit_icosahedron() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSoup soup;
  soup.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : soup.vertices) p = glm::normalize(p);
  soup.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return soup;
}

// Index of the triangle whose centroid lies furthest along `direction`.
size_t triangle_towards(const TriangleSoup& soup, const Vec3& direction) {
  size_t best = 0;
  double best_score = -INFINITY;
  for (size_t t = 0; t < soup.size(); ++t) {
    std::array<Vec3, 3> c = soup.corners(t);
    double score = glm::dot(c[0] + c[1] + c[2], direction);
    if (score > best_score) best = t, best_score = score;
  }
  return best;
}

uint32_t add_vertex(TriangleSoup& soup, const Vec3& p) {
  soup.vertices.push_back(p);
  return static_cast<uint32_t>(soup.vertices.size() - 1);
}

// Splits triangle t in three around a point just inside its first edge; the triangle on
// that edge is a needle a thousandth of the others' height.
void add_sliver(TriangleSoup& soup, size_t t, std::vector<Triangle>& out) {
  auto [a, b, c] = soup.triangles[t];
  Vec3 edge_middle = 0.5 * (soup.vertices[a] + soup.vertices[b]);
  uint32_t m = add_vertex(soup, edge_middle + 1e-3 * (soup.vertices[c] - edge_middle));
  out.push_back({a, b, m});
  out.push_back({b, c, m});
  out.push_back({c, a, m});
}

// A triangle standing outwards on the first edge of triangle t.
Triangle make_fin(TriangleSoup& soup, size_t t) {
  auto [a, b, c] = soup.triangles[t];
  Vec3 edge_middle = 0.5 * (soup.vertices[a] + soup.vertices[b]);
  double height = glm::length(soup.vertices[b] - soup.vertices[a]);
  uint32_t apex = add_vertex(soup, edge_middle + height * glm::normalize(edge_middle));
  return {a, b, apex};
}

// Builds a soup whose vertices are welded as they are added: the tiles of repair_soup share
// their borders by position, and each shared position becomes one index.
class WeldingBuilder {
 public:
  uint32_t vertex(const Vec3& p) {
    auto [it, inserted] =
        index_.try_emplace({p.x, p.y, p.z}, static_cast<uint32_t>(soup_.vertices.size()));
    if (inserted) soup_.vertices.push_back(p);
    return it->second;
  }
  TriangleSoup& soup() { return soup_; }

 private:
  TriangleSoup soup_;
  std::map<std::array<double, 3>, uint32_t> index_;
};

// Point `along` (0..1) of the way around the border of the square of half size h centred at
// c, counter-clockwise from its corner (h, -h); `spokes` points per turn, so spokes / 4 per
// side. Each coordinate is computed from the index counted from the side's low end, so two
// tiles compute their shared side's points bit for bit alike.
Vec3 square_point(const Vec3& c, double h, int spoke, int spokes) {
  const int per_side = spokes / 4, side = spoke / per_side, j = spoke % per_side;
  auto at = [h, per_side](int from_low) { return -h + 2.0 * h * from_low / per_side; };
  switch (side) {
    case 0:
      return c + Vec3(h, at(j), 0.0);
    case 1:
      return c + Vec3(at(per_side - j), h, 0.0);
    case 2:
      return c + Vec3(-h, at(per_side - j), 0.0);
    default:
      return c + Vec3(at(j), -h, 0.0);
  }
}

// One tile of repair_soup: rings of quads from the hole's polygon (radius hole_radius; a
// point when it is 0, where the first ring becomes a fan) out to the square border. The
// spoke from hole corner i runs straight to border point i. Appends the triangles ring by
// ring from the inside out, spoke by spoke within a ring: two per quad, one per fan triangle.
void add_tile(WeldingBuilder& builder, const Vec3& centre, double hole_radius, int spokes,
              int rings) {
  auto point = [&](int ring, int spoke) {
    spoke %= spokes;
    double angle = -kPi / 4.0 + 2.0 * kPi * spoke / spokes;
    Vec3 inner = centre + hole_radius * Vec3(std::cos(angle), std::sin(angle), 0.0);
    if (ring == 0) return builder.vertex(inner);
    if (ring == rings) return builder.vertex(square_point(centre, 1.0, spoke, spokes));
    double t = static_cast<double>(ring) / rings;
    return builder.vertex((1.0 - t) * inner + t * square_point(centre, 1.0, spoke, spokes));
  };
  std::vector<Triangle>& out = builder.soup().triangles;
  for (int ring = 0; ring < rings; ++ring) {
    for (int i = 0; i < spokes; ++i) {
      if (ring == 0 && hole_radius == 0.0) {
        out.push_back({point(0, 0), point(1, i), point(1, i + 1)});
        continue;
      }
      // Counter-clockwise from +z: outwards along spoke i, then round to spoke i + 1.
      out.push_back({point(ring, i), point(ring + 1, i), point(ring + 1, i + 1)});
      out.push_back({point(ring, i), point(ring + 1, i + 1), point(ring, i + 1)});
    }
  }
}

// A triangle standing straight up (+z) on the first edge of triangle t, as tall as the edge.
Triangle make_upright_fin(TriangleSoup& soup, size_t t) {
  auto [a, b, c] = soup.triangles[t];
  Vec3 edge_middle = 0.5 * (soup.vertices[a] + soup.vertices[b]);
  double height = glm::length(soup.vertices[b] - soup.vertices[a]);
  return {a, b, add_vertex(soup, edge_middle + Vec3(0.0, 0.0, height))};
}

}  // namespace

TriangleSoup icosphere(const Vec3& center, double radius, int subdivisions) {
  TriangleSoup soup = unit_icosahedron();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> cache;
    std::vector<Triangle> finer;
    finer.reserve(4 * soup.size());
    for (auto [a, b, c] : soup.triangles) {
      uint32_t ab = midpoint(a, b, soup.vertices, cache);
      uint32_t bc = midpoint(b, c, soup.vertices, cache);
      uint32_t ca = midpoint(c, a, soup.vertices, cache);
      finer.insert(finer.end(), {Triangle{a, ab, ca}, Triangle{b, bc, ab}, Triangle{c, ca, bc}, Triangle{ab, bc, ca}});
    }
    soup.triangles = std::move(finer);
  }
  for (Vec3& p : soup.vertices) p = center + radius * p;
  return soup;
}

TriangleSoup torus(double major, double minor, int nu, int nv) {
  TriangleSoup soup;
  auto index = [nu, nv](int i, int j) { return static_cast<uint32_t>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i) {
    double u = 2.0 * kPi * i / nu;
    for (int j = 0; j < nv; ++j) {
      double v = 2.0 * kPi * j / nv;
      double ring = major + minor * std::cos(v);
      soup.vertices.emplace_back(ring * std::cos(u), ring * std::sin(u), minor * std::sin(v));
    }
  }
  // Going round the axis, then round the tube, turns counter-clockwise seen from outside.
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return soup;
}

TriangleSoup sheet_with_hole(double half_size, int cells, double hole_radius) {
  TriangleSoup soup;
  auto index = [cells](int i, int j) { return static_cast<uint32_t>(j * (cells + 1) + i); };
  auto coordinate = [half_size, cells](double i) { return -half_size + 2.0 * half_size * i / cells; };
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) soup.vertices.emplace_back(coordinate(i), coordinate(j), 0.0);
  }
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      double cx = coordinate(i + 0.5), cy = coordinate(j + 0.5);
      if (std::hypot(cx, cy) < hole_radius) continue;
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return soup;
}

TriangleSoup flat_grid(double half_size, int cells) { return sheet_with_hole(half_size, cells, 0.0); }

TriangleSoup defective_soup(const SoupDefects& defects) {
  TriangleSoup soup = icosphere(Vec3(0.0), 1.0, defects.subdivisions);
  // Each defect sits on its own side of the sphere, so their effects simply add up.
  const size_t flipped = triangle_towards(soup, {0, 0, 1});
  const size_t duplicated = triangle_towards(soup, {0, 0, -1});
  const size_t sliver = triangle_towards(soup, {1, 0, 0});
  const size_t fin = triangle_towards(soup, {0, -1, 0});

  std::vector<Triangle> triangles;
  for (size_t t = 0; t < soup.size(); ++t) {
    Triangle tri = soup.triangles[t];
    bool around_vertex_0 = tri[0] == 0 || tri[1] == 0 || tri[2] == 0;
    if (defects.hole && around_vertex_0) continue;
    if (defects.sliver && t == sliver) {
      add_sliver(soup, t, triangles);
      continue;
    }
    if (defects.flipped && t == flipped) std::swap(tri[1], tri[2]);
    triangles.push_back(tri);
  }
  if (defects.duplicated) triangles.push_back(soup.triangles[duplicated]);
  if (defects.fin) triangles.push_back(make_fin(soup, fin));
  if (defects.zero_area) {
    uint32_t first = add_vertex(soup, {-0.25, 0.0, 0.0});
    add_vertex(soup, {0.0, 0.0, 0.0});
    add_vertex(soup, {0.25, 0.0, 0.0});
    triangles.push_back({first, first + 1, first + 2});
  }
  if (defects.repeated_vertex) {
    Triangle near_duplicate = soup.triangles[duplicated];
    triangles.push_back({near_duplicate[0], near_duplicate[0], near_duplicate[1]});
  }
  soup.triangles = std::move(triangles);
  return soup;
}

TriangleSoup repair_soup(const RepairDefects& defects) {
  const int n = defects.spokes, k = defects.rings;
  const int defect_count =
      defects.flipped + defects.duplicated + defects.slivers + (defects.fin ? 1 : 0);
  if (n < 16 || n % 8 != 0 || k < 4 || defect_count > 8) {
    throw std::invalid_argument(
        "repair_soup: spokes must be a multiple of 8 (>= 16), rings >= 4, defects <= 8");
  }
  for (double a : defects.hole_radii) {
    if (!(a > 0.0 && a < 1.0))
      throw std::invalid_argument("repair_soup: hole radii must lie in (0, 1)");
  }
  WeldingBuilder builder;
  add_tile(builder, {-1.0, 1.0, 0.0}, defects.hole_radii[0], n, k);
  add_tile(builder, {1.0, 1.0, 0.0}, defects.hole_radii[1], n, k);
  add_tile(builder, {-1.0, -1.0, 0.0}, defects.hole_radii[2], n, k);
  const size_t solid_first = builder.soup().size();
  add_tile(builder, {1.0, -1.0, 0.0}, 0.0, n, k);
  TriangleSoup soup = std::move(builder.soup());

  // Defect d goes on the first triangle of the quad at spoke d * n / 8 of the solid tile's
  // middle ring: eight spokes apart at the least, no two share a vertex, and none touches
  // the fan or the tile's border.
  const int middle = k / 2;
  auto defect_triangle = [&](int d) {
    return solid_first + static_cast<size_t>(n + 2 * n * (middle - 1) + 2 * (d * n / 8));
  };
  enum class Defect { kNone, kFlipped, kDuplicated, kSliver, kFin };
  std::vector<Defect> defect(soup.size(), Defect::kNone);
  int d = 0;
  for (int i = 0; i < defects.flipped; ++i) defect[defect_triangle(d++)] = Defect::kFlipped;
  for (int i = 0; i < defects.duplicated; ++i) defect[defect_triangle(d++)] = Defect::kDuplicated;
  for (int i = 0; i < defects.slivers; ++i) defect[defect_triangle(d++)] = Defect::kSliver;
  if (defects.fin) defect[defect_triangle(d++)] = Defect::kFin;

  std::vector<Triangle> triangles, appended;  // copies and fins go at the end, as a soup has them
  for (size_t t = 0; t < soup.size(); ++t) {
    Triangle tri = soup.triangles[t];
    switch (defect[t]) {
      case Defect::kFlipped:
        std::swap(tri[1], tri[2]);
        break;
      case Defect::kDuplicated:
        appended.push_back(tri);
        break;
      case Defect::kSliver:
        add_sliver(soup, t, triangles);
        continue;
      case Defect::kFin:
        appended.push_back(make_upright_fin(soup, t));
        break;
      case Defect::kNone:
        break;
    }
    triangles.push_back(tri);
  }
  triangles.insert(triangles.end(), appended.begin(), appended.end());
  soup.triangles = std::move(triangles);
  return soup;
}

}  // namespace convray::mesh
