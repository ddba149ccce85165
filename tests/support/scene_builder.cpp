#include "support/scene_builder.h"

namespace clr::testing {

Scene make_scene(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width, int height) {
    Scene scene;
    scene.path = "test-scene.json";
    scene.name = "test-scene";
    scene.camera_path = {{eye, lookat}};
    scene.up = up;
    scene.fov_degrees = fov_degrees;
    scene.width = width;
    scene.height = height;
    return scene;
}

Sphere make_sphere(const Vec3& center, double radius, const Color& ambient, bool mirror) {
    Sphere sphere;
    sphere.center = center;
    sphere.radius = radius;
    sphere.ambient = ambient;
    sphere.is_mirror = mirror;
    return sphere;
}

Billboard make_billboard(const Vec3& upper_left, const Vec3& lower_left, const Vec3& upper_right, const Color& ambient,
                         std::shared_ptr<const Image> image, bool mirror) {
    Billboard billboard;
    billboard.upper_left = upper_left;
    billboard.lower_left = lower_left;
    billboard.upper_right = upper_right;
    billboard.has_ambient = true;
    billboard.ambient = ambient;
    billboard.image = std::move(image);
    billboard.is_mirror = mirror;
    return billboard;
}

}  // namespace clr::testing
