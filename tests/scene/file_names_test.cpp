// scene/file_names.h: a scene's file names relative to its folder, "." steps dropped, a name
// with ".." kept as written for the system to resolve.
#include "scene/file_names.h"

#include <gtest/gtest.h>

namespace clr {
namespace {

TEST(FileNames, DotStepsAreDroppedAndDotDotIsLeftToTheSystem) {
    EXPECT_EQ(path_in_folder("/s/scenes", "a.png"), "/s/scenes/a.png");
    EXPECT_EQ(path_in_folder("/s/scenes", "./img/./a.png"), "/s/scenes/img/a.png");
    EXPECT_EQ(path_in_folder("/s/scenes", "/abs/./a.png"), "/abs/a.png");
    EXPECT_EQ(path_in_folder("/s/scenes", "link/../a.png"), "/s/scenes/link/../a.png");
    EXPECT_EQ(path_in_folder("/s/./scenes", "../a.png"), "/s/./scenes/../a.png") << "as written, whole";
    EXPECT_EQ(path_in_folder("", "a.png"), "a.png") << "a scene in the working folder";
}

}  // namespace
}  // namespace clr
