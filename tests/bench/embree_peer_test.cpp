// The Embree peer sees and shades what clrender's kernels do: the benchmark's ratio is only
// fair when both draw the same image, and its "differing pixels" check relies on the peer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "bench/bench_scenes.h"
#include "render/frame_camera.h"
#include "support/render_helpers.h"

#if CLRENDER_BENCH_HAVE_EMBREE
#include "bench/embree_peer.h"
#endif

namespace clr::bench {
namespace {

#if CLRENDER_BENCH_HAVE_EMBREE

constexpr int kWidth = 192, kHeight = 108;

ClrCamera device_camera(const Scene& scene) {
    const CameraKey& key = scene.camera_path.front();
    return make_frame_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, kWidth, kHeight).device();
}

// Unlit, the terrain's triangles show the mesh's id on both sides, the sphere its own, pixel
// for pixel but for a few on edges (measured: none differ at this size).
TEST(EmbreePeer, FlatTrianglesShowTheSameObjects) {
    Scene scene = make_bench_scene(find_bench_scene("70k triangles"), kWidth, kHeight);
    scene.only_ambient = true;
    std::vector<std::uint32_t> clr = object_ids(testing::render_with_kernels(scene));
    EmbreePeer peer(scene, device_camera(scene));
    peer.trace_frame();
    const std::vector<std::uint32_t>& embree = peer.ids();
    ASSERT_EQ(embree.size(), clr.size());
    std::size_t differing = 0, on_mesh = 0, on_sphere = 0;
    for (std::size_t i = 0; i < clr.size(); ++i) {
        differing += clr[i] != embree[i];
        on_mesh += embree[i] == mesh_id(1, 0, 0);
        on_sphere += embree[i] == sphere_id(0);
    }
    EXPECT_LE(differing, clr.size() / 1000);
    EXPECT_GT(on_mesh, clr.size() / 2) << "the terrain fills most of the view";
    EXPECT_GT(on_sphere, clr.size() / 100) << "the sphere is in view";
}

// Lit by the sun, the peer's colours (n.l with interpolated corner normals, shadow rays) are
// clrender's within the benchmark's tolerance, shadow of the sphere on the hills included
// (measured: 1 pixel of 20,736 differs; without shadow rays 332 do, swapping u and v 6,317).
TEST(EmbreePeer, LitTrianglesMatchClrendersImage) {
    Scene scene = make_bench_scene(find_bench_scene("70k triangles"), kWidth, kHeight);
    ASSERT_TRUE(scene.lit());
    Image clr = testing::render_with_kernels(scene);
    EmbreePeer peer(scene, device_camera(scene));
    peer.trace_frame();
    const std::vector<std::uint8_t>& rgb = peer.rgb();
    ASSERT_EQ(rgb.size(), 3u * kWidth * kHeight);
    std::size_t differing = 0, dark_mesh = 0, lit_mesh = 0;
    for (std::size_t i = 0; i < peer.ids().size(); ++i) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) differs |= std::abs(int{clr.rgba[4 * i + c]} - int{rgb[3 * i + c]}) > kLitTolerance;
        differing += differs;
        if (peer.ids()[i] == mesh_id(1, 0, 0)) {
            bool black = rgb[3 * i] == 0 && rgb[3 * i + 1] == 0 && rgb[3 * i + 2] == 0;
            dark_mesh += black;
            lit_mesh += !black;
        }
    }
    EXPECT_LE(differing, peer.ids().size() / 1000);
    // The comparison means something: shading varies, and the sphere's shadow is in view.
    EXPECT_GT(dark_mesh, peer.ids().size() / 100) << "some of the terrain lies in shadow";
    EXPECT_GT(lit_mesh, peer.ids().size() / 2) << "most of the terrain is lit";
}

// The course's objects with a lit mesh: the peer's colours are clrender's, sunlit spheres and
// ball, their shadows (through the sprite's holes too) and unlit billboards alike (measured:
// none differ; billboards that cast no shadow in the peer make 742 pixels differ).
TEST(EmbreePeer, LitCourseWithMeshMatchesClrendersImage) {
    Scene scene = make_bench_scene(find_bench_scene("course + mesh"), kWidth, kHeight);
    Image clr = testing::render_with_kernels(scene);
    EmbreePeer peer(scene, device_camera(scene));
    peer.trace_frame();
    const std::vector<std::uint8_t>& rgb = peer.rgb();
    std::size_t differing = 0, on_mesh = 0, shaded_mesh = 0;
    for (std::size_t i = 0; i < peer.ids().size(); ++i) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) differs |= std::abs(int{clr.rgba[4 * i + c]} - int{rgb[3 * i + c]}) > kLitTolerance;
        differing += differs;
        if (peer.ids()[i] == mesh_id(3, 2, 0)) {
            ++on_mesh;
            Color full = id_color(mesh_id(3, 2, 0));
            shaded_mesh += std::abs(rgb[3 * i] - static_cast<int>(std::lround(full.x * 255))) > 8;
        }
    }
    EXPECT_LE(differing, peer.ids().size() / 1000);
    EXPECT_GT(on_mesh, peer.ids().size() / 200) << "the ball is in view";
    EXPECT_GT(shaded_mesh, on_mesh / 2) << "and lit, not flat";
}

#else

TEST(EmbreePeer, FlatTrianglesShowTheSameObjects) { GTEST_SKIP() << "built without Embree"; }

#endif

}  // namespace
}  // namespace clr::bench
