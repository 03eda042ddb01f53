#pragma once
// Palette job: a pose's local transforms to the bone rows the GPU skins with. One forward sweep
// composes the hierarchy (parents come before children) under the character's placement, then
// each joint's model-space transform meets its inverse bind matrix:
//   bone[j] = placement * root * local[root joint] * ... * local[j] * inverseBind[j].
#include <cstdint>
#include <span>

#include "anim/affine.h"
#include "anim/clip_library.h"

namespace anim {

struct PaletteJob {
    const ClipLibrary* library = nullptr;
    std::uint32_t model = 0;
    Affine placement{};  // world transform of the character (anim::placementAffine)
    std::span<const Transform> locals;
    std::span<Affine> scratch;  // model-space transforms, one per joint
    std::span<gpu::BoneRows> output;

    bool validate() const;
    void run() const;
};

}  // namespace anim
