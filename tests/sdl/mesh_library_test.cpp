// Mesh files kept across parses (animation frames): the same file is read once and shared, a
// changed file is read again, and every convolution mesh knows its file's triangles and the
// placement that gives its own.
#include "sdl/mesh_library.hpp"

#include <filesystem>
#include <fstream>

#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

struct Folder {
  std::filesystem::path path;
  explicit Folder(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~Folder() { std::filesystem::remove_all(path); }
};

// One square (two triangles) of side `side` as OBJ.
void write_square(const std::filesystem::path& file, int side) {
  std::ofstream(file) << "v 0 0 0\nv " << side << " 0 0\nv " << side << " " << side << " 0\nv 0 "
                      << side << " 0\nf 1 2 3 4\n";
}

scene::MeshComponent first_mesh(const ParseResult& result) {
  return shape_of<scene::Implicit>(only_object(result)).object.meshes.at(0);
}

ParseOptions with_library(std::shared_ptr<MeshLibrary> library) {
  ParseOptions options;
  options.mesh_library = std::move(library);
  return options;
}

TEST(MeshLibrary, TwoParsesShareOneReadOfTheFile) {
  const Folder folder("convray_mesh_library_shared");
  write_square(folder.path / "square.obj", 1);
  const std::string scene =
      "convolution { mesh { \"square.obj\" rotate <0, 0, clock * 90> translate x } }\n";
  std::ofstream(folder.path / "scene.pov") << scene;
  auto library = std::make_shared<MeshLibrary>();
  ParseOptions options = with_library(library);
  const auto frame0 = parse_file((folder.path / "scene.pov").string(), options);
  options.clock = 0.5;
  const auto frame1 = parse_file((folder.path / "scene.pov").string(), options);
  const scene::MeshComponent a = first_mesh(frame0);
  const scene::MeshComponent b = first_mesh(frame1);
  ASSERT_TRUE(a.source && b.source);
  EXPECT_EQ(a.source->local.get(), b.source->local.get());
  EXPECT_EQ(library->reads(), 1u);
  EXPECT_NE(a.source->placement, b.source->placement);  // the clock turned it
  // Without a library every parse reads its own copy.
  const auto alone = parse_file((folder.path / "scene.pov").string(), ParseOptions{});
  ASSERT_TRUE(first_mesh(alone).source);
  EXPECT_NE(first_mesh(alone).source->local.get(), a.source->local.get());
}

TEST(MeshLibrary, AChangedFileIsReadAgain) {
  const Folder folder("convray_mesh_library_changed");
  const auto file = folder.path / "square.obj";
  write_square(file, 1);
  MeshLibrary library;
  const SharedSkeleton first = library.load(file.string());
  EXPECT_EQ(library.load(file.string()).get(), first.get());
  // Rewritten with another size and an older time stamp.
  write_square(file, 20);
  std::filesystem::last_write_time(file,
                                   std::filesystem::last_write_time(file) - std::chrono::hours(1));
  const SharedSkeleton second = library.load(file.string());
  EXPECT_NE(second.get(), first.get());
  EXPECT_EQ(library.reads(), 2u);
  EXPECT_EQ(library.size(), 1u);
  ASSERT_EQ(second->triangles.size(), 2u);
  double largest = 0.0;
  for (const field::Triangle& t : second->triangles) largest = std::max({largest, t.a.x, t.b.x, t.c.x});
  EXPECT_EQ(largest, 20.0);
  // Only the time stamp changed: read again too.
  std::filesystem::last_write_time(file,
                                   std::filesystem::last_write_time(file) + std::chrono::hours(2));
  EXPECT_NE(library.load(file.string()).get(), second.get());
  EXPECT_EQ(library.reads(), 3u);
}

TEST(MeshLibrary, ThePlacementOfTheFilesTrianglesGivesTheComponents) {
  const Folder folder("convray_mesh_library_placement");
  write_square(folder.path / "square.obj", 1);
  const std::string path = (folder.path / "square.obj").string();
  const auto result = parse("convolution { radius 0.5 mesh { \"" + path +
                            "\" scale 2 rotate <10, 20, 30> translate <1, -2, 3> } "
                            "triangle { <0,0,0>, <1,0,0>, <0,1,0> } }",
                            reading_from(folder.path.string()));
  const scene::ConvolutionObject object = shape_of<scene::Implicit>(only_object(result)).object;
  ASSERT_EQ(object.meshes.size(), 2u);
  const scene::MeshComponent& mesh = object.meshes[0];
  ASSERT_TRUE(mesh.source);
  const std::vector<field::Triangle>& local = *mesh.source->local;
  ASSERT_EQ(local.size(), mesh.triangles.size());
  for (size_t i = 0; i < local.size(); ++i) {
    const Mat4& m = mesh.source->placement;
    EXPECT_EQ(transform_point(m, local[i].a), mesh.triangles[i].a);
    EXPECT_EQ(transform_point(m, local[i].b), mesh.triangles[i].b);
    EXPECT_EQ(transform_point(m, local[i].c), mesh.triangles[i].c);
  }
  // The file's own coordinates: the unit square.
  for (const field::Triangle& t : local) {
    for (const Vec3& p : {t.a, t.b, t.c}) {
      EXPECT_TRUE(p.x == 0.0 || p.x == 1.0);
      EXPECT_EQ(p.z, 0.0);
    }
  }
  EXPECT_FALSE(object.meshes[1].source);  // inline triangles have no file
}

TEST(MeshLibrary, AFilesPointsAndSegmentsArePlacedComponentsOfTheMeshsWeight) {
  // A point cloud of two points and a polyline of two segments, in one OBJ (no faces).
  const Folder folder("convray_mesh_library_skeleton");
  std::ofstream(folder.path / "skeleton.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\np 1 3\n";
  const std::string path = (folder.path / "skeleton.obj").string();
  const auto result = parse("convolution { radius 0.5 threshold 0.3 mesh { \"" + path +
                            "\" strength 2 scale 2 translate <0, 0, 5> } }",
                            reading_from(folder.path.string()));
  const scene::Implicit& implicit = shape_of<scene::Implicit>(only_object(result));
  const scene::ConvolutionObject& object = implicit.object;
  EXPECT_TRUE(object.meshes.empty());  // no triangles: no mesh component
  ASSERT_EQ(object.segments.size(), 2u);
  ASSERT_EQ(object.points.size(), 2u);
  // Placed by scale 2 then translate <0, 0, 5>; the radius scales with them.
  EXPECT_EQ(object.segments[1].segment.a, Vec3(2, 0, 5));
  EXPECT_EQ(object.segments[1].segment.b, Vec3(2, 2, 5));
  EXPECT_EQ(object.points[1].center, Vec3(2, 2, 5));
  for (const auto& point : object.points) {
    EXPECT_EQ(point.weight.strength, 2.0);
    EXPECT_EQ(point.weight.radius, 1.0);
  }
  EXPECT_EQ(object.segments[0].weight.radius, 1.0);
  EXPECT_EQ(implicit.component_order.size(), 4u);
}

}  // namespace
}  // namespace convray::sdl
