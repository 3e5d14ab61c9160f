// Writing pictures: values read back through OpenImageIO itself, the sRGB curve computed here
// from its definition, and no file left behind by a write that fails.
#include "core/image_file.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "reference/test_folder.hpp"
#include "util/error.hpp"

namespace convray::render {
namespace {

namespace fs = std::filesystem;

class ImageFile : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  size_t files_in_folder() const { return size_t(std::distance(fs::directory_iterator(dir_), {})); }

  // A 4x2 picture whose values cover dark, mid, bright and out-of-range linear light.
  static std::vector<float> test_values() {
    return {0.0f, 0.001f, 0.002f, 0.01f, 0.05f, 0.1f,  0.18f, 0.2f,  0.3f,  0.4f,  0.5f,  0.6f,
            0.7f, 0.8f,   0.9f,   1.0f,  0.25f, 0.75f, 2.0f,  -0.5f, 0.33f, 0.66f, 0.99f, 0.004f};
  }

  convray::testing::TestFolder folder_{"image"};
  const fs::path& dir_ = folder_.path();
};

struct ReadBack {
  int width = 0, height = 0, channels = 0;
  std::string format;  // the stored type, e.g. "uint8"
  std::vector<float> values;
};

ReadBack read_back(const std::string& file) {
  auto in = OIIO::ImageInput::open(file);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  ReadBack r{spec.width, spec.height, spec.nchannels, spec.format.c_str(), {}};
  r.values.resize(size_t(r.width) * r.height * r.channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, r.channels, OIIO::TypeDesc::FLOAT, r.values.data()));
  return r;
}

// IEC 61966-2-1, from its definition.
double srgb(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

TEST_F(ImageFile, PngStoresEightBitSrgb) {
  const std::vector<float> values = test_values();
  write_image_atomically(path("a.png"), {4, 2, values, PixelEncoding::linear});
  const ReadBack r = read_back(path("a.png"));
  ASSERT_EQ(r.width, 4);
  ASSERT_EQ(r.height, 2);
  ASSERT_EQ(r.channels, 3);
  EXPECT_EQ(r.format, "uint8");
  for (size_t k = 0; k < values.size(); ++k) {
    EXPECT_NEAR(r.values[k], srgb(values[k]), 0.5 / 255 + 1e-6)
        << k;  // rounded to the nearest level
  }
  EXPECT_EQ(files_in_folder(), 1u);
}

TEST_F(ImageFile, ExrStoresLinearFloatsExactly) {
  const std::vector<float> values = test_values();
  write_image_atomically(path("a.exr"), {4, 2, values, PixelEncoding::linear});
  const ReadBack r = read_back(path("a.exr"));
  EXPECT_EQ(r.format, "float");
  EXPECT_EQ(r.values, values);
}

TEST_F(ImageFile, TiffStoresSixteenBitSrgb) {
  const std::vector<float> values = test_values();
  write_image_atomically(path("a.TIF"), {4, 2, values, PixelEncoding::linear});
  const ReadBack r = read_back(path("a.TIF"));
  EXPECT_EQ(r.format, "uint16");
  for (size_t k = 0; k < values.size(); ++k)
    EXPECT_NEAR(r.values[k], srgb(values[k]), 0.5 / 65535 + 1e-6) << k;
}

TEST_F(ImageFile, DisplayValuesAreStoredAsGiven) {
  const std::vector<float> values = test_values();
  write_image_atomically(path("a.png"), {4, 2, values, PixelEncoding::display});
  const ReadBack r = read_back(path("a.png"));
  for (size_t k = 0; k < values.size(); ++k) {
    EXPECT_NEAR(r.values[k], std::clamp(values[k], 0.0f, 1.0f), 0.5 / 255 + 1e-6) << k;
  }
}

TEST_F(ImageFile, FormatsByExtension) {
  EXPECT_EQ(image_format_for("x.png").bits, 8);
  EXPECT_EQ(image_format_for("x.PNG").extension, "png");
  EXPECT_TRUE(image_format_for("dir/x.exr").floating);
  EXPECT_EQ(image_format_for("x.tiff").bits, 16);
}

TEST_F(ImageFile, UnknownExtensionIsAnInputErrorAndWritesNothing) {
  const std::vector<float> values = test_values();
  for (const std::string name : {"a.notanimage", "no_extension"}) {
    try {
      write_image_atomically(path(name), {4, 2, values, PixelEncoding::linear});
      ADD_FAILURE() << name << " was written";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path(name)), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(".png"), std::string::npos)
          << e.what();  // says what works
    }
    EXPECT_THROW(check_image_destination(path(name)), InputError);
  }
  EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(ImageFile, MissingFolderFailsBeforeAndDuringTheWrite) {
  const std::vector<float> values = test_values();
  EXPECT_THROW(check_image_destination(path("no/such/folder/a.png")), InputError);
  EXPECT_THROW(
      write_image_atomically(path("no/such/folder/a.png"), {4, 2, values, PixelEncoding::linear}),
      InputError);
  EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(ImageFile, FailedRenameLeavesNoPartialFile) {
  // The partial file can be written, but a folder stands where it must be renamed to.
  fs::create_directories(dir_ / "taken.png" / "inside");
  const std::vector<float> values = test_values();
  EXPECT_THROW(check_image_destination(path("taken.png")), InputError);
  EXPECT_THROW(write_image_atomically(path("taken.png"), {4, 2, values, PixelEncoding::linear}),
               InputError);
  EXPECT_EQ(files_in_folder(), 1u);  // only the folder
  EXPECT_TRUE(fs::is_directory(dir_ / "taken.png" / "inside"));
}

TEST_F(ImageFile, ReplacesAnExistingFileWhole) {
  std::ofstream(path("a.png")) << "old contents";
  const std::vector<float> values = test_values();
  write_image_atomically(path("a.png"), {4, 2, values, PixelEncoding::linear});
  EXPECT_EQ(read_back(path("a.png")).width, 4);
  EXPECT_EQ(files_in_folder(), 1u);
}

// +C trusts a frame only when it is whole: every truncation of a PNG, a flipped byte, or
// another size is not complete, a whole file of the right size is (for PNG and for TIFF), and
// the check prints nothing (no "libpng error" line on the terminal).
TEST_F(ImageFile, CompletenessFindsEveryTruncationQuietly) {
  const std::vector<float> values = test_values();
  write_image_atomically(path("a.png"), {4, 2, values, PixelEncoding::linear});
  write_image_atomically(path("a.tif"), {4, 2, values, PixelEncoding::linear});
  EXPECT_TRUE(image_file_is_complete(path("a.png"), 4, 2));
  EXPECT_TRUE(image_file_is_complete(path("a.tif"), 4, 2));
  EXPECT_FALSE(image_file_is_complete(path("a.png"), 2, 4));
  EXPECT_FALSE(image_file_is_complete(path("missing.png"), 4, 2));
  std::ifstream in(path("a.png"), std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ::testing::internal::CaptureStderr();
  for (size_t size = 0; size < whole.size(); ++size) {
    std::ofstream(path("cut.png"), std::ios::binary) << whole.substr(0, size);
    EXPECT_FALSE(image_file_is_complete(path("cut.png"), 4, 2)) << size << " bytes";
  }
  for (size_t at = 8; at < whole.size(); at += 7) {
    std::string damaged = whole;
    damaged[at] = char(damaged[at] ^ 0x20);
    std::ofstream(path("bad.png"), std::ios::binary) << damaged;
    EXPECT_FALSE(image_file_is_complete(path("bad.png"), 4, 2)) << "byte " << at;
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

// Formats other than PNG go through the plugin: written, checked whole, and a truncated file
// is not complete.
TEST_F(ImageFile, PluginFormatsAreCheckedWhole) {
  const std::vector<float> values = test_values();
  for (const std::string name : {"a.exr", "a.tif", "a.jpg"}) {
    write_image_atomically(path(name), {4, 2, values, PixelEncoding::linear});
    EXPECT_EQ(read_back(path(name)).width, 4) << name;
    EXPECT_TRUE(image_file_is_complete(path(name), 4, 2)) << name;
    EXPECT_FALSE(image_file_is_complete(path(name), 4, 3)) << name;
    const auto size = fs::file_size(path(name));
    fs::resize_file(path(name), size / 2);
    EXPECT_FALSE(image_file_is_complete(path(name), 4, 2)) << name << " cut to " << size / 2;
  }
}

// A destination that cannot be written fails the same way whichever writer the format has
// (libpng here, OpenImageIO in the plugin): the same message after the name, no file left.
TEST_F(ImageFile, AnUnwritableDestinationFailsAlikeForEveryFormat) {
  std::ofstream(path("file.txt")) << "not a folder";
  const std::vector<float> values = test_values();
  std::vector<std::string> messages;
  for (const std::string name : {"file.txt/a.png", "file.txt/a.exr", "file.txt/a.tif"}) {
    EXPECT_THROW(check_image_destination(path(name)), InputError) << name;
    try {
      write_image_atomically(path(name), {4, 2, values, PixelEncoding::linear});
      ADD_FAILURE() << name << " was written";
    } catch (const InputError& e) {
      const std::string what = e.what();
      ASSERT_EQ(what.find(path(name) + ": cannot write the image: "), 0u) << what;
      messages.push_back(what.substr(path(name).size()));
    }
  }
  ASSERT_EQ(messages.size(), 3u);
  EXPECT_EQ(messages[0], messages[1]);
  EXPECT_EQ(messages[0], messages[2]);
  EXPECT_EQ(files_in_folder(), 1u);  // only file.txt
}

TEST(EncodeSrgb, MatchesTheDefinition) {
  for (const float v : {0.0f, 0.002f, 0.0031308f, 0.01f, 0.5f, 0.9f, 1.0f})
    EXPECT_NEAR(encode_srgb(v), srgb(v), 1e-6);
  EXPECT_EQ(encode_srgb(-1.0f), 0.0f);
  EXPECT_EQ(encode_srgb(5.0f), 1.0f);
  EXPECT_EQ(encode_srgb(std::nanf("")), 0.0f);
}

}  // namespace
}  // namespace convray::render
