#pragma once
// The library's failures as one exception type, without Vulkan: the core (models, animation, crowd)
// throws it too. gpu/vulkan_error.h adds the Vulkan calls' failures.
#include <stdexcept>
#include <string>

namespace gpu {

// What kind of failure, for the library's error codes (crowdgpu::ErrorCode has the same values).
enum class ErrorKind {
    InvalidArgument = 1, Unsupported, OutOfDeviceMemory, OutOfHostMemory, WrongOrder, LoadFailed, Vulkan, CapacityExceeded
};

// A failure the user can act on (no device, out of memory, bad input): main() prints what() as
// one line and exits non-zero.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, ErrorKind kind = ErrorKind::InvalidArgument)
        : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const { return kind_; }

private:
    ErrorKind kind_;
};

}  // namespace gpu
