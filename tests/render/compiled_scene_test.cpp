// Moving the origin of a compiled scene (every animation frame) must give exactly what
// compiling the scene at that origin gives.
#include "render/compiled_scene.h"

#include <gtest/gtest.h>

#include <cstring>

#include "support/random_scene.h"

namespace clr {
namespace {

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(CompiledScene, MovingTheOriginEqualsCompilingThere) {
    Scene scene = testing::make_random_scene(260, 12, 12);
    scene.has_sun = true;
    scene.sun_location = {3, 40, -7};
    const Vec3 origin{1e5, -2.5, 37};
    CompiledScene moved = compile_scene(scene);
    move_origin(moved, scene, origin);
    CompiledScene direct = compile_scene(scene, origin);
    EXPECT_TRUE(same_bytes(moved.spheres, direct.spheres));
    EXPECT_TRUE(same_bytes(moved.billboards, direct.billboards));
    EXPECT_EQ(std::memcmp(&moved.info, &direct.info, sizeof(ClrSceneInfo)), 0);
    EXPECT_FALSE(same_bytes(moved.spheres, compile_scene(scene).spheres)) << "the origin must matter";
}

}  // namespace
}  // namespace clr
