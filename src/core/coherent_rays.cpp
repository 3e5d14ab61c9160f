#include "core/coherent_rays.hpp"

namespace convray {
namespace {

thread_local uint64_t current_run = 0;

}  // namespace

void begin_coherent_rays() { ++current_run; }

uint64_t coherent_run() { return current_run; }

}  // namespace convray
