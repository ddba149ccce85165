#include "bench/error_scenes.h"

#include <cstdint>
#include <filesystem>
#include <memory>

#include "scene/camera_path.h"
#include "scene/scene_loader.h"
#include "support/scene_builder.h"

namespace clr::bench {
namespace {

// The showcase's animation frame that the benchmark measures: mid-flight, with the mirror
// sphere, the cut-out billboard and the backdrop all in view.
constexpr int kShowcaseFrame = 48;

// The scene at root/relative_path; `relative_path` also names it in the report.
ErrorScene from_file(const std::string& name, const std::string& root, const std::string& relative_path, int width,
                     int height, int frame = 0) {
    LoadOptions options;
    options.width_override = width;
    options.height_override = height;
    ErrorScene view{name, relative_path, load_scene(root + "/" + relative_path, options), {}, frame};
    view.key = camera_at_frame(view.scene, frame);
    return view;
}

// A scene with one camera key, no objects, black background and flat shading.
Scene empty_scene(const std::string& name, const CameraKey& key, double fov_degrees, int width, int height) {
    Scene scene = testing::make_scene(key.eye, key.lookat, {0, 1, 0}, fov_degrees, width, height);
    scene.path = name + " (generated)";
    scene.name = name;
    return scene;
}

// `what` says what the scene is, for the report.
ErrorScene generated(const std::string& name, const std::string& what, Scene scene) {
    CameraKey key = scene.camera_path.front();
    return {name, "generated in bench/error_scenes.cpp: " + what, std::move(scene), key, 0};
}

// An opaque size x size chessboard of orange and blue texels.
std::shared_ptr<const Image> chessboard(int size) {
    auto image = std::make_shared<Image>();
    image->width = image->height = size;
    image->path = "chessboard (generated)";
    for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
            bool odd = (row + col) % 2;
            image->rgba.insert(image->rgba.end(), {std::uint8_t(odd ? 235 : 30), std::uint8_t(odd ? 140 : 90),
                                                   std::uint8_t(odd ? 40 : 210), 255});
        }
    return image;
}

// A unit-sized lit world (sphere with a shadow-casting companion, a mirror sphere, a textured
// backdrop) placed around `origin` and seen from near it: it tests that float32 keeps its
// precision wherever the scene lies, since the device works relative to the eye.
Scene translated_world(const Vec3& origin, int width, int height) {
    Scene scene = empty_scene("translated", {origin + Vec3{0.6, 1.1, 7.5}, origin}, 50, width, height);
    scene.background = {0.35, 0.5, 0.75};  // for the mirror to show
    scene.has_sun = true;
    scene.sun_location = origin + Vec3{25, 30, 12};
    scene.spheres = {testing::make_sphere(origin, 1, {0.85, 0.35, 0.25}),
                     testing::make_sphere(origin + Vec3{0.8, 1.5, 0.5}, 0.45, {0.25, 0.85, 0.4}),
                     testing::make_sphere(origin + Vec3{-2.3, 0.1, 0.4}, 0.9, {0, 0, 0}, true)};
    scene.billboards = {testing::make_billboard(origin + Vec3{-5, 3.5, -3}, origin + Vec3{-5, -2.5, -3},
                                                origin + Vec3{5, 3.5, -3}, {0, 0, 0}, chessboard(12))};
    return scene;
}

// A floor of abutting 1x1 billboards in two greys, seen from just above it so that the far
// tiles are met at grazing angles: thin, aliased rows of tiles that need many samples, and a
// magenta background that any crack between tiles would show.
Scene grazing_floor(int width, int height) {
    Scene scene = empty_scene("grazing floor", {{0.4, 0.8, 2}, {0.1, 0, -20}}, 50, width, height);
    scene.background = {1, 0, 1};
    for (int i = -16; i < 16; ++i)
        for (int j = 0; j < 64; ++j) {
            double x = i, z = -j;
            Color grey = (i + j) % 2 ? Color{0.85, 0.85, 0.85} : Color{0.15, 0.15, 0.15};
            scene.billboards.push_back(testing::make_billboard({x, 0, z - 1}, {x, 0, z}, {x + 1, 0, z - 1}, grey));
        }
    return scene;
}

}  // namespace

std::vector<ErrorScene> error_bench_scenes(const std::string& root, int width, int height) {
    std::vector<ErrorScene> scenes;
    scenes.push_back(from_file("showcase@48", root, "scenes/demo/showcase.json", width, height, kShowcaseFrame));
    scenes.push_back(from_file("demo", root, "scenes/demo/demo.json", width, height));
    const std::string course = "../shared/course-scenes/spring2023-a03/testScene_grads.json";
    if (std::filesystem::exists(root + "/" + course)) scenes.push_back(from_file("course-grads", root, course, width, height));
    scenes.push_back(generated("translated-1e5",
                               "a small lit world (spheres, a mirror sphere, a textured backdrop) placed 1e5 away from "
                               "the origin",
                               translated_world({1e5, 1e5, -1e5}, width, height)));
    scenes.push_back(generated("grazing-floor",
                               "a floor of 32 x 64 abutting 1x1 billboards seen from 0.8 above it, so that distant "
                               "tiles are thin, aliased rows",
                               grazing_floor(width, height)));
    return scenes;
}

}  // namespace clr::bench
