#pragma once
// How much host memory this machine can give a run, for refusing a crowd before it is built.
#include <cstdint>

namespace app {

// Memory the kernel could give without swapping (Linux: MemAvailable), or 0 when unknown.
std::uint64_t availableHostBytes();

}  // namespace app
