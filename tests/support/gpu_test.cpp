#include "support/gpu_test.h"

#include <algorithm>
#include <iterator>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "api/api_data.h"
#include "api/renderer_data.h"
#include "app/crowd_app.h"
#include "gpu/buffer.h"
#include "gpu/one_shot_commands.h"
#include "render/camera.h"
#include "render/geometry_pool.h"
#include "render/frame_view.h"

namespace test {

namespace {

// Which device each live test's context views: helpers given only the context reach the device.
std::map<const gpu::VulkanContext*, const app::HostDevice*>& hosts() {
    static std::map<const gpu::VulkanContext*, const app::HostDevice*> map;
    return map;
}

}  // namespace

const app::HostDevice& hostOf(const gpu::VulkanContext& context) { return *hosts().at(&context); }

void GpuTest::SetUp() {
    // Tests pick the device like users do; CI has only lavapipe.
    const char* selector = std::getenv("CROWD_TEST_DEVICE");
    this->device = std::make_unique<app::HostDevice>(app::HostDeviceOptions{true, selector ? selector : "", {}, false});
    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(this->device->physicalDevice, &features);
    context = std::make_unique<gpu::VulkanContext>(gpu::BorrowedHandles{
        this->device->instance, this->device->physicalDevice, this->device->device, this->device->queueFamily,
        features.fragmentStoresAndAtomics == VK_TRUE, this->device->queue, true, this->device->int64Atomics()});
    hosts()[context.get()] = this->device.get();
}


void GpuTest::TearDown() {
    ASSERT_TRUE(device);
    hosts().erase(context.get());
    context.reset();
    if (device->device) vkDeviceWaitIdle(device->device);
    const std::uint64_t before = device->validationMessages();
    device.reset();  // object destruction is validated too (counted before the messenger goes)
    EXPECT_EQ(before, 0u) << "validation reported messages (printed above)";
}

crowdgpu::Crowd borrowCrowd(crowd::Crowd& crowd) {
    auto data = std::make_unique<crowdgpu::detail::CrowdData>();
    data->borrowed = &crowd;
    return crowdgpu::Crowd(std::move(data));
}

namespace {

crowdgpu::Renderer makeLibraryRenderer(const app::HostDevice& device, crowd::Crowd& crowd, const RendererOptions& options) {
    // The public settings the renderer reports: the internal options' values.
    crowdgpu::RendererSettings settings;
    settings.target = {options.target.color, options.target.depth, options.target.samples};
    settings.method = publicMethod(options.method);
    settings.animation = options.animation == render::AnimationPath::Cpu ? crowdgpu::Animation::Cpu : crowdgpu::Animation::Gpu;
    settings.culling = options.cull.mode == render::CullMode::Cpu   ? crowdgpu::Culling::Cpu
                       : options.cull.mode == render::CullMode::Off ? crowdgpu::Culling::Off
                                                                    : crowdgpu::Culling::Gpu;
    settings.lod = options.cull.lod;
    settings.lodThresholds[0] = options.cull.lodThresholds[0];
    settings.lodThresholds[1] = options.cull.lodThresholds[1];
    settings.lodHysteresis = options.cull.hysteresis;
    settings.impostors = options.cull.impostors;
    settings.impostorThreshold = options.cull.impostorThreshold;
    settings.meshCapacity = options.meshCapacity;
    settings.framesInFlight = options.framesInFlight;
    settings.shadows = options.shadows;
    settings.shadowLod = options.cull.shadowLod;
    settings.lodFade = options.cull.lodFade;
    settings.impostorBlend = options.impostorBlend;
    settings.farCrowd = options.farCrowd;
    settings.sky = options.sky;
    settings.shadowMapSize = options.shadowMapSize;
    settings.shadowCascades = options.shadowCascades;
    settings.raster = options.raster == render::RasterMode::Compute ? crowdgpu::Raster::Compute
                      : options.raster == render::RasterMode::Auto  ? crowdgpu::Raster::Auto
                                                                    : crowdgpu::Raster::Hardware;
    // The programs' frame (app::rendererSettings): the ground behind the characters.
    frame::RecorderOptions recorder = options;
    recorder.ground = settings.ground = true;
    return crowdgpu::detail::makeRenderer(device.libraryDevice(), crowd, recorder, settings);
}

}  // namespace

TestRenderer::TestRenderer(const app::HostDevice& device, crowd::Crowd& crowd, const RendererOptions& options)
    : BorrowedCrowd(crowd),
      app::CrowdRenderer(device, publicCrowd, makeLibraryRenderer(device, crowd, options), options.size,
                         options.passClock) {}

frame::CrowdRecorder& TestRenderer::recorder() const { return *library().data().frame; }

TestRenderer::TestRenderer(const gpu::VulkanContext& context, crowd::Crowd& crowd, const RendererOptions& options)
    : TestRenderer(hostOf(context), crowd, options) {}

void TestRenderer::setCull(const render::CullSettings& cull) {
    const auto culling = cull.mode == render::CullMode::Cpu ? crowdgpu::Culling::Cpu
                         : cull.mode == render::CullMode::Off ? crowdgpu::Culling::Off
                                                              : crowdgpu::Culling::Gpu;
    setCulling(culling, cull.lod, cull.impostors);
    setLevels(cull.lodThresholds, cull.hysteresis, cull.impostorThreshold);
    library().setShadowLod(cull.shadowLod);
    library().setLodFade(cull.lodFade);
}

gpu::CullUniforms TestRenderer::cullUniforms() const {
    return recorder().cullUniforms(render::frameViewOf(internalCamera(camera), extent(), 0.0f));
}

crowd::Crowd mixedCrowd(const model::SkinnedModel& soldier, const model::SkinnedModel& horse, std::uint32_t count) {
    crowd::LayoutOptions layout;
    layout.count = count;
    layout.weights = {3.0f, 1.0f};
    const model::SkinnedModel* models[2] = {&soldier, &horse};
    return crowd::Crowd({&soldier, &horse}, crowd::gridLayout(models, layout));
}

std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const app::SceneOptions& scene) {
    crowd::LayoutOptions layout;
    layout.count = scene.count;
    layout.seed = scene.seed;
    layout.randomClips = scene.clip == "random";
    const int clip = scene.clip.empty() || layout.randomClips ? -1 : model.findClip(scene.clip);
    layout.clips = {clip};
    const model::SkinnedModel* models[1] = {&model};
    return crowd::gridLayout(models, layout);
}

app::CrowdShape shapeOf(const crowd::Crowd& crowd) { return {crowd.center(), crowd.radius(), crowd.tallestHeight()}; }

app::Camera appCamera(const render::Camera& camera) {
    return {camera.eye, camera.target, camera.verticalFov, camera.nearPlane, camera.farPlane};
}

render::Camera internalCamera(const app::Camera& camera) {
    render::Camera internal;
    internal.eye = camera.eye;
    internal.target = camera.target;
    internal.verticalFov = camera.verticalFov;
    internal.nearPlane = camera.nearPlane;
    internal.farPlane = camera.farPlane;
    return internal;
}

render::LodCounts internalCounts(const crowdgpu::FrameCounts& counts) {
    render::LodCounts result;
    for (int l = 0; l < 3; ++l) result.characters[l] = counts.characters[l], result.triangles[l] = counts.triangles[l];
    result.skinnedVertices = counts.skinnedVertices;
    result.impostors = counts.impostors;
    result.demoted = counts.demoted;
    return result;
}

std::uint32_t clipIndex(const model::SkinnedModel& model, const std::string& clip) {
    crowdgpu::Model wrapped(std::make_shared<const crowdgpu::detail::ModelData>(crowdgpu::detail::ModelData{model, {}}));
    return app::clipIndex(wrapped, clip);
}

crowdgpu::Method publicMethod(skin::Method method) {
    for (crowdgpu::Method m : app::allMethods())
        if (crowdgpu::detail::internalMethod(m) == method) return m;
    return crowdgpu::Method::TwoPass;
}

model::SkinnedModel loadModel(const std::string& name, std::uint32_t seed) {
    return app::loadModel(name, seed).data()->model;
}

const model::SkinnedModel& soldier() {
    static const model::SkinnedModel m = loadModel("soldier", 1);
    return m;
}

const model::SkinnedModel& horse() {
    static const model::SkinnedModel m = loadModel("horse", 1);
    return m;
}

std::vector<skin::CpuSkinnedVertex> cpuFadedCharacter(const model::SkinnedModel& model,
                                                      const std::vector<model::LodMorphTarget>& targets,
                                                      const std::vector<skin::CpuSkinnedVertex>& own, std::uint32_t lod,
                                                      std::uint32_t state) {
    const std::uint32_t steps = state >> FADE_SHIFT;
    if (steps == 0 || lod + 1 >= LOD_COUNT) return own;
    return skin::morphOnCpu(own, targets, render::lodsOf(model)[lod + 1].vertexCount,
                            static_cast<double>(steps) / FADE_STEPS);
}

ReadbackVertices readSkinnedVertices(const gpu::VulkanContext& context, const render::SkinnedVertices& vertices,
                                     std::uint32_t firstVertex, std::uint32_t vertexCount) {
    const VkDeviceSize bytes = static_cast<VkDeviceSize>(vertexCount) * sizeof(glm::vec4);
    gpu::Buffer staging = gpu::createBuffer(context, 2 * bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            gpu::MemoryUse::HostReadback, "test readback");
    const VkDeviceSize first = static_cast<VkDeviceSize>(firstVertex) * sizeof(glm::vec4);
    gpu::runOneShot(context, [&](VkCommandBuffer cmd) {
        const VkBufferCopy regions[2] = {{first, 0, bytes}, {vertices.normalsOffset + first, bytes, bytes}};
        vkCmdCopyBuffer(cmd, vertices.buffer->buffer, staging.buffer, 2, regions);
    });
    ReadbackVertices result{std::vector<glm::vec4>(vertexCount), std::vector<glm::vec4>(vertexCount)};
    std::memcpy(result.positions.data(), staging.mapped, bytes);
    std::memcpy(result.normals.data(), static_cast<const char*>(staging.mapped) + bytes, bytes);
    gpu::destroyBuffer(context, staging);
    return result;
}

std::vector<std::uint32_t> differ(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
    std::vector<std::uint32_t> result;
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(result));
    return result;
}

std::vector<std::byte> readBuffer(const gpu::VulkanContext& context, const gpu::Buffer& buffer) {
    gpu::Buffer staging = gpu::createBuffer(context, buffer.size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            gpu::MemoryUse::HostReadback, "test readback");
    gpu::runOneShot(context, [&](VkCommandBuffer cmd) {
        const VkBufferCopy region{0, 0, buffer.size};
        vkCmdCopyBuffer(cmd, buffer.buffer, staging.buffer, 1, &region);
    });
    std::vector<std::byte> bytes(buffer.size);
    std::memcpy(bytes.data(), staging.mapped, bytes.size());
    gpu::destroyBuffer(context, staging);
    return bytes;
}

crowd::VisibleLists readVisibleLists(const gpu::VulkanContext& context, const TestRenderer& renderer) {
    const render::DrawLists& lists = renderer.drawLists();
    const std::vector<std::byte> frames = readBuffer(context, lists.bucketFrames());
    const std::vector<std::byte> visible = readBuffer(context, lists.visible());
    crowd::VisibleLists result(lists.bucketCount());
    for (std::uint32_t b = 0; b < lists.bucketCount(); ++b) {
        gpu::BucketFrame frame;
        std::memcpy(&frame, frames.data() + b * sizeof frame, sizeof frame);
        const std::byte* first = visible.data() + lists.buckets()[b].list.z * 4;
        result[b].resize(frame.count);
        std::memcpy(result[b].data(), first, frame.count * 4);
        std::sort(result[b].begin(), result[b].end());
    }
    return result;
}

std::vector<std::uint32_t> readImpostorList(const gpu::VulkanContext& context, const TestRenderer& renderer) {
    const render::DrawLists& lists = renderer.drawLists();
    const std::vector<std::byte> frameBytes = readBuffer(context, lists.impostorFrame());
    const std::vector<std::byte> listBytes = readBuffer(context, lists.impostorList());
    gpu::ImpostorFrame frame;
    std::memcpy(&frame, frameBytes.data(), sizeof frame);
    std::vector<std::uint32_t> list(frame.count);
    std::memcpy(list.data(), listBytes.data(), frame.count * 4);
    std::sort(list.begin(), list.end());
    return list;
}

crowd::ShadowLists readShadowLists(const gpu::VulkanContext& context, const TestRenderer& renderer) {
    const render::DrawLists& lists = renderer.drawLists();
    const std::vector<std::byte> frames = readBuffer(context, lists.bucketFrames());
    const std::vector<std::byte> visible = readBuffer(context, lists.visible());
    crowd::ShadowLists result;
    result.casters.resize(lists.bucketCount());
    for (std::uint32_t b = 0; b < lists.bucketCount(); ++b) {
        gpu::BucketFrame frame;
        std::memcpy(&frame, frames.data() + b * sizeof frame, sizeof frame);
        const std::byte* first = visible.data() + (lists.shadowListBase() + lists.buckets()[b].list.z) * 4;
        result.casters[b].resize(frame.shadowCount);
        std::memcpy(result.casters[b].data(), first, frame.shadowCount * 4);
        std::sort(result.casters[b].begin(), result.casters[b].end());
    }
    const std::vector<std::byte> frameBytes = readBuffer(context, lists.impostorFrame());
    const std::vector<std::byte> listBytes = readBuffer(context, lists.impostorList());
    gpu::ImpostorFrame impostors;
    std::memcpy(&impostors, frameBytes.data(), sizeof impostors);
    result.impostors.resize(impostors.shadowCount);
    std::memcpy(result.impostors.data(), listBytes.data() + std::size_t{lists.characterCount()} * 4,
                impostors.shadowCount * 4);
    std::sort(result.impostors.begin(), result.impostors.end());
    const std::vector<std::byte> states = readBuffer(context, lists.shadowStates());
    result.states.resize(lists.characterCount());
    std::memcpy(result.states.data(), states.data(), result.states.size() * 4);
    return result;
}

std::vector<gpu::CharacterRecord> readCharacterRecords(const gpu::VulkanContext& context,
                                                       const TestRenderer& renderer) {
    const std::vector<std::byte> bytes = readBuffer(context, renderer.buffers().characters());
    std::vector<gpu::CharacterRecord> records(renderer.buffers().characterCount());
    std::memcpy(records.data(), bytes.data(), records.size() * sizeof(gpu::CharacterRecord));
    return records;
}

std::map<std::uint32_t, DrawnCharacter> readDrawList(const gpu::VulkanContext& context,
                                                     const TestRenderer& renderer) {
    const render::DrawLists& lists = renderer.drawLists();
    const std::vector<std::byte> totalsBytes = readBuffer(context, lists.totals());
    const std::vector<std::byte> drawBytes = readBuffer(context, lists.draws());
    gpu::DrawTotals totals;
    std::memcpy(&totals, totalsBytes.data(), sizeof totals);
    std::map<std::uint32_t, DrawnCharacter> drawn;
    for (std::uint32_t i = 0; i < totals.drawCount; ++i) {
        gpu::DrawIndexedCommand draw;
        std::memcpy(&draw, drawBytes.data() + i * sizeof draw, sizeof draw);
        const std::uint32_t model = renderer.buffers().records()[draw.firstInstance].ids.x;
        for (const gpu::BucketRecord& bucket : lists.buckets())
            if (bucket.list.x == model && bucket.mesh.x == draw.firstIndex && bucket.mesh.y == draw.indexCount) {
                drawn[draw.firstInstance] = {bucket.list.y, static_cast<std::uint32_t>(draw.vertexOffset), bucket.mesh.z};
                break;
            }
    }
    return drawn;
}

ReadbackVertices readSkinnedCharacter(const gpu::VulkanContext& context, TestRenderer& renderer,
                                      std::uint32_t character) {
    const std::map<std::uint32_t, DrawnCharacter> drawn = readDrawList(context, renderer);
    const DrawnCharacter& d = drawn.at(character);
    return readSkinnedVertices(context, renderer.method().skinnedVertices(), d.firstVertex, d.vertexCount);
}

namespace {

app::Rgba8Image renderCrowd(const app::HostDevice& device, crowd::Crowd crowd, const app::Camera& camera) {
    RendererOptions options;
    options.size = {192, 108};
    options.method = skin::Method::Compute;
    // Each model's own crowd lacks the other's shadows (and frames its light differently): compare
    // the characters themselves.
    options.shadows = false;
    TestRenderer renderer(device, crowd, options);
    renderer.camera = camera;
    renderer.renderFrame(1.25f);
    return renderer.readback();
}

glm::ivec4 pixelAt(const app::Rgba8Image& image, std::size_t p) {
    return glm::ivec4(image.pixels[p], image.pixels[p + 1], image.pixels[p + 2], image.pixels[p + 3]);
}

bool samePixel(glm::ivec4 x, glm::ivec4 y) { return glm::all(glm::lessThanEqual(glm::abs(x - y), glm::ivec4(2))); }

}  // namespace

MixedCrowdMatch compareMixedCrowd(const app::HostDevice& context, const model::SkinnedModel& a,
                                  const model::SkinnedModel& b, float scaleB, const std::string& name) {
    // A row of alternating characters, far enough apart that none overlaps another on screen.
    std::vector<crowd::Character> mixed;
    for (std::uint32_t i = 0; i < 6; ++i) {
        crowd::Character c;
        c.model = i % 2;
        c.clip = 0;
        c.timeOffset = 0.1f * static_cast<float>(i);
        c.position = glm::vec3(3.2f * (static_cast<float>(i) - 2.5f), 0.0f, 0.0f);
        c.heading = 0.5f;
        c.scale = c.model == 1 ? scaleB : 1.0f;
        c.tint = glm::vec3(0.85f + 0.05f * static_cast<float>(i));
        mixed.push_back(c);
    }
    // The props each character carries when it does not choose hash its index, which differs in the
    // one-model crowds: they take the mixed crowd's choice (docs/props.md).
    {
        const crowd::Crowd chosen({&a, &b}, mixed);
        for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i].props = chosen.characters()[i].props;
    }
    auto only = [&](std::uint32_t model) {
        std::vector<crowd::Character> subset;
        for (crowd::Character c : mixed)
            if (c.model == model) c.model = 0, subset.push_back(c);
        return subset;
    };
    app::Camera camera;
    camera.eye = {0.0f, 4.0f, 12.0f};
    camera.target = {0.0f, 0.8f, 0.0f};
    crowd::Character away;  // one character behind the camera: culled, so the picture is the empty scene
    away.position = {0.0f, 0.0f, 100.0f};
    const app::Rgba8Image both = renderCrowd(context, crowd::Crowd({&a, &b}, mixed), camera);
    const app::Rgba8Image first = renderCrowd(context, crowd::Crowd(a, only(0)), camera);
    const app::Rgba8Image second = renderCrowd(context, crowd::Crowd(b, only(1)), camera);
    const app::Rgba8Image empty = renderCrowd(context, crowd::Crowd(a, {away}), camera);
    MixedCrowdMatch match;
    std::size_t matching = 0, firstMatching = 0, secondMatching = 0;
    for (std::size_t p = 0; p < both.pixels.size(); p += 4) {
        const bool inFirst = !samePixel(pixelAt(first, p), pixelAt(empty, p));
        const bool inSecond = !samePixel(pixelAt(second, p), pixelAt(empty, p));
        match.firstModelPixels += inFirst, match.secondModelPixels += inSecond;
        const glm::ivec4 expected = inFirst ? pixelAt(first, p) : inSecond ? pixelAt(second, p) : pixelAt(empty, p);
        const bool same = samePixel(pixelAt(both, p), expected);
        matching += same, firstMatching += same && inFirst, secondMatching += same && inSecond;
    }
    match.matchingFraction = static_cast<double>(matching) / static_cast<double>(both.pixels.size() / 4);
    match.firstModelMatching = static_cast<double>(firstMatching) / static_cast<double>(std::max<std::size_t>(match.firstModelPixels, 1));
    match.secondModelMatching = static_cast<double>(secondMatching) / static_cast<double>(std::max<std::size_t>(match.secondModelPixels, 1));
    if (match.matchingFraction < 0.995) {
        app::writePng(artifactPath(name + "-mixed.png"), both);
        app::writePng(artifactPath(name + "-first.png"), first);
        app::writePng(artifactPath(name + "-second.png"), second);
    }
    return match;
}

double fractionOfMatchingPixels(const app::Rgba8Image& a, const app::Rgba8Image& b, int tolerance) {
    if (a.width != b.width || a.height != b.height || a.pixels.empty()) return 0.0;
    std::size_t matching = 0;
    for (std::size_t p = 0; p < a.pixels.size(); p += 4) {
        bool same = true;
        for (int c = 0; c < 4; ++c) same = same && std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c])) <= tolerance;
        matching += same;
    }
    return static_cast<double>(matching) / static_cast<double>(a.pixels.size() / 4);
}

std::vector<bool> darkenedPixels(const app::Rgba8Image& shadowed, const app::Rgba8Image& unshadowed, int levels) {
    std::vector<bool> mask(shadowed.pixels.size() / 4);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        bool darker = true;
        for (int ch = 0; ch < 3; ++ch)
            darker = darker && int(unshadowed.pixels[4 * i + ch]) - int(shadowed.pixels[4 * i + ch]) > levels;
        mask[i] = darker;
    }
    return mask;
}

bool pixelWithin(const app::Rgba8Image& a, const app::Rgba8Image& b, std::size_t pixel, int tolerance) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(int(a.pixels[pixel * 4 + k]) - int(b.pixels[pixel * 4 + k])) > tolerance) return false;
    return true;
}

CharacterAgreement characterAgreement(const app::Rgba8Image& a, const app::Rgba8Image& b, const app::Rgba8Image& background) {
    CharacterAgreement agreement;
    for (std::size_t i = 0; i < a.pixels.size() / 4; ++i) {
        if (pixelWithin(a, background, i, 0) && pixelWithin(b, background, i, 0)) continue;
        ++agreement.pixels;
        agreement.within2 += pixelWithin(a, b, i, 2) ? 1 : 0;
        agreement.within24 += pixelWithin(a, b, i, 24) ? 1 : 0;
    }
    return agreement;
}

render::Camera cameraSeeingSphereAcross(const model::SkinnedModel& model, float across) {
    render::Camera camera;
    const float focal = 60.0f / std::tan(0.5f * camera.verticalFov);  // pixels per unit at unit distance
    camera.target = glm::vec3(0.0f, glm::vec3(model.poseSphere).y, 0.0f);
    camera.eye = camera.target + glm::vec3(0.0f, 0.3f, 1.0f) * (2.0f * model.poseSphere.w * focal / across);
    return camera;
}

void keepRasterImages(const std::string& name, const app::Rgba8Image& hardware, const app::Rgba8Image& compute) {
    app::writePng(artifactPath(name + "-hardware.png"), hardware);
    app::writePng(artifactPath(name + "-compute.png"), compute);
}

std::string artifactPath(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "crowd-test-artifacts";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

}  // namespace test
