#version 460
#extension GL_GOOGLE_include_directive : require
// The motion pass: one thread per character evaluates its motion segment (or a driven character's keys)
// at this frame's time and writes where it is, which way it faces and what it plays into its
// CharacterRecord, which culling, the palette pass, skinning and drawing then read. Every character, seen
// or not: the closed form costs a few dozen operations, and off-screen characters must be where culling
// can find them.
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { MotionPush push; };
layout(std430, set = 0, binding = 0) readonly buffer Models { AnimationModel animModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Clips { AnimationClip animClips[]; };
layout(std430, set = 0, binding = 2) readonly buffer RootSamples { vec2 rootSamples[]; };
layout(std430, set = 0, binding = 3) readonly buffer Motions { MotionRecord motions[]; };
layout(std430, set = 0, binding = 4) buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 5) readonly buffer DrivenModels { DrivenModel drivenModels[]; };
layout(std430, set = 0, binding = 6) readonly buffer Keys { DrivenKey keys[]; };
layout(std430, set = 0, binding = 7) readonly buffer Heads { uint heads[]; };
layout(std430, set = 0, binding = 8) readonly buffer Owners { uint owners[]; };  // shaders/driven_ingest.comp.glsl
TERRAIN_BUFFER(0, 9);

#include "motion.glsl.inc"
#include "driven_keys.h"
#include "terrain_sample.glsl.inc"

float groundHeight(vec2 p) { return terrainHeightAt(terrainGrid, p); }

// A driven character with keys: between the keys around the frame's time less the delay (time.y, on the
// clock of epoch time.w), or past its newest (crowd::Crowd::drivenState repeats this search).
void moveDriven(uint c, uint model, uint count) {
    uint slots = push.counts.x, perSlot = push.counts.z;
    float epoch = push.time.w, clock = push.time.y;
    DrivenModel driven = drivenModels[model];
    uint oldest = count > perSlot ? count - perSlot : 0u;
    uint k = count - 1u;
    DrivenKey a = keys[(k % perSlot) * slots + c];
    while (k > oldest && drivenKeyTime(a, epoch) > clock) {
        --k;
        a = keys[(k % perSlot) * slots + c];
    }
    float ta = drivenKeyTime(a, epoch);
    DrivenPose pose;
    if (k + 1u < count) {
        DrivenKey b = keys[((k + 1u) % perSlot) * slots + c];
        pose = drivenBetween(a, b, ta, drivenKeyTime(b, epoch), clock);
    } else if (clock <= ta) {
        pose = drivenAt(a);
    } else {
        bool only = k == oldest;
        DrivenKey previous = keys[((only ? k : k - 1u) % perSlot) * slots + c];
        pose = drivenBeyond(previous, a, only, drivenKeyTime(previous, epoch), ta, clock, push.time.z, epoch, driven);
    }
    uvec2 clips = drivenClips(pose.gait, driven);
    float weight = pose.gait - drivenLevel(pose.gait);
    // The clips' own sway: their root motion less its straight stride (the samples give the straight path),
    // so their planted feet stay still (crowd::Crowd::drivenState adds the same).
    uint firstClip = animModels[model].info.z;
    float cycle = fract(pose.phase);
    vec2 swayFrom = rootMotionAt(firstClip + clips.x, cycle) - cycle * rootSamples[animClips[firstClip + clips.x].info.y + ROOT_MOTION_SAMPLES];
    vec2 swayTo = rootMotionAt(firstClip + clips.y, cycle) - cycle * rootSamples[animClips[firstClip + clips.y].info.y + ROOT_MOTION_SAMPLES];
    vec2 ground = pose.position + turnToWorld(mix(swayFrom, swayTo, weight), pose.heading);
    characters[c].placement = vec4(ground.x, groundHeight(ground), ground.y, pose.heading);
    characters[c].ids.w = clips.x | (clips.y << 16u);
    characters[c].pose.xy = vec2(pose.phase, weight);  // z: its props, fixed
}

void moveCharacter(uint c) {
    MotionRecord m = motions[c];
    uint model = characters[c].ids.x;
    // A driven character with keys (a device-driven one's: its own, not its slot's last character's). A
    // crowd with driven characters always keeps keys (crowd::Crowd refuses them otherwise), so heads[] has a
    // count per slot here. (Not tested against push.counts.z: lavapipe compiles a shader anew at every bind
    // when a branch reads push constants alone, gpu_types.h.)
    bool keyed = m.phase.w == MOTION_DRIVEN_HOST ||
                 (m.phase.w == MOTION_DRIVEN_DEVICE && owners[c] == floatBitsToUint(characters[c].pose.w));
    if (keyed && heads[c] > 0u) {
        moveDriven(c, model, heads[c]);
        return;
    }
    uint firstClip = animModels[model].info.z;
    float elapsed = max(push.time.x - m.timing.x, 0.0);
    vec3 position = m.origin.xyz;
    if (m.phase.w == MOTION_ROOT) {
        vec2 offset = travelled(m, elapsed, firstClip + m.clips.x, firstClip + m.clips.y);
        position.xz += offset;
    }
    position.y += groundHeight(position.xz);
    characters[c].placement = vec4(position, motionHeading(m, elapsed));
    characters[c].ids.w = m.clips.x | (m.clips.y << 16u);
    characters[c].pose.xy = vec2(motionPhase(m, elapsed), motionWeight(m, elapsed));  // z: its props, fixed
}

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint c = gl_GlobalInvocationID.x; c < push.counts.x; c += stride) moveCharacter(c);
}
