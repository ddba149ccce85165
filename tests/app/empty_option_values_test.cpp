// An option given an empty value ('', e.g. from an unset shell variable) is a usage error:
// read as "not given", an empty --frames rendered every frame of an animation.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/options.h"

namespace clr {
namespace {

ParsedOptions parse(std::vector<const char*> arguments) {
    arguments.insert(arguments.begin(), "clrender");
    return parse_options(static_cast<int>(arguments.size()), arguments.data());
}

TEST(EmptyOptionValues, AreUsageErrors) {
    for (const char* option : {"--frames", "-o", "--output", "--video", "--stats", "--kernel-dir", "-d", "--device", "--size"}) {
        ::testing::internal::CaptureStderr();
        const ParsedOptions parsed = parse({"scene.json", option, ""});
        const std::string printed = ::testing::internal::GetCapturedStderr();
        EXPECT_EQ(parsed.exit_code, 1) << option;
        EXPECT_NE(printed.find("the value is empty"), std::string::npos) << option << ": " << printed;
    }
}

TEST(EmptyOptionValues, EmptySceneNameIsAUsageError) {
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(parse({""}).exit_code, 1);
    EXPECT_NE(::testing::internal::GetCapturedStderr().find("the scene file name is empty"), std::string::npos);
}

TEST(EmptyOptionValues, GivenValuesAndLeftOutOptionsStillWork) {
    const ParsedOptions parsed = parse({"scene.json", "--frames", "3", "-o", "f_%04d.png"});
    EXPECT_FALSE(parsed.exit_code.has_value());
    EXPECT_EQ(parsed.options.frames, "3");
    EXPECT_TRUE(parse({"scene.json"}).options.frames.empty());
}

}  // namespace
}  // namespace clr
