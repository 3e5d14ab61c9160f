#pragma once
// A declared union placed many times (`#declare U = union { ... }  object { U translate ... }`
// in a loop) is shared, not copied: each placement is an instance record that holds the
// declared record and the placement's transforms. Copying would move every textured member's
// texture by the placement (textures are evaluated where they are placed: scene/texture.hpp),
// which costs time and memory in proportion to placements times members; an instance leaves
// the textures in the union's own space, and geometry/ evaluates them at hit points carried
// back into that space (geometry/instance.hpp).
//
// Only placements that add nothing but transforms are instances: a texture, interior or flag
// given to the placement changes what the members inherit, so such a placement is the copy
// (flattened) before that modifier applies.
#include "scene/object.hpp"

namespace convray::scene {

// Whether `object { declared ... }` with transforms only may share `declared`: a union that
// POV-Ray would split into the scene's hierarchy (split_union, no inverse, no clipped_by or
// bounded_by), or an instance of one.
bool can_instance(const Object& declared);

// The placement of `declared` (can_instance) by `placement`; an instance of an instance holds
// the inner one (the transforms compose when it is traced).
Object instance_of(const ObjectPtr& declared, const Transform& placement, const SourceLoc& loc);

// The copy that the instance stands for, as the parser made it before instances: the declared
// union (flattened itself when it is an instance) with the placement appended to its transform
// and every texture in it moved by the placement. Costs what copying costs; for the places
// that need the members one by one (a placement inside CSG, or under a texture it inherits).
Object flattened(const Object& instance);

// The declared union an instance shares (through instances of instances), and the transform
// from that union's parent space to the instance's parent space.
const ObjectPtr& shared_union(const Object& instance, Transform& placement);

// How many object records the scene's objects hold, each shared record counted once (a
// declared union placed 1000 times counts its members once): what instances save.
size_t distinct_records(const std::vector<ObjectPtr>& objects);

}  // namespace convray::scene
