#include "app/progress.h"

#include <gtest/gtest.h>

namespace clr {
namespace {

TEST(Progress, DurationsReadAsMinutesAndHours) {
    EXPECT_EQ(format_duration(0), "0:00");
    EXPECT_EQ(format_duration(59.4), "0:59");
    EXPECT_EQ(format_duration(65), "1:05");
    EXPECT_EQ(format_duration(3600), "1:00:00");
    EXPECT_EQ(format_duration(12 * 3600 + 3 * 60 + 7), "12:03:07");
    EXPECT_EQ(format_duration(-3), "0:00");
}

}  // namespace
}  // namespace clr
