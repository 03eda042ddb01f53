#pragma once
// The ImGui panel: what the frame costs (fps, frame ms, GPU ms per pass, characters and triangles
// drawn, a frame-time graph) and the controls users explore with. It only reads state and returns
// requests; the viewer applies them (some rebuild the crowd).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <crowdgpu/renderer.hpp>

#include "app/options.h"
#include "view/camera_controller.h"
#include "view/frame_history.h"

namespace view {

struct PanelState {
    const FrameHistory* history = nullptr;
    std::string device;
    std::string presentMode;
    std::uint32_t characters = 0;
    std::uint32_t maxCharacters = 1;
    crowdgpu::FrameCounts lods{};      // drawn in the newest frame, per level of detail
    app::CullOptions cull;
    bool shadows = true;
    bool gpuAnimation = true;  // bone matrices from the GPU passes (else the CPU jobs)
    bool scenePath = false;
    crowdgpu::Method method = crowdgpu::Method::TwoPass;
    std::string model;
    std::vector<std::string> models;  // choices: built-in models, plus the --model file if any
    float speed = 1.0f;
    bool paused = false;
    double time = 0.0;      // the scene's time
    double duration = 0.0;  // a replayed recording's (--trajectories; 0: none): the time slider's range
    CameraMode cameraMode = CameraMode::Orbit;
    std::optional<std::uint32_t> followed;
    std::string message;  // the last note or refusal ("compute needs 90 GiB ...")
};

struct PanelRequests {
    std::optional<std::uint32_t> characters;
    std::optional<crowdgpu::Method> method;
    std::optional<std::string> model;
    std::optional<float> speed;
    std::optional<bool> paused;
    std::optional<double> seek;  // the recording's time slider moved: the scene's time from now
    std::optional<CameraMode> cameraMode;
    std::optional<std::optional<std::uint32_t>> follow;  // a character, or nullopt inside: stop following
    std::optional<app::CullOptions> cull;  // LOD or culling switched
    std::optional<bool> scenePath;
    std::optional<bool> shadows;
    std::optional<bool> gpuAnimation;
    bool resetCamera = false;
    bool screenshot = false;
};

class Panel {
public:
    // Declares the panel's widgets for this ImGui frame.
    PanelRequests draw(const PanelState& state);

private:
    void drawStats(const PanelState& state);
    void drawCrowd(const PanelState& state, PanelRequests& requests);
    void drawAnimation(const PanelState& state, PanelRequests& requests);
    void drawCamera(const PanelState& state, PanelRequests& requests);
    void drawCulling(const PanelState& state, PanelRequests& requests);

    // A crowd size being edited: applied when the slider is let go, not on every step of a drag
    // (each step would rebuild the crowd).
    std::uint32_t editedCharacters_ = 0;
    int followIndex_ = 0;
};

}  // namespace view
