#pragma once
// crowd-view's frame loop: input -> panel -> camera -> acquire -> render the crowd (the renderer's
// frame, with the blit, the panel and the present transition recorded after the scene) -> present.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/host_device.h"
#include "view/camera_controller.h"
#include "view/camera_input.h"
#include "view/crowd_scene.h"
#include "view/event_markers.h"
#include "view/frame_history.h"
#include "view/panel.h"
#include "view/swapchain.h"
#include "view/ui_pass.h"
#include "view/viewer_options.h"
#include "view/window.h"

namespace view {

class Viewer {
public:
    // Opens the window and builds the crowd; throws app::Error with a one-line message on failure.
    explicit Viewer(const ViewerOptions& options);

    // Runs until the window closes, Esc, or the script's last frame; returns the exit status
    // (3 when validation reported anything, as crowd-render).
    int run();

private:
    // What the user changes live that is not part of the scene options.
    struct Controls {
        float speed = 1.0f;
        bool paused = false;
        bool scenePath = false;  // the camera flies the scene's path instead of the user's controls
        bool showPanel = true;
        std::optional<std::uint32_t> followed;
    };

    bool drawFrame(double time, bool screenshot);
    void recreateSwapchain(VkExtent2D size);
    void buildUi();
    // Shortcut keys become the same requests as the panel's controls.
    void handleKeys(const std::vector<int>& keys);
    void apply(const PanelRequests& requests);
    void rebuild(const app::SceneOptions& scene);
    void follow(std::optional<std::uint32_t> character);
    void frameHome(bool moveCamera);
    std::uint32_t characterNearViewCenter() const;
    glm::vec3 characterCenter(std::uint32_t character) const;
    void writeScreenshot(const app::Rgba8Image& image);
    void note(const std::string& message);
    PanelState panelState() const;

    ViewerOptions options_;
    // Declared in creation order: destroyed in reverse, the surface before the instance, the
    // instance before GLFW lets the window go.
    Window window_;
    app::HostDevice context_;
    Swapchain swapchain_;
    CrowdScene scene_;
    EventMarkers markers_;  // dust puffs at the footsteps of the renderer's event buffer
    std::unique_ptr<UiPass> ui_;
    Panel panel_;
    CameraController camera_;
    CameraInputReader input_;
    FrameHistory history_;
    Controls controls_;
    PanelRequests requests_;  // this frame's, from the panel and the keys
    double sceneTime_ = 0.0;  // the time of the frame drawn last (the panel's recording slider)
    std::uint32_t maxCharacters_ = 1;
    // What the scene is drawn at: the window's size, or less when that is past the device's limits.
    VkExtent2D renderSize_{};
    bool swapchainStale_ = false;
    std::string message_;
    std::uint32_t screenshots_ = 0;
};

}  // namespace view
