#include "skin/skinning_method.h"

#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"

#include "skin/compute_skinning.h"
#include "skin/direct_fragment_skinning.h"
#include "skin/fragment_skinning.h"
#include "skin/skin_target_layout.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/vertex_shader_skinning.h"

namespace skin {

const char* methodName(Method method) {
    switch (method) {
        case Method::VertexShader: return "vs";
        case Method::VertexShaderInstanced: return "vs-instanced";
        case Method::TwoPass: return "two-pass";
        case Method::TwoPassDirect: return "two-pass-direct";
        case Method::Compute: return "compute";
        case Method::Static: return "static";
    }
    return "?";
}

std::vector<Method> allMethods() {
    return {Method::VertexShader, Method::VertexShaderInstanced, Method::TwoPass,
            Method::TwoPassDirect, Method::Compute, Method::Static};
}

bool parseMethod(const std::string& name, Method& method) {
    for (Method m : allMethods())
        if (name == methodName(m)) return method = m, true;
    return false;
}

std::unique_ptr<SkinningMethod> createSkinningMethod(Method method, const MethodSetup& setup) {
    switch (method) {
        case Method::VertexShader:
            // It binds each character's bones at a dynamic uniform offset, which must be aligned.
            if (!setup.crowd.bonesAligned())
                throw gpu::Error("method vs: this crowd's bone matrices fit the device's storage-buffer range only "
                                 "packed tightly, and vs binds each character's at an aligned offset; use another "
                                 "method or fewer characters");
            return std::make_unique<VertexShaderSkinning>(false);
        case Method::VertexShaderInstanced: return std::make_unique<VertexShaderSkinning>(true);
        case Method::TwoPass: return std::make_unique<FragmentSkinning>(setup);
        case Method::TwoPassDirect: return std::make_unique<DirectFragmentSkinning>(setup);
        case Method::Compute: return std::make_unique<ComputeSkinning>(setup, ComputeSkinning::Every::Frame);
        case Method::Static: return std::make_unique<ComputeSkinning>(setup, ComputeSkinning::Every::CharacterOnce);
    }
    return nullptr;
}

render::BoneBlocks boneBlocksFor(Method method, render::AnimationPath animation) {
    const bool everyCharacter =
        method == Method::VertexShader || method == Method::Static || animation == render::AnimationPath::Cpu;
    return everyCharacter ? render::BoneBlocks::PerCharacter : render::BoneBlocks::PerMeshSlot;
}

std::uint64_t estimateMethodBytes(Method method, std::uint64_t characters, std::uint64_t skinnedCapacity,
                                  std::uint64_t fixedCapacity, std::uint32_t maxTargetDimension) {
    switch (method) {
        case Method::VertexShader:
        case Method::VertexShaderInstanced: return 0;
        case Method::Compute:
        case Method::TwoPassDirect: return SkinnedVertexBuffer::bytesFor(skinnedCapacity);
        case Method::Static:
            // the fixed layout, and a list of every character per bucket
            return SkinnedVertexBuffer::bytesFor(fixedCapacity) + characters * LOD_COUNT * 4;
        case Method::TwoPass:
            return SkinnedVertexBuffer::bytesFor(skinnedCapacity) +
                   planSkinTargets(skinnedCapacity, maxTargetDimension).bytes();
    }
    return 0;
}

}  // namespace skin
