// Where a picture's pixels land in the preview window (display/preview_layout.hpp) and what
// the window's picture holds (display/preview_image.hpp): the PNG file's 8-bit levels.
#include <gtest/gtest.h>

#include <vector>

#include "core/image_file.hpp"
#include "core/png_writer.hpp"
#include "display/preview_image.hpp"
#include "display/preview_layout.hpp"

namespace convray::display {
namespace {

TEST(PreviewLayout, APictureThatFitsKeepsItsSize) {
  EXPECT_EQ(fit_preview(800, 600).width, 800);
  EXPECT_EQ(fit_preview(800, 600).height, 600);
  EXPECT_EQ(fit_preview(1280, 1024).width, 1280);
  EXPECT_EQ(fit_preview(1, 1).height, 1);
}

TEST(PreviewLayout, ALargerOneIsScaledDownKeepingItsAspect) {
  const PreviewSize wide = fit_preview(1400, 300);
  EXPECT_EQ(wide.width, 1280);
  EXPECT_EQ(wide.height, 274);  // 300 * 1280 / 1400 = 274.3
  const PreviewSize tall = fit_preview(1000, 4000);
  EXPECT_EQ(tall.width, 256);
  EXPECT_EQ(tall.height, 1024);
  const PreviewSize huge = fit_preview(32768, 32768);
  EXPECT_EQ(huge.width, 1024);
  EXPECT_EQ(huge.height, 1024);
  EXPECT_EQ(fit_preview(32768, 1).height, 1);  // never below one pixel
}

TEST(PreviewLayout, UnscaledEveryPixelShowsItself) {
  for (int i = 0; i < 57; ++i) EXPECT_EQ(source_of(i, 57, 57), i);
  const ShownRange r = shown_range(16, 32, 57, 57);
  EXPECT_EQ(r.first, 16);
  EXPECT_EQ(r.last, 32);
}

TEST(PreviewLayout, ShownRangesAreExactlyThePixelsThatSampleATile) {
  for (int source : {7, 300, 1400, 4001}) {
    for (int shown : {1, 5, 274, 1280}) {
      if (shown > source) continue;
      for (int from = 0; from < source; from += 13) {
        const int to = std::min(source, from + 16);
        const ShownRange r = shown_range(from, to, shown, source);
        for (int u = 0; u < shown; ++u) {
          const int s = source_of(u, shown, source);
          ASSERT_EQ(s >= from && s < to, u >= r.first && u < r.last)
              << "source " << source << " shown " << shown << " tile " << from << " u " << u;
        }
      }
    }
  }
}

TEST(PreviewImage, HoldsThePngWritersLevels) {
  PreviewImage image({0, 0, 4, 2}, {4, 2});
  std::vector<float> rgb;
  for (int k = 0; k < 4 * 2 * 3; ++k) rgb.push_back(float(k) / 23.0f - 0.1f);
  image.put({0, 0, 4, 2}, rgb);
  std::vector<uint8_t> levels;
  ASSERT_TRUE(image.take_if_changed(levels));
  ASSERT_EQ(levels.size(), rgb.size());
  for (size_t k = 0; k < rgb.size(); ++k) EXPECT_EQ(levels[k], quantize_8bit(encode_srgb(rgb[k])));
  EXPECT_FALSE(image.take_if_changed(levels));  // nothing new
  image.mark_changed();
  EXPECT_TRUE(image.take_if_changed(levels));
}

TEST(PreviewImage, APartialRendersWindowIsShownAlone) {
  // The picture is 10 x 10; the window shows its columns 2-5 and rows 3-4.
  PreviewImage image({2, 3, 6, 5}, {4, 2});
  std::vector<float> tile(3 * 10 * 10);
  for (int j = 0; j < 10; ++j) {
    for (int i = 0; i < 10; ++i) tile[3 * size_t(j * 10 + i)] = float(i + 10 * j) / 100.0f;
  }
  image.put({0, 0, 10, 10}, tile);
  std::vector<uint8_t> levels;
  ASSERT_TRUE(image.take_if_changed(levels));
  for (int v = 0; v < 2; ++v) {
    for (int u = 0; u < 4; ++u) {
      const float red = float((u + 2) + 10 * (v + 3)) / 100.0f;
      EXPECT_EQ(levels[3 * size_t(v * 4 + u)], quantize_8bit(encode_srgb(red))) << u << "," << v;
    }
  }
}

}  // namespace
}  // namespace convray::display
