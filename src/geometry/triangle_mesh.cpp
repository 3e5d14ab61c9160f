#include "geometry/triangle_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace convray::geometry {
namespace {

bool valid_index(int index, size_t size) { return index >= 0 && size_t(index) < size; }

}  // namespace

TriangleMeshShape::TriangleMeshShape(const scene::TriangleMesh& mesh,
                                     std::vector<SurfaceInfoPtr> surfaces)
    : normals_(mesh.normals), surfaces_(std::move(surfaces)) {
  if (surfaces_.empty()) throw std::invalid_argument("mesh: no surface description");
  if (mesh.inside_vector) {
    if (!(glm::length(*mesh.inside_vector) > 0.0)) {
      throw std::invalid_argument("mesh: the inside_vector must not be zero");
    }
    inside_direction_ = glm::normalize(*mesh.inside_vector);
  }
  faces_.reserve(mesh.faces.size());
  std::vector<Box3> boxes;
  boxes.reserve(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const scene::MeshFace& face = mesh.faces[f];
    const std::string which = "mesh face " + std::to_string(f);
    for (int v : face.vertices) {
      if (!valid_index(v, mesh.vertices.size())) {
        throw std::invalid_argument(which + ": vertex index " + std::to_string(v) +
                                    " out of range");
      }
    }
    const bool smooth = face.normals[0] >= 0 || face.normals[1] >= 0 || face.normals[2] >= 0;
    for (int n : face.normals) {
      if (smooth && !valid_index(n, normals_.size())) {
        throw std::invalid_argument(which + ": normal index " + std::to_string(n) +
                                    " out of range");
      }
    }
    if (face.texture != -1 && !valid_index(face.texture + 1, surfaces_.size())) {
      throw std::invalid_argument(which + ": texture index " + std::to_string(face.texture) +
                                  " out of range");
    }
    const Vec3 a = mesh.vertices[size_t(face.vertices[0])];
    const Vec3 b = mesh.vertices[size_t(face.vertices[1])];
    const Vec3 c = mesh.vertices[size_t(face.vertices[2])];
    if (glm::length(glm::cross(b - a, c - a)) == 0.0) continue;  // no area: never hit
    faces_.push_back({a, b - a, c - a, smooth ? face.normals : std::array<int32_t, 3>{-1, -1, -1},
                      uint32_t(face.texture + 1)});
    Box3 box;
    box.extend(a);
    box.extend(b);
    box.extend(c);
    boxes.push_back(box);
  }
  bvh_ = Bvh(boxes);
}

Box3 TriangleMeshShape::bounds() const { return bvh_.bounds(); }

Box3 TriangleMeshShape::inside_bounds() const { return inside_direction_ ? bounds() : Box3{}; }

// Möller and Trumbore's test: barycentric (u, v) of the hit by Cramer's rule.
bool TriangleMeshShape::intersect(const Face& face, const Ray& ray, double tmin, double tmax,
                                  Hit& hit) {
  const Vec3 p = glm::cross(ray.direction, face.edge2);
  const double det = glm::dot(face.edge1, p);
  if (det == 0.0) return false;  // the ray lies in the triangle's plane
  const double inverse = 1.0 / det;
  const Vec3 s = ray.origin - face.a;
  const double u = glm::dot(s, p) * inverse;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = glm::cross(s, face.edge1);
  const double v = glm::dot(ray.direction, q) * inverse;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = glm::dot(face.edge2, q) * inverse;
  if (!(t > tmin && t < tmax)) return false;
  hit = {t, u, v};
  return true;
}

Crossing TriangleMeshShape::make_crossing(const Face& face, const Hit& hit) const {
  const Vec3 flat = glm::normalize(glm::cross(face.edge1, face.edge2));
  Vec3 normal = flat;
  if (face.normals[0] >= 0) {
    // smooth_triangle: the vertex normals weighted by the barycentric coordinates.
    const Vec3 blend = (1.0 - hit.u - hit.v) * normals_[size_t(face.normals[0])] +
                       hit.u * normals_[size_t(face.normals[1])] +
                       hit.v * normals_[size_t(face.normals[2])];
    const double length = glm::length(blend);
    if (length > 0.0) normal = blend / length;
  }
  return {hit.t, normal, surfaces_[face.surface].get()};
}

void TriangleMeshShape::crossings(const Ray& ray, double tmin, double tmax,
                                  std::vector<Crossing>& out, TraceStats& /*stats*/) const {
  const size_t first = out.size();
  double reach = tmax;
  bvh_.traverse(ray, tmin, reach, [&](uint32_t f, double&) {
    Hit hit;
    if (intersect(faces_[f], ray, tmin, tmax, hit)) out.push_back(make_crossing(faces_[f], hit));
  });
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

std::optional<Crossing> TriangleMeshShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                          TraceStats& /*stats*/) const {
  const Face* nearest = nullptr;
  Hit nearest_hit{};
  bvh_.traverse(ray, tmin, tmax, [&](uint32_t f, double& reach) {
    Hit hit;
    if (intersect(faces_[f], ray, tmin, reach, hit)) {
      nearest = &faces_[f];
      nearest_hit = hit;
      reach = hit.t;  // only nearer triangles matter now
    }
  });
  if (!nearest) return std::nullopt;
  return make_crossing(*nearest, nearest_hit);
}

void TriangleMeshShape::crossings_brute_force(const Ray& ray, double tmin, double tmax,
                                              std::vector<Crossing>& out) const {
  const size_t first = out.size();
  for (const Face& face : faces_) {
    Hit hit;
    if (intersect(face, ray, tmin, tmax, hit)) out.push_back(make_crossing(face, hit));
  }
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

size_t TriangleMeshShape::count_crossings(const Ray& ray) const {
  size_t count = 0;
  double reach = kInfinity;
  bvh_.traverse(ray, 0.0, reach, [&](uint32_t f, double&) {
    Hit hit;
    if (intersect(faces_[f], ray, 0.0, kInfinity, hit)) ++count;
  });
  return count;
}

bool TriangleMeshShape::inside(const Vec3& p) const {
  if (!inside_direction_ || !contains(bounds(), p)) return false;
  return count_crossings(Ray{p, *inside_direction_}) % 2 == 1;
}

}  // namespace convray::geometry
