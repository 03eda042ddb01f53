#include "support/gpu_test.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "gpu/buffer.h"
#include "gpu/one_shot_commands.h"
#include "render/camera.h"

namespace test {

void GpuTest::SetUp() {
    // Tests pick the device like users do; CI has only lavapipe.
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    context = std::make_unique<gpu::VulkanContext>(gpu::ContextOptions{true, device ? device : "", {}, false});
}

void GpuTest::TearDown() {
    ASSERT_TRUE(context);
    const std::uint64_t messages = context->validationMessages();
    context.reset();  // object destruction is validated too
    EXPECT_EQ(messages, 0u) << "validation reported messages (printed above)";
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

crowd::VisibleLists readVisibleLists(const gpu::VulkanContext& context, const app::CrowdRenderer& renderer) {
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

std::vector<std::uint32_t> readImpostorList(const gpu::VulkanContext& context, const app::CrowdRenderer& renderer) {
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

std::vector<gpu::CharacterRecord> readCharacterRecords(const gpu::VulkanContext& context,
                                                       const app::CrowdRenderer& renderer) {
    const std::vector<std::byte> bytes = readBuffer(context, renderer.buffers().characters());
    std::vector<gpu::CharacterRecord> records(renderer.buffers().characterCount());
    std::memcpy(records.data(), bytes.data(), records.size() * sizeof(gpu::CharacterRecord));
    return records;
}

std::map<std::uint32_t, DrawnCharacter> readDrawList(const gpu::VulkanContext& context,
                                                     const app::CrowdRenderer& renderer) {
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

ReadbackVertices readSkinnedCharacter(const gpu::VulkanContext& context, app::CrowdRenderer& renderer,
                                      std::uint32_t character) {
    const std::map<std::uint32_t, DrawnCharacter> drawn = readDrawList(context, renderer);
    const DrawnCharacter& d = drawn.at(character);
    return readSkinnedVertices(context, renderer.method().skinnedVertices(), d.firstVertex, d.vertexCount);
}

namespace {

render::Rgba8Image renderCrowd(const gpu::VulkanContext& context, crowd::Crowd crowd, const render::Camera& camera) {
    app::RendererOptions options;
    options.size = {192, 108};
    options.method = skin::Method::Compute;
    // Each model's own crowd lacks the other's shadows (and frames its light differently): compare
    // the characters themselves.
    options.shadows = false;
    app::CrowdRenderer renderer(context, crowd, options);
    renderer.camera = camera;
    renderer.renderFrame(1.25f);
    return renderer.readback();
}

glm::ivec4 pixelAt(const render::Rgba8Image& image, std::size_t p) {
    return glm::ivec4(image.pixels[p], image.pixels[p + 1], image.pixels[p + 2], image.pixels[p + 3]);
}

bool samePixel(glm::ivec4 x, glm::ivec4 y) { return glm::all(glm::lessThanEqual(glm::abs(x - y), glm::ivec4(2))); }

}  // namespace

MixedCrowdMatch compareMixedCrowd(const gpu::VulkanContext& context, const model::SkinnedModel& a,
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
    auto only = [&](std::uint32_t model) {
        std::vector<crowd::Character> subset;
        for (crowd::Character c : mixed)
            if (c.model == model) c.model = 0, subset.push_back(c);
        return subset;
    };
    render::Camera camera;
    camera.eye = {0.0f, 4.0f, 12.0f};
    camera.target = {0.0f, 0.8f, 0.0f};
    crowd::Character away;  // one character behind the camera: culled, so the picture is the empty scene
    away.position = {0.0f, 0.0f, 100.0f};
    const render::Rgba8Image both = renderCrowd(context, crowd::Crowd({&a, &b}, mixed), camera);
    const render::Rgba8Image first = renderCrowd(context, crowd::Crowd(a, only(0)), camera);
    const render::Rgba8Image second = renderCrowd(context, crowd::Crowd(b, only(1)), camera);
    const render::Rgba8Image empty = renderCrowd(context, crowd::Crowd(a, {away}), camera);
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
        render::writePng(artifactPath(name + "-mixed.png"), both);
        render::writePng(artifactPath(name + "-first.png"), first);
        render::writePng(artifactPath(name + "-second.png"), second);
    }
    return match;
}

double fractionOfMatchingPixels(const render::Rgba8Image& a, const render::Rgba8Image& b, int tolerance) {
    if (a.width != b.width || a.height != b.height || a.pixels.empty()) return 0.0;
    std::size_t matching = 0;
    for (std::size_t p = 0; p < a.pixels.size(); p += 4) {
        bool same = true;
        for (int c = 0; c < 4; ++c) same = same && std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c])) <= tolerance;
        matching += same;
    }
    return static_cast<double>(matching) / static_cast<double>(a.pixels.size() / 4);
}

std::string artifactPath(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "crowd-test-artifacts";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

}  // namespace test
