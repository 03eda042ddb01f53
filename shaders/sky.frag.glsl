#version 460
#extension GL_GOOGLE_include_directive : require
// The sky's one colour, the one the ground and far characters fade into (crowdgpu::kHorizonColor),
// opaque, as the clear that it replaces.
#include "gpu_types.h"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(scene.skyColor.rgb, 1.0); }
