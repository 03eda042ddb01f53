#pragma once
// The rules of driven characters (shaders/driven_keys.h) for the CPU: the same source the shaders
// compile, here with glm's functions and gpu_types.h's types, so the CPU's keys and poses are the GPU's.
#include <glm/glm.hpp>

#include "gpu_types.h"

namespace crowd::driven {

using namespace glm;
using gpu::DrivenKey;
using gpu::DrivenModel;
using gpu::uint;

#include "driven_keys.h"

}  // namespace crowd::driven
