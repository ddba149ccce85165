// Scenes that break naive float32 code, each compared with the double-precision reference:
// at most 0.1% of pixels may differ by more than 1/255 (SPEC: accurate to the last pixel).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <set>
#include <sstream>
#include <utility>

#include "support/image_compare.h"
#include "support/render_helpers.h"
#include "reference/reference.h"
#include "render/frame_camera.h"
#include "support/scene_builder.h"
#include "support/stage_runner.h"

namespace clr {
namespace {

// Checks float and double kernels; double must be at least as close as float.
// No NaN or infinite colour anywhere, checked on the stage kernels' float outputs (a NaN
// would be hidden by the conversion to bytes): primary rays, their hits, their shading.
void expect_no_nan(const Scene& scene, const std::string& what) {
    testing::StageRunner runner(scene);
    const CameraKey& key = scene.camera_path.front();
    std::vector<ClrRay> rays = runner.raygen(make_frame_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height).device());
    std::vector<ClrHit> hits = runner.intersect(rays);
    testing::ShadeOutput shaded = runner.shade(rays, hits, 0);
    int bad = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        bad += std::isnan(hits[i].t);
        for (int k = 0; k < 4; ++k) bad += !std::isfinite(shaded.colors[i].s[k]) || !std::isfinite(rays[i].direction.s[k]);
    }
    EXPECT_EQ(bad, 0) << what << ": NaN or infinite values";
}

void expect_close_to_reference(const Scene& scene, const std::string& what) {
    expect_no_nan(scene, what);
    Image reference = testing::render_with_reference(scene);
    RendererOptions in_double;
    in_double.double_precision = true;
    testing::ImageComparison double_comparison = testing::compare_images(testing::render_with_kernels(scene, in_double), reference);
    EXPECT_LE(double_comparison.differing_fraction(), 0.001) << what << " in double";
    testing::ImageComparison comparison = testing::compare_images(testing::render_with_kernels(scene), reference);
    std::cout << what << " (double): " << double_comparison.differing << " pixels differ by more than 1/255, largest "
              << double_comparison.max_channel_difference << "/255\n";
    std::cout << what << ": " << comparison.differing << " of " << comparison.pixels << " pixels differ by more than 1/255 ("
              << 100 * comparison.differing_fraction() << "%), largest difference " << comparison.max_channel_difference
              << "/255\n";
    EXPECT_LE(comparison.differing_fraction(), 0.001) << what << ": " << comparison.differing << " pixels differ";
}

std::shared_ptr<Image> checker(int size) {
    return testing::make_image(size, size, [](int col, int row) {
        bool dark = (col + row) % 2 == 0;
        return std::array<std::uint8_t, 4>{std::uint8_t(dark ? 40 : 230), 120, std::uint8_t(dark ? 200 : 30), 255};
    });
}

// A small scene with a lit sphere, a shadow, a textured billboard and a mirror, placed at
// `origin` and seen from `origin + (0.5, 1.2, 8) scale` (all sizes about `scale`; the
// smallest length is the radius 0.4 scale).
Scene small_world(const Vec3& origin, double scale = 1) {
    const auto at = [&](double x, double y, double z) { return origin + Vec3{x, y, z} * scale; };
    Scene scene = testing::make_scene(at(0.5, 1.2, 8), origin, {0, 1, 0}, 50, 160, 120);
    scene.has_sun = true;
    scene.sun_location = at(20, 30, 15);
    scene.spheres.push_back(testing::make_sphere(origin, 1 * scale, {0.9, 0.4, 0.2}));
    scene.spheres.push_back(testing::make_sphere(at(0.7, 1.6, 0.6), 0.4 * scale, {0.2, 0.9, 0.4}));
    scene.spheres.push_back(testing::make_sphere(at(-2.2, 0, 0.5), 0.8 * scale, {0, 0, 0}, true));
    scene.billboards.push_back(testing::make_billboard(at(-4, 3, -3), at(-4, -2, -3), at(4, 3, -3), {0, 0, 0}, checker(16)));
    return scene;
}

TEST(Stress, UnitSphereTenThousandAwayThroughANarrowLens) {
    Scene scene = testing::make_scene({0, 0, 1e4}, {0, 0, 0}, {0, 1, 0}, 1.5, 160, 120);
    scene.has_sun = true;
    scene.sun_location = {1e4, 1e4, 1e4};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1, {0.8, 0.8, 0.2}));
    scene.spheres.push_back(testing::make_sphere({1.5, 0.5, -3}, 0.5, {0.2, 0.8, 0.8}));
    expect_close_to_reference(scene, "sphere 1e4 away, fov 1.5");
}

TEST(Stress, GroundSphereOfRadiusOneHundredThousand) {
    Scene scene = testing::make_scene({0, 1, 0}, {0, 0.6, -20}, {0, 1, 0}, 70, 200, 120);
    scene.has_sun = true;
    scene.sun_location = {50, 200, 80};
    scene.spheres.push_back(testing::make_sphere({0, -1e5, 0}, 1e5, {0.3, 0.7, 0.3}));
    scene.spheres.push_back(testing::make_sphere({1, 0.5, -6}, 0.5, {0.9, 0.2, 0.2}));  // casts a shadow on the ground
    scene.background = {0.5, 0.7, 1.0};
    expect_close_to_reference(scene, "ground sphere r=1e5, eye 1 above");
}

TEST(Stress, SpheresOfRadiusOneThousandth) {
    Scene scene = testing::make_scene({0, 0, 0.01}, {0, 0, 0}, {0, 1, 0}, 40, 160, 120);
    scene.has_sun = true;
    scene.sun_location = {1, 1, 1};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1e-3, {0.9, 0.9, 0.9}));
    scene.spheres.push_back(testing::make_sphere({0.0015, 0.001, -0.002}, 5e-4, {0.9, 0.3, 0.3}));
    expect_close_to_reference(scene, "spheres of radius 1e-3");
}

TEST(Stress, WholeSceneTranslatedByOneHundredThousand) {
    expect_close_to_reference(small_world({0, 0, 0}), "small world at the origin");
    expect_close_to_reference(small_world({1e5, 1e5, -1e5}), "small world translated by 1e5");
}

TEST(Stress, CameraPathThroughABillboardsPlane) {
    for (double z : {0.5, 0.01, 1e-4, 0.0, -1e-4, -0.01, -0.5}) {
        Scene scene = testing::make_scene({0.3, 0.2, z}, {0.3, 0.2, z - 1}, {0, 1, 0}, 90, 120, 90);
        // The billboard's plane is z = 0; the camera crosses it while looking along -z, and a
        // second, tilted one is seen edge-on.
        scene.billboards.push_back(testing::make_billboard({-2, 2, 0}, {-2, -2, 0}, {2, 2, 0}, {0, 0, 0}, checker(8)));
        scene.billboards.push_back(testing::make_billboard({-3, 3, -5}, {-3, -3, -5}, {3, 3, -5}, {0.2, 0.3, 0.9}));
        scene.spheres.push_back(testing::make_sphere({0.5, 0, -2}, 0.5, {0.9, 0.9, 0.1}));
        expect_close_to_reference(scene, "eye at z = " + std::to_string(z));
    }
}

// Abutting billboards seen at grazing angles: no crack between them may show what is behind.
TEST(Stress, AbuttingBillboardsAtGrazingAnglesLeaveNoCracks) {
    Scene scene = testing::make_scene({0.37, 0.25, 12}, {0.2, 0, -30}, {0, 1, 0}, 40, 240, 120);
    scene.background = {1, 0, 1};  // a crack would show magenta
    for (int i = -6; i < 6; ++i)
        for (int j = 0; j < 40; ++j) {
            // A floor of 1x1 tiles at y = 0, seen from 0.25 above: grazing far away.
            double x = i, z = -j;
            Color color = (i + j) % 2 ? Color{0.8, 0.8, 0.8} : Color{0.2, 0.2, 0.2};
            scene.billboards.push_back(testing::make_billboard({x, 0, z - 1}, {x, 0, z}, {x + 1, 0, z - 1}, color));
        }
    scene.billboards.push_back(testing::make_billboard({-50, 0, 5}, {-50, -0.0001, 5}, {50, 0, 5}, {0, 0, 0}));
    expect_close_to_reference(scene, "grazing floor of abutting billboards");
    // A crack is a magenta pixel between two floor pixels (left and right, or above and below).
    Image image = testing::render_with_kernels(scene);
    auto magenta = [&image](int col, int row) {
        return image.at(col, row, 0) == 255 && image.at(col, row, 1) == 0 && image.at(col, row, 2) == 255;
    };
    int cracks = 0;
    for (int row = 1; row + 1 < image.height; ++row)
        for (int col = 1; col + 1 < image.width; ++col)
            cracks += magenta(col, row) && ((!magenta(col - 1, row) && !magenta(col + 1, row)) ||
                                            (!magenta(col, row - 1) && !magenta(col, row + 1)));
    EXPECT_EQ(cracks, 0);
}

TEST(Stress, SphereWhoseSurfaceTouchesTheEye) {
    Scene scene = testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 120, 90);
    scene.has_sun = true;
    scene.sun_location = {3, 5, 2};
    scene.spheres.push_back(testing::make_sphere({0, 0, -1}, 1, {0.8, 0.5, 0.3}));     // eye on its surface, looking in
    scene.spheres.push_back(testing::make_sphere({1.2, 0, 0}, 1.2, {0.3, 0.5, 0.8}));   // eye on its surface, beside
    scene.billboards.push_back(testing::make_billboard({-5, 5, -6}, {-5, -5, -6}, {5, 5, -6}, {0.9, 0.9, 0.9}));
    expect_close_to_reference(scene, "spheres touching the eye");
}

// ---------------------------------------------------------------------------------------
// Extreme but valid numbers (docs/scene-format.md, Numeric ranges): directions of any finite
// length, and scenes at the smallest and largest supported lengths and coordinates. Each is
// checked twice: the reference against an independent expectation (the same picture as an
// ordinary scene, or the pixels geometry says a shape covers), and the kernels against the
// reference.

// Two renderings of the same picture: at most 0.1% of the pixels may differ (a direction
// rounded one ulp differently can move a silhouette pixel), and the picture must not be
// blank, so that two blank images cannot pass.
void expect_same_picture(const Image& image, const Image& expected, const std::string& what) {
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i < expected.rgba.size(); i += 4)
        colours.insert(expected.rgba[i] << 16 | expected.rgba[i + 1] << 8 | expected.rgba[i + 2]);
    ASSERT_GE(colours.size(), 3u) << what << ": the expected picture is nearly blank";
    const testing::ImageComparison comparison = testing::compare_images(image, expected);
    EXPECT_LE(comparison.differing_fraction(), 0.001)
        << what << ": " << comparison.differing << " pixels differ from the expected picture";
}

std::string describe(const Vec3& v) {
    std::ostringstream text;
    text << "[" << v.x << ", " << v.y << ", " << v.z << "]";
    return text.str();
}

Scene with_camera(Scene scene, const Vec3& eye, const Vec3& lookat, const Vec3& up) {
    scene.camera_path = {{eye, lookat}};
    scene.up = up;
    return scene;
}

// small_world with two impostors, which turn about `up` (upright) or face the eye (free).
Scene world_with_impostors(const Vec3& up) {
    Scene scene = small_world({0, 0, 0});
    scene.up = up;
    Impostor upright;
    upright.center = {2.4, 0.3, -0.5};
    upright.width = 1;
    upright.height = 2;
    upright.ambient = {0.9, 0.9, 0.2};
    scene.impostors.push_back(upright);
    Impostor free = upright;
    free.center = {-1, -1.6, 1};
    free.facing = Facing::Free;
    free.ambient = {0.3, 0.3, 0.9};
    scene.impostors.push_back(free);
    return scene;
}

// `up` may have any finite non-zero length; 1e-300 and 1e300 once drew a blank image, and an
// up whose cross product with the view overflows drew nothing either.
TEST(Stress, UpOfAnyFiniteLengthGivesTheSamePicture) {
    const std::vector<std::pair<Vec3, Vec3>> cases = {
        {{0, 1e-300, 0}, {0, 1, 0}},
        {{0, 1e300, 0}, {0, 1, 0}},
        {{0, 5e-324, 0}, {0, 1, 0}},  // the smallest subnormal double
        {{1.5e308, 1.5e308, -1.5e308}, {1, 1, -1}},
    };
    for (const auto& [extreme, ordinary] : cases) {
        const std::string what = "up " + describe(extreme);
        const Scene scene = world_with_impostors(extreme);
        expect_same_picture(testing::render_with_reference(scene),
                            testing::render_with_reference(world_with_impostors(ordinary)), what + " (reference)");
        expect_close_to_reference(scene, what);
    }
}

// The eye 1e-300 from the look-at point: the view direction is still defined, and the picture
// is the one seen from the same eye towards a far look-at point in the same direction.
TEST(Stress, EyeATinyDistanceFromTheLookatPoint) {
    const Scene world = small_world({0, -0.5, -8});
    for (const Vec3& offset : {Vec3{0, 0, 1}, Vec3{0.05, 0.06, 1}}) {
        const Vec3 eye = offset * 1e-300;
        const Scene scene = with_camera(world, eye, {0, 0, 0}, {0, 1, 0});
        const std::string what = "eye 1e-300 from lookat along " + describe(offset);
        expect_same_picture(testing::render_with_reference(scene),
                            testing::render_with_reference(with_camera(world, eye, -offset, {0, 1, 0})), what + " (reference)");
        expect_close_to_reference(scene, what);
    }
}

// The whole of small_world scaled down until its smallest radius is the smallest supported
// length (1e-15), and scaled up and moved until it reaches the coordinate limit 1e15: the
// same picture as at scale 1.
TEST(Stress, SmallWorldAtTheSmallestAndLargestSupportedScales) {
    const Image expected = testing::render_with_reference(small_world({0, 0, 0}));
    const Scene tiny = small_world({0, 0, 0}, 2.5e-15);
    EXPECT_NEAR(tiny.spheres[1].radius, 1e-15, 1e-30);
    expect_same_picture(testing::render_with_reference(tiny), expected, "world of scale 2.5e-15 (reference)");
    expect_close_to_reference(tiny, "world of scale 2.5e-15");

    const Scene huge = small_world({4e14, 4e14, -4e14}, 2e13);
    EXPECT_EQ(huge.sun_location.y, 1e15);  // at the coordinate limit
    expect_same_picture(testing::render_with_reference(huge), expected, "world of scale 2e13 at 4e14 (reference)");
    expect_close_to_reference(huge, "world of scale 2e13 at 4e14");
}

// small_world's meshes: a smooth sphere mesh (corner normals) shadowing a floor grid, and a
// faceted one (geometric normals), placed and sized as small_world places its spheres; the
// smallest triangle edge is about 0.06 scale.
Scene mesh_world(const Vec3& origin, double scale = 1) {
    const auto at = [&](double x, double y, double z) { return origin + Vec3{x, y, z} * scale; };
    Scene scene = testing::make_scene(at(0.5, 1.2, 8), origin, {0, 1, 0}, 50, 160, 120);
    scene.has_sun = true;
    scene.sun_location = at(20, 30, 15);
    testing::add_mesh(scene, testing::sphere_mesh(origin, 1 * scale, 24, 12, true), {0.9, 0.4, 0.2});
    testing::add_mesh(scene, testing::sphere_mesh(at(0.7, 1.6, 0.6), 0.4 * scale, 10, 6, false), {0.2, 0.9, 0.4});
    testing::add_mesh(scene, testing::grid_mesh(at(-4, -1.2, -3), Vec3{8, 0, 0} * scale, Vec3{0, 0.3, 6} * scale, 8, 6),
                      {0.3, 0.5, 0.9});
    return scene;
}

// mesh_world at scales whose weights and squared areas leave float's range unless rescaled
// (triangle.cl: edges near 1e-16 and 1e12, weights near 1e-30 and 1e28, their products with
// distances beyond 1e38): the same picture as at scale 1, and the kernels the reference's.
TEST(Stress, MeshWorldAtTheSmallestAndLargestSupportedScales) {
    const Image expected = testing::render_with_reference(mesh_world({0, 0, 0}));
    for (const double scale : {2.5e-15, 1e-12, 1e10}) {
        std::ostringstream what;
        what << "mesh world of scale " << scale;
        const Scene scene = mesh_world({0, 0, 0}, scale);
        expect_same_picture(testing::render_with_reference(scene), expected, what.str() + " (reference)");
        expect_close_to_reference(scene, what.str());
    }
    const Scene huge = mesh_world({4e14, 4e14, -4e14}, 2e13);
    expect_same_picture(testing::render_with_reference(huge), expected, "mesh world of scale 2e13 at 4e14 (reference)");
    expect_close_to_reference(huge, "mesh world of scale 2e13 at 4e14");
}

// A ball mesh a thousand and ten thousand times its size away, through a lens narrow enough to
// show it at the size it has from ten: the edge volumes of its triangles must not be made of
// products of their corners' long distances (kernels/kinds/triangle.cl, edge_volume_normal),
// whose rounding broke the silhouette into blocks and put false shadows on the ball.
TEST(Stress, AMeshFarAwayThroughANarrowLens) {
    for (const auto& [distance, fov] : {std::pair{1000.0, 0.4}, std::pair{10000.0, 0.04}}) {
        Scene scene = testing::make_scene(Vec3{0.6, 0.5, 0.8} * distance, {0, 0.75, 0}, {0, 1, 0}, fov, 160, 120);
        scene.has_sun = true;
        scene.sun_location = {-50, 60, 20};
        testing::add_mesh(scene, testing::sphere_mesh({0, 0.75, 0}, 0.7, 24, 12, true), {1, 0.8, 0.2});
        std::ostringstream what;
        what << "ball mesh at " << distance;
        expect_close_to_reference(scene, what.str());
    }
}

// Ground triangles far larger than their distance from the eye, as people model a floor: 2e8
// across and 1.4 below the eye, level and tilted by a tenth, lit, with a sphere standing on them
// (its shadow on the floor, the floor cutting it). Their corners are 1e8 away, where float
// steps by 8: the t blended from the corners' distances along the ray was units off (a sixth of
// the level floor's pixels lit wrongly), and the tilted plane through the rounded corner and
// normal passed units off the eye's surroundings (the whole floor shaded wrongly, the sphere cut
// in the wrong place). The kernels now take t from the plane's offset from the eye, computed in
// double by the host, where it is the more exact.
TEST(Stress, GroundTrianglesFarLargerThanTheirDistanceFromTheEye) {
    for (const double tilt : {0.0, 0.1}) {
        Scene scene = testing::make_scene({0.3, 0.4, 3}, {0, -1, 0}, {0, 1, 0}, 60, 96, 72);
        scene.has_sun = true;
        scene.sun_location = {2, 3, 4};
        scene.spheres.push_back(testing::make_sphere({0.2, -0.9, -0.3}, 0.4, {0.9, 0.2, 0.2}));
        const double s = 1e8;
        testing::TestMesh floor;
        floor.triangles.push_back({Vec3{-s, -1 - tilt * s, -s}, Vec3{s, -1 + tilt * s, -s}, Vec3{0, -1, s}});
        testing::add_mesh(scene, floor, {0.8, 0.8, 0.8});
        expect_close_to_reference(scene, tilt == 0 ? "level floor 2e8 across" : "tilted floor 2e8 across");
    }
}

// A ground sphere (a planet under the eye) and ground billboards far larger than their
// distance from the eye, 1.4 below it, lit, with a sphere standing on them. The sphere's
// |eye - centre|^2 - r^2 cancelled in float (squares of 1e16 rounding by 6e8 for a radius of
// 1e8): whether the eye was inside came out at random, and the image black. A billboard 2e12
// across, tilted by a tenth, had its plane units off the eye (the corner rounded to float 1e12
// away) and vanished. The host gives both the eye's power and the plane's offset in double.
TEST(Stress, GroundSpheresAndBillboardsFarLargerThanTheirDistanceFromTheEye) {
    const auto ground_scene = [] {
        Scene scene = testing::make_scene({0.3, 0.4, 3}, {0, -1, 0}, {0, 1, 0}, 60, 96, 72);
        scene.has_sun = true;
        scene.sun_location = {2, 3, 4};
        scene.spheres.push_back(testing::make_sphere({0.2, -0.6, -0.3}, 0.4, {0.9, 0.2, 0.2}));
        return scene;
    };
    for (const double radius : {1e8, 1e14}) {
        Scene scene = ground_scene();
        scene.spheres.push_back(testing::make_sphere({0, -1 - radius, 0}, radius, {0.8, 0.8, 0.8}));
        std::ostringstream what;
        what << "ground sphere of radius " << radius;
        expect_close_to_reference(scene, what.str());
    }
    for (const double tilt : {0.0, 0.1}) {
        const double s = 1e12;
        Scene scene = ground_scene();
        scene.billboards.push_back(testing::make_billboard({-s, -1 - tilt * s, -s}, {-s, -1 - tilt * s, s},
                                                           {s, -1 + tilt * s, -s}, {0.8, 0.8, 0.8}));
        expect_close_to_reference(scene, tilt == 0 ? "level ground billboard 2e12 across" : "tilted ground billboard 2e12 across");
    }
}

// Whether the ray through (x, y, -1) (camera looking along -z, up +y) clearly meets a shape:
// 1 inside, 0 outside, -1 too close to its outline to say.
using Coverage = std::function<int(double x, double y)>;

// Every pixel whose centre is clearly inside shows `inside`, clearly outside shows `outside`:
// computed from the field of view alone, independently of either renderer.
void expect_coverage(const Image& image, const Scene& scene, const Coverage& covers, const Color& inside,
                     const Color& outside, const std::string& what) {
    const double half = std::tan(scene.fov_degrees * 3.14159265358979323846 / 360);
    const double larger = std::max(scene.width, scene.height);
    int wrong = 0, inside_count = 0;
    for (int row = 0; row < image.height; ++row)
        for (int col = 0; col < image.width; ++col) {
            const double x = (2 * (col + 0.5) / image.width - 1) * half * image.width / larger;
            const double y = (1 - 2 * (row + 0.5) / image.height) * half * image.height / larger;
            const int verdict = covers(x, y);
            if (verdict < 0) continue;
            inside_count += verdict;
            const Color& colour = verdict ? inside : outside;
            for (int c = 0; c < 3; ++c) wrong += image.at(col, row, c) != reference::to_byte(colour[c]);
        }
    EXPECT_GT(inside_count, 100) << what << ": the shape should cover many pixels";
    EXPECT_EQ(wrong, 0) << what << ": pixels of the wrong colour";
}

void expect_coverage_in_both(const Scene& scene, const Coverage& covers, const Color& inside, const Color& outside,
                             const std::string& what) {
    expect_coverage(testing::render_with_reference(scene), scene, covers, inside, outside, what + " (reference)");
    expect_coverage(testing::render_with_kernels(scene), scene, covers, inside, outside, what + " (kernels)");
    expect_close_to_reference(scene, what);
}

// A sphere of radius r centred on the axis at distance d covers the rays within the angle
// asin(r / d) of it: x^2 + y^2 < r^2 / (d^2 - r^2). 1% either side of the outline is left out.
Coverage sphere_on_axis(double r, double d) {
    const double limit = r * r / (d * d - r * r);
    return [limit](double x, double y) {
        const double q = (x * x + y * y) / limit;
        return q < 0.98 ? 1 : q > 1.02 ? 0 : -1;
    };
}

TEST(Stress, SphereOfTheSmallestSupportedRadiusSeenHeadOn) {
    Scene scene = testing::make_scene({0, 0, 4e-15}, {0, 0, 0}, {0, 1, 0}, 40, 120, 90);
    scene.background = {0.1, 0.2, 0.3};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1e-15, {0.9, 0.6, 0.2}));
    expect_coverage_in_both(scene, sphere_on_axis(1e-15, 4e-15), {0.9, 0.6, 0.2}, {0.1, 0.2, 0.3}, "sphere of radius 1e-15");
}

// The eye at the coordinate limit inside a sphere of the largest radius, looking at a sphere
// of radius 1e14 at the opposite limit.
TEST(Stress, SpheresAtTheLargestSupportedRadiusAndCoordinates) {
    Scene scene = testing::make_scene({0, 0, 1e15}, {0, 0, 0}, {0, 1, 0}, 30, 120, 90);
    scene.background = {1, 0, 1};  // never seen: everything lies inside the big sphere
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1e16, {0.2, 0.4, 0.9}));
    scene.spheres.push_back(testing::make_sphere({0, 0, -1e15}, 1e14, {0.9, 0.3, 0.1}));
    expect_coverage_in_both(scene, sphere_on_axis(1e14, 2e15), {0.9, 0.3, 0.1}, {0.2, 0.4, 0.9}, "spheres of radius 1e16 and 1e14");
}

// A square billboard whose edges are the smallest supported length, 1e-15, seen head-on from
// 3e-15: it covers |x|, |y| < 0.5e-15 / 3e-15.
TEST(Stress, BillboardOfTheSmallestSupportedEdgeSeenHeadOn) {
    Scene scene = testing::make_scene({0, 0, 3e-15}, {0, 0, 0}, {0, 1, 0}, 40, 120, 90);
    const double h = 0.5e-15;
    scene.billboards.push_back(testing::make_billboard({-h, h, 0}, {-h, -h, 0}, {h, h, 0}, {0.3, 0.9, 0.5}));
    const Coverage square = [](double x, double y) {
        const double q = std::max(std::fabs(x), std::fabs(y)) * 6;
        return q < 0.98 ? 1 : q > 1.02 ? 0 : -1;
    };
    expect_coverage_in_both(scene, square, {0.3, 0.9, 0.5}, {0, 0, 0}, "billboard of edge 1e-15");
}

}  // namespace
}  // namespace clr
