#include "mesh/gzip.hpp"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <memory>
#include <new>
#include <vector>

#include "mesh/load_error.hpp"

namespace convray::mesh {
namespace {

constexpr size_t kChunk = size_t{1} << 16;

// Owns a z_stream set up for gzip decoding, so every exit path releases it.
class GzipInflater {
 public:
  explicit GzipInflater(const std::string& file) {
    // 16 + MAX_WBITS: expect a gzip header and trailer rather than a raw zlib stream.
    if (inflateInit2(&stream_, 16 + MAX_WBITS) != Z_OK) fail(file, "gzip: cannot initialise zlib");
  }
  ~GzipInflater() { inflateEnd(&stream_); }
  GzipInflater(const GzipInflater&) = delete;
  GzipInflater& operator=(const GzipInflater&) = delete;

  z_stream& stream() { return stream_; }

 private:
  z_stream stream_{};
};

bool starts_gzip_member(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

[[noreturn]] void fail_too_big(const std::string& file, uint64_t limit) {
  fail(file, "gzip: the decompressed data exceeds " + std::to_string(limit) +
                 " bytes (100 times the compressed size, at least 1 MiB, at most 4 GiB); "
                 "refusing what looks like a decompression bomb");
}

// Inflates every member of `compressed` a chunk at a time, handing each chunk to `sink`
// (which returns false to stop early); returns the bytes inflated. Stops with the bomb error
// past `limit`.
template <typename Sink>
uint64_t inflate_all(std::string_view compressed, const std::string& file, uint64_t limit,
                     Sink&& sink) {
  GzipInflater inflater(file);
  z_stream& stream = inflater.stream();
  std::vector<char> chunk(kChunk);
  uint64_t total = 0;
  std::string_view input = compressed;
  for (;;) {
    // zlib counts in uInt; feed at most UINT_MAX bytes at a time.
    size_t feed = std::min<size_t>(input.size(), UINT_MAX);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
    stream.avail_in = static_cast<uInt>(feed);
    stream.next_out = reinterpret_cast<Bytef*>(chunk.data());
    stream.avail_out = static_cast<uInt>(kChunk);
    int status = inflate(&stream, Z_NO_FLUSH);
    const size_t produced = kChunk - stream.avail_out;
    total += produced;
    input.remove_prefix(feed - stream.avail_in);
    if (total > limit) fail_too_big(file, limit);
    if (!sink(chunk.data(), produced)) return total;
    if (status == Z_STREAM_END) {
      if (!starts_gzip_member(input)) return total;  // done; trailing bytes ignored
      inflateReset(&stream);                          // another member follows
    } else if (status == Z_BUF_ERROR || (status == Z_OK && input.empty() && stream.avail_out != 0)) {
      fail(file, "gzip: the compressed data ends early (the file is truncated)");
    } else if (status != Z_OK) {
      fail(file, std::string("gzip: corrupt data (") + (stream.msg ? stream.msg : "zlib error") + ")");
    }
  }
}

}  // namespace

uint64_t inflated_size_limit(uint64_t compressed_size) {
  uint64_t by_ratio = compressed_size > kMaxInflatedBytes / kMaxInflationRatio
                          ? kMaxInflatedBytes
                          : compressed_size * kMaxInflationRatio;
  return std::min(kMaxInflatedBytes, std::max(kMinInflatedLimit, by_ratio));
}

namespace {

// The size the gzip trailer states: ISIZE, the last member's length modulo 2^32, in the
// last four bytes (little-endian). Only a hint: earlier members, bytes after the last one, a
// file over 4 GiB or a forged trailer make it wrong.
uint64_t stated_size(std::string_view compressed) {
  if (compressed.size() < 18) return 0;  // a 10-byte header and an 8-byte trailer at least
  uint64_t size = 0;
  for (int k = 0; k < 4; ++k) {
    size |= uint64_t(static_cast<unsigned char>(compressed[compressed.size() - 4 + k])) << (8 * k);
  }
  return size;
}

// One pass, where the trailer's size is right (every file gzip(1) wrote in one go): libdeflate
// inflates the member in one call into a buffer of the size the trailer states (the dragon's
// 7.3 MB in about half zlib's time), never grown past it. Returns false, the output empty,
// wherever zlib's two passes must decide instead: no usable stated size, a member that does
// not fit it, data libdeflate calls bad (zlib then names what is wrong), or a second member.
bool inflate_with_libdeflate(std::string_view compressed, uint64_t limit,
                             std::vector<char>& output) {
  const uint64_t stated = stated_size(compressed);
  if (stated == 0 || stated > limit) return false;
  const std::unique_ptr<libdeflate_decompressor, decltype(&libdeflate_free_decompressor)>
      decompressor(libdeflate_alloc_decompressor(), libdeflate_free_decompressor);
  if (!decompressor) return false;
  try {
    output.resize(static_cast<size_t>(stated));
  } catch (const std::bad_alloc&) {
    return false;  // a forged size: zlib's counting pass finds the real one
  }
  size_t used = 0, produced = 0;
  const libdeflate_result result =
      libdeflate_gzip_decompress_ex(decompressor.get(), compressed.data(), compressed.size(),
                                    output.data(), output.size(), &used, &produced);
  if (result != LIBDEFLATE_SUCCESS || starts_gzip_member(compressed.substr(used))) {
    std::vector<char>().swap(output);
    return false;
  }
  output.resize(produced);
  return true;
}

}  // namespace

// Where the trailer's size is wrong, two passes: the first only counts, so a bomb is refused
// without holding any of it and a good file gets one allocation of its exact size. A buffer
// grown by doubling held up to three times the output during its last copy and ran out of
// memory on issue 17's 20 GB of zeros before the limit refused them.
std::vector<char> gunzip(std::string_view compressed, const std::string& file) {
  if (!starts_gzip_member(compressed)) fail(file, "gzip: not gzip data (the file does not start with 1f 8b)");
  const uint64_t limit = inflated_size_limit(compressed.size());
  std::vector<char> output;
  if (inflate_with_libdeflate(compressed, limit, output)) return output;
  const uint64_t size = inflate_all(compressed, file, limit, [](const char*, size_t) { return true; });
  output.reserve(static_cast<size_t>(size));
  inflate_all(compressed, file, limit, [&](const char* data, size_t n) {
    output.insert(output.end(), data, data + n);
    return true;
  });
  return output;
}

}  // namespace convray::mesh
