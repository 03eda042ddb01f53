#pragma once
// A skinned character: mesh, skeleton, clips and material palette, ready for the GPU.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"
#include "anim/skeleton.h"
#include "gpu_types.h"

namespace model {

struct SkinnedModel {
    std::string name;
    anim::Skeleton skeleton;
    // Bind-pose vertices in model space; joints index skeleton joints.
    std::vector<gpu::SkinVertex> vertices;
    // Triangle list, counter-clockwise when seen from outside.
    std::vector<std::uint32_t> indices;
    std::vector<anim::Clip> clips;
    // Colour per material index (SkinVertex::normal.w); at most MAX_MATERIALS.
    std::vector<glm::vec4> materialColors;
    // Texture coordinates per vertex (glTF convention: origin at the image's top left); empty when the
    // model has none. Only the glTF loader fills them; the built-in models are flat-coloured.
    std::vector<glm::vec2> uvs;
    // The base-colour texture as 8-bit RGBA rows from the top (sRGB, as glTF stores it); empty when
    // none. A model has at most one: when materials use different images the loader keeps the first.
    struct Texture {
        std::uint32_t width = 0;
        std::uint32_t height = 0;
        std::vector<std::uint8_t> rgba;
    } baseColorTexture;
    // Bit m set: material m's colour is materialColors[m] times baseColorTexture at the vertex's uv
    // (glTF's baseColorFactor * baseColorTexture); clear: materialColors[m] alone.
    std::uint32_t texturedMaterials = 0;
    // Axis-aligned bounds of the bind pose in model space (y is up).
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{0.0f};

    std::size_t triangleCount() const { return indices.size() / 3; }
    float height() const { return boundsMax.y - boundsMin.y; }
    // Index of the clip with this name, or -1.
    int findClip(const std::string& clipName) const;
};

// Recomputes boundsMin/boundsMax from the vertices.
void computeBounds(SkinnedModel& model);

}  // namespace model
