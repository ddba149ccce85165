// A stop that cannot wait for the orderly one (the watchdog after a signal, a crash in the
// driver) kills the process groups of the helper programs still running, so that none of them
// (nor what they started) outlives clrender (core/interruption.h).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <optional>
#include <thread>

#include "core/interruption.h"
#include "output/child_process.h"

namespace clr {
namespace {

// The child's wait status once it has exited, waiting at most five seconds.
std::optional<int> exit_within_seconds(ChildProcess& child) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < give_up) {
        if (std::optional<int> status = child.poll_exit()) return status;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return std::nullopt;
}

TEST(ForcedStop, KillsTheProcessGroupsOfRunningHelpers) {
    // A helper that would run for minutes, and a process it started in its group.
    ChildProcess helper({"/bin/sh", "-c", "sleep 300 & sleep 300; wait"}, -1, -1, -1);
    ChildProcess other({"/bin/sleep", "300"}, -1, -1, -1);
    kill_child_groups();
    for (ChildProcess* child : {&helper, &other}) {
        const std::optional<int> status = exit_within_seconds(*child);
        ASSERT_TRUE(status.has_value()) << "a helper outlived the forced stop";
        EXPECT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == SIGKILL) << *status;
    }
}

TEST(ForcedStop, AFinishedHelperIsNoLongerKilled) {
    ChildProcess finished({"/bin/true"}, -1, -1, -1);
    ASSERT_TRUE(exit_within_seconds(finished).has_value());  // reaped: its group is forgotten
    ChildProcess running({"/bin/sleep", "300"}, -1, -1, -1);
    kill_child_groups();  // reaches the running one; the finished one's id may belong to anyone now
    const std::optional<int> status = exit_within_seconds(running);
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == SIGKILL);
}

}  // namespace
}  // namespace clr
