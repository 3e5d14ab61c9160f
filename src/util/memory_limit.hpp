#pragma once
// How much more memory this process can have: what jobs are sized against before they start,
// so that a job that cannot fit is refused with its estimate instead of running out of memory
// an hour in (issue 17).
#include <cstdint>
#include <string>

namespace convray {

// The smaller of the machine's physical memory (sysconf) and, under an address-space limit
// (RLIMIT_AS, `ulimit -v`), that limit less the address space the process already maps.
uint64_t memory_available();

// "512 MB", "7.6 GB": decimal units, two or three significant digits.
std::string byte_size(uint64_t bytes);

}  // namespace convray
