#pragma once
// The interface every skinning method implements, so the renderer, the benchmark, the viewer and the
// tests treat them alike: prepare resources for a crowd; record a frame; report what it allocated.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/scene_pass.h"

namespace gpu {
class VulkanContext;
class GpuTimer;
struct Buffer;
}  // namespace gpu
namespace render { class CrowdBuffers; }

namespace skin {

enum class Method { VertexShader, VertexShaderInstanced, TwoPass, TwoPassDirect, Compute, Static };

// "vs", "vs-instanced", "two-pass", "two-pass-direct", "compute", "static"; parseMethod returns false
// for an unknown name.
const char* methodName(Method method);
bool parseMethod(const std::string& name, Method& method);
std::vector<Method> allMethods();

struct MemoryItem {
    std::string what;
    std::uint64_t bytes;
};

// Where a method leaves the skinned world-space vertices (methods that skin while drawing leave none).
struct SkinnedVertices {
    const gpu::Buffer* buffer = nullptr;
    VkDeviceSize normalsOffset = 0;       // bytes from the start of the buffer to the first normal
    std::uint32_t characterStride = 0;    // vertices from one character's first vertex to the next's
};

struct MethodSetup {
    const gpu::VulkanContext& context;
    const render::CrowdBuffers& crowd;
    VkDescriptorSetLayout sceneSetLayout;
    // Largest skinning target side in texels; 0 uses the device limit (tests lower it to force tiling).
    std::uint32_t maxTargetDimension = 0;
};

class SkinningMethod {
public:
    virtual ~SkinningMethod() = default;
    virtual Method method() const = 0;
    // Records the work that precedes the scene pass (skinning, copies), marking each pass on the timer.
    virtual void recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) = 0;
    // Records the characters' draws inside the scene pass.
    virtual void recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) = 0;
    // Buffers and images this method allocated for the crowd (beyond the shared crowd buffers).
    virtual std::vector<MemoryItem> memory() const = 0;
    virtual SkinnedVertices skinnedVertices() const { return {}; }
    // False once the method no longer reads bones (the static ceiling): the frame then skips
    // animation and the bone upload.
    virtual bool needsAnimation() const { return true; }
};

std::unique_ptr<SkinningMethod> createSkinningMethod(Method method, const MethodSetup& setup);

// Device memory a method needs for this crowd, beyond the shared crowd buffers: checked before any
// allocation so an impossible --count fails with a clear message instead of a driver error.
std::uint64_t estimateMethodBytes(Method method, std::uint32_t vertexCount, std::uint32_t characterCount,
                                  std::uint32_t maxTargetDimension);

}  // namespace skin
