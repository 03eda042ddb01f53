#include "app/options.h"

#include <algorithm>
#include <charconv>
#include <functional>
#include <cmath>
#include <cstdio>

#include "app/number_text.h"
#include "app/scene_presets.h"
#include "app/start_time.h"
#include "app/terrain_hills.h"

#include "app/error.h"

namespace app {


namespace {
constexpr const char* kRenderUsage = R"(crowd-render: renders a skinned crowd headless and writes a PNG of the last frame plus timings.

usage: crowd-render [options]
  --scene NAME            default, paper-fig3, paper-fig4, paper-fig5, mixed, stress, march, mill or
                          cavalry: a crowd, what it does, its culling and LOD, and a camera path
                          (flags beside it override)
  --model LIST            soldier, horse, cavalry (a soldier on a horse) or a skinned glTF 2.0 file
                          (.gltf/.glb); several as NAME[:WEIGHT],... e.g. soldier:3,horse:1 (default
                          soldier)
  --asset-root DIR        let a glTF file's buffers and images come from anywhere inside DIR (default:
                          the file's own folder and below)
  --count N               characters, 1..16777216 (default 1024)
  --lod on|off            three levels of detail chosen by projected size (default on)
  --cull gpu|cpu|off      frustum culling and LOD choice on the GPU, on the CPU (the reference), or
                          no culling (default gpu)
  --lod-thresholds A,B    LOD 0 while a character's pose sphere is at least A pixels across, LOD 1
                          while at least B, else LOD 2 (default 150,50)
  --impostors on|off      the impostor level: characters whose pose sphere is under the impostor
                          threshold are drawn as camera-facing quads from an atlas baked at load time
                          (default off)
  --impostor-threshold PX impostor level below PX pixels across, 0 < PX < B of --lod-thresholds (default 32)
  --props on|off          characters carry their models' props (the soldier's rifle, one in eight a
                          flag; docs/props.md); off: none (default on)
  --impostor-blend on|off impostors blend the two nearest views, elevation bands and animation frames;
                          off: the nearest atlas cell, one texture fetch instead of up to eight (default on)
  --far-crowd average|off impostors of 16 px or less drawn in compute add their coverage to a blended
                          layer, a stable average; off: each wins whole pixels or none (default average)
  --events on|off         the GPU event buffer: clip events (footsteps) of the characters in view,
                          found by a pass after culling (default on; docs/events.md)
  --mesh-capacity N       with impostors on: at most N characters at LOD 0-2 in a frame; beyond N, the
                          smallest on screen are drawn as impostors; sizes the skinned-vertex buffers
                          (default 65536)
  --shadows on|off        the sun's shadow map, drawn from the same skinned vertices (default on)
  --shadow-lod on|off     casters drawn into the shadow map at a level of detail from their size in it
                          (texels, the --lod-thresholds values), never finer than in view, and not at
                          all under 2 texels; off: at their level in view (default on)
  --shadow-raster hardware|compute
                          the shadow map's casters (meshes and impostors) drawn by the graphics
                          pipeline or rasterized in compute (methods with skinned vertices in a buffer;
                          default compute)
  --shadow-cascades N     the shadow map's cascades, 1 to 4, split by distance: near shadows get finer
                          texels, far ones coarser, for a cost; 1: one map over the whole view (default 1)
  --aa off|msaa2|msaa4|msaa8|fxaa|msaaN+fxaa
                          anti-aliasing: 2, 4 or 8 samples per pixel for the characters, impostors
                          and ground, averaged into the picture; fxaa: an edge filter over the
                          finished picture, in compute; or both (default %AA%)
  --raster hardware|compute|auto
                          which rasterizer draws the impostors: the hardware's, a compute pass into a
                          visibility buffer, or by size on screen (compute up to 128 px); compute needs
                          64-bit atomics, auto falls back to hardware; with --aa, what compute draws
                          fills whole pixels (default auto)
  --mesh-raster-limit auto|PX
                          under --raster auto, characters up to PX pixels across (pose sphere) have their
                          meshes rasterized in compute every frame (methods that skin into a buffer); 0:
                          none; auto: 64 px on frames after one that drew 4,000,000 mesh triangles
                          (default auto); --raster compute takes every mesh wholly in front of the eye
  --terrain flat|hills    the ground: a plane at y = 0, or built-in hills (slopes to 19 degrees) under the
                          scene that every character stands on (default flat)
  --trajectories FILE     the crowd is a recorded (or simulated) crowd's people, replayed: each enters when
                          its track starts, follows its samples and leaves when it ends (PeTrack text,
                          JuPedSim SQLite, ETH/UCY obsmat or CSV, found from the content; docs/host-driven.md)
  --trajectory-format F   auto, petrack, jupedsim, obsmat or csv (default auto)
  --trajectory-fps N      the recording's frames per second when the file does not say it
  --trajectory-units U    m, cm or mm when the file does not say it
  --trajectory-copies N   N copies of the recording side by side, shifted in time (default 1)
  --trajectory-smoothing S  seconds over which a track's head sway is smoothed out (default 0.6; 0 off)
  --drive-delay S         driven characters are drawn S seconds behind their samples (default 0.1)
  --export-states FILE.csv  every frame's living characters: id (the file's, for a replay), time, root
                          x y z, heading, clip, playback rate
  --export-joints LIST    and these joints' world positions (NAME,...; with --export-states)
  --churn PERCENT         that share of the crowd leaves and as many enter every frame (a live population)
  --agents none|host|device
                          the crowd's characters are agents of a simulation on the CPU, handed over in arrays
                          (Crowd::drive), or on the GPU, a pass writing device samples, a sample a frame
  --start SECONDS         scene time of the first frame: where on the camera path, in the clips and in
                          the behaviours the run begins (default 0, at most 1e9; as exact and as quick
                          to reach at 1e9 as at 0)
  --lod-hysteresis F      a character keeps its level until its size passes a threshold by this
                          fraction of it, 0..0.5 (default 0.1)
  --lod-fade on|off       level and impostor changes fade instead of popping: up to twice that
                          fraction above a level's threshold its shape morphs into the coarser level's;
                          within that fraction of the impostor threshold mesh and impostor share
                          dithered pixels (in place of hysteresis; not with vs, vs-instanced and static)
                          (default on)
  --clip NAME|INDEX       clip every character plays; "random" picks one per character (default walk)
  --behaviour NAME        in-place (every character loops its clip where it stands, as in the paper),
                          march (a formation in step: out, about turn, back, halt) or mill (each
                          wanders between targets near home, walking, running and stopping)
  --animation cpu|gpu     bone matrices from CPU jobs uploaded each frame (the reference), or from
                          compute passes for the characters culling keeps (default gpu)
  --method NAME           skinning method: two-pass (default, the paper's), vs (the paper's baseline),
                          vs-instanced, two-pass-direct, compute, static (no skinning: the ceiling)
  --frames N              frames to render (default 30)
  --size WxH              image size in pixels (default 1280x720)
  --out FILE.png          image of the last frame (default crowd.png)
  --json FILE             fps, median frame ms, median GPU ms per pass, device and driver
  --device INDEX|NAME     Vulkan device by index or name substring (see --list-devices)
  --seed N                seed of the crowd's layout, phases and speeds (default 1)
  --threads N             CPU threads that planning and CPU animation share, this one included; 0: one
                          per core (default 0)
  --validation            enable the Khronos validation layer (with synchronization checks)
  --list-devices          print the Vulkan devices and exit
  --list-clips            print the model, its levels of detail, pose sphere and clips and exit (no GPU)
  --export-pose FILE.obj  write one character's skinned mesh at --clip and --time as OBJ and exit (no GPU)
  --time SECONDS          time into the clip for --export-pose (default 0; clips loop)
  --help                  print this help and exit
)";

}  // namespace

const char* renderUsage() {
    // The default's name comes from the constant, so that moving the default moves the help.
    static const std::string usage = [] {
        std::string text = kRenderUsage;
        text.replace(text.find("%AA%"), 4, antiAliasingName(kDefaultAntiAliasing));
        return text;
    }();
    return usage.c_str();
}

std::uint32_t parseCount(const std::string& flag, const std::string& text, std::uint32_t min, std::uint32_t max) {
    std::uint64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error == std::errc::invalid_argument || ptr != end)
        throw app::Error(flag + ": '" + text + "' is not a whole number");
    if (error == std::errc::result_out_of_range || value > max)
        throw app::Error(flag + ": " + text + " is too large (at most " + std::to_string(max) + ")");
    if (value < min) throw app::Error(flag + ": " + text + " is too small (at least " + std::to_string(min) + ")");
    return static_cast<std::uint32_t>(value);
}

VkExtent2D parseSize(const std::string& flag, const std::string& text) {
    const std::size_t x = text.find('x');
    if (x == std::string::npos) throw app::Error(flag + ": '" + text + "' is not of the form WIDTHxHEIGHT");
    const std::uint32_t width = parseCount(flag + " width", text.substr(0, x), 1, 16384);
    const std::uint32_t height = parseCount(flag + " height", text.substr(x + 1), 1, 16384);
    return {width, height};
}

float parseNumber(const std::string& flag, const std::string& text, float min, float max) {
    float value = 0.0f;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || ptr != end || !std::isfinite(value))
        throw app::Error(flag + ": '" + text + "' is not a number");
    if (value < min || value > max)
        throw app::Error(flag + ": " + text + " is outside " + formatNumber(min) + ".." + formatNumber(max));
    return value;
}

namespace {

std::string formatPixels(float pixels) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", pixels);
    return text;
}

crowdgpu::Raster parseRaster(const std::string& flag, const std::string& text) {
    for (const crowdgpu::Raster raster : {crowdgpu::Raster::Hardware, crowdgpu::Raster::Compute, crowdgpu::Raster::Auto})
        if (text == crowdgpu::rasterName(raster)) return raster;
    throw app::Error(flag + ": '" + text + "' is not hardware, compute or auto");
}

bool parseOnOff(const std::string& flag, const std::string& text) {
    if (text == "on") return true;
    if (text == "off") return false;
    throw app::Error(flag + ": '" + text + "' is not on or off");
}

// --far-crowd: the far crowd averaged by coverage, or cut at half coverage as before.
bool parseFarCrowd(const std::string& flag, const std::string& text) {
    if (text == "average") return true;
    if (text == "off") return false;
    throw app::Error(flag + ": '" + text + "' is not average or off");
}

void parseThresholds(const std::string& flag, const std::string& text, app::CullOptions& cull) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) throw app::Error(flag + ": '" + text + "' is not of the form A,B (pixels)");
    const float a = parseNumber(flag, text.substr(0, comma), 0.0f, 1e6f);
    const float b = parseNumber(flag, text.substr(comma + 1), 0.0f, 1e6f);
    if (!(a > b && b > 0.0f))
        throw app::Error(flag + ": thresholds " + text + " are out of order (need A > B > 0: LOD 0 above A pixels, "
                         "LOD 1 above B)");
    cull.lodThresholds[0] = a;
    cull.lodThresholds[1] = b;
}

// Sets the crowd, culling and camera of a preset; flags parsed afterwards override them.
void applyPreset(const ScenePreset& preset, RenderOptions& options) {
    options.scene.scene = preset.name;
    options.scene.model = preset.models;
    options.scene.count = preset.count;
    options.cull.lod = preset.lod;
    options.cull.mode = preset.cull;
    options.camera = preset.camera;
    options.scene.behaviour = preset.behaviour;
    options.scene.depthRatio = preset.depthRatio;
}

// The host's world's flags (WorldOptions); false for another flag.
bool parseWorldFlag(const std::string& flag, const std::function<std::string()>& next, WorldOptions& world) {
    if (flag == "--terrain") world.hills = parseTerrain(flag, next());
    else if (flag == "--trajectories") world.trajectories = next();
    else if (flag == replay::kFormatFlag) world.read.format = replay::parseTrajectoryFormat(next());
    else if (flag == replay::kFpsFlag) world.read.fps = replay::parseTrajectoryFps(next());
    else if (flag == replay::kUnitsFlag) world.read.units = replay::parseTrajectoryUnits(next());
    else if (flag == replay::kCopiesFlag) world.copies = replay::parseTrajectoryCopies(next());
    else if (flag == replay::kSmoothingFlag) world.smoothing = replay::parseTrajectorySmoothing(next());
    else if (flag == "--drive-delay") world.delay = parseNumber(flag, next(), 0.0f, 10.0f);
    else if (flag == "--churn") world.churn = parseNumber(flag, next(), 0.0f, 100.0f) / 100.0;
    else if (flag == "--agents") {
        const std::string value = next();
        if (value == "host") world.agents = WorldOptions::Agents::Host;
        else if (value == "device") world.agents = WorldOptions::Agents::Device;
        else if (value == "none") world.agents = WorldOptions::Agents::None;
        else throw app::Error("--agents: '" + value + "' is not none, host or device");
    }
    else if (flag == "--export-states") world.exportStates = next();
    else if (flag == "--export-joints") {
        world.exportJoints.clear();
        const std::string list = next();
        for (std::size_t start = 0; start <= list.size();) {
            const std::size_t comma = std::min(list.find(',', start), list.size());
            if (comma == start) throw app::Error("--export-joints: an empty joint name in '" + list + "'");
            world.exportJoints.push_back(list.substr(start, comma - start));
            start = comma + 1;
        }
    }
    else return false;
    return true;
}

// --scene first, wherever it stands, so that every other flag overrides the preset.
std::string sceneName(const std::vector<std::string>& args) {
    std::string name = "default";
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--scene" && i + 1 < args.size()) name = args[i + 1];
        else if (args[i].rfind("--scene=", 0) == 0) name = args[i].substr(8);
    }
    return name;
}

}  // namespace

RenderOptions parseRenderOptions(const std::vector<std::string>& args, const ExtraFlagParser& extra) {
    RenderOptions options;
    applyPreset(findScenePreset(sceneName(args)), options);
    bool impostorThresholdGiven = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string flag = args[i];
        std::string value;
        bool hasInlineValue = false;
        if (const std::size_t eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = flag.substr(eq + 1);
            flag = flag.substr(0, eq);
            hasInlineValue = true;
        }
        bool valueTaken = false;
        // An empty value is an error, never "not given": --json '' must not quietly skip the JSON.
        auto next = [&]() -> std::string {
            valueTaken = true;
            if (!hasInlineValue) {
                if (i + 1 >= args.size()) throw app::Error(flag + " needs a value (see --help)");
                value = args[++i];
            }
            if (value.empty()) throw app::Error(flag + ": empty value");
            return value;
        };
        if (flag == "--help" || flag == "-h") options.help = true;
        else if (flag == "--list-devices") options.listDevices = true;
        else if (flag == "--validation") options.validation = true;
        else if (flag == "--scene") next();  // applied first
        else if (flag == "--model") options.scene.model = next();
        else if (flag == "--lod") options.cull.lod = parseOnOff(flag, next());
        else if (flag == "--lod-thresholds") parseThresholds(flag, next(), options.cull);
        else if (flag == "--shadows") options.shadows = parseOnOff(flag, next());
        else if (flag == "--props") options.scene.props = parseOnOff(flag, next());
        else if (flag == "--shadow-lod") options.cull.shadowLod = parseOnOff(flag, next());
        else if (flag == "--shadow-raster") {
            const std::string raster = next();
            if (!app::parseShadowRaster(raster, options.cull.shadowRaster))
                throw app::Error("--shadow-raster: '" + raster + "' is not hardware or compute");
        }
        else if (flag == "--shadow-cascades") options.cull.shadowCascades = parseCount(flag, next(), 1, 4);
        else if (flag == "--lod-fade") options.cull.lodFade = parseOnOff(flag, next());
        else if (flag == "--impostor-blend") options.cull.impostorBlend = parseOnOff(flag, next());
        else if (flag == "--far-crowd") options.cull.farCrowd = parseFarCrowd(flag, next());
        else if (flag == "--events") options.cull.events = parseOnOff(flag, next());
        else if (flag == "--aa") options.antiAliasing = parseAntiAliasing(flag, next());
        else if (flag == "--raster") options.cull.raster = parseRaster(flag, next());
        else if (flag == "--mesh-raster-limit") {
            const std::string value = next();
            options.cull.meshRasterLimit = value == "auto" ? crowdgpu::RendererSettings{}.meshRasterLimit
                                                           : parseNumber(flag, value, 0.0f, 1e6f);
        }
        else if (flag == "--impostors") options.cull.impostors = parseOnOff(flag, next());
        else if (flag == "--impostor-threshold") {
            options.cull.impostorThreshold = parseNumber(flag, next(), 0.0f, 1e6f);
            impostorThresholdGiven = true;
            if (!(options.cull.impostorThreshold > 0.0f)) throw app::Error(flag + ": the threshold must be above 0 pixels");
        }
        else if (flag == "--mesh-capacity") options.meshCapacity = parseCount(flag, next(), 1, kMaxCharacters);
        else if (flag == "--start") options.startSeconds = parseStartSeconds(flag, next());
        else if (flag == "--lod-hysteresis") options.cull.hysteresis = parseNumber(flag, next(), 0.0f, 0.5f);
        else if (flag == "--cull") {
            const std::string mode = next();
            if (!app::parseCulling(mode, options.cull.mode))
                throw app::Error("--cull: '" + mode + "' is not gpu, cpu or off");
        }
        else if (flag == "--asset-root") options.scene.assetRoot = next();
        else if (flag == "--behaviour") {
            const std::string name = next();
            if (!app::parseBehaviour(name, options.scene.behaviour))
                throw app::Error("--behaviour: '" + name + "' is not in-place, march or mill");
        } else if (flag == "--animation") {
            const std::string name = next();
            if (!app::parseAnimation(name, options.animation))
                throw app::Error("--animation: '" + name + "' is not cpu or gpu");
        }
        else if (parseWorldFlag(flag, next, options.scene.world)) {}
        else if (flag == "--count") options.scene.count = parseCount(flag, next(), 1, kMaxCharacters);
        else if (flag == "--clip") options.scene.clip = next();
        else if (flag == "--seed") options.scene.seed = parseCount(flag, next(), 0, UINT32_MAX);
        else if (flag == "--threads") options.threads = parseCount(flag, next(), 0, 1024);
        else if (flag == "--frames") options.frames = parseCount(flag, next(), 1, 1000000);
        else if (flag == "--size") options.size = parseSize(flag, next());
        else if (flag == "--out") options.out = next();
        else if (flag == "--json") options.json = next();
        else if (flag == "--device") options.device = next();
        else if (flag == "--method") {
            const std::string name = next();
            if (!app::parseMethod(name, options.method))
                throw app::Error("--method: unknown method '" + name + "' (" + methodList() + ")");
        } else if (!extra || !extra(flag, next)) {
            throw app::Error("unknown option '" + args[i] + "' (see --help)");
        }
        // --validation=no must not turn validation on.
        if (hasInlineValue && !valueTaken) throw app::Error(flag + " takes no value (got '" + flag + "=" + value + "')");
    }
    const WorldOptions& world = options.scene.world;
    if (!world.exportJoints.empty() && world.exportStates.empty())
        throw app::Error("--export-joints needs --export-states (the joints are columns of its CSV)");
    if (!world.trajectories.empty() && world.agents != WorldOptions::Agents::None)
        throw app::Error("--agents: the crowd is the recording's people (--trajectories); give one or the other");
    if (world.churn > 0.0 && (!world.trajectories.empty() || world.agents != WorldOptions::Agents::None))
        throw app::Error("--churn: a replay's and the agents' populations are their own; give --churn alone");
    // Checked once every flag is known: --lod-thresholds may come after it. Only when impostors are on or
    // their threshold was given: otherwise the default threshold would refuse valid --lod-thresholds 20,10.
    if ((options.cull.impostors || impostorThresholdGiven) && !(options.cull.impostorThreshold < options.cull.lodThresholds[1]))
        throw app::Error("--impostor-threshold: " + formatPixels(options.cull.impostorThreshold) +
                         " px is not below the LOD 2 threshold of " + formatPixels(options.cull.lodThresholds[1]) +
                         " px (--lod-thresholds A,B needs B > impostor threshold > 0)");
    return options;
}

}  // namespace app
