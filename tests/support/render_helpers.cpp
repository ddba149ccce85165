#include "support/render_helpers.h"

#include "reference/reference.h"
#include "support/opencl_test_device.h"

namespace clr::testing {

Image render_with_kernels(const Scene& scene, const RendererOptions& options) {
    Renderer renderer(test_device(), scene, options);
    return renderer.render(scene.camera_path.front());
}

Image render_with_reference(const Scene& scene) {
    const CameraKey& key = scene.camera_path.front();
    return reference::render(scene, reference::camera_of(scene, key));
}

}  // namespace clr::testing
