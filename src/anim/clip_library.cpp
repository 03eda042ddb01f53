#include "anim/clip_library.h"

#include <limits>
#include <string>

#include "anim/affine.h"
#include "anim/skinning_matrices.h"
#include "gpu/error.h"

namespace anim {
namespace {

std::uint32_t pathSlot(ChannelPath path) {
    switch (path) {
        case ChannelPath::Translation: return 0;
        case ChannelPath::Rotation: return 1;
        case ChannelPath::Scale: return 2;
    }
    return 0;
}

std::uint32_t interpolationCode(Interpolation interpolation) {
    switch (interpolation) {
        case Interpolation::Step: return 0;
        case Interpolation::Linear: return 1;
        case Interpolation::CubicSpline: return 2;
    }
    return 1;
}

std::uint32_t checkedIndex(std::size_t size) {
    if (size > std::numeric_limits<std::uint32_t>::max())
        throw gpu::Error("animation library: more keys than 32-bit indices address");
    return static_cast<std::uint32_t>(size);
}

}  // namespace

std::uint32_t ClipLibrary::addModel(const Skeleton& skeleton, std::span<const Clip> clips,
                                    std::span<const RootMotion> rootMotion) {
    const auto joints = static_cast<std::uint32_t>(skeleton.jointCount());
    if (joints == 0 || joints > MAX_ANIMATION_JOINTS)
        throw gpu::Error("animation library: a model has " + std::to_string(joints) + " joints; 1 to " +
                         std::to_string(MAX_ANIMATION_JOINTS) + " are supported");
    gpu::AnimationModel model{};
    model.info = glm::uvec4(checkedIndex(joints_.size()), joints, checkedIndex(clips_.size()),
                            static_cast<std::uint32_t>(clips.size()));
    model.root = toRows(skeleton.rootTransform);
    models_.push_back(model);
    for (std::uint32_t j = 0; j < joints; ++j) {
        const Transform& rest = skeleton.restPose[j];
        gpu::AnimationJoint joint{};
        joint.restTranslation = glm::vec4(rest.translation, static_cast<float>(skeleton.parents[j]));
        joint.restRotation = glm::vec4(rest.rotation.x, rest.rotation.y, rest.rotation.z, rest.rotation.w);
        joint.restScale = glm::vec4(rest.scale, j < skeleton.propOfJoint.size() ? static_cast<float>(skeleton.propOfJoint[j]) : 0.0f);
        joint.inverseBind = toRows(skeleton.inverseBind[j]);
        joints_.push_back(joint);
    }
    for (std::size_t c = 0; c < clips.size(); ++c)
        addClip(clips[c], joints, c < rootMotion.size() ? &rootMotion[c] : nullptr);
    return static_cast<std::uint32_t>(models_.size() - 1);
}

void ClipLibrary::addClip(const Clip& clip, std::uint32_t joints, const RootMotion* rootMotion) {
    gpu::AnimationClip record{};
    const RootMotion inPlace{};
    const RootMotion& motion = rootMotion ? *rootMotion : inPlace;
    record.info = glm::uvec4(checkedIndex(tracks_.size()), checkedIndex(rootSamples_.size()), 0u, 0u);
    record.timing = glm::vec4(clip.duration, 0.0f, motion.stride.x, motion.stride.y);
    clips_.push_back(record);
    rootSamples_.insert(rootSamples_.end(), motion.samples.begin(), motion.samples.end());
    // Every (joint, path) gets a track; one without keys keeps the rest value. A later channel on the
    // same joint and path wins, as it does in sampleClip.
    const std::size_t firstTrack = tracks_.size();
    tracks_.resize(firstTrack + 3u * joints, gpu::AnimationTrack{0u, 0u, 1u, 0u});
    for (const Channel& channel : clip.channels) {
        if (channel.joint >= joints || channel.times.empty()) continue;
        gpu::AnimationTrack& track = tracks_[firstTrack + 3u * channel.joint + pathSlot(channel.path)];
        track = {checkedIndex(times_.size()), checkedIndex(channel.times.size()), interpolationCode(channel.interpolation),
                 checkedIndex(values_.size())};
        times_.insert(times_.end(), channel.times.begin(), channel.times.end());
        values_.insert(values_.end(), channel.values.begin(), channel.values.end());
    }
}

glm::vec2 ClipLibrary::stride(std::uint32_t model, std::uint32_t clip) const {
    const glm::vec4& timing = this->clip(model, clip).timing;
    return {timing.z, timing.w};
}

glm::vec2 ClipLibrary::rootMotion(std::uint32_t model, std::uint32_t clip, float phase) const {
    return rootMotionAt(rootMotionSamples(model, clip), phase);
}

const glm::vec2* ClipLibrary::rootMotionSamples(std::uint32_t model, std::uint32_t clip) const {
    return rootSamples_.data() + this->clip(model, clip).info.y;
}

std::uint64_t ClipLibrary::bytes() const {
    return models_.size() * sizeof(gpu::AnimationModel) + joints_.size() * sizeof(gpu::AnimationJoint) +
           clips_.size() * sizeof(gpu::AnimationClip) + tracks_.size() * sizeof(gpu::AnimationTrack) +
           times_.size() * sizeof(float) + values_.size() * sizeof(glm::vec4) + rootSamples_.size() * sizeof(glm::vec2);
}

}  // namespace anim
