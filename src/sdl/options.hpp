#pragma once
// What the command line tells the scene: the image size, the animation clock, where includes
// are searched, identifiers declared from outside, and the limits that stop runaway scenes.
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace convray::scene {
class ColorSources;  // scene/color_sources.hpp
}  // namespace convray::scene

namespace convray::sdl {

class MeshLibrary;
class ObjectQueries;
class ImageReader;
struct ParseLog;          // sdl/parse_log.hpp
struct ConvolutionEdit;   // sdl/parse_log.hpp

struct ParseOptions {
  int image_width = 800, image_height = 600;
  // Animation identifiers (clock, clock_delta, clock_on, frame_number, ...): POV-Ray's values
  // for a still image unless the command line says otherwise.
  double clock = 0.0, clock_delta = 0.0;
  bool clock_on = false;
  int frame_number = 0, initial_frame = 0, final_frame = 0;
  double initial_clock = 0.0, final_clock = 0.0;
  // +L paths, searched after the scene's own folder and before POV-Ray's installed includes.
  std::vector<std::string> library_paths;
  // Where POV-Ray's include files are installed, searched last when the folder exists.
  std::vector<std::string> system_include_paths{"/usr/share/povray-3.7/include"};
  // POV-Ray's I/O restrictions: a scene reads files (includes, meshes, file_exists) only from
  // its own folder, the working folder, library_paths, system_include_paths and these folders,
  // each with everything below it (util/read_permissions.hpp); or from anywhere.
  std::vector<std::string> read_folders;
  bool read_anywhere = false;
  // Where #fopen ... write puts a relative file name: the output image's folder. Writing is
  // allowed there and in the scene's own folder only; empty: #fopen for writing is an error.
  std::string write_folder;
  // Declare=ID=value from the command line: float values.
  std::vector<std::pair<std::string, double>> declares;
  // Runaway scenes stop with an error at these limits.
  int max_include_depth = 64;
  int max_macro_depth = 256;
  long long max_loop_iterations = 10'000'000;   // per #while / #for loop
  long long max_tokens = 2'000'000'000;         // tokens read in all
  // Elements of all live arrays together (an array of arrays counts every element of each):
  // about 1.6 GB of values.
  std::size_t max_live_array_elements = std::size_t(1) << 24;
  // Mesh files kept across parses (an animation's frames; sdl/mesh_library.hpp); without
  // one, each parse reads its meshes afresh.
  std::shared_ptr<MeshLibrary> mesh_library;
  // min_extent, max_extent and trace() ask the objects' geometry (sdl/object_queries.hpp);
  // without an implementation they are errors.
  std::shared_ptr<const ObjectQueries> object_queries;
  // Pigment, pattern and noise functions ask the renderer (scene/color_sources.hpp); null:
  // such functions are unsupported where called.
  std::shared_ptr<const scene::ColorSources> color_sources;
  // image_map reads its picture through this (sdl/image_reader.hpp); without one, an
  // image_map is an error.
  std::shared_ptr<const ImageReader> image_reader;
  // `convray view`: where the parse notes the files it read and the convolution headers, and
  // the headers' radius and offset it replaces (sdl/parse_log.hpp). Null and empty: neither.
  std::shared_ptr<ParseLog> log;
  std::shared_ptr<const std::vector<ConvolutionEdit>> convolution_edits;
};

}  // namespace convray::sdl
