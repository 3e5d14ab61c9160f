#pragma once
// What a convolution object is made of, as plain records: skeleton primitives, each with its
// own strength and support radius, summed into one field F and its surface F = T. Negative
// strengths subtract. This is the description a scene (or `convray quick`) fills in; the
// traceable, queryable form is implicit::Surface (implicit/surface.hpp, implicit::make_surface).
#include <memory>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

#include "field/arc.hpp"
#include "field/kernel.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "util/math.hpp"

namespace convray::scene {

// The kinds of component, in the order scene::Implicit lists them.
enum class ComponentKind { mesh, segment, arc, point, blob_sphere, blob_cylinder };
// One component of a ConvolutionObject: its kind and its index in that kind's vector.
struct ComponentRef {
  ComponentKind kind = ComponentKind::point;
  uint32_t index = 0;
  bool operator==(const ComponentRef&) const = default;
};

struct Weight {
  double strength = 1.0;
  double radius = 1.0;  // support radius R of the kernel (1 - r^2/R^2)^2
};

// Where a mesh component's triangles came from: a file's triangles as loaded, shared by every
// component (and every animation frame) that places the same file, and the placement. It lets
// an implicit::SupportCache recognise a mesh it has prepared before (implicit/support_cache.hpp).
struct MeshSource {
  std::shared_ptr<const std::vector<field::Triangle>> local;  // the file's triangles
  Mat4 placement{1.0};  // local -> object space: triangles[i] = placement(local[i])
};

struct MeshComponent {
  // In object space; what every reader of the component uses (fields, bounds, textures).
  std::vector<field::Triangle> triangles;  // one weight for the whole mesh (keeps it small)
  Weight weight;
  std::optional<MeshSource> source = std::nullopt;  // absent for inline triangles
};
struct SegmentComponent {
  field::Segment segment;
  Weight weight;
};
struct ArcComponent {
  field::Arc arc;
  Weight weight;
};
struct PointComponent {
  Vec3 center{0.0};
  Weight weight;
};
// POV-Ray blob components: distance kernels s (1 - d^2/r^2)^2, not integrals (field/blob.hpp).
struct BlobSphereComponent {
  Vec3 center{0.0};
  Weight weight;
};
struct BlobCylinderComponent {
  Vec3 base{0.0}, apex{0.0};
  Weight weight;
};

struct ConvolutionObject {
  std::vector<MeshComponent> meshes;
  std::vector<SegmentComponent> segments;
  std::vector<ArcComponent> arcs;
  std::vector<PointComponent> points;
  std::vector<BlobSphereComponent> blob_spheres;
  std::vector<BlobCylinderComponent> blob_cylinders;
  double threshold = 1.0;  // the surface is F = T; inside is F >= T
  field::Kernel kernel;  // the quartic or the Cauchy kernel
};

}  // namespace convray::scene
