#pragma once
// The programs' failures: a message for the user (a bad flag, a file that cannot be written, no
// device), printed by main() as one line before a non-zero exit. The library throws crowdapp::Error.
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace app {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "VK_ERROR_OUT_OF_DEVICE_MEMORY", ...
const char* resultName(VkResult result);

// Throws Error naming `call` and the result when `result` is an error code.
void check(VkResult result, const char* call);

}  // namespace app

// Checks a Vulkan call, naming it in the error.
#define CHECK_VK(call) ::app::check((call), #call)
