// The worker pool visits every index exactly once, for any count and chunk size, many times over.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "crowd/worker_pool.h"

TEST(WorkerPool, VisitsEveryIndexExactlyOnce) {
    crowd::WorkerPool pool(4);
    for (std::uint32_t count : {0u, 1u, 7u, 32u, 33u, 1000u, 4097u})
        for (std::uint32_t chunk : {1u, 5u, 32u, 5000u}) {
            std::vector<std::atomic<int>> visits(count);
            pool.parallelFor(count, chunk, [&](std::uint32_t begin, std::uint32_t end) {
                for (std::uint32_t i = begin; i < end; ++i) visits[i]++;
            });
            for (std::uint32_t i = 0; i < count; ++i) ASSERT_EQ(visits[i].load(), 1) << count << "/" << chunk << " @" << i;
        }
}

TEST(WorkerPool, RunsRepeatedlyWithoutLosingWork) {
    crowd::WorkerPool pool(3);
    std::atomic<std::uint64_t> sum{0};
    for (int round = 0; round < 500; ++round)
        pool.parallelFor(100, 7, [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t i = begin; i < end; ++i) sum += i;
        });
    EXPECT_EQ(sum.load(), 500u * 4950u);
}

TEST(WorkerPool, CallersOnSeveralThreadsEachGetAllTheirWork) {
    // Two crowds advanced on two host threads share WorkerPool::shared(): each call must see every one
    // of its own indices, and none of the other's.
    crowd::WorkerPool pool(3);
    auto caller = [&](std::uint64_t& sum) {
        for (int round = 0; round < 300; ++round) {
            std::atomic<std::uint64_t> local{0};
            pool.parallelFor(1000, 16, [&](std::uint32_t begin, std::uint32_t end) {
                for (std::uint32_t i = begin; i < end; ++i) local += i;
            });
            sum += local.load();
        }
    };
    std::uint64_t first = 0, second = 0;
    std::thread other(caller, std::ref(second));
    caller(first);
    other.join();
    EXPECT_EQ(first, 300u * 499500u);
    EXPECT_EQ(second, 300u * 499500u);
}

TEST(WorkerPool, WorkersThatWakeLateNeitherLoseNorRepeatWork) {
    // Many more workers than cores: most wake after the caller and the first ones have taken every chunk
    // (they skip the closed call, or join the next one). Each call still visits each index once, and
    // returns with none of its work running.
    crowd::WorkerPool pool(std::max(16u, 8 * std::thread::hardware_concurrency()));
    for (int round = 0; round < 2000; ++round) {
        const std::uint32_t count = 1 + static_cast<std::uint32_t>(round % 97) * 13;
        std::vector<std::atomic<int>> visits(count);
        std::atomic<int> running{0};
        pool.parallelFor(count, 1 + round % 5, [&](std::uint32_t begin, std::uint32_t end) {
            ++running;
            for (std::uint32_t i = begin; i < end; ++i) visits[i]++;
            --running;
        });
        ASSERT_EQ(running.load(), 0) << "round " << round;
        for (std::uint32_t i = 0; i < count; ++i) ASSERT_EQ(visits[i].load(), 1) << "round " << round << " @" << i;
    }
}
