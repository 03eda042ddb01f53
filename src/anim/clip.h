#pragma once
// An animation clip: keyframed channels on joints' translation, rotation or scale.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace anim {

enum class Interpolation { Step, Linear, CubicSpline };
enum class ChannelPath { Translation, Rotation, Scale };

struct Channel {
    std::uint32_t joint = 0;
    ChannelPath path = ChannelPath::Rotation;
    Interpolation interpolation = Interpolation::Linear;
    // Strictly increasing key times in seconds.
    std::vector<float> times;
    // One value per key (xyz used for translation and scale; rotation is a quaternion as x, y, z, w).
    // CubicSpline keys hold three values each: in-tangent, value, out-tangent.
    std::vector<glm::vec4> values;
};

// A named moment of a clip's cycle (a footstep, a shot): the crowd reports it each time a character's
// phase passes it (crowd::Crowd::events).
struct ClipEvent {
    std::string name;
    float time = 0.0f;  // seconds into the cycle, [0, duration]
    // The joint where it happens (a footstep's foot), or -1: where a host puts dust or a sound. Its
    // position at `time` in the clip gives the event a place (docs/events.md).
    std::int32_t joint = -1;
};

struct Clip {
    std::string name;
    float duration = 0.0f;  // seconds; clips loop over [0, duration)
    std::vector<Channel> channels;
    std::vector<ClipEvent> events;  // in time order
};

}  // namespace anim
