#pragma once
// The geometry behind the scene language's min_extent, max_extent and trace()
// (sdl/object_queries.hpp): each query builds the object's shape as the renderer would.
#include <memory>

#include "sdl/object_queries.hpp"

namespace convray::app {

std::shared_ptr<const sdl::ObjectQueries> geometry_object_queries();

}  // namespace convray::app
