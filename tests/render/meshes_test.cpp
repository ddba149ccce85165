// Mesh triangles in whole kernel images (kernels/kinds/triangle.cl against the reference's
// kinds/triangle_reference.cpp): smooth and faceted meshes lit by the sun with shadows,
// mirror meshes, both sides of a triangle, a concave mesh shadowing itself, no false shadow
// on a flat mesh, and no crack where rays pass exactly through shared edges and vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "render/feature_set.h"
#include "render/renderer.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using testing::add_mesh;
using testing::grid_mesh;
using testing::sphere_mesh;

// A smooth ball, a faceted ball and a sphere above a tessellated floor, lit by the sun: the
// balls' shading and their shadows on the floor and on each other.
Scene lit_meshes() {
    Scene scene = testing::make_scene({0, 3, 9}, {0, 0, 0}, {0, 1, 0}, 55, 160, 120);
    scene.background = {0.1, 0.1, 0.3};
    scene.has_sun = true;
    scene.sun_location = {6, 9, 5};
    add_mesh(scene, sphere_mesh({-1.6, 0, 0}, 1, 24, 12, true), {0.9, 0.2, 0.2});
    add_mesh(scene, sphere_mesh({1.2, 0.2, -0.5}, 0.9, 10, 6, false), {0.2, 0.9, 0.3});
    add_mesh(scene, grid_mesh({-5, -1.2, 4}, {10, 0, 0}, {0, 0, -10}, 7, 7), {0.8, 0.8, 0.8});
    scene.spheres.push_back(testing::make_sphere({0, 2.2, 1}, 0.5, {0.9, 0.9, 0.2}));
    return scene;
}

TEST(Meshes, LitMeshesAndTheirShadowsMatchTheReference) {
    const Scene scene = lit_meshes();
    testing::expect_kernels_match_reference(scene, "screen tiles");
    RendererOptions brute_force;
    brute_force.screen_tiles = false;
    testing::expect_kernels_match_reference(scene, "brute force", brute_force);
    RendererOptions double_precision;
    double_precision.double_precision = true;
    testing::expect_kernels_match_reference(scene, "double", double_precision);
}

TEST(Meshes, FlatShadedMeshesMatchTheReference) {
    Scene scene = lit_meshes();
    scene.has_sun = false;
    testing::expect_kernels_match_reference(scene, "flat");
}

// A mirror made of a tessellated wall, and a faceted mirror ball, reflecting the lit scene.
TEST(Meshes, MirrorMeshesReflectLikeMirrorSpheres) {
    Scene scene = lit_meshes();
    add_mesh(scene, grid_mesh({-5, -1.2, -3}, {10, 0, 0}, {0, 6, 0}, 3, 2), {0, 0, 0}, true);
    add_mesh(scene, sphere_mesh({2.8, 1.5, 1}, 0.7, 12, 6, true), {0, 0, 0}, true);
    scene.max_depth = 3;
    testing::expect_kernels_match_reference(scene, "mirrors");
    const Image image = testing::render_with_kernels(scene);
    Scene without = lit_meshes();
    EXPECT_NE(image.rgba, testing::render_with_kernels(without).rgba);
}

// A still of meshes, lit and mirrored and flat, whose own program the program store does not
// hold, may render with the store's general program instead: the same bytes.
TEST(Meshes, TheGeneralProgramRendersTheSameBytes) {
    // Sunlit without mirrors: the scene's own program and the general one without mirrors
    // trace 16 shadow rays at a time (packet/shadows16.cl), the general one with mirrors each
    // alone; all three give the same bytes.
    testing::expect_general_program_renders_the_same(lit_meshes());
    FeatureSet mirrored;
    mirrored.mirrors = true;
    RendererOptions each_alone;
    each_alone.features = FeatureSet::general(mirrored);
    EXPECT_TRUE(testing::render_with_kernels(lit_meshes()).rgba == testing::render_with_kernels(lit_meshes(), each_alone).rgba);
    Scene scene = lit_meshes();
    add_mesh(scene, grid_mesh({-5, -1.2, -3}, {10, 0, 0}, {0, 6, 0}, 3, 2), {0, 0, 0}, true);
    scene.max_depth = 3;
    testing::expect_general_program_renders_the_same(scene);
    scene.has_sun = false;
    testing::expect_general_program_renders_the_same(scene);
}

// A mesh has no back: a triangle whose corners are listed the other way round shows the
// same, lit from the viewer's side.
TEST(Meshes, BothSidesOfATriangleAreLitAlike) {
    Scene front = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 48, 48);
    front.has_sun = true;
    front.sun_location = {1, 2, 6};
    Scene back = front;
    testing::TestMesh one;
    one.triangles.push_back({Vec3{-2, -2, 0}, Vec3{2, -2, 0}, Vec3{0, 2, 0}});
    testing::TestMesh reversed;
    reversed.triangles.push_back({Vec3{-2, -2, 0}, Vec3{0, 2, 0}, Vec3{2, -2, 0}});
    add_mesh(front, one, {0.9, 0.6, 0.3});
    add_mesh(back, reversed, {0.9, 0.6, 0.3});
    const Image image = testing::render_with_kernels(front);
    EXPECT_EQ(image.rgba, testing::render_with_kernels(back).rgba);
    EXPECT_GT(image.at(24, 30, 0), 100) << "lit, not black";
    testing::expect_kernels_match_reference(back, "reversed");
}

// A floor of many triangles, the sun low over it and nothing above it: no pixel of the floor
// may be in shadow. A shadow ray leaving one triangle must not meet its neighbours, which
// rounding puts a hair above the point it leaves.
TEST(Meshes, AFlatMeshCastsNoShadowOnItself) {
    // Seen from afar, so that the hit points' rounding is large, with the sun 2 degrees up.
    Scene scene = testing::make_scene({0, 400, 900}, {0, 0, 0}, {0, 1, 0}, 8, 256, 192);
    scene.background = {0, 0, 1};
    scene.has_sun = true;
    scene.sun_location = {-5000, 200, -300};
    add_mesh(scene, grid_mesh({-60, 0, 60}, {120, 0, 0}, {0, 0, -120}, 60, 60), {1, 1, 1});
    for (bool double_precision : {false, true}) {
        RendererOptions options;
        options.double_precision = double_precision;
        const Image image = testing::render_with_kernels(scene, options);
        long long floor = 0, dark = 0;
        for (int row = 0; row < image.height; ++row)
            for (int col = 0; col < image.width; ++col) {
                if (image.at(col, row, 2) == 255 && image.at(col, row, 0) == 0) continue;  // background
                ++floor;
                if (image.at(col, row, 0) == 0) ++dark;
            }
        EXPECT_GT(floor, 5000);
        EXPECT_EQ(dark, 0) << (double_precision ? "double" : "float") << ": floor pixels in a false shadow";
    }
}

// A flat mesh lit by point lights that graze it, 0.1 and 0.03 degrees above its plane, with a
// highlight of exponent 0 (all of k_s wherever a light counts): no point of it may be in
// shadow. A shadow ray leaving one triangle crosses its neighbours' plane, which rounding puts
// a hair off the point, at that hair over the ray's slant, beyond any gap in t: with a gap of
// 1.5e-5 of the point's distance, 0.09% (0.1 degrees) and 0.3% (0.03) of the image's pixels
// lost the lights' highlight.
TEST(Meshes, ALightGrazingAFlatMeshFindsNoShadowOfItOnIt) {
    const double kPi = 3.14159265358979323846;
    const Vec3 centre{0.2, -0.9, -0.5};
    for (double degrees : {0.1, 0.03}) {
        Scene scene = testing::make_scene({1.8, -0.5, 2.3}, centre, {0, 1, 0}, 50, 160, 120);
        scene.background = {0.07, 0.11, 0.13};
        add_mesh(scene, grid_mesh(centre - Vec3{1.25, 1.25, 0}, {2.5, 0, 0}, {0, 2.5, 0}, 8, 8), {0.1, 0.1, 0.1});
        Material material;
        material.diffuse = {0.5, 0.5, 0.5};
        material.specular = {0.5, 0.5, 0.5};
        material.phong_exponent = 0;
        scene.materials.push_back(material);
        scene.meshes[0].material = static_cast<std::uint32_t>(scene.materials.size() - 1);
        const double up = degrees * kPi / 180;
        for (double around : {30.0, 158.0, 300.0}) {
            const double a = around * kPi / 180;
            const Vec3 away{std::cos(up) * std::cos(a), std::cos(up) * std::sin(a), std::sin(up)};
            scene.lights.push_back({centre + away * 20, {0.3, 0.3, 0.3}});
        }
        const std::string what = "light " + std::to_string(degrees) + " degrees over the mesh";
        testing::expect_kernels_match_reference(scene, what, {}, 0);
        RendererOptions double_precision;
        double_precision.double_precision = true;
        testing::expect_kernels_match_reference(scene, what + " (double)", double_precision, 0);
    }
}

// A fold: a wall standing on a floor, both of one mesh, the sun behind the wall. The wall
// shadows the floor in front of it: a shadow ray skips only the triangle it leaves.
TEST(Meshes, AConcaveMeshShadowsItself) {
    Scene scene = testing::make_scene({0, 3, 8}, {0, 0, 0}, {0, 1, 0}, 60, 96, 72);
    scene.has_sun = true;
    scene.sun_location = {0, 4, -10};
    testing::TestMesh fold = grid_mesh({-4, 0, 4}, {8, 0, 0}, {0, 0, -6}, 4, 3);
    const testing::TestMesh wall = grid_mesh({-2, 0, -1}, {4, 0, 0}, {0, 3, 0}, 2, 2);
    fold.triangles.insert(fold.triangles.end(), wall.triangles.begin(), wall.triangles.end());
    add_mesh(scene, fold, {0.9, 0.9, 0.9});
    const Image image = testing::render_with_kernels(scene);
    // The floor just in front of the wall, at (0, 0, -0.5), lies in its shadow.
    EXPECT_EQ(image.at(48, 44, 0), 0);
    testing::expect_kernels_match_reference(scene, "fold");
}

// Every pixel-centre ray passes through an edge or vertex that several triangles share: a
// grid whose vertices sit at the pixel centres' points of the plane, its diagonals through
// them too. The mesh fills the image, so a single background pixel is a crack.
long long background_pixels(const Scene& scene, const RendererOptions& options) {
    const Image image = testing::render_with_kernels(scene, options);
    long long count = 0;
    for (int row = 0; row < image.height; ++row)
        for (int col = 0; col < image.width; ++col) count += image.at(col, row, 1) == 0;
    return count;
}

TEST(Meshes, RaysThroughSharedEdgesAndVerticesFindNoCrack) {
    // 64 x 64 pixels at 90 degrees from 32 units: pixel centres meet z = 0 at half-integers.
    Scene scene = testing::make_scene({0, 0, 32}, {0, 0, 0}, {0, 1, 0}, 90, 64, 64);
    add_mesh(scene, grid_mesh({-32.5, -32.5, 0}, {65, 0, 0}, {0, 65, 0}, 65, 65), {1, 1, 1});
    // A fan of thin triangles around the centre of an odd-sized image, whose middle ray runs
    // exactly through the fan's shared vertex.
    Scene fan = testing::make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60, 65, 65);
    testing::TestMesh blades;
    const int count = 97;
    for (int k = 0; k < count; ++k) {
        const double a0 = 2 * 3.14159265358979 * k / count, a1 = 2 * 3.14159265358979 * (k + 1) / count;
        blades.triangles.push_back({Vec3{0, 0, 0}, Vec3{30 * std::cos(a0), 30 * std::sin(a0), 0},
                                    Vec3{30 * std::cos(a1), 30 * std::sin(a1), 0}});
    }
    add_mesh(fan, blades, {1, 1, 1});
    for (bool tiles : {true, false})
        for (bool double_precision : {false, true}) {
            RendererOptions options;
            options.screen_tiles = tiles;
            options.double_precision = double_precision;
            const std::string what = std::string(tiles ? "tiles" : "brute force") + (double_precision ? ", double" : "");
            EXPECT_EQ(background_pixels(scene, options), 0) << what << ": cracks in the grid";
            EXPECT_EQ(background_pixels(fan, options), 0) << what << ": cracks in the fan";
        }
    // Tilted, so that the edges run across the rays at every angle; the grid reaches well
    // past the view.
    Scene tilted = testing::make_scene({3, -2, 30}, {0.5, 0.25, 0}, {0, 1, 0}, 90, 64, 64);
    add_mesh(tilted, grid_mesh({-100.5, -100.5, 0}, {201, 0, 0}, {0, 201, 0}, 201, 201), {1, 1, 1});
    EXPECT_EQ(background_pixels(tilted, {}), 0) << "tilted grid";
}

// A grid mesh on an oblique plane whose vertices lie on the camera's rays through the pixels'
// corners (every pixel-centre ray crosses a shared diagonal) or through the pixel centres
// (every one passes through a shared vertex). It fills the image: a pixel of the background
// is a crack, in the reference as in the kernels.
// `diagonals` picks each cell's diagonal (bit k of a cell's draw: the other one), so that
// vertices are shared by four to eight triangles.
Scene pixel_ray_grid(const Vec3& eye, const Vec3& lookat, double fov, int width, int height, const Vec3& plane_normal,
                     bool through_corners, std::mt19937* diagonals = nullptr) {
    Scene scene = testing::make_scene(eye, lookat, {0, 1, 0}, fov, width, height);
    const Vec3 w = normalize(eye - lookat), u = normalize(cross(Vec3{0, 1, 0}, w)), v = cross(w, u);
    const double half = std::tan(fov * 3.14159265358979323846 / 360);
    const double half_w = width >= height ? half : half * width / height;
    const double half_h = width >= height ? half * height / width : half;
    const Vec3 n = normalize(plane_normal);
    const int columns = through_corners ? width + 1 : width, rows = through_corners ? height + 1 : height;
    std::vector<Vec3> points;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            const double x = through_corners ? 2.0 * j / width - 1 : 2 * (j + 0.5) / width - 1;
            const double y = through_corners ? 1 - 2.0 * i / height : 1 - 2 * (i + 0.5) / height;
            const Vec3 d = normalize(u * (x * half_w) + v * (y * half_h) - w);
            points.push_back(eye + d * (dot(lookat - eye, n) / dot(d, n)));
        }
    testing::TestMesh grid;
    for (int i = 0; i + 1 < rows; ++i)
        for (int j = 0; j + 1 < columns; ++j) {
            const Vec3 &a = points[i * columns + j], &b = points[i * columns + j + 1];
            const Vec3 &c = points[(i + 1) * columns + j], &e = points[(i + 1) * columns + j + 1];
            if (diagonals && (*diagonals)() % 2) {
                grid.triangles.push_back({a, b, c});
                grid.triangles.push_back({b, e, c});
            } else {
                grid.triangles.push_back({a, b, e});
                grid.triangles.push_back({a, e, c});
            }
        }
    add_mesh(scene, grid, {1, 1, 1});
    return scene;
}

long long interior_background_pixels(const Image& image, bool interior) {
    long long count = 0;
    for (int row = interior; row < image.height - interior; ++row)
        for (int col = interior; col < image.width - interior; ++col) count += image.at(col, row, 1) == 0;
    return count;
}

TEST(Meshes, AGridOnThePixelRaysHasNoCrackInTheReferenceNorInTheKernels) {
    const Scene edges = pixel_ray_grid({-0.9, 0.4, 3.6}, {-0.6, -0.5, -0.9}, 40, 12, 9, {0.1, -0.8, 0.5}, true);
    const Scene vertices = pixel_ray_grid({-2.7, 4.6, -3.7}, {0.4, -0.8, -0.5}, 90, 40, 30, {-0.6, 0.3, -0.1}, false);
    for (const auto& [scene, what] : {std::pair{&edges, "edges"}, std::pair{&vertices, "vertices"}}) {
        // The vertex grid's outer pixels reach past its last vertices: only the inner ones count.
        const bool interior = scene == &vertices;
        EXPECT_EQ(interior_background_pixels(testing::render_with_reference(*scene), interior), 0)
            << what << ": cracks in the reference";
        for (bool double_precision : {false, true}) {
            RendererOptions options;
            options.double_precision = double_precision;
            EXPECT_EQ(interior_background_pixels(testing::render_with_kernels(*scene, options), interior), 0)
                << what << ": cracks in the kernels" << (double_precision ? " (double)" : "");
        }
    }
}


// Random oblique grids whose vertices lie on the pixel-centre rays, each cell's diagonal drawn
// at random: every pixel's ray passes through a vertex that four to eight triangles share,
// 8,512 of them inside the grids. Each edge's side, decided on its own from a volume rounded on
// its own, left 0.15% of such vertices (0.21% in the reference) outside every triangle around
// them; decided exactly where it is near zero (kernels/kinds/triangle_sides.cl), none.
TEST(Meshes, RaysThroughVerticesOfObliqueGridsFindNoCrackOnAnyPath) {
    std::mt19937 random(20261128);
    std::uniform_real_distribution<double> unit(-1, 1);
    long long reference = 0, tiles = 0, bvh_packets = 0, per_pixel = 0, in_double = 0;
    for (int camera = 0; camera < 8; ++camera) {
        const Vec3 lookat{0.3 * unit(random), 0.3 * unit(random), 0.3 * unit(random)};
        const Vec3 eye = lookat + normalize(Vec3{unit(random), unit(random), unit(random)}) * (5 + 3 * unit(random));
        // A plane that the view meets at least 35 degrees from edge on.
        const Vec3 view = normalize(eye - lookat);
        Vec3 normal = normalize(Vec3{unit(random), unit(random), unit(random)});
        const double facing = dot(normal, view);
        if (std::fabs(facing) < 0.6) normal = normalize(normal + view * (facing < 0 ? -1.0 : 1.0));
        const Scene scene = pixel_ray_grid(eye, lookat, 55 + 25 * unit(random), 40, 30, normal, false, &random);
        reference += interior_background_pixels(testing::render_with_reference(scene), true);
        RendererOptions options;
        tiles += interior_background_pixels(testing::render_with_kernels(scene, options), true);
        options.packets_walk_bvh = true;
        bvh_packets += interior_background_pixels(testing::render_with_kernels(scene, options), true);
        options.packets_walk_bvh.reset();
        options.per_pixel = true;
        per_pixel += interior_background_pixels(testing::render_with_kernels(scene, options), true);
        options.per_pixel.reset();
        options.double_precision = true;
        in_double += interior_background_pixels(testing::render_with_kernels(scene, options), true);
    }
    EXPECT_EQ(reference, 0) << "cracks in the reference";
    EXPECT_EQ(tiles, 0) << "cracks in the kernels' screen tiles";
    EXPECT_EQ(bvh_packets, 0) << "cracks in the kernels' packets through the BVH";
    EXPECT_EQ(per_pixel, 0) << "cracks in the kernels' rays one per pixel";
    EXPECT_EQ(in_double, 0) << "cracks in the kernels in double";
}

// An eye that lies in a triangle's plane meets it at t = 0, which is no hit: the floor of a
// scene whose camera stands at floor height is not seen, nor are the faces of a cube whose
// face or edge holds the eye; an eye just above the floor sees it below the horizon only.
// (The kernels' t blends the corners' distances, which for such an eye rounded to noise of
// either sign: 37-90% of the pixels showed a speckled surface.)
TEST(Meshes, AnEyeInATrianglesPlaneSeesNothingOfItThere) {
    auto scene_from = [](const Vec3& eye, const Vec3& look_at, bool sun) {
        Scene scene = testing::make_scene(eye, look_at, {0, 1, 0}, 60, 96, 72);
        scene.background = {0.2, 0.2, 0.3};
        scene.has_sun = sun;
        scene.sun_location = {3, 9, 6};
        scene.spheres.push_back(testing::make_sphere({0, 0.5, 0}, 0.5, {1, 0, 0}));
        return scene;
    };
    auto with_floor = [&](double eye_height, bool sun) {
        Scene scene = scene_from({0.3, eye_height, 4}, {0, eye_height, 0}, sun);
        add_mesh(scene, grid_mesh({-10, 0, 10}, {20, 0, 0}, {0, 0, -20}, 3, 3), {0.2, 0.8, 0.2});
        return scene;
    };
    // A cube of side 2 from (-1, -1, -1) to (1, 1, 1), each face a grid of 2 x 2 squares.
    auto with_cube = [&](const Vec3& eye, const Vec3& look_at) {
        Scene scene = scene_from(eye, look_at, true);
        scene.spheres.clear();
        scene.spheres.push_back(testing::make_sphere({-3, 0, -4}, 1, {1, 0, 0}));
        for (double side : {-1.0, 1.0}) {
            add_mesh(scene, grid_mesh({-1, -1, side}, {2, 0, 0}, {0, 2, 0}, 2, 2), {0.8, 0.8, 0.2});
            add_mesh(scene, grid_mesh({side, -1, -1}, {0, 0, 2}, {0, 2, 0}, 2, 2), {0.2, 0.8, 0.8});
            add_mesh(scene, grid_mesh({-1, side, -1}, {2, 0, 0}, {0, 0, 2}, 2, 2), {0.8, 0.2, 0.8});
        }
        return scene;
    };
    // The eye on a triangle's corner (its second), its other corners where the doubles of the
    // eye's distance from the plane, measured from the first corner, came to 7e-15: the kernels
    // took that for "in front" and drew the triangle over nine tenths of the view.
    auto on_corner = [&](bool sun) {
        Scene scene = scene_from({0, 0, 50}, {0, 0, 0}, sun);
        scene.spheres.clear();
        testing::TestMesh triangle;
        triangle.triangles.push_back({Vec3{-63, -49, -50}, Vec3{0, 0, 50}, Vec3{-35.25, -48.75, -25}});
        add_mesh(scene, triangle, {0.4, 0.8, 0.4});
        return scene;
    };
    const std::vector<std::pair<Scene, std::string>> cases = {
        {on_corner(false), "eye on a triangle's corner"},
        {on_corner(true), "eye on a triangle's corner, sunlit"},
        {with_floor(0, false), "eye on the floor"},
        {with_floor(0, true), "eye on the floor, sunlit"},
        {with_floor(1e-9, false), "eye 1e-9 above the floor"},
        {with_cube({1, 1, 0.3}, {-3, 0, -4}), "eye on the cube's edge"},
        {with_cube({0.4, 1, 0.3}, {-3, 0, -4}), "eye on the cube's face"},
    };
    for (const auto& [scene, what] : cases) {
        testing::expect_kernels_match_reference(scene, what, {}, 0.0001);
        RendererOptions double_precision;
        double_precision.double_precision = true;
        testing::expect_kernels_match_reference(scene, what + " (double)", double_precision, 0.0001);
    }
    // The eye just above the floor sees it below the horizon, as the reference does.
    const Image above = testing::render_with_reference(with_floor(1e-9, false));
    EXPECT_EQ(above.at(2, above.height - 3, 1), 204) << "the floor's green below the horizon";
    EXPECT_NE(above.at(2, 2, 1), 204) << "no floor above the horizon";
}

// A mirror or shadow ray that leaves a floor beside a wall meets the wall however near: the
// self gap that keeps a point from meeting its coplanar neighbours (kernels/kinds/triangle.cl)
// let rays through the concave crease, a line of background along a mirror corner seen
// through a narrow lens (1% of the pixels), and a lit line where the wall shades the floor.
TEST(Meshes, AConcaveCreaseHoldsMirrorAndShadowRays) {
    auto corner = [](bool mirror, bool sun) {
        Scene scene = testing::make_scene({0, 3, 5}, {0, 0, -5}, {0, 1, 0}, 0.05, 200, 200);
        scene.background = {0, 0, 0.3};
        scene.has_sun = sun;
        scene.sun_location = {0, 30, -60};  // behind the wall: the floor by the crease is in shade
        scene.max_depth = 4;
        const Color colour = mirror ? Color{0, 0, 0} : Color{0.8, 0.8, 0.8};
        add_mesh(scene, grid_mesh({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, 1, 1), colour, mirror);
        add_mesh(scene, grid_mesh({-5, 0, -5}, {10, 0, 0}, {0, 5, 0}, 1, 1), colour, mirror);
        scene.spheres.push_back(testing::make_sphere({0, 15, 43}, 10, {1, 0.8, 0}));
        return scene;
    };
    testing::expect_kernels_match_reference(corner(true, false), "mirror corner", {}, 0.0001);
    testing::expect_kernels_match_reference(corner(false, true), "shaded corner", {}, 0.0001);
}

}  // namespace
}  // namespace clr
