// Bringing a compiled scene to another frame (every animation frame: a new origin, impostors
// turned to a new eye) must give exactly what compiling that frame afresh gives.
#include "render/compiled_scene.h"

#include <gtest/gtest.h>

#include <cstring>

#include "kinds/kinds.h"
#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

template <typename Vector>
bool same_bytes(const Vector& a, const Vector& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

void expect_same_device_form(const CompiledScene& a, const CompiledScene& b) {
    EXPECT_TRUE(same_bytes(a.spheres, b.spheres));
    EXPECT_TRUE(same_bytes(a.billboards, b.billboards));
    EXPECT_TRUE(same_bytes(a.texels, b.texels));
    EXPECT_EQ(std::memcmp(&a.info, &b.info, sizeof(ClrSceneInfo)), 0);
}

// Two views, each a 2x2 picture of its own colour with one transparent texel.
Impostor two_view_impostor(const Vec3& center) {
    Impostor impostor;
    impostor.center = center;
    impostor.width = 2;
    impostor.height = 3;
    for (int side : {1, -1}) {
        auto image = testing::make_image(2, 2, [=](int col, int row) {
            std::array<std::uint8_t, 4> texel{static_cast<std::uint8_t>(side > 0 ? 200 : 40), 90, 30, 255};
            if (col == 0 && row == 0) texel[3] = 0;
            return texel;
        });
        impostor.views.push_back({{static_cast<double>(side), 0, 0}, image});
    }
    return impostor;
}

TEST(CompiledScene, MovingTheOriginEqualsCompilingThere) {
    Scene scene = testing::make_random_scene(260, 12, 12);
    scene.has_sun = true;
    scene.sun_location = {3, 40, -7};
    FrameGeometry frame(scene);
    const Vec3 origin{1e5, -2.5, 37};
    CompiledScene moved = compile_scene(frame);
    compile_frame(moved, frame, origin);
    expect_same_device_form(moved, compile_scene(frame, origin));
    EXPECT_FALSE(same_bytes(moved.spheres, compile_scene(frame).spheres)) << "the origin must matter";
}

TEST(CompiledScene, ANewFrameWithTurnedImpostorsEqualsCompilingIt) {
    Scene scene = testing::make_random_scene(261, 5, 5);
    scene.impostors = {two_view_impostor({0, 0, 0}), two_view_impostor({4, 1, -3})};
    const CameraKey from_plus_x{{20, 2, 1}, {0, 0, 0}}, from_minus_x{{-20, 3, -2}, {0, 0, 0}};
    FrameGeometry frame(scene);
    frame.place_impostors(from_plus_x);
    CompiledScene compiled = compile_scene(frame, from_plus_x.eye);
    const std::vector<ClrBillboard> first_frame = compiled.billboards;

    frame.place_impostors(from_minus_x);
    compile_frame(compiled, frame, from_minus_x.eye);
    expect_same_device_form(compiled, compile_scene(frame, from_minus_x.eye));
    ASSERT_EQ(compiled.billboards.size(), scene.billboards.size() + scene.impostors.size());
    EXPECT_EQ(compiled.info.billboard_count, static_cast<int>(compiled.billboards.size()));
    // The impostors turned and switched views: their slots after the scene's own changed.
    for (std::size_t i = scene.billboards.size(); i < compiled.billboards.size(); ++i) {
        EXPECT_NE(compiled.billboards[i].normal.s[0], first_frame[i].normal.s[0]) << "impostor " << i;
        EXPECT_NE(compiled.billboards[i].texel_offset, first_frame[i].texel_offset) << "impostor " << i;
    }
}

// The renderer gives the texels to the device in place (CL_MEM_USE_HOST_PTR), which PoCL takes
// without a copy only at its CL_DEVICE_MEM_BASE_ADDR_ALIGN (128 bytes); malloc's large blocks
// start 16 bytes into a page. Page alignment covers every device met so far.
TEST(CompiledScene, ManyTrianglesMoveEachAsOnItsOwn) {
    // More triangles than one worker's share (compile_frame moves them on every usable core):
    // each must come out as TriangleKind::device() makes it alone, wherever its share ran.
    Scene scene = testing::make_scene({0, 5, 30}, {0, 0, 0}, {0, 1, 0}, 60, 64, 48);
    testing::add_mesh(scene, testing::grid_mesh({-20, -1, 20}, {40, 0, 0}, {0, 3, -40}, 230, 230), {0.5, 0.6, 0.7});
    ASSERT_GT(scene.triangles.size(), 100000u);
    const FrameGeometry frame(scene);
    CompiledScene compiled = compile_scene(frame);
    const Vec3 origin{3.25, -7.5, 1e4};
    compile_frame(compiled, frame, origin);
    ASSERT_EQ(compiled.triangles.size(), scene.triangles.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const ClrTriangle alone = TriangleKind::device(scene, scene.triangles[i], origin);
        differ += std::memcmp(&alone, &compiled.triangles[i], sizeof alone) != 0;
    }
    EXPECT_EQ(differ, 0u);
}

TEST(CompiledScene, TexelsStartOnAPage) {
    Scene scene = testing::make_random_scene(262, 3, 3);
    scene.impostors = {two_view_impostor({0, 0, 0})};
    // Large enough that malloc would map it on its own (and not page-aligned).
    auto big = testing::make_image(1024, 600, [](int, int) { return std::array<std::uint8_t, 4>{1, 2, 3, 255}; });
    scene.impostors[0].views[0].image = big;
    FrameGeometry frame(scene);
    frame.place_impostors({{20, 2, 1}, {0, 0, 0}});
    const CompiledScene compiled = compile_scene(frame);
    ASSERT_GE(compiled.texels.size(), big->rgba.size());
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(compiled.texels.data()) % 4096, 0u);
}

}  // namespace
}  // namespace clr
