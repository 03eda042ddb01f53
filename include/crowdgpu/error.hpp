// crowdgpu: the one exception type of the C++ API.
#pragma once

#include <stdexcept>
#include <string>

namespace crowdgpu {

// What went wrong, for a host that reacts differently to each (the C API returns the same codes).
enum class ErrorCode {
    InvalidArgument = 1,   // a value out of range, an unknown name, a malformed view
    Unsupported = 2,       // the device lacks a feature, format or limit the library needs
    OutOfDeviceMemory = 3, // the configuration does not fit the device (see memoryNeeded)
    OutOfHostMemory = 4,
    WrongOrder = 5,        // a record call out of order, or before setup was recorded
    LoadFailed = 6,        // a model file that cannot be read or is not a usable glTF character
    Vulkan = 7,            // a Vulkan call failed (the message names it and its VkResult)
    CapacityExceeded = 8,  // a spawn past the crowd's capacity for that model (Crowd::spawn)
};

// Every failure of the library throws this: a one-line message that says what and where, in the
// library's words (never a command-line flag), and a code. Nothing is left half-made when it throws.
class Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ErrorCode code() const { return code_; }

private:
    ErrorCode code_;
};

}  // namespace crowdgpu
