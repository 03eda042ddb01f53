#include "skin/skinning_method.h"

#include "skin/compute_skinning.h"
#include "skin/direct_fragment_skinning.h"
#include "skin/fragment_skinning.h"
#include "skin/instanced_vertex_skinning.h"
#include "skin/skin_target_layout.h"
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
        case Method::VertexShader: return std::make_unique<VertexShaderSkinning>(setup);
        case Method::VertexShaderInstanced: return std::make_unique<InstancedVertexSkinning>(setup);
        case Method::TwoPass: return std::make_unique<FragmentSkinning>(setup);
        case Method::TwoPassDirect: return std::make_unique<DirectFragmentSkinning>(setup);
        case Method::Compute: return std::make_unique<ComputeSkinning>(setup, false);
        case Method::Static: return std::make_unique<ComputeSkinning>(setup, true);
    }
    return nullptr;
}

std::uint64_t estimateMethodBytes(Method method, std::uint32_t vertexCount, std::uint32_t characterCount,
                                  std::uint32_t maxTargetDimension) {
    const std::uint64_t drawCommands = static_cast<std::uint64_t>(characterCount) * 20;
    const std::uint64_t skinnedVertexBytes = 2 * 16;  // position and normal, RGBA32F each
    switch (method) {
        case Method::VertexShader:
        case Method::VertexShaderInstanced: return 0;
        case Method::Compute:
        case Method::Static:
            return static_cast<std::uint64_t>(vertexCount) * characterCount * skinnedVertexBytes + drawCommands;
        case Method::TwoPass:
        case Method::TwoPassDirect: break;
    }
    const SkinTargetLayout layout = planSkinTargets(vertexCount, characterCount, maxTargetDimension);
    const std::uint64_t texels = static_cast<std::uint64_t>(layout.characterStride()) * characterCount;
    // two-pass: two RGBA32F targets plus the vertex buffer they are copied into.
    const std::uint64_t images = method == Method::TwoPass ? texels * skinnedVertexBytes : 0;
    return images + texels * skinnedVertexBytes + drawCommands;
}

}  // namespace skin
