// The viewer's renderer (view/render_service.h) starts from the program store as a render
// does: a scene whose own program is not prebuilt (here planes and lights) is served by the
// store's general program without a compile, and shows the image the scene's own program
// renders.
#include "view/render_service.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <sstream>
#include <thread>

#include "render/feature_set.h"
#include "render/program_store_builder.h"
#include "support/opencl_test_device.h"
#include "support/scene_builder.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"
#include "view/view_camera.h"
#include "view/view_parameters.h"

namespace clr {
namespace {

// The general program that stands in for a scene with point lights (and mirrors), without clipping.
FeatureSet general_with_lights() {
    FeatureSet lit;
    lit.lights = true;
    return FeatureSet::general(lit);
}

// A sphere on a floor plane under a point light (the fall 2019 format's kinds).
Scene lit_floor() {
    Scene scene = testing::make_scene({2, 5, 14}, {0, 1, 0}, {0, 1, 0}, 50, 64, 48);
    Material material;
    material.diffuse = {0.6, 0.4, 0.2};
    material.specular = {0.5, 0.5, 0.5};
    material.phong_exponent = 20;
    scene.materials.push_back(material);
    Sphere ball = testing::make_sphere({0, 2, 0}, 2, {0.1, 0.05, 0.05});
    ball.material = 1;
    scene.spheres.push_back(ball);
    Plane floor;
    floor.point = {0, 0, 0};
    floor.normal = {0, 1, 0};
    floor.ambient = {0.05, 0.05, 0.05};
    floor.material = 1;
    scene.planes.push_back(floor);
    scene.lights.push_back({{8, 12, 6}, {0.8, 0.8, 0.8}});
    return scene;
}

TEST(RenderService, AViewOfAnotherFeatureSetTakesTheStoresGeneralProgram) {
    const Scene scene = lit_floor();
    ASSERT_TRUE(FeatureSet::of(scene).planes && FeatureSet::of(scene).lights);
    testing::TempFolder folder;
    std::ostringstream log;
    ASSERT_EQ(build_program_store(folder.file("store"), testing::test_device().entry(),
                                  {general_with_lights()}, log)
                  .built,
              1)
        << log.str();
    const Image own = Renderer(testing::test_device(), scene).render(scene.camera_path.front());

    testing::ScopedEnv store("CLRENDER_PROGRAM_STORE", folder.file("store").c_str());
    testing::ScopedEnv cache("CLRENDER_CACHE_DIR", folder.file("cache").c_str());  // empty: no program of its own
    RenderService service(scene, Options{});
    EXPECT_EQ(service.store_hits(), 1);
    EXPECT_EQ(service.cache_hits(), 0);
    const ViewCamera view = resolve_view_camera(scene, ViewQuery{});  // the scene's own camera
    EXPECT_TRUE(service.render(view).rgba == own.rgba);
}

// A frame whose client went away stops before its next band, and the service renders the next
// frame as if nothing had happened.
TEST(RenderService, AnAbandonedFrameStopsAndTheNextRendersWhole) {
    const Scene scene = lit_floor();
    const Image own = Renderer(testing::test_device(), scene).render(scene.camera_path.front());
    RenderService service(scene, Options{});
    const ViewCamera view = resolve_view_camera(scene, ViewQuery{});  // the scene's own camera
    int asked = 0;
    EXPECT_THROW(service.render(view, [&asked] { return ++asked > 0; }), FrameAbandoned);
    EXPECT_EQ(asked, 1) << "asked before the first band";
    int asked_after = 0;
    EXPECT_TRUE(service.render(view, [&asked_after] { return ++asked_after < 0; }).rgba == own.rgba);
    EXPECT_GE(asked_after, 1);
    EXPECT_TRUE(service.render(view).rgba == own.rgba);
}

// Each explanation holds copies of the scene while it runs: two asked at once run one after
// the other, the second's kernels not started while the first's reference still samples.
TEST(RenderService, ExplanationsRunOneAtATime) {
    const Scene scene = lit_floor();
    RenderService service(scene, Options{});
    const ViewCamera view = resolve_view_camera(scene, ViewQuery{});  // the scene's own camera
    std::atomic<bool> first_asked{false}, first_asking{false}, overlapped{false};
    std::thread first([&] {
        service.explain(view, 10, 10, [&] {
            first_asking = true;
            first_asked = true;
            std::this_thread::sleep_for(std::chrono::milliseconds(200));  // slow, also while sampling
            first_asking = false;
            return false;
        });
    });
    while (!first_asked) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    service.explain(view, 20, 20, [&] {
        if (first_asking) overlapped = true;
        return false;
    });
    first.join();
    EXPECT_FALSE(overlapped);
}

}  // namespace
}  // namespace clr
