// --frames lists and -o frame patterns.
#include "app/frame_selection.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"

namespace clr {
namespace {

// The message of the UsageError that parsing `text` throws, or "" if it throws none.
std::string usage_error_of(const std::string& text, int frame_count) {
    try {
        parse_frame_list(text, frame_count);
    } catch (const UsageError& error) {
        EXPECT_EQ(error.code(), kExitUsage);
        return error.what();
    }
    return "";
}

TEST(FrameSelection, SingleFrame) { EXPECT_EQ(parse_frame_list("7", 11), std::vector<int>({7})); }

TEST(FrameSelection, InclusiveRange) {
    std::vector<int> all(100);
    for (int i = 0; i < 100; ++i) all[i] = i;
    EXPECT_EQ(parse_frame_list("0-99", 100), all);
    EXPECT_EQ(parse_frame_list("4-4", 5), std::vector<int>({4}));
}

TEST(FrameSelection, ListOfFramesAndRanges) {
    EXPECT_EQ(parse_frame_list("5,7,10-12", 20), std::vector<int>({5, 7, 10, 11, 12}));
}

TEST(FrameSelection, SortsAndRemovesDuplicates) {
    EXPECT_EQ(parse_frame_list("9,2-4,3,0,9", 10), std::vector<int>({0, 2, 3, 4, 9}));
}

TEST(FrameSelection, ToleratesSpacesAroundItems) {
    EXPECT_EQ(parse_frame_list(" 5 , 7,\t10 - 11 ", 20), std::vector<int>({5, 7, 10, 11}));
}

TEST(FrameSelection, RejectsBadSyntax) {
    for (const char* text : {"5-", "-3", "a", "5,,7", "5,", ",5", "1-2-3", "+4", "4.0", "0x10", "7 8"}) {
        const std::string message = usage_error_of(text, 100);
        EXPECT_NE(message.find("--frames"), std::string::npos) << "'" << text << "' gave: " << message;
    }
    EXPECT_NE(usage_error_of("", 10).find("empty"), std::string::npos);
    EXPECT_NE(usage_error_of("  ", 10).find("empty"), std::string::npos);
    EXPECT_NE(usage_error_of("5,,7", 10).find("empty item"), std::string::npos);
    EXPECT_NE(usage_error_of("a", 10).find("'a' is not a frame number"), std::string::npos);
}

TEST(FrameSelection, RejectsBackwardsRanges) {
    EXPECT_NE(usage_error_of("3-1", 10).find("runs backwards (write 1-3)"), std::string::npos);
}

TEST(FrameSelection, RejectsFramesPastTheEnd) {
    EXPECT_EQ(usage_error_of("12", 11), "frame 12 is out of range: the animation has 11 frames (0-10)");
    EXPECT_EQ(usage_error_of("5-11", 11), "frame 11 is out of range: the animation has 11 frames (0-10)");
    EXPECT_EQ(usage_error_of("1", 1), "frame 1 is out of range: the animation has 1 frame (0)");
    // A number too large for an int is reported as out of range, not wrapped around.
    EXPECT_NE(usage_error_of("99999999999999999999", 11).find("out of range"), std::string::npos);
    // ... and named by the bound, not by the saturated number it never typed.
    EXPECT_EQ(usage_error_of("99999999999", 11),
              "a frame past 2147483647 is out of range: the animation has 11 frames (0-10)");
    EXPECT_EQ(usage_error_of("2147483647", 11), "frame 2147483647 is out of range: the animation has 11 frames (0-10)");
    EXPECT_EQ(parse_frame_list("10", 11), std::vector<int>({10}));
}

TEST(FrameSelection, RecognisesFramePatterns) {
    EXPECT_TRUE(is_frame_pattern("frames/out_%04d.png"));
    EXPECT_TRUE(is_frame_pattern("out%d.ppm"));
    EXPECT_TRUE(is_frame_pattern("out_####.png"));
    EXPECT_TRUE(is_frame_pattern("#.png"));
    EXPECT_FALSE(is_frame_pattern("out.png"));
    EXPECT_FALSE(is_frame_pattern("100%.png"));
    EXPECT_FALSE(is_frame_pattern("out_%s.png"));
    EXPECT_FALSE(is_frame_pattern("take#2/out.png"));   // a '#' in a folder is not a placeholder
    EXPECT_FALSE(is_frame_pattern("run%03d/out.png"));  // nor is a '%d' there
}

TEST(FrameSelection, ExpandsFramePatterns) {
    EXPECT_EQ(frame_path("out_%04d.png", 7), "out_0007.png");
    EXPECT_EQ(frame_path("out_%d.png", 7), "out_7.png");
    EXPECT_EQ(frame_path("out_%d.png", 0), "out_0.png");
    EXPECT_EQ(frame_path("out_####.png", 42), "out_0042.png");
    EXPECT_EQ(frame_path("#.png", 3), "3.png");
    EXPECT_EQ(frame_path("out_%2d.png", 5), "out_05.png");  // as ffmpeg reads it: zero-padded
    EXPECT_EQ(frame_path("out_%02d.png", 12345), "out_12345.png");
    EXPECT_EQ(frame_path("take#2/f_###.ppm", 9), "take#2/f_009.ppm");
}

TEST(FrameSelection, ReplacesOnlyTheFirstPlaceholder) {
    EXPECT_EQ(frame_path("a_%03d_%d.png", 4), "a_004_%d.png");
    EXPECT_EQ(frame_path("a_##_%d.png", 4), "a_04_%d.png");
    EXPECT_EQ(frame_path("a_%d_##.png", 4), "a_4_##.png");
}

TEST(FrameSelection, NeverTreatsThePathAsAFormatString) {
    // Conversions other than %d stay as they are; printf would read memory for %s and %n.
    EXPECT_EQ(frame_path("%s%n%x_%d.png", 1), "%s%n%x_1.png");
    EXPECT_EQ(frame_path("100%_%03d.png", 1), "100%_001.png");
}

TEST(FrameSelection, PatternWithoutPlaceholderIsAUsageError) {
    EXPECT_THROW(frame_path("out.png", 1), UsageError);
    EXPECT_THROW(frame_path("run_%03d/out.png", 1), UsageError);
    EXPECT_THROW(frame_path("out_%04d.png", -1), std::invalid_argument);
}

}  // namespace
}  // namespace clr
