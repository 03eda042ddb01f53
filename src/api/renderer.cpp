// crowdgpu::Renderer over frame::CrowdRecorder on a borrowed device.
#include "crowdgpu/renderer.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "api/api_data.h"
#include "api/crowd_arguments.h"
#include "api/device_requirements.h"
#include "api/renderer_arguments.h"
#include "api/renderer_data.h"
#include "frame/memory_plan.h"
#include "gpu/buffer.h"
#include "render/raster_mode.h"
#include "render/scene_pass.h"
#include "skin/storage_ranges.h"

// The public event layout is the shaders' (gpu_types.h), byte for byte.
static_assert(sizeof(crowdgpu::GpuEventHeader) == sizeof(gpu::EventHeader) &&
              offsetof(crowdgpu::GpuEventHeader, capacity) == offsetof(gpu::EventHeader, capacity));
static_assert(sizeof(crowdgpu::GpuEvent) == sizeof(gpu::EventRecord) &&
              offsetof(crowdgpu::GpuEvent, position) == offsetof(gpu::EventRecord, place));
static_assert(sizeof(crowdgpu::DeviceSample) == sizeof(gpu::DeviceSample) &&
              offsetof(crowdgpu::DeviceSample, heading) == offsetof(gpu::DeviceSample, heading));
static_assert(crowdgpu::kHorizonColor[0] == render::kSkyColor.x && crowdgpu::kHorizonColor[1] == render::kSkyColor.y &&
                  crowdgpu::kHorizonColor[2] == render::kSkyColor.z,
              "the public horizon colour is the fog's");

namespace crowdgpu {
namespace detail {

skin::Method internalMethod(Method method) {
    switch (method) {
        case Method::TwoPass: return skin::Method::TwoPass;
        case Method::TwoPassDirect: return skin::Method::TwoPassDirect;
        case Method::VertexShader: return skin::Method::VertexShader;
        case Method::VertexShaderInstanced: return skin::Method::VertexShaderInstanced;
        case Method::Compute: return skin::Method::Compute;
        case Method::Static: return skin::Method::Static;
    }
    throw Error(ErrorCode::InvalidArgument, "unknown skinning method " + std::to_string(static_cast<int>(method)));
}

render::ShadowRasterPath internalShadowRaster(ShadowRaster raster) {
    return raster == ShadowRaster::Compute ? render::ShadowRasterPath::Compute : render::ShadowRasterPath::Hardware;
}

render::RasterMode internalRaster(Raster raster) {
    switch (raster) {
        case Raster::Hardware: return render::RasterMode::Hardware;
        case Raster::Compute: return render::RasterMode::Compute;
        case Raster::Auto: return render::RasterMode::Auto;
    }
    throw Error(ErrorCode::InvalidArgument, "unknown raster mode " + std::to_string(static_cast<int>(raster)));
}

render::CullSettings cullSettings(const RendererSettings& s) {
    render::CullSettings cull;
    cull.mode = s.culling == Culling::Cpu ? render::CullMode::Cpu
                : s.culling == Culling::Off ? render::CullMode::Off
                                            : render::CullMode::Gpu;
    cull.lod = s.lod;
    cull.lodThresholds[0] = s.lodThresholds[0];
    cull.lodThresholds[1] = s.lodThresholds[1];
    cull.hysteresis = s.lodHysteresis;
    cull.lodFade = s.lodFade;
    cull.impostors = s.impostors;
    cull.impostorThreshold = s.impostorThreshold;
    // A shadow shows no more than a view of the same size would: the view's thresholds, read in texels.
    cull.shadowLod = s.shadowLod;
    cull.shadowLodThresholds[0] = s.lodThresholds[0];
    cull.shadowLodThresholds[1] = s.lodThresholds[1];
    return cull;
}

static_assert(RendererSettings{}.meshRasterLimit == render::kMeshRasterAutomatic,
              "the public default is the recorder's");
static_assert(RendererSettings{}.shadowCascades == render::kDefaultShadowCascades, "the public default is the recorder's");

void checkShadowCascades(std::uint32_t count, std::uint32_t mapSize) {
    if (count < 1 || count > render::kMostShadowCascades)
        throw Error(ErrorCode::InvalidArgument, "shadow cascades must be 1 to 4 (asked for " + std::to_string(count) + ")");
    if (count > 1 && mapSize < render::kLeastCascadedMapSize)
        throw Error(ErrorCode::InvalidArgument, "2 to 4 shadow cascades need a shadow map of at least 64 texels (it has " +
                                                    std::to_string(mapSize) + ")");
}

frame::RecorderOptions rendererOptions(const RendererSettings& s) {
    checkSettingEnums(s);
    if (!std::isfinite(s.lodThresholds[0]) || !std::isfinite(s.impostorThreshold) || !(s.impostorThreshold > 0.0f))
        throw Error(ErrorCode::InvalidArgument, "LOD and impostor thresholds must be finite numbers of pixels above 0");
    if (!(s.lodThresholds[0] > s.lodThresholds[1] && s.lodThresholds[1] > 0.0f))
        throw Error(ErrorCode::InvalidArgument, "LOD thresholds must fall: lodThresholds[0] > lodThresholds[1] > 0");
    if (s.impostors && !(s.impostorThreshold > 0.0f && s.impostorThreshold < s.lodThresholds[1]))
        throw Error(ErrorCode::InvalidArgument, "the impostor threshold must lie between 0 and lodThresholds[1]");
    if (!(s.lodHysteresis >= 0.0f && s.lodHysteresis < 1.0f))
        throw Error(ErrorCode::InvalidArgument, "LOD hysteresis must lie in [0, 1)");
    if (s.shadowMapSize == 0 || s.shadowMapSize > 16384)
        throw Error(ErrorCode::InvalidArgument, "shadow map size must be 1 to 16384 texels");
    checkShadowCascades(s.shadowCascades, s.shadowMapSize);
    if (!(s.meshRasterLimit == render::kMeshRasterAutomatic || (s.meshRasterLimit >= 0.0f && s.meshRasterLimit <= 1e6f)))
        throw Error(ErrorCode::InvalidArgument, "the mesh raster limit must lie in [0, 1e6] pixels, or be -1 (automatic)");
    if (s.terrainSamples > (1u << 25))
        throw Error(ErrorCode::InvalidArgument, "terrainSamples: " + std::to_string(s.terrainSamples) + " is over 2^25");
    if (s.events && !(s.eventCapacity >= 1 && s.eventCapacity <= 4000000))
        throw Error(ErrorCode::InvalidArgument, "the event capacity must be 1 to 4,000,000 records");
    frame::RecorderOptions o;
    o.target = {s.target.color, s.target.depth, s.target.samples};
    o.method = internalMethod(s.method);
    o.animation = s.animation == Animation::Cpu ? render::AnimationPath::Cpu : render::AnimationPath::Gpu;
    o.cull = cullSettings(s);
    o.shadows = s.shadows;
    o.impostorBlend = s.impostorBlend;
    o.farCrowd = s.farCrowd;
    o.ground = s.ground;
    o.sky = s.sky;
    o.shadowMapSize = s.shadowMapSize;
    o.shadowRaster = internalShadowRaster(s.shadowRaster);
    o.shadowCascades = s.shadowCascades;
    o.framesInFlight = s.framesInFlight;
    o.meshCapacity = s.impostors ? s.meshCapacity : 0u;
    o.raster = internalRaster(s.raster);
    o.meshRasterLimitPixels = s.meshRasterLimit;
    o.events = s.events;
    o.eventCapacity = s.eventCapacity;
    o.terrainSamples = s.terrainSamples;
    return o;
}

}  // namespace detail

namespace {

render::FrameView internalView(const FrameView& v) {
    render::FrameView view;
    view.view = glm::make_mat4(v.view);
    view.projection = glm::make_mat4(v.projection);
    view.viewport = v.viewport;
    view.time = v.time;
    return view;
}

}  // namespace

FrameView lookAt(const float eye[3], const float target[3], float verticalFov, float nearPlane, float farPlane,
                 VkExtent2D extent, double time) {
    render::Camera camera;
    camera.eye = glm::make_vec3(eye);
    camera.target = glm::make_vec3(target);
    camera.verticalFov = verticalFov;
    camera.nearPlane = nearPlane;
    camera.farPlane = farPlane;
    const render::FrameView v = render::frameViewOf(camera, extent, time);
    FrameView result;
    std::memcpy(result.view, glm::value_ptr(v.view), sizeof result.view);
    std::memcpy(result.projection, glm::value_ptr(v.projection), sizeof result.projection);
    result.viewport = v.viewport;
    result.time = time;
    return result;
}

std::uint64_t memoryNeeded(VkPhysicalDevice physicalDevice, const Crowd& crowd, const RendererSettings& settings) {
    detail::checkPhysicalDeviceGiven("memoryNeeded", physicalDevice);
    return detail::translated([&] {
        const gpu::VulkanContext limits(gpu::BorrowedHandles{VK_NULL_HANDLE, physicalDevice, VK_NULL_HANDLE, 0, true});
        return frame::planMemory(limits, crowd.data().crowd(), detail::rendererOptions(settings)).total();
    });
}

const char* methodName(Method method) { return skin::methodName(detail::internalMethod(method)); }
const char* animationName(Animation animation) {
    return render::animationPathName(animation == Animation::Cpu ? render::AnimationPath::Cpu : render::AnimationPath::Gpu);
}
const char* rasterName(Raster raster) { return render::rasterModeName(detail::internalRaster(raster)); }
const char* cullingName(Culling culling) { return render::cullModeName(detail::cullSettings({.culling = culling}).mode); }
const char* shadowRasterName(ShadowRaster raster) { return raster == ShadowRaster::Compute ? "compute" : "hardware"; }

DeviceLimitCheck checkDeviceLimits(VkPhysicalDevice physicalDevice, const Crowd& crowd, const RendererSettings& settings) {
    detail::checkPhysicalDeviceGiven("checkDeviceLimits", physicalDevice);
    return detail::translated([&] {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(physicalDevice, &properties);
        const frame::RecorderOptions options = detail::rendererOptions(settings);
        const crowd::Crowd& internal = crowd.data().crowd();
        const std::uint32_t capacity = frame::meshCapacityInEffect(options, internal);
        DeviceLimitCheck check;
        check.mostCharacters =
            skin::maxCharactersInStorageRange(properties.limits, internal, options.method, capacity, options.animation);
        if (const auto problem =
                skin::storageRangeProblem(properties.limits, internal, options.method, capacity, options.animation)) {
            check.problem = problem->message;
            check.meshCapacityBound = problem->meshCapacityBound;
        }
        return check;
    });
}

std::string viewportProblem(VkPhysicalDevice physicalDevice, const RendererSettings& settings, VkExtent2D extent) {
    detail::checkPhysicalDeviceGiven("viewportProblem", physicalDevice);
    return detail::translated([&] {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(physicalDevice, &properties);
        return frame::viewportProblem(properties.limits, properties.deviceName,
                                      detail::rendererOptions(settings).raster, extent);
    });
}

namespace detail {

Renderer makeRenderer(const Device& device, const crowd::Crowd& crowd, const frame::RecorderOptions& options,
                      const RendererSettings& settings) {
    auto data = std::make_unique<RendererData>();
    translated([&] {
        data->context = std::make_shared<gpu::VulkanContext>(checkBorrowedDevice(device));
        checkTargetFormat(device.physicalDevice, settings.target);
        if (options.method == skin::Method::TwoPassDirect && !data->context->fragmentStores)
            throw Error(ErrorCode::Unsupported, "method two-pass-direct needs the feature fragmentStoresAndAtomics");
        const std::uint64_t needed = frame::planMemory(*data->context, crowd, options).total();
        const std::uint64_t available = data->context->deviceLocalBytes();
        if (needed > available)
            throw Error(ErrorCode::OutOfDeviceMemory,
                        "a crowd of " + std::to_string(crowd.size()) + " characters needs " + gpu::formatBytes(needed) +
                            " of device memory with these settings; " + data->context->description.name + " has " +
                            gpu::formatBytes(available));
        skin::checkStorageRanges(data->context->properties.limits, crowd, options.method,
                                 frame::meshCapacityInEffect(options, crowd), options.animation);
        data->settings = settings;
        frame::RecorderOptions withOwner = options;
        withOwner.contextOwner = data->context;  // a shared atlas may outlive this renderer
        data->frame = std::make_unique<frame::CrowdRecorder>(*data->context, crowd, withOwner);
        if (settings.edgeFilter)
            data->edgeFilter = std::make_unique<render::EdgeFilter>(
                *data->context, render::isSrgbFormat(settings.target.color), settings.framesInFlight);
    });
    return Renderer(std::move(data));
}

}  // namespace detail

Renderer::Renderer(std::unique_ptr<detail::RendererData> data) : data_(std::move(data)) {}

namespace {

frame::RecorderOptions optionsWithSharedAtlas(const RendererSettings& settings) {
    frame::RecorderOptions options = detail::rendererOptions(settings);
    if (const Renderer* other = settings.impostorsFrom) {
        options.atlas = other->data().frame->impostorAtlas();
        if (!options.atlas)
            throw Error(ErrorCode::WrongOrder, "impostorsFrom: that renderer has no baked impostor atlas yet");
    }
    return options;
}

}  // namespace

Renderer::Renderer(const Device& device, const Crowd& crowd, const RendererSettings& settings)
    : Renderer(detail::makeRenderer(device, crowd.data().crowd(), optionsWithSharedAtlas(settings), settings)) {
    data_->models = crowd.models();  // the layout's models outlive the crowd as long as the renderer needs them
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

bool Renderer::setupPending() const { return data_->frame->setupPending(); }

void Renderer::recordSetup(VkCommandBuffer cmd) {
    detail::translated([&] { data_->frame->recordSetup(cmd); });
}

void Renderer::setupCompleted() { data_->frame->setupCompleted(); }

void Renderer::recordCompute(VkCommandBuffer cmd, std::uint32_t slot, const FrameView& view, const Crowd& crowd) {
    detail::checkTime("recordCompute", "view.time", view.time);
    detail::translated([&] { data_->frame->recordCompute(cmd, slot, internalView(view), crowd.data().crowd()); });
}

void Renderer::recordCompute(VkCommandBuffer cmd, std::uint32_t slot, const FrameView& view, const Crowd& crowd,
                             const DeviceSamples& samples) {
    detail::checkTime("recordCompute", "view.time", view.time);
    const render::DeviceSampleInput input{samples.buffer, samples.offset, samples.size};
    detail::translated([&] { data_->frame->recordCompute(cmd, slot, internalView(view), crowd.data().crowd(), &input); });
}

void Renderer::recordShadows(VkCommandBuffer cmd, std::uint32_t slot) {
    detail::translated([&] { data_->frame->recordShadows(cmd, slot); });
}

void Renderer::recordGround(VkCommandBuffer cmd, std::uint32_t slot) const {
    detail::translated([&] { data_->frame->recordGround(cmd, slot); });
}

void Renderer::recordCharacters(VkCommandBuffer cmd, std::uint32_t slot) {
    detail::translated([&] { data_->frame->recordCharacters(cmd, slot); });
}

void Renderer::recordEdgeFilter(VkCommandBuffer cmd, std::uint32_t slot, VkImageView source, VkImageView destination,
                                VkExtent2D extent) {
    if (!data_->edgeFilter)
        throw Error(ErrorCode::WrongOrder, "recordEdgeFilter: the renderer was made without RendererSettings::edgeFilter");
    if (slot >= data_->settings.framesInFlight)
        throw Error(ErrorCode::InvalidArgument, "recordEdgeFilter: frame slot " + std::to_string(slot) + " out of range");
    if (!source || !destination || source == destination)
        throw Error(ErrorCode::InvalidArgument, "recordEdgeFilter: needs a source view and a different destination view");
    if (extent.width == 0 || extent.height == 0)
        throw Error(ErrorCode::InvalidArgument, "recordEdgeFilter: the extent is empty");
    detail::translated([&] { data_->edgeFilter->record(cmd, slot, source, destination, extent); });
    gpu::passDone(data_->frame->passObserver(), cmd, "edge filter");
}

FrameOutput Renderer::output() const {
    const frame::FrameOutput o = data_->frame->output();
    FrameOutput out;
    out.skinned = o.input == render::DrawInput::SkinnedVertices && o.vertices.buffer;
    if (out.skinned) {
        out.vertices = o.vertices.buffer->buffer;
        out.normalsOffset = o.vertices.normalsOffset;
    }
    out.indices = o.indices;
    out.draws = o.draws;
    out.drawCount = o.drawCount;
    out.drawCountOffset = o.drawCountOffset;
    out.maxDraws = o.maxDraws;
    out.fadingDrawsOffset = o.fadingDrawsOffset;
    out.fadingCountOffset = o.fadingCountOffset;
    out.events = o.events;
    out.eventCapacity = o.eventCapacity;
    return out;
}

FrameCounts Renderer::counts(std::uint32_t slot) const {
    if (slot >= data_->settings.framesInFlight)
        throw Error(ErrorCode::InvalidArgument, "counts: frame slot " + std::to_string(slot) + " out of range");
    const render::LodCounts c = data_->frame->countsOf(slot);
    FrameCounts result{};
    for (int l = 0; l < 3; ++l) result.characters[l] = c.characters[l], result.triangles[l] = c.triangles[l];
    result.impostors = c.impostors;
    result.demoted = c.demoted;
    result.skinnedVertices = c.skinnedVertices;
    for (int l = 0; l < 3; ++l)
        result.shadowCharacters[l] = c.shadowCharacters[l], result.shadowTriangles[l] = c.shadowTriangles[l];
    result.shadowImpostors = c.shadowImpostors;
    const render::IngestTally tally = data_->frame->ingestTally(slot);
    result.deviceSamples = {tally.applied, tally.late, tally.refused};
    return result;
}

std::uint64_t Renderer::framesLost() const { return data_->frame->framesLost(); }

void Renderer::setPassObserver(PassObserver observer) { data_->frame->setPassObserver(std::move(observer)); }

void Renderer::setMethod(Method method) {
    detail::checkMethod("setMethod", method);
    detail::translated([&] {
        data_->frame->setMethod(detail::internalMethod(method));
        data_->settings.method = method;
    });
}

void Renderer::setShadows(bool on) {
    data_->frame->setShadows(on);
    data_->settings.shadows = on;
}

void Renderer::setShadowLod(bool on) {
    RendererSettings s = data_->settings;
    s.shadowLod = on;
    detail::translated([&] { data_->frame->setCull(detail::cullSettings(s)); });
    data_->settings = s;
}

void Renderer::setShadowRaster(ShadowRaster raster) {
    detail::checkShadowRaster("setShadowRaster", raster);
    detail::translated([&] { data_->frame->setShadowRaster(detail::internalShadowRaster(raster)); });
    data_->settings.shadowRaster = raster;
}

void Renderer::setShadowCascades(std::uint32_t count) {
    detail::translated([&] {
        detail::checkShadowCascades(count, data_->settings.shadowMapSize);
        data_->frame->setShadowCascades(count);
    });
    data_->settings.shadowCascades = count;
}

void Renderer::setLodFade(bool on) {
    RendererSettings s = data_->settings;
    s.lodFade = on;
    detail::translated([&] { data_->frame->setCull(detail::cullSettings(s)); });
    data_->settings = s;
}

void Renderer::setImpostorBlend(bool on) {
    data_->frame->setImpostorBlend(on);
    data_->settings.impostorBlend = on;
}

void Renderer::setFarCrowd(bool on) {
    data_->frame->setFarCrowd(on);
    data_->settings.farCrowd = on;
}

void Renderer::setGround(bool on) {
    data_->frame->setGround(on);
    data_->settings.ground = on;
}

void Renderer::setCulling(Culling culling, bool lod) {
    detail::checkCulling("setCulling", culling);
    RendererSettings s = data_->settings;
    s.culling = culling;
    s.lod = lod;
    detail::translated([&] { data_->frame->setCull(detail::cullSettings(s)); });
    data_->settings = s;
}

void Renderer::setImpostors(bool on) {
    RendererSettings s = data_->settings;
    s.impostors = on;
    detail::translated([&] { data_->frame->setCull(detail::cullSettings(s)); });
    data_->settings = s;
}

void Renderer::setAnimation(Animation animation) {
    detail::checkAnimation("setAnimation", animation);
    // The CPU path needs a bone block per character: the bones may be reallocated, or refused.
    detail::translated([&] {
        data_->frame->setAnimation(animation == Animation::Cpu ? render::AnimationPath::Cpu
                                                               : render::AnimationPath::Gpu);
        data_->settings.animation = animation;
    });
}

void Renderer::setLevels(const float lodThresholds[2], float lodHysteresis, float impostorThreshold) {
    RendererSettings s = data_->settings;
    s.lodThresholds[0] = lodThresholds[0];
    s.lodThresholds[1] = lodThresholds[1];
    s.lodHysteresis = lodHysteresis;
    s.impostorThreshold = impostorThreshold;
    detail::rendererOptions(s);  // checks the values
    detail::translated([&] { data_->frame->setCull(detail::cullSettings(s)); });
    data_->settings = s;
}

const RendererSettings& Renderer::settings() const { return data_->settings; }

std::map<std::string, double> Renderer::memoryPerCharacter() const { return data_->frame->memoryPerCharacter(); }

bool Renderer::animatesOnCpu() const {
    const skin::SkinningMethod& method = data_->frame->method();
    return method.needsAnimation() && (method.fixedLayout() || data_->frame->animation() == render::AnimationPath::Cpu);
}

double Renderer::impostorBakeMs() const {
    const auto atlas = data_->frame->impostorAtlas();
    return atlas ? atlas->bakeMs() : 0.0;
}

std::vector<MemoryItem> Renderer::memory() const {
    std::vector<MemoryItem> items;
    for (const skin::MemoryItem& item : data_->frame->memory()) items.push_back({item.what, item.bytes});
    return items;
}

}  // namespace crowdgpu
