// From scene records to traceable shapes: each object's primitive in its own space, wrapped
// by its modifiers (inverse, clipped_by, bounded_by) and placed by its transform, with the
// textures and interiors POV-Ray's inheritance rules give it.
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/box.hpp"
#include "geometry/conic_prism.hpp"
#include "geometry/cone.hpp"
#include "geometry/csg.hpp"
#include "geometry/disc.hpp"
#include "geometry/height_field.hpp"
#include "geometry/polygon.hpp"
#include "geometry/sor.hpp"
#include "geometry/implicit_shape.hpp"
#include "geometry/instance.hpp"
#include "geometry/isosurface.hpp"
#include "geometry/lathe.hpp"
#include "geometry/modifiers.hpp"
#include "geometry/plane.hpp"
#include "geometry/polynomial_surface.hpp"
#include "geometry/sphere.hpp"
#include "geometry/superellipsoid.hpp"
#include "geometry/extruded_outline.hpp"
#include "geometry/torus.hpp"
#include "geometry/transformed.hpp"
#include "geometry/triangle_mesh.hpp"
#include "geometry/world.hpp"
#include "scene/instance.hpp"
#include "scene/moved_textures.hpp"

namespace convray::geometry {
namespace {

// What a CSG parent hands down: a child without a texture (interior) takes its parent's;
// no_shadow, no_image, no_reflection and double_illuminate on a parent cover its children.
struct Inherited {
  scene::TexturePtr texture;
  scene::TexturePtr interior_texture;
  std::optional<scene::Interior> interior;
  bool no_shadow = false;
  bool no_image = false;
  bool no_reflection = false;
  bool double_illuminate = false;
  bool hollow = false;
};

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(double x) { return std::isfinite(x); }

// Throws the message as an error of the scene when `ok` is false.
void require(bool ok, const char* message) {
  if (!ok) throw std::invalid_argument(message);
}

class ShapeBuilder {
 public:
  // `shared` (optional) keeps the shared unions of instances for the whole World.
  ShapeBuilder(implicit::SupportCache* cache, implicit::Tracer tracer,
               SharedUnions* shared = nullptr)
      : cache_(cache), tracer_(tracer), shared_(shared) {}
  // `placement` follows the object's own transform (a split union's, when it is a member).
  ShapePtr build(const scene::Object& object, const Inherited& parent,
                 const scene::Transform& placement = {});
  // The object's shapes for the scene's hierarchy: a union that may be split gives its
  // members (recursively), each placed and textured as inside the union; anything else one.
  void split(const scene::Object& object, const Inherited& parent,
             const scene::Transform& placement, std::vector<ShapePtr>& out);

 private:
  ShapePtr build_primitive(const scene::Object& object, const Inherited& own);
  ShapePtr instance_shape(const scene::Object& instance, const Inherited& parent,
                          const scene::Transform& placement);
  std::shared_ptr<const Shape> shared_union(const scene::ObjectPtr& declared,
                                            const Inherited& own);
  SurfaceInfoPtr surface_for(const Inherited& own) const;

  ShapePtr make(const scene::Sphere& s, const Inherited& own) const;
  ShapePtr make(const scene::Box& b, const Inherited& own) const;
  ShapePtr make(const scene::Plane& p, const Inherited& own) const;
  ShapePtr make(const scene::Cylinder& c, const Inherited& own) const;
  ShapePtr make(const scene::Cone& c, const Inherited& own) const;
  ShapePtr make(const scene::Torus& t, const Inherited& own) const;
  ShapePtr make(const scene::Polynomial& p, const Inherited& own) const;
  ShapePtr make(const scene::Text& t, const Inherited& own) const;
  ShapePtr make(const scene::Prism& p, const Inherited& own) const;
  ShapePtr make(const scene::Superellipsoid& s, const Inherited& own) const {
    return std::make_unique<SuperellipsoidShape>(s.e, s.n, surface_for(own));
  }
  ShapePtr make(const scene::Lathe& l, const Inherited& own) const {
    return std::make_unique<LatheShape>(l.pieces, surface_for(own));
  }
  ShapePtr make(const scene::Isosurface& i, const Inherited& own) const {
    return std::make_unique<IsosurfaceShape>(i, surface_for(own));
  }
  ShapePtr make(const scene::Disc& d, const Inherited& own) const;
  ShapePtr make(const scene::HeightField& h, const Inherited& own) const {
    return std::make_unique<HeightFieldShape>(h, surface_for(own));
  }
  ShapePtr make(const scene::Sor& s, const Inherited& own) const {
    return std::make_unique<SorShape>(s.points, s.open, surface_for(own));
  }
  ShapePtr make(const scene::Polygon& p, const Inherited& own) const {
    return std::make_unique<PolygonShape>(p.outlines, p.normal, surface_for(own));
  }
  ShapePtr make(const scene::TriangleMesh& m, const Inherited& own) const;
  ShapePtr make(const scene::Implicit& i, const Inherited& own) const;
  ShapePtr make(const scene::Csg& c, const Inherited& own);

  // POV-Ray's default texture (black pigment), shared by every object without one.
  scene::TexturePtr default_texture_ =
      std::make_shared<const scene::Texture>(scene::default_texture());
  implicit::SupportCache* cache_;  // for convolution objects' meshes; may be null
  implicit::Tracer tracer_;        // how quartic-kernel convolution surfaces are traced
  SharedUnions* shared_;           // null: instances are flattened (copied)
  // The last surface made: the members of a union mostly share one (memory for 10^6 members).
  mutable SurfaceInfoPtr last_surface_;
};

// Inherited state after `object`: its own texture and interior, else its parent's.
Inherited inherit(const scene::Object& object, const Inherited& parent) {
  Inherited own;
  own.texture = object.texture ? object.texture : parent.texture;
  own.interior_texture = object.interior_texture ? object.interior_texture : parent.interior_texture;
  own.interior = object.interior ? object.interior : parent.interior;
  own.no_shadow = object.no_shadow || parent.no_shadow;
  own.no_image = object.no_image || parent.no_image;
  own.no_reflection = object.no_reflection || parent.no_reflection;
  own.double_illuminate = object.double_illuminate || parent.double_illuminate;
  own.hollow = object.hollow || parent.hollow;
  return own;
}

SurfaceInfoPtr ShapeBuilder::surface_for(const Inherited& own) const {
  const scene::TexturePtr& texture = own.texture ? own.texture : default_texture_;
  const scene::Interior interior = own.interior.value_or(scene::Interior{});
  if (last_surface_ && last_surface_->texture == texture &&
      last_surface_->interior_texture == own.interior_texture &&
      last_surface_->interior == interior && last_surface_->no_shadow == own.no_shadow &&
      last_surface_->no_image == own.no_image && last_surface_->no_reflection == own.no_reflection &&
      last_surface_->double_illuminate == own.double_illuminate &&
      last_surface_->hollow == own.hollow) {
    return last_surface_;
  }
  auto info = std::make_shared<SurfaceInfo>();
  info->texture = texture;
  info->interior_texture = own.interior_texture;
  info->interior = interior;
  info->no_shadow = own.no_shadow;
  info->no_image = own.no_image;
  info->no_reflection = own.no_reflection;
  info->double_illuminate = own.double_illuminate;
  info->hollow = own.hollow;
  last_surface_ = info;
  return info;
}

ShapePtr ShapeBuilder::make(const scene::Sphere& s, const Inherited& own) const {
  require(finite(s.center) && finite(s.radius), "sphere: centre and radius must be finite");
  require(s.radius != 0.0, "sphere: the radius must not be zero");
  // POV-Ray squares the radius, so a negative one draws the same sphere.
  return std::make_unique<SphereShape>(s.center, std::abs(s.radius), surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Box& b, const Inherited& own) const {
  require(finite(b.corner1) && finite(b.corner2), "box: the corners must be finite");
  return std::make_unique<BoxShape>(b.corner1, b.corner2, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Plane& p, const Inherited& own) const {
  require(finite(p.normal) && finite(p.distance), "plane: normal and distance must be finite");
  require(glm::length(p.normal) > 0.0, "plane: the normal must not be zero");
  return std::make_unique<PlaneShape>(p.normal, p.distance, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Cylinder& c, const Inherited& own) const {
  require(finite(c.base) && finite(c.cap) && finite(c.radius),
          "cylinder: end points and radius must be finite");
  require(glm::length(c.cap - c.base) > 0.0, "cylinder: the end points must differ");
  require(c.radius > 0.0, "cylinder: the radius must be positive");
  return std::make_unique<ConeShape>(c.base, c.radius, c.cap, c.radius, c.open, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Cone& c, const Inherited& own) const {
  require(finite(c.base) && finite(c.cap) && finite(c.base_radius) && finite(c.cap_radius),
          "cone: end points and radii must be finite");
  require(glm::length(c.cap - c.base) > 0.0, "cone: the end points must differ");
  require(c.base_radius >= 0.0 && c.cap_radius >= 0.0, "cone: the radii must not be negative");
  require(c.base_radius > 0.0 || c.cap_radius > 0.0, "cone: the radii must not both be zero");
  return std::make_unique<ConeShape>(c.base, c.base_radius, c.cap, c.cap_radius, c.open,
                                     surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Torus& t, const Inherited& own) const {
  require(finite(t.major) && finite(t.minor), "torus: the radii must be finite");
  require(t.major > 0.0 && t.minor > 0.0, "torus: the radii must be positive");
  return std::make_unique<TorusShape>(t.major, t.minor, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Polynomial& p, const Inherited& own) const {
  require(p.order >= 1 && p.order <= kMaxPolynomialDegree, "poly: the order must be 1 to 8");
  for (double c : p.coefficients) require(std::isfinite(c), "poly: coefficients must be finite");
  return std::make_unique<PolynomialSurface>(p.order, p.coefficients, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Text& t, const Inherited& own) const {
  require(std::isfinite(t.thickness), "text: the thickness must be finite");
  for (const auto& glyph : t.glyphs) {
    for (const scene::OutlinePiece& piece : glyph) {
      require(std::isfinite(piece.a.x + piece.a.y + piece.b.x + piece.b.y + piece.c.x + piece.c.y),
              "text: the glyphs' outlines must be finite (is the offset?)");
    }
  }
  return std::make_unique<ExtrudedOutlineShape>(t.glyphs, ExtrusionAxes{0, 1, 2, 0.0, t.thickness},
                                                surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Prism& p, const Inherited& own) const {
  require(std::isfinite(p.height1) && std::isfinite(p.height2),
          "prism: the heights must be finite");
  for (const auto& polygon : p.polygons) {
    for (const scene::SplinePiece& piece : polygon) {
      for (const Vec2& c : piece.c) {
        require(std::isfinite(c.x + c.y), "prism: the points must be finite");
      }
    }
  }
  if (p.conic) {
    return std::make_unique<ConicPrismShape>(p.polygons, p.height1, p.height2, surface_for(own));
  }
  // Outline (x, z), extruded along y.
  std::vector<scene::SplinePiece> pieces;
  for (const auto& polygon : p.polygons) pieces.insert(pieces.end(), polygon.begin(), polygon.end());
  return std::make_unique<ExtrudedOutlineShape>(
      std::vector<std::vector<scene::SplinePiece>>{pieces},
      ExtrusionAxes{0, 2, 1, p.height1, p.height2, true}, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::Disc& d, const Inherited& own) const {
  require(finite(d.center) && finite(d.normal) && finite(d.radius) && finite(d.hole_radius),
          "disc: centre, normal and radii must be finite");
  require(glm::length(d.normal) > 0.0, "disc: the normal must not be zero");
  require(d.radius > 0.0, "disc: the radius must be positive");
  require(d.hole_radius >= 0.0 && d.hole_radius < d.radius,
          "disc: the hole radius must be at least 0 and less than the radius");
  return std::make_unique<DiscShape>(d.center, d.normal, d.radius, d.hole_radius, surface_for(own));
}

ShapePtr ShapeBuilder::make(const scene::TriangleMesh& m, const Inherited& own) const {
  // The object's surface first, then one per texture of the mesh (with the object's interior).
  std::vector<SurfaceInfoPtr> surfaces{surface_for(own)};
  for (const scene::TexturePtr& texture : m.textures) {
    Inherited face = own;
    if (texture) face.texture = texture;
    surfaces.push_back(surface_for(face));
  }
  for (const Vec3& v : m.vertices) require(finite(v), "mesh: vertices must be finite");
  return std::make_unique<TriangleMeshShape>(m, std::move(surfaces));
}

ShapePtr ShapeBuilder::make(const scene::Implicit& i, const Inherited& own) const {
  return std::make_unique<ImplicitShape>(i, surface_for(own), cache_, tracer_);
}

ShapePtr ShapeBuilder::make(const scene::Csg& c, const Inherited& own) {
  std::vector<ShapePtr> children;
  for (const scene::ObjectPtr& child : c.children) {
    if (child) children.push_back(build(*child, own));
  }
  return std::make_unique<CsgShape>(c.operation, std::move(children));
}

ShapePtr ShapeBuilder::build_primitive(const scene::Object& object, const Inherited& own) {
  try {
    return std::visit([&](const auto& record) { return make(record, own); }, object.shape);
  } catch (const std::invalid_argument& e) {
    throw InputError(object.loc, e.what());
  }
}

// POV-Ray's split_union: a union's members go into the scene's hierarchy as if each stood
// alone, unless the union says `split_union off` or its inside is used as a whole (inverse,
// clipped_by) or a bounded_by asks for it to be one object. Every crossing of a union is a
// crossing of a member, so nothing seen changes; only the hierarchy gets the members' boxes.
bool splits(const scene::Object& object) {
  const auto* csg = std::get_if<scene::Csg>(&object.shape);
  return csg && csg->operation == scene::CsgOperation::union_ && object.split_union &&
         !object.inverse && object.clipped_by.empty() && !object.bounded_by &&
         !object.unsupported;
}

void ShapeBuilder::split(const scene::Object& object, const Inherited& parent,
                         const scene::Transform& placement, std::vector<ShapePtr>& out) {
  if (object.instance) {
    if (ShapePtr shape = instance_shape(object, parent, placement)) {
      out.push_back(std::move(shape));
    } else {
      split(scene::flattened(object), parent, placement, out);
    }
    return;
  }
  if (!splits(object)) {
    out.push_back(build(object, parent, placement));
    return;
  }
  const Inherited own = inherit(object, parent);
  const scene::Transform members_placement = object.transform.then(placement);
  for (const scene::ObjectPtr& child : std::get<scene::Csg>(object.shape).children) {
    if (child) split(*child, own, members_placement, out);
  }
}

bool depends_on_position(const scene::TexturePtr& texture) {
  return texture && scene::depends_on_position(*texture);
}

// Whether every surface in `object` wears a texture of its own or of a CSG parent inside it:
// then no texture it inherits from outside shows.
bool wears_own_textures(const scene::Object& object) {
  if (object.texture) return true;
  const auto* csg = std::get_if<scene::Csg>(&object.shape);
  if (!csg) return false;
  for (const scene::ObjectPtr& child : csg->children) {
    if (child && !wears_own_textures(*child)) return false;
  }
  return true;
}

InheritedState state_of(const Inherited& own) {
  const unsigned flags = (own.no_shadow ? 1u : 0u) | (own.no_image ? 2u : 0u) |
                         (own.no_reflection ? 4u : 0u) | (own.double_illuminate ? 8u : 0u) |
                         (own.hollow ? 16u : 0u);
  return {own.texture, own.interior_texture, own.interior, flags};
}

// A placement of a shared union in the scene's hierarchy: one shape over the union's members,
// built once. Null where the placement must be the copy instead: when no World keeps shared
// unions (a lone object's shape, or inside a shared union being built: crossings name one
// placement, not a chain of them), or when some member would wear an inherited texture that
// depends on where it is (a patterned texture from outside is in the world's space, not the
// union's).
ShapePtr ShapeBuilder::instance_shape(const scene::Object& instance, const Inherited& parent,
                                      const scene::Transform& placement) {
  if (!shared_) return nullptr;
  scene::Transform to_parent;
  const scene::ObjectPtr& declared = scene::shared_union(instance, to_parent);
  Inherited own = inherit(instance, parent);
  if (wears_own_textures(*declared)) own.texture = nullptr;  // nothing wears it
  if (depends_on_position(own.texture) || depends_on_position(own.interior_texture)) {
    return nullptr;
  }
  std::shared_ptr<const Shape> shared = shared_union(declared, own);
  if (!shared) return nullptr;  // an empty union: the copy adds nothing either
  return std::make_unique<TransformedShape>(std::move(shared), to_parent.then(placement),
                                            /*places_shared=*/true);
}

std::shared_ptr<const Shape> ShapeBuilder::shared_union(const scene::ObjectPtr& declared,
                                                        const Inherited& own) {
  const InheritedState state = state_of(own);
  if (const SharedUnion* built = shared_->find(declared, state)) return built->shape;
  SharedUnions* const shared = std::exchange(shared_, nullptr);  // no instances inside
  std::vector<ShapePtr> members;
  split(*declared, own, scene::Transform{}, members);
  shared_ = shared;
  if (members.empty()) return nullptr;
  const size_t count = members.size();
  std::shared_ptr<const Shape> shape =
      count == 1 ? std::shared_ptr<const Shape>(std::move(members.front()))
                 : std::make_shared<const CsgShape>(scene::CsgOperation::union_,
                                                    std::move(members));
  return shared_->add(declared, state, SharedUnion{std::move(shape), count});
}

// A sphere under a similarity (translations, rotations, uniform scales) is a sphere: placed
// directly, it costs a ray what a sphere written in place costs, as in POV-Ray (unions of
// spheres moved by the union's `translate` are the usual case). Only without clipped_by and
// bounded_by, which live in the sphere's own space.
std::optional<scene::Sphere> sphere_in_place(const scene::Object& object,
                                             const scene::Transform& transform) {
  const auto* sphere = std::get_if<scene::Sphere>(&object.shape);
  if (!sphere || !object.clipped_by.empty() || object.bounded_by || transform.is_identity() ||
      !transform.is_similarity()) {
    return std::nullopt;
  }
  return scene::Sphere{transform.point(sphere->center), sphere->radius * transform.uniform_scale()};
}

ShapePtr ShapeBuilder::build(const scene::Object& object, const Inherited& parent,
                             const scene::Transform& placement) {
  // As one object (a CSG's member, a clipping object, a lone object's shape): the copy.
  if (object.instance) return build(scene::flattened(object), parent, placement);
  const Inherited own = inherit(object, parent);
  const scene::Transform transform =
      placement.is_identity() ? object.transform : object.transform.then(placement);
  if (!transform.is_identity()) {
    const double det = glm::determinant(glm::dmat3(transform.forward()));
    const double inverse_det = glm::determinant(glm::dmat3(transform.backward()));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det) || !std::isfinite(inverse_det)) {
      throw InputError(object.loc, "the object's transform is singular (a scale by zero?)");
    }
  }
  if (const auto sphere = sphere_in_place(object, transform)) {
    scene::Object placed = object;
    placed.shape = *sphere;
    ShapePtr shape = build_primitive(placed, own);
    if (object.inverse) shape = std::make_unique<InvertedShape>(std::move(shape));
    return shape;
  }
  ShapePtr shape = build_primitive(object, own);
  if (object.inverse) shape = std::make_unique<InvertedShape>(std::move(shape));
  // Clipping and bounding objects live in the object's own space and move with it.
  if (!object.clipped_by.empty()) {
    std::vector<ShapePtr> clips;
    for (const scene::ObjectPtr& clip : object.clipped_by) {
      if (clip) clips.push_back(build(*clip, own));
    }
    shape = std::make_unique<ClippedShape>(std::move(shape), std::move(clips));
  }
  if (object.bounded_by) {
    const ShapePtr bound = build(*object.bounded_by, own);
    shape = std::make_unique<BoundedShape>(std::move(shape), *bound);
  }
  if (!transform.is_identity()) {
    shape = std::make_unique<TransformedShape>(std::move(shape), transform);
  }
  return shape;
}

}  // namespace

ShapePtr build_shape(const scene::Object& object, implicit::SupportCache* cache,
                     implicit::Tracer tracer) {
  ShapeBuilder builder(cache, tracer);
  return builder.build(object, Inherited{});
}

void build_split_shapes(const scene::Object& object, std::vector<ShapePtr>& out,
                        implicit::SupportCache* cache, implicit::Tracer tracer,
                        SharedUnions* shared) {
  ShapeBuilder builder(cache, tracer, shared);
  builder.split(object, Inherited{}, scene::Transform{}, out);
}

}  // namespace convray::geometry
