#include "app/view_session.hpp"

#include <algorithm>
#include <filesystem>

#include "app/parse_hooks.hpp"
#include "field/threshold.hpp"
#include "mesh/load.hpp"
#include "mesh/skeleton_stats.hpp"
#include "mesh/stats.hpp"
#include "render/render_scene.hpp"
#include "render/scene_camera.hpp"
#include "scene/quick_scene.hpp"
#include "sdl/mesh_library.hpp"
#include "sdl/parser.hpp"

namespace convray::app {

namespace {

std::string quoted(const std::string& path) {
  std::string q = "\"";
  for (char c : path) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return q + "\"";
}

// Every convolution in `object`'s tree, alone and placed in the world as in the tree (its
// own transform, then its CSG parents'), with the place of its header.
struct PlacedConvolution {
  scene::Object alone;
  SourceLoc header;
};
void placed_convolutions(const scene::Object& object, const scene::Transform& above,
                         std::vector<PlacedConvolution>& out) {
  const scene::Transform placed = object.transform.then(above);
  if (const auto* implicit = std::get_if<scene::Implicit>(&object.shape)) {
    if (implicit->header_loc.file.empty()) return;
    scene::Object alone = object;
    alone.transform = placed;
    alone.inverse = false;
    out.push_back({std::move(alone), implicit->header_loc});
  } else if (const auto* csg = std::get_if<scene::Csg>(&object.shape)) {
    for (const scene::ObjectPtr& child : csg->children) placed_convolutions(*child, placed, out);
  }
}

}  // namespace

ViewSession::ViewSession(ViewOptions options)
    : options_(std::move(options)), meshes_(std::make_shared<sdl::MeshLibrary>()) {}

ViewSession::~ViewSession() = default;

// What `quick` renders, as scene text: the mesh convolved at the radius `convray info`
// advises, framed by the camera quick chooses, in quick's clay, under quick's light. As text,
// its header can be edited and printed like a scene file's.
std::string ViewSession::mesh_scene_text() const {
  const mesh::LoadedMesh loaded = mesh::load_mesh(options_.input);
  const double radius = mesh::advise_radius(mesh::compute_stats(loaded.soup),
                                            mesh::compute_skeleton_stats(loaded)).radius;
  Box3 bounds = loaded.bounds();
  bounds.lo -= Vec3(radius);
  bounds.hi += Vec3(radius);
  const scene::LookAtView view =
      scene::frame_bounds(bounds, options_.width, options_.height, 40.0);
  const Vec3 light =
      scene::default_light_position(scene::look_at_camera(view), bounds);
  const std::string path = std::filesystem::absolute(options_.input).lexically_normal().string();
  const scene::Texture& clay = *scene::quick_texture();  // quick's own, written out
  return "// convray view " + options_.input + ": the scene convray quick renders\n"
         "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
         "camera {\n  perspective\n  location " + vector_text(view.location) +
         "\n  look_at " + vector_text(view.look_at) + "\n  right x * image_width / image_height\n"
         "  angle 40\n}\n"
         "light_source { " + vector_text(light) + " color rgb 1 }\n"
         "background { color rgb " + vector_text(scene::quick_background()) + " }\n"
         "convolution {\n  radius " + exact_number(radius) + "\n  mesh { " + quoted(path) + " }\n"
         "  texture {\n    pigment { color rgb " + vector_text(clay.pigment.color.rgb) + " }\n"
         "    finish { ambient " + vector_text(clay.finish.ambient) +
         " diffuse " + exact_number(clay.finish.diffuse) +
         " phong " + exact_number(clay.finish.phong) +
         " phong_size " + exact_number(clay.finish.phong_size) + " }\n  }\n}\n";
}

std::shared_ptr<const ViewFrame> ViewSession::load(const ViewOverrides& overrides) {
  sdl::ParseOptions p;
  p.mesh_library = meshes_;
  p.image_width = options_.width;
  p.image_height = options_.height;
  p.clock = overrides.clock;
  p.library_paths = options_.library_paths;
  p.read_folders = options_.read_folders;
  p.read_anywhere = options_.read_anywhere;
  use_program_hooks(p);
  auto log = std::make_shared<sdl::ParseLog>();
  p.log = log;
  p.convolution_edits = std::make_shared<const std::vector<sdl::ConvolutionEdit>>(overrides.edits);
  sdl::ParseResult parsed;
  try {
    if (mesh::is_mesh_file_name(options_.input)) {
      if (!mesh_scene_) mesh_scene_ = mesh_scene_text();
      parsed = sdl::parse_string(*mesh_scene_, options_.input + ".pov", p);
    } else {
      parsed = sdl::parse_file(options_.input, p);
    }
  } catch (...) {
    files_ = log->files;  // a broken include is watched too: saving it fixes the scene
    throw;
  }
  files_ = log->files;
  auto frame = std::make_shared<ViewFrame>();
  frame->scene = std::move(parsed.scene);
  if (overrides.camera) frame->scene.camera = camera_of(*overrides.camera);
  frame->world = std::make_shared<const geometry::World>(frame->scene, &hierarchies_);
  hierarchies_.next_frame();
  frame->camera = overrides.camera.value_or(view_of(frame->scene.camera, frame->world->bounds()));
  frame->convolutions = log->convolutions;
  frame->warnings = std::move(parsed.warnings);
  return frame;
}

std::shared_ptr<const ViewFrame> ViewSession::with_camera(const ViewFrame& frame,
                                                          const ViewCamera& camera) {
  auto moved = std::make_shared<ViewFrame>();
  moved->scene = frame.scene;  // records shared, not copied
  moved->scene.camera = camera_of(camera);
  moved->world = frame.world;
  moved->camera = camera;
  moved->convolutions = frame.convolutions;
  return moved;
}

std::vector<std::string> ViewSession::watched_files() const {
  std::vector<std::string> files{options_.input};
  for (const std::string& f : files_) {
    if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
  }
  return files;
}

render::RenderResult ViewSession::render(const ViewFrame& frame, int block,
                                         render::RenderObserver* observer) const {
  render::RenderSettings s;
  s.width = options_.width;
  s.height = options_.height;
  s.block_size = block;
  s.antialias = options_.antialias;
  s.aa_threshold = options_.aa_threshold;
  return render::render_scene(frame.scene, *frame.world, s, nullptr, observer);
}

std::optional<sdl::ConvolutionHeader> convolution_at(const ViewFrame& frame, int width,
                                                     int height, int x, int y) {
  if (x < 0 || y < 0 || x >= width || y >= height) return std::nullopt;
  const render::SceneCamera camera(frame.scene.camera, width, height);
  const Ray ray = camera.primary_ray(x, y);
  if (ray.direction == Vec3(0.0)) return std::nullopt;
  const double tmin = render::automatic_ray_offset(frame.scene, *frame.world);
  TraceStats stats;
  const auto seen = frame.world->first_hit(ray, tmin, kInfinity, stats,
                                           geometry::World::Objects::all,
                                           geometry::World::Viewer::camera);
  if (!seen) return std::nullopt;
  // The convolution whose own surface passes through the point seen: in a union, or carved
  // by CSG, the visible surface at that depth is one member's (a member hidden behind another
  // object, or cut away, has no crossing there).
  const double near = 1e-7 * (1.0 + std::abs(seen->t));
  std::optional<SourceLoc> best;
  double best_gap = near;
  for (const scene::ObjectPtr& object : frame.scene.objects) {
    std::vector<PlacedConvolution> members;
    placed_convolutions(*object, scene::Transform(), members);
    for (const PlacedConvolution& member : members) {
      std::vector<geometry::ShapePtr> shapes;
      geometry::build_split_shapes(member.alone, shapes);
      for (const geometry::ShapePtr& shape : shapes) {
        std::vector<geometry::Crossing> crossings;
        shape->crossings(ray, std::max(tmin, seen->t - near), seen->t + near, crossings, stats);
        for (const geometry::Crossing& c : crossings) {
          const double gap = std::abs(c.t - seen->t);
          if (gap <= best_gap) best_gap = gap, best = member.header;
        }
      }
    }
  }
  if (!best) return std::nullopt;
  for (const sdl::ConvolutionHeader& header : frame.convolutions) {
    if (sdl::same_place(header.loc, *best)) return header;
  }
  return std::nullopt;
}

double header_offset(const sdl::ConvolutionHeader& h) {
  if (h.offset) return *h.offset;
  if (!h.threshold) return 0.5 * h.radius;
  // The offset whose plane field is the threshold written: the field falls with the offset.
  double lo = 0.0, hi = h.radius;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (field::plane_threshold(h.kernel, h.strength, h.radius, mid) > *h.threshold ? lo : hi) = mid;
  }
  return lo;
}

std::string convolution_header_text(const sdl::ConvolutionHeader& h) {
  std::string text = "convolution {  // " + h.loc.str() + "\n";
  text += "  radius " + exact_number(h.radius) + "\n";
  text += "  offset " + exact_number(header_offset(h)) + "\n";
  if (h.strength != 1.0) text += "  strength " + exact_number(h.strength) + "\n";
  if (h.kernel.type == field::KernelType::cauchy) {
    text += "  kernel cauchy " + exact_number(h.kernel.sharpness) + "\n";
  }
  return text + "  // ... its components and modifiers, as in the scene\n";
}

}  // namespace convray::app
