// parallel_for: every index runs exactly once, on the caller and the threads asked for, and
// the first failure in index order comes back once all have finished.
#include "core/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace clr {
namespace {

TEST(ParallelFor, EachIndexRunsOnceOnTheCallerAndTheThreadsAskedFor) {
    for (std::size_t threads : {1u, 2u, 4u}) {
        std::vector<std::atomic<int>> runs(1000);
        std::mutex mutex;
        std::set<std::thread::id> ids;
        parallel_for(runs.size(), threads, [&](std::size_t i) {
            ++runs[i];
            std::lock_guard<std::mutex> lock(mutex);
            ids.insert(std::this_thread::get_id());
        });
        for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i].load(), 1) << "index " << i << ", " << threads << " threads";
        EXPECT_LE(ids.size(), threads);
        if (threads == 1) {
            EXPECT_TRUE(ids.count(std::this_thread::get_id())) << "one thread: the caller's";
        }
    }
    parallel_for(0, 4, [](std::size_t) { FAIL() << "no index to run"; });
}

TEST(ParallelFor, TheFirstFailureInIndexOrderComesBackAfterEveryIndexRan) {
    std::atomic<int> ran{0};
    try {
        parallel_for(64, 3, [&](std::size_t i) {
            if (i == 40) std::this_thread::sleep_for(std::chrono::milliseconds(5));  // fails last, in time
            ++ran;
            if (i == 40 || i == 7 || i == 50) throw std::runtime_error("index " + std::to_string(i));
        });
        FAIL() << "no exception came back";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()), "index 7");
    }
    EXPECT_EQ(ran.load(), 64) << "the other indices still ran";
}

}  // namespace
}  // namespace clr
