// bicubic_patch { [type 0 | 1] [flatness F] [u_steps N] [v_steps M] [uv_vectors ...]
//                 P00 P01 P02 P03 P10 ... P33 [modifiers] }
//
// The settings' numbers end at a '<': `v_steps 5 <0, 0, 1> ...` is a number and a point.
//
// POV-Ray draws a Bezier patch as the triangles of its 2^u_steps x 2^v_steps grid of points
// on the surface, shaded with the surface's normals at the grid points (smooth triangles).
// Here the patch becomes that mesh (scene::TriangleMesh), always at the full grid: POV-Ray
// stops subdividing where a piece is flat within `flatness`, which changes its silhouette by
// less than that tolerance. Checked against the povray binary's pictures
// (tests/app/povray_bicubic_patch_test.cpp). `uv_vectors` only matter to uv_mapping, which
// convray refuses; they are read and not kept.
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <string>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

using ControlPoints = std::array<Vec3, 16>;  // row by row

// The cubic Bernstein polynomials at t and their derivatives.
std::array<double, 4> bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

std::array<double, 4> bernstein_slope(double t) {
  const double s = 1.0 - t;
  return {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
}

// The surface point at (u, v), u along a row, v across the rows; `du`, `dv` its tangents.
Vec3 surface(const ControlPoints& p, double u, double v, Vec3* du = nullptr,
             Vec3* dv = nullptr) {
  const auto bu = bernstein(u), bv = bernstein(v);
  const auto su = bernstein_slope(u), sv = bernstein_slope(v);
  Vec3 point(0.0), tangent_u(0.0), tangent_v(0.0);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const Vec3& c = p[size_t(4 * i + j)];
      point += bv[size_t(i)] * bu[size_t(j)] * c;
      tangent_u += bv[size_t(i)] * su[size_t(j)] * c;
      tangent_v += sv[size_t(i)] * bu[size_t(j)] * c;
    }
  }
  if (du) *du = tangent_u;
  if (dv) *dv = tangent_v;
  return point;
}

// The normal at (u, v). Where the patch degenerates (a whole edge in one point, as at the
// teapot's lid) the tangents vanish: the normal is taken a little inside the patch.
Vec3 surface_normal(const ControlPoints& p, double u, double v) {
  for (double step : {0.0, 1e-6, 1e-4, 1e-2}) {
    Vec3 du, dv;
    surface(p, u + (u < 0.5 ? step : -step), v + (v < 0.5 ? step : -step), &du, &dv);
    const Vec3 n = glm::cross(du, dv);
    const double length = glm::length(n);
    if (length > 1e-12 && std::isfinite(length)) return n / length;
  }
  return Vec3(0.0, 0.0, 1.0);
}

int steps_param(Parser& parser, const std::string& word) {
  const SourceLoc loc = parser.peek().loc;
  const int steps = int(parser.parse_float_before_points());
  // POV-Ray accepts large values; past 2^10 pieces per side a patch is finer than any picture.
  if (steps < 0 || steps > 10) {
    parser.fail(loc, word + " must lie in 0..10, found " + std::to_string(steps));
  }
  return steps;
}

scene::TriangleMesh patch_mesh(const ControlPoints& p, int u_steps, int v_steps) {
  const int nu = 1 << u_steps, nv = 1 << v_steps;
  scene::TriangleMesh mesh;
  for (int i = 0; i <= nv; ++i) {
    for (int j = 0; j <= nu; ++j) {
      const double u = double(j) / nu, v = double(i) / nv;
      mesh.vertices.push_back(surface(p, u, v));
      mesh.normals.push_back(surface_normal(p, u, v));
    }
  }
  const auto index = [&](int i, int j) { return i * (nu + 1) + j; };
  const auto add = [&](int a, int b, int c) {
    const auto& v = mesh.vertices;
    const Vec3 area = glm::cross(v[size_t(b)] - v[size_t(a)], v[size_t(c)] - v[size_t(a)]);
    if (!(glm::length(area) > 0.0)) return;  // a degenerate corner of the grid
    scene::MeshFace face;
    face.vertices = {a, b, c};
    face.normals = {a, b, c};
    mesh.faces.push_back(face);
  };
  for (int i = 0; i < nv; ++i) {
    for (int j = 0; j < nu; ++j) {
      add(index(i, j), index(i, j + 1), index(i + 1, j + 1));
      add(index(i, j), index(i + 1, j + 1), index(i + 1, j));
    }
  }
  return mesh;
}

}  // namespace

scene::ObjectPtr parse_bicubic_patch(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "bicubic_patch", loc);
  int u_steps = 0, v_steps = 0;
  static constexpr std::string_view kSettings[] = {"type", "flatness", "u_steps", "v_steps",
                                                   "uv_vectors"};
  while (at_any_word(parser, kSettings)) {
    const std::string word = parser.peek().text;
    const SourceLoc word_loc = take_keyword(parser);
    if (word == "type") {
      const int type = int(parser.parse_float_before_points());
      if (type != 0 && type != 1) parser.fail(word_loc, "bicubic_patch type must be 0 or 1");
    } else if (word == "flatness") {
      parser.parse_float_before_points();
    } else if (word == "u_steps") {
      u_steps = steps_param(parser, word);
    } else if (word == "v_steps") {
      v_steps = steps_param(parser, word);
    } else {
      for (int k = 0; k < 4; ++k) {
        parser.accept_comma();
        parser.parse_vector_before_points();
      }
    }
    parser.accept_comma();
  }
  ControlPoints points;
  for (Vec3& point : points) {
    parser.accept_comma();
    point = parser.parse_vector_before_points();
  }
  scene::Object object;
  object.loc = loc;
  scene::TriangleMesh mesh = patch_mesh(points, u_steps, v_steps);
  if (mesh.faces.empty()) parser.fail(loc, "this bicubic_patch has no area");
  object.shape = std::move(mesh);
  return parse_modifiers(block, std::move(object), kSettings);
}

}  // namespace convray::sdl::items
