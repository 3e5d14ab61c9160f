#pragma once
// glibc's malloc, tuned for convray's few large arrays: transparent huge pages, and freed
// memory kept for the next array instead of handed back (docs/benchmarks.md, "Start-up in
// huge pages"). Only the dynamic loader reads GLIBC_TUNABLES, so the program sets it and
// executes itself once more, first thing in main.

namespace convray::app {

// Where GLIBC_TUNABLES does not yet say glibc.malloc.hugetlb (so once per process chain, and
// never against a user's own choice such as glibc.malloc.hugetlb=0), adds convray's malloc
// tunables to it and executes /proc/self/exe with the same arguments. Returns only when that
// is not done or fails (the environment is then as it was): the program goes on as before.
void reexec_with_malloc_tunables(char** argv);

}  // namespace convray::app
