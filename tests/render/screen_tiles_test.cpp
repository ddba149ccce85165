// Screen tiles of objects that reach behind the eye plane: they are listed only in the tiles
// that their part inside the view frustum can cover (host/render/frustum_clip.h), not in every
// tile, and the tiled kernel still gives the brute-force kernel's image.
#include "render/screen_tiles.h"

#include <gtest/gtest.h>

#include <sched.h>

#include <cmath>
#include <random>
#include <set>

#include "render/frame_camera.h"
#include "render/frame_geometry.h"
#include "render/frustum_clip.h"
#include "render/renderer.h"
#include "render/scene_item.h"
#include "support/opencl_test_device.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The tile columns whose lists hold `item`.
std::set<int> tile_columns_listing(const ScreenTiles& tiles, std::uint32_t item) {
    std::set<int> columns;
    for (int t = 0; t < tiles.tiles_x * tiles.tiles_y; ++t)
        for (std::uint32_t k = tiles.offsets[t]; k < tiles.offsets[t + 1]; ++k)
            if (tiles.items[k] == item) columns.insert(t % tiles.tiles_x);
    return columns;
}

// A camera at the origin looking down -z with a 90 degree field of view across 320 pixels:
// a point at depth d and x = s d projects to column (s + 1) * 160 - 0.5.
Scene side_scene() { return testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 320, 160); }

TEST(ScreenTiles, BillboardBesideTheEyeIsListedOnlyWhereItsVisiblePartProjects) {
    Scene scene = side_scene();
    // A wall at x = 2 from 3 behind the eye to 8 in front: seen on the right, from column
    // (2/8 + 1) * 160 - 0.5 = 199.5 (its far edge) to the screen's right edge.
    scene.billboards.push_back(testing::make_billboard({2, 1, 3}, {2, -1, 3}, {2, 1, -8}, {1, 0, 0}));
    FrameGeometry frame(scene);
    FrameCamera camera = frame_camera(scene, scene.camera_path.front(), 0);
    ScreenTiles tiles = bin_screen_tiles(frame, camera);
    std::set<int> columns = tile_columns_listing(tiles, scene_item(CLR_HIT_BILLBOARD, 0));
    ASSERT_FALSE(columns.empty());
    // Pixel 199 lies in tile 12; a few pixels of margin may reach tile 11, never further.
    EXPECT_GE(*columns.begin(), 11) << "listed in tiles left of its visible part";
    EXPECT_EQ(*columns.rbegin(), tiles.tiles_x - 1);
}

TEST(ScreenTiles, SphereAroundTheEyePlaneIsListedOnlyWhereItsVisiblePartProjects) {
    Scene scene = side_scene();
    // A sphere of radius 1 centred 2 left of the eye at depth 1: its box (x from -3 to -1,
    // depth from 0 to 2) reaches the eye plane. Its part inside the frustum lies at
    // x / depth <= -1/2 (the corner x = -1 at depth 2), left of column 79.5: tile 4.
    scene.spheres.push_back(testing::make_sphere({-2, 0, -1}, 1, {0, 1, 0}));
    FrameGeometry frame(scene);
    FrameCamera camera = frame_camera(scene, scene.camera_path.front(), 0);
    ScreenTiles tiles = bin_screen_tiles(frame, camera);
    std::set<int> columns = tile_columns_listing(tiles, scene_item(CLR_HIT_SPHERE, 0));
    ASSERT_FALSE(columns.empty());
    EXPECT_EQ(*columns.begin(), 0);
    // A few pixels of margin may reach tile 5, never further.
    EXPECT_LE(*columns.rbegin(), 5) << "listed in tiles right of its visible part";
}

TEST(ScreenTiles, ObjectWhollyBehindTheEyeIsNotListed) {
    Scene scene = side_scene();
    scene.billboards.push_back(testing::make_billboard({-1, 1, 2}, {-1, -1, 2}, {1, 1, 2}, {1, 0, 0}));
    FrameGeometry frame(scene);
    ScreenTiles tiles = bin_screen_tiles(frame, frame_camera(scene, scene.camera_path.front(), 0));
    EXPECT_TRUE(tiles.items.empty());
}

// The pixel rows (first, last) that the lists give `item`, and the tile columns listing it.
struct Listing {
    int first_row = -1, last_row = -1;
    std::set<int> tile_columns;
};

Listing listing_of(const ScreenTiles& tiles, std::uint32_t item) {
    Listing listing;
    listing.tile_columns = tile_columns_listing(tiles, item);
    for (std::size_t k = 0; k < tiles.items.size(); ++k)
        if (tiles.items[k] == item) {
            listing.first_row = static_cast<int>(tiles.rows[k] >> 16);
            listing.last_row = static_cast<int>(tiles.rows[k] & 0xffffu);
        }
    return listing;
}

// A square at depth 10 from x, y = -1 to 1 in side_scene(): columns (+-0.1 + 1) * 160 - 0.5,
// 143.5 to 175.5, rows (1 -+ 0.2) * 80 - 0.5, 63.5 to 95.5. With one sample a pixel's ray
// passes through its centre: rows 64 to 95 and columns 144 to 175 (tiles 9 and 10) see the
// square, and no other row or tile needs to test it. With several samples its rays spread
// over the whole pixel: rows 63 and 96, columns 143 (tile 8) and 176 (tile 11) touch it too.
TEST(ScreenTiles, ListsOnlyThePixelsWhoseRaysCanMeetTheObject) {
    Scene scene = side_scene();
    scene.billboards.push_back(testing::make_billboard({-1, 1, -10}, {-1, -1, -10}, {1, 1, -10}, {1, 0, 0}));
    FrameGeometry frame(scene);
    const Listing centres = listing_of(bin_screen_tiles(frame, frame_camera(scene, scene.camera_path.front(), 0)),
                                       scene_item(CLR_HIT_BILLBOARD, 0));
    EXPECT_EQ(centres.first_row, 64);
    EXPECT_EQ(centres.last_row, 95);
    EXPECT_EQ(centres.tile_columns, (std::set<int>{9, 10}));

    scene.sampling.samples_per_pixel = 4;
    const Listing spread = listing_of(bin_screen_tiles(frame, frame_camera(scene, scene.camera_path.front(), 0)),
                                      scene_item(CLR_HIT_BILLBOARD, 0));
    EXPECT_EQ(spread.first_row, 63);
    EXPECT_EQ(spread.last_row, 96);
    EXPECT_EQ(spread.tile_columns, (std::set<int>{8, 9, 10, 11}));
}

// The kernel stops a row once its hits are nearer than the next object's bound: every list
// must run nearest first, and no bound may exceed its object's distance from the eye.
TEST(ScreenTiles, ListsRunNearestFirstWithBoundsBelowTheObjectsDistances) {
    Scene scene = testing::make_scene({0.5, 1, 6}, {0, 0, -10}, {0, 1, 0}, 60, 160, 96);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> spot(-12, 12), depth(-30, 2), size(0.2, 2);
    for (int i = 0; i < 300; ++i) {
        const Vec3 at{spot(random), spot(random) / 2, depth(random)};
        scene.spheres.push_back(testing::make_sphere(at, size(random), {1, 1, 1}));
        const double s = size(random);
        scene.billboards.push_back(testing::make_billboard(at + Vec3{-s, s, 1}, at + Vec3{-s, -s, 1}, at + Vec3{s, s, 1.5}, {1, 1, 1}));
    }
    FrameGeometry frame(scene);
    FrameCamera camera = frame_camera(scene, scene.camera_path.front(), 0);
    ScreenTiles tiles = bin_screen_tiles(frame, camera);
    const Vec3 eye = camera.eye_in_scene();
    ASSERT_GT(tiles.items.size(), 600u);
    for (int t = 0; t < tiles.tiles_x * tiles.tiles_y; ++t)
        for (std::uint32_t k = tiles.offsets[t]; k < tiles.offsets[t + 1]; ++k) {
            if (k > tiles.offsets[t]) {
                EXPECT_LE(tiles.nearest[k - 1], tiles.nearest[k]) << "tile " << t << " entry " << k;
            }
            const std::uint32_t index = scene_item_index(tiles.items[k]);
            double distance;
            if (scene_item_kind(tiles.items[k]) == CLR_HIT_BILLBOARD) {
                const Billboard& b = frame.billboard(index);
                const Vec3 normal = normalize(cross(b.upper_right - b.upper_left, b.lower_left - b.upper_left));
                distance = std::fabs(dot(eye - b.upper_left, normal));
            } else {
                distance = length(frame.spheres()[index].center - eye) - frame.spheres()[index].radius;
            }
            EXPECT_LE(tiles.nearest[k], distance) << "tile " << t << " entry " << k;
        }
}

// The object's place in the frame: its spheres, then its billboards.
std::size_t frame_index(const FrameGeometry& frame, std::uint32_t item) {
    const std::size_t index = scene_item_index(item);
    return scene_item_kind(item) == CLR_HIT_BILLBOARD ? frame.spheres().size() + index : index;
}

// A frame of 20,000 objects bins on every usable core (chunks of objects, then tile rows):
// its lists are those one CPU makes, byte for byte, and each runs nearest first, ties in the
// frame's order, so that no thread's timing can change a tile's list.
TEST(ScreenTiles, ManyObjectsBinOnAllCoresAsOnOne) {
    Scene scene = testing::make_scene({0, 0, 6}, {0, 0, -10}, {0, 1, 0}, 60, 640, 360);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> spot(-20, 20), depth(-40, 0), size(0.05, 0.6);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 at{spot(random), spot(random) / 2, depth(random)};
        scene.spheres.push_back(testing::make_sphere(at, size(random), {1, 1, 1}));
        const double s = size(random);
        scene.billboards.push_back(testing::make_billboard(at + Vec3{-s, s, 0}, at + Vec3{-s, -s, 0}, at + Vec3{s, s, 0}, {1, 1, 1}));
    }
    scene.spheres.push_back(testing::make_sphere({0.1, 0, -45}, 0.5, {1, 1, 1}));  // as far as
    scene.spheres.push_back(testing::make_sphere({-0.1, 0, -45}, 0.5, {1, 1, 1}));  // each other
    FrameGeometry frame(scene);
    const FrameCamera camera = frame_camera(scene, scene.camera_path.front(), 0);
    const ScreenTiles all = bin_screen_tiles(frame, camera);
    ASSERT_GT(all.items.size(), 20000u);
    int ties = 0;
    for (int t = 0; t < all.tiles_x * all.tiles_y; ++t)
        for (std::uint32_t k = all.offsets[t] + 1; k < all.offsets[t + 1]; ++k) {
            const bool nearer = all.nearest[k - 1] < all.nearest[k];
            const bool tie_in_order = all.nearest[k - 1] == all.nearest[k] &&
                                      frame_index(frame, all.items[k - 1]) < frame_index(frame, all.items[k]);
            ASSERT_TRUE(nearer || tie_in_order) << "tile " << t << " entry " << k;
            ties += tie_in_order;
        }
    EXPECT_GT(ties, 0) << "the two spheres as far from the eye share tiles";

    cpu_set_t allowed, one;
    ASSERT_EQ(::sched_getaffinity(0, sizeof allowed, &allowed), 0);
    if (CPU_COUNT(&allowed) < 2) GTEST_SKIP() << "one usable CPU: the lists above were made on it";
    int first_cpu = 0;
    while (!CPU_ISSET(first_cpu, &allowed)) ++first_cpu;
    CPU_ZERO(&one);
    CPU_SET(first_cpu, &one);
    ASSERT_EQ(::sched_setaffinity(0, sizeof one, &one), 0);
    const ScreenTiles single = bin_screen_tiles(frame, camera);
    ASSERT_EQ(::sched_setaffinity(0, sizeof allowed, &allowed), 0);
    EXPECT_TRUE(single.offsets == all.offsets);
    EXPECT_TRUE(single.items == all.items);
    EXPECT_TRUE(single.nearest == all.nearest);
    EXPECT_TRUE(single.rows == all.rows);
}

TEST(FrustumClip, KeepsOnlyThePartInsideTheWidenedFrustum) {
    // A quad in the plane x = 1 from depth -2 to 4: inside the 90 degree frustum
    // (|x| <= z) where depth >= 1.
    const std::vector<ViewPoint> quad = {{1, -0.5, -2}, {1, 0.5, -2}, {1, 0.5, 4}, {1, -0.5, 4}};
    std::vector<ViewPoint> clipped = clip_to_frustum(quad, {0, 0, 0});
    ASSERT_FALSE(clipped.empty());
    double nearest = INFINITY;
    for (const ViewPoint& p : clipped) {
        EXPECT_LE(std::fabs(p.x), p.z * (1 + 1e-12));
        EXPECT_LE(std::fabs(p.y), p.z * (1 + 1e-12));
        nearest = std::min(nearest, p.z);
    }
    EXPECT_NEAR(nearest, 1, 1e-12);
    // A wider frustum keeps more: x <= 1.25 (z + 0.1) from depth 0.7 on.
    nearest = INFINITY;
    for (const ViewPoint& p : clip_to_frustum(quad, {0.25, 0.25, 0.1})) nearest = std::min(nearest, p.z);
    EXPECT_NEAR(nearest, 1 / 1.25 - 0.1, 1e-12);
    EXPECT_TRUE(clip_to_frustum({{1, 0, -1}, {-1, 0, -1}, {0, 1, -3}}, {0.1, 0.1, 0.01}).empty()) << "behind the eye";
    EXPECT_TRUE(clip_to_frustum({{3, 0, 1}, {4, 0, 1}, {4, 1, 2}}, {0.1, 0.1, 0.01}).empty()) << "right of the frustum";
}

// Billboards and spheres reaching behind the eye on every side, seen from several eyes and
// with several samples per pixel: the tiled kernel gives the brute-force kernel's bytes.
TEST(ScreenTiles, ObjectsAcrossTheEyePlaneRenderAsInTheBruteForceKernel) {
    Scene scene = testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 70, 200, 130);
    scene.sampling.samples_per_pixel = 4;
    auto stripes = testing::make_image(8, 8, [](int col, int row) {
        return std::array<std::uint8_t, 4>{std::uint8_t(col * 30), std::uint8_t(row * 30), 90,
                                           std::uint8_t((col + row) % 3 == 0 ? 0 : 255)};
    });
    for (int side = 0; side < 4; ++side) {
        const double angle = side * kPi / 2;
        const double c = std::cos(angle), s = std::sin(angle);
        // A wall 1.5 beside the eye, from 2 behind it to 9 in front, and a sphere farther out.
        const Vec3 out{1.5 * c, 1.5 * s, 0}, along{-s, c, 0};
        scene.billboards.push_back(testing::make_billboard(out + along + Vec3{0, 0, 2}, out - along + Vec3{0, 0, 2},
                                                           out + along + Vec3{0, 0, -9}, {0.2, 0.3 * side, 0.5}, stripes));
        scene.spheres.push_back(testing::make_sphere(out * 2.2 + Vec3{0, 0, 0.5}, 1.4, {0.9, 0.2 * side, 0.1}));
    }
    scene.billboards.push_back(testing::make_billboard({-9, 9, -12}, {-9, -9, -12}, {9, 9, -12}, {0.1, 0.1, 0.1}));
    scene.camera_path = {{{0, 0, 0}, {0, 0, -1}}, {{0.3, -0.2, 0.4}, {1.5, 0.5, -3}}, {{-0.2, 0.1, 0}, {-2, -1, -1}}};
    RendererOptions brute;
    brute.screen_tiles = false;
    Renderer tiled(testing::test_device(), scene);
    Renderer every_object(testing::test_device(), scene, brute);
    for (std::size_t k = 0; k < scene.camera_path.size(); ++k)
        EXPECT_EQ(tiled.render(scene.camera_path[k]).rgba, every_object.render(scene.camera_path[k]).rgba) << "key " << k;
}

}  // namespace
}  // namespace clr
