#include "scene/instance.hpp"

#include <unordered_set>

#include "scene/moved_textures.hpp"

namespace convray::scene {

bool can_instance(const Object& declared) {
  if (declared.instance) return true;
  const auto* csg = std::get_if<Csg>(&declared.shape);
  return csg && csg->operation == CsgOperation::union_ && declared.split_union &&
         !declared.inverse && declared.clipped_by.empty() && !declared.bounded_by &&
         !declared.unsupported;
}

Object instance_of(const ObjectPtr& declared, const Transform& placement, const SourceLoc& loc) {
  Object instance;
  instance.shape = Csg{CsgOperation::union_, {declared}};
  instance.transform = placement;
  instance.instance = true;
  instance.loc = loc;
  return instance;
}

Object flattened(const Object& instance) {
  const ObjectPtr& declared = std::get<Csg>(instance.shape).children.front();
  Object copy = declared->instance ? flattened(*declared) : *declared;
  const Transform& placement = instance.transform;
  copy.transform = copy.transform.then(placement);
  // The instance's own texture (the default texture given to a top-level object) is already
  // where it is placed: it covers the members without one, as it would the copy.
  copy.texture = copy.texture ? moved_texture(copy.texture, placement) : instance.texture;
  copy.interior_texture = copy.interior_texture
                              ? moved_texture(copy.interior_texture, placement)
                              : instance.interior_texture;
  move_inner_textures(copy, placement);
  copy.loc = instance.loc;
  return copy;
}

const ObjectPtr& shared_union(const Object& instance, Transform& placement) {
  const ObjectPtr& declared = std::get<Csg>(instance.shape).children.front();
  if (!declared->instance) {
    placement = instance.transform;
    return declared;
  }
  const ObjectPtr& inner = shared_union(*declared, placement);
  placement = placement.then(instance.transform);
  return inner;
}

namespace {

void collect_records(const ObjectPtr& object, std::unordered_set<const Object*>& seen) {
  if (!object || !seen.insert(object.get()).second) return;
  if (const auto* csg = std::get_if<Csg>(&object->shape)) {
    for (const ObjectPtr& child : csg->children) collect_records(child, seen);
  }
  for (const ObjectPtr& clip : object->clipped_by) collect_records(clip, seen);
  collect_records(object->bounded_by, seen);
}

}  // namespace

size_t distinct_records(const std::vector<ObjectPtr>& objects) {
  std::unordered_set<const Object*> seen;
  for (const ObjectPtr& object : objects) collect_records(object, seen);
  return seen.size();
}

}  // namespace convray::scene
