#pragma once
// Fields with known surfaces, written out by hand for the polygonizer's tests: the quartic
// kernel (1 - d^2/R^2)^2 of the distance d to a point, a circle or a sphere, whose level sets
// are spheres, tori and pairs of spheres of known radii.
#include <cmath>
#include <vector>

#include "polygonize/field_source.hpp"

namespace convray::polygonize::testing {

// The kernel k(d) = (1 - d^2/R^2)^2 for d < R, with dk/dd; zero beyond R.
inline void kernel(double d, double radius, double& value, double& slope) {
  const double x = 1.0 - d * d / (radius * radius);
  value = x > 0.0 ? x * x : 0.0;
  slope = x > 0.0 ? -4.0 * x * d / (radius * radius) : 0.0;
}

// The level set k(d) = T lies at d = R sqrt(1 - sqrt(T)).
inline double level_distance(double radius, double threshold) {
  return radius * std::sqrt(1.0 - std::sqrt(threshold));
}

// A distance function with its gradient, as the kernel's argument.
struct Distance {
  virtual ~Distance() = default;
  virtual double at(const Vec3& p, Vec3& gradient) const = 0;
};

struct ToPoint : Distance {
  Vec3 center;
  explicit ToPoint(const Vec3& c) : center(c) {}
  double at(const Vec3& p, Vec3& g) const override {
    const double d = glm::length(p - center);
    g = d > 0.0 ? (p - center) / d : Vec3(0.0);
    return d;
  }
};

// The circle of radius `major` around the z axis in the plane z = 0.
struct ToCircle : Distance {
  double major;
  explicit ToCircle(double a) : major(a) {}
  double at(const Vec3& p, Vec3& g) const override {
    const double rho = std::hypot(p.x, p.y);
    const Vec3 nearest =
        rho > 0.0 ? Vec3(major * p.x / rho, major * p.y / rho, 0.0) : Vec3(major, 0.0, 0.0);
    const double d = glm::length(p - nearest);
    g = d > 0.0 ? (p - nearest) / d : Vec3(0.0);
    return d;
  }
};

// The sphere of radius `rho` around the origin: its level sets are two spheres, rho ± d.
struct ToSphere : Distance {
  double rho;
  explicit ToSphere(double r) : rho(r) {}
  double at(const Vec3& p, Vec3& g) const override {
    const double r = glm::length(p);
    g = r > 0.0 ? (r >= rho ? 1.0 : -1.0) * p / r : Vec3(0.0);
    return std::abs(r - rho);
  }
};

// A sum of kernels of distances, each with its strength, radius and bounding box.
struct KernelSum {
  struct Term {
    const Distance* distance;
    double strength, radius;
    Box3 box;
  };
  std::vector<Term> terms;

  FieldSource source(double threshold) const {
    FieldSource s;
    s.threshold = threshold;
    for (const Term& t : terms) s.supports.push_back(t.box);
    s.field = [this](const Vec3& p) {
      field::FieldSample sum;
      for (const Term& t : terms) {
        Vec3 g;
        const double d = t.distance->at(p, g);
        double k = 0.0, slope = 0.0;
        kernel(d, t.radius, k, slope);
        sum.value += t.strength * k;
        sum.gradient += t.strength * slope * g;
      }
      return sum;
    };
    return s;
  }
};

inline Box3 cube(const Vec3& center, double half) {
  return {center - Vec3(half), center + Vec3(half)};
}

}  // namespace convray::polygonize::testing
