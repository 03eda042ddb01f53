#pragma once
// The interface every skinning method implements, so the renderer, the benchmark, the viewer and the
// tests treat them alike: prepare resources for a crowd; record the skinning of a frame's visible
// characters; say what it produced for the draw pass to consume; report what it allocated.
//
// A method *produces*: world-space vertices in a buffer (render::DrawInput::SkinnedVertices), laid
// out as culling placed them (render/draw_lists.h), or nothing, when the draw skins the bind pose as
// it goes (the vertex-shader methods). Drawing is not a method's business (render/character_draw.h).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/pass_observer.h"
#include "render/animation_pass.h"
#include "render/character_draw.h"

namespace gpu {
class VulkanContext;
}  // namespace gpu
namespace render {
class CrowdBuffers;
class DrawLists;
class GeometryPool;
}  // namespace render

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

struct MethodSetup {
    const gpu::VulkanContext& context;
    const render::GeometryPool& pool;
    const render::CrowdBuffers& crowd;
    const render::DrawLists& lists;
    // Largest skinning target side in texels; 0 uses the device limit (tests lower it to force tiling).
    std::uint32_t maxTargetDimension = 0;
};

class SkinningMethod {
public:
    virtual ~SkinningMethod() = default;
    virtual Method method() const = 0;
    // What the draw pass consumes from this method.
    virtual render::DrawInput drawInput() const { return render::DrawInput::SkinnedVertices; }
    // Records the work between culling and drawing (skinning, copies), telling `passes` as each ends.
    virtual void recordSkinning(VkCommandBuffer, const gpu::PassObserver&) {}
    virtual render::SkinnedVertices skinnedVertices() const { return {}; }
    // Buffers and images this method allocated for the crowd.
    virtual std::vector<MemoryItem> memory() const { return {}; }
    // False once the method no longer reads bones (the static ceiling): the frame then skips
    // animation and the bone upload.
    virtual bool needsAnimation() const { return true; }
    // The population changed: a method that skinned every character once (static) skins them again.
    virtual void invalidateSkinning() {}
    // True when every character has its own skinned slot at every LOD (static), instead of the
    // frame's dense layout of visible characters.
    virtual bool fixedLayout() const { return false; }
};

std::unique_ptr<SkinningMethod> createSkinningMethod(Method method, const MethodSetup& setup);

// Whom the bone blocks belong to with this method and animation path (render::BoneBlocks): mesh slots,
// except where something needs every character's bones at a fixed place: vs binds them at offsets the
// CPU records, static skins every character once from CPU palettes, the CPU path uploads them all.
render::BoneBlocks boneBlocksFor(Method method, render::AnimationPath animation);

// Device memory a method needs for a crowd whose worst frame skins `skinnedCapacity` vertices (every
// character visible at LOD 0) and whose fixed layout holds `fixedCapacity` (every character at every
// LOD): checked before any allocation so an impossible --count fails with a clear message.
std::uint64_t estimateMethodBytes(Method method, std::uint64_t characters, std::uint64_t skinnedCapacity,
                                  std::uint64_t fixedCapacity, std::uint32_t maxTargetDimension);

}  // namespace skin
