// POV-Ray's functions of objects: min_extent(OBJECT) and max_extent(OBJECT), the corners of
// its bounding box, and trace(OBJECT, A, B [, NORMAL]), the first point where the ray from A
// along B meets it (<0, 0, 0> when none), NORMAL set to the surface normal there (or
// <0, 0, 0>). The geometry answers through ParseOptions::object_queries.
#include "scene/object.hpp"
#include "sdl/items.hpp"
#include "sdl/object_queries.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {

namespace {

Value vector_value(const Vec3& v) {
  Vector vector;
  vector.v = {v.x, v.y, v.z, 0.0, 0.0};
  return make_value(vector);
}

}  // namespace

Value Parser::Impl::call_object_function(const LexToken& name, TokenRef at) {
  const std::string function(name.view());
  if (!options.object_queries) {
    fail_unsupported(loc(at), "'" + function + "' is not supported yet by convray");
  }
  advance();
  expect_symbol('(', "after '" + function + "'");
  ScopedValue not_in_vector(angle_depth, 0);
  const TokenRef object_at = ref();
  const Value value = parse_expression();
  const auto* object = value.get<scene::ObjectPtr>();
  if (object == nullptr || *object == nullptr) {
    fail(object_at,
         "expected an object as the argument of '" + function + "', found " + type_name(value));
  }
  if (const scene::UnsupportedObject* unsupported = find_unsupported(**object)) {
    fail(object_at, "'" + unsupported->kind + "' objects are not supported yet by convray: " +
                        function + " uses the one declared at " + unsupported->declared_at.str());
  }
  const ObjectQueries& queries = *options.object_queries;
  if (function != "trace") {
    expect_symbol(')', "after the argument of '" + function + "'");
    const Box3 box = queries.bounds(**object);
    return vector_value(function == "min_extent" ? box.lo : box.hi);
  }
  expect_symbol(',', "after the object of 'trace'");
  const Vec3 origin = to_vector(parse_expression(), object_at, "trace's start").xyz();
  expect_symbol(',', "after the start of 'trace'");
  const TokenRef direction_at = ref();
  const Vec3 direction = to_vector(parse_expression(), direction_at, "trace's direction").xyz();
  std::optional<Alias> normal_target;
  if (accept_symbol(',')) {
    const TokenRef normal_at = ref();
    normal_target = parse_reference_argument();
    if (!normal_target) fail(normal_at, "trace's fourth argument must name a declared variable");
  }
  expect_symbol(')', "after the arguments of 'trace'");
  std::optional<TraceHit> hit;
  if (glm::length(direction) > 0.0) hit = queries.trace(**object, origin, direction);
  if (normal_target) {
    store_through(*normal_target, vector_value(hit ? hit->normal : Vec3(0.0)), direction_at);
  }
  return vector_value(hit ? hit->point : Vec3(0.0));
}

}  // namespace convray::sdl
