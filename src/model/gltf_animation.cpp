// glTF animations as clips: translation, rotation and scale channels on skeleton nodes, with their
// keys checked (increasing times, enough values, unit quaternions) so sampling never reads past a
// channel or produces NaN.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "anim/pose_reach.h"
#include "model/gltf_internal.h"
#include "model/gltf_loader.h"

namespace model::gltf {
namespace {

// Most key values (times and values) of all clips together: 16 Mi keys is hours of a 100-joint rig
// at 30 Hz. Channels may share accessors, so without a budget a small file could name one big
// accessor from a million channels.
constexpr std::size_t kMaxKeyValues = std::size_t{1} << 24;

bool channelPath(const std::string& path, anim::ChannelPath& out) {
    if (path == "translation")
        out = anim::ChannelPath::Translation;
    else if (path == "rotation")
        out = anim::ChannelPath::Rotation;
    else if (path == "scale")
        out = anim::ChannelPath::Scale;
    else
        return false;
    return true;
}

anim::Interpolation interpolation(const std::string& name, const std::string& what) {
    if (name.empty() || name == "LINEAR") return anim::Interpolation::Linear;
    if (name == "STEP") return anim::Interpolation::Step;
    if (name == "CUBICSPLINE") return anim::Interpolation::CubicSpline;
    fail(what + ": unknown interpolation '" + name + "' (LINEAR, STEP or CUBICSPLINE)");
}

anim::Channel readChannel(const tinygltf::Model& model, const tinygltf::Animation& animation,
                          const tinygltf::AnimationChannel& source, anim::ChannelPath path, const std::string& what) {
    if (source.sampler < 0 || static_cast<std::size_t>(source.sampler) >= animation.samplers.size())
        fail(what + ": sampler " + std::to_string(source.sampler) + " does not exist (the animation has " +
             std::to_string(animation.samplers.size()) + ")");
    const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(source.sampler)];
    anim::Channel channel;
    channel.path = path;
    channel.interpolation = interpolation(sampler.interpolation, what);

    const FloatData times =
        readFloats(model, sampler.input, {what + " input", {TINYGLTF_TYPE_SCALAR}, {TINYGLTF_COMPONENT_TYPE_FLOAT}});
    if (times.count == 0) fail(what + ": no keys");
    channel.times = times.values;
    for (std::size_t k = 1; k < channel.times.size(); ++k)
        if (channel.times[k] < channel.times[k - 1])
            fail(what + ": key times decrease at key " + std::to_string(k) + " (they must increase)");

    const bool rotation = path == anim::ChannelPath::Rotation;
    const AccessorRule valueRule =
        rotation ? AccessorRule{what + " output",
                                {TINYGLTF_TYPE_VEC4},
                                {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}}
                 : AccessorRule{what + " output", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}};
    const FloatData values = readFloats(model, sampler.output, valueRule);
    const bool cubic = channel.interpolation == anim::Interpolation::CubicSpline;
    const std::size_t needed = times.count * (cubic ? 3 : 1);
    if (values.count < needed)
        fail(what + ": " + std::to_string(values.count) + " values for " + std::to_string(times.count) + " keys (" +
             (cubic ? "CUBICSPLINE needs 3 per key" : "needs 1 per key") + ")");
    channel.values.resize(needed);
    for (std::size_t i = 0; i < needed; ++i) {
        const float* v = values.element(i);
        channel.values[i] = rotation ? glm::vec4(v[0], v[1], v[2], v[3]) : glm::vec4(v[0], v[1], v[2], 0.0f);
        // Key values (not spline tangents) of rotations are normalized when sampled: a zero one has no direction.
        const bool keyValue = !cubic || i % 3 == 1;
        if (rotation && keyValue && !(glm::length(channel.values[i]) > 1e-6f))
            fail(what + ": rotation key " + std::to_string(cubic ? i / 3 : i) + " is not a unit quaternion");
    }
    return channel;
}

const char* pathName(anim::ChannelPath path) {
    switch (path) {
        case anim::ChannelPath::Translation: return "translation";
        case anim::ChannelPath::Rotation: return "rotation";
        case anim::ChannelPath::Scale: return "scale";
    }
    return "";
}

std::string distance(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// Fails when some pose of `clip` (channels from animation `a`; `sourceChannels` their indices there)
// could put a vertex beyond kMaxGltfPoseReach, naming the channel that takes it there.
void checkPoseReach(const anim::Skeleton& skeleton, const anim::Clip& clip, std::size_t a,
                    const std::vector<std::size_t>& sourceChannels, double maxBindDistance) {
    const anim::PoseReach reach = anim::poseReach(skeleton, clip, maxBindDistance, kMaxGltfPoseReach);
    if (reach.distance <= kMaxGltfPoseReach) return;
    const std::string beyond = "can put vertices " + distance(reach.distance) + " from the origin, beyond the " +
                               distance(kMaxGltfPoseReach) + " within which skinning stays finite";
    if (reach.channel < 0) fail("the rest pose " + beyond + " (check the node transforms and inverse bind matrices)");
    const anim::Channel& channel = clip.channels[static_cast<std::size_t>(reach.channel)];
    fail("animation " + std::to_string(a) + " '" + clip.name + "' channel " +
         std::to_string(sourceChannels[static_cast<std::size_t>(reach.channel)]) + " (" + pathName(channel.path) +
         " of joint '" + skeleton.jointNames[channel.joint] + "'): its keys " + beyond);
}

// The clip's events from the animation's extras (documented in docs/events.md):
//   "extras": {"events": [{"name": "footstep.left", "time": 0.25, "joint": "foot_l"}, ...]}
// "joint" (optional) is the name of a node of the skin's skeleton, the first of that name. Anything
// else in extras is the file's own business; a malformed "events" fails naming the field. The JSON
// types were checked on the file as written (gltf_json_types.cpp: tinygltf drops null, [] and {}
// values); here, what the values mean.
std::vector<anim::ClipEvent> readEvents(const tinygltf::Animation& animation, std::size_t a, float duration,
                                       const std::vector<std::string>& jointNames) {
    std::vector<anim::ClipEvent> events;
    if (!animation.extras.IsObject() || !animation.extras.Has("events")) return events;
    const std::string field = "animations[" + std::to_string(a) + "].extras.events";
    const tinygltf::Value& list = animation.extras.Get("events");
    for (std::size_t e = 0; e < list.ArrayLen(); ++e) {
        const std::string at = field + "[" + std::to_string(e) + "]";
        const tinygltf::Value& event = list.Get(static_cast<int>(e));
        const double time = event.Get("time").GetNumberAsDouble();
        if (!(time >= 0.0 && time <= static_cast<double>(duration)))
            fail(at + ".time: " + std::to_string(time) + " s is outside the clip (0 to " + std::to_string(duration) + " s)");
        std::int32_t joint = -1;
        if (event.Has("joint")) {
            const tinygltf::Value& name = event.Get("joint");
            const auto found = std::find(jointNames.begin(), jointNames.end(), name.Get<std::string>());
            if (found == jointNames.end())
                fail(at + ".joint: no joint named '" + name.Get<std::string>() + "' in the skeleton");
            joint = static_cast<std::int32_t>(found - jointNames.begin());
        }
        events.push_back({event.Get("name").Get<std::string>(), static_cast<float>(time), joint});
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const anim::ClipEvent& x, const anim::ClipEvent& y) { return x.time < y.time; });
    return events;
}

}  // namespace

std::vector<bool> animatedNodes(const tinygltf::Model& model) {
    std::vector<bool> animated(model.nodes.size(), false);
    for (const tinygltf::Animation& animation : model.animations) {
        for (const tinygltf::AnimationChannel& channel : animation.channels) {
            anim::ChannelPath path;
            if (channelPath(channel.target_path, path) && channel.target_node >= 0 &&
                static_cast<std::size_t>(channel.target_node) < model.nodes.size())
                animated[static_cast<std::size_t>(channel.target_node)] = true;
        }
    }
    return animated;
}

std::vector<anim::Clip> loadClips(const tinygltf::Model& model, const SkeletonBuild& skeleton, double maxBindDistance,
                                  std::vector<std::string>& notes) {
    const std::vector<int>& jointOfNode = skeleton.jointOfNode;
    checkPoseReach(skeleton.skeleton, anim::Clip{}, 0, {}, maxBindDistance);
    std::vector<anim::Clip> clips;
    std::size_t ignored = 0, morphWeights = 0, keyValues = 0;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        anim::Clip clip;
        clip.name = animation.name.empty() ? "clip" + std::to_string(a) : animation.name;
        std::vector<std::size_t> sourceChannels;  // of each of the clip's channels, for messages
        for (std::size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& source = animation.channels[c];
            const std::string what = "animation " + std::to_string(a) + " channel " + std::to_string(c);
            anim::ChannelPath path;
            if (!channelPath(source.target_path, path)) {
                ++morphWeights;
                continue;
            }
            if (source.target_node < 0 || static_cast<std::size_t>(source.target_node) >= model.nodes.size())
                fail(what + ": target node " + std::to_string(source.target_node) + " does not exist (the file has " +
                     std::to_string(model.nodes.size()) + " nodes)");
            const int joint = jointOfNode[static_cast<std::size_t>(source.target_node)];
            if (joint < 0) {
                ++ignored;  // a node outside the character's skeleton: another object, or the mesh node
                continue;
            }
            anim::Channel channel = readChannel(model, animation, source, path, what);
            keyValues += channel.times.size() + channel.values.size();
            if (keyValues > kMaxKeyValues)
                fail("the animations have more than " + std::to_string(kMaxKeyValues) + " keys in all");
            channel.joint = static_cast<std::uint32_t>(joint);
            clip.duration = std::max(clip.duration, channel.times.back());
            clip.channels.push_back(std::move(channel));
            sourceChannels.push_back(c);
        }
        checkPoseReach(skeleton.skeleton, clip, a, sourceChannels, maxBindDistance);
        clip.events = readEvents(animation, a, clip.duration, skeleton.skeleton.jointNames);
        clips.push_back(std::move(clip));
    }
    if (ignored > 0)
        notes.push_back(std::to_string(ignored) + " animation channel(s) move nodes outside the skeleton; ignored");
    if (morphWeights > 0) notes.push_back(std::to_string(morphWeights) + " morph-target weight channel(s) ignored");
    return clips;
}

}  // namespace model::gltf
