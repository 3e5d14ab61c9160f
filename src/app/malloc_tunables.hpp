#pragma once
// glibc's malloc, tuned for convray's few large arrays: freed memory kept for the next array
// instead of handed back, and transparent huge pages where they pay on this machine
// (docs/benchmarks.md, issue 15's fourteenth and twenty-fourth steps). Only
// the dynamic loader reads GLIBC_TUNABLES, so the program sets it and executes itself once
// more, first thing in main.
#include <optional>
#include <string>

namespace convray::app {

// Seconds the first touch of one 4 KiB page takes (a page fault and its zeroing), averaged
// over 2 MiB of them, or nothing where the kernel gives no transparent huge pages to ask for
// (THP "never", no sysfs, or not Linux). Under a millisecond; the memory is handed back.
std::optional<double> probe_small_page_touch();

// Whether malloc should ask for transparent huge pages, given probe_small_page_touch: where a
// small page's first touch costs more than kHugePagesPayAbove seconds. Huge pages save the
// faults (one instead of 512), which is all they can save: on bare metal a fault costs about
// a microsecond, and huge pages would save a millisecond or two for a large mesh. On a virtual
// machine whose host takes back the guest's free memory, the free 2 MiB blocks are the ones
// taken back: there a huge page's first touch cost 4-5 times its small pages' (1.5-2.5 ms a
// MiB against 0.35-0.5, an Intel host whose small faults took 1-2.3 us), while on a host
// whose small faults took 7-11 us huge pages halved a start-up (docs/benchmarks.md).
constexpr double kHugePagesPayAbove = 4e-6;
bool huge_pages_pay(std::optional<double> small_page_touch);

// GLIBC_TUNABLES with convray's malloc tunables added after `before` (a user's own, kept).
std::string malloc_tunables(const std::string& before, bool huge_pages);

// Where GLIBC_TUNABLES does not yet say glibc.malloc.hugetlb (so once per process chain, and
// never against a user's own choice such as glibc.malloc.hugetlb=0), adds convray's malloc
// tunables to it and executes /proc/self/exe with the same arguments. Returns only when that
// is not done or fails (the environment is then as it was): the program goes on as before.
void reexec_with_malloc_tunables(char** argv);

}  // namespace convray::app
