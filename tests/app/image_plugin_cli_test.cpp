// The image formats' plugin (libconvray_oiio.so, core/oiio_plugin_api.hpp) through the
// program: convray itself does not load OpenImageIO, a PNG render needs no plugin, and a
// format that does need it, when the plugin is missing, is an error naming the plugin's file
// that leaves no picture behind.
#include <gtest/gtest.h>

#include "cli.hpp"

namespace convray::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = R"(
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
camera { location -5*z look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
)";

class ImagePlugin : public CliTest {
 protected:
  // The program alone in a folder of its own: no plugin beside it.
  std::string lone_convray() const {
    fs::create_directories(dir_ / "alone");
    fs::copy_file(CONVRAY_BINARY, dir_ / "alone" / "convray");
    return (dir_ / "alone" / "convray").string();
  }

  CliRun run(const std::string& program, const std::string& arguments) const {
    const std::string command =
        "cd '" + dir_.string() + "' && '" + program + "' " + arguments + " > .stdout 2> .stderr";
    const int status = std::system(command.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(dir_ / ".stdout");
    r.err = read_file(dir_ / ".stderr");
    return r;
  }
};

TEST_F(ImagePlugin, TheProgramDoesNotLinkOpenImageIO) {
  const CliRun ldd = run("ldd", "'" + std::string(CONVRAY_BINARY) + "'");
  ASSERT_EQ(ldd.exit_code, 0) << ldd.all();
  EXPECT_EQ(ldd.out.find("OpenImageIO"), std::string::npos) << ldd.out;
}

TEST_F(ImagePlugin, PngNeedsNoPlugin) {
  std::ofstream(file("s.pov")) << kScene;
  const CliRun r = run(lone_convray(), "s.pov +W16 +H12 -o s.png");
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(fs::is_regular_file(file("s.png")));
}

TEST_F(ImagePlugin, AMissingPluginIsNamedAndNothingIsWritten) {
  std::ofstream(file("s.pov")) << kScene;
  const std::string program = lone_convray();
  for (const std::string name : {"s.exr", "s.tif", "s.jpg"}) {
    const CliRun r = run(program, "s.pov +W16 +H12 -o " + name);
    EXPECT_EQ(r.exit_code, 2) << r.all();
    EXPECT_NE(r.err.find(name + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find((dir_ / "alone" / "libconvray_oiio.so").string()), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(file(name)));
  }
  // Beside the same program, the plugin makes the format work.
  fs::create_symlink(fs::path(CONVRAY_BINARY).parent_path() / "libconvray_oiio.so",
                     dir_ / "alone" / "libconvray_oiio.so");
  const CliRun r = run(program, "s.pov +W16 +H12 -o s.exr");
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(fs::is_regular_file(file("s.exr")));
}

}  // namespace
}  // namespace convray::testing
