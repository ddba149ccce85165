// Numbers in messages (scene/value_ranges.h, number_text): the fewest digits that read back
// as the same double, as a person writes them.
#include <gtest/gtest.h>

#include "scene/value_ranges.h"

namespace clr {
namespace {

TEST(NumberText, ShortestFormAsAPersonWritesIt) {
    EXPECT_EQ(number_text(2.5), "2.5");
    EXPECT_EQ(number_text(1e15), "1e15");
    EXPECT_EQ(number_text(-1e15), "-1e15");
    EXPECT_EQ(number_text(2e6), "2e6");
    EXPECT_EQ(number_text(1e-5), "1e-5");
    EXPECT_EQ(number_text(1e300), "1e300");
    EXPECT_EQ(number_text(0.1), "0.1");
    // Whole numbers stay written out where that is no longer than the exponent form.
    EXPECT_EQ(number_text(30), "30");
    EXPECT_EQ(number_text(-30), "-30");
    EXPECT_EQ(number_text(100), "100");
    EXPECT_EQ(number_text(123456), "123456");
    EXPECT_EQ(number_text(0), "0");
}

}  // namespace
}  // namespace clr
