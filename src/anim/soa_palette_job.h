#pragma once
// The palette job on a pose in structure of arrays: anim::PaletteJob's bones, bit for bit. Four joints'
// local transforms become affine rows at once (SoA), turned into one row set a joint; the hierarchy,
// joint after joint (a child needs its parent), composes rows as Float4s: three broadcasts, three
// multiplies and three adds a row instead of twelve scalar multiply-adds.
#include <cstdint>
#include <span>

#include "anim/affine.h"
#include "anim/clip_library.h"
#include "anim/soa_transform.h"

namespace anim {

struct SoaPaletteJob {
    const ClipLibrary* library = nullptr;
    std::uint32_t model = 0;
    Affine placement{};  // world transform of the character (anim::placementAffine)
    std::span<const SoaTransform> locals;  // soaGroups(joints) groups
    std::span<Affine> scratch;  // world transforms of the joints, one per joint (Crowd::jointWorld reads them)
    std::span<gpu::BoneRows> output;

    bool validate() const;
    void run() const;  // with simd::NativeFloat4
    template <class F>
    void runWith() const;  // F: simd::NativeFloat4 or simd::LaneFloat4
};

}  // namespace anim
