// The pose sphere of clips of long duration: its cost is bounded however long the clip (a 2e6 s clip
// used to need 60 poses a second of it, and never finished; above 3.6e7 s the count overflowed int),
// and it still holds every pose, including one the evenly spaced samples of a long clip step over.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "support/gpu_test.h"
#include "skin/cpu_skinning.h"
#include "app/crowd_app.h"
#include "crowd/pose_bounds.h"
#include "support/gltf_builder.h"
#include "support/run_program.h"

namespace {

// The strip character with clip "long" of `duration` seconds: its root stands still but for a jump of
// 5 m up around `spikeAt`, a tenth of its spacing between neighbouring keys (so thinned samples
// step over it).
test::GltfBuilder stripWithLongClip(float duration, float spikeAt, float spikeWidth) {
    test::GltfBuilder b = test::stripCharacter();
    const int times = b.floats({0.0f, spikeAt - spikeWidth, spikeAt, spikeAt + spikeWidth, duration}, "SCALAR");
    const int moves = b.floats({0, 0, 0, 0, 0, 0, 0, 5, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
    b.doc["animations"].push_back(
        {{"name", "long"},
         {"samplers", {{{"input", times}, {"output", moves}, {"interpolation", "LINEAR"}}}},
         {"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}}}}});
    return b;
}

// Every vertex of `model` playing `clip` at `time` lies in its pose sphere.
void expectPoseInSphere(const model::SkinnedModel& model, std::uint32_t clip, float time) {
    const glm::vec4 sphere = model.poseSphere;
    for (const skin::CpuSkinnedVertex& v : skin::poseOnCpu(model, clip, time))
        EXPECT_LE(glm::length(v.position - glm::dvec3(sphere)), sphere.w) << "at " << time << " s";
}

}  // namespace

TEST(PoseSphereOfLongClips, HoldsAPoseTheEvenlySpacedSamplesStepOver) {
    // 1000 s: 60,000 samples a second's worth would be sampled; 1,200 evenly spaced ones are 0.83 s
    // apart and miss the 0.2 s jump at 500.4 s.
    model::SkinnedModel strip = test::loadText(stripWithLongClip(1000.0f, 500.4f, 0.1f).gltf());
    strip.poseSphere = crowd::computePoseSphere(strip);
    ASSERT_EQ(strip.clips[1].name, "long");
    expectPoseInSphere(strip, 1, 500.4f);
    expectPoseInSphere(strip, 1, 0.0f);
    expectPoseInSphere(strip, 0, 0.75f);  // the other clip too
}

TEST(PoseSphereOfLongClips, ClipsOfAbsurdLengthLoadQuicklyWithAConservativeSphere) {
    for (const float duration : {2e6f, 1e9f, 3e38f}) {
        const float spikeAt = duration / 2.0f, spikeWidth = duration / 1e4f;
        const std::filesystem::path gltf = std::filesystem::temp_directory_path() /
                                           ("crowd-long-clip-" + std::to_string(::getpid()) + ".gltf");
        std::ofstream(gltf) << stripWithLongClip(duration, spikeAt, spikeWidth).gltf();
        // What a user sees: the model lists at once (it used to run out of memory or never finish).
        const test::ProgramResult r =
            test::runProgram(CROWD_RENDER_BINARY, "--model " + gltf.string() + " --list-clips", "", 30);
        EXPECT_EQ(r.exitCode, 0) << duration << " s: " << r.err;
        EXPECT_NE(r.out.find("pose sphere"), std::string::npos) << r.out;
        const model::SkinnedModel strip = test::loadModel(gltf.string(), 1);
        std::filesystem::remove(gltf);
        expectPoseInSphere(strip, 1, spikeAt);
        expectPoseInSphere(strip, 1, spikeAt / 3.0f);
    }
}
