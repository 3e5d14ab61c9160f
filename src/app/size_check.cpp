#include "app/size_check.hpp"

#include <sys/statvfs.h>

#include <filesystem>
#include <optional>

#include "app/usage_error.hpp"
#include "util/memory_limit.hpp"

namespace convray::app {
namespace {

// The bytes this user may still write in `folder`, or nothing when the file system does not
// say.
std::optional<uint64_t> free_disk_bytes(const std::string& folder) {
  struct statvfs info {};
  if (::statvfs(folder.c_str(), &info) != 0) return std::nullopt;
  return uint64_t(info.f_bavail) * uint64_t(info.f_frsize);
}

}  // namespace

void refuse_unless_fits(uint64_t bytes, const std::string& job, const std::string& details,
                        const std::string& advice, bool force) {
  if (force) return;
  const uint64_t available = memory_available();
  if (bytes <= available) return;
  throw UsageError(job + " needs about " + byte_size(bytes) + " (" + details + "), more than the " +
                   byte_size(available) +
                   " this process can have (physical memory, ulimit -v): " + advice +
                   ", or --force to try anyway");
}

void refuse_unless_image_fits(int width, int height, const std::string& advice, bool force) {
  // Peak memory per pixel, measured at 3000x3000 on the example soup (quick): 23 bytes for a
  // PNG, 43 for an EXR (the linear float film, its encoded copy, the file), rounded up.
  constexpr uint64_t kBytesPerPixel = 48;
  const uint64_t pixels = uint64_t(width) * uint64_t(height);
  refuse_unless_fits(pixels * kBytesPerPixel,
                     "a " + std::to_string(width) + "x" + std::to_string(height) + " image",
                     std::to_string(pixels) + " pixels", advice, force);
}

void refuse_unless_frames_fit_on_disk(uint64_t frames, int width, int height, int bits_per_channel,
                                      const std::string& output, bool force) {
  if (force) return;
  // Rows of 3 channels with a filter byte each, and a few KiB of headers: the most a PNG (or an
  // uncompressed TIFF or EXR) of the image can take.
  constexpr uint64_t kHeaderBytes = 4096;
  const uint64_t row = uint64_t(width) * 3 * uint64_t(bits_per_channel) / 8 + 1;
  const uint64_t per_frame = row * uint64_t(height) + kHeaderBytes;
  std::string folder = std::filesystem::path(output).parent_path().string();
  if (folder.empty()) folder = ".";
  const std::optional<uint64_t> free = free_disk_bytes(folder);
  if (!free || frames <= *free / per_frame) return;
  throw UsageError("the " + std::to_string(frames) + " frames of " + std::to_string(width) + "x" +
                   std::to_string(height) + " may need up to " + byte_size(frames * per_frame) +
                   " on disk (" + byte_size(per_frame) + " a frame, uncompressed), more than the " +
                   byte_size(*free) + " free in '" + folder +
                   "': give fewer frames (+KFI, +KFF, +SF, +EF, Frame_Step), a smaller +W and +H "
                   "or another output folder, or --force to try anyway");
}

}  // namespace convray::app
