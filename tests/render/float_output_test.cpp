// The kernels' float output mode (FeatureSet::float_output; docs/command-line.md, HDR and alpha
// outputs): each pixel's linear, unclamped mean colour and its coverage. The display bytes of
// those floats are exactly the bytes the default kernels write, and the floats and coverage
// are the double reference's within float rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "reference/reference.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// A scene of flat spheres and a billboard, on a background that shows around them; each
// option adds what the float mode must follow: texture holes, sun, mirrors, samples.
struct SceneParts {
    bool holes = false;
    bool sun = false;
    bool mirrors = false;
    int samples = 1;
};

Scene test_scene(const SceneParts& parts) {
    Scene scene = testing::make_scene({1, 2, 12}, {0, 0, 0}, {0, 1, 0}, 50, 96, 72);
    scene.background = {0.2, 0.3, 0.5};
    // A colour above 1: the linear values keep it, the display bytes clamp it.
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 2, {2.5, 0.4, 0.1}));
    scene.spheres.push_back(testing::make_sphere({-3, 1.5, -1}, 1, {0.3, 0.9, 0.4}));
    std::shared_ptr<Image> texture;
    if (parts.holes) {
        texture = testing::make_image(8, 8, [](int col, int row) {
            bool hole = (col + row) % 3 == 0;
            return std::array<std::uint8_t, 4>{std::uint8_t(30 * col), std::uint8_t(30 * row), 200,
                                               std::uint8_t(hole ? 0 : 255)};
        });
    }
    scene.billboards.push_back(testing::make_billboard({1, 3, -3}, {1, -2, -3}, {5, 3, -3}, {0.9, 0.8, 0.1}, texture));
    if (parts.sun) {
        scene.has_sun = true;
        scene.sun_location = {-20, 30, 20};
    }
    if (parts.mirrors) {
        scene.max_depth = 3;
        scene.spheres.push_back(testing::make_sphere({3, -2, 1}, 1.2, {0, 0, 0}, true));
    }
    scene.sampling.samples_per_pixel = parts.samples;
    return scene;
}

// The display byte written independently of the renderer: round half up of clamp(c) * 255,
// in float as the kernels compute it.
std::uint8_t expected_byte(float c) {
    const volatile float scaled = std::clamp(c, 0.0f, 1.0f) * 255.0f;
    return static_cast<std::uint8_t>(std::floor(scaled + 0.5f));
}

RendererOptions float_mode(bool screen_tiles) {
    RendererOptions options;
    options.float_output = true;
    options.screen_tiles = screen_tiles;
    return options;
}

void expect_floats_give_the_default_bytes(const Scene& scene, bool screen_tiles) {
    RendererOptions bytes_mode;
    bytes_mode.screen_tiles = screen_tiles;
    const Image bytes = testing::render_with_kernels(scene, bytes_mode);
    const Image floats = testing::render_with_kernels(scene, float_mode(screen_tiles));
    ASSERT_EQ(floats.linear.size(), bytes.rgba.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < bytes.rgba.size(); ++i) {
        const std::uint8_t expected = i % 4 == 3 ? 255 : expected_byte(floats.linear[i]);
        if (bytes.rgba[i] != expected && ++mismatches <= 3)
            ADD_FAILURE() << "value " << i << ": default kernel " << int(bytes.rgba[i]) << ", float mode "
                          << floats.linear[i] << " -> " << int(expected);
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_TRUE(floats.rgba == bytes.rgba) << "the float mode's own display bytes differ";
}

// Coverage equal to the reference's wherever the reference's coverage does not change within
// the pixel's 8 neighbours (off silhouettes), colours within float rounding there.
void expect_matches_reference(const Scene& scene, bool screen_tiles) {
    const Image kernel = testing::render_with_kernels(scene, float_mode(screen_tiles));
    const Image reference = reference::render_linear(scene, reference::camera_of(scene, scene.camera_path.front()));
    ASSERT_EQ(kernel.linear.size(), reference.linear.size());
    const int w = scene.width, h = scene.height;
    auto value = [&](const Image& image, int col, int row, int c) {
        return image.linear[(static_cast<std::size_t>(row) * w + col) * 4 + c];
    };
    int compared = 0, partial = 0, above_one = 0, bad = 0;
    for (int row = 1; row + 1 < h; ++row) {
        for (int col = 1; col + 1 < w; ++col) {
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    interior &= value(reference, col + dx, row + dy, 3) == value(reference, col, row, 3) &&
                                value(reference, col + dx, row + dy, 0) == value(reference, col, row, 0);
            float coverage = value(reference, col, row, 3);
            partial += coverage > 0 && coverage < 1;
            above_one += value(reference, col, row, 0) > 1;
            if (!interior) continue;
            ++compared;
            bool same = value(kernel, col, row, 3) == coverage;
            for (int c = 0; c < 3; ++c) {
                float r = value(reference, col, row, c);
                same &= std::fabs(value(kernel, col, row, c) - r) <= 1e-4f * std::max(1.0f, std::fabs(r));
            }
            if (!same && ++bad <= 3)
                ADD_FAILURE() << "(" << col << ", " << row << "): kernel " << value(kernel, col, row, 0) << ","
                              << value(kernel, col, row, 1) << "," << value(kernel, col, row, 2) << " a "
                              << value(kernel, col, row, 3) << ", reference " << value(reference, col, row, 0)
                              << "," << value(reference, col, row, 1) << "," << value(reference, col, row, 2)
                              << " a " << coverage;
        }
    }
    EXPECT_EQ(bad, 0);
    EXPECT_GT(compared, w * h / 2) << "too few pixels off the edges to compare";
    EXPECT_GT(above_one, 0) << "the scene must show a colour above 1 (unclamped)";
    if (scene.sampling.samples_per_pixel > 1) {
        EXPECT_GT(partial, 0) << "no partly covered pixel at the edges";
    }
}

struct NamedParts {
    const char* name;
    SceneParts parts;
};

const NamedParts kScenes[] = {
    {"spheres", {}},
    {"texture holes", {true, false, false, 1}},
    {"sun", {false, true, false, 1}},
    {"mirrors", {false, true, true, 1}},
    {"spp 4", {true, true, true, 4}},
};

TEST(FloatOutput, DisplayBytesOfTheFloatsAreTheDefaultKernelsBytes) {
    for (const NamedParts& scene : kScenes) {
        SCOPED_TRACE(scene.name);
        expect_floats_give_the_default_bytes(test_scene(scene.parts), true);
        expect_floats_give_the_default_bytes(test_scene(scene.parts), false);
    }
}

TEST(FloatOutput, LinearColoursAndCoverageMatchTheReference) {
    for (const NamedParts& scene : kScenes) {
        SCOPED_TRACE(scene.name);
        expect_matches_reference(test_scene(scene.parts), true);
        expect_matches_reference(test_scene(scene.parts), false);
    }
}

TEST(FloatOutput, CoverageCountsSamplesThatHitAnObject) {
    // Reference coverage against geometry: the centre is on the big sphere, a corner sees
    // only background, a texture hole lets the background through (coverage 0 there).
    Scene scene = test_scene({true, false, false, 4});
    const Image kernel = testing::render_with_kernels(scene, float_mode(true));
    auto coverage = [&](int col, int row) { return kernel.linear[(static_cast<std::size_t>(row) * 96 + col) * 4 + 3]; };
    EXPECT_EQ(coverage(48, 36), 1.0f);
    EXPECT_EQ(coverage(0, 0), 0.0f);
    EXPECT_EQ(coverage(95, 71), 0.0f);
}

TEST(FloatOutput, DefaultModeFillsNoLinearColours) {
    EXPECT_TRUE(testing::render_with_kernels(test_scene({})).linear.empty());
}

}  // namespace
}  // namespace clr
