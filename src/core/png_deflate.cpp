#include "core/png_deflate.hpp"

#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

namespace convray {
namespace {

// zlib's window: the most of the bytes before a band that its deflate can refer back to.
constexpr size_t kWindow = 32768;

unsigned char paeth_predictor(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return static_cast<unsigned char>(a);
  return static_cast<unsigned char>(pb <= pc ? b : c);
}

// The filtered scanlines of rows [first, end) of the image, one after the other.
struct Rows {
  const unsigned char* pixels;
  size_t row_bytes, pixel_bytes;

  void filter(size_t first, size_t end, unsigned char* out) const {
    for (size_t y = first; y < end; ++y) {
      const unsigned char* above = y > 0 ? pixels + (y - 1) * row_bytes : nullptr;
      paeth_filter_row(pixels + y * row_bytes, above, row_bytes, pixel_bytes,
                       out + (y - first) * (row_bytes + 1));
    }
  }
};

[[noreturn]] void fail(const char* what, int status) {
  if (status == Z_MEM_ERROR) throw std::bad_alloc();
  throw std::runtime_error(std::string("zlib: ") + what + " failed (" + std::to_string(status) +
                           ")");
}

// Owns a raw deflate stream (no zlib header or trailer: the bands are joined by hand).
class RawDeflate {
 public:
  explicit RawDeflate(int level) {
    const int status = deflateInit2(&stream_, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY);
    if (status != Z_OK) fail("deflateInit2", status);
  }
  ~RawDeflate() { deflateEnd(&stream_); }
  RawDeflate(const RawDeflate&) = delete;
  RawDeflate& operator=(const RawDeflate&) = delete;

  void set_dictionary(const unsigned char* bytes, size_t size) {
    const int status = deflateSetDictionary(&stream_, bytes, uInt(size));
    if (status != Z_OK) fail("deflateSetDictionary", status);
  }

  // All of `input`, then a sync flush (a band in the middle) or the stream's end (the last).
  std::vector<unsigned char> compress(const std::vector<unsigned char>& input, bool last) {
    std::vector<unsigned char> out(deflateBound(&stream_, uLong(input.size())) + 16);
    stream_.next_in = const_cast<Bytef*>(input.data());
    stream_.avail_in = uInt(input.size());
    size_t written = 0;
    const int flush = last ? Z_FINISH : Z_SYNC_FLUSH;
    for (;;) {
      stream_.next_out = out.data() + written;
      stream_.avail_out = uInt(out.size() - written);
      const int status = deflate(&stream_, flush);
      written = out.size() - stream_.avail_out;
      if (status == Z_STREAM_END) break;
      if (status != Z_OK && status != Z_BUF_ERROR) fail("deflate", status);
      if (stream_.avail_out > 0) {
        if (!last && status == Z_OK) break;  // flushed, with room to spare
        fail("deflate", status);             // no progress although there was room
      }
      out.resize(out.size() * 2);  // the bound is for Z_FINISH: grow on the rare shortfall
    }
    out.resize(written);
    return out;
  }

 private:
  z_stream stream_{};
};

struct Band {
  std::vector<unsigned char> deflated;
  uLong adler = 0;
  size_t length = 0;  // filtered bytes
};

// Band `b` of `count`: its filtered rows deflated, with the filtered bytes just before it (up
// to a window, filtered again here) as the dictionary, so the bands compress as one stream.
Band deflate_band(const Rows& rows, size_t height, size_t b, size_t count, int level) {
  const size_t first = height * b / count, end = height * (b + 1) / count;
  const size_t line = rows.row_bytes + 1;
  Band band;
  std::vector<unsigned char> filtered((end - first) * line);
  rows.filter(first, end, filtered.data());
  band.length = filtered.size();
  band.adler = adler32(adler32(0, Z_NULL, 0), filtered.data(), uInt(filtered.size()));
  RawDeflate deflater(level);
  if (first > 0) {
    const size_t back = std::min(first, (kWindow + line - 1) / line);
    std::vector<unsigned char> before(back * line);
    rows.filter(first - back, first, before.data());
    const size_t size = std::min(before.size(), kWindow);
    deflater.set_dictionary(before.data() + before.size() - size, size);
  }
  band.deflated = deflater.compress(filtered, b + 1 == count);
  return band;
}

}  // namespace

void paeth_filter_row(const unsigned char* row, const unsigned char* above, size_t row_bytes,
                      size_t pixel_bytes, unsigned char* out) {
  out[0] = 4;  // Paeth
  for (size_t i = 0; i < row_bytes; ++i) {
    const int a = i >= pixel_bytes ? row[i - pixel_bytes] : 0;
    const int b = above ? above[i] : 0;
    const int c = above && i >= pixel_bytes ? above[i - pixel_bytes] : 0;
    out[i + 1] = static_cast<unsigned char>(row[i] - paeth_predictor(a, b, c));
  }
}

std::vector<unsigned char> png_image_data(const unsigned char* pixels, size_t row_bytes,
                                          size_t height, size_t pixel_bytes, int level,
                                          size_t bands) {
  bands = std::max<size_t>(1, std::min(bands, height));
  const Rows rows{pixels, row_bytes, pixel_bytes};
  std::vector<Band> done(bands);
  tbb::parallel_for(size_t(0), bands, [&](size_t b) {
    done[b] = deflate_band(rows, height, b, bands, level);
  });
  // zlib's header: deflate with a 32 KiB window, the level's class, a multiple of 31.
  const unsigned level_class = level < 2 ? 0 : level < 6 ? 1 : level == 6 ? 2 : 3;
  unsigned header = (0x78u << 8) | (level_class << 6);
  header += (31 - header % 31) % 31;
  std::vector<unsigned char> stream{static_cast<unsigned char>(header >> 8),
                                    static_cast<unsigned char>(header & 0xff)};
  uLong adler = adler32(0, Z_NULL, 0);
  for (const Band& band : done) {
    stream.insert(stream.end(), band.deflated.begin(), band.deflated.end());
    adler = adler32_combine(adler, band.adler, z_off_t(band.length));
  }
  for (int shift = 24; shift >= 0; shift -= 8) {
    stream.push_back(static_cast<unsigned char>((adler >> shift) & 0xff));
  }
  return stream;
}

}  // namespace convray
