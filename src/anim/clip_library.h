#pragma once
// Every clip of a crowd's models flattened into key arrays, ozz-animation's runtime layout: one track
// per (clip, joint, path) naming a range of key times and values, skeletons as joint tables, one
// root-motion curve per clip. The CPU jobs read these arrays and the GPU path uploads them once,
// unchanged (render/animation_pass.h), so both paths animate from the same data.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"
#include "anim/root_motion.h"
#include "anim/skeleton.h"
#include "gpu_types.h"

namespace anim {

class ClipLibrary {
public:
    // Adds a model's skeleton and clips with one root-motion curve per clip (an empty span: every clip
    // in place). Returns the model's index. Throws gpu::Error past MAX_ANIMATION_JOINTS joints or when
    // the tables would outgrow 32-bit indices.
    std::uint32_t addModel(const Skeleton& skeleton, std::span<const Clip> clips, std::span<const RootMotion> rootMotion);

    std::uint32_t modelCount() const { return static_cast<std::uint32_t>(models_.size()); }
    std::uint32_t jointCount(std::uint32_t model) const { return models_[model].info.y; }
    std::uint32_t clipCount(std::uint32_t model) const { return models_[model].info.w; }
    // The library-wide index of a model's clip.
    std::uint32_t clipIndex(std::uint32_t model, std::uint32_t clip) const { return models_[model].info.z + clip; }
    const gpu::AnimationClip& clip(std::uint32_t model, std::uint32_t clip) const { return clips_[clipIndex(model, clip)]; }
    float duration(std::uint32_t model, std::uint32_t clip) const { return this->clip(model, clip).timing.x; }
    glm::vec2 stride(std::uint32_t model, std::uint32_t clip) const;
    // Root motion of a model's clip at `phase` cycles (model space x, z).
    glm::vec2 rootMotion(std::uint32_t model, std::uint32_t clip, float phase) const;
    // The clip's root-motion samples, for anim::rootMotionAt in loops that evaluate one clip many times.
    const glm::vec2* rootMotionSamples(std::uint32_t model, std::uint32_t clip) const;

    // The flat tables, as the GPU receives them.
    const std::vector<gpu::AnimationModel>& models() const { return models_; }
    const std::vector<gpu::AnimationJoint>& joints() const { return joints_; }
    const std::vector<gpu::AnimationClip>& clips() const { return clips_; }
    const std::vector<gpu::AnimationTrack>& tracks() const { return tracks_; }
    const std::vector<float>& keyTimes() const { return times_; }
    const std::vector<glm::vec4>& keyValues() const { return values_; }
    const std::vector<glm::vec2>& rootSamples() const { return rootSamples_; }
    std::uint64_t bytes() const;

private:
    void addClip(const Clip& clip, std::uint32_t joints, const RootMotion* rootMotion);

    std::vector<gpu::AnimationModel> models_;
    std::vector<gpu::AnimationJoint> joints_;
    std::vector<gpu::AnimationClip> clips_;
    std::vector<gpu::AnimationTrack> tracks_;
    std::vector<float> times_;
    std::vector<glm::vec4> values_;
    std::vector<glm::vec2> rootSamples_;
};

}  // namespace anim
