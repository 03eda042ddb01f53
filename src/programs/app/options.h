#pragma once
// Command-line flags shared by crowd-render, crowd-view and crowd-bench, so the same command line
// describes the same crowd in each.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <crowdgpu/renderer.hpp>

#include "app/anti_aliasing.h"
#include "app/camera_path.h"
#include "app/names.h"
#include "replay/path_smoothing.h"
#include "replay/trajectory_options.h"

namespace app {

// Mesh-level characters a frame may draw when impostors are on (--mesh-capacity): 65,536 soldiers'
// skinned vertices take 1.7 GB, while from inside a crowd of millions a few thousand pass the
// impostor threshold.
inline constexpr std::uint32_t kDefaultMeshCapacity = 65536;

// Culling and levels of detail (crowdgpu::RendererSettings has the same values).
struct CullOptions {
    crowdgpu::Culling mode = crowdgpu::Culling::Gpu;
    bool lod = true;
    float lodThresholds[2] = {150.0f, 50.0f};  // pixels of pose-sphere diameter for LOD 0 and 1
    float hysteresis = 0.1f;
    bool impostors = false;
    float impostorThreshold = 32.0f;
    bool shadowLod = true;  // casters' level in the shadow map from their size there (crowdgpu::RendererSettings)
    crowdgpu::ShadowRaster shadowRaster = crowdgpu::ShadowRaster::Compute;  // how the map's casters are drawn
    std::uint32_t shadowCascades = crowdgpu::RendererSettings{}.shadowCascades;  // the map's cascades, 1 to 4
    bool lodFade = true;        // level changes fade across the hysteresis band (crowdgpu::RendererSettings)
    bool impostorBlend = true;  // impostors blend up to eight atlas cells, or show the nearest (crowdgpu::RendererSettings)
    bool farCrowd = crowdgpu::RendererSettings{}.farCrowd;  // --far-crowd average|off (crowdgpu::RendererSettings)
    bool events = true;  // the GPU event buffer of the characters in view (crowdgpu::RendererSettings::events)
    // Which rasterizer draws the impostors, decided per impostor by its size under auto (--raster).
    crowdgpu::Raster raster = crowdgpu::Raster::Auto;
    // Under auto, the largest character (pixels across) whose mesh goes to compute (--mesh-raster-limit).
    float meshRasterLimit = crowdgpu::RendererSettings{}.meshRasterLimit;
};

// The host's world (docs/host-driven.md): the ground, a recorded crowd replayed by characters, and the
// benchmarks' populations that come and go and their agents driven from the host's memory or a device buffer.
struct WorldOptions {
    bool hills = false;         // --terrain hills: a built-in hilly ground under the scene (app/terrain_hills.h)
    std::string trajectories;   // --trajectories FILE: the crowd is the file's people, replayed (app/replay_driver.h)
    replay::ReadOptions read;   // --trajectory-format, --trajectory-fps, --trajectory-units
    std::uint32_t copies = 1;   // --trajectory-copies N: copies side by side, shifted in time
    double smoothing = replay::kDefaultSmoothingWindow;  // --trajectory-smoothing SECONDS (0: the raw samples)
    double delay = 0.1;         // --drive-delay SECONDS: driven characters are drawn this far behind their samples
    double churn = 0.0;         // --churn PERCENT: that share of the crowd leaves and as many enter every frame
    // --agents host|device: the crowd's characters driven by a simulation of agents on the CPU (samples in
    // arrays, Crowd::drive) or on the GPU (a pass of the host's writing device samples), a sample a frame.
    enum class Agents { None, Host, Device } agents = Agents::None;
    std::string exportStates;                // --export-states FILE.csv: every frame's living characters
    std::vector<std::string> exportJoints;   // --export-joints NAME,...: and these joints' world positions
};

// What a crowd is: models, size, clip, seed.
struct SceneOptions {
    std::string scene = "default";  // the preset the other values started from (app/scene_presets.h)
    // "soldier", "horse" or a glTF file; several as NAME[:WEIGHT],... (each model's share of the crowd)
    std::string model = "soldier";
    std::uint32_t count = 1024;
    std::string clip;               // name or index; "" = the model's default clip, "random" = one per character
    std::uint32_t seed = 1;
    std::string assetRoot;          // folder a glTF model's external files must lie in; "" = the model's own
    crowdgpu::Behaviour behaviour = crowdgpu::Behaviour::InPlace;  // what the characters do (crowdgpu/crowd.hpp)
    float depthRatio = 1.0f;        // the grid's rows over columns (a scene's; crowdgpu::GridLayout)
    bool props = true;              // --props: characters carry their models' props (docs/props.md)
    WorldOptions world;             // the host's world: terrain, recordings, populations that change, agents
};

struct RenderOptions {
    SceneOptions scene;
    app::CullOptions cull;
    app::CameraPath camera = app::CameraPath::Framed;
    double startSeconds = 0.0;  // scene time of the first frame (where on the camera path a run begins)
    bool shadows = true;        // the directional light's shadow map
    unsigned threads = 0;       // --threads: CPU threads of the crowd's work (crowdgpu::setWorkerThreads); 0: one per core
    AntiAliasing antiAliasing = kDefaultAntiAliasing;  // --aa: samples per pixel and the edge filter
    crowdgpu::Method method = crowdgpu::Method::TwoPass;
    crowdgpu::Animation animation = crowdgpu::Animation::Gpu;  // where bone matrices are computed
    // With impostors on (cull.impostors): the most characters at a mesh level (LOD 0-2) in a frame.
    std::uint32_t meshCapacity = kDefaultMeshCapacity;
    std::uint32_t frames = 30;
    VkExtent2D size{1280, 720};
    std::string out = "crowd.png";
    std::string device;
    std::string json;
    bool validation = false;
    bool listDevices = false;
    bool help = false;
};

// A program's own flags beyond the shared ones: returns true when it consumed `flag`, calling
// `value()` to take the flag's value.
using ExtraFlagParser = std::function<bool(const std::string& flag, const std::function<std::string()>& value)>;

// Turns argv into options. Throws app::Error with a one-line message naming the bad flag or value.
RenderOptions parseRenderOptions(const std::vector<std::string>& args, const ExtraFlagParser& extra = {});

// Strict parsers for flag values (whole string, no sign, within [min, max]); throw app::Error.
std::uint32_t parseCount(const std::string& flag, const std::string& text, std::uint32_t min, std::uint32_t max);
VkExtent2D parseSize(const std::string& flag, const std::string& text);
float parseNumber(const std::string& flag, const std::string& text, float min, float max);

const char* renderUsage();

// Largest --count accepted before any memory check: beyond it the CPU-side crowd alone is unreasonable.
constexpr std::uint32_t kMaxCharacters = 16u * 1024u * 1024u;

}  // namespace app
