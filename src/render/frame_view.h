#pragma once
// How a frame sees the crowd: the host's view and projection matrices, its viewport and the
// animation time. Culling, levels of detail, the shadow map's fit and fog all derive from these.
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "render/camera.h"

namespace render {

struct FrameView {
    glm::mat4 view{1.0f};
    // Vulkan clip space: y down, depth 0 at the near plane and 1 at the far one (perspective).
    glm::mat4 projection{1.0f};
    VkRect2D viewport{};
    double time = 0.0;  // seconds, the crowd's clock (a double: exact at any scene time)
};

// The camera the matrices describe: eye, a target one unit ahead, field of view and planes. A far
// plane at infinity becomes a large finite one.
Camera cameraOf(const FrameView& view);
float aspectOf(const FrameView& view);
// The programs' way: a camera and an image size.
FrameView frameViewOf(const Camera& camera, VkExtent2D extent, double time);
// Whether the matrices are a usable perspective view (finite, invertible, a positive field of view).
bool isPerspectiveView(const FrameView& view);

}  // namespace render
