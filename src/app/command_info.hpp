#pragma once
// `convray info MESH`: what is in a mesh file, and what radius to start from.
#include <ostream>
#include <string>

namespace convray::app {

// Prints the report on `out`, one `label: value` line per fact (the labels are fixed; tests
// and scripts may rely on them). On an InputError, prints its message on `err` and returns 2;
// otherwise returns 0. With `self_intersections`, also counts the pairs of faces that
// intersect beyond their shared corners (exactly; mesh/self_intersections.hpp) and lists the
// first few.
int run_info(const std::string& path, bool self_intersections, std::ostream& out,
             std::ostream& err);

}  // namespace convray::app
