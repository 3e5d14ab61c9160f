#include "app/command_slice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <span>
#include <vector>

#include <tbb/parallel_for.h>

#include "app/command_step.hpp"
#include "app/size_check.hpp"
#include "app/usage_error.hpp"
#include "scene/mesh_skeleton.hpp"
#include "implicit/mesh_field.hpp"
#include "field/threshold.hpp"
#include "mesh/load.hpp"
#include "core/image_file.hpp"
#include "util/error.hpp"

namespace convray::app {

namespace {

using Rgb = std::array<float, 3>;

// A perceptually ordered ramp (dark blue -> teal -> yellow) for 0 <= t <= 1.
Rgb ramp(double t) {
  static constexpr Rgb stops[] = {{0.05f, 0.03f, 0.20f}, {0.10f, 0.35f, 0.55f},
                                  {0.15f, 0.65f, 0.55f}, {0.95f, 0.85f, 0.25f}};
  t = std::clamp(t, 0.0, 1.0) * 3.0;
  const int i = std::min(int(t), 2);
  const float f = float(t - i);
  Rgb c;
  for (int k = 0; k < 3; ++k) c[k] = stops[i][k] + f * (stops[i + 1][k] - stops[i][k]);
  return c;
}

// Maps pixels to points on the plane axis = at, framing the box with equal scale on both axes.
struct PlaneFrame {
  int u_axis = 0, v_axis = 1, w_axis = 2;
  double u0 = 0, v0 = 0, scale = 1, at = 0;

  Vec3 point(double px, double py) const {
    Vec3 p;
    p[u_axis] = u0 + px * scale;
    p[v_axis] = v0 - py * scale;  // image rows go down, v goes up
    p[w_axis] = at;
    return p;
  }
};

PlaneFrame frame_for(const Box3& box, char axis, double at, double margin, int w, int h) {
  PlaneFrame f;
  f.w_axis = axis - 'x';
  f.u_axis = (f.w_axis + 1) % 3;
  f.v_axis = (f.w_axis + 2) % 3;
  if (f.w_axis == 1) std::swap(f.u_axis, f.v_axis);  // y slices show x right, z up
  const double du = box.hi[f.u_axis] - box.lo[f.u_axis] + 2 * margin;
  const double dv = box.hi[f.v_axis] - box.lo[f.v_axis] + 2 * margin;
  f.scale = std::max(du / w, dv / h);
  f.u0 = 0.5 * (box.lo[f.u_axis] + box.hi[f.u_axis]) - 0.5 * w * f.scale;
  f.v0 = 0.5 * (box.lo[f.v_axis] + box.hi[f.v_axis]) + 0.5 * h * f.scale;
  f.at = at;
  return f;
}

// Draws where each triangle crosses the plane, so the skeleton shows under its surface.
void draw_cross_section(const std::vector<field::Triangle>& triangles, const PlaneFrame& f,
                        int w, int h, std::vector<Rgb>& image) {
  for (const field::Triangle& t : triangles) {
    const Vec3 v[3] = {t.a, t.b, t.c};
    std::vector<Vec3> cuts;
    for (int k = 0; k < 3; ++k) {
      const double a = v[k][f.w_axis] - f.at, b = v[(k + 1) % 3][f.w_axis] - f.at;
      if ((a < 0) != (b < 0)) cuts.push_back(v[k] + (a / (a - b)) * (v[(k + 1) % 3] - v[k]));
    }
    if (cuts.size() != 2) continue;
    const double x0 = (cuts[0][f.u_axis] - f.u0) / f.scale, y0 = (f.v0 - cuts[0][f.v_axis]) / f.scale;
    const double x1 = (cuts[1][f.u_axis] - f.u0) / f.scale, y1 = (f.v0 - cuts[1][f.v_axis]) / f.scale;
    const int steps = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int s = 0; s <= steps; ++s) {
      const int x = int(x0 + (x1 - x0) * s / steps), y = int(y0 + (y1 - y0) * s / steps);
      if (x >= 0 && y >= 0 && x < w && y < h) image[size_t(y) * w + x] = {0.f, 0.f, 0.f};
    }
  }
}

}  // namespace

int run_slice(const SliceOptions& o, std::ostream& out, std::ostream& err) {
  CommandStep step("reading " + o.mesh_path, kFreeMemory);
  try {
    check_image_destination(o.output);  // before the work, not after it
    refuse_unless_image_fits(o.width, o.height, "give a smaller --size", o.force);
    double threshold = 0.0;
    try {
      threshold = field::resolve_threshold(o.strength, o.radius, o.offset, o.threshold);
    } catch (const std::invalid_argument& e) {
      throw InputError({"command line"}, e.what());
    }
    const mesh::LoadedMesh loaded = mesh::load_mesh(o.mesh_path);
    mesh::require_triangles(loaded, o.mesh_path, "slice");
    step.now("building the field of " + o.mesh_path, kFreeMemory);
    const implicit::MeshField field(scene::soup_triangles(loaded.soup), o.radius, o.strength);
    const PlaneFrame frame =
        frame_for(loaded.soup.bounds(), o.axis, o.at, 1.5 * o.radius, o.width, o.height);

    step.now("drawing the " + std::to_string(o.width) + "x" + std::to_string(o.height) + " slice",
             "give a smaller --size");
    std::vector<double> values(size_t(o.width) * o.height);
    tbb::parallel_for(0, o.height, [&](int y) {
      for (int x = 0; x < o.width; ++x) {
        values[size_t(y) * o.width + x] = field.value(frame.point(x + 0.5, y + 0.5));
      }
    });
    std::vector<Rgb> image(values.size());
    const auto inside = [&](int x, int y) { return values[size_t(y) * o.width + x] >= threshold; };
    for (int y = 0; y < o.height; ++y) {
      for (int x = 0; x < o.width; ++x) {
        const bool edge = (x + 1 < o.width && inside(x, y) != inside(x + 1, y)) ||
                          (y + 1 < o.height && inside(x, y) != inside(x, y + 1));
        image[size_t(y) * o.width + x] =
            edge ? Rgb{1.f, 1.f, 1.f} : ramp(values[size_t(y) * o.width + x] / (2.0 * threshold));
      }
    }
    draw_cross_section(field.triangles(), frame, o.width, o.height, image);
    // The ramp's colours are meant for display as they are: no sRGB encoding on top.
    static_assert(sizeof(Rgb) == 3 * sizeof(float), "Rgb pixels must pack as float triples");
    write_image_atomically(
        o.output, {o.width, o.height, std::span<const float>(image.front().data(), 3 * image.size()),
                   PixelEncoding::display});
    out << "slice " << o.axis << " = " << o.at << " of " << o.mesh_path << " (" << field.triangle_count()
        << " triangles, R = " << o.radius << ", T = " << threshold << "): wrote " << o.output
        << " (" << o.width << "x" << o.height << ")\n";
    return 0;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    err << "convray slice: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  } catch (const std::exception& e) {
    err << "convray slice: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace convray::app
