// The banded PNG image data (core/png_deflate.hpp) against the PNG specification's decoder:
// zlib inflates the whole stream (one valid zlib stream, its Adler-32 checked by zlib), and
// the scanlines are unfiltered here by the specification's rule for each filter type, written
// independently of the encoder; the pixels must come back exactly, whatever the bands.
#include "core/png_deflate.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>
#include <random>
#include <vector>

namespace convray {
namespace {

std::vector<unsigned char> inflate_whole(const std::vector<unsigned char>& stream,
                                         size_t expected) {
  std::vector<unsigned char> out(expected + 1);  // a byte more: the stream must end at expected
  uLongf size = uLongf(out.size());
  const int status = uncompress(out.data(), &size, stream.data(), uLong(stream.size()));
  EXPECT_EQ(status, Z_OK);
  out.resize(size);
  return out;
}

// The PNG specification's reconstruction (section 9): each filter type undone byte by byte.
std::vector<unsigned char> unfilter(const std::vector<unsigned char>& data, size_t row_bytes,
                                    size_t height, size_t bpp) {
  std::vector<unsigned char> pixels(row_bytes * height);
  for (size_t y = 0; y < height; ++y) {
    const unsigned char type = data[y * (row_bytes + 1)];
    const unsigned char* filtered = &data[y * (row_bytes + 1) + 1];
    unsigned char* row = &pixels[y * row_bytes];
    for (size_t i = 0; i < row_bytes; ++i) {
      const int a = i >= bpp ? row[i - bpp] : 0;
      const int b = y > 0 ? pixels[(y - 1) * row_bytes + i] : 0;
      const int c = y > 0 && i >= bpp ? pixels[(y - 1) * row_bytes + i - bpp] : 0;
      int predictor = 0;
      switch (type) {
        case 0: predictor = 0; break;
        case 1: predictor = a; break;
        case 2: predictor = b; break;
        case 3: predictor = (a + b) / 2; break;
        case 4: {
          const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          predictor = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default: ADD_FAILURE() << "filter type " << int(type); return pixels;
      }
      row[i] = static_cast<unsigned char>(filtered[i] + predictor);
    }
  }
  return pixels;
}

// Smooth gradients with noise and flat runs: what renders look like, and what a window's
// back-references (the dictionaries across bands) find.
std::vector<unsigned char> picture(size_t row_bytes, size_t height, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<unsigned char> pixels(row_bytes * height);
  for (size_t y = 0; y < height; ++y) {
    for (size_t i = 0; i < row_bytes; ++i) {
      const bool flat = (y / 7 + i / 50) % 3 == 0;
      pixels[y * row_bytes + i] =
          static_cast<unsigned char>(flat ? 40 : (i + 2 * y) % 256 + rng() % 5);
    }
  }
  return pixels;
}

TEST(PngImageData, DecodesToThePixelsForAnyBands) {
  for (const size_t bpp : {size_t(1), size_t(3)}) {
    for (const size_t width : {size_t(1), size_t(2), size_t(37), size_t(300)}) {
      for (const size_t height : {size_t(1), size_t(5), size_t(64), size_t(201)}) {
        const size_t row_bytes = width * bpp;
        const std::vector<unsigned char> pixels = picture(row_bytes, height, unsigned(width + height));
        for (const size_t bands : {size_t(1), size_t(2), size_t(3), size_t(8), size_t(1000)}) {
          for (const int level : {1, 3, 9}) {
            const std::vector<unsigned char> stream =
                png_image_data(pixels.data(), row_bytes, height, bpp, level, bands);
            const std::vector<unsigned char> data =
                inflate_whole(stream, (row_bytes + 1) * height);
            ASSERT_EQ(data.size(), (row_bytes + 1) * height)
                << bpp << " " << width << "x" << height << " bands " << bands;
            EXPECT_EQ(unfilter(data, row_bytes, height, bpp), pixels)
                << bpp << " " << width << "x" << height << " bands " << bands;
          }
        }
      }
    }
  }
}

TEST(PngImageData, HeaderIsAValidZlibHeader) {
  const std::vector<unsigned char> pixels = picture(30, 10, 1);
  for (const int level : {0, 1, 3, 6, 9}) {
    const std::vector<unsigned char> stream = png_image_data(pixels.data(), 30, 10, 3, level, 2);
    ASSERT_GE(stream.size(), 6u);
    EXPECT_EQ(stream[0], 0x78);  // deflate, 32 KiB window (RFC 1950)
    EXPECT_EQ((stream[0] * 256 + stream[1]) % 31, 0);
    EXPECT_EQ(stream[1] & 0x20, 0);  // no preset dictionary for the stream as a whole
  }
}

// The dictionaries across bands: a picture of repeated rows compresses as well in bands as in
// one piece (a band without the rows before it would restart its matches).
TEST(PngImageData, BandsCompressLikeOneStream) {
  const size_t row_bytes = 3 * 200, height = 400;
  const std::vector<unsigned char> pixels = picture(row_bytes, height, 9);
  const size_t whole = png_image_data(pixels.data(), row_bytes, height, 3, 3, 1).size();
  const size_t banded = png_image_data(pixels.data(), row_bytes, height, 3, 3, 8).size();
  EXPECT_LE(double(banded), 1.02 * double(whole) + 64.0) << whole << " " << banded;
}

}  // namespace
}  // namespace convray
