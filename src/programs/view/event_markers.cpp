#include "view/event_markers.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <imgui.h>

#include "app/host_device.h"

namespace view {

EventMarkers::EventMarkers(const app::HostDevice& device, std::uint32_t framesInFlight)
    : device_(device), framesInFlight_(framesInFlight), copies_(framesInFlight + 1) {}

EventMarkers::~EventMarkers() {
    for (Copy& copy : copies_) app::destroyReadbackBuffer(device_, copy.buffer);
}

void EventMarkers::recordCopy(VkCommandBuffer cmd, const crowdgpu::FrameOutput& output, double time) {
    Copy& copy = copyFor(frames_++);
    copy.pending = false;
    if (!output.events) return;
    const VkDeviceSize size = output.eventsOffset + VkDeviceSize{output.eventCapacity} * sizeof(crowdgpu::GpuEvent);
    if (copy.buffer.size != size) {
        // This entry's last frame was collected before this one was recorded (collectFinished).
        app::destroyReadbackBuffer(device_, copy.buffer);
        copy.buffer = app::createReadbackBuffer(device_, size, "event markers");
    }
    // The renderer's own barrier after its event pass makes the buffer readable by any later command.
    const VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(cmd, output.events, copy.buffer.buffer, 1, &region);
    app::copiedForHost(cmd, copy.buffer);
    copy.time = time;
    copy.pending = true;
}

void EventMarkers::collect(Copy& copy) {
    if (!copy.pending) return;
    copy.pending = false;
    crowdgpu::GpuEventHeader header;
    std::memcpy(&header, copy.buffer.mapped, sizeof header);
    const auto* events = reinterpret_cast<const crowdgpu::GpuEvent*>(static_cast<const std::byte*>(copy.buffer.mapped) + 16);
    for (std::uint32_t i = 0; i < std::min(header.count, header.capacity); ++i)
        markers_.push_back({{events[i].position[0], events[i].position[1], events[i].position[2]},
                            copy.time - static_cast<double>(events[i].age)});
}

void EventMarkers::collectFinished() {
    if (frames_ > framesInFlight_) collect(copyFor(frames_ - 1 - framesInFlight_));
}

void EventMarkers::collectAll() {
    // Oldest first, so markers keep their order of birth.
    for (std::uint64_t k = std::min<std::uint64_t>(frames_, copies_.size()); k > 0; --k) collect(copyFor(frames_ - k));
}

void EventMarkers::clear() {
    markers_.clear();
    for (Copy& copy : copies_) copy.pending = false;
}

void EventMarkers::draw(const crowdgpu::FrameView& view, double now) {
    // Forget the faded (and, after time went back, the unborn).
    std::erase_if(markers_, [&](const Marker& m) { return now - m.born > kLifetime || now < m.born; });
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float* v = view.view;
    const float* p = view.projection;
    for (const Marker& m : markers_) {
        // Column-major: eye = V x, clip = P eye.
        float eye[4], clip[4];
        for (int r = 0; r < 4; ++r)
            eye[r] = v[r] * m.position[0] + v[4 + r] * m.position[1] + v[8 + r] * m.position[2] + v[12 + r];
        for (int r = 0; r < 4; ++r) clip[r] = p[r] * eye[0] + p[4 + r] * eye[1] + p[8 + r] * eye[2] + p[12 + r] * eye[3];
        if (!(clip[3] > 1e-3f)) continue;  // behind the eye
        const float x = (clip[0] / clip[3] * 0.5f + 0.5f) * display.x, y = (clip[1] / clip[3] * 0.5f + 0.5f) * display.y;
        // A puff that grows from a third of its size and fades: its radius in metres, projected.
        const auto life = static_cast<float>((now - m.born) / kLifetime);
        const float radius = kRadius * (0.35f + 0.65f * life) * p[5] * 0.5f * display.y / clip[3];
        const auto alpha = static_cast<int>(200.0f * (1.0f - life));
        // At least 3 pixels across, so a far crowd's footsteps still show.
        list->AddCircleFilled(ImVec2(x, y), std::max(radius, 3.0f), IM_COL32(235, 215, 170, alpha));
        list->AddCircle(ImVec2(x, y), std::max(radius, 3.0f), IM_COL32(120, 90, 50, alpha), 0, 1.5f);
    }
}

}  // namespace view
