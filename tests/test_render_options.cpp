// The command line the three programs share (app/options.h): what it accepts and what it refuses,
// without starting a device; crowd-render's own runs are in test_crowd_render_cli.cpp.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/options.h"
#include "app/error.h"
#include "support/run_program.h"

namespace {

std::string refusal(const std::vector<std::string>& args) {
    try {
        app::parseRenderOptions(args);
    } catch (const app::Error& e) {
        return e.what();
    }
    return "";
}

TEST(RenderOptions, LodThresholdsBelowTheDefaultImpostorThresholdAreValidWithImpostorsOff) {
    // A > B > 0 is all --lod-thresholds asks; the impostor threshold (default 32 px) matters only with impostors.
    const app::RenderOptions options = app::parseRenderOptions({"--lod-thresholds", "20,10"});
    EXPECT_EQ(options.cull.lodThresholds[0], 20.0f);
    EXPECT_EQ(options.cull.lodThresholds[1], 10.0f);
    EXPECT_EQ(refusal({"--lod-thresholds", "20,10", "--impostors", "off"}), "");
    EXPECT_EQ(refusal({"--impostors", "on", "--lod-thresholds", "20,10", "--impostor-threshold", "5"}), "");
}

TEST(RenderOptions, AnImpostorThresholdNotBelowLodTwoIsRefusedWhenImpostorsAreOnOrItIsGiven) {
    EXPECT_NE(refusal({"--lod-thresholds", "20,10", "--impostors", "on"}).find("not below the LOD 2 threshold of 10"),
              std::string::npos);
    EXPECT_NE(refusal({"--impostor-threshold", "20", "--lod-thresholds", "100,15"}).find("not below"), std::string::npos);
}

TEST(RenderOptions, CrowdRenderDrawsWithLowLodThresholds) {
    const test::ProgramResult r =
        test::runProgram(CROWD_RENDER_BINARY, "--lod-thresholds 20,10 --count 4 --frames 1 --size 64x64 --out /dev/null");
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
