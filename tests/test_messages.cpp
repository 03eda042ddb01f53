// Messages a person reads: numbers as a person writes them, and a memory shortfall blamed on the flag
// that causes it, with figures that differ.
#include <gtest/gtest.h>

#include "app/memory_shortfall.h"
#include "app/number_text.h"
#include "app/options.h"
#include "app/start_time.h"
#include "app/error.h"

namespace {

std::string parseError(const std::string& flag, const std::string& text, float min, float max) {
    try {
        app::parseNumber(flag, text, min, max);
    } catch (const app::Error& error) {
        return error.what();
    }
    return "";
}

constexpr std::uint64_t kGiB = 1ull << 30;

}  // namespace

TEST(Messages, NumbersAreWrittenAsAPersonWritesThem) {
    EXPECT_EQ(app::formatNumber(0.0f), "0");
    EXPECT_EQ(app::formatNumber(1e6f), "1000000");
    EXPECT_EQ(app::formatNumber(0.5f), "0.5");
    EXPECT_EQ(app::formatNumber(12.25f), "12.25");
    EXPECT_EQ(app::formatNumber(-3.0f), "-3");
}

TEST(Messages, RangesReadAsWrittenInTheHelp) {
    EXPECT_EQ(parseError("--impostor-threshold", "2e6", 0.0f, 1e6f), "--impostor-threshold: 2e6 is outside 0..1000000");
    EXPECT_EQ(parseError("--lod-hysteresis", "0.9", 0.0f, 0.5f), "--lod-hysteresis: 0.9 is outside 0..0.5");
}

TEST(Messages, StartTimesReadAsWrittenInTheHelp) {
    auto startError = [](const std::string& text) {
        try {
            app::parseStartSeconds("--start", text);
        } catch (const app::Error& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_EQ(startError("2e9"), "--start: 2e9 is outside 0..1000000000");
    EXPECT_EQ(startError("-0.5"), "--start: -0.5 is outside 0..1000000000");
    EXPECT_EQ(startError("1e9"), "");
    // A double: the start is kept to the microsecond at a million seconds (a float kept 62.5 ms).
    EXPECT_EQ(app::parseStartSeconds("--start", "1000000.000001"), 1000000.000001);
    EXPECT_EQ(app::formatNumber(1e9), "1000000000");
}

TEST(Messages, AnImageTooLargeForDeviceMemoryIsBlamedOnSize) {
    // The crowd alone would fit; the image makes it overflow by 1 MiB, which "2.0 GiB" against "2.0 GiB" hid.
    const std::string line = app::describeShortfall(
        {1, {16384, 16384}, "two-pass", 2 * kGiB + (1u << 20), 2 * kGiB, 2 * kGiB, "llvmpipe"});
    EXPECT_EQ(line, "--size 16384x16384: the image needs 2.0 GiB of device memory besides the crowd's 1.0 MiB, "
                    "2.001 GiB in all; llvmpipe has 2.000 GiB");
}

TEST(Messages, ACrowdTooLargeForDeviceMemoryIsBlamedOnCount) {
    const std::string line = app::describeShortfall(
        {16777216, {96, 64}, "two-pass", 40 * kGiB, 96 * 64 * 8, 2 * kGiB, "llvmpipe"});
    EXPECT_EQ(line, "--count 16777216: two-pass needs about 40.0 GiB of device memory; llvmpipe has 2.0 GiB");
}
