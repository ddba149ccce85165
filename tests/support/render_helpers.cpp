#include "support/render_helpers.h"

#include "reference/reference.h"
#include "render/device_camera.h"
#include "support/opencl_test_device.h"

namespace clr::testing {

Image render_with_kernels(const Scene& scene, const RendererOptions& options) {
    Renderer renderer(test_device(), scene, options);
    const CameraKey& key = scene.camera_path.front();
    return renderer.render_view(key);
}

Image render_with_reference(const Scene& scene) {
    const CameraKey& key = scene.camera_path.front();
    return reference::render(scene, reference::make_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height));
}

}  // namespace clr::testing
