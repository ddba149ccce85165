// Impostors through the kernels (docs/scene-format.md, Impostors): the host places them for
// each frame and the kernels render the placed billboards. Checked against the double
// reference, which places them on its own from the same documented rule.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "reference/eye_relative.h"
#include "reference/impostors.h"
#include "reference/reference.h"
#include "scene/camera_path.h"
#include "render/feature_set.h"
#include "render/impostor_placement.h"
#include "render/scene_bvh.h"
#include "support/image_compare.h"
#include "support/opencl_test_device.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using Rgba = std::array<std::uint8_t, 4>;

constexpr Rgba kRed{230, 20, 20, 255}, kBlue{20, 20, 230, 255}, kGreen{20, 200, 20, 255}, kYellow{230, 220, 20, 255};
constexpr Rgba kHole{0, 0, 0, 0};

// A 4x4 picture whose left half is `left` and right half `right`, with a hole in each corner.
std::shared_ptr<Image> two_tone(Rgba left, Rgba right) {
    return testing::make_image(4, 4, [=](int col, int row) {
        bool corner = (col == 0 || col == 3) && (row == 0 || row == 3);
        return corner ? kHole : (col < 2 ? left : right);
    });
}

// A tree-like impostor with four views: from +z red|blue, from +x green|yellow, from -z
// blue|red, from -x yellow|green.
Impostor four_view_impostor(const Vec3& center, Facing facing = Facing::Upright) {
    Impostor impostor;
    impostor.center = center;
    impostor.width = 2;
    impostor.height = 3;
    impostor.facing = facing;
    impostor.views = {{{0, 0, 1}, two_tone(kRed, kBlue)},
                      {{1, 0, 0}, two_tone(kGreen, kYellow)},
                      {{0, 0, -1}, two_tone(kBlue, kRed)},
                      {{-1, 0, 0}, two_tone(kYellow, kGreen)}};
    return impostor;
}

Scene impostor_scene(const Vec3& eye, const Vec3& lookat) {
    Scene scene = testing::make_scene(eye, lookat, {0, 1, 0}, 50, 64, 48);
    scene.background = {0.3, 0.5, 0.8};
    scene.billboards.push_back(testing::make_billboard({-30, 0, -30}, {-30, 0, 30}, {30, 0, -30}, {0.2, 0.4, 0.1}));
    return scene;
}

void expect_matches_reference(const Image& kernel, const Image& reference, const std::string& what) {
    testing::ImageComparison comparison = testing::compare_images(kernel, reference);
    EXPECT_LE(comparison.differing_fraction(), 0.002) << what << ": " << comparison.differing << " pixels differ";
    EXPECT_EQ(comparison.differing_off_edge, 0) << what << ": " << comparison.first_off_edge;
}

// ---------------------------------------------------------------------------------------
// Placement on the host, against the reference's

// The reference's placement of `impostor` for a camera at `key`, relative to the eye as the
// reference traces it (reference/eye_relative.h), and so as the host places it.
Billboard reference_placement(const Impostor& impostor, Scene scene, const CameraKey& key) {
    scene.impostors = {impostor};
    const reference::EyeRelative relative = reference::relative_to_eye(scene, reference::camera_of(scene, key));
    return reference::place_impostor(relative.scene.impostors[0], relative.camera, scene.up);
}

TEST(ImpostorPlacement, HostPlacementEqualsTheReferencesForRandomCameras) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-20, 20);
    for (int trial = 0; trial < 300; ++trial) {
        Vec3 up = normalize(Vec3{coordinate(random) * 0.1, 1, coordinate(random) * 0.1});
        CameraKey key{{coordinate(random), coordinate(random), coordinate(random)},
                      {coordinate(random), coordinate(random), coordinate(random)}};
        Impostor impostor = four_view_impostor({coordinate(random), coordinate(random), coordinate(random)},
                                               trial % 2 ? Facing::Free : Facing::Upright);
        impostor.width = 1 + trial % 5;
        Scene scene = impostor_scene(key.eye, key.lookat);
        scene.up = up;
        reference::CameraFrame camera = reference::camera_of(scene, key);
        PlacementCamera placement(key, scene.up);
        Billboard host = place_impostor(impostor, placement);
        Billboard expected = reference_placement(impostor, scene, key);
        for (auto corner : {&Billboard::upper_left, &Billboard::upper_right, &Billboard::lower_left})
            EXPECT_LT(length(host.*corner - expected.*corner), 1e-12 * (1 + length(impostor.center - key.eye))) << "trial " << trial;
        EXPECT_EQ(choose_view(impostor, placement), reference::chosen_view(impostor, camera)) << "trial " << trial;
        EXPECT_EQ(host.image, expected.image);
    }
}

TEST(ImpostorPlacement, DegenerateEyesFollowTheDocumentedFallbacks) {
    // Straight above an upright impostor, and at the centre of a free one.
    for (Facing facing : {Facing::Upright, Facing::Free}) {
        Impostor impostor = four_view_impostor({1, 2, 3}, facing);
        for (const CameraKey& key : {CameraKey{{1, 9, 3}, {1.5, 2, 2}}, CameraKey{{1, 2, 3}, {0, 2, 0}}}) {
            Scene scene = impostor_scene(key.eye, key.lookat);
            Billboard host = place_impostor(impostor, PlacementCamera(key, scene.up));
            Billboard expected = reference_placement(impostor, scene, key);
            EXPECT_LT(length(host.upper_left - expected.upper_left), 1e-12);
            EXPECT_LT(length(host.upper_right - expected.upper_right), 1e-12);
            EXPECT_LT(length(host.lower_left - expected.lower_left), 1e-12);
        }
    }
}

// Placed relative to the eye, corners are exact near it wherever the scene lies: the same
// impostor and camera moved by up to the documented 1e15 (by multiples of 1/8, so that every
// position stays exact) give the same corners bit for bit, and the same view. In scene
// coordinates, corners near 1e15 are rounded to 1/8.
TEST(ImpostorPlacement, CornersRelativeToTheEyeAreTheSameAnywhereInRange) {
    for (Facing facing : {Facing::Upright, Facing::Free}) {
        const Impostor near = four_view_impostor({2.5, 0.25, -0.5}, facing);
        const CameraKey near_key{{0.5, 1.25, 8}, {0, 0.5, 0}};
        const PlacementCamera near_camera(near_key, {0, 1, 0});
        const Billboard expected = place_impostor(near, near_camera);
        for (double size : {1e6, 1e9, 1e12, 1e15 - 64}) {
            for (const Vec3& offset : {Vec3{size, 0, 0}, Vec3{size, -size, size}, Vec3{-size, size, -size}}) {
                Impostor moved = near;
                moved.center = near.center + offset;
                const PlacementCamera camera(CameraKey{near_key.eye + offset, near_key.lookat + offset}, {0, 1, 0});
                const Billboard placed = place_impostor(moved, camera);
                EXPECT_EQ(placed.upper_left, expected.upper_left) << "offset " << size;
                EXPECT_EQ(placed.upper_right, expected.upper_right) << "offset " << size;
                EXPECT_EQ(placed.lower_left, expected.lower_left) << "offset " << size;
                EXPECT_EQ(choose_view(moved, camera), choose_view(near, near_camera)) << "offset " << size;
            }
        }
    }
}

TEST(ImpostorPlacement, ExactTiesShowTheFirstOfTheTiedViews) {
    Impostor impostor = four_view_impostor({0, 0, 0});
    impostor.views = {{{1, 0, 0}, two_tone(kRed, kRed)}, {{-1, 0, 0}, two_tone(kBlue, kBlue)}};
    PlacementCamera on_the_z_axis(CameraKey{{0, 0, 5}, {0, 0, 0}}, {0, 1, 0});  // both scores exactly 0
    EXPECT_EQ(choose_view(impostor, on_the_z_axis), 0);
    EXPECT_EQ(place_impostor(impostor, on_the_z_axis).image, impostor.views[0].image);
    std::swap(impostor.views[0], impostor.views[1]);
    EXPECT_EQ(place_impostor(impostor, on_the_z_axis).image, impostor.views[0].image);
    PlacementCamera off_axis(CameraKey{{-1e-9, 0, 5}, {0, 0, 0}}, {0, 1, 0});
    EXPECT_EQ(choose_view(impostor, off_axis), 0) << "views[0] is now the -x view";
}

// ---------------------------------------------------------------------------------------
// Whole frames through the kernels

// The camera circles the impostor at constant height through a quarter turn, from +z to +x:
// the shown view switches from the +z view to the +x view at 45 degrees. One renderer renders
// every frame, as an animation does.
TEST(ImpostorFrames, CirclingCameraSwitchesViewsWhereTheReferenceDoes) {
    Scene scene = impostor_scene({0, 2, 8}, {0, 1.5, 0});
    scene.impostors.push_back(four_view_impostor({0, 1.5, 0}));
    scene.camera_path.clear();
    const int frames = 13;
    for (int k = 0; k < frames; ++k) {
        double angle = (k + 0.5) * (M_PI / 2) / frames;  // never exactly on the 45-degree tie
        scene.camera_path.push_back({{8 * std::sin(angle), 2, 8 * std::cos(angle)}, {0, 1.5, 0}});
    }
    Renderer renderer(testing::test_device(), scene);
    std::set<int> views_seen;
    for (int k = 0; k < frames; ++k) {
        const CameraKey& key = scene.camera_path[k];
        reference::CameraFrame camera = reference::camera_of(scene, key);
        views_seen.insert(reference::chosen_view(scene.impostors[0], camera));
        Image kernel = renderer.render(key, k);
        expect_matches_reference(kernel, reference::render(scene, camera, k), "frame " + std::to_string(k));
        // The impostor's centre pixel column: left of it the picture's left half shows.
        Image expected_left = k < frames / 2 ? *two_tone(kRed, kBlue) : *two_tone(kGreen, kYellow);
        int row = 24;
        std::uint8_t red = kernel.at(30, row, 0), green = kernel.at(30, row, 1);
        EXPECT_EQ(red, expected_left.at(1, 1, 0)) << "frame " << k;
        EXPECT_EQ(green, expected_left.at(1, 1, 1)) << "frame " << k;
    }
    EXPECT_EQ(views_seen, (std::set<int>{0, 1})) << "the path must cross the switch";
}

// Whichever side the eye is on, the impostor shows its front: its picture reads left to right
// as drawn, never mirrored.
TEST(ImpostorFrames, NeverShowsItsBack) {
    for (Facing facing : {Facing::Upright, Facing::Free}) {
        for (int step = 0; step < 8; ++step) {
            double angle = step * M_PI / 4 + 0.1;
            Scene scene = impostor_scene({7 * std::sin(angle), 1.5 + step * 0.5, 7 * std::cos(angle)}, {0, 1.5, 0});
            Impostor impostor = four_view_impostor({0, 1.5, 0}, facing);
            impostor.views.resize(1);  // red on the left, blue on the right, from everywhere
            scene.impostors.push_back(impostor);
            Image image = testing::render_with_kernels(scene);
            EXPECT_GT(image.at(29, 24, 0), 200) << "left of centre is red, step " << step;
            EXPECT_GT(image.at(34, 24, 2), 200) << "right of centre is blue, step " << step;
            expect_matches_reference(image, testing::render_with_reference(scene), "step " + std::to_string(step));
        }
    }
}

// Rays pass through an impostor's holes to the impostors behind, whatever their order in the
// list; the image is the same either way.
TEST(ImpostorFrames, HolesShowWhatIsBehindWhateverTheOrder) {
    auto bars = testing::make_image(8, 8, [](int col, int) { return col % 2 ? kHole : kRed; });
    Scene scene = impostor_scene({0, 1.5, 9}, {0, 1.5, 0});
    Impostor front = four_view_impostor({0, 1.5, 2});
    front.views = {{{0, 0, 1}, bars}};
    Impostor back = four_view_impostor({0.3, 1.5, -2});
    back.views.resize(1);
    scene.impostors = {front, back};
    Image front_first = testing::render_with_kernels(scene);
    scene.impostors = {back, front};
    Image back_first = testing::render_with_kernels(scene);
    EXPECT_EQ(front_first.rgba, back_first.rgba);
    expect_matches_reference(back_first, testing::render_with_reference(scene), "back first");
    // Through a hole of the front picture the back one's blue (right half) shows.
    bool blue_behind = false;
    for (int col = 32; col < 40; ++col) blue_behind |= front_first.at(col, 24, 2) > 200 && front_first.at(col, 24, 0) < 50;
    EXPECT_TRUE(blue_behind);
}

// Each frame of the scene's camera path through one renderer, as an animation renders them:
// the same bytes as the general brute-force kernel's, and the reference's image.
void expect_frames_are_the_general_kernels_and_the_references(const Scene& scene, const std::string& what) {
    RendererOptions general;
    general.features = FeatureSet::all();
    general.screen_tiles = false;
    Renderer specialised(testing::test_device(), scene);
    Renderer brute_force(testing::test_device(), scene, general);
    for (const CameraKey& key : scene.camera_path) {
        Image image = specialised.render(key);
        EXPECT_EQ(image.rgba, brute_force.render(key).rgba) << what;
        expect_matches_reference(image, reference::render(scene, reference::camera_of(scene, key)), what);
    }
}

// Many impostors with a sun and a mirror: the BVH over the placed billboards (rebuilt every
// frame) and the screen tiles give the general kernel's image, which matches the reference.
TEST(ImpostorFrames, ForestWithSunAndMirrorEqualsTheGeneralKernel) {
    Scene scene = impostor_scene({1, 3, 14}, {0, 1, 0});
    scene.has_sun = true;
    scene.sun_location = {20, 40, 10};
    std::mt19937 random(3);
    std::uniform_real_distribution<double> spot(-8, 8);
    for (int i = 0; i < 40; ++i) scene.impostors.push_back(four_view_impostor({spot(random), 1.5, spot(random)}));
    for (int i = 0; i < 6; ++i) scene.spheres.push_back(testing::make_sphere({spot(random), 0.7, spot(random)}, 0.7, {0.6, 0.6, 0.6}));
    scene.spheres[0].is_mirror = true;
    ASSERT_TRUE(FeatureSet::of(scene).bvh);
    scene.camera_path.push_back({{-6, 2.5, 12}, {0, 1, 0}});  // a second frame, from elsewhere
    expect_frames_are_the_general_kernels_and_the_references(scene, "forest");
}

// Large meshes have BVH trees of their own, built once (a copy of one file refitted), that
// each frame joins with the tree over the impostors placed for it (render/scene_bvh.h): the
// shadows and reflections of every frame are still the general kernel's and the reference's.
TEST(ImpostorFrames, LargeMeshesKeepTheirTreesWhileImpostorsTurn) {
    Scene scene = impostor_scene({1, 3, 14}, {0, 1, 0});
    scene.has_sun = true;
    scene.sun_location = {20, 40, 10};
    for (int i = 0; i < 8; ++i) scene.impostors.push_back(four_view_impostor({-7.0 + 2 * i, 1.5, -3}));
    for (const Vec3& centre : {Vec3{-3, 1.5, 2}, Vec3{3, 1.5, 2}}) {
        testing::add_mesh(scene, testing::sphere_mesh(centre, 1.4, 48, 24, true), {0.8, 0.3, 0.2});
        scene.meshes.back().path = "ball.obj";  // one file placed twice: the second is refitted
    }
    testing::add_mesh(scene, testing::grid_mesh({-6, 3.5, -6}, {0, 0, 12}, {0, 1.5, 0}, 32, 16), {0, 0, 0}, true);
    scene.spheres.push_back(testing::make_sphere({0, 0.8, 4}, 0.8, {0.6, 0.6, 0.6}));
    ASSERT_EQ(build_mesh_trees(scene).trees.size(), 3u) << "the test needs meshes large enough for trees";
    scene.camera_path.push_back({{-6, 2.5, 12}, {0, 1, 0}});
    expect_frames_are_the_general_kernels_and_the_references(scene, "meshes");
}

}  // namespace
}  // namespace clr
