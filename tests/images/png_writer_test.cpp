// The PNG writer (libpng, core/png_writer.hpp) against what convray wrote through
// OpenImageIO before: the same floats encoded by OpenImageIO's own PNG writer here, both files
// decoded by OpenImageIO's reader (a decoder independent of ours), every level equal; the
// 8-bit rule against OpenImageIO's float-to-uint8 conversion; the colour chunks against those
// OpenImageIO writes.
#include "core/png_writer.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "reference/test_folder.hpp"
#include "core/image_file.hpp"
#include "util/error.hpp"

namespace convray::render {
namespace {

namespace fs = std::filesystem;

class PngWriter : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  convray::testing::TestFolder folder_{"png"};
  const fs::path& dir_ = folder_.path();
};

// Floats where rounding is decided: 40 neighbours either side of every level k/255 and of
// every midpoint (k + 0.5)/255, then the specials, 0 and 1's neighbours, values outside
// [0, 1], and an even ramp.
std::vector<float> hard_values() {
  std::vector<float> values;
  auto around = [&](float centre) {
    float below = centre, above = centre;
    for (int step = 0; step < 40; ++step) {
      below = std::nextafter(below, -1.0f);
      above = std::nextafter(above, 2.0f);
      values.push_back(below);
      values.push_back(above);
    }
    values.push_back(centre);
  };
  for (int k = 0; k <= 255; ++k) {
    around(float(k) / 255.0f);
    around(float(k + 0.5) / 255.0f);
    around(float(double(k) / 255.0));  // the same level, computed in double then rounded
  }
  const float inf = std::numeric_limits<float>::infinity();
  for (const float v : {std::nanf(""), -std::nanf(""), inf, -inf, -0.0f, 1e-45f, 1e-38f, -1e-6f,
                        1.0000001f, 2.0f, 255.0f, 1e30f, -1e30f})
    values.push_back(v);
  for (int i = 0; i <= 20000; ++i) values.push_back(-0.1f + 1.2f * float(i) / 20000.0f);
  while (values.size() % 3 != 0) values.push_back(0.5f);
  return values;
}

// The levels OpenImageIO converts these floats to, in one call (its vectorised path, which
// converts all but the last few values of a row) and one value at a time (its scalar path).
// The two paths disagree on one float: the value whose product with 255 is the largest float
// below 0.5, which the scalar path rounds up (it adds 0.5 in float: 0.49999997 + 0.5 rounds to
// 1) and the vectorised path rounds down. quantize_8bit follows the vectorised path; the PNG
// tests below put that value where OpenImageIO's writer converts it vectorised. (Checked
// outside the suite over every float in [0, 1]: the vectorised path agrees everywhere, the
// scalar path everywhere but there.)
TEST(Quantize8bit, AgreesWithOpenImageIOsConversion) {
  const std::vector<float> values = hard_values();
  std::vector<uint8_t> together(values.size());
  ASSERT_TRUE(OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, values.data(),
                                         OIIO::TypeDesc::UINT8, together.data(),
                                         int(values.size())));
  const float below_half = std::nextafter(0.5f, 0.0f);
  size_t disputed = 0;
  for (size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(int(quantize_8bit(values[k])), int(together[k])) << values[k];
    uint8_t alone = 0;
    ASSERT_TRUE(OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, &values[k], OIIO::TypeDesc::UINT8,
                                           &alone, 1));
    if (values[k] * 255.0f == below_half) {
      ++disputed;
      EXPECT_EQ(int(quantize_8bit(values[k])) + 1, int(alone)) << values[k];
      continue;
    }
    EXPECT_EQ(int(quantize_8bit(values[k])), int(alone)) << values[k];
  }
  EXPECT_GE(disputed, 1u);  // the list holds it (a neighbour of 0.5/255)
}

// What OpenImageIO's PNG writer makes of the values convray handed it before: sRGB-encoded
// floats for linear light, with the colour space said; display values as given.
void write_with_openimageio(const std::string& file, const ImagePixels& pixels) {
  std::vector<float> values(pixels.rgb.begin(), pixels.rgb.end());
  OIIO::ImageSpec spec(pixels.width, pixels.height, 3, OIIO::TypeDesc::UINT8);
  if (pixels.encoding == PixelEncoding::linear) {
    for (float& v : values) v = encode_srgb(v);
    spec.attribute("oiio:ColorSpace", "sRGB");
  }
  auto out = OIIO::ImageOutput::create(file);
  ASSERT_TRUE(out && out->open(file, spec) &&
              out->write_image(OIIO::TypeDesc::FLOAT, values.data()) && out->close())
      << OIIO::geterror();
}

struct Decoded {
  int width = 0, height = 0, channels = 0;
  std::vector<uint8_t> levels;
};

Decoded decode_with_openimageio(const std::string& file) {
  auto in = OIIO::ImageInput::open(file);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  Decoded d{spec.width, spec.height, spec.nchannels, {}};
  d.levels.resize(size_t(d.width) * d.height * d.channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, d.channels, OIIO::TypeDesc::UINT8, d.levels.data()));
  return d;
}

// The colour chunks of a PNG file (ISO/IEC 15948): type -> contents.
std::map<std::string, std::string> colour_chunks(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<std::string, std::string> chunks;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    const size_t length = size_t(b[0]) << 24 | size_t(b[1]) << 16 | size_t(b[2]) << 8 | b[3];
    const std::string type = bytes.substr(at + 4, 4);
    if (type == "gAMA" || type == "sRGB" || type == "cHRM" || type == "iCCP")
      chunks[type] = bytes.substr(at + 8, length);
    at += 12 + length;
  }
  return chunks;
}

void expect_same_as_openimageio(const std::string& ours, const std::string& theirs,
                                const ImagePixels& pixels) {
  write_image_atomically(ours, pixels);
  write_with_openimageio(theirs, pixels);
  const Decoded a = decode_with_openimageio(ours), b = decode_with_openimageio(theirs);
  EXPECT_EQ(a.width, pixels.width);
  EXPECT_EQ(a.height, pixels.height);
  EXPECT_EQ(a.channels, 3);
  ASSERT_EQ(a.levels.size(), b.levels.size());
  size_t different = 0;
  for (size_t k = 0; k < a.levels.size(); ++k) {
    if (a.levels[k] != b.levels[k] && ++different <= 10)
      ADD_FAILURE() << "value " << pixels.rgb[k] << ": " << int(a.levels[k]) << " here, "
                    << int(b.levels[k]) << " from OpenImageIO";
  }
  EXPECT_EQ(different, 0u);
  EXPECT_EQ(colour_chunks(ours), colour_chunks(theirs));
}

TEST_F(PngWriter, LinearLightDecodesAsOpenImageIOsEncoding) {
  const std::vector<float> values = hard_values();
  const int width = 257, height = int(values.size() / 3 / 257);  // rows of 257 pixels
  const ImagePixels pixels{width, height, std::span(values).first(3 * size_t(width) * height),
                           PixelEncoding::linear};
  expect_same_as_openimageio(path("ours.png"), path("theirs.png"), pixels);
  EXPECT_TRUE(colour_chunks(path("ours.png")).count("sRGB"));  // the file says it is sRGB
}

TEST_F(PngWriter, DisplayValuesDecodeAsOpenImageIOsEncoding) {
  const std::vector<float> values = hard_values();
  const ImagePixels pixels{int(values.size() / 3), 1, values, PixelEncoding::display};
  expect_same_as_openimageio(path("ours.png"), path("theirs.png"), pixels);
  EXPECT_TRUE(colour_chunks(path("ours.png")).empty());
}

// Runs of equal pixels and of equal channels (a background, a flat colour: the writer keeps a
// channel's level for the next pixel) decode as OpenImageIO encodes every pixel on its own,
// NaN, -0 and values one ulp apart among them.
TEST_F(PngWriter, RunsOfEqualValuesDecodeAsOpenImageIOsEncoding) {
  const std::vector<float> hard = hard_values();
  std::vector<float> values;
  for (size_t k = 0; k + 3 <= hard.size(); k += 3) {
    for (int repeat = 0; repeat < 3; ++repeat) values.insert(values.end(), &hard[k], &hard[k] + 3);
    // The same red, another green and blue: only the red channel's level is kept.
    values.insert(values.end(), {hard[k], hard[(k + 7) % hard.size()], -0.0f});
    values.insert(values.end(), {0.0f, std::nanf(""), hard[k + 2]});
  }
  const ImagePixels pixels{int(values.size() / 3), 1, values, PixelEncoding::linear};
  expect_same_as_openimageio(path("ours.png"), path("theirs.png"), pixels);
}

// A picture big enough for several compressed data chunks, read back whole.
TEST_F(PngWriter, ALargePictureIsCompleteAndReadsBack) {
  const int width = 640, height = 480;
  std::vector<float> values(3 * size_t(width) * height);
  for (size_t k = 0; k < values.size(); ++k) values[k] = float((k * 7919) % 1000) / 999.0f;
  write_image_atomically(path("big.png"), {width, height, values, PixelEncoding::linear});
  EXPECT_TRUE(image_file_is_complete(path("big.png"), width, height));
  EXPECT_FALSE(image_file_is_complete(path("big.png"), width, height + 1));
  const Decoded d = decode_with_openimageio(path("big.png"));
  EXPECT_EQ(d.width, width);
  EXPECT_EQ(d.height, height);
  EXPECT_EQ(d.levels.size(), values.size());
}

// libpng refuses a width beyond its limit (a million pixels); that is an InputError naming the
// file, not a crash, and nothing is written.
TEST_F(PngWriter, LibpngErrorsAreInputErrors) {
  const std::vector<float> values(3 * 1000001, 0.5f);
  try {
    encode_png(path("wide.png"), {1000001, 1, values, PixelEncoding::display});
    ADD_FAILURE() << "a PNG 1000001 pixels wide was encoded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path("wide.png") + ": cannot write the image: "),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(
      write_image_atomically(path("wide.png"), {1000001, 1, values, PixelEncoding::display}),
      InputError);
  EXPECT_FALSE(fs::exists(path("wide.png")));
}

}  // namespace
}  // namespace convray::render
