#pragma once
// A skinned character: mesh, skeleton, clips and material palette, ready for the GPU.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"
#include "anim/skeleton.h"
#include "gpu_types.h"

namespace model {

// Number of levels of detail a model has (model/lod_builder.h): the paper's soldier has three
// (1,084 / 544 / 312 polygons).
inline constexpr std::size_t kLodLevels = 3;

struct SkinnedModel {
    std::string name;
    anim::Skeleton skeleton;
    // Bind-pose vertices in model space; joints index skeleton joints.
    std::vector<gpu::SkinVertex> vertices;
    // Triangle list, counter-clockwise when seen from outside.
    std::vector<std::uint32_t> indices;
    std::vector<anim::Clip> clips;
    // Colour per material index (SkinVertex::normal.w); at most MAX_MODEL_MATERIALS.
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
    // Axis-aligned bounds of the bind pose in model space (y is up), props left out (the body's).
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{0.0f};

    // Levels of detail over the one vertex array (model/lod_builder.h fills them). Level l draws
    // lods[l].indices, a triangle list that references only vertices [0, lods[l].vertexCount): the
    // vertices are ordered so that a coarser level uses a prefix of a finer one's, and skinning work
    // shrinks with the level. lods[0] is the full mesh (its indices equal `indices`). Empty until built.
    struct Lod {
        std::vector<std::uint32_t> indices;
        std::uint32_t vertexCount = 0;
    };
    std::vector<Lod> lods;
    // A sphere in model space holding every vertex in every pose of every clip (and the rest pose):
    // xyz centre, w radius (crowd/pose_bounds.h). Culling tests it; zero until computed.
    glm::vec4 poseSphere{0.0f};
    // Rigid props attached to joints (model/attach_prop.h), at most MAX_PROPS: prop k is moved by its
    // own joint (skeleton.propOfJoint == k + 1), a child of the joint it is attached to.
    struct PropPart {
        std::string name;
        std::uint32_t joint = 0;       // the prop's own joint
        std::uint32_t attachedTo = 0;  // the joint it hangs from
        float share = 1.0f;            // of the characters that carry it when they do not choose
        // The prop's own triangles at levels 1 and 2 (coarserLevels[l - 1], model vertex indices; its
        // level 0 is part of `indices`), which buildLods draws beside the body's simplified levels
        // instead of simplifying the prop with the body. Empty: not drawn at that level.
        std::array<std::vector<std::uint32_t>, kLodLevels - 1> coarserLevels;
    };
    std::vector<PropPart> props;

    // The height the ground band of root-motion measurement scales with (model/measure_root_motion.h);
    // 0: height(). A mounted model keeps its mount's, so that it travels exactly as its mount alone.
    float footingHeight = 0.0f;

    std::size_t triangleCount() const { return indices.size() / 3; }
    float height() const { return boundsMax.y - boundsMin.y; }
    // Index of the clip with this name, or -1.
    int findClip(const std::string& clipName) const;
};

// Recomputes boundsMin/boundsMax from the vertices, those of props (model/attach_prop.h) left out.
void computeBounds(SkinnedModel& model);

}  // namespace model
