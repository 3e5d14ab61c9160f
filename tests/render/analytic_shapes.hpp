#pragma once
// Shapes whose ray intersections are known in closed form, as Traceables: the renderer's
// tests draw these instead of convolution surfaces, so a wrong pixel can only be the
// renderer's fault.
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "render/traceable.hpp"

namespace convray::testing {

using render::Ray;
using render::SurfaceHit;
using render::TraceStats;

class AnalyticShape : public render::Traceable {
 public:
  bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override {
    return first_hit(ray, tmin, tmax, stats).has_value();
  }
};

// The sphere |p - center| = radius; normals point out.
class SphereShape final : public AnalyticShape {
 public:
  SphereShape(const Vec3& center, double radius) : center_(center), radius_(radius) {}

  Box3 bounds() const override { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override {
    ++stats.rays;
    // |o + t d - c|^2 = r^2 with |d| = 1: t^2 + 2 b t + c = 0.
    const Vec3 oc = ray.origin - center_;
    const double b = glm::dot(oc, ray.direction);
    const double c = glm::dot(oc, oc) - radius_ * radius_;
    const double disc = b * b - c;
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(disc);
    for (const double t : {-b - root, -b + root}) {
      if (t >= tmin && t <= tmax) {
        const Vec3 p = ray.at(t);
        return SurfaceHit{t, p, (p - center_) / radius_};
      }
    }
    return std::nullopt;
  }

 private:
  Vec3 center_;
  double radius_;
};

// The square |x|, |z| <= half_size at height y = height, facing +y (bounds: a thin box).
class FloorShape final : public AnalyticShape {
 public:
  FloorShape(double height, double half_size) : height_(height), half_(half_size) {}

  Box3 bounds() const override {
    return {Vec3(-half_, height_, -half_), Vec3(half_, height_, half_)};
  }

  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override {
    ++stats.rays;
    if (ray.direction.y == 0.0) return std::nullopt;
    const double t = (height_ - ray.origin.y) / ray.direction.y;
    if (!(t >= tmin && t <= tmax)) return std::nullopt;
    const Vec3 p = ray.at(t);
    if (std::abs(p.x) > half_ || std::abs(p.z) > half_) return std::nullopt;
    return SurfaceHit{t, Vec3(p.x, height_, p.z), Vec3(0.0, 1.0, 0.0)};
  }

 private:
  double height_, half_;
};

// The nearest hit among several shapes.
class ShapeGroup final : public AnalyticShape {
 public:
  void add(std::unique_ptr<AnalyticShape> shape) { shapes_.push_back(std::move(shape)); }

  Box3 bounds() const override {
    Box3 box;
    for (const auto& s : shapes_) {
      box.extend(s->bounds().lo);
      box.extend(s->bounds().hi);
    }
    return box;
  }

  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override {
    std::optional<SurfaceHit> best;
    for (const auto& s : shapes_) {
      if (auto hit = s->first_hit(ray, tmin, best ? best->t : tmax, stats)) best = hit;
    }
    return best;
  }

 private:
  std::vector<std::unique_ptr<AnalyticShape>> shapes_;
};

}  // namespace convray::testing
