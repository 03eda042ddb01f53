#include "skin/skinning_method.h"

#include "skin/fragment_skinning.h"
#include "skin/skin_target_layout.h"
#include "skin/vertex_shader_skinning.h"

namespace skin {

const char* methodName(Method method) {
    switch (method) {
        case Method::VertexShader: return "vs";
        case Method::TwoPass: return "two-pass";
    }
    return "?";
}

std::vector<Method> allMethods() { return {Method::VertexShader, Method::TwoPass}; }

bool parseMethod(const std::string& name, Method& method) {
    for (Method m : allMethods())
        if (name == methodName(m)) return method = m, true;
    return false;
}

std::unique_ptr<SkinningMethod> createSkinningMethod(Method method, const MethodSetup& setup) {
    switch (method) {
        case Method::VertexShader: return std::make_unique<VertexShaderSkinning>(setup);
        case Method::TwoPass: return std::make_unique<FragmentSkinning>(setup);
    }
    return nullptr;
}

std::uint64_t estimateMethodBytes(Method method, std::uint32_t vertexCount, std::uint32_t characterCount,
                                  std::uint32_t maxTargetDimension) {
    if (method == Method::VertexShader) return 0;
    const SkinTargetLayout layout = planSkinTargets(vertexCount, characterCount, maxTargetDimension);
    const std::uint64_t texels = static_cast<std::uint64_t>(layout.characterStride()) * characterCount;
    // Two RGBA32F targets plus the vertex buffer they are copied into (positions and normals).
    return texels * 16 * 2 * 2 + static_cast<std::uint64_t>(characterCount) * 20;
}

}  // namespace skin
