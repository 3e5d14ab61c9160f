#include "app/size_check.hpp"

#include "app/usage_error.hpp"
#include "util/memory_limit.hpp"

namespace convray::app {

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

}  // namespace convray::app
