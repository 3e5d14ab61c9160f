#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace convray::app {

// Either a mesh's triangles with one radius and strength, or a convolution or blob object
// declared in a scene (`#declare NAME = convolution { ... }`), placed by its transform.
struct FieldOptions {
  std::string mesh_path;
  double radius = 1.0;
  double strength = 1.0;
  std::string scene_path;
  std::string object_name;
  std::vector<std::string> library_paths;  // for the scene's #include and mesh files
  std::vector<std::string> read_folders;   // --allow-read: more folders the scene may read
};

// `convray field`: reads "x y z" lines from `in`, writes "F dF/dx dF/dy dF/dz" lines with 17
// significant digits to `out` (a scene object: its raw field F, whose surface is F = T). Returns the process exit code: 0, or 2 for bad input (the
// message, "stdin:LINE: what is wrong", goes to `err`; lines before it are answered).
int run_field(const FieldOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace convray::app
