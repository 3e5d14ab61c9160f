#pragma once
// `convray info MESH`: what is in a mesh file, and what radius to start from.
#include <ostream>
#include <string>

namespace convray::app {

// Prints the report on `out`, one `label: value` line per fact (the labels are fixed; tests
// and scripts may rely on them). On an InputError, prints its message on `err` and returns 2;
// otherwise returns 0.
int run_info(const std::string& path, std::ostream& out, std::ostream& err);

}  // namespace convray::app
