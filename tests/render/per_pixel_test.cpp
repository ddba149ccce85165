// Primary rays one work-item a pixel through the BVH (RendererOptions::per_pixel, a GPU's path:
// docs/benchmarks.md, A GPU) give the bytes of screen tiles and 16-ray packets (a CPU's path),
// and search a BVH wherever there are enough objects, lit or not.
#include <gtest/gtest.h>

#include <random>

#include "render/feature_set.h"
#include "render/primary_ray_path.h"
#include "render/renderer.h"
#include "support/opencl_test_device.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using testing::add_mesh;
using testing::grid_mesh;
using testing::sphere_mesh;

RendererOptions path(bool per_pixel) {
    RendererOptions options;
    options.per_pixel = per_pixel;
    return options;
}

// 300 unlit spheres and 40 flat billboards in random places, some reaching behind the eye: no
// secondary ray, so only the per-pixel path needs a BVH.
Scene unlit_crowd() {
    Scene scene = testing::make_scene({0, 0, 12}, {0, 0, 0}, {0, 1, 0}, 70, 157, 101);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> place(-9, 9), size(0.1, 1.2), shade(0, 1);
    for (int i = 0; i < 300; ++i)
        scene.spheres.push_back(testing::make_sphere({place(random), place(random), place(random)}, size(random),
                                                     {shade(random), shade(random), shade(random)}));
    for (int i = 0; i < 40; ++i) {
        const Vec3 corner{place(random), place(random), place(random) + 3};
        scene.billboards.push_back(testing::make_billboard(corner, corner + Vec3{0, -size(random), 0},
                                                           corner + Vec3{size(random), 0, -size(random)},
                                                           {shade(random), shade(random), shade(random)}));
    }
    return scene;
}

// Smooth and faceted meshes on a floor under the sun, with a mirror ball: shadow and mirror
// rays through the BVH as well.
Scene lit_meshes_and_a_mirror() {
    Scene scene = testing::make_scene({0, 3, 9}, {0, 0, 0}, {0, 1, 0}, 55, 131, 97);
    scene.has_sun = true;
    scene.sun_location = {6, 9, 5};
    scene.max_depth = 3;
    add_mesh(scene, sphere_mesh({-1.6, 0, 0}, 1, 24, 12, true), {0.9, 0.2, 0.2});
    add_mesh(scene, sphere_mesh({1.2, 0.2, -0.5}, 0.9, 10, 6, false), {0.2, 0.9, 0.3});
    add_mesh(scene, grid_mesh({-5, -1.2, 4}, {10, 0, 0}, {0, 0, -10}, 7, 7), {0.8, 0.8, 0.8});
    scene.spheres.push_back(testing::make_sphere({0, 1.6, 1}, 0.7, {0, 0, 0}, true));
    return scene;
}

TEST(PerPixel, AGpuTracesPerPixelACpuAndOclgrindInPackets) {
    EXPECT_TRUE(traces_per_pixel(CL_DEVICE_TYPE_GPU));
    EXPECT_TRUE(traces_per_pixel(CL_DEVICE_TYPE_GPU | CL_DEVICE_TYPE_DEFAULT));
    EXPECT_FALSE(traces_per_pixel(CL_DEVICE_TYPE_CPU));
    EXPECT_FALSE(traces_per_pixel(CL_DEVICE_TYPE_CPU | CL_DEVICE_TYPE_DEFAULT));
    EXPECT_FALSE(traces_per_pixel(CL_DEVICE_TYPE_ACCELERATOR));
    // Oclgrind's simulator: every type at once.
    EXPECT_FALSE(traces_per_pixel(CL_DEVICE_TYPE_ACCELERATOR | CL_DEVICE_TYPE_GPU | CL_DEVICE_TYPE_CPU |
                                  CL_DEVICE_TYPE_DEFAULT));
    // The test device (PoCL's CPU, Oclgrind, Intel's CPU runtime or a GPU) renders as it says.
    const Scene scene = unlit_crowd();
    const Renderer own_choice(testing::test_device(), scene);
    EXPECT_EQ(own_choice.features().bvh,
              traces_per_pixel(testing::test_device().device().getInfo<CL_DEVICE_TYPE>()));
}

TEST(PerPixel, UnlitObjectsAreSearchedThroughABvh) {
    const Scene scene = unlit_crowd();
    const Renderer per_pixel(testing::test_device(), scene, path(true));
    EXPECT_TRUE(per_pixel.features().bvh);
    const Renderer tiles(testing::test_device(), scene, path(false));
    EXPECT_FALSE(tiles.features().bvh) << "screen tiles need no BVH without secondary rays";
}

TEST(PerPixel, UnlitObjectsGiveTheScreenTilesBytes) {
    const Scene scene = unlit_crowd();
    const Image tiles = testing::render_with_kernels(scene, path(false));
    const Image per_pixel = testing::render_with_kernels(scene, path(true));
    EXPECT_TRUE(tiles.rgba == per_pixel.rgba);
    testing::expect_kernels_match_reference(scene, "per pixel", path(true));
}

TEST(PerPixel, LitMeshesAndMirrorsGiveTheScreenTilesBytes) {
    Scene scene = lit_meshes_and_a_mirror();
    for (int samples : {1, 3}) {
        scene.sampling.samples_per_pixel = samples;
        for (bool in_double : {false, true}) {
            RendererOptions tiles = path(false), per_pixel = path(true);
            tiles.double_precision = per_pixel.double_precision = in_double;
            EXPECT_TRUE(testing::render_with_kernels(scene, tiles).rgba ==
                        testing::render_with_kernels(scene, per_pixel).rgba)
                << samples << " samples, " << (in_double ? "double" : "float");
        }
    }
}

}  // namespace
}  // namespace clr
