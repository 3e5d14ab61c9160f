#include "app/malloc_tunables.hpp"

#include <sys/auxv.h>
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace convray::app {
namespace {

// A mesh of 200,000 triangles first-touches about 60-110 MB while it is read and made ready.
// hugetlb: malloc asks for transparent huge pages (madvise) where it grows its heaps, if
// huge_pages_pay; mmap_threshold (glibc's largest) and trim_threshold: arrays freed between
// the steps of a build are reused by the next instead of being unmapped and faulted in anew;
// top_pad: the heap grows in 32 MiB steps.
constexpr const char* kThresholds =
    "glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=4294967296:"
    "glibc.malloc.top_pad=33554432";

constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kSmallPage = 4096;

// Whether the kernel gives transparent huge pages to a range that asks (madvise or always).
bool huge_pages_offered() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  if (!std::getline(in, modes)) return false;
  return modes.find("[never]") == std::string::npos;
}

// Seconds to write one byte in each small page of [begin, begin + kHugePage).
double touch_seconds(volatile char* begin) {
  const auto start = std::chrono::steady_clock::now();
  for (size_t at = 0; at < kHugePage; at += kSmallPage) begin[at] = 1;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::optional<double> probe_small_page_touch() {
#if defined(__linux__) && defined(MADV_NOHUGEPAGE)
  if (!huge_pages_offered()) return std::nullopt;
  void* mapped = mmap(nullptr, kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                      -1, 0);
  if (mapped == MAP_FAILED) return std::nullopt;
  std::optional<double> seconds;
  if (madvise(mapped, kHugePage, MADV_NOHUGEPAGE) == 0) {
    seconds = touch_seconds(static_cast<char*>(mapped)) / double(kHugePage / kSmallPage);
  }
  munmap(mapped, kHugePage);
  return seconds;
#else
  return std::nullopt;
#endif
}

bool huge_pages_pay(std::optional<double> small_page_touch) {
  return small_page_touch && *small_page_touch > kHugePagesPayAbove;
}

std::string malloc_tunables(const std::string& before, bool huge_pages) {
  const std::string ours =
      std::string("glibc.malloc.hugetlb=") + (huge_pages ? "1:" : "0:") + kThresholds;
  return before.empty() ? ours : before + ":" + ours;
}

void reexec_with_malloc_tunables(char** argv) {
#if defined(__GLIBC__) && __GLIBC_PREREQ(2, 35)  // glibc.malloc.hugetlb is 2.35's
  if (getauxval(AT_SECURE)) return;  // the loader ignores tunables there
  if (!argv || !argv[0]) return;      // started without even a program name: leave it be
  const char* before = std::getenv("GLIBC_TUNABLES");
  if (before && std::strstr(before, "glibc.malloc.hugetlb")) return;
  const std::string saved = before ? before : "";
  const std::string tunables = malloc_tunables(saved, huge_pages_pay(probe_small_page_touch()));
  if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // No /proc, or the file is gone: go on with malloc as it is.
  if (before) {
    setenv("GLIBC_TUNABLES", saved.c_str(), 1);
  } else {
    unsetenv("GLIBC_TUNABLES");
  }
#else
  (void)argv;
#endif
}

}  // namespace convray::app
