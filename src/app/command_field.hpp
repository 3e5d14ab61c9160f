#pragma once
#include <iosfwd>
#include <string>

namespace convray::app {

struct FieldOptions {
  std::string mesh_path;
  double radius = 1.0;
  double strength = 1.0;
};

// `convray field`: reads "x y z" lines from `in`, writes "F dF/dx dF/dy dF/dz" lines with 17
// significant digits to `out`. Returns the process exit code: 0, or 2 for bad input (the
// message, "stdin:LINE: what is wrong", goes to `err`; lines before it are answered).
int run_field(const FieldOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace convray::app
