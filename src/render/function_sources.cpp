#include "render/function_sources.hpp"

#include "render/noise.hpp"
#include "render/patterns.hpp"
#include "render/pigment.hpp"

namespace convray::render {

namespace {

class PigmentSource final : public scene::ColorSource {
 public:
  explicit PigmentSource(scene::Pigment pigment) : pigment_(std::move(pigment)) {}
  scene::Color at(const Vec3& point) const override { return evaluate_pigment(pigment_, point); }

 private:
  scene::Pigment pigment_;
};

class PatternSource final : public scene::ColorSource {
 public:
  explicit PatternSource(scene::PatternSpace space) : space_(std::move(space)) {}
  scene::Color at(const Vec3& point) const override {
    const double value = pattern_value(space_, point);
    return scene::Color{Vec3(value), 0.0, 0.0};
  }

 private:
  scene::PatternSpace space_;
};

class NoiseSource final : public scene::ColorSource {
 public:
  scene::Color at(const Vec3& point) const override {
    return scene::Color{Vec3(noise(point)), 0.0, 0.0};
  }
};

}  // namespace

std::shared_ptr<const scene::ColorSource> noise_source() {
  static const auto source = std::make_shared<const NoiseSource>();
  return source;
}

std::shared_ptr<const scene::ColorSource> pigment_source(scene::Pigment pigment) {
  return std::make_shared<PigmentSource>(std::move(pigment));
}

std::shared_ptr<const scene::ColorSource> pattern_source(scene::PatternSpace space) {
  return std::make_shared<PatternSource>(std::move(space));
}

namespace {
class RendererColorSources final : public scene::ColorSources {
 public:
  std::shared_ptr<const scene::ColorSource> pigment(scene::Pigment pigment) const override {
    return pigment_source(std::move(pigment));
  }
  std::shared_ptr<const scene::ColorSource> pattern(scene::PatternSpace space) const override {
    return pattern_source(std::move(space));
  }
  std::shared_ptr<const scene::ColorSource> noise() const override { return noise_source(); }
};
}  // namespace

std::shared_ptr<const scene::ColorSources> renderer_color_sources() {
  return std::make_shared<const RendererColorSources>();
}

}  // namespace convray::render
