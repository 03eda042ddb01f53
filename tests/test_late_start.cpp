// The latest start a run accepts (app::kMaxStartSeconds) still animates frame by frame: scene time is
// a float, and at 1e6 s (the old limit) it moved in 62.5 ms steps, so consecutive frames were one
// picture.
#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "app/start_time.h"
#include "model/procedural_models.h"
#include "support/gpu_test.h"

namespace {

class LateStart : public test::GpuTest {};

// The largest distance any vertex of character 0 moves between two frames at times a and b.
double poseChange(const gpu::VulkanContext& context, crowd::Crowd& crowd, float a, float b) {
    test::RendererOptions options;
    options.size = {32, 32};
    options.method = skin::Method::Compute;
    options.cull.mode = render::CullMode::Off;
    options.cull.lod = false;
    test::TestRenderer renderer(context, crowd, options);
    renderer.renderFrame(a);
    renderer.finish();
    const test::ReadbackVertices first = test::readSkinnedCharacter(context, renderer, 0);
    renderer.renderFrame(b);
    renderer.finish();
    const test::ReadbackVertices second = test::readSkinnedCharacter(context, renderer, 0);
    double largest = 0.0;
    for (std::size_t v = 0; v < first.positions.size(); ++v)
        largest = std::max<double>(largest, glm::length(glm::vec3(first.positions[v]) - glm::vec3(second.positions[v])));
    return largest;
}

}  // namespace

TEST_F(LateStart, ConsecutiveFramesAtTheLatestStartDiffer) {
    const model::SkinnedModel soldier = model::makeSoldier(1);
    const std::uint32_t walk = static_cast<std::uint32_t>(soldier.findClip("walk"));
    crowd::Crowd crowd(soldier, {crowd::Character{walk}});
    const float start = app::kMaxStartSeconds;
    // A walking soldier's hands and feet move centimetres in a sixtieth of a second.
    EXPECT_GT(poseChange(*context, crowd, start, app::frameTime(1, start)), 0.005);
    EXPECT_GT(poseChange(*context, crowd, app::frameTime(1, start), app::frameTime(2, start)), 0.005);
}
