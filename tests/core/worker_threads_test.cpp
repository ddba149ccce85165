// WorkerThreads: every run() calls its task on the caller and the helpers asked for, and
// returns only when all of them have returned; runs one after another reuse the threads.
#include "core/worker_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>

namespace clr {
namespace {

TEST(WorkerThreads, ATaskRunsOnTheCallerAndEachHelperAndAllFinishBeforeRunReturns) {
    WorkerThreads& threads = WorkerThreads::shared();
    threads.start(3);
    for (int round = 0; round < 200; ++round) {
        std::atomic<int> calls{0}, finished{0};
        std::mutex mutex;
        std::set<std::thread::id> ids;
        threads.run(3, [&] {
            ++calls;
            {
                std::lock_guard<std::mutex> lock(mutex);
                ids.insert(std::this_thread::get_id());
            }
            if (round % 50 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
            ++finished;
        });
        ASSERT_EQ(calls.load(), 4) << "round " << round;
        ASSERT_EQ(finished.load(), 4) << "round " << round;
        ASSERT_EQ(ids.size(), 4u) << "round " << round;
        ASSERT_TRUE(ids.count(std::this_thread::get_id()));
    }
}

TEST(WorkerThreads, FewerHelpersThanStartedTakeFewerThreads) {
    WorkerThreads& threads = WorkerThreads::shared();
    threads.start(3);
    std::atomic<int> calls{0};
    threads.run(1, [&] { ++calls; });
    EXPECT_EQ(calls.load(), 2);
    calls = 0;
    threads.run(0, [&] { ++calls; });
    EXPECT_EQ(calls.load(), 1);
}

TEST(WorkerThreads, NoMoreThanTheCapOfThreadsIsEverStarted) {
    std::atomic<std::size_t> calls{0};
    WorkerThreads::shared().run(static_cast<std::size_t>(-1), [&] { ++calls; });
    EXPECT_GE(calls.load(), 2u);
    EXPECT_LE(calls.load(), WorkerThreads::kMostThreads + 1);
}

TEST(WorkerThreads, ARunFromInsideATaskRunsItsTaskOnItsOwnThreadOnly) {
    std::atomic<int> inner{0};
    WorkerThreads::shared().run(0, [&] { WorkerThreads::shared().run(2, [&] { ++inner; }); });
    EXPECT_EQ(inner.load(), 1);
}

}  // namespace
}  // namespace clr
