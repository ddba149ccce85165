// Renderer::render(key) depends on its key alone, not on the frames rendered before it: the
// geometry moves to each key's eye and impostors turn to it (with a BVH over them when shadows
// need one). Each frame is compared with the reference's image of its key, and byte for byte
// with a fresh renderer whose scene starts at that key.
#include <gtest/gtest.h>

#include "reference/reference.h"
#include "render/renderer.h"
#include "support/image_compare.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

Impostor impostor_at(const Vec3& center) {
    Impostor impostor;
    impostor.center = center;
    impostor.width = 3;
    impostor.height = 4;
    impostor.ambient = {0.9, 0.8, 0.1};
    return impostor;
}

Image fresh_render(Scene scene, const CameraKey& key, int frame) {
    scene.camera_path = {key};  // a renderer starts placed for the scene's first key
    Renderer renderer(testing::test_device(), scene);
    return renderer.render(key, frame);
}

void expect_each_frame_as_if_first(const Scene& scene, const std::vector<CameraKey>& keys) {
    Renderer renderer(testing::test_device(), scene);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const int frame = static_cast<int>(k);
        Image image = renderer.render(keys[k], frame);
        // Float kernels may differ from the double reference on silhouettes and edges only.
        testing::ImageComparison comparison =
            testing::compare_images(image, reference::render(scene, reference::camera_of(scene, keys[k]), frame));
        EXPECT_LE(comparison.differing_fraction(), 0.01) << "frame " << k << ": " << comparison.differing;
        EXPECT_EQ(comparison.differing_off_edge, 0) << "frame " << k << ": " << comparison.first_off_edge;
        EXPECT_EQ(image.rgba, fresh_render(scene, keys[k], frame).rgba) << "frame " << k;
    }
}

Scene lit_scene_with_impostors() {
    Scene scene = testing::make_random_scene(31, 20, 6);
    scene.width = 64;
    scene.height = 48;
    scene.has_sun = true;  // with over 16 objects, shadow rays go through a BVH
    scene.sun_location = {5, 40, 10};
    for (int i = 0; i < 6; ++i) scene.impostors.push_back(impostor_at({-10.0 + 4 * i, 0, 2.0 * (i % 3)}));
    return scene;
}

const std::vector<CameraKey> kKeys = {{{0, 4, 30}, {0, 0, 0}}, {{28, 6, -5}, {0, 0, 0}}, {{-25, 2, 12}, {1, 0, 0}}};

TEST(FramePerKey, ImpostorsTurnToEachKey) {
    Scene scene = lit_scene_with_impostors();
    scene.camera_path = {kKeys.back()};  // placed for another key at construction
    expect_each_frame_as_if_first(scene, kKeys);
}

TEST(FramePerKey, GeometryMovesToEachKey) {
    Scene scene = lit_scene_with_impostors();
    scene.impostors.clear();
    scene.camera_path = {kKeys.back()};
    expect_each_frame_as_if_first(scene, {kKeys[0], kKeys[1], kKeys[0]});
}

TEST(FramePerKey, WarmingUpChangesNoFrame) {
    Scene scene = lit_scene_with_impostors();
    scene.camera_path = {kKeys[1]};
    Renderer renderer(testing::test_device(), scene);
    renderer.warm_up();
    EXPECT_EQ(renderer.render(kKeys[0]).rgba, fresh_render(scene, kKeys[0], 0).rgba);
}

}  // namespace
}  // namespace clr
