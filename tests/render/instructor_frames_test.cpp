// The course's example1.js against the instructor's own renders of it
// (../shared/course-scenes/fall2020-a04/reference-output/, MaxDepth 0..5, 1500x1500 JPEG).
// Those frames carry a text label, yellow mirror borders, JPEG noise, and chessboard images
// the course never published, so pixels cannot match; what must match is where the directly
// visible spheres are and how the sun shades them. Each sphere is found in both images by its
// colour, away from the central mirror, and the two masks and their brightness compared.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "scene/image_loader.h"
#include "scene/scene_loader.h"
#include "support/render_helpers.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

const fs::path kFolder = fs::path(CLRENDER_SOURCE_DIR) / ".." / "shared" / "course-scenes" / "fall2020-a04";

enum class Hue { Green, Blue };

// A strongly green or blue pixel, as the two big spheres are (ambient 0.09/0.99/0.09 and
// 0.09/0.09/0.99, lit): the other channels stay well below the dominant one. Only the lit
// side counts: where n.l < 0 the instructor's frames show a flat dim colour (2, 5, 48)
// instead of the black that max(0, n.l) gives (docs/scene-format.md, Conventions: Lighting and shadows), so the dominant channel
// must exceed that floor.
bool has_hue(const Image& image, int col, int row, Hue hue) {
    int r = image.at(col, row, 0), g = image.at(col, row, 1), b = image.at(col, row, 2);
    int main = hue == Hue::Green ? g : b;
    int other = std::max(r, hue == Hue::Green ? b : g);
    return main > 60 && main > 2 * other + 10;
}

// Outside the label (top rows) and the central mirror with its border, whose reflections
// show the spheres again.
bool compared(int col, int row) {
    bool label = row < 120;
    bool central_mirror = col >= 370 && col < 1130 && row >= 370 && row < 1130;
    return !label && !central_mirror;
}

struct MaskComparison {
    long long ours = 0, theirs = 0, both = 0;
    double our_brightness = 0, their_brightness = 0;  // mean dominant channel over `both`
    double iou() const { return double(both) / double(ours + theirs - both); }
};

MaskComparison compare_hue(const Image& ours, const Image& theirs, Hue hue) {
    MaskComparison result;
    int channel = hue == Hue::Green ? 1 : 2;
    for (int row = 0; row < ours.height; ++row)
        for (int col = 0; col < ours.width; ++col) {
            if (!compared(col, row)) continue;
            bool in_ours = has_hue(ours, col, row, hue), in_theirs = has_hue(theirs, col, row, hue);
            result.ours += in_ours;
            result.theirs += in_theirs;
            if (in_ours && in_theirs) {
                ++result.both;
                result.our_brightness += ours.at(col, row, channel);
                result.their_brightness += theirs.at(col, row, channel);
            }
        }
    if (result.both) result.our_brightness /= result.both, result.their_brightness /= result.both;
    return result;
}

TEST(InstructorFrames, SpheresSitAndShadeAsInTheInstructorsRenders) {
    if (!fs::exists(kFolder / "reference-output")) GTEST_SKIP() << "the course's reference frames are not here";
    LoadOptions options;
    options.placeholder_images = true;
    Scene scene = load_scene((kFolder / "scenes" / "example1.js").string(), options);
    ASSERT_EQ(scene.width, 299);
    scene.width = scene.height = 1500;  // the instructor rendered at 1500x1500

    // Outside the central mirror the picture does not depend on MaxDepth; the first and the
    // last of the instructor's frames are compared. (Inside the mirror the frames differ by
    // design: where clrender shows the background once MaxDepth runs out (docs/scene-format.md,
    // Conventions: Mirrors), the instructor's renderer shows a flat grey.)
    for (int depth : {0, 5}) {
        SCOPED_TRACE("MaxDepth " + std::to_string(depth));
        scene.max_depth = depth;
        Image ours = testing::render_with_kernels(scene);
        auto theirs = load_image((kFolder / "reference-output" / ("19-55-22_" + std::to_string(depth) + ".jpg")).string());
        ASSERT_EQ(theirs->width, 1500);
        for (Hue hue : {Hue::Green, Hue::Blue}) {
            MaskComparison mask = compare_hue(ours, *theirs, hue);
            const char* name = hue == Hue::Green ? "green sphere" : "blue sphere";
            EXPECT_GT(mask.ours, 20000) << name;
            EXPECT_GT(mask.iou(), 0.95) << name << ": ours " << mask.ours << " px, theirs " << mask.theirs << ", both " << mask.both;
            EXPECT_NEAR(mask.our_brightness, mask.their_brightness, 6) << name << " mean brightness";
            std::cout << "MaxDepth " << depth << ", " << name << ": IoU " << mask.iou() << ", mean brightness "
                      << mask.our_brightness << " (instructor " << mask.their_brightness << ")\n";
        }
    }
}

}  // namespace
}  // namespace clr
