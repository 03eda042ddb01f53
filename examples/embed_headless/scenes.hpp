// What embed_headless draws: its own small scene, or the crowd and camera path of one of the scenes
// crowdgpu's programs know by name (crowd-render / crowd-bench --scene), rebuilt here with the public
// API alone. The programs' frame N of a scene is the crowd at time start + N / 60 s seen from their
// camera path at that time; so is the example's, which is what lets a script compare the cost of the
// very same frames drawn by the programs and by this host.
#pragma once

#include <cstdint>
#include <string>

#include <crowdgpu/crowd.hpp>

enum class Scene {
    Own,        // 64 soldiers seen three-quarter from above, the host's ground and boxes around them
    PaperFig4,  // crowd-bench --scene paper-fig4: 10,240 soldiers, the camera flying over them
    Stress,     // crowd-bench --scene stress: 100,000 soldiers, from high above down into the crowd
};

// "own", "paper-fig4", "stress"; false for any other name.
bool parseScene(const std::string& name, Scene& scene);
const char* sceneName(Scene scene);
// The scene's crowd size unless the command line gives one.
std::uint32_t defaultCount(Scene scene);

// The programs' crowd of `count` built-in soldiers (proportions seed 1) on their seeded grid: every
// scene here is that crowd, only its size differs.
crowdgpu::Crowd makeCrowd(std::uint32_t count);

// Where the camera is at `seconds` on the scene's clock, as crowdgpu::lookAt takes it.
struct CameraPose {
    float eye[3];
    float target[3];
    float verticalFov;  // radians
    float nearPlane, farPlane;
};
CameraPose cameraAt(Scene scene, const crowdgpu::Crowd& crowd, double seconds);

// The programs' clock: frame `index` of a run that starts at `start` seconds, at a fixed 60 Hz step
// so that every run of a scene shows the same frames.
inline double frameTime(std::uint32_t index, double start) { return start + static_cast<double>(index) / 60.0; }
