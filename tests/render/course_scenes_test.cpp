// Every course scene whose images exist (../shared/course-scenes, when present), rendered by
// the kernels and by the reference: at least 99.9% of pixels agree, and the rest lie on
// edges of the reference image (silhouettes, billboard borders, texel edges).
#include <gtest/gtest.h>

#include <filesystem>

#include "scene/scene_loader.h"
#include "support/image_compare.h"
#include "support/render_helpers.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

const fs::path kCourseScenes = fs::path(CLRENDER_SOURCE_DIR) / ".." / "shared" / "course-scenes";

struct CourseScene {
    const char* path;   // relative to course-scenes/
    bool placeholders;  // the course never published some of its images
    int size;           // square size override, 0: the scene's own
};

const CourseScene kScenes[] = {
    {"spring2023-a03/testScene_grads.json", false, 0},
    {"spring2023-a03/testSceneUndergrad.json", false, 0},
    {"spring2023-a03/testScene.v1_e038c70_2022-02-20.json", false, 0},
    {"spring2023-a03/testScene.v2_c4c2221_2022-02-20.json", false, 0},
    {"fall2020-a04/scenes/example1.js", true, 0},
    {"fall2020-a04/scenes/example2.js", true, 0},
    {"fall2020-a04/scenes/metal_mickey.js", true, 0},
    {"spring2025-hw2/testSceneSingleBB.js", true, 0},
    {"spring2025-hw2/testSceneSingleSphere_and_BB.js", true, 0},
    {"spring2025-hw2/testSceneSingleSphere_and_BB_close.js", true, 0},
    {"spring2025-hw2/MyTestSceneSingleLightTweakedForDebug.js", true, 0},
    {"spring2025-a03-webgl/scene1.js", true, 200},
};

class CourseSceneTest : public ::testing::TestWithParam<CourseScene> {};

TEST_P(CourseSceneTest, KernelsAgreeWithReference) {
    const CourseScene& course = GetParam();
    fs::path path = kCourseScenes / course.path;
    if (!fs::exists(path)) GTEST_SKIP() << path << " is not here";
    LoadOptions options;
    options.placeholder_images = course.placeholders;
    if (course.size) options.width_override = options.height_override = course.size;
    Scene scene = load_scene(path.string(), options);

    testing::ImageComparison comparison =
        testing::compare_images(testing::render_with_kernels(scene), testing::render_with_reference(scene));
    EXPECT_LE(comparison.differing_fraction(), 0.001)
        << comparison.differing << " of " << comparison.pixels << " pixels differ";
    EXPECT_EQ(comparison.differing_off_edge, 0) << "first off an edge: " << comparison.first_off_edge;
}

INSTANTIATE_TEST_SUITE_P(Course, CourseSceneTest, ::testing::ValuesIn(kScenes), [](const auto& info) {
    std::string name = fs::path(info.param.path).stem().string();
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name + "_" + std::to_string(info.index);
});

}  // namespace
}  // namespace clr
