// The structure-of-arrays animation jobs (anim/soa_*_job.h) against the scalar jobs they replace in the
// crowd, which stay the reference: sampling on every clip of the built-in models, the STEP and
// CUBICSPLINE test character and the shared glTF assets; blending and slerp at every angle; palettes;
// and the crowd's bones mid-crossfade against the scalar chain. Each runs both backends: the native one
// (SSE2 on x86-64) and the portable one that builds for other processors run.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "anim/props_carried.h"
#include "anim/blending_job.h"
#include "anim/palette_job.h"
#include "anim/sampling_job.h"
#include "anim/soa_blending_job.h"
#include "anim/soa_maths.h"
#include "anim/soa_palette_job.h"
#include "anim/soa_sampling_job.h"
#include "crowd/crowd.h"
#include "support/gltf_builder.h"
#include "support/gpu_test.h"

namespace {

using Native = simd::NativeFloat4;
using Portable = simd::LaneFloat4;

using test::horse;
using test::soldier;
// The test strip character with a LINEAR clip ("bend") and a STEP + CUBICSPLINE one ("hop").
const model::SkinnedModel& strip() {
    static const model::SkinnedModel m = [] {
        test::GltfBuilder b = test::stripCharacter();
        test::addHopAnimation(b);
        return test::loadText(b.gltf());
    }();
    return m;
}

const char* const kSharedAssets[] = {"fox/Fox.glb", "cesium-man/CesiumMan.glb", "rigged-simple/RiggedSimple.glb"};

// The shared assets, or the first one missing (its path) when not all are present.
std::vector<model::SkinnedModel> sharedAssets(std::string& missing) {
    const std::filesystem::path root(CROWD_SHARED_ASSETS_DIR);
    std::vector<model::SkinnedModel> assets;
    for (const char* file : kSharedAssets) {
        if (!std::filesystem::exists(root / file)) {
            missing = (root / file).string();
            return {};
        }
        assets.push_back(test::loadModel((root / file).string(), 1));
    }
    return assets;
}

// Differences between two joints' transforms: translation and scale relative to their size (at least
// 1), rotation as 1 - |dot| (q and -q are one rotation).
struct PoseError {
    float translation = 0.0f, rotation = 0.0f, scale = 0.0f;
    std::uint32_t joints = 0, bitIdentical = 0;

    void add(const anim::Transform& expected, const anim::Transform& got) {
        auto relative = [](glm::vec3 e, glm::vec3 g) { return glm::length(e - g) / std::max(1.0f, glm::length(e)); };
        translation = std::max(translation, relative(expected.translation, got.translation));
        scale = std::max(scale, relative(expected.scale, got.scale));
        rotation = std::max(rotation, 1.0f - std::abs(glm::dot(expected.rotation, got.rotation)));
        ++joints;
        if (std::memcmp(&expected, &got, sizeof expected) == 0) ++bitIdentical;
    }
};

// The existing tolerances of the scalar sampling job against anim::sampleClip (tests/test_living_crowd.cpp).
void expectWithinSamplingTolerance(const PoseError& e, const std::string& what) {
    EXPECT_LT(e.translation, 1e-6f) << what;
    EXPECT_LT(e.rotation, 1e-6f) << what;
    EXPECT_LT(e.scale, 1e-6f) << what;
}

// Every clip of the model at 40 times, forward in small steps (the cursors' fast path) then anywhere
// with the same garbage in both jobs' cursors: the SoA job with backend F against the scalar job.
template <class F>
PoseError soaSamplingError(const model::SkinnedModel& m) {
    anim::ClipLibrary library;
    library.addModel(m.skeleton, m.clips, {});
    const std::size_t joints = m.skeleton.jointCount();
    std::vector<anim::Transform> expected(joints), got(joints);
    std::vector<anim::SoaTransform> soa(anim::soaGroups(joints));
    std::vector<std::uint16_t> scalarCursors(3 * joints, 0), soaCursors(3 * joints, 0);
    std::mt19937 random(7);
    PoseError error;
    for (std::uint32_t clip = 0; clip < m.clips.size(); ++clip) {
        const float duration = m.clips[clip].duration;
        for (int i = 0; i < 40; ++i) {
            const float t = i < 20 ? 0.013f * static_cast<float>(i) : 1.5f * duration * std::uniform_real_distribution<float>()(random);
            if (i >= 20)
                for (std::size_t k = 0; k < scalarCursors.size(); ++k)
                    scalarCursors[k] = soaCursors[k] = static_cast<std::uint16_t>(random() % 70);
            anim::SamplingJob{&library, 0, clip, t, scalarCursors, expected}.run();
            const anim::SoaSamplingJob job{&library, 0, clip, t, soaCursors, soa};
            EXPECT_TRUE(job.validate());
            job.runWith<F>();
            anim::fromSoa(soa, got);
            for (std::size_t j = 0; j < joints; ++j) error.add(expected[j], got[j]);
            // Padding lanes hold the identity, so a palette over them stays finite.
            for (std::size_t j = joints; j < soa.size() * anim::kSoaLanes; ++j) {
                const anim::Transform pad = anim::soaLane(soa.back(), j % anim::kSoaLanes);
                EXPECT_EQ(pad.rotation, glm::quat(1, 0, 0, 0));
                EXPECT_EQ(pad.scale, glm::vec3(1.0f));
            }
        }
    }
    return error;
}

template <class F>
void expectSamplingMatches(const model::SkinnedModel& m) {
    const PoseError e = soaSamplingError<F>(m);
    std::printf("%s: worst translation %.2g, rotation 1-|dot| %.2g, scale %.2g; %u of %u joints bit for bit\n",
                m.name.c_str(), e.translation, e.rotation, e.scale, e.bitIdentical, e.joints);
    expectWithinSamplingTolerance(e, m.name);
    // The lerps, the nlerp and the normalization repeat the scalar operations: most joints come out
    // bit for bit (only slerped keys, through the polynomial trigonometry, may differ in the last bits).
    EXPECT_GT(e.bitIdentical, e.joints * 9 / 10) << m.name;
}

TEST(SoaJobs, SamplingEqualsTheScalarJobOnEveryBuiltInClip) {
    for (const model::SkinnedModel* m : {&soldier(), &horse(), &strip()}) {
        ASSERT_FALSE(m->clips.empty()) << m->name;
        expectSamplingMatches<Native>(*m);
        expectSamplingMatches<Portable>(*m);
    }
}

TEST(SoaJobs, SamplingEqualsTheScalarJobOnEverySharedAssetClip) {
    std::string missing;
    const std::vector<model::SkinnedModel> assets = sharedAssets(missing);
    if (assets.empty()) GTEST_SKIP() << "shared asset " << missing << " not present (see ../shared/assets/INVENTORY.md)";
    for (const model::SkinnedModel& m : assets) {
        expectSamplingMatches<Native>(m);
        expectSamplingMatches<Portable>(m);
    }
}

glm::quat randomRotation(std::mt19937& random) {
    std::normal_distribution<float> normal;
    return glm::normalize(glm::quat(normal(random), normal(random), normal(random), normal(random)));
}

// Pairs of unit quaternions at angles spread over 0 to 180 degrees (half of them written as -q), and
// blends spread over [0, 1]: the SoA slerp against anim::slerpShortest, on the arc and in the nlerp band.
template <class F>
float slerpError(std::uint32_t& slerped) {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit;
    float worst = 0.0f;
    for (int pair = 0; pair < 4000; pair += 4) {
        glm::vec4 a[4], b[4];
        float s[4];
        for (int lane = 0; lane < 4; ++lane) {
            const glm::quat qa = randomRotation(random);
            const float angle = std::numbers::pi_v<float> * static_cast<float>((pair + lane) % 400) / 399.0f;
            glm::quat qb = qa * glm::angleAxis(angle, glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) + 0.1f));
            if (lane % 2) qb = -qb;
            a[lane] = {qa.x, qa.y, qa.z, qa.w};
            b[lane] = {qb.x, qb.y, qb.z, qb.w};
            s[lane] = unit(random);
            if (std::abs(glm::dot(a[lane], b[lane])) <= anim::kNlerpAbove) ++slerped;
        }
        auto soa = [](const glm::vec4 (&v)[4]) {
            F x = F::load(&v[0].x), y = F::load(&v[1].x), z = F::load(&v[2].x), w = F::load(&v[3].x);
            transpose(x, y, z, w);
            return anim::soa::Quat<F>{x, y, z, w};
        };
        const anim::soa::Quat<F> q = anim::soa::slerpShortest(soa(a), soa(b), F::set(s[0], s[1], s[2], s[3]));
        for (int lane = 0; lane < 4; ++lane) {
            const glm::vec4 expected = anim::slerpShortest(a[lane], b[lane], s[lane]);
            const glm::vec4 got(q.x.lane(lane), q.y.lane(lane), q.z.lane(lane), q.w.lane(lane));
            worst = std::max(worst, glm::length(expected - got));
        }
    }
    return worst;
}

TEST(SoaJobs, SlerpEqualsTheScalarSlerpAtEveryAngle) {
    std::uint32_t slerped = 0;
    // The polynomial inverse cosine and sines are within a few float ulps of libm's: 1e-6 of a unit quaternion.
    const float native = slerpError<Native>(slerped), portable = slerpError<Portable>(slerped);
    std::printf("slerp: worst %.2g (native), %.2g (portable); %u of 8,000 pairs on the arc\n", native, portable, slerped);
    EXPECT_LT(native, 1e-6f);
    EXPECT_LT(portable, 1e-6f);
    EXPECT_GT(slerped, 6000u) << "most of the 8,000 pairs are far apart enough to take the arc, not the nlerp";
}

TEST(SoaJobs, PolynomialTrigonometryIsWithinTwoUlpsOfLibm) {
    float acosWorst = 0.0f, sinWorst = 0.0f;
    for (int i = 0; i <= 100000; i += 4) {
        const auto at = [&](int k, float top) { return top * static_cast<float>(std::min(i + k, 100000)) / 100000.0f; };
        const Native x = Native::set(at(0, 1.0f), at(1, 1.0f), at(2, 1.0f), at(3, 1.0f));
        const Native y = Native::set(at(0, 1.5707964f), at(1, 1.5707964f), at(2, 1.5707964f), at(3, 1.5707964f));
        const Native acos = anim::soa::acosUnit(x), sin = anim::soa::sinQuarterTurn(y);
        for (int lane = 0; lane < 4; ++lane) {
            acosWorst = std::max(acosWorst, std::abs(acos.lane(lane) - std::acos(x.lane(lane))));
            sinWorst = std::max(sinWorst, std::abs(sin.lane(lane) - std::sin(y.lane(lane))));
        }
    }
    std::printf("acos: worst %.2g, sin: worst %.2g\n", acosWorst, sinWorst);
    // Two ulps at the largest values (pi/2 and 1).
    EXPECT_LE(acosWorst, 2.0f * 1.2e-7f);
    EXPECT_LE(sinWorst, 2.0f * 6e-8f);
}

// Two random poses in SoA (rotations in either hemisphere, translations and scales spread), blended by
// both jobs at several weights, the output aliasing `to` as the crowd runs it.
template <class F>
PoseError blendingError() {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> spread(-3.0f, 3.0f);
    const std::size_t joints = 23;
    std::vector<anim::Transform> from(joints), to(joints), expected(joints), got(joints);
    PoseError error;
    for (float weight : {0.0f, 0.1f, 0.37f, 0.5f, 0.93f, 1.0f}) {
        for (std::size_t j = 0; j < joints; ++j) {
            from[j] = {{spread(random), spread(random), spread(random)}, randomRotation(random),
                       glm::vec3(1.0f) + 0.2f * glm::vec3(spread(random))};
            to[j] = {{spread(random), spread(random), spread(random)}, randomRotation(random),
                     glm::vec3(1.0f) + 0.2f * glm::vec3(spread(random))};
        }
        anim::BlendingJob{from, to, weight, expected}.run();
        std::vector<anim::SoaTransform> soaFrom(anim::soaGroups(joints)), soaTo(anim::soaGroups(joints));
        anim::toSoa(from, soaFrom);
        anim::toSoa(to, soaTo);
        const anim::SoaBlendingJob job{soaFrom, soaTo, weight, soaTo};
        EXPECT_TRUE(job.validate());
        job.runWith<F>();
        anim::fromSoa(soaTo, got);
        for (std::size_t j = 0; j < joints; ++j) error.add(expected[j], got[j]);
    }
    return error;
}

TEST(SoaJobs, BlendingEqualsTheScalarJob) {
    for (const PoseError& e : {blendingError<Native>(), blendingError<Portable>()}) {
        expectWithinSamplingTolerance(e, "blend");
        EXPECT_EQ(e.bitIdentical, e.joints) << "the same operations in the same order";
    }
}

// Bones of the scalar and SoA palette jobs over the scalar sampling job's pose of every clip.
template <class F>
float paletteError(const model::SkinnedModel& m, std::uint32_t& bitIdentical, std::uint32_t& compared) {
    anim::ClipLibrary library;
    library.addModel(m.skeleton, m.clips, {});
    const std::size_t joints = m.skeleton.jointCount();
    std::vector<anim::Transform> locals(joints);
    std::vector<anim::SoaTransform> soa(anim::soaGroups(joints));
    std::vector<std::uint16_t> cursors(3 * joints, 0);
    std::vector<anim::Affine> scratch(joints), soaScratch(joints);
    std::vector<gpu::BoneRows> expected(joints), got(joints);
    const anim::Affine placement = anim::placementAffine({3.0f, 0.5f, -2.0f}, 0.7f, 1.3f);
    float worst = 0.0f;
    for (std::uint32_t clip = 0; clip < m.clips.size(); ++clip) {
        anim::SamplingJob{&library, 0, clip, 0.37f * m.clips[clip].duration, cursors, locals}.run();
        anim::toSoa(locals, soa);
        anim::PaletteJob{&library, 0, placement, locals, scratch, expected}.run();
        const anim::SoaPaletteJob job{&library, 0, placement, soa, soaScratch, got};
        EXPECT_TRUE(job.validate());
        job.runWith<F>();
        for (std::size_t j = 0; j < joints; ++j) {
            for (int r = 0; r < 3; ++r) {
                const glm::vec4 e = (&expected[j].row0)[r], g = (&got[j].row0)[r];
                worst = std::max(worst, glm::length(e - g) / std::max(1.0f, glm::length(e)));
                const glm::vec4 ew = (&scratch[j].row0)[r], gw = (&soaScratch[j].row0)[r];
                worst = std::max(worst, glm::length(ew - gw) / std::max(1.0f, glm::length(ew)));
            }
            ++compared;
            if (std::memcmp(&expected[j], &got[j], sizeof got[j]) == 0) ++bitIdentical;
        }
    }
    return worst;
}

TEST(SoaJobs, PaletteEqualsTheScalarJob) {
    std::string missing;
    std::vector<model::SkinnedModel> models = sharedAssets(missing);
    if (models.empty()) std::printf("shared asset %s not present: built-in models only\n", missing.c_str());
    for (const model::SkinnedModel* m : {&soldier(), &horse(), &strip()}) models.push_back(*m);
    for (const model::SkinnedModel& m : models) {
        std::uint32_t identical = 0, compared = 0;
        const float native = paletteError<Native>(m, identical, compared), portable = paletteError<Portable>(m, identical, compared);
        std::printf("%s palette: worst %.2g (native), %.2g (portable); %u of %u bones bit for bit\n", m.name.c_str(), native,
                    portable, identical, compared);
        // The existing tolerance of the palette job against the 4x4 hierarchy: 1e-5.
        EXPECT_LT(native, 1e-5f) << m.name;
        EXPECT_LT(portable, 1e-5f) << m.name;
        // The same products in the same order; only a zero's sign may differ.
        EXPECT_GT(identical, compared * 9 / 10) << m.name;
    }
}

// Soldiers, horses and test characters on a grid, each started on a random clip with a 1.2 s crossfade
// up to 1 s before `time`, planned to `time`.
crowd::Crowd crossfadingCrowd(std::uint32_t count, float time) {
    const std::vector<const model::SkinnedModel*> models = {&soldier(), &horse(), &strip()};
    std::vector<crowd::Character> characters;
    for (std::uint32_t i = 0; i < count; ++i) {
        crowd::Character c;
        c.position = {1.5f * static_cast<float>(i % 6), 0.0f, 1.5f * static_cast<float>(i / 6)};
        c.model = i % models.size();
        c.timeOffset = 0.37f * static_cast<float>(i);
        characters.push_back(c);
    }
    crowd::Crowd crowd(models, characters);
    std::mt19937 random(11);
    for (std::uint32_t i = 0; i < crowd.size(); ++i) {
        const auto clips = static_cast<std::uint32_t>(crowd.modelOf(i).clips.size());
        crowd.play(i, static_cast<std::int32_t>(random() % clips), time - std::uniform_real_distribution<float>(0.0f, 1.0f)(random),
                   1.2f, 0.8f + 0.05f * static_cast<float>(i % 8));
    }
    crowd.advanceTo(time);
    return crowd;
}

// The crowd's bones (SoA jobs) against the scalar chain the crowd ran before: sampling both clips,
// blending, palette, for characters caught mid-crossfade between random clips.
TEST(SoaJobs, CrowdBonesEqualTheScalarJobsMidCrossfade) {
    const float time = 4.0f;
    const crowd::Crowd crowd = crossfadingCrowd(36, time);
    const anim::ClipLibrary& library = crowd.library();
    std::uint32_t blending = 0;
    float worst = 0.0f;
    for (std::uint32_t i = 0; i < crowd.size(); ++i) {
        const std::uint32_t model = crowd.characters()[i].model;
        const std::uint32_t joints = library.jointCount(model);
        std::vector<gpu::BoneRows> got(joints), expected(joints);
        crowd.animateCharacter(i, time, got);

        const crowd::MotionState state = crowd.stateAt(i, time);
        std::vector<anim::Transform> from(joints), to(joints);
        std::vector<std::uint16_t> cursors(3 * joints, 0);
        const float cycle = state.phase - std::floor(state.phase);
        anim::SamplingJob{&library, model, state.clipTo, cycle * library.duration(model, state.clipTo), cursors, to}.run();
        if (state.weight < 1.0f) {
            anim::SamplingJob{&library, model, state.clipFrom, cycle * library.duration(model, state.clipFrom), cursors, from}.run();
            anim::BlendingJob{from, to, state.weight, to}.run();
        }
        if (state.weight > 0.05f && state.weight < 0.95f) ++blending;
        std::vector<anim::Affine> scratch(joints);
        anim::PaletteJob{&library, model, anim::placementAffine(state.position, state.heading, crowd.characters()[i].scale),
                         to, scratch, expected}.run();
        // Props the character does not carry, collapsed as the crowd does (anim/props_carried.h).
        anim::collapseUncarriedProps(crowd.model(model).skeleton.propOfJoint, crowd.characters()[i].props, scratch, expected);
        for (std::uint32_t j = 0; j < joints; ++j)
            for (int r = 0; r < 3; ++r) {
                const glm::vec4 e = (&expected[j].row0)[r];
                worst = std::max(worst, glm::length(e - (&got[j].row0)[r]) / std::max(1.0f, glm::length(e)));
            }
    }
    std::printf("crowd: %u of %u characters mid-crossfade, worst bone row %.2g\n", blending, crowd.size(), worst);
    EXPECT_GT(blending, 15u) << "most characters are mid-crossfade";
    EXPECT_LT(worst, 1e-5f);
}

#ifdef CROWD_ANIM_HAVE_SSE2
// The portable backend is what builds for other processors run: on x86-64 it must give SSE2's bones
// bit for bit, so its tests here stand for those builds.
TEST(SoaJobs, PortableBackendGivesTheNativeBonesBitForBit) {
    const model::SkinnedModel& m = soldier();
    anim::ClipLibrary library;
    library.addModel(m.skeleton, m.clips, {});
    const std::size_t joints = m.skeleton.jointCount();
    std::vector<anim::SoaTransform> native(anim::soaGroups(joints)), portable(anim::soaGroups(joints));
    std::vector<std::uint16_t> cursors(3 * joints, 0);
    std::vector<anim::Affine> scratch(joints);
    std::vector<gpu::BoneRows> nativeBones(joints), portableBones(joints);
    for (std::uint32_t clip = 0; clip < m.clips.size(); ++clip) {
        for (float t : {0.0f, 0.21f, 0.77f, 1.9f}) {
            anim::SoaSamplingJob{&library, 0, clip, t, cursors, native}.runWith<simd::Sse2Float4>();
            anim::SoaSamplingJob{&library, 0, clip, t, cursors, portable}.runWith<simd::LaneFloat4>();
            ASSERT_EQ(std::memcmp(native.data(), portable.data(), native.size() * sizeof native[0]), 0) << clip << " " << t;
            const anim::Affine placement = anim::placementAffine({1.0f, 0.0f, 2.0f}, 0.4f, 1.1f);
            anim::SoaPaletteJob{&library, 0, placement, native, scratch, nativeBones}.runWith<simd::Sse2Float4>();
            anim::SoaPaletteJob{&library, 0, placement, portable, scratch, portableBones}.runWith<simd::LaneFloat4>();
            for (std::size_t j = 0; j < joints; ++j)
                for (int r = 0; r < 3; ++r) EXPECT_EQ((&nativeBones[j].row0)[r], (&portableBones[j].row0)[r]);
        }
    }
}
#endif

}  // namespace
