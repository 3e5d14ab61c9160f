#pragma once
// The objects of a scene as plain records: one Object node per shape or CSG operation, each
// with its placement, texture, interior and flags, and the place in the scene file that made
// it (for messages). Shapes are in their own space; `transform` places them. geometry/ turns
// these records into traceable shapes.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/convolution_object.hpp"
#include "scene/function.hpp"
#include "scene/texture.hpp"
#include "scene/transform.hpp"
#include "util/element_count.hpp"
#include "util/error.hpp"
#include "util/math.hpp"

namespace convray::scene {

struct Object;
using ObjectPtr = std::shared_ptr<const Object>;

struct Sphere {
  Vec3 center{0.0};
  double radius = 1.0;
};
struct Box {
  Vec3 corner1{-1.0}, corner2{1.0};  // any two opposite corners
};
// POV-Ray's plane: the points p with dot(p, normal / |normal|) < distance are inside.
struct Plane {
  Vec3 normal{0.0, 1.0, 0.0};
  double distance = 0.0;
};
struct Cylinder {
  Vec3 base{0.0}, cap{0.0, 1.0, 0.0};
  double radius = 1.0;
  bool open = false;  // no end caps (and then no inside)
};
struct Cone {
  Vec3 base{0.0};
  double base_radius = 1.0;
  Vec3 cap{0.0, 1.0, 0.0};
  double cap_radius = 0.0;
  bool open = false;
};
// About the y axis, in the plane y = 0.
struct Torus {
  double major = 1.0, minor = 0.25;
};
struct Disc {
  Vec3 center{0.0}, normal{0.0, 1.0, 0.0};
  double radius = 1.0, hole_radius = 0.0;
};
// POV-Ray's `polygon`: sub-polygons (each closed, corners in order, the closing corner not
// repeated) in one plane; a point is inside when it is inside an odd number of them.
struct Polygon {
  std::vector<std::vector<Vec3>> outlines;
  Vec3 normal{0.0, 0.0, 1.0};  // the plane's, not necessarily unit
};
// POV-Ray's `sor` (geometry/sor.hpp): points <r, h>, the first and last setting slopes only.
struct Sor {
  std::vector<Vec2> points;
  bool open = false;
};
// POV-Ray's `height_field` (geometry/height_field.hpp): heights in [0, 1] on a grid of
// columns x rows vertices over the unit square of the x-z plane, row 0 at z = 0.
struct HeightField {
  int columns = 0, rows = 0;
  std::vector<double> heights;  // row-major
  bool smooth = false;          // normals interpolated from the vertices'
  double water_level = 0.0;     // the surface below this height is not drawn
};
// `triangle` and `smooth_triangle` (normals given), and the faces of `mesh` and `mesh2`.
struct MeshFace {
  std::array<int, 3> vertices{0, 0, 0};
  std::array<int, 3> normals{-1, -1, -1};  // -1: flat face
  int texture = -1;                        // index into TriangleMesh::textures; -1: object's
};
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;
  std::vector<MeshFace> faces;
  std::vector<TexturePtr> textures;
  // `inside_vector`: a mesh with one is a solid (inside by ray parity along it).
  std::optional<Vec3> inside_vector;
  // The mesh's vertices, normals, textures and faces in the scene parser's element budget
  // (docs/limits.md): each copy of the mesh counts them again, as it takes their memory again.
  ElementCount counted;
};

// POV-Ray's `poly`, `cubic`, `quartic` and `quadric`: the surface where the polynomial
// sum c x^i y^j z^k (i + j + k <= order) is zero, inside where it is negative. The terms are
// in POV-Ray's order: x's exponent descending, then y's, then z's (quartic: x^4, x^3 y,
// x^3 z, x^3, x^2 y^2, x^2 y z, ..., z, 1): (order + 1)(order + 2)(order + 3) / 6 of them.
struct Polynomial {
  int order = 2;
  std::vector<double> coefficients;
};

// A texture given to one component of a blob or convolution object: `index` counts the
// components in the order the scene listed them (all kinds together).
struct ComponentTexture {
  size_t index = 0;
  TexturePtr texture;
};

// POV-Ray's `blob` and our `convolution`: both become the field of scene::ConvolutionObject
// (blob: blob_spheres / blob_cylinders; convolution: meshes, segments, arcs, points), with the
// components already in the object's own space (component transforms applied).
struct Implicit {
  scene::ConvolutionObject object;
  // For per-component textures: the order in which components were listed, as (kind, index in
  // that kind's vector of `object`).
  using Kind = scene::ComponentKind;
  std::vector<std::pair<Kind, size_t>> component_order;
  std::vector<ComponentTexture> component_textures;
  bool is_blob = false;  // written as `blob`: POV-Ray's inside rule F > T - 1e-6 applies
  // Where its `convolution` keyword was (empty for blobs and quick's object): `convray view`
  // finds the header of the object under the cursor by it (sdl/parse_log.hpp).
  SourceLoc header_loc = {};
};

// One piece of a glyph's outline: the quadratic Bezier curve from `a` to `c` with control
// point `b` (a straight piece has `b` halfway).
struct OutlinePiece {
  Vec2 a, b, c;
};

// POV-Ray's `text { ttf FONT STRING THICKNESS, OFFSET }`: the outlines of the glyphs, placed
// along +x in the font's em units (1 = one em), extruded from z = 0 to z = thickness. Every
// closed contour runs clockwise around what it encloses (TrueType's orientation; holes
// counter-clockwise); inside is where the contours wind around a point (nonzero rule).
struct Text {
  std::vector<std::vector<OutlinePiece>> glyphs;  // one entry per drawn glyph
  double thickness = 1.0;
};

// POV-Ray's `superellipsoid { <e, n> }` in the box [-1, 1]^3 (geometry/superellipsoid.hpp).
struct Superellipsoid {
  double e = 1.0, n = 1.0;
};

// POV-Ray's `isosurface`: inside where function(x, y, z) < threshold within the container (a
// box, or a sphere); the surface is function = threshold (geometry/isosurface.hpp).
struct Isosurface {
  std::shared_ptr<const Function> function;
  double threshold = 0.0;
  double max_gradient = 1.1;  // POV-Ray's defaults
  double accuracy = 0.001;
  bool open = false;          // the container's surface is not drawn
  bool sphere_container = false;
  Vec3 box_lo{-1.0}, box_hi{1.0};  // the default container, box { -1, 1 }
  Vec3 center{0.0};
  double radius = 1.0;
};

// One piece of a spline: the polynomial point(s) = c[0] + c[1] s + c[2] s^2 + c[3] s^3 for
// s in [0, 1] (linear and quadratic pieces have zero high coefficients).
struct SplinePiece {
  std::array<Vec2, 4> c{};
};

// POV-Ray's `lathe`: the curve of the pieces' (r, y) points turned about the y axis;
// inside where a point's (sqrt(x^2 + z^2), y) is enclosed an odd number of times.
struct Lathe {
  std::vector<SplinePiece> pieces;
};

// POV-Ray's `prism`: closed outlines of spline pieces in the xz plane (outline point (x, z)),
// inside where an odd number of them enclose a point. linear_sweep: extruded along y from
// height1 to height2 (height1 <= height2); conic_sweep: the outline scaled by y between
// those heights, so that the sides run towards the origin.
struct Prism {
  std::vector<std::vector<SplinePiece>> polygons;  // each closed
  double height1 = 0.0, height2 = 1.0;
  bool conic = false;
};

enum class CsgOperation { union_, intersection, difference, merge };
struct Light;  // scene.hpp

struct Csg {
  CsgOperation operation = CsgOperation::union_;
  std::vector<ObjectPtr> children;  // in order; difference: first minus the rest
  // light_sources written among the members, in the CSG's own space: POV-Ray places them
  // with the CSG (the parser adds them to the scene's lights where the object is placed).
  std::vector<std::shared_ptr<const Light>> lights = {};
};

using Shape = std::variant<Sphere, Box, Plane, Cylinder, Cone, Torus, Disc, TriangleMesh,
                           Implicit, Csg, Polynomial, Text, Prism, Superellipsoid,
                           Lathe, Polygon, HeightField, Sor, Isosurface>;

// A POV-Ray object convray cannot draw yet (`sor`, `text`, ...) that a scene declared: an
// empty stand-in, so that include files declaring such objects still work; placing it in the
// scene (itself, or inside CSG) is an error that names it.
struct UnsupportedObject {
  std::string kind;  // the POV-Ray keyword
  SourceLoc declared_at;
};

struct Object {
  Shape shape;
  std::optional<UnsupportedObject> unsupported;
  Transform transform;      // own space -> world (or parent CSG space)
  TexturePtr texture;       // null: inherited from the CSG parent, else the default texture
  // interior_texture: what the inside of the surface wears (null: the parent's, else the
  // texture); rays that meet the surface from within the solid see it.
  TexturePtr interior_texture;
  std::optional<Interior> interior;
  bool inverse = false;     // inside and outside swapped
  bool no_shadow = false;   // casts no shadow
  bool no_image = false;       // not seen by camera rays (nor through what they pass)
  bool no_reflection = false;  // not seen in reflections
  bool double_illuminate = false;  // lit on both sides: lights behind the surface light it too
  bool hollow = false;
  // union only: POV-Ray's split_union (on by default) puts the members into the scene's
  // hierarchy; off keeps the union one object (with a hierarchy of its own inside).
  bool split_union = true;
  // A placement of a declared union shared as it is (`object { U translate ... }`,
  // scene/instance.hpp): a union whose only child is the declared record, `transform` the
  // placement's transforms and nothing else set (but the default texture of a top-level
  // object, in the space it is placed in). Unlike every other record, the textures inside
  // are in this object's own space, not moved by `transform`.
  bool instance = false;
  // clipped_by and bounded_by objects are in the object's own space, like a CSG's children:
  // `transform` places them with the object.
  std::vector<ObjectPtr> clipped_by;  // keep only the parts inside all of these
  ObjectPtr bounded_by;               // a bound the renderer may use; never changes the image
  SourceLoc loc;            // where the scene declared it
};

}  // namespace convray::scene
