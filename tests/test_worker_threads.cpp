// The CPU threads the library shares its work over (crowdgpu::setWorkerThreads, the C API's
// crowdgpu_set_worker_threads, the programs' --threads): a host can set them, and nothing but the
// threads changes. Nothing here asserts a time.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "crowdgpu/crowd.hpp"
#include "crowdgpu/crowdgpu.h"
#include "crowdgpu/error.hpp"
#include "crowdgpu/model.hpp"
#include "support/csv_file.h"
#include "support/run_program.h"

namespace {

// Resets the threads to the default when a test ends, however it ends.
struct DefaultThreadsAfter {
    ~DefaultThreadsAfter() { crowdgpu::setWorkerThreads(0); }
};

// Every character's state every 2 s over 20 s of a milling crowd advanced at 60 Hz, and the palettes of
// its last frame, as bytes. 100,000 characters: a few hundred are due a frame, enough for the planning,
// the calendar's and the restating loops to be split into chunks (smaller calls run on the caller alone).
std::vector<unsigned char> milledCrowd(const crowdgpu::Model& soldier) {
    crowdgpu::GridLayout layout;
    layout.count = 100000;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, crowdgpu::Behaviour::Mill);
    std::vector<unsigned char> bytes;
    auto append = [&](const void* data, std::size_t size) {
        const auto* first = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), first, first + size);
    };
    for (int frame = 0; frame <= 1200; ++frame) {
        const double time = frame / 60.0;
        crowd.advanceTo(time);
        if (frame % 120 != 0) continue;
        for (std::uint32_t c = 0; c < crowd.size(); ++c) {
            const crowdgpu::CharacterState state = crowd.stateAt(c, time);
            append(&state, sizeof state);
        }
    }
    std::vector<float> rows;
    crowd.computePalettes(20.0, rows, true);
    append(rows.data(), rows.size() * sizeof(float));
    return bytes;
}

}  // namespace

TEST(WorkerThreads, AHostSetsThemAndTheCrowdDoesNotChange) {
    DefaultThreadsAfter reset;
    const crowdgpu::Model soldier = crowdgpu::Model::soldier();
    crowdgpu::setWorkerThreads(1);
    EXPECT_EQ(crowdgpu::workerThreads(), 1u);
    const std::vector<unsigned char> alone = milledCrowd(soldier);
    crowdgpu::setWorkerThreads(5);  // more than this machine's cores: workers wake late and share the work
    EXPECT_EQ(crowdgpu::workerThreads(), 5u);
    const std::vector<unsigned char> shared = milledCrowd(soldier);
    ASSERT_EQ(alone.size(), shared.size());
    EXPECT_EQ(std::memcmp(alone.data(), shared.data(), alone.size()), 0)
        << "a milling crowd planned on one thread and on five differs";
    crowdgpu::setWorkerThreads(0);
    EXPECT_GE(crowdgpu::workerThreads(), 1u);  // one per core
}

TEST(WorkerThreads, MoreThan1024AreRefusedAndChangeNothing) {
    DefaultThreadsAfter reset;
    crowdgpu::setWorkerThreads(3);
    try {
        crowdgpu::setWorkerThreads(1025);
        FAIL() << "1025 worker threads accepted";
    } catch (const crowdgpu::Error& error) {
        EXPECT_EQ(error.code(), crowdgpu::ErrorCode::InvalidArgument);
        EXPECT_EQ(std::string(error.what()), "worker threads: 1025 is over 1024");
    }
    EXPECT_EQ(crowdgpu::workerThreads(), 3u);
    EXPECT_EQ(crowdgpu_set_worker_threads(4000), CROWDGPU_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(std::string(crowdgpu_last_error()), "worker threads: 4000 is over 1024");
    EXPECT_EQ(crowdgpu_worker_threads(), 3u);
    EXPECT_EQ(crowdgpu_set_worker_threads(2), CROWDGPU_OK);
    EXPECT_EQ(crowdgpu_worker_threads(), 2u);
}

TEST(WorkerThreads, TheProgramsTakeThemFromTheCommandLine) {
    // crowd-bench --palette reports the threads its every-core palettes shared.
    const std::string csv = (std::filesystem::temp_directory_path() /
                             ("crowd-worker-threads-" + std::to_string(::getpid()) + ".csv")).string();
    const test::ProgramResult bench = test::runProgram(
        CROWD_BENCH_BINARY, "--palette --threads 3 --counts 64 --frames 1 --warmup 0 --csv " + csv, "", 300);
    ASSERT_EQ(bench.exitCode, 0) << bench.err;
    const std::vector<std::string> rows = test::readLines(csv);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(test::csvField(rows, 1, "cpu_threads"), "3") << rows[1];
    std::filesystem::remove(csv);
    for (const char* program : {CROWD_RENDER_BINARY, CROWD_BENCH_BINARY})
        for (const char* value : {"1025", "x", "-1"}) {
            const test::ProgramResult bad = test::runProgram(program, std::string("--threads ") + value);
            EXPECT_EQ(bad.exitCode, 1) << program << " --threads " << value;
            EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
            EXPECT_NE(bad.err.find("--threads"), std::string::npos) << bad.err;
        }
}
