#pragma once
// `convray view`'s work without a window (docs/view.md): a scene file (or a mesh, made a
// scene as `quick` makes one) parsed with the view's overrides (the clock, the camera the
// mouse moved, the convolution headers edited), built into a World, and rendered as a coarse
// picture (one ray per 8 x 8 block) or at full resolution, through the one renderer. Each
// load remembers the files the parse read, for the watcher. The window (src/display) and
// the worker thread (view_worker.hpp) use it; so do the tests and the benchmark.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/view_camera.hpp"
#include "geometry/world.hpp"
#include "implicit/support_cache.hpp"
#include "render/render_observer.hpp"
#include "render/render_result.hpp"
#include "scene/scene.hpp"
#include "sdl/parse_log.hpp"

namespace convray::sdl {
class MeshLibrary;
}

namespace convray::app {

struct ViewOptions {
  std::string input;  // a scene file, or a mesh file (.obj .ply .stl .off, optionally .gz)
  int width = 800, height = 600;
  bool antialias = false;  // the full-resolution pass: +A0.3
  double aa_threshold = 0.3;
  std::vector<std::string> library_paths, read_folders;
  bool read_anywhere = false;
};

// What the mouse and keys changed: applied at each load.
struct ViewOverrides {
  double clock = 0.0;
  std::optional<ViewCamera> camera;  // none: the scene's own
  std::vector<sdl::ConvolutionEdit> edits;
};

// A scene parsed and built: what a render needs, immutable, shared with the render thread.
struct ViewFrame {
  scene::Scene scene;
  std::shared_ptr<const geometry::World> world;  // shared by frames that differ in camera
  ViewCamera camera;  // the camera's items (the scene's, or the override)
  std::vector<sdl::ConvolutionHeader> convolutions;
  std::vector<std::string> warnings;
};

// The block of the first, coarse picture.
constexpr int kCoarseBlock = 8;

class ViewSession {
 public:
  explicit ViewSession(ViewOptions options);
  ~ViewSession();

  const ViewOptions& options() const { return options_; }

  // Parses and builds with `overrides`. Throws InputError (file:line:col: message) for a
  // bad scene; the files the parse read are known either way (watched_files).
  std::shared_ptr<const ViewFrame> load(const ViewOverrides& overrides);

  // `frame` seen through `camera` instead: the same World, no parse (the mouse moved).
  static std::shared_ptr<const ViewFrame> with_camera(const ViewFrame& frame,
                                                      const ViewCamera& camera);

  // The scene file (or mesh) and every file its last parse read.
  std::vector<std::string> watched_files() const;

  // Renders `frame`: block 1 is the full picture (anti-aliased if asked), kCoarseBlock the
  // coarse one. `observer` sees each tile and may stop the render (RenderCancelled).
  render::RenderResult render(const ViewFrame& frame, int block,
                              render::RenderObserver* observer = nullptr) const;

 private:
  std::string mesh_scene_text() const;

  ViewOptions options_;
  std::shared_ptr<sdl::MeshLibrary> meshes_;
  implicit::SupportCache hierarchies_;
  std::vector<std::string> files_;
  std::optional<std::string> mesh_scene_;  // a mesh's scene, made once
};

// The convolution header of the object that the ray through pixel (x, y) meets first, if it
// is (or is part of) a convolution object; none for other objects and the background.
std::optional<sdl::ConvolutionHeader> convolution_at(const ViewFrame& frame, int width,
                                                     int height, int x, int y);

// The offset a header stands for: the one written, or the one its threshold gives
// (field::threshold's inverse is not needed: a written threshold shows as R / 2 until edited).
double header_offset(const sdl::ConvolutionHeader& header);

// `convolution { radius R offset D [strength s] [kernel ...]` : the header to paste over the
// scene's, in the scene language.
std::string convolution_header_text(const sdl::ConvolutionHeader& header);

}  // namespace convray::app
