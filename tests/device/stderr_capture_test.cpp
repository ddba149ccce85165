// What a library writes straight to file descriptor 2 (PoCL's compiler does) is held back
// while captured, and handed over afterwards.
#include "device/stderr_capture.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <string>

namespace clr {
namespace {

TEST(StderrCapture, HoldsBackWhatIsWrittenToDescriptorTwo) {
    ::testing::internal::CaptureStderr();  // what reaches the real stderr after the capture
    std::string held;
    {
        StderrCapture capture;
        const std::string text = "2 errors generated.\n";
        ASSERT_EQ(::write(STDERR_FILENO, text.data(), text.size()), static_cast<ssize_t>(text.size()));
        held = capture.finish();
    }
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(held, "2 errors generated.\n");
    EXPECT_EQ(printed, "");
}

TEST(StderrCapture, StderrWorksAgainAfterwards) {
    { StderrCapture capture; }
    ::testing::internal::CaptureStderr();
    ASSERT_EQ(::write(STDERR_FILENO, "after\n", 6), 6);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "after\n");
}

}  // namespace
}  // namespace clr
