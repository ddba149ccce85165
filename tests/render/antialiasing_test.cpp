// Anti-aliasing: several samples per pixel at the positions of kernels/shared/clr_samples.h,
// the same in the kernels (scalar and 16-lane paths) and in the reference.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/clr_samples.h"
#include "support/image_compare.h"
#include "support/random_scene.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// Distance between two points of the unit square taken as a torus (the pattern wraps).
double toroidal_distance(double ax, double ay, double bx, double by) {
    double dx = std::fabs(ax - bx), dy = std::fabs(ay - by);
    dx = std::min(dx, 1 - dx);
    dy = std::min(dy, 1 - dy);
    return std::sqrt(dx * dx + dy * dy);
}

TEST(SamplePattern, OneSampleIsThePixelCentre) {
    EXPECT_EQ(clr_sample_offset_x(123, 4, 5, 0, 1), 0.5f);
    EXPECT_EQ(clr_sample_offset_y(123, 4, 5, 0, 1), 0.5f);
}

// Stratified in x and in y (every column and row of an n x n grid laid from the pixel's
// random shift holds one sample), and no two samples close together in 2D.
TEST(SamplePattern, SamplesAreStratifiedAndWellSpread) {
    for (int samples : {2, 4, 5, 16, 64, 100}) {
        for (int pixel = 0; pixel < 20; ++pixel) {
            std::vector<std::pair<double, double>> points;
            std::vector<int> columns(samples, 0), rows(samples, 0);
            float shift_x = clr_pixel_rotation(7, pixel, 3 * pixel, 0), shift_y = clr_pixel_rotation(7, pixel, 3 * pixel, 1);
            for (int s = 0; s < samples; ++s) {
                double x = clr_sample_offset_x(7, pixel, 3 * pixel, s, samples);
                double y = clr_sample_offset_y(7, pixel, 3 * pixel, s, samples);
                ASSERT_TRUE(x >= 0 && x < 1 && y >= 0 && y < 1) << x << ", " << y;
                points.emplace_back(x, y);
                // Undo the shift (mod 1) to find the grid cell; the half-cell offset keeps
                // float rounding away from cell borders.
                ++columns[static_cast<int>(std::floor(std::fmod(x - shift_x + 1, 1.0) * samples)) % samples];
                ++rows[static_cast<int>(std::floor(std::fmod(y - shift_y + 1, 1.0) * samples)) % samples];
            }
            for (int i = 0; i < samples; ++i) {
                EXPECT_EQ(columns[i], 1) << samples << " samples, pixel " << pixel << ", column " << i;
                EXPECT_EQ(rows[i], 1) << samples << " samples, pixel " << pixel << ", row " << i;
            }
            double closest = 1;
            for (std::size_t i = 0; i < points.size(); ++i)
                for (std::size_t j = i + 1; j < points.size(); ++j)
                    closest = std::min(closest, toroidal_distance(points[i].first, points[i].second, points[j].first,
                                                                  points[j].second));
            // A random pattern would put some pairs almost on top of each other.
            EXPECT_GT(closest, 0.4 / std::sqrt(samples)) << samples << " samples, pixel " << pixel;
        }
    }
}

TEST(SamplePattern, DependsOnSeedFrameAndPixelOnly) {
    unsigned a = clr_frame_seed(1, 0), b = clr_frame_seed(1, 1), c = clr_frame_seed(2, 0);
    EXPECT_NE(a, b);
    EXPECT_NE(a, c);
    EXPECT_EQ(clr_frame_seed(1, 0), a);
    EXPECT_NE(clr_sample_offset_x(a, 0, 0, 1, 4), clr_sample_offset_x(b, 0, 0, 1, 4));
    EXPECT_NE(clr_sample_offset_x(a, 0, 0, 1, 4), clr_sample_offset_x(a, 1, 0, 1, 4));
}

// A white billboard on black whose left edge lies 30% of the way into pixel column 5: the
// column's pixels must show about 30% of white with 16 samples, and 0 or 255 with one.
TEST(Antialiasing, PartlyCoveredPixelsShowTheirCoverage) {
    const double D = 5;  // fov 90 at distance D: the plane z = 0 spans [-D, D] over 10 pixels
    auto scene_with = [&](int samples) {
        Scene scene = testing::make_scene({0, 0, D}, {0, 0, 0}, {0, 1, 0}, 90, 10, 10);
        double pixel = 2 * D / 10;
        double edge = -D + 5.7 * pixel;  // 30% of column 5 (x from 5.7 to 6) is white
        scene.billboards.push_back(testing::make_billboard({edge, 9, 0}, {edge, -9, 0}, {9, 9, 0}, {1, 1, 1}));
        scene.sampling.samples_per_pixel = samples;
        return scene;
    };
    Image one = testing::render_with_kernels(scene_with(1));
    Image sixteen = testing::render_with_kernels(scene_with(16));
    for (int row = 0; row < 10; ++row) {
        EXPECT_EQ(one.at(5, row, 0), 0) << "the centre of column 5 is not covered";
        EXPECT_EQ(one.at(6, row, 0), 255);
        EXPECT_NEAR(sixteen.at(5, row, 0), 0.3 * 255, 0.1 * 255) << "row " << row;
        EXPECT_EQ(sixteen.at(4, row, 0), 0);
        EXPECT_EQ(sixteen.at(6, row, 0), 255);
    }
}

Scene textured_random_scene(std::uint32_t seed, int samples) {
    Scene scene = testing::make_random_scene(seed, 10, 10);
    scene.camera_path = {{{4, 6, 32}, {0, 0, 0}}};
    scene.width = 83;
    scene.height = 50;
    scene.has_sun = true;
    scene.sun_location = {20, 30, 25};
    scene.spheres[1].is_mirror = true;
    scene.sampling.samples_per_pixel = samples;
    scene.sampling.seed = seed;
    return scene;
}

TEST(Antialiasing, PacketPathEqualsBruteForceAndReference) {
    for (int samples : {4, 7}) {
        SCOPED_TRACE(std::to_string(samples) + " samples");
        Scene scene = textured_random_scene(300 + samples, samples);
        RendererOptions brute_force;
        brute_force.screen_tiles = false;
        Image packets = testing::render_with_kernels(scene);
        EXPECT_TRUE(packets.rgba == testing::render_with_kernels(scene, brute_force).rgba);
        testing::ImageComparison comparison = testing::compare_images(packets, testing::render_with_reference(scene));
        EXPECT_LE(comparison.differing_fraction(), 0.001) << comparison.differing << " pixels differ";
        EXPECT_EQ(comparison.differing_off_edge, 0) << comparison.first_off_edge;
    }
}

TEST(Antialiasing, SameSeedAndFrameGiveTheSameBytes) {
    Scene scene = textured_random_scene(310, 5);
    Image first = testing::render_with_kernels(scene);
    EXPECT_TRUE(first.rgba == testing::render_with_kernels(scene).rgba);
    scene.sampling.seed = 311;
    EXPECT_FALSE(first.rgba == testing::render_with_kernels(scene).rgba) << "another seed moves the samples";
}

}  // namespace
}  // namespace clr
