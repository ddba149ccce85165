#include "reference/eye_relative.h"

#include <memory>

#include "reference/triangle_tree.h"

namespace clr::reference {

EyeRelative relative_to_eye(const Scene& scene, const CameraFrame& camera) {
    const Vec3 eye = camera.eye;
    EyeRelative relative{scene, camera, eye};
    Scene& moved = relative.scene;
    for (Sphere& sphere : moved.spheres) sphere.center = sphere.center - eye;
    for (Billboard& billboard : moved.billboards) {
        billboard.upper_left = billboard.upper_left - eye;
        billboard.lower_left = billboard.lower_left - eye;
        billboard.upper_right = billboard.upper_right - eye;
    }
    for (Triangle& triangle : moved.triangles)
        for (Vec3& corner : triangle.corners) corner = corner - eye;
    moved.triangle_tree.reset();
    if (!moved.triangles.empty()) moved.triangle_tree = std::make_shared<const TriangleTree>(moved.triangles);
    for (Impostor& impostor : moved.impostors) impostor.center = impostor.center - eye;
    moved.sun_location = moved.sun_location - eye;
    for (Plane& plane : moved.planes) plane.point = plane.point - eye;
    for (PointLight& light : moved.lights) light.position = light.position - eye;
    for (CameraKey& key : moved.camera_path) {
        key.eye = key.eye - eye;
        key.lookat = key.lookat - eye;
    }
    relative.camera.eye = {0, 0, 0};
    return relative;
}

}  // namespace clr::reference
