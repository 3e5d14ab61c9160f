#include "geometry/cauchy_shape.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geometry/first_open_crossing.hpp"
#include "implicit/ray_box.hpp"

namespace convray::geometry {

CauchyShape::CauchyShape(const scene::Implicit& record, SurfaceInfoPtr surface)
    : surface_(record.object), object_surface_(std::move(surface)) {
  for (const scene::ComponentTexture& given : record.component_textures) {
    if (given.index >= record.component_order.size()) {
      throw std::invalid_argument("component texture for component " + std::to_string(given.index) +
                                  ", which does not exist");
    }
    const auto [kind, index] = record.component_order[given.index];
    auto info = std::make_shared<SurfaceInfo>(*object_surface_);
    if (given.texture) info->texture = given.texture;
    component_surfaces_.emplace_back(implicit::ComponentRef{kind, uint32_t(index)}, info);
  }
}

const SurfaceInfo* CauchyShape::surface_at(const Vec3& p) const {
  if (component_surfaces_.empty()) return object_surface_.get();
  thread_local std::vector<implicit::CauchySurface::ComponentValue> values, sums;
  values.clear();
  sums.clear();
  surface_.component_values(p, values);
  for (const auto& v : values) {  // few components reach any one point
    auto it = std::find_if(sums.begin(), sums.end(),
                           [&](const auto& s) { return s.component == v.component; });
    if (it == sums.end()) {
      sums.push_back(v);
    } else {
      it->value += v.value;
    }
  }
  const auto dominant = std::max_element(
      sums.begin(), sums.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
  if (dominant == sums.end() || !(dominant->value > 0.0)) return object_surface_.get();
  for (const auto& [component, info] : component_surfaces_) {
    if (component == dominant->component) return info.get();
  }
  return object_surface_.get();
}

void CauchyShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                            TraceStats& stats) const {
  double t0 = tmin, t1 = tmax;
  if (!implicit::clip_to_box(ray, surface_.bounds(), t0, t1)) return;
  thread_local std::vector<implicit::SurfaceHit> hits;  // not re-entered: hits() calls no shape
  hits.clear();
  surface_.hits(ray, t0, t1, hits, stats);
  for (const implicit::SurfaceHit& hit : hits) {
    if (hit.t > tmin && hit.t < tmax) out.push_back({hit.t, hit.normal, surface_at(hit.point)});
  }
}

std::optional<Crossing> CauchyShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                    TraceStats& stats) const {
  return first_open_crossing(*this, surface_, ray, tmin, tmax, stats);
}

bool CauchyShape::inside(const Vec3& p) const {
  return surface_.field(p).value >= surface_.threshold();
}

}  // namespace convray::geometry
