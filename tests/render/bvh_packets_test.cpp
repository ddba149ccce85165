// 16-ray packets that walk the BVH (RendererOptions::packets_walk_bvh, packet/bvh_walk16.cl,
// the CPU's path for large meshes) give the bytes of packets over screen-tile lists, in every
// shading mode the packet kernel has: flat colours from the walk with alpha-tested textures,
// the sun's shadow packets, mirrors, point lights with planes, several samples, double
// precision, the float output, frames of a moving camera, and bands and crops that cut the
// walk's 4x4 blocks.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "render/primary_ray_path.h"
#include "render/renderer.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using testing::add_mesh;
using testing::grid_mesh;
using testing::sphere_mesh;

RendererOptions walk(bool bvh) {
    RendererOptions options;
    options.per_pixel = false;  // packets, whatever the test device
    options.packets_walk_bvh = bvh;
    return options;
}

// Expects the walk's image of `scene` to be the lists' image, byte for byte (and, in the float
// output mode, value for value).
void expect_walk_gives_the_lists_bytes(const Scene& scene, const std::string& what, RendererOptions lists = walk(false)) {
    RendererOptions bvh = lists;
    bvh.packets_walk_bvh = true;
    const Image from_lists = testing::render_with_kernels(scene, lists);
    const Image from_bvh = testing::render_with_kernels(scene, bvh);
    EXPECT_TRUE(from_lists.rgba == from_bvh.rgba) << what;
    EXPECT_TRUE(from_lists.linear == from_bvh.linear) << what;
}

// Smooth and faceted meshes on a grid floor under the sun, with spheres and a billboard among
// them, some objects behind the eye.
Scene sunlit_meshes() {
    Scene scene = testing::make_scene({0, 3, 9}, {0, 0, 0}, {0, 1, 0}, 55, 131, 97);
    scene.has_sun = true;
    scene.only_ambient = false;
    scene.sun_location = {6, 9, 5};
    add_mesh(scene, sphere_mesh({-1.6, 0, 0}, 1, 24, 12, true), {0.9, 0.2, 0.2});
    add_mesh(scene, sphere_mesh({1.2, 0.2, -0.5}, 0.9, 10, 6, false), {0.2, 0.9, 0.3});
    add_mesh(scene, grid_mesh({-5, -1.2, 4}, {10, 0, 0}, {0, 0, -10}, 7, 7), {0.8, 0.8, 0.8});
    add_mesh(scene, sphere_mesh({0.5, 3, 11}, 1, 8, 4, false), {0.5, 0.5, 0.9});  // behind the eye
    scene.spheres.push_back(testing::make_sphere({0.2, 1.5, 1}, 0.5, {0.9, 0.9, 0.2}));
    scene.billboards.push_back(
        testing::make_billboard({2, 2, -2}, {2, 0, -2}, {3.5, 2, -3}, {0.3, 0.6, 0.9}));
    return scene;
}

TEST(BvhPackets, FromTwoHundredThousandTrianglesUnlessTheCameraClips) {
    EXPECT_FALSE(prefers_bvh_packets(0, false));
    EXPECT_FALSE(prefers_bvh_packets(kPacketBvhMinTriangles - 1, false));
    EXPECT_TRUE(prefers_bvh_packets(kPacketBvhMinTriangles, false));
    EXPECT_TRUE(prefers_bvh_packets(5'000'000, false));
    EXPECT_FALSE(prefers_bvh_packets(5'000'000, true));
    EXPECT_EQ(kPacketBvhMinTriangles, 200000u) << "docs/benchmarks.md and the bench's --help quote it";
}

TEST(BvhPackets, AWalkBuildsItsBvhAndAClippingCameraKeepsTheLists) {
    const Scene scene = sunlit_meshes();
    const Renderer small(testing::test_device(), scene, walk(false));
    EXPECT_FALSE(small.packets_walk_bvh());
    const Renderer walking(testing::test_device(), scene, walk(true));
    EXPECT_TRUE(walking.packets_walk_bvh());
    // Unlit, the lists need no BVH; the walk does.
    const Scene unlit = testing::make_random_scene(5, 30, 30);
    EXPECT_FALSE(Renderer(testing::test_device(), unlit, walk(false)).features().bvh);
    EXPECT_TRUE(Renderer(testing::test_device(), unlit, walk(true)).features().bvh);
    // Clipped rays search the lists lane by lane: no walk, whatever is asked.
    Scene clipped = scene;
    clipped.clip_near = 2;
    clipped.clip_far = 40;
    ASSERT_TRUE(clipped.clips());
    EXPECT_FALSE(Renderer(testing::test_device(), clipped, walk(true)).packets_walk_bvh());
    expect_walk_gives_the_lists_bytes(clipped, "clipped");
}

TEST(BvhPackets, FlatColoursWithTransparentTexelsGiveTheListsBytes) {
    // Spheres and billboards, half of them textured with transparent texels, unlit: the
    // colours come from the walk itself, texels included.
    const Scene scene = testing::make_random_scene(11, 120, 120);
    expect_walk_gives_the_lists_bytes(scene, "random unlit");
    testing::expect_kernels_match_reference(scene, "bvh packets", walk(true));
}

TEST(BvhPackets, SunlitMeshesGiveTheListsBytes) {
    Scene scene = sunlit_meshes();
    expect_walk_gives_the_lists_bytes(scene, "sunlit meshes");
    testing::expect_kernels_match_reference(scene, "bvh packets", walk(true));
    scene.sampling.samples_per_pixel = 3;
    RendererOptions in_double = walk(false);
    in_double.double_precision = true;
    expect_walk_gives_the_lists_bytes(scene, "3 samples");
    expect_walk_gives_the_lists_bytes(scene, "3 samples, double", in_double);
    RendererOptions linear = walk(false);
    linear.float_output = true;
    expect_walk_gives_the_lists_bytes(scene, "float output", linear);
}

// A walking packet renders a 4x4 block of pixels (render_block16): bands and crops that cut
// blocks anywhere, and a frame of 131x97, whose last blocks hang over its edges, still give
// every pixel its own bytes.
TEST(BvhPackets, BandsAndCropsThatCutItsBlocksGiveTheListsBytes) {
    const Scene scene = sunlit_meshes();
    for (int band_rows : {1, 5, 7}) {
        RendererOptions lists = walk(false);
        lists.band_rows = band_rows;
        expect_walk_gives_the_lists_bytes(scene, "bands of " + std::to_string(band_rows) + " rows", lists);
    }
    RendererOptions cropped = walk(false);
    cropped.crop = PixelRect{3, 70, 5, 62};
    expect_walk_gives_the_lists_bytes(scene, "a crop from (3, 5)", cropped);
    cropped.float_output = true;
    cropped.band_rows = 3;
    expect_walk_gives_the_lists_bytes(scene, "a crop in the float output mode, bands of 3 rows", cropped);
}

// Each screen tile finds where its packets enter the tree (packet/bvh_entries.cl) by the
// pyramid of its rays: a floor of 45,000 small triangles that fills most of the view makes the
// tree deep and each tile's pyramid meet few of its boxes, so that a tile's entries lie far
// below the root; cameras rolled, narrow, wide, grazing the floor and inside its box, with
// three samples a pixel and bands of 5 rows, see what the lists see.
TEST(BvhPackets, TilesEnteringTheTreeBelowItsRootGiveTheListsBytes) {
    Scene scene = testing::make_scene({0, 3, 9}, {0, 0, 0}, {0, 1, 0}, 55, 131, 97);
    add_mesh(scene, grid_mesh({-12, -1, 12}, {24, 0, 0}, {0, 0.8, -24}, 150, 150), {0.7, 0.7, 0.7});
    add_mesh(scene, sphere_mesh({1, 0.5, 0}, 1.2, 40, 20, true), {0.9, 0.3, 0.2});
    struct View {
        Vec3 eye, lookat, up;
        double fov;
        const char* what;
    };
    const View views[] = {
        {{0, 3, 9}, {0, 0, 0}, {0, 1, 0}, 55, "from above"},
        {{2, 6, 4}, {-1, -1, -3}, {1, 1, 0.2}, 35, "rolled"},
        {{0.3, 2, 3}, {0.5, 0, 0}, {0, 1, 0}, 8, "narrow"},
        {{0, 1.5, 6}, {0, 0, -4}, {0, 1, 0}, 140, "wide"},
        {{-9, -0.5, 10}, {6, -0.3, -9}, {0, 1, 0}, 60, "grazing the floor"},
        {{0, -0.2, 0}, {3, 1, -3}, {0, 0, 1}, 90, "inside the floor's box"},
    };
    for (const View& view : views) {
        scene.camera_path = {{view.eye, view.lookat}};
        scene.up = view.up;
        scene.fov_degrees = view.fov;
        expect_walk_gives_the_lists_bytes(scene, view.what);
    }
    scene.sampling.samples_per_pixel = 3;
    RendererOptions bands = walk(false);
    bands.band_rows = 5;
    expect_walk_gives_the_lists_bytes(scene, "inside the floor's box, 3 samples, bands of 5 rows", bands);
}

// A lens within 1e-10 degrees of 180 makes the camera's right and up vectors about 1e12 long,
// and a tile's pyramid's side normals their products: against a box 1e15 away their sums passed
// float's range, and a box the tile's rays meet could be left out.
TEST(BvhPackets, ATilesPyramidHoldsFarBoxesThroughTheWidestLens) {
    Scene scene = testing::make_scene({0, 0, 0}, {1, 0.3, -1}, {0, 1, 0}, 179.99999999995, 64, 48);
    add_mesh(scene, grid_mesh({-1e15, -1e15, -1e15}, {2e15, 0, 0}, {0, 0, 2e15}, 60, 60), {0.7, 0.7, 0.7});
    add_mesh(scene, sphere_mesh({6e14, 3e14, -6e14}, 2e14, 24, 12, false), {0.9, 0.3, 0.2});
    add_mesh(scene, sphere_mesh({-6e14, 1e14, 6e14}, 3e14, 24, 12, false), {0.2, 0.3, 0.9});
    expect_walk_gives_the_lists_bytes(scene, "fov 179.99999999995");
}

TEST(BvhPackets, MirrorsAndPointLightsWithPlanesGiveTheListsBytes) {
    expect_walk_gives_the_lists_bytes(testing::make_sunlit_mirror_scene(), "sunlit mirrors");
    Scene lit = sunlit_meshes();
    lit.has_sun = false;
    Material material;
    material.diffuse = {0.6, 0.5, 0.4};
    material.specular = {0.5, 0.5, 0.5};
    material.phong_exponent = 20;
    lit.materials.push_back(material);
    Plane floor;
    floor.point = {0, -1.3, 0};
    floor.normal = {0, 1, 0};
    floor.ambient = {0.1, 0.1, 0.1};
    floor.material = 0;
    lit.planes.push_back(floor);
    for (Sphere& sphere : lit.spheres) sphere.material = 0;
    for (Mesh& mesh : lit.meshes) mesh.material = 0;
    lit.lights.push_back({{5, 8, 6}, {0.8, 0.8, 0.8}});
    ASSERT_TRUE(lit.lit_by_lights());
    expect_walk_gives_the_lists_bytes(lit, "point lights and a plane");
    testing::expect_kernels_match_reference(lit, "bvh packets, lights", walk(true));
}

TEST(BvhPackets, AMovingCameraGivesTheListsBytesFrameByFrame) {
    // Each frame's geometry and BVH move to its eye: the walk reads them there.
    Scene scene = sunlit_meshes();
    scene.camera_path = {{{0, 3, 9}, {0, 0, 0}}, {{-6, 2, 5}, {0, 0, -1}}, {{3, 8, -7}, {0, 0, 0}}};
    Renderer lists(testing::test_device(), scene, walk(false));
    Renderer bvh(testing::test_device(), scene, walk(true));
    for (int frame = 0; frame < static_cast<int>(scene.camera_path.size()); ++frame) {
        const Image from_lists = lists.render(scene.camera_path[frame], frame);
        const Image from_bvh = bvh.render(scene.camera_path[frame], frame);
        EXPECT_TRUE(from_lists.rgba == from_bvh.rgba) << "frame " << frame;
    }
}

}  // namespace
}  // namespace clr
