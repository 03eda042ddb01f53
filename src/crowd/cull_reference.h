#pragma once
// Frustum culling and level-of-detail choice on the CPU: the reference the GPU cull pass is tested
// against (the same operations as shaders/cull.glsl.inc, in the same order), and the `--cull cpu`
// path. It reads the same records the GPU reads, so both see identical inputs.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace crowd {

// The six planes of a Vulkan view-projection (clip x, y in [-w, w], z in [0, w]), normals pointing
// inside, normalized so that plane distances are in world units.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProjection);

glm::vec4 worldSphere(const gpu::CharacterRecord& character, const gpu::ModelRecord& model);
bool sphereInFrustum(const glm::vec4 planes[6], const glm::vec4& sphere);
bool casterInFrustum(const glm::vec4 planes[6], const glm::vec4& sphere, const glm::vec3& towardsLight);
float projectedDiameter(const glm::vec4& sphere, const glm::vec4& camera);
std::uint32_t lodForSize(float size, const glm::vec4& lod, float scale);
std::uint32_t chooseLod(float size, std::uint32_t previous, const glm::vec4& lod);
// Fades (cull.fade.x): the level a character is listed and skinned at (the finer of the two it fades
// between), and the coarser one's share in steps of 1/FADE_STEPS (0: not fading), as shaders/cull.glsl.inc.
std::uint32_t fadedLod(float size, const glm::vec4& lod);
std::uint32_t fadeShare(float size, std::uint32_t finer, const glm::vec4& lod);
// The shadow cascades whose volumes a sphere reaches, a bit each (gpu_types.h, SHADOW_CASCADE_SHIFT).
std::uint32_t cascadesReached(const glm::vec4& sphere, const gpu::CullUniforms& cull);
// A character's shadow this frame (gpu_types.h, SHADOW_*): in view, casting, its level in the shadow map,
// the cascades it is drawn in.
std::uint32_t shadowState(const glm::vec4& sphere, std::uint32_t viewLod, bool inView, const gpu::CullUniforms& cull);

// Visible characters per bucket (model x LOD_COUNT + lod), in character order.
using VisibleLists = std::vector<std::vector<std::uint32_t>>;

// What the shadow pass draws: mesh casters per bucket of their shadow level, impostor-level casters
// (quads facing the light), both in character order, and every character's shadow state.
struct ShadowLists {
    VisibleLists casters;
    std::vector<std::uint32_t> impostors;
    std::vector<std::uint32_t> states;
};

// Culls and picks levels for every character as the GPU pass does. `lodState` holds each character's
// last level + 1 (0: none yet) and is updated, as the GPU keeps it. With fades, a character in view
// fading from the last mesh level is listed both in its bucket and among the impostors, and its shadow
// state carries its fade (gpu_types.h, FADE_SHIFT; dropped when the cap demotes it). A character in view is listed at
// its level in view, a shadow caster out of view at its shadow level. With a mesh-level cap
// (cull.limits.z), the characters beyond it are demoted smallest on screen first
// (crowd/farthest_first.h); `demoted` counts them when given. Characters at the impostor level or
// demoted that are in view go to `impostors` when given, in character order; the shadow pass's lists
// go to `shadows` when given.
VisibleLists cullOnCpu(const gpu::CullUniforms& cull, std::span<const gpu::CharacterRecord> characters,
                       std::span<const gpu::ModelRecord> models, std::span<std::uint32_t> lodState,
                       std::vector<std::uint32_t>* impostors = nullptr, std::uint32_t* demoted = nullptr,
                       ShadowLists* shadows = nullptr);

}  // namespace crowd
