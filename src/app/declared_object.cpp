#include "app/declared_object.hpp"

#include <variant>

#include "util/error.hpp"

namespace convray::app {

const scene::Object& declared_implicit(const sdl::ParseResult& parsed,
                                       const std::string& scene_path, const std::string& name) {
  const auto found = parsed.globals.find(name);
  if (found == parsed.globals.end()) {
    throw InputError(SourceLoc{scene_path},
                     "no identifier '" + name + "' is declared in the scene");
  }
  const scene::ObjectPtr* object = found->second.get<scene::ObjectPtr>();
  if (!object || !std::holds_alternative<scene::Implicit>((*object)->shape)) {
    throw InputError(found->second.loc, "'" + name + "' is " + sdl::type_name(found->second) +
                                            ", not a convolution object or blob");
  }
  return **object;
}

}  // namespace convray::app
