// Each specialised kernel (only the features a scene uses compiled in) must render exactly
// what the fully general kernel renders for the same scene.
#include <gtest/gtest.h>

#include "render/feature_set.h"
#include "render/frame_camera.h"
#include "render/screen_tiles.h"

#include <random>
#include "support/random_scene.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

void expect_same_as_general(const Scene& scene) {
    RendererOptions general;  // every feature compiled in, no culling
    general.features = FeatureSet::all();
    general.screen_tiles = false;
    Image specialised = testing::render_with_kernels(scene);
    Image reference = testing::render_with_kernels(scene, general);
    ASSERT_EQ(specialised.rgba.size(), reference.rgba.size());
    EXPECT_TRUE(specialised.rgba == reference.rgba) << "features: " << FeatureSet::of(scene).build_options();
}

Scene camera_on(Scene scene) {
    scene.camera_path = {{{4, 6, 32}, {0, 0, 0}}};
    scene.width = 96;
    scene.height = 64;
    return scene;
}

TEST(FeatureVariants, SpheresOnly) { expect_same_as_general(camera_on(testing::make_random_scene(11, 15, 0))); }

TEST(FeatureVariants, BillboardsOnlyWithAlpha) { expect_same_as_general(camera_on(testing::make_random_scene(12, 0, 15))); }

TEST(FeatureVariants, OpaqueTexturesAndFlatBillboards) {
    Scene scene = camera_on(testing::make_random_scene(13, 5, 0));
    auto opaque = testing::make_image(3, 2, [](int col, int row) {
        return std::array<std::uint8_t, 4>{std::uint8_t(col * 100), std::uint8_t(row * 200), 50, 255};
    });
    scene.billboards.push_back(testing::make_billboard({-8, 8, -5}, {-8, -8, -5}, {8, 8, -5}, {0, 1, 0}, opaque));
    scene.billboards.push_back(testing::make_billboard({-3, 9, 2}, {-3, 5, 2}, {3, 9, 2}, {1, 0, 1}));
    EXPECT_FALSE(FeatureSet::of(scene).alpha);
    expect_same_as_general(scene);
}

TEST(FeatureVariants, SunAndMirrors) {
    Scene scene = camera_on(testing::make_random_scene(14, 10, 6));
    scene.has_sun = true;
    scene.sun_location = {30, 40, 20};
    scene.spheres[0].is_mirror = true;
    scene.billboards[1].is_mirror = true;
    scene.max_depth = 3;
    FeatureSet features = FeatureSet::of(scene);
    EXPECT_TRUE(features.sun && features.mirrors);
    expect_same_as_general(scene);
}

// A sun without mirrors: billboard and background lanes take their colour from the
// intersection loop, sphere lanes are shaded one by one (shadows through cut-out texels too).
TEST(FeatureVariants, SunWithoutMirrors) {
    Scene scene = camera_on(testing::make_random_scene(17, 12, 12));
    scene.has_sun = true;
    scene.sun_location = {-20, 40, 30};
    FeatureSet features = FeatureSet::of(scene);
    EXPECT_TRUE(features.sun && features.alpha && !features.mirrors);
    // With a BVH the 16 lanes' shadow rays walk it together (kernels/packet/shadows16.cl),
    // through billboards' transparent texels too; the general kernel traces them one by one.
    EXPECT_TRUE(features.bvh);
    expect_same_as_general(scene);
    scene.spheres.clear();  // a sun with nothing to light
    expect_same_as_general(scene);
}

// Many objects a few pixels tall: each row of a tile tests only the objects whose pixel rows
// include it.
TEST(FeatureVariants, ManySmallObjectsSkippedByRow) {
    Scene scene = camera_on(testing::make_random_scene(18, 0, 0));
    scene.width = 160;
    scene.height = 120;
    Scene small = testing::make_random_scene(19, 300, 300);
    for (Sphere& sphere : small.spheres) sphere.radius *= 0.1;
    for (Billboard& billboard : small.billboards) {
        billboard.upper_right = billboard.upper_left + (billboard.upper_right - billboard.upper_left) * 0.1;
        billboard.lower_left = billboard.upper_left + (billboard.lower_left - billboard.upper_left) * 0.1;
    }
    scene.spheres = small.spheres;
    scene.billboards = small.billboards;
    expect_same_as_general(scene);
}

// The camera in the middle of the objects, as in a forest: those wholly behind it are left
// out of every tile, those reaching past its side into every tile, and the image is the
// general kernel's.
TEST(FeatureVariants, ObjectsAllAroundTheCamera) {
    Scene scene = testing::make_random_scene(22, 40, 40);
    for (const Vec3& lookat : {Vec3{0, 0, -1}, Vec3{1, 0.2, 0}, Vec3{0, -1, 0.3}}) {
        scene.camera_path = {{{0.5, 0.2, 0.1}, lookat}};
        scene.width = 96;
        scene.height = 64;
        expect_same_as_general(scene);
    }
    const CameraKey& key = scene.camera_path.front();
    ScreenTiles tiles = bin_screen_tiles(FrameGeometry(scene), frame_camera(scene, key, 0));
    std::size_t tile_count = tiles.offsets.size() - 1;
    EXPECT_LT(tiles.items.size(), tile_count * (scene.spheres.size() + scene.billboards.size()) / 2)
        << "objects behind the camera must not be listed in every tile";
}

TEST(FeatureVariants, EmptyScene) { expect_same_as_general(camera_on(testing::make_random_scene(15, 0, 0))); }

TEST(FeatureSet, OptionsAreDeterministicAndComplete) {
    FeatureSet none;
    EXPECT_EQ(none.build_options(),
              "-DCLR_FEATURE_ALPHA=0 -DCLR_FEATURE_BILLBOARDS=0 -DCLR_FEATURE_BVH=0 -DCLR_FEATURE_CLIP=0 "
              "-DCLR_FEATURE_DOUBLE=0 -DCLR_FEATURE_FLOAT_OUTPUT=0 -DCLR_FEATURE_LIGHTS=0 "
              "-DCLR_FEATURE_MIRRORS=0 -DCLR_FEATURE_PLANES=0 -DCLR_FEATURE_SPHERES=0 "
              "-DCLR_FEATURE_SUN=0 -DCLR_FEATURE_TEXTURES=0 -DCLR_FEATURE_TRIANGLES=0 -DCLR_FEATURE_TRIANGLE_TIES=0");
    EXPECT_EQ(FeatureSet::all().build_options(),
              "-DCLR_FEATURE_ALPHA=1 -DCLR_FEATURE_BILLBOARDS=1 -DCLR_FEATURE_BVH=1 -DCLR_FEATURE_CLIP=1 "
              "-DCLR_FEATURE_DOUBLE=0 -DCLR_FEATURE_FLOAT_OUTPUT=0 -DCLR_FEATURE_LIGHTS=1 "
              "-DCLR_FEATURE_MIRRORS=1 -DCLR_FEATURE_PLANES=1 -DCLR_FEATURE_SPHERES=1 "
              "-DCLR_FEATURE_SUN=1 -DCLR_FEATURE_TEXTURES=1 -DCLR_FEATURE_TRIANGLES=1 -DCLR_FEATURE_TRIANGLE_TIES=1");
}

TEST(FeatureSet, AnalysisFollowsTheScene) {
    Scene scene = testing::make_random_scene(16, 2, 0);
    FeatureSet features = FeatureSet::of(scene);
    EXPECT_TRUE(features.spheres);
    EXPECT_FALSE(features.billboards || features.textures || features.alpha || features.sun || features.mirrors);
    scene.has_sun = true;
    EXPECT_TRUE(FeatureSet::of(scene).sun);
    scene.only_ambient = true;  // OnlyAmbient 1 turns the sun off
    EXPECT_FALSE(FeatureSet::of(scene).sun);
    auto holey = testing::make_image(1, 1, [](int, int) { return std::array<std::uint8_t, 4>{1, 2, 3, 0}; });
    scene.billboards.push_back(testing::make_billboard({0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 0, 0}, holey, true));
    features = FeatureSet::of(scene);
    EXPECT_TRUE(features.billboards && features.mirrors);
    EXPECT_FALSE(features.textures || features.alpha) << "a mirror ignores its image";
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

// Screen-tile culling must not change a single byte: random scenes seen from cameras inside
// and around them (objects behind the eye, spheres around it, billboards crossing the eye's
// plane), against the brute-force kernel.
TEST(ScreenTiles, CulledRenderEqualsBruteForce) {
    for (std::uint32_t seed = 200; seed < 212; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Scene scene = testing::make_random_scene(seed, 25, 25);
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> coordinate(-14, 14);
        Vec3 eye{coordinate(random), coordinate(random), coordinate(random)};
        scene.camera_path = {{eye, {coordinate(random) * 0.3, coordinate(random) * 0.3, coordinate(random) * 0.3}}};
        scene.fov_degrees = 30 + (seed % 5) * 30;
        scene.width = 77;
        scene.height = 45 + (seed % 3) * 20;
        if (seed % 4 == 0) scene.spheres[0].center = eye;  // the eye inside a sphere
        RendererOptions brute_force;
        brute_force.screen_tiles = false;
        Image tiled = testing::render_with_kernels(scene);
        Image reference = testing::render_with_kernels(scene, brute_force);
        EXPECT_TRUE(tiled.rgba == reference.rgba);
    }
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

// The double-precision kernels: their 16-lane path equals their scalar path, byte for byte.
TEST(DoublePrecision, PacketsEqualBruteForceAndAntialiasingWorks) {
    for (std::uint32_t seed : {220u, 221u}) {
        Scene scene = testing::make_random_scene(seed, 20, 20);
        scene.camera_path = {{{2, 3, 28}, {0, 0, 0}}};
        scene.width = 70;
        scene.height = 50;
        scene.has_sun = true;
        scene.sun_location = {15, 25, 20};
        scene.spheres[2].is_mirror = true;
        scene.sampling.samples_per_pixel = seed == 221u ? 3 : 1;
        RendererOptions packets, brute_force;
        packets.double_precision = brute_force.double_precision = true;
        brute_force.screen_tiles = false;
        EXPECT_TRUE(testing::render_with_kernels(scene, packets).rgba == testing::render_with_kernels(scene, brute_force).rgba)
            << "seed " << seed;
    }
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

// Shadow and mirror rays through the BVH give exactly the brute-force image, in float and in
// double, with hundreds of objects, mirrors bouncing between them, and the eye inside the
// scene.
TEST(Bvh, SecondaryRaysThroughTheBvhEqualBruteForce) {
    for (std::uint32_t seed : {230u, 231u, 232u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Scene scene = testing::make_random_scene(seed, 150, 150);
        scene.camera_path = {{{seed == 232u ? 1.0 : 6.0, 4, seed == 232u ? 2.0 : 34.0}, {0, 0, 0}}};
        scene.width = 64;
        scene.height = 48;
        scene.has_sun = true;
        scene.sun_location = {25, 40, 30};
        scene.max_depth = 4;
        for (std::size_t i = 0; i < scene.spheres.size(); i += 5) scene.spheres[i].is_mirror = true;
        for (std::size_t i = 0; i < scene.billboards.size(); i += 7) scene.billboards[i].is_mirror = true;
        FeatureSet features = FeatureSet::of(scene);
        ASSERT_TRUE(features.bvh);
        for (bool in_double : {false, true}) {
            RendererOptions with_bvh, brute_force;
            with_bvh.double_precision = brute_force.double_precision = in_double;
            brute_force.features = features;
            brute_force.features->bvh = false;
            EXPECT_TRUE(testing::render_with_kernels(scene, with_bvh).rgba ==
                        testing::render_with_kernels(scene, brute_force).rgba)
                << (in_double ? "double" : "float");
        }
    }
}

TEST(Bvh, OnlyScenesWithSecondaryRaysAndManyObjectsGetOne) {
    Scene many = testing::make_random_scene(240, 30, 30);
    EXPECT_FALSE(FeatureSet::of(many).bvh) << "flat shading: primary rays only, culled by screen tiles";
    many.has_sun = true;
    EXPECT_TRUE(FeatureSet::of(many).bvh);
    Scene few = testing::make_random_scene(241, 5, 5);
    few.has_sun = true;
    EXPECT_FALSE(FeatureSet::of(few).bvh);
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

// render_packets' fast paths for flat shading: tiles no object reaches (filled with the
// background's mean over the samples at once) and colours taken from the intersection loop
// (spheres, flat billboards, textured ones with and without holes), in float and double, with
// one and several samples, against the fully general brute-force kernel.
TEST(ScreenTiles, FlatShadingFastPathsEqualBruteForce) {
    Scene scene = testing::make_random_scene(250, 6, 6);
    for (Sphere& sphere : scene.spheres) sphere.radius *= 0.4;  // leave most tiles empty
    auto opaque = testing::make_image(5, 3, [](int col, int row) {
        return std::array<std::uint8_t, 4>{std::uint8_t(col * 50 + 3), std::uint8_t(row * 90 + 1), 77, 255};
    });
    scene.billboards.push_back(testing::make_billboard({-2, 3, 4}, {-2, 1, 4}, {1, 3, 3}, {0, 1, 0}, opaque));
    scene.background = {0.1, 0.7, 0.3};  // not exactly representable: the mean over samples must round alike
    scene.camera_path = {{{3, 4, 40}, {0, 0, 0}}};
    scene.width = 101;
    scene.height = 70;
    FeatureSet features = FeatureSet::of(scene);
    ASSERT_TRUE(features.textures && features.alpha && !features.sun && !features.mirrors);
    for (bool in_double : {false, true})
        for (int samples : {1, 3}) {
            SCOPED_TRACE(std::string(in_double ? "double, " : "float, ") + std::to_string(samples) + " samples");
            scene.sampling.samples_per_pixel = samples;
            RendererOptions packets, general;
            packets.double_precision = general.double_precision = in_double;
            general.features = FeatureSet::all();
            general.screen_tiles = false;
            Image tiled = testing::render_with_kernels(scene, packets);
            EXPECT_TRUE(tiled.rgba == testing::render_with_kernels(scene, general).rgba);
            int background_pixels = 0;
            for (std::size_t i = 0; i < tiled.rgba.size(); i += 4)
                background_pixels += tiled.rgba[i] == 26 && tiled.rgba[i + 1] == 179 && tiled.rgba[i + 2] == 77;
            EXPECT_GT(background_pixels, static_cast<int>(tiled.rgba.size() / 4 / 3)) << "mostly empty tiles";
        }
}

}  // namespace
}  // namespace clr
