#pragma once
// Footstep markers: how a host consumes the renderer's GPU event buffer (crowdgpu::FrameOutput::events,
// docs/events.md). Each frame's commands copy the buffer into host memory (a ring, one entry per frame
// that may still be in flight); once that frame is done its events become markers, a dust puff at
// each event's world position that grows and fades over half a second of scene time, drawn over the
// scene with the panel's ImGui (so --no-ui shows none).
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include <crowdgpu/renderer.hpp>

#include "app/host_image.h"

namespace app { class HostDevice; }

namespace view {

class EventMarkers {
public:
    // `framesInFlight`: how many frames the renderer may have running (their copies must not be
    // overwritten before they are read).
    EventMarkers(const app::HostDevice& device, std::uint32_t framesInFlight);
    ~EventMarkers();
    EventMarkers(const EventMarkers&) = delete;
    EventMarkers& operator=(const EventMarkers&) = delete;

    // In the frame's command buffer, after recordCompute: copies this frame's events (nothing when the
    // renderer has events off). `time`: the frame's scene time.
    void recordCopy(VkCommandBuffer cmd, const crowdgpu::FrameOutput& output, double time);
    // After the renderer has waited for the frame `framesInFlight` frames back: its events become markers.
    void collectFinished();
    // Every copy taken so far, once the GPU is idle (a screenshot, a resize).
    void collectAll();
    // The markers alive at scene time `now` over the window (ImGui's background list), seen through
    // `view` (its matrices; the window shows the whole scene image).
    void draw(const crowdgpu::FrameView& view, double now);
    // Markers alive now (the panel's statistics).
    std::size_t count() const { return markers_.size(); }
    void clear();

    // How long a marker lasts (scene seconds) and its radius when it fades out (metres).
    static constexpr double kLifetime = 0.5;
    static constexpr float kRadius = 0.35f;

private:
    struct Copy {
        app::ReadbackBuffer buffer;
        double time = 0.0;
        bool pending = false;
    };
    struct Marker {
        float position[3];
        double born;  // scene time
    };
    void collect(Copy& copy);
    Copy& copyFor(std::uint64_t frame) { return copies_[frame % copies_.size()]; }

    const app::HostDevice& device_;
    std::uint32_t framesInFlight_;
    std::vector<Copy> copies_;
    std::uint64_t frames_ = 0;  // copies recorded
    std::vector<Marker> markers_;
};

}  // namespace view
