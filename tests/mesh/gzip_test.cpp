// gunzip (mesh/gzip.hpp) against zlib's own gzip decoding written here: its fast path
// (libdeflate, one member whose trailer states its size) and its zlib paths (several members,
// a trailer that states another size, trailing bytes) give the bytes zlib gives.
#include "mesh/gzip.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <string>
#include <vector>

#include "util/error.hpp"

namespace convray::mesh {
namespace {

// One gzip member of `data`, compressed by zlib at `level`.
std::string gzip_member(const std::string& data, int level) {
  z_stream stream{};
  EXPECT_EQ(deflateInit2(&stream, level, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&stream, uLong(data.size())) + 64, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  stream.avail_in = uInt(data.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = uInt(out.size());
  EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return out;
}

// zlib's decoding of every member back to back (what gzip -dc prints).
std::string zlib_gunzip(const std::string& compressed) {
  std::string out;
  size_t at = 0;
  while (at + 2 <= compressed.size() && uint8_t(compressed[at]) == 0x1f &&
         uint8_t(compressed[at + 1]) == 0x8b) {
    z_stream stream{};
    EXPECT_EQ(inflateInit2(&stream, 16 + MAX_WBITS), Z_OK);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + at));
    stream.avail_in = uInt(compressed.size() - at);
    char chunk[4096];
    int status = Z_OK;
    while (status == Z_OK) {
      stream.next_out = reinterpret_cast<Bytef*>(chunk);
      stream.avail_out = sizeof chunk;
      status = inflate(&stream, Z_NO_FLUSH);
      out.append(chunk, sizeof chunk - stream.avail_out);
    }
    EXPECT_EQ(status, Z_STREAM_END);
    at += stream.total_in;
    inflateEnd(&stream);
    if (status != Z_STREAM_END) break;
  }
  return out;
}

// Text like a mesh file's: numbers, repeats and noise.
std::string mesh_like(std::mt19937& rng, size_t lines) {
  std::string text;
  for (size_t i = 0; i < lines; ++i) {
    text += "v " + std::to_string(rng() % 1000) + "." + std::to_string(rng() % 10000) + " " +
            std::to_string(int(rng() % 200) - 100) + " 0.5\n";
  }
  return text;
}

std::string gunzipped(const std::string& compressed) {
  const std::vector<char> bytes = gunzip(compressed, "test.obj.gz");
  return std::string(bytes.begin(), bytes.end());
}

TEST(Gunzip, OneMemberAsZlibDecodesIt) {
  std::mt19937 rng(3);
  for (const size_t lines : {size_t(1), size_t(10), size_t(3000), size_t(60000)}) {
    for (const int level : {0, 1, 6, 9}) {
      const std::string compressed = gzip_member(mesh_like(rng, lines), level);
      EXPECT_EQ(gunzipped(compressed), zlib_gunzip(compressed)) << lines << " " << level;
    }
  }
}

TEST(Gunzip, SeveralMembersAndTrailingBytesAsZlibDecodesThem) {
  std::mt19937 rng(4);
  const std::string a = gzip_member(mesh_like(rng, 500), 6), b = gzip_member(mesh_like(rng, 70), 1);
  for (const std::string& compressed : {a + b, a + b + a, a + std::string("trailing junk"),
                                        a + std::string(8, '\0')}) {
    const std::string expected = zlib_gunzip(compressed);
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(gunzipped(compressed), expected);
  }
}

// A trailer that states another size than the member's (4 bytes rewritten): zlib's check of
// the length refuses the member, and gunzip says it is corrupt, whichever path tried first.
TEST(Gunzip, AWrongStatedSizeIsCorruptData) {
  std::mt19937 rng(5);
  for (const int delta : {-1, 1, 1000}) {
    std::string compressed = gzip_member(mesh_like(rng, 200), 6);
    uint32_t size = 0;
    for (int k = 0; k < 4; ++k) size |= uint32_t(uint8_t(compressed[compressed.size() - 4 + k])) << (8 * k);
    size += uint32_t(delta);
    for (int k = 0; k < 4; ++k) compressed[compressed.size() - 4 + k] = char((size >> (8 * k)) & 0xff);
    EXPECT_THROW(gunzip(compressed, "test.obj.gz"), InputError) << delta;
  }
}

}  // namespace
}  // namespace convray::mesh
