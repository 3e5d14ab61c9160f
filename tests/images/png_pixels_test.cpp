// The tests' own PNG reader (tests/reference/png_pixels.hpp, libpng) against OpenImageIO:
// files of every common layout written by OpenImageIO's PNG writer, read back by ours and by
// OpenImageIO, every value equal (grey replicated, alpha dropped, 16-bit samples rounded to
// the nearest 8-bit level).
#include "reference/png_pixels.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace convray::reference {
namespace {

namespace fs = std::filesystem;

struct Layout {
  const char* name;
  int channels;  // 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA
  bool sixteen;
};

class PngPixelsAgainstOpenImageIO : public ::testing::TestWithParam<Layout> {};

// A picture of random samples in the layout, written by OpenImageIO.
template <class Sample>
void write_random(const std::string& path, const Layout& layout, int w, int h) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> sample(0, layout.sixteen ? 65535 : 255);
  std::vector<Sample> values(size_t(w) * h * layout.channels);
  for (Sample& v : values) v = Sample(sample(random));
  const OIIO::TypeDesc type = layout.sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(w, h, layout.channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // stored as given, not divided by alpha
  auto out = OIIO::ImageOutput::create(path);
  EXPECT_TRUE(out && out->open(path, spec) && out->write_image(type, values.data()) &&
              out->close())
      << OIIO::geterror();
}

// The file's samples as OpenImageIO reads them, in their own type, alpha left as stored.
std::vector<int> read_stored(const std::string& path, const Layout& layout) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.nchannels, layout.channels);
  const size_t count = size_t(spec.width) * spec.height * spec.nchannels;
  std::vector<int> stored;
  if (layout.sixteen) {
    std::vector<uint16_t> v(count);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, v.data()));
    stored.assign(v.begin(), v.end());
  } else {
    std::vector<uint8_t> v(count);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, v.data()));
    stored.assign(v.begin(), v.end());
  }
  return stored;
}

TEST_P(PngPixelsAgainstOpenImageIO, EveryValueAsStored) {
  const Layout& layout = GetParam();
  const fs::path path =
      fs::temp_directory_path() /
      ("convray-png-pixels-" + std::to_string(::getpid()) + "-" + layout.name + ".png");
  const int w = 64, h = 48;
  if (layout.sixteen) {
    write_random<uint16_t>(path.string(), layout, w, h);
  } else {
    write_random<uint8_t>(path.string(), layout, w, h);
  }
  const std::vector<int> stored = read_stored(path.string(), layout);
  const PngPixels read = read_png_rgb8(path.string());
  fs::remove(path);
  ASSERT_EQ(stored.size(), size_t(w) * h * layout.channels);
  ASSERT_EQ(read.width, w) << read.error;
  ASSERT_EQ(read.height, h);
  ASSERT_EQ(read.rgb.size(), size_t(w) * h * 3);
  const bool grey = layout.channels < 3;
  for (size_t pixel = 0; pixel < size_t(w) * h; ++pixel) {
    for (int c = 0; c < 3; ++c) {
      const int value = stored[pixel * layout.channels + (grey ? 0 : c)];
      // 16 bits to 8: the nearest level, value * 255 / 65535 = value / 257.
      const int expected = layout.sixteen ? int(std::lround(value / 257.0)) : value;
      ASSERT_EQ(int(read.rgb[pixel * 3 + c]), expected)
          << layout.name << " pixel " << pixel << " channel " << c << " stored " << value;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, PngPixelsAgainstOpenImageIO,
                         ::testing::Values(Layout{"rgb8", 3, false}, Layout{"rgba8", 4, false},
                                           Layout{"grey8", 1, false},
                                           Layout{"greyalpha8", 2, false},
                                           Layout{"rgb16", 3, true}, Layout{"rgba16", 4, true},
                                           Layout{"grey16", 1, true}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(PngPixels, AFileThatIsNotAPngSaysWhy) {
  const fs::path path =
      fs::temp_directory_path() / ("convray-not-png-" + std::to_string(::getpid()) + ".png");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_TRUE(f);
  std::fputs("not a picture", f);
  std::fclose(f);
  const PngPixels read = read_png_rgb8(path.string());
  fs::remove(path);
  EXPECT_TRUE(read.rgb.empty());
  EXPECT_NE(read.error.find(path.string()), std::string::npos) << read.error;
  EXPECT_TRUE(read_png_rgb8(path.string() + ".missing").rgb.empty());
}

}  // namespace
}  // namespace convray::reference
