#include "view/viewer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <GLFW/glfw3.h>

#include "app/crowd_app.h"
#include "app/error.h"
#include "app/camera.h"
#include "app/png_writer.h"
#include "view/present_commands.h"
#include "view/screenshot.h"

namespace view {
namespace {

// The renderer's frames in flight; the swapchain sizes its ring of acquire semaphores by it.
const std::uint32_t kFramesInFlight = app::RendererOptions{}.framesInFlight;
// A stall (a rebuild, a dragged window) must not make the animation jump ahead.
constexpr float kMaxStepSeconds = 0.25f;

const char* presentModeName(VkPresentModeKHR mode) {
    switch (mode) {
        case VK_PRESENT_MODE_FIFO_KHR: return "vsync: FIFO";
        case VK_PRESENT_MODE_MAILBOX_KHR: return "no vsync: MAILBOX";
        case VK_PRESENT_MODE_IMMEDIATE_KHR: return "no vsync: IMMEDIATE";
        default: return "other present mode";
    }
}

std::vector<std::string> modelChoices(const std::string& given) {
    std::vector<std::string> models = {"soldier", "horse", "cavalry"};
    if (std::find(models.begin(), models.end(), given) == models.end()) models.push_back(given);
    return models;
}

bool operator!=(VkExtent2D a, VkExtent2D b) { return a.width != b.width || a.height != b.height; }

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      window_(options.render.size, "crowd-view"),
      context_(app::HostDeviceOptions{options.render.validation, options.render.device,
                                      Window::requiredInstanceExtensions(), true}),
      swapchain_(context_, window_.createSurface(context_.instance), window_.framebufferSize(), options.vsync,
                 kFramesInFlight),
      scene_(context_, options.render.scene, options.render.method, options.render.cull, options.render.shadows,
             options.render.meshCapacity, options.render.antiAliasing, swapchain_.extent()),
      markers_(context_, scene_.renderer().library().settings().framesInFlight) {
    window_.limitFramebufferSize(swapchain_.largestExtent());
    renderSize_ = swapchain_.extent();
    scene_.setAnimation(options.render.animation, renderSize_);
    controls_.scenePath = options.render.camera != app::CameraPath::Framed;
    if (options.ui) ui_ = std::make_unique<UiPass>(context_, window_.handle(), swapchain_);
    frameHome(true);
    maxCharacters_ = scene_.maxCharacters(renderSize_);
    std::printf("crowd-view: %s (%s), %u x %s, %s, %ux%u, anti-aliasing %s, %s\n", context_.description.name.c_str(),
                context_.description.driver.c_str(), scene_.crowd().size(), scene_.model().name().c_str(),
                crowdgpu::methodName(scene_.method()), swapchain_.extent().width, swapchain_.extent().height,
                app::antiAliasingName(options.render.antiAliasing).c_str(), presentModeName(swapchain_.presentMode()));
    for (const std::string& n : scene_.takeNotes()) note(n);
}

int Viewer::run() {
    using Clock = std::chrono::steady_clock;
    Clock::time_point previous = Clock::now();
    double animationTime = 0.0;
    std::uint32_t frame = 0;  // frames drawn: a script's frame N is crowd-render's frame N
    while (!window_.shouldClose() && (!options_.scripted || frame < options_.render.frames)) {
        window_.pollEvents();
        if (!window_.waitWhileMinimized()) break;
        const VkExtent2D size = window_.framebufferSize();
        if (swapchainStale_ || size != swapchain_.windowSize()) {
            recreateSwapchain(size);
            if (swapchainStale_) continue;
        }
        const Clock::time_point now = Clock::now();
        const float seconds = std::min(std::chrono::duration<float>(now - previous).count(), kMaxStepSeconds);
        previous = now;

        buildUi();
        handleKeys(window_.takeKeyPresses());
        apply(requests_);
        if (requests_.seek) animationTime = *requests_.seek - options_.render.startSeconds;  // the recording's slider
        const bool mouseFree = !ui_ || !ui_->wantsMouse();
        const bool keysFree = !ui_ || !ui_->wantsKeyboard();
        camera_.update(input_.read(window_.handle(), window_.takeWheel(), mouseFree, keysFree, seconds));
        if (controls_.followed) camera_.track(characterCenter(*controls_.followed));
        scene_.renderer().camera = camera_.camera();

        // Scripts step a fixed 1/60 s per frame, as crowd-render does; people see real time.
        if (!controls_.paused) animationTime += seconds * controls_.speed;
        const double time = options_.scripted ? app::frameTime(frame, options_.render.startSeconds)
                                             : options_.render.startSeconds + animationTime;
        sceneTime_ = time;
        if (controls_.scenePath) {
            // The scene's camera path, as crowd-render flies it (frame N of a script is its frame N).
            const VkExtent2D extent = swapchain_.extent();
            scene_.renderer().camera = app::cameraOnPath(options_.render.camera, app::crowdShape(scene_.crowd()),
                                                            static_cast<float>(extent.width) / extent.height, time);
        }
        if (ui_) {
            // The footstep markers over this frame's view, then the panel's frame is complete.
            markers_.draw(app::frameView(scene_.renderer().camera, swapchain_.extent(), time), time);
            ui_->endFrame();
        }
        const bool lastScripted = options_.scripted && frame + 1 == options_.render.frames;
        if (!drawFrame(time, requests_.screenshot || (lastScripted && !options_.screenshot.empty()))) {
            swapchainStale_ = true;  // out of date before anything was drawn: recreate, draw this frame again
            continue;
        }
        for (const app::FrameStats& stats : scene_.renderer().takeStats()) history_.add(stats);
        ++frame;
    }
    scene_.renderer().finish();
    CHECK_VK(vkDeviceWaitIdle(context_.device));
    if (options_.scripted && frame < options_.render.frames && !options_.screenshot.empty()) {
        std::fprintf(stderr, "crowd-view: window closed after %u of %u frames; %s not written\n", frame,
                     options_.render.frames, options_.screenshot.c_str());
        return 1;
    }
    if (context_.validationMessages() > 0) {
        std::fprintf(stderr, "crowd-view: %llu validation message(s)\n",
                     static_cast<unsigned long long>(context_.validationMessages()));
        return 3;
    }
    return 0;
}

bool Viewer::drawFrame(double time, bool screenshot) {
    const std::optional<Swapchain::Frame> frame = swapchain_.acquire();
    if (!frame) return false;
    if (screenshot && !swapchain_.canReadBack()) {
        note("this window's images cannot be read back on " + context_.description.name + ": no screenshot");
        screenshot = false;
    }
    std::unique_ptr<Screenshot> shot;
    if (screenshot) shot = std::make_unique<Screenshot>(context_, swapchain_.extent(), swapchain_.format());

    app::PresentHooks hooks;
    hooks.waitSemaphore = frame->acquired;
    hooks.signalSemaphore = frame->rendered;
    hooks.recordAfterScene = [&](VkCommandBuffer cmd, VkImage scene, VkExtent2D sceneExtent) {
        // The renderer wrote this frame's events in recordCompute: copy them for the markers.
        markers_.recordCopy(cmd, scene_.renderer().library().output(), time);
        SwapchainImage image{frame->image, swapchain_.extent()};
        blitScene(cmd, scene, sceneExtent, image);
        if (ui_) {
            prepareForUi(cmd, image);
            ui_->record(cmd, frame->imageIndex, image.extent);
        }
        if (shot) shot->record(cmd, image);
        prepareForPresent(cmd, image);
    };
    scene_.renderer().renderFrame(time, &hooks);
    markers_.collectFinished();  // renderFrame waited for the frame whose slot it took
    if (!swapchain_.present(*frame)) swapchainStale_ = true;  // drawn and shown; recreate before the next
    if (shot) {
        scene_.renderer().finish();  // the copy is done once the frame's fence has signalled
        markers_.collectAll();
        writeScreenshot(shot->pixels());
    }
    return true;
}

void Viewer::recreateSwapchain(VkExtent2D size) {
    swapchainStale_ = !swapchain_.recreate(size);
    if (swapchainStale_) {
        // Resized beyond what the device can present (no window manager enforced the limit): shrink back.
        const VkExtent2D largest = swapchain_.largestExtent();
        if (size.width > largest.width || size.height > largest.height) {
            note("a " + std::to_string(size.width) + "x" + std::to_string(size.height) + " window is larger than " +
                 context_.description.name + " can present (" + std::to_string(largest.width) + "x" +
                 std::to_string(largest.height) + "); shrinking it");
            window_.limitFramebufferSize(largest);
        }
        return;
    }
    if (ui_) ui_->onSwapchainRecreated(swapchain_);
    // A window past what the device can draw into with these settings (16384 x 16384 with 4 samples: a
    // 4 GiB image) is drawn at the largest size of its shape that fits and scaled up to it.
    const VkExtent2D window = swapchain_.extent();
    const app::FittingSize fitting = scene_.fittingSize(window);
    if (fitting.size != window)
        note("the " + std::to_string(window.width) + "x" + std::to_string(window.height) + " window is drawn at " +
             std::to_string(fitting.size.width) + "x" + std::to_string(fitting.size.height) +
             " and scaled up (at its own size with anti-aliasing " +
             app::antiAliasingName(options_.render.antiAliasing) + ", " + fitting.why + ")");
    renderSize_ = fitting.size;
    scene_.renderer().resize(renderSize_);
    frameHome(false);  // R frames the crowd for the new shape; the camera stays where it is
    maxCharacters_ = scene_.maxCharacters(renderSize_);
}

void Viewer::buildUi() {
    requests_ = {};
    if (!ui_) return;
    ui_->beginFrame();
    if (controls_.showPanel) requests_ = panel_.draw(panelState());
    // ImGui's frame ends in run(), once the frame's view is known (the markers are drawn in it).
}

void Viewer::handleKeys(const std::vector<int>& keys) {
    if (ui_ && ui_->wantsKeyboard()) return;  // typing into a panel field
    for (int key : keys) {
        if (key == GLFW_KEY_ESCAPE) window_.requestClose();
        if (key == GLFW_KEY_C)
            requests_.cameraMode = camera_.mode() == CameraMode::Orbit ? CameraMode::Fly : CameraMode::Orbit;
        if (key == GLFW_KEY_R) requests_.resetCamera = true;
        if (key == GLFW_KEY_F)
            requests_.follow = controls_.followed ? std::nullopt : std::optional(characterNearViewCenter());
        if (key == GLFW_KEY_SPACE) requests_.paused = !controls_.paused;
        if (key == GLFW_KEY_H) controls_.showPanel = !controls_.showPanel;
        if (key == GLFW_KEY_F12) requests_.screenshot = true;
    }
}

void Viewer::apply(const PanelRequests& requests) {
    if (requests.speed) controls_.speed = *requests.speed;
    if (requests.paused) controls_.paused = *requests.paused;
    if (requests.cameraMode) {
        camera_.setMode(*requests.cameraMode);
        if (*requests.cameraMode == CameraMode::Fly) controls_.followed.reset();  // flying leaves the character
    }
    if (requests.resetCamera) {
        controls_.followed.reset();
        camera_.reset();
    }
    if (requests.follow) follow(*requests.follow);
    if (requests.scenePath) controls_.scenePath = *requests.scenePath;
    if (requests.cull) {
        const app::CullOptions& cull = *requests.cull;
        scene_.renderer().setCulling(cull.mode, cull.lod, cull.impostors);
        scene_.renderer().setLevels(cull.lodThresholds, cull.hysteresis, cull.impostorThreshold);
        scene_.renderer().library().setLodFade(cull.lodFade);
        scene_.renderer().library().setImpostorBlend(cull.impostorBlend);
        scene_.renderer().library().setFarCrowd(cull.farCrowd);
    }
    if (requests.shadows) scene_.setShadows(*requests.shadows);
    try {
        if (requests.gpuAnimation) {
            scene_.setAnimation(*requests.gpuAnimation ? crowdgpu::Animation::Gpu : crowdgpu::Animation::Cpu,
                                renderSize_);
            maxCharacters_ = scene_.maxCharacters(renderSize_);  // the CPU path's bones bound it sooner
        }
        if (requests.method) {
            scene_.setMethod(*requests.method, renderSize_);
            maxCharacters_ = scene_.maxCharacters(renderSize_);
            history_.clear();
        }
        if (requests.characters || requests.model) {
            app::SceneOptions scene = scene_.options();
            if (requests.characters) scene.count = *requests.characters;
            if (requests.model) scene.model = *requests.model;
            rebuild(scene);
        }
    } catch (const app::Error& error) {
        note(error.what());  // the current crowd and method stay
    }
}

void Viewer::rebuild(const app::SceneOptions& scene) {
    scene_.rebuild(scene, renderSize_);
    markers_.clear();
    history_.clear();
    frameHome(true);
    maxCharacters_ = scene_.maxCharacters(renderSize_);
    controls_.followed.reset();
    message_.clear();
    for (const std::string& n : scene_.takeNotes()) note(n);
}

void Viewer::follow(std::optional<std::uint32_t> character) {
    controls_.followed = character;
    if (character) camera_.centerOn(characterCenter(*character));
}

void Viewer::frameHome(bool moveCamera) {
    // The same framing crowd-render's renderer starts with, so a script's picture matches its own.
    const app::CrowdShape shape = app::crowdShape(scene_.crowd());
    const VkExtent2D extent = swapchain_.extent();
    const float aspect = static_cast<float>(extent.width) / static_cast<float>(extent.height);
    camera_.setHome(app::frameCrowd(shape, aspect), {shape.center, shape.radius, shape.characterHeight});
    if (moveCamera) camera_.reset();
}

glm::vec3 Viewer::characterCenter(std::uint32_t character) const {
    // Its home, raised to the middle of the pose sphere: the sphere's centre height is about the
    // character's half height.
    const crowdgpu::Character c = scene_.crowd().character(character);
    float sphereCenter[3], radius = 0.0f;
    scene_.crowd().models()[c.model].poseSphere(sphereCenter, radius);
    return glm::vec3(c.position[0], c.position[1] + c.scale * sphereCenter[1], c.position[2]);
}

std::uint32_t Viewer::characterNearViewCenter() const {
    // Where the view's centre ray meets the ground, or the look-at point when it looks up.
    const app::Camera& camera = camera_.camera();
    const glm::vec3 direction = camera.target - camera.eye;
    const glm::vec3 point = direction.y < 0.0f ? camera.eye + direction * (-camera.eye.y / direction.y) : camera.target;
    const crowdgpu::Crowd& crowd = scene_.crowd();
    std::uint32_t nearest = 0;
    float nearestDistance = INFINITY;
    for (std::uint32_t i = 0; i < crowd.size(); ++i) {
        const crowdgpu::Character c = crowd.character(i);
        const glm::vec2 offset(c.position[0] - point.x, c.position[2] - point.z);
        const float distance = glm::dot(offset, offset);
        if (distance < nearestDistance) nearestDistance = distance, nearest = i;
    }
    return nearest;
}

void Viewer::writeScreenshot(const app::Rgba8Image& image) {
    std::string path = options_.screenshot;
    while (path.empty() || (options_.screenshot.empty() && std::filesystem::exists(path))) {
        char name[32];
        std::snprintf(name, sizeof name, "crowd-view-%03u.png", ++screenshots_);
        path = name;
    }
    try {
        app::writePng(path, image);
        note("wrote " + path + " (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    } catch (const app::Error& error) {
        if (options_.scripted) throw;  // a script's one output: failing it fails the run
        note(error.what());
    }
}

void Viewer::note(const std::string& message) {
    message_ = message;
    std::printf("crowd-view: %s\n", message.c_str());
    std::fflush(stdout);
}

PanelState Viewer::panelState() const {
    PanelState state;
    state.history = &history_;
    state.device = context_.description.name;
    state.presentMode = presentModeName(swapchain_.presentMode());
    state.characters = scene_.crowd().size();
    state.maxCharacters = maxCharacters_;
    state.lods = history_.latestLods();
    state.cull = cullOf(scene_.renderer().settings());
    state.shadows = scene_.renderer().settings().shadows;
    state.gpuAnimation = scene_.renderer().settings().animation == crowdgpu::Animation::Gpu;
    state.scenePath = controls_.scenePath;
    state.method = scene_.method();
    state.model = scene_.options().model;
    state.models = modelChoices(options_.render.scene.model);
    state.speed = controls_.speed;
    state.paused = controls_.paused;
    state.time = sceneTime_;
    state.duration = scene_.recordingDuration();
    state.cameraMode = camera_.mode();
    state.followed = controls_.followed;
    state.message = message_;
    return state;
}

}  // namespace view
