// Bone blocks belong to mesh slots (render/crowd_buffers.h, BoneBlocks): a crowd larger than the mesh
// capacity gets bones for the capacity, not the crowd, as the memory planner says before any
// allocation; the methods and the path that need every character's bones keep a block each; and a
// character whose slot changes between frames still skins with its own pose (the CPU reference).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <span>

#include <gtest/gtest.h>

#include "crowdgpu/renderer.hpp"
#include "frame/memory_plan.h"
#include "skin/cpu_skinning.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr const char* kBonesItem = "character records and bone matrices";

std::uint64_t itemBytes(const std::vector<skin::MemoryItem>& items, const std::string& what) {
    for (const skin::MemoryItem& item : items)
        if (item.what == what) return item.bytes;
    ADD_FAILURE() << "no memory item " << what;
    return 0;
}

// 2,000 soldiers, impostors on, at most 300 at a mesh level: the cap is in effect.
test::RendererOptions cappedOptions(skin::Method method, render::AnimationPath animation) {
    test::RendererOptions options;
    options.size = {64, 64};
    options.method = method;
    options.animation = animation;
    options.cull.impostors = true;
    options.meshCapacity = 300;
    return options;
}

TEST_F(GpuTest, ACrowdOverTheMeshCapacityAllocatesBonesForTheCapacityNotTheCrowd) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 2000;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    const std::uint64_t joints = soldier.skeleton.jointCount();
    const std::uint64_t records = 2000 * sizeof(gpu::CharacterRecord);
    struct Case {
        skin::Method method;
        render::AnimationPath animation;
        bool perSlot;
    };
    const Case cases[] = {{skin::Method::Compute, render::AnimationPath::Gpu, true},
                          {skin::Method::TwoPass, render::AnimationPath::Gpu, true},
                          {skin::Method::VertexShaderInstanced, render::AnimationPath::Gpu, true},
                          {skin::Method::VertexShader, render::AnimationPath::Gpu, false},
                          {skin::Method::Static, render::AnimationPath::Gpu, false},
                          {skin::Method::Compute, render::AnimationPath::Cpu, false}};
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(skin::methodName(c.method)) + ", " + render::animationPathName(c.animation) +
                     " animation");
        const test::RendererOptions options = cappedOptions(c.method, c.animation);
        const frame::MemoryPlan plan = frame::planMemory(*context, crowd, options);
        test::TestRenderer renderer(*context, crowd, options);
        const render::CrowdBuffers& buffers = renderer.buffers();
        // A block: the soldier's joints, rounded up to the device's offset alignment.
        const std::uint64_t block = buffers.largestBoneBlock();
        EXPECT_GE(block, joints);
        EXPECT_LT(block, 2 * joints);
        const std::uint64_t blocks = c.perSlot ? 300 : 2000 + 1;  // per character: one spare for vs's range
        EXPECT_EQ(buffers.bones().size, blocks * block * sizeof(gpu::BoneRows));
        EXPECT_EQ(buffers.boneBlocks(), c.perSlot ? render::BoneBlocks::PerMeshSlot : render::BoneBlocks::PerCharacter);
        // The planner's figure is the allocation, to the byte, and the totals agree within 1 %.
        EXPECT_EQ(itemBytes(plan.items, kBonesItem), records + buffers.bones().size);
        EXPECT_EQ(itemBytes(renderer.recorder().memory(), kBonesItem), records + buffers.bones().size);
        std::uint64_t allocated = 0;
        for (const skin::MemoryItem& item : renderer.recorder().memory()) allocated += item.bytes;
        EXPECT_NEAR(static_cast<double>(plan.total()), static_cast<double>(allocated), 0.01 * static_cast<double>(allocated));
        EXPECT_DOUBLE_EQ(renderer.recorder().memoryPerCharacter().at("bones"),
                         static_cast<double>(buffers.bones().size) / 2000.0);
        // The renderer draws with them (validation silent).
        renderer.renderFrame(1.0f);
        renderer.finish();
    }
}

// The bones of every character the last frame skinned, read where its record says they are, against
// the CPU jobs' (skinned positions, in units of the model's height); with blocks per character, the
// record must name the character's own block.
double worstListedBones(const gpu::VulkanContext& context, const test::TestRenderer& renderer, crowd::Crowd& crowd,
                        float time) {
    const std::vector<std::byte> bytes = test::readBuffer(context, renderer.buffers().bones());
    const auto* gpuBones = reinterpret_cast<const gpu::BoneRows*>(bytes.data());
    const std::vector<gpu::CharacterRecord> records = test::readCharacterRecords(context, renderer);
    const bool perCharacter = renderer.buffers().boneBlocks() == render::BoneBlocks::PerCharacter;
    double worst = 0.0;
    std::size_t listed = 0;
    for (const std::vector<std::uint32_t>& bucket : test::readVisibleLists(context, renderer))
        for (std::uint32_t c : bucket) {
            const model::SkinnedModel& m = crowd.modelOf(c);
            if (perCharacter) {
                EXPECT_EQ(records[c].ids.y, renderer.buffers().boneOffsets()[c]) << "character " << c;
            }
            std::vector<gpu::BoneRows> cpu(m.skeleton.jointCount());
            crowd.animateCharacter(c, time, cpu);
            const std::span<const gpu::BoneRows> gpu(gpuBones + records[c].ids.y, cpu.size());
            const std::vector<skin::CpuSkinnedVertex> a = skin::skinOnCpu(m, cpu), b = skin::skinOnCpu(m, gpu);
            for (std::size_t v = 0; v < a.size(); ++v)
                worst = std::max(worst, glm::length(a[v].position - b[v].position) / m.height());
            ++listed;
        }
    EXPECT_GT(listed, 50u) << "the frame skins characters";
    return worst;
}

// A switch to a method or path that needs every character's bones reallocates them, and back; after
// each, the bones of every character skinned are its own pose, where its record says.
TEST_F(GpuTest, SwitchingToTheVsBaselineOrTheCpuPathGivesEveryCharacterABoneBlock) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 2000;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options = cappedOptions(skin::Method::Compute, render::AnimationPath::Gpu);
    options.size = {160, 90};
    test::TestRenderer renderer(*context, crowd, options);
    render::Camera inside;  // in the crowd, so that the mesh capacity fills
    inside.eye = crowd.center() + glm::vec3(0.0f, 2.0f, 0.0f);
    inside.target = inside.eye + glm::vec3(10.0f, -1.0f, 3.0f);
    renderer.camera = test::appCamera(inside);
    const std::uint64_t block = renderer.buffers().largestBoneBlock() * sizeof(gpu::BoneRows);
    float time = 0.5f;
    auto frame = [&] {
        time += 0.25f;  // every frame another pose: a block left from the last frame is wrong
        renderer.renderFrame(time);
        renderer.finish();
        EXPECT_LT(worstListedBones(*context, renderer, crowd, time), 1e-5);
        return renderer.readback();
    };
    const app::Rgba8Image slots = frame();
    EXPECT_EQ(renderer.buffers().bones().size, 300 * block);
    // vs binds every character's own block at offsets the CPU recorded: the records' ids.y, which the
    // compute frames set to slots, are the characters' own again.
    renderer.setMethod(crowdgpu::Method::VertexShader);
    EXPECT_EQ(renderer.buffers().bones().size, 2001 * block);
    frame();
    renderer.setMethod(crowdgpu::Method::Compute);
    EXPECT_EQ(renderer.buffers().bones().size, 300 * block);
    frame();
    renderer.setAnimation(crowdgpu::Animation::Cpu);
    EXPECT_EQ(renderer.buffers().bones().size, 2001 * block);
    frame();
    renderer.setAnimation(crowdgpu::Animation::Gpu);
    EXPECT_EQ(renderer.buffers().bones().size, 300 * block);
    frame();
    // The first frame's time again, after all that: the first frame's picture.
    time = 0.5f;
    EXPECT_GT(test::fractionOfMatchingPixels(slots, frame(), 2), 0.995);
}

// What memoryNeeded says the crowd needs: 10,000,000 soldiers, impostors on, the default mesh
// capacity (65,536), shadows on, `compute`. Above the capacity every item grows by a fixed amount per
// character (records, motion segments, LOD and shadow states, impostor lists, the cut's lists and tie
// bits), so two crowds' figures give that amount and the 10,000,000 figure exactly (a third crowd
// checks that the growth is linear); building a crowd of 10,000,000 here would take gigabytes of host
// memory. The amount per far character must be at most 200 bytes, the whole under 4 GiB.
TEST_F(GpuTest, TenMillionSoldiersWithImpostorsNeedUnderFourGibibytes) {
    crowdgpu::RendererSettings settings;
    settings.method = crowdgpu::Method::Compute;
    settings.impostors = true;
    ASSERT_EQ(settings.meshCapacity, 65536u);
    ASSERT_TRUE(settings.shadows);
    auto needed = [&](std::uint32_t count) {
        crowdgpu::GridLayout layout;
        layout.count = count;
        const crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
        return static_cast<double>(crowdgpu::memoryNeeded(context->physicalDevice, crowd, settings));
    };
    const double small = needed(200000), middle = needed(300000), large = needed(400000);
    const double perCharacter = (large - small) / 200000.0;
    EXPECT_NEAR(middle, 0.5 * (small + large), 64.0) << "linear above the capacity";
    const double tenMillion = large + perCharacter * (10000000.0 - 400000.0);
    std::printf("memoryNeeded, compute, impostors, capacity 65,536: %.0f bytes at 200,000; %.2f bytes per far "
                "character; %.0f bytes (%.3f GiB) at 10,000,000\n",
                small, perCharacter, tenMillion, tenMillion / 1073741824.0);
    EXPECT_LE(perCharacter, 200.0);
    EXPECT_LT(tenMillion, 4.0 * 1073741824.0);
}

// Draw i of the last frame: its character.
std::vector<std::uint32_t> drawnCharacters(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    const std::vector<std::byte> totalsBytes = test::readBuffer(context, renderer.drawLists().totals());
    const std::vector<std::byte> drawBytes = test::readBuffer(context, renderer.drawLists().draws());
    gpu::DrawTotals totals;
    std::memcpy(&totals, totalsBytes.data(), sizeof totals);
    std::vector<std::uint32_t> characters(totals.drawCount);
    for (std::uint32_t i = 0; i < totals.drawCount; ++i) {
        gpu::DrawIndexedCommand draw;
        std::memcpy(&draw, drawBytes.data() + i * sizeof draw, sizeof draw);
        characters[i] = draw.firstInstance;
    }
    return characters;
}

// A line of soldiers, each with its own clip, phase and speed, walking away from the camera's start.
std::vector<crowd::Character> soldierLine(const model::SkinnedModel& soldier, std::uint32_t count) {
    std::vector<crowd::Character> characters(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        crowd::Character& c = characters[i];
        c.clip = i % static_cast<std::uint32_t>(soldier.clips.size());
        c.timeOffset = 0.173f * static_cast<float>(i);
        c.speed = 0.8f + 0.1f * static_cast<float>(i % 5);
        c.heading = 0.7f * static_cast<float>(i);
        c.position = glm::vec3(static_cast<float>(i % 3) - 1.0f, 0.0f, -1.5f * static_cast<float>(i));
    }
    return characters;
}

// Two frames from two places along the line, so the characters at a mesh level, their levels and
// their places in the draw list change: every drawn character's skinned vertices equal the CPU
// reference's for its own pose at that frame's time, its record names its slot's block, and some
// characters drawn in both frames changed slot.
TEST_F(GpuTest, ACharacterThatChangesMeshSlotSkinsWithItsOwnPose) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const std::vector<skin::Method> methods = context->fragmentStores
                                                  ? std::vector<skin::Method>{skin::Method::Compute, skin::Method::TwoPass,
                                                                              skin::Method::TwoPassDirect}
                                                  : std::vector<skin::Method>{skin::Method::Compute, skin::Method::TwoPass};
    for (const skin::Method method : methods) {
        SCOPED_TRACE(skin::methodName(method));
        crowd::Crowd crowd(soldier, soldierLine(soldier, 60));
        test::RendererOptions options;
        options.size = {320, 180};
        options.method = method;
        options.cull.lodThresholds[0] = 90.0f;
        options.cull.lodThresholds[1] = 40.0f;
        options.cull.impostors = true;
        options.cull.impostorThreshold = 6.0f;
        options.meshCapacity = 20;
        test::TestRenderer renderer(*context, crowd, options);
        ASSERT_EQ(renderer.buffers().boneBlocks(), render::BoneBlocks::PerMeshSlot);
        const std::uint32_t blockRows = renderer.buffers().slotBoneRows();
        const double height = soldier.height();
        const std::vector<model::LodMorphTarget> targets = model::lodMorphTargets(soldier, render::lodsOf(soldier));
        std::map<std::uint32_t, std::uint32_t> previousSlot;
        std::uint32_t changedSlot = 0;
        for (const auto& [z, time] : {std::pair{6.0f, 0.6f}, std::pair{-24.0f, 1.35f}}) {
            SCOPED_TRACE("camera at z = " + std::to_string(z));
            render::Camera camera;
            camera.eye = glm::vec3(4.0f, 3.0f, z);
            camera.target = glm::vec3(0.0f, 1.0f, z - 20.0f);
            renderer.camera = test::appCamera(camera);
            renderer.renderFrame(time);
            renderer.finish();
            const std::vector<std::uint32_t> drawn = drawnCharacters(*context, renderer);
            const std::map<std::uint32_t, test::DrawnCharacter> where = test::readDrawList(*context, renderer);
            const std::vector<gpu::CharacterRecord> records = test::readCharacterRecords(*context, renderer);
            const std::vector<std::uint32_t> states = test::readShadowLists(*context, renderer).states;
            EXPECT_EQ(drawn.size(), 20u) << "the mesh capacity is full";
            double worst = 0.0;
            std::vector<gpu::BoneRows> bones(soldier.skeleton.jointCount());
            for (std::uint32_t slot = 0; slot < drawn.size(); ++slot) {
                const std::uint32_t c = drawn[slot];
                EXPECT_EQ(records[c].ids.y, slot * blockRows) << "character " << c;
                if (previousSlot.contains(c) && previousSlot[c] != slot) ++changedSlot;
                crowd.animateCharacter(c, time, bones);
                const test::DrawnCharacter& d = where.at(c);
                const std::vector<skin::CpuSkinnedVertex> expected =
                    test::cpuFadedCharacter(soldier, targets, skin::skinOnCpu(soldier, bones), d.lod, states[c]);
                const test::ReadbackVertices gpu =
                    test::readSkinnedVertices(*context, renderer.method().skinnedVertices(), d.firstVertex, d.vertexCount);
                for (std::uint32_t v = 0; v < d.vertexCount; ++v)
                    worst = std::max(worst, glm::length(glm::dvec3(gpu.positions[v]) - expected[v].position) / height);
            }
            EXPECT_LT(worst, 1e-5);
            previousSlot.clear();
            for (std::uint32_t slot = 0; slot < drawn.size(); ++slot) previousSlot[drawn[slot]] = slot;
        }
        EXPECT_GT(changedSlot, 0u) << "no character drawn in both frames changed slot: the test shows nothing";
    }
}

}  // namespace
