// Late starts on the GPU: scene time is a double and reaches the motion pass relative to the crowd's
// epoch (crowd/epoch.h), so at 1e6 s, 1e7 s and the latest --start (app::kMaxStartSeconds) a frame is a
// sixtieth of a second after the one before, as at 0 s. Before, time was a float: at 1e6 s it moved in
// 62.5 ms steps and consecutive frames were one picture.
#include <cmath>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "app/start_time.h"
#include "model/procedural_models.h"
#include "app/camera_path.h"
#include "support/gpu_test.h"

namespace {

class LateStart : public test::GpuTest {};

// Character 0's skinned vertices at each of `times`, rendered one after another by one renderer.
std::vector<test::ReadbackVertices> skinnedAt(const gpu::VulkanContext& context, crowd::Crowd& crowd,
                                              render::AnimationPath path, const std::vector<double>& times) {
    test::RendererOptions options;
    options.size = {32, 32};
    options.method = skin::Method::Compute;
    options.animation = path;
    options.cull.mode = render::CullMode::Off;
    options.cull.lod = false;
    test::TestRenderer renderer(context, crowd, options);
    std::vector<test::ReadbackVertices> frames;
    for (double time : times) {
        renderer.renderFrame(time);
        renderer.finish();
        frames.push_back(test::readSkinnedCharacter(context, renderer, 0));
    }
    return frames;
}

// The largest distance a vertex is apart in two readbacks.
double farthestApart(const test::ReadbackVertices& a, const test::ReadbackVertices& b) {
    double farthest = 0.0;
    for (std::size_t v = 0; v < a.positions.size(); ++v)
        farthest = std::max<double>(farthest, glm::length(glm::vec3(a.positions[v]) - glm::vec3(b.positions[v])));
    return farthest;
}

std::vector<double> framesFrom(double start, std::uint32_t count) {
    std::vector<double> times;
    for (std::uint32_t f = 0; f < count; ++f) times.push_back(app::frameTime(f, start));
    return times;
}

}  // namespace

TEST_F(LateStart, ConsecutiveFramesDifferAndMatchTheSamePointOfTheCycleNearZero) {
    const model::SkinnedModel soldier = model::makeSoldier(1);
    const auto walk = static_cast<std::uint32_t>(soldier.findClip("walk"));
    const double period = soldier.clips[walk].duration;  // a soldier walking in place at speed 1 from 0 s
    for (const render::AnimationPath path : {render::AnimationPath::Gpu, render::AnimationPath::Cpu}) {
        for (const double start : {1e6, 1e7, app::kMaxStartSeconds}) {
            crowd::Crowd late(soldier, {crowd::Character{walk}}), early(soldier, {crowd::Character{walk}});
            const double samePoint = start - std::floor(start / period) * period;
            const std::vector<test::ReadbackVertices> frames = skinnedAt(*context, late, path, framesFrom(start, 3));
            const std::vector<test::ReadbackVertices> reference =
                skinnedAt(*context, early, path, framesFrom(samePoint, 3));
            for (std::size_t f = 0; f < frames.size(); ++f) {
                // A walking soldier's hands and feet move centimetres in a sixtieth of a second...
                if (f > 0) {
                    EXPECT_GT(farthestApart(frames[f - 1], frames[f]), 0.005) << start << " frame " << f;
                }
                // ... exactly as they do at the same point of the walk near 0 s (well under a millimetre).
                EXPECT_LT(farthestApart(frames[f], reference[f]), 1e-3) << start << " frame " << f;
            }
        }
    }
}

TEST_F(LateStart, EitherAnimationPathDrawsTheSameMillingCrowdAMillionSecondsIn) {
    // The CPU reference evaluates the same epoch-relative records with the same float arithmetic as the
    // motion pass, so the two paths agree as closely at 1e6 s as at 0 s.
    const app::CrowdModels models = app::loadModels("soldier:3,horse:1", 1);
    app::SceneOptions scene;
    scene.model = "soldier:3,horse:1";
    scene.count = 96;
    scene.seed = 2;
    scene.behaviour = crowdgpu::Behaviour::Mill;
    auto render = [&](crowdgpu::Animation path, double time) {
        crowdgpu::Crowd crowd = app::buildCrowd(models, scene);
        app::RendererOptions options;
        options.size = {160, 96};
        options.method = crowdgpu::Method::Compute;
        options.animation = path;
        app::CrowdRenderer renderer(*device, crowd, options);
        for (double t : {time - 3.0, time - 1.0, time}) {
            renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, app::crowdShape(crowd), 160.0f / 96.0f, t);
            renderer.renderFrame(t);
        }
        return renderer.readback();
    };
    const double late = 1e6 + 9.0;
    const app::Rgba8Image cpu = render(crowdgpu::Animation::Cpu, late);
    const app::Rgba8Image gpu = render(crowdgpu::Animation::Gpu, late);
    const app::Rgba8Image earlier = render(crowdgpu::Animation::Gpu, late - 1.0);
    EXPECT_GT(test::fractionOfMatchingPixels(cpu, gpu, 2), 0.999);
    EXPECT_LT(test::fractionOfMatchingPixels(gpu, earlier, 2), 0.98) << "and the crowd moves";
}
