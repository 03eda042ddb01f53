// Buffers bound whole as one storage buffer must fit the device's maxStorageBufferRange (128 MiB on
// lavapipe): a crowd that needs more is refused in one line before anything is allocated, and the
// viewer's panel offers no such crowd. CPU only (the limits are given); the programs' side is in
// the last test, on the tests' device.
#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "app/host_device.h"
#include "app/crowd_app.h"
#include "gpu/vulkan_context.h"
#include "render/geometry_pool.h"
#include "skin/storage_ranges.h"
#include "support/run_program.h"

namespace {

constexpr std::uint32_t kLavapipeRange = 128u << 20;

VkPhysicalDeviceLimits lavapipeLimits() {
    VkPhysicalDeviceLimits limits{};
    limits.maxStorageBufferRange = kLavapipeRange;
    limits.minStorageBufferOffsetAlignment = 16;
    limits.minUniformBufferOffsetAlignment = 16;
    return limits;
}

struct SoldierCrowd {
    app::CrowdModels models = app::loadModels("soldier", 1);
    crowdgpu::Crowd publicCrowd;
    crowd::Crowd& crowd;
    explicit SoldierCrowd(std::uint32_t count)
        : publicCrowd(app::buildCrowd(models, sceneOf(count))), crowd(publicCrowd.data().crowd()) {}
    static app::SceneOptions sceneOf(std::uint32_t count) {
        app::SceneOptions scene;
        scene.count = count;
        return scene;
    }
    // Soldiers whose LOD 0 positions (16 bytes a vertex) fill the range.
    std::uint32_t lod0Fitting() const {
        return kLavapipeRange / (16u * render::lodsOf(models.models.front().data()->model)[0].vertexCount);
    }
    std::uint32_t allLodsFitting() const {
        std::uint32_t vertices = 0;
        for (const auto& lod : render::lodsOf(models.models.front().data()->model)) vertices += lod.vertexCount;
        return kLavapipeRange / (16u * vertices);
    }
};

std::string refusal(const crowd::Crowd& crowd, skin::Method method, std::uint32_t meshCapacity = 0) {
    try {
        skin::checkStorageRanges(lavapipeLimits(), crowd, method, meshCapacity);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(StorageRanges, SkinnedVerticesPastTheRangeAreRefusedForTheMethodsThatStoreIntoThem) {
    const SoldierCrowd fits(SoldierCrowd(1).lod0Fitting());
    const SoldierCrowd over(fits.crowd.size() + 1);
    EXPECT_EQ(fits.crowd.size(), 9510u);  // the soldier: 882 vertices at LOD 0 (body 690, rifle 120, flag 72)
    for (skin::Method m : {skin::Method::Compute, skin::Method::TwoPassDirect}) {
        EXPECT_EQ(refusal(fits.crowd, m), "") << skin::methodName(m);
        const std::string message = refusal(over.crowd, m);
        EXPECT_EQ(message.rfind("a crowd of 9511 characters: ", 0), 0u) << message;  // the library's words, no flag
        EXPECT_NE(message.find("skinned vertex positions"), std::string::npos) << message;
        EXPECT_NE(message.find("at most 9510 of these characters fit"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    // two-pass copies into the buffer and binds no more of it than the range; vs reads no skinned vertices.
    for (skin::Method m : {skin::Method::TwoPass, skin::Method::VertexShader, skin::Method::VertexShaderInstanced})
        EXPECT_EQ(refusal(over.crowd, m), "") << skin::methodName(m);
}

TEST(StorageRanges, StaticNeedsASlotPerLevelAndIsRefusedSooner) {
    const std::uint32_t fitting = SoldierCrowd(1).allLodsFitting();
    EXPECT_EQ(refusal(SoldierCrowd(fitting).crowd, skin::Method::Static), "");
    const std::string message = refusal(SoldierCrowd(fitting + 1).crowd, skin::Method::Static);
    EXPECT_NE(message.find("at most " + std::to_string(fitting) + " of these"), std::string::npos) << message;
}

TEST(StorageRanges, AMeshCapacityBoundsTheSkinnedVertices) {
    const SoldierCrowd crowd(20000);
    // Over the cap the skinned vertices are sized for the cap: one that fits lets the crowd fit.
    EXPECT_EQ(refusal(crowd.crowd, skin::Method::Compute, 9000), "");
    const std::string message = refusal(crowd.crowd, skin::Method::Compute, 12000);
    EXPECT_EQ(message.rfind("a crowd of 20000 characters: compute binds ", 0), 0u) << message;
    EXPECT_NE(message.find("a mesh capacity of at most 9510 fits"), std::string::npos) << message;
    EXPECT_EQ(message.find("--"), std::string::npos) << message;
}

TEST(StorageRanges, TheViewersLimitIsTheMostThatFits) {
    const SoldierCrowd crowd(100);
    const VkPhysicalDeviceLimits limits = lavapipeLimits();
    EXPECT_EQ(skin::maxCharactersInStorageRange(limits, crowd.crowd, skin::Method::Compute, 0), 9510u);
    EXPECT_EQ(skin::maxCharactersInStorageRange(limits, crowd.crowd, skin::Method::Static, 0), crowd.allLodsFitting());
    // two-pass: the bone matrices bound it (1,104 bytes a soldier of 23 joints packed tightly).
    const std::uint64_t twoPass = skin::maxCharactersInStorageRange(limits, crowd.crowd, skin::Method::TwoPass, 0);
    EXPECT_GT(twoPass, 100000u);
    EXPECT_EQ(refusal(SoldierCrowd(static_cast<std::uint32_t>(twoPass)).crowd, skin::Method::TwoPass), "");
    // With a cap that fits, neither the skinned vertices nor the bones (a block per mesh slot) bound it:
    // the character records do, 64 bytes each. The CPU path keeps a bone block per character.
    EXPECT_EQ(skin::maxCharactersInStorageRange(limits, crowd.crowd, skin::Method::Compute, 9000),
              kLavapipeRange / sizeof(gpu::CharacterRecord));
    EXPECT_EQ(skin::maxCharactersInStorageRange(limits, crowd.crowd, skin::Method::Compute, 9000,
                                                render::AnimationPath::Cpu),
              skin::maxCharactersInStorageRange(limits, crowd.crowd, skin::Method::VertexShader, 9000));
}

// Bone blocks per mesh slot (issue 18): over the mesh capacity the bones stop growing, so a crowd whose
// per-character blocks would pass the range fits with the GPU methods; vs and the CPU path, which keep
// a block per character, are refused in one line naming the bones.
TEST(StorageRanges, BonesPerMeshSlotStopGrowingAtTheMeshCapacity) {
    const SoldierCrowd crowd(140000);  // per-character blocks: at most 121,573 soldiers (1,104 bytes each) in 128 MiB
    EXPECT_EQ(refusal(crowd.crowd, skin::Method::Compute, 9000), "");
    EXPECT_EQ(refusal(crowd.crowd, skin::Method::VertexShaderInstanced, 9000), "");
    for (skin::Method m : {skin::Method::VertexShader, skin::Method::Compute}) {
        std::string message;
        try {
            skin::checkStorageRanges(lavapipeLimits(), crowd.crowd, m, 9000,
                                     m == skin::Method::Compute ? render::AnimationPath::Cpu : render::AnimationPath::Gpu);
        } catch (const std::exception& e) {
            message = e.what();
        }
        EXPECT_EQ(message.rfind("a crowd of 140000 characters: " + std::string(skin::methodName(m)) + " binds ", 0), 0u)
            << message;
        EXPECT_NE(message.find("of bone matrices as one storage buffer, over this device's limit of 128.0 MiB"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("at most 121573 of these characters fit"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// 10,000,000 soldiers with impostors and the default mesh capacity on the H100's limits (4 GiB of
// storage-buffer range: 4,000,000 soldiers' aligned bone blocks, 4.6 GB, passed it there, their packed
// ones, 4.0 GB, did not): every GPU method's bindings fit; vs's per-character bones do not.
TEST(StorageRanges, TenMillionSoldiersFitTheH100sRangesWithBonesPerMeshSlot) {
    VkPhysicalDeviceLimits h100{};
    h100.maxStorageBufferRange = 0xFFFFFFFFu;
    h100.minUniformBufferOffsetAlignment = 64;
    h100.minStorageBufferOffsetAlignment = 16;
    const SoldierCrowd mix(1000);  // the most of this mix that fit, whatever the crowd's own size
    for (skin::Method m : {skin::Method::Compute, skin::Method::TwoPass, skin::Method::TwoPassDirect,
                           skin::Method::VertexShaderInstanced})
        EXPECT_GE(skin::maxCharactersInStorageRange(h100, mix.crowd, m, 65536), 10000000u) << skin::methodName(m);
    EXPECT_LT(skin::maxCharactersInStorageRange(h100, mix.crowd, skin::Method::VertexShader, 65536), 10000000u);
    EXPECT_LT(skin::maxCharactersInStorageRange(h100, mix.crowd, skin::Method::Compute, 65536, render::AnimationPath::Cpu),
              10000000u);
}

TEST(StorageRanges, CrowdRenderRefusesInOneLineWhatTheDeviceCannotBindAndTwoPassDrawsItWithValidationSilent) {
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    const std::uint64_t range =
        app::HostDevice({false, device ? device : "", {}, false}).properties.limits.maxStorageBufferRange;
    const SoldierCrowd one(1);
    const std::uint64_t over = range / (16u * render::lodsOf(one.models.models.front().data()->model)[0].vertexCount) + 1;
    if (over > app::kMaxCharacters) GTEST_SKIP() << "this device binds skinned vertices for every crowd size";
    const std::string deviceFlag = device ? std::string(" --device '") + device + "'" : "";
    const std::string png = (std::filesystem::temp_directory_path() /
                             ("crowd-storage-" + std::to_string(::getpid()) + ".png")).string();
    const std::string crowd = "--count " + std::to_string(over) + " --size 64x64 --frames 1 --validation" + deviceFlag +
                              " --out " + png;
    for (const char* method : {"compute", "two-pass-direct", "static"}) {
        const test::ProgramResult r = test::runProgram(CROWD_RENDER_BINARY, crowd + " --method " + method);
        EXPECT_EQ(r.exitCode, 1) << method << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << method << " printed:\n" << r.err;
        EXPECT_EQ(r.err.rfind("crowd-render: --count " + std::to_string(over) + ": " + method + " binds ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("as one storage buffer"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(png)) << method << ": refused only after rendering";
    }
    // two-pass never binds its skinned vertices for the shaders to store into: the same crowd renders.
    const test::ProgramResult r = test::runProgram(CROWD_RENDER_BINARY, crowd + " --method two-pass");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::exists(png));
    std::filesystem::remove(png);
}

// A viewport whose visibility buffer passes the range: `--raster compute` is refused in one line naming the
// size before anything is drawn; the same size is within the device's viewport (16384 on lavapipe).
TEST(StorageRanges, CrowdRenderRefusesRasterComputeForAViewportPastTheRangeInOneLine) {
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    const std::uint64_t range =
        app::HostDevice({false, device ? device : "", {}, false}).properties.limits.maxStorageBufferRange;
    const std::uint32_t width = 16384, height = static_cast<std::uint32_t>(range / (8u * width) + 1);
    if (height > 16384) GTEST_SKIP() << "this device binds a visibility buffer for every viewport";
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const std::string png = (std::filesystem::temp_directory_path() /
                             ("crowd-viewport-" + std::to_string(::getpid()) + ".png")).string();
    const std::string deviceFlag = device ? std::string(" --device '") + device + "'" : "";
    const test::ProgramResult r =
        test::runProgram(CROWD_RENDER_BINARY, "--count 4 --impostors on --raster compute --frames 1 --size " + size +
                                                  deviceFlag + " --out " + png);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("crowd-render: --size " + size + ": --raster compute binds a visibility buffer of ", 0), 0u)
        << r.err;
    EXPECT_NE(r.err.find("maxStorageBufferRange"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
