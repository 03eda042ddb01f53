// libFuzzer target for the glTF loader: any bytes either load into a character that is safe to
// animate and skin, or fail with gpu::Error. Anything else (a sanitizer report, another exception,
// a broken invariant, a timeout) is a crash. Built and run by scripts/fuzz.sh.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "gpu/vulkan_error.h"
#include "model/gltf_loader.h"
#include "skin/cpu_skinning.h"

namespace {

[[noreturn]] void broken(const char* invariant) {
    std::fprintf(stderr, "gltf_loader_fuzzer: loaded model breaks an invariant: %s\n", invariant);
    std::abort();
}

#define EXPECT(condition)                     \
    do {                                      \
        if (!(condition)) broken(#condition); \
    } while (0)

// What every consumer of a SkinnedModel (crowd, GPU methods, CPU reference) relies on.
void checkModel(const model::SkinnedModel& m) {
    const anim::Skeleton& s = m.skeleton;
    const std::size_t joints = s.jointCount();
    EXPECT(joints >= 1 && joints <= model::kMaxGltfJoints);
    EXPECT(s.restPose.size() == joints && s.inverseBind.size() == joints && s.jointNames.size() == joints);
    for (std::size_t j = 0; j < joints; ++j) EXPECT(s.parents[j] < static_cast<std::int32_t>(j) && s.parents[j] >= -1);
    EXPECT(!m.vertices.empty() && !m.indices.empty() && m.indices.size() % 3 == 0);
    EXPECT(!m.materialColors.empty() && m.materialColors.size() <= MAX_MATERIALS);
    for (const std::uint32_t i : m.indices) EXPECT(i < m.vertices.size());
    for (const gpu::SkinVertex& v : m.vertices) {
        float sum = 0.0f;
        for (int k = 0; k < MAX_INFLUENCES; ++k) {
            EXPECT(v.joints[k] < joints);
            EXPECT(v.weights[k] >= 0.0f && v.weights[k] <= 1.0f);
            sum += v.weights[k];
        }
        EXPECT(std::abs(sum - 1.0f) < 1e-4f);
        EXPECT(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
        EXPECT(std::abs(glm::length(glm::vec3(v.normal)) - 1.0f) < 1e-3f);
        EXPECT(v.normal.w >= 0.0f && v.normal.w < static_cast<float>(m.materialColors.size()));
    }
    EXPECT(m.uvs.empty() || m.uvs.size() == m.vertices.size());
    const auto& texture = m.baseColorTexture;
    EXPECT(texture.rgba.size() == static_cast<std::size_t>(texture.width) * texture.height * 4);
    EXPECT(!m.clips.empty());
    for (const anim::Clip& clip : m.clips) {
        EXPECT(std::isfinite(clip.duration) && clip.duration >= 0.0f);
        for (const anim::Channel& c : clip.channels) {
            EXPECT(c.joint < joints && !c.times.empty());
            const std::size_t perKey = c.interpolation == anim::Interpolation::CubicSpline ? 3 : 1;
            EXPECT(c.values.size() == c.times.size() * perKey);
            for (std::size_t k = 1; k < c.times.size(); ++k) EXPECT(c.times[k] >= c.times[k - 1]);
        }
    }
}

// Runs the crowd's CPU jobs on a few poses of every clip (at most 4 clips, to keep executions fast).
void animate(const model::SkinnedModel& m) {
    const anim::Skeleton& s = m.skeleton;
    std::vector<anim::Transform> locals(s.jointCount());
    std::vector<glm::mat4> global(s.jointCount());
    std::vector<gpu::BoneRows> bones(s.jointCount());
    for (std::size_t c = 0; c < m.clips.size() && c < 4; ++c) {
        for (const float t : {0.0f, 0.37f * m.clips[c].duration, m.clips[c].duration}) {
            anim::sampleClip(m.clips[c], t, s.restPose, locals);
            anim::localToModel(s.parents, locals, s.rootTransform, global);
            anim::skinningMatrices(global, s.inverseBind, glm::mat4(1.0f), bones);
            (void)skin::skinOnCpu(m, bones);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        std::vector<std::string> notes;
        const model::SkinnedModel m = model::loadGltfFromMemory(std::span(data, size), "input", {}, &notes);
        checkModel(m);
        animate(m);
    } catch (const gpu::Error& error) {
        // The contract: one line naming the source.
        const std::string message = error.what();
        EXPECT(message.rfind("input: ", 0) == 0);
        EXPECT(message.find('\n') == std::string::npos);
    }
    return 0;
}
