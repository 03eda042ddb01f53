#include "view/panel.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <imgui.h>

namespace view {
namespace {

// Fixed widths: the panel sizes itself to its contents, so nothing in it may size itself to the panel.
constexpr float kItemWidth = 190.0f;
constexpr float kGraphWidth = 320.0f;

// 276480 -> "276,480": triangle counts run to billions.
std::string thousands(std::uint64_t n) {
    const std::string digits = std::to_string(n);
    std::string grouped;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ',';
        grouped += digits[i];
    }
    return grouped;
}

// A glTF model is shown by its file name; the directories would crowd out the combo.
std::string fileName(const std::string& model) { return std::filesystem::path(model).filename().string(); }

}  // namespace

PanelRequests Panel::draw(const PanelState& state) {
    PanelRequests requests;
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("crowd-view", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::PushItemWidth(kItemWidth);
        drawStats(state);
        drawCrowd(state, requests);
        drawAnimation(state, requests);
        drawCulling(state, requests);
        drawCamera(state, requests);
        if (ImGui::Button("Screenshot (F12)")) requests.screenshot = true;
        if (!state.message.empty()) {
            ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + kGraphWidth);
            ImGui::TextUnformatted(state.message.c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::PopItemWidth();
    }
    ImGui::End();
    return requests;
}

void Panel::drawStats(const PanelState& state) {
    const FrameHistory& history = *state.history;
    ImGui::Text("%s", state.device.c_str());
    ImGui::Text("%.1f fps  %.2f ms/frame  (%s)", history.fps(), history.meanFrameMs(), state.presentMode.c_str());
    ImGui::Text("CPU %.2f ms (animate + record)", history.meanCpuMs());
    for (const app::PassTime& pass : history.meanGpuMs())
        ImGui::Text("GPU %-7s %7.3f ms", pass.pass.c_str(), pass.milliseconds);
    const crowdgpu::FrameCounts& lods = state.lods;
    ImGui::Text("drawn: %s of %s characters, %s triangles",
                thousands(lods.characters[0] + lods.characters[1] + lods.characters[2]).c_str(),
                thousands(state.characters).c_str(), thousands(lods.triangles[0] + lods.triangles[1] + lods.triangles[2]).c_str());
    for (int l = 0; l < app::kLodCount; ++l)
        ImGui::Text("  LOD %d: %s characters, %s triangles", l, thousands(state.lods.characters[l]).c_str(),
                    thousands(state.lods.triangles[l]).c_str());
    ImGui::Text("  impostors: %s characters (%s over the mesh cap)", thousands(state.lods.impostors).c_str(),
                thousands(state.lods.demoted).c_str());

    const std::vector<float> times = history.frameMs();
    const float longest = times.empty() ? 1.0f : *std::max_element(times.begin(), times.end());
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "frame ms, last %zu (max %.1f)", times.size(), longest);
    ImGui::PlotLines("##frame-ms", times.data(), static_cast<int>(times.size()), 0, overlay, 0.0f, longest * 1.2f,
                     ImVec2(kGraphWidth, 60.0f));
}

void Panel::drawCrowd(const PanelState& state, PanelRequests& requests) {
    if (!ImGui::CollapsingHeader("Crowd", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!ImGui::IsAnyItemActive()) editedCharacters_ = state.characters;
    const std::uint32_t one = 1;
    ImGui::SliderScalar("characters", ImGuiDataType_U32, &editedCharacters_, &one, &state.maxCharacters, "%u",
                        ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemDeactivatedAfterEdit() && editedCharacters_ != state.characters)
        requests.characters = editedCharacters_;
    if (ImGui::Button("/2") && state.characters > 1) requests.characters = state.characters / 2;
    ImGui::SameLine();
    if (ImGui::Button("x2")) requests.characters = std::min(state.maxCharacters, state.characters * 2);
    ImGui::SameLine();
    ImGui::TextDisabled("(limit %s)", thousands(state.maxCharacters).c_str());

    if (ImGui::BeginCombo("method", crowdgpu::methodName(state.method))) {
        for (crowdgpu::Method m : app::allMethods())
            if (ImGui::Selectable(crowdgpu::methodName(m), m == state.method) && m != state.method) requests.method = m;
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("model", fileName(state.model).c_str())) {
        for (const std::string& name : state.models)
            if (ImGui::Selectable(fileName(name).c_str(), name == state.model) && name != state.model)
                requests.model = name;
        ImGui::EndCombo();
    }
}

void Panel::drawAnimation(const PanelState& state, PanelRequests& requests) {
    if (!ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    float speed = state.speed;
    if (ImGui::SliderFloat("speed", &speed, 0.0f, 4.0f, "%.2fx")) requests.speed = speed;
    bool paused = state.paused;
    if (ImGui::Checkbox("paused (Space)", &paused)) requests.paused = paused;
    if (state.duration > 0.0) {  // a replayed recording: its time, to scrub back and forth
        float time = static_cast<float>(state.time);
        if (ImGui::SliderFloat("recording", &time, 0.0f, static_cast<float>(state.duration), "%.1f s"))
            requests.seek = time;
    }
}

void Panel::drawCulling(const PanelState& state, PanelRequests& requests) {
    if (!ImGui::CollapsingHeader("LOD and culling", ImGuiTreeNodeFlags_DefaultOpen)) return;
    app::CullOptions cull = state.cull;
    bool changed = ImGui::Checkbox("levels of detail", &cull.lod);
    int mode = static_cast<int>(cull.mode);
    ImGui::Text("culling");
    for (crowdgpu::Culling m : {crowdgpu::Culling::Gpu, crowdgpu::Culling::Cpu, crowdgpu::Culling::Off}) {
        ImGui::SameLine();
        changed |= ImGui::RadioButton(crowdgpu::cullingName(m), &mode, static_cast<int>(m));
    }
    cull.mode = static_cast<crowdgpu::Culling>(mode);
    float thresholds[2] = {cull.lodThresholds[0], cull.lodThresholds[1]};
    if (ImGui::DragFloat2("LOD px", thresholds, 1.0f, 1.0f, 2000.0f, "%.0f") && thresholds[0] > thresholds[1] &&
        thresholds[1] > (cull.impostors ? cull.impostorThreshold : 0.0f)) {
        cull.lodThresholds[0] = thresholds[0], cull.lodThresholds[1] = thresholds[1];
        changed = true;
    }
    // The first switch to impostors bakes the atlas (a second or so; the frame waits).
    if (ImGui::Checkbox("impostors", &cull.impostors)) {
        // LOD thresholds set while impostors were off may lie at or below the impostor threshold: the
        // impostor level must stay below LOD 2, so it moves down (shown in "impostor px").
        if (cull.impostors && !(cull.impostorThreshold < cull.lodThresholds[1]))
            cull.impostorThreshold = 0.5f * cull.lodThresholds[1];
        changed = true;
    }
    float impostorPx = cull.impostorThreshold;
    if (ImGui::DragFloat("impostor px", &impostorPx, 0.5f, 1.0f, 2000.0f, "%.0f") && impostorPx > 0.0f &&
        impostorPx < cull.lodThresholds[1]) {
        cull.impostorThreshold = impostorPx;
        changed = true;
    }
    // Level changes that fade across the hysteresis band, and impostors that blend four atlas cells.
    changed |= ImGui::Checkbox("fades", &cull.lodFade);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("impostor blend", &cull.impostorBlend);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("far crowd averaged", &cull.farCrowd);
    if (changed) requests.cull = cull;
    bool shadows = state.shadows;
    if (ImGui::Checkbox("shadows", &shadows)) requests.shadows = shadows;
    bool gpuAnimation = state.gpuAnimation;
    if (ImGui::Checkbox("GPU animation", &gpuAnimation)) requests.gpuAnimation = gpuAnimation;
}

void Panel::drawCamera(const PanelState& state, PanelRequests& requests) {
    if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
    bool path = state.scenePath;
    if (ImGui::Checkbox("scene's camera path", &path)) requests.scenePath = path;
    int mode = state.cameraMode == CameraMode::Orbit ? 0 : 1;
    if (ImGui::RadioButton("orbit", &mode, 0)) requests.cameraMode = CameraMode::Orbit;
    ImGui::SameLine();
    if (ImGui::RadioButton("fly (C)", &mode, 1)) requests.cameraMode = CameraMode::Fly;
    ImGui::SameLine();
    if (ImGui::Button("reset (R)")) requests.resetCamera = true;

    bool following = state.followed.has_value();
    if (state.followed) followIndex_ = static_cast<int>(*state.followed);
    const int last = static_cast<int>(state.characters) - 1;
    if (ImGui::Checkbox("follow", &following))
        requests.follow = following ? std::optional<std::uint32_t>(std::clamp(followIndex_, 0, last)) : std::nullopt;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::InputInt("character (F)", &followIndex_)) {
        followIndex_ = std::clamp(followIndex_, 0, last);
        requests.follow = static_cast<std::uint32_t>(followIndex_);
    }
}

}  // namespace view
