// crowd-view: its window-free logic (camera control, frame statistics) as plain functions, and the
// program as a user runs it, under a virtual X server (xvfb-run) on the tests' Vulkan device: a
// scripted run shows crowd-render's picture, the panel draws over it, validation stays silent,
// and the window survives being resized.
#ifdef CROWD_VIEW_BINARY

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include "app/png_writer.h"
#include "support/gltf_builder.h"
#include "support/gpu_test.h"
#include "support/run_program.h"
#include "view/camera_controller.h"
#include "view/frame_history.h"

namespace {

// ---------------------------------------------------------------------------------------------
// Camera control

app::Camera homeCamera() {
    app::Camera camera;
    camera.eye = {0.0f, 10.0f, 20.0f};
    camera.target = {0.0f, 1.0f, 0.0f};
    camera.nearPlane = 0.2f;
    camera.farPlane = 100.0f;
    return camera;
}

view::CameraController controllerAtHome() {
    view::CameraController controller;
    controller.setHome(homeCamera(), {glm::vec3(0.0f), 10.0f, 1.8f});
    controller.reset();
    return controller;
}

float distanceToTarget(const app::Camera& camera) { return glm::length(camera.eye - camera.target); }

TEST(ViewerCamera, NoInputLeavesTheHomeViewBitForBit) {
    // Scripted runs rely on it: the viewer's frame N must be crowd-render's frame N.
    view::CameraController controller = controllerAtHome();
    view::CameraInput idle;
    idle.seconds = 1.0f / 60.0f;
    for (view::CameraMode mode : {view::CameraMode::Orbit, view::CameraMode::Fly}) {
        controller.setMode(mode);
        controller.update(idle);
    }
    const app::Camera& camera = controller.camera();
    const app::Camera home = homeCamera();
    EXPECT_EQ(camera.eye, home.eye);
    EXPECT_EQ(camera.target, home.target);
    EXPECT_EQ(camera.nearPlane, home.nearPlane);
    EXPECT_EQ(camera.farPlane, home.farPlane);
}

TEST(ViewerCamera, OrbitDragCirclesTheTargetAtTheSameDistance) {
    view::CameraController controller = controllerAtHome();
    view::CameraInput drag;
    drag.orbitDrag = {120.0f, -40.0f};
    controller.update(drag);
    const app::Camera& camera = controller.camera();
    EXPECT_EQ(camera.target, homeCamera().target);
    EXPECT_NEAR(distanceToTarget(camera), distanceToTarget(homeCamera()), 1e-4f);
    EXPECT_GT(glm::length(camera.eye - homeCamera().eye), 1.0f);
}

TEST(ViewerCamera, OrbitStopsShortOfLookingStraightDown) {
    // glm::lookAt with up = +y breaks down when the view is vertical.
    view::CameraController controller = controllerAtHome();
    view::CameraInput drag;
    drag.orbitDrag = {0.0f, 100000.0f};
    controller.update(drag);
    const glm::vec3 view = glm::normalize(controller.camera().target - controller.camera().eye);
    EXPECT_GT(view.y, -0.999f);
    EXPECT_LT(view.y, -0.9f);
}

TEST(ViewerCamera, WheelZoomsTowardTheTargetAndStopsAtACloseUp) {
    view::CameraController controller = controllerAtHome();
    view::CameraInput wheel;
    wheel.wheel = 1.0f;
    controller.update(wheel);
    EXPECT_NEAR(distanceToTarget(controller.camera()), 0.85f * distanceToTarget(homeCamera()), 1e-3f);
    wheel.wheel = 1000.0f;
    controller.update(wheel);
    EXPECT_NEAR(distanceToTarget(controller.camera()), 0.5f * 1.8f, 1e-4f);  // half a character height
    EXPECT_LT(controller.camera().nearPlane, 0.5f * 1.8f);                     // the close-up is not clipped
}

TEST(ViewerCamera, FlyMovesEyeAndTargetTogether) {
    view::CameraController controller = controllerAtHome();
    controller.setMode(view::CameraMode::Fly);
    view::CameraInput forward;
    forward.move = {0.0f, 0.0f, 1.0f};
    forward.seconds = 0.5f;
    controller.update(forward);
    const app::Camera& camera = controller.camera();
    const glm::vec3 moved = camera.eye - homeCamera().eye;
    // Half a second at two character heights per second (more than a quarter of the radius per second).
    EXPECT_NEAR(glm::length(moved), 0.5f * 2.0f * 1.8f, 1e-3f);
    EXPECT_NEAR(glm::length(camera.target - homeCamera().target - moved), 0.0f, 1e-4f);
    EXPECT_GT(glm::dot(moved, homeCamera().target - homeCamera().eye), 0.0f);
}

TEST(ViewerCamera, FlyLookTurnsAroundTheEye) {
    view::CameraController controller = controllerAtHome();
    controller.setMode(view::CameraMode::Fly);
    view::CameraInput look;
    look.lookDrag = {200.0f, 0.0f};
    controller.update(look);
    EXPECT_EQ(controller.camera().eye, homeCamera().eye);
    EXPECT_GT(glm::length(controller.camera().target - homeCamera().target), 1.0f);
}

TEST(ViewerCamera, ResetReturnsHomeAfterAnyMove) {
    view::CameraController controller = controllerAtHome();
    view::CameraInput input;
    input.orbitDrag = {50.0f, 20.0f};
    input.wheel = 3.0f;
    controller.update(input);
    controller.reset();
    EXPECT_EQ(controller.camera().eye, homeCamera().eye);
    EXPECT_EQ(controller.camera().target, homeCamera().target);
    EXPECT_EQ(controller.camera().farPlane, homeCamera().farPlane);
}

TEST(ViewerCamera, CenterOnOrbitsTheCharacterFromAFewHeightsAway) {
    view::CameraController controller = controllerAtHome();
    controller.setMode(view::CameraMode::Fly);
    const glm::vec3 character(4.0f, 0.9f, -2.0f);
    controller.centerOn(character);
    EXPECT_EQ(controller.mode(), view::CameraMode::Orbit);
    EXPECT_EQ(controller.camera().target, character);
    EXPECT_NEAR(distanceToTarget(controller.camera()), 3.0f * 1.8f, 1e-4f);
    controller.track(character + glm::vec3(1.0f, 0.0f, 0.0f));  // it walked one unit along x
    EXPECT_EQ(controller.camera().target, character + glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_NEAR(distanceToTarget(controller.camera()), 3.0f * 1.8f, 1e-4f);
}

// ---------------------------------------------------------------------------------------------
// Frame statistics

app::FrameStats frameStats(double intervalMs, double skinMs) {
    app::FrameStats stats;
    stats.intervalMs = intervalMs;
    stats.animateMs = 1.0;
    stats.recordMs = 0.5;
    stats.gpu = {{"skin", skinMs}, {"draw", 2.0}};
    return stats;
}

TEST(ViewerFrameHistory, KeepsOnlyTheLastFrames) {
    view::FrameHistory history(3);
    for (double ms : {10.0, 20.0, 30.0, 40.0}) history.add(frameStats(ms, 1.0));
    EXPECT_EQ(history.size(), 3u);
    EXPECT_EQ(history.frameMs(), (std::vector<float>{20.0f, 30.0f, 40.0f}));
    EXPECT_DOUBLE_EQ(history.meanFrameMs(), 30.0);
    EXPECT_NEAR(history.fps(), 1000.0 / 30.0, 1e-9);
}

TEST(ViewerFrameHistory, FirstFrameWithoutIntervalIsLeftOutOfFrameTimes) {
    view::FrameHistory history;
    history.add(frameStats(0.0, 1.0));  // a renderer's first frame has no previous one
    history.add(frameStats(16.0, 1.0));
    EXPECT_EQ(history.frameMs(), std::vector<float>{16.0f});
    EXPECT_DOUBLE_EQ(history.meanCpuMs(), 1.5);
}

TEST(ViewerFrameHistory, AveragesGpuTimePerPassInFirstSeenOrder) {
    view::FrameHistory history;
    history.add(frameStats(16.0, 1.0));
    history.add(frameStats(16.0, 3.0));
    const std::vector<app::PassTime> passes = history.meanGpuMs();
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_EQ(passes[0].pass, "skin");
    EXPECT_DOUBLE_EQ(passes[0].milliseconds, 2.0);
    EXPECT_EQ(passes[1].pass, "draw");
    EXPECT_DOUBLE_EQ(passes[1].milliseconds, 2.0);
}

// ---------------------------------------------------------------------------------------------
// The program

const std::string kView = CROWD_VIEW_BINARY;
const std::string kRender = CROWD_RENDER_BINARY;

bool onPath(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

std::string tempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-view-test-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

// The device the GPU tests use (CROWD_TEST_DEVICE), for both programs.
std::string deviceFlag() {
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    return device ? std::string(" --device '") + device + "'" : "";
}

// xvfb-run with a server number of its own: ctest -j starts several at once, and xvfb-run -a alone
// races for the same free number.
std::string xvfbRun() {
    return "xvfb-run -a -n " + std::to_string(100 + ::getpid() % 2000) + " -s '-screen 0 1600x900x24' ";
}

// Runs `program` under xvfb-run. Its own clean-up (removing its temporary directory) fails now and then
// when several run at once ("xvfb-run: error: problem while cleaning up temporary directory", exit 5,
// seen under ctest -j2): the wrapper's failure, not the program's, so that run is repeated, twice at most.
test::ProgramResult runUnderXvfb(const std::string& program, const std::string& arguments) {
    test::ProgramResult r;
    for (int attempt = 0; attempt < 3; ++attempt) {
        r = test::runProgram(xvfbRun() + program, arguments);
        if (r.err.find("xvfb-run: error:") == std::string::npos) break;
    }
    return r;
}

#define SKIP_WITHOUT_XVFB()                                                                                   \
    if (!onPath("xvfb-run") || !onPath("xauth"))                                                              \
    GTEST_SKIP() << "xvfb-run or xauth not found: the viewer tests need a virtual X server "                  \
                    "(scripts/setup.sh --tests installs xvfb and xauth)"

app::Rgba8Image readPng(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) return {};
    app::Rgba8Image image{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height),
                             std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(width) * height * 4)};
    stbi_image_free(data);
    return image;
}

// crowd-render's picture of the same scene, size and frame count.
app::Rgba8Image renderReference(const std::string& scene, const std::string& name) {
    const std::string png = tempFile(name);
    const test::ProgramResult r = test::runProgram(kRender, scene + deviceFlag() + " --out " + png);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    app::Rgba8Image image = readPng(png);
    std::filesystem::remove(png);
    return image;
}

// A run exits 0 and the validation layer (with synchronization checks) said nothing, exit included.
void expectCleanRun(const test::ProgramResult& r) {
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
}

void keepForInspection(const app::Rgba8Image& viewer, const app::Rgba8Image& reference, const std::string& name) {
    app::writePng(test::artifactPath(name + "-view.png"), viewer);
    app::writePng(test::artifactPath(name + "-render.png"), reference);
}

TEST(ViewerProgram, ScriptedScreenshotMatchesCrowdRender) {
    SKIP_WITHOUT_XVFB();
    // The swapchain path (scene image -> blit into a B8G8R8A8_SRGB swapchain image -> copy out,
    // BGRA to RGBA) must keep every byte of crowd-render's image; with the edge filter (--aa fxaa) too,
    // whose picture is another image, written in compute.
    std::vector<app::Rgba8Image> references;
    for (const std::string aa : {"off", "fxaa"}) {
        const std::string scene = "--count 16 --frames 3 --size 160x120 --validation --aa " + aa;
        const std::string png = tempFile("scripted-" + aa + ".png");
        const test::ProgramResult r = runUnderXvfb(kView, scene + deviceFlag() + " --no-ui --screenshot " + png);
        expectCleanRun(r);
        const app::Rgba8Image viewer = readPng(png);
        references.push_back(renderReference(scene, "scripted-reference-" + aa + ".png"));
        ASSERT_EQ(viewer.width, 160u);
        ASSERT_EQ(viewer.height, 120u);
        const double matching = test::fractionOfMatchingPixels(viewer, references.back(), 2);
        EXPECT_GE(matching, 0.995) << "--aa " << aa;
        if (matching < 0.995) keepForInspection(viewer, references.back(), "viewer-scripted-" + aa);
        std::filesystem::remove(png);
    }
    EXPECT_LT(test::fractionOfMatchingPixels(references[0], references[1], 2), 0.995) << "the filter changed nothing";
}

TEST(ViewerProgram, ARecordingReplaysAsInCrowdRender) {
    SKIP_WITHOUT_XVFB();
    // A recorded crowd (two people walking past each other, PeTrack text) on hills, from 1.5 s into it:
    // the viewer's picture is crowd-render's (the recording's time, which the panel's slider scrubs, is
    // the scene's time).
    const std::string recording = tempFile("walkers.txt");
    {
        std::ofstream file(recording);
        file << "# framerate: 25 fps\n# id frame x/cm y/cm z/cm\n";
        for (int frame = 0; frame <= 100; ++frame)
            file << "1 " << frame << " " << 4.8 * frame << " 0 170\n2 " << frame << " " << 600 - 4.8 * frame << " 150 170\n";
    }
    const std::string scene =
        "--trajectories " + recording + " --terrain hills --start 1.5 --frames 3 --size 160x120 --validation";
    const std::string png = tempFile("replay.png");
    const test::ProgramResult r = runUnderXvfb(kView, scene + deviceFlag() + " --no-ui --screenshot " + png);
    expectCleanRun(r);
    const app::Rgba8Image viewer = readPng(png);
    const app::Rgba8Image reference = renderReference(scene, "replay-reference.png");
    ASSERT_EQ(viewer.width, 160u);
    const double matching = test::fractionOfMatchingPixels(viewer, reference, 2);
    EXPECT_GE(matching, 0.995);
    if (matching < 0.995) keepForInspection(viewer, reference, "viewer-replay");
    std::filesystem::remove(png);
    std::filesystem::remove(recording);
}

TEST(ViewerProgram, MeshCapacityGivesCrowdRendersPicture) {
    SKIP_WITHOUT_XVFB();
    // Impostors with a cap of 2 mesh-level characters: the other 14 are drawn as impostors, in both programs.
    const std::string scene = "--count 16 --frames 3 --size 160x120 --impostors on --mesh-capacity 2 --validation";
    const std::string png = tempFile("capped.png");
    const test::ProgramResult r =
        runUnderXvfb(kView, scene + deviceFlag() + " --no-ui --screenshot " + png);
    expectCleanRun(r);
    const app::Rgba8Image viewer = readPng(png);
    const app::Rgba8Image reference = renderReference(scene, "capped-reference.png");
    const app::Rgba8Image uncapped =
        renderReference("--count 16 --frames 3 --size 160x120 --impostors on", "uncapped-reference.png");
    ASSERT_EQ(viewer.width, 160u);
    EXPECT_LT(test::fractionOfMatchingPixels(reference, uncapped, 2), 0.995) << "the cap changes nothing here";
    const double matching = test::fractionOfMatchingPixels(viewer, reference, 2);
    EXPECT_GE(matching, 0.995);
    if (matching < 0.995) keepForInspection(viewer, reference, "viewer-capped");
    std::filesystem::remove(png);
}

TEST(ViewerProgram, PanelDrawsOverTheSameSceneWithValidationSilent) {
    SKIP_WITHOUT_XVFB();
    const std::string scene = "--count 16 --frames 3 --size 640x360 --validation";
    const std::string png = tempFile("panel.png");
    const test::ProgramResult r = runUnderXvfb(kView, scene + deviceFlag() + " --screenshot " + png);
    expectCleanRun(r);
    const app::Rgba8Image viewer = readPng(png);
    const app::Rgba8Image reference = renderReference(scene, "panel-reference.png");
    ASSERT_EQ(viewer.width, 640u);
    // The panel covers the top-left corner; the rest of the window is crowd-render's picture.
    const double matching = test::fractionOfMatchingPixels(viewer, reference, 2);
    EXPECT_LT(matching, 0.95) << "no panel drawn";
    EXPECT_GT(matching, 0.40) << "the scene is missing around the panel";
    if (matching >= 0.95 || matching <= 0.40) keepForInspection(viewer, reference, "viewer-panel");
    std::filesystem::remove(png);
}

// Footstep markers (view/event_markers.h): strip characters whose clip fires an event every 0.1 s (no
// joint: at each one's root), 30 scripted frames with the panel. Right of the panel, the picture with
// --events on differs from --events off only where markers are drawn: some pixels, at least three in four
// pulled towards the markers' fill or outline colour (measured 84 %; the rest are where the outline is
// blended over the fill).
// Without markers the two pictures are equal.
constexpr int kMarkerColours[2][3] = {{235, 215, 170}, {120, 90, 50}};  // view/event_markers.cpp
TEST(ViewerProgram, EventMarkersAreDrawnWhereEventsFire) {
    SKIP_WITHOUT_XVFB();
    test::GltfBuilder strip = test::stripCharacter();
    nlohmann::json events = nlohmann::json::array();
    for (int i = 0; i < 10; ++i) events.push_back({{"name", "tick"}, {"time", 0.05 + 0.1 * i}});
    strip.doc["animations"][0]["extras"] = {{"events", events}};
    const std::string model = tempFile("strip-events.gltf");
    std::ofstream(model) << strip.gltf();
    const std::string scene = "--model " + model + " --count 16 --frames 30 --size 640x360 --validation";
    app::Rgba8Image pictures[2];
    for (int on = 0; on < 2; ++on) {
        const std::string png = tempFile(on ? "events-on.png" : "events-off.png");
        const test::ProgramResult r = runUnderXvfb(
            kView, scene + deviceFlag() + " --events " + (on ? "on" : "off") + " --screenshot " + png);
        expectCleanRun(r);
        pictures[on] = readPng(png);
        std::filesystem::remove(png);
    }
    std::filesystem::remove(model);
    ASSERT_EQ(pictures[0].width, 640u);
    ASSERT_EQ(pictures[1].width, 640u);
    std::size_t differing = 0, sandy = 0;
    for (std::uint32_t y = 0; y < 360; ++y)
        for (std::uint32_t x = 400; x < 640; ++x) {  // right of the panel (its statistics differ run to run)
            const std::size_t p = (std::size_t{y} * 640 + x) * 4;
            int change = 0;
            for (int c = 0; c < 3; ++c) change = std::max(change, std::abs(pictures[1].pixels[p + c] - pictures[0].pixels[p + c]));
            if (change <= 8) continue;
            ++differing;
            // Nearer the marker's fill or outline colour than the picture without markers.
            auto toMarker = [&](const app::Rgba8Image& image) {
                double nearest = 1e9;
                for (const auto& colour : kMarkerColours) {
                    double d = 0.0;
                    for (int c = 0; c < 3; ++c) d += std::pow(image.pixels[p + c] - colour[c], 2.0);
                    nearest = std::min(nearest, d);
                }
                return nearest;
            };
            sandy += toMarker(pictures[1]) < toMarker(pictures[0]) ? 1u : 0u;
        }
    EXPECT_GT(differing, 20u) << "no markers drawn";
    EXPECT_GE(sandy, differing * 3 / 4) << "pixels changed that are not markers";
    std::printf("[ markers ] %zu pixels differ right of the panel, %zu towards sand\n", differing, sandy);
}

TEST(ViewerProgram, ResizedWindowRendersAtItsNewSizeAndEscapeCloses) {
    SKIP_WITHOUT_XVFB();
    if (!onPath("xdotool")) GTEST_SKIP() << "xdotool not found: it resizes the window (apt-get install xdotool)";
    // Two resizes (each recreates the swapchain and the renderer's target), then F12 and Esc as a
    // user would press them. X delivers the resize before the keys, so F12 sees the new size.
    const std::string png = tempFile("resized.png");
    const std::string script = tempFile("resize.sh");
    std::ofstream(script) << "set -e\n"
                          << kView << " --count 4 --size 160x120 --no-ui --validation" << deviceFlag()
                          << " --screenshot " << png << " &\n"
                          << "pid=$!\n"
                          << "wid=$(xdotool search --sync --name '^crowd-view$' | head -n 1)\n"
                          << "xdotool windowsize $wid 320 200\nsleep 1\n"
                          << "xdotool windowsize $wid 240 100\nsleep 1\n"
                          << "xdotool windowfocus $wid key F12\nsleep 1\n"
                          << "xdotool key Escape\n"
                          << "wait $pid\n";
    const test::ProgramResult r = runUnderXvfb("sh", script);
    expectCleanRun(r);
    const app::Rgba8Image viewer = readPng(png);
    ASSERT_EQ(viewer.width, 240u) << r.out;
    ASSERT_EQ(viewer.height, 100u);
    // Real time, so poses differ from crowd-render's; the ground, sky and framing do not (the camera
    // stays put on resize, and frameCrowd frames both shapes alike).
    const app::Rgba8Image reference =
        renderReference("--count 4 --frames 1 --size 240x100", "resized-reference.png");
    const double matching = test::fractionOfMatchingPixels(viewer, reference, 2);
    EXPECT_GT(matching, 0.90);
    if (matching <= 0.90) keepForInspection(viewer, reference, "viewer-resized");
    std::filesystem::remove(png);
    std::filesystem::remove(script);
}

TEST(ViewerProgram, ScreenshotThatCannotBeWrittenFailsTheScript) {
    SKIP_WITHOUT_XVFB();
    const std::string png = tempFile("cut-short.png");
    for (const auto& [program, path] : {std::pair{kView, std::string("/dev/full")},
                                        std::pair{test::withFileSizeLimit(kView, 1), png}}) {
        const test::ProgramResult r = runUnderXvfb(
            program, "--count 4 --frames 1 --size 320x240 --no-ui" + deviceFlag() + " --screenshot " + path);
        EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
        EXPECT_EQ(r.err, "crowd-view: cannot write " + path + ": " +
                             (path == png ? "File too large" : "No space left on device") + "\n");
        EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
    }
    EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(ViewerProgram, WindowLargerThanTheDeviceCanPresentIsShrunkWithValidationSilent) {
    SKIP_WITHOUT_XVFB();
    if (!onPath("xdotool")) GTEST_SKIP() << "xdotool not found: it resizes the window (apt-get install xdotool)";
    // 17,000 rows is beyond the largest image, framebuffer and viewport of lavapipe (16,384) and most
    // GPUs, while its X11 surface asks for exactly the window's size: the swapchain, the renderer's
    // target and the panel's pass must stay within the device's limits, and the window is shrunk back.
    // The panel is on, so its pass is checked too.
    const std::string png = tempFile("tall.png");
    const std::string script = tempFile("tall.sh");
    std::ofstream(script) << "set -e\n"
                          << kView << " --count 4 --size 160x120 --validation" << deviceFlag() << " --screenshot "
                          << png << " &\n"
                          << "pid=$!\n"
                          << "wid=$(xdotool search --sync --name '^crowd-view$' | head -n 1)\n"
                          << "xdotool windowsize $wid 100 17000\nsleep 2\n"
                          << "xdotool windowfocus $wid key F12\nsleep 2\n"
                          << "xdotool key Escape\n"
                          << "wait $pid\n";
    const test::ProgramResult r = runUnderXvfb("sh", script);
    expectCleanRun(r);
    const app::Rgba8Image viewer = readPng(png);
    // Two ways to shrink, both correct: the window's size limits (set from the device's largest extent)
    // make the X server refuse the height outright, or, when the resize arrives before they take hold,
    // the viewer sees 17,000 rows, notes "a 100x17000 window is larger than ..." and shrinks the window
    // back. Which one happens is a race, so the test checks the outcome: the size below.
    EXPECT_EQ(viewer.width, 100u) << r.out;
    EXPECT_GE(viewer.height, 4096u) << "Vulkan guarantees 4,096-pixel images";
    EXPECT_LT(viewer.height, 17000u);
    std::filesystem::remove(png);
    std::filesystem::remove(script);
}

TEST(ViewerProgram, AWindowPastTheDevicesLimitsWithMultisamplingIsDrawnScaled) {
    SKIP_WITHOUT_XVFB();
    if (!onPath("xdotool")) GTEST_SKIP() << "xdotool not found: it resizes the window (apt-get install xdotool)";
    // 16384 x 16384 with 4 samples a pixel is a 4 GiB multisampled colour image (and as much depth): past
    // lavapipe's maxResourceSize and its 2 GiB heap, and most GPUs'. Before, the viewer quit with
    // validation errors and VK_ERROR_OUT_OF_DEVICE_MEMORY. Now it draws at the largest size of the
    // window's shape that fits, scaled up, and says so; back at a small size it draws 1:1 again.
    const std::string png = tempFile("huge-msaa.png");
    const std::string log = tempFile("huge-msaa.log");
    const std::string script = tempFile("huge-msaa.sh");
    std::ofstream(script) << "set -e\n"
                          << kView << " --count 4 --size 160x120 --aa msaa4 --no-ui --validation" << deviceFlag()
                          << " --screenshot " << png << " > " << log << " &\n"
                          << "pid=$!\n"
                          << "wid=$(xdotool search --sync --name '^crowd-view$' | head -n 1)\n"
                          << "xdotool windowsize $wid 16384 16384\n"
                          // The viewer notes the scaled size when it recreates its swapchain, then draws.
                          << "for i in $(seq 120); do grep -q 'scaled up' " << log << " && break; sleep 1; done\n"
                          << "sleep 10\n"
                          << "xdotool windowsize $wid 240 100\nsleep 3\n"
                          << "xdotool windowfocus $wid key F12\nsleep 2\n"
                          << "xdotool key Escape\n"
                          << "status=0; wait $pid || status=$?\n"
                          << "cat " << log << "\nexit $status\n";
    const test::ProgramResult r = runUnderXvfb("sh", script);
    expectCleanRun(r);
    EXPECT_EQ(r.err.find("OUT_OF_DEVICE_MEMORY"), std::string::npos) << r.err;
    const std::size_t note = r.out.find("the 16384x16384 window is drawn at ");
    ASSERT_NE(note, std::string::npos) << r.out;
    unsigned width = 0, height = 0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + note, "the 16384x16384 window is drawn at %ux%u", &width, &height), 2) << r.out;
    EXPECT_LT(width, 16384u);
    EXPECT_EQ(width, height) << "the window's shape is kept";
    EXPECT_GE(width, 1024u);
    EXPECT_NE(r.out.find("msaa4"), std::string::npos) << "the note names the anti-aliasing kept: " << r.out;
    const app::Rgba8Image viewer = readPng(png);
    EXPECT_EQ(viewer.width, 240u) << r.out;
    EXPECT_EQ(viewer.height, 100u);
    std::filesystem::remove(png);
    std::filesystem::remove(log);
    std::filesystem::remove(script);
}

TEST(ViewerProgram, BadFlagsAndNoDisplayFailWithOneLine) {
    // None of these needs a display: they fail before a window opens.
    struct Case {
        std::string arguments, mention, environment;
    };
    const std::vector<Case> cases = {
        {"--vsync sometimes", "--vsync", ""},
        {"--screenshot /nonexistent-dir/x.png --frames 1", "/nonexistent-dir/x.png", ""},
        {"--count 0", "--count", ""},
        {"--bogus", "--bogus", ""},
        {"--count 1 --frames 1", "display", "DISPLAY= WAYLAND_DISPLAY="},
    };
    for (const Case& c : cases) {
        const test::ProgramResult r = test::runProgram(kView, c.arguments, c.environment);
        EXPECT_EQ(r.exitCode, 1) << c.arguments << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.arguments << " printed:\n" << r.err;
        EXPECT_NE(r.err.find(c.mention), std::string::npos) << c.arguments << " printed:\n" << r.err;
        EXPECT_EQ(r.err.rfind("crowd-view: ", 0), 0u) << r.err;
    }
    const test::ProgramResult help = test::runProgram(kView, "--help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--screenshot"), std::string::npos);
}

}  // namespace

#endif  // CROWD_VIEW_BINARY
